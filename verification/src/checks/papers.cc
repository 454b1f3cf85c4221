#include "../families.h"

namespace bearing::verify {

std::vector<Check> paper_checks() {
  return {};
}

}  // namespace bearing::verify
