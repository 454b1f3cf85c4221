#include "bearing/choice.h"

#include "bearing/errors.h"
#include "edit_distance.h"

namespace bearing {

void throw_unknown_name(const std::string& key, std::string_view name, std::string_view what,
                        const std::vector<std::string_view>& names) {
  std::string msg =
      key + " = \"" + std::string(name) + "\": unknown " + std::string(what) + "; allowed: ";
  std::string_view nearest;
  std::size_t best = 4;  // suggest only within three edits
  for (std::size_t i = 0; i < names.size(); ++i) {
    msg += (i ? ", " : "") + std::string(names[i]);
    const std::size_t d = detail::edit_distance(name, names[i]);
    if (d < best) best = d, nearest = names[i];
  }
  if (!nearest.empty()) msg += " (did you mean \"" + std::string(nearest) + "\"?)";
  throw InputError(msg);
}

}  // namespace bearing
