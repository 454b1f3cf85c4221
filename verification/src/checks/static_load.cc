#include "../families.h"

namespace bearing::verify {

std::vector<Check> static_load_checks() {
  return {};
}

}  // namespace bearing::verify
