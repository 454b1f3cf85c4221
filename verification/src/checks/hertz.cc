#include "../families.h"

namespace bearing::verify {

std::vector<Check> hertz_checks() {
  return {};
}

}  // namespace bearing::verify
