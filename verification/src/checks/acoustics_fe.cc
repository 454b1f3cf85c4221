#include "../families.h"

namespace bearing::verify {

std::vector<Check> acoustics_fe_checks() {
  return {};
}

}  // namespace bearing::verify
