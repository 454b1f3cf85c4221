#include "../families.h"

namespace bearing::verify {

std::vector<Check> dynamics_checks() {
  return {};
}

}  // namespace bearing::verify
