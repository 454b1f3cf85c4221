// The pieces every HTML page of bearing-verify shares: escaping, the style, embedded figures.
#include "html.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace bearing::verify {

std::string escape_html(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

namespace {

std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned n = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8 |
                       (unsigned char)bytes[i + 2];
    for (int k = 18; k >= 0; k -= 6) out += digits[(n >> k) & 63];
  }
  if (i < bytes.size()) {
    unsigned n = (unsigned char)bytes[i] << 16;
    if (i + 1 < bytes.size()) n |= (unsigned char)bytes[i + 1] << 8;
    out += digits[(n >> 18) & 63];
    out += digits[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? digits[(n >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

}  // namespace

// The figure as an <img> with its PNG inside, or a note saying why it is missing.
std::string figure_html(const Figure& f, const std::string& figures_dir) {
  std::ifstream in(std::filesystem::path(figures_dir) / (f.name + ".png"), std::ios::binary);
  if (!in)
    return "<p class=\"note\">Figure " + escape_html(f.name) +
           " not drawn (needs /usr/bin/python3 with matplotlib; its data is in "
           "figures/figures.json).</p>";
  std::stringstream ss;
  ss << in.rdbuf();
  return "<figure><img alt=\"" + escape_html(f.title) + "\" src=\"data:image/png;base64," +
         base64(ss.str()) + "\"><figcaption>" + escape_html(f.title) + "</figcaption></figure>";
}

// Print-friendly, phone-friendly: tables scroll sideways in their box, images shrink.
constexpr const char* kStyle = R"(
body{font-family:system-ui,-apple-system,"Segoe UI",Roboto,sans-serif;margin:0 auto;max-width:70em;
padding:0 1em 3em;color:#1b1f23;line-height:1.45}
h1{font-size:1.6em;margin-top:1em}h2{font-size:1.25em;margin-top:2em;border-bottom:1px solid #ddd}
.scroll{overflow-x:auto;-webkit-overflow-scrolling:touch}
table{border-collapse:collapse;font-size:.9em;margin:.5em 0}
th,td{border:1px solid #d0d7de;padding:.3em .55em;text-align:left;vertical-align:top}
th{background:#f3f5f7}td.num{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}
tr.fail td{background:#ffd7d5}tr.skipped td{background:#fff5cc}tr.pass td.verdict{color:#116329}
tr.fail td.verdict{color:#a40e26;font-weight:bold}td.why{font-size:.85em;color:#444}
.banner{padding:.6em 1em;border-radius:6px;font-weight:bold;margin:1em 0}
.ok{background:#dafbe1;color:#116329}.bad{background:#ffd7d5;color:#a40e26}
.planted{background:#fff5cc;color:#7d4e00}
figure{margin:1em 0;max-width:40em}figure img{max-width:100%;height:auto;border:1px solid #eee}
figcaption{font-size:.85em;color:#555}code{font-size:.9em;white-space:nowrap}.note{color:#7d4e00}
)";

std::string html_head(const std::string& title) {
  return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
         escape_html(title) + "</title>\n<style>" + kStyle + "</style></head><body>\n";
}

}  // namespace bearing::verify
