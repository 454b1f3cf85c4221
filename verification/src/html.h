#pragma once
// The pieces every HTML page of bearing-verify shares (report.html, the calibration report): one
// self-contained page, no script, figures embedded as data: URIs, readable on a phone.

#include <string>

#include "figure.h"

namespace bearing::verify {

std::string escape_html(const std::string& s);
/// <!DOCTYPE …><head> with the style, up to and including <body>.
std::string html_head(const std::string& title);
/// The figure's PNG (figures_dir/NAME.png) embedded as an <img>, or a note saying why it is
/// missing.
std::string figure_html(const Figure& f, const std::string& figures_dir);

}  // namespace bearing::verify
