#include "report.h"

namespace bearing::verify {

std::string report_markdown(const Report&) {
  return "# bearing-verify report\n";
}

}  // namespace bearing::verify
