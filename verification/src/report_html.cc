#include "report.h"

namespace bearing::verify {

std::string report_html(const Report&, const std::string&) {
  return "<!doctype html><title>bearing-verify</title>\n";
}

}  // namespace bearing::verify
