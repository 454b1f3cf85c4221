#include "../families.h"

namespace bearing::verify {

std::vector<Check> hertz_fe_checks() {
  return {};
}

}  // namespace bearing::verify
