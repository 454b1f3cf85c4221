#include "bearing/limits.h"

#include "bearing/errors.h"

namespace bearing {

void Limit::check(double v) const {
  if (contains(v)) return;
  const std::string shown =
      unit ? format_quantity(v, unit, dim)
           : format_number(v) + (si_unit(dim).empty() ? "" : " " + std::string(si_unit(dim)));
  throw InputError(std::string(key) + " = " + shown + ": " + allowed);
}

}  // namespace bearing
