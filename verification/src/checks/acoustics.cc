#include "../families.h"

namespace bearing::verify {

std::vector<Check> acoustics_checks() {
  return {};
}

}  // namespace bearing::verify
