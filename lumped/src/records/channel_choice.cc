#include "bearing/records/channel_choice.h"

#include <algorithm>

#include "bearing/records/raw_channel.h"

namespace bearing {

std::string join_names(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::size_t choose_channel(const std::vector<std::string>& candidates, const RecordOptions& options,
                           const std::string& file, std::string_view kind,
                           const std::string& also) {
  const std::string others = also.empty() ? "" : "; not channels: " + also;
  const std::string k(kind);
  if (options.channel.empty()) {
    if (candidates.size() == 1) return 0;
    if (candidates.empty()) throw record_error(file, "", "no " + k + " to read" + others);
    throw record_error(file, "",
                       std::to_string(candidates.size()) + " " + k + "s (" +
                           join_names(candidates) + "): choose one with --channel");
  }
  const auto it = std::find(candidates.begin(), candidates.end(), options.channel);
  if (it != candidates.end()) return static_cast<std::size_t>(it - candidates.begin());
  const std::string there =
      candidates.empty() ? "the file has none" : "the file has " + join_names(candidates);
  throw record_error(file, options.channel, "no such " + k + "; " + there + others);
}

}  // namespace bearing
