// Writes a libFuzzer dictionary from the library itself, so it cannot drift from the schema:
//   fuzz_dictionary case         the case file's tables, keys (as TOML keys and as --set keys),
//                                units, choice values, presets, and examples/' files
//   fuzz_dictionary calibration  the JSON keys and fixed strings of calibration.json
// The waviness table's few header words are a committed file (waviness.dict).

#include <cstdio>
#include <set>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "bearing/acoustics/acoustics_options.h"
#include "bearing/acoustics/pressure.h"
#include "bearing/calibration.h"
#include "bearing/case_file.h"
#include "bearing/contact.h"
#include "bearing/contact_loop.h"
#include "bearing/local_defect.h"
#include "bearing/models/model_kind.h"
#include "bearing/presets.h"
#include "bearing/signal/envelope.h"
#include "bearing/signal/spectrum.h"
#include "bearing/solvers/integrator.h"
#include "bearing/units.h"

namespace {

// One entry per distinct token, in libFuzzer's syntax: "..." with \\, \" and \xNN escapes.
class Dictionary {
 public:
  void add(const std::string& token) {
    if (!token.empty()) tokens_.insert(token);
  }
  void print() const {
    for (const std::string& t : tokens_) {
      std::string line = "\"";
      for (const unsigned char c : t) {
        if (c == '"' || c == '\\') {
          line += '\\';
          line += static_cast<char>(c);
        } else if (c < 0x20 || c >= 0x7f) {
          char hex[8];
          std::snprintf(hex, sizeof hex, "\\x%02X", c);
          line += hex;
        } else {
          line += static_cast<char>(c);
        }
      }
      std::printf("%s\"\n", line.c_str());
    }
  }

 private:
  std::set<std::string> tokens_;
};

template <class E, std::size_t N>
void add_choices(Dictionary& d, const bearing::Named<E> (&table)[N]) {
  for (const auto& entry : table) d.add("\"" + std::string(entry.name) + "\"");
}

void case_dictionary(Dictionary& d) {
  using bearing::Dimension;
  for (const std::string& key : bearing::known_keys()) {
    d.add(key + "=");  // a --set argument
    d.add(key.substr(key.rfind('.') + 1) + " = ");
    for (std::size_t dot = key.find('.'); dot != std::string::npos; dot = key.find('.', dot + 1)) {
      d.add("[" + key.substr(0, dot) + "]\n");
      d.add("[[" + key.substr(0, dot) + "]]\n");
    }
    d.add("[[" + key + "]]\n");  // the arrays of tables are keys themselves (waviness.inner)
  }
  for (int i = 0; i <= static_cast<int>(Dimension::dimensionless); ++i)
    for (const std::string& unit : bearing::accepted_units(static_cast<Dimension>(i)))
      d.add(" " + unit + "\"");
  add_choices(d, bearing::kModelKinds);
  add_choices(d, bearing::kContactLaws);
  add_choices(d, bearing::kIntegratorMethods);
  add_choices(d, bearing::kWindows);
  add_choices(d, bearing::kEnvelopeBandSources);
  add_choices(d, bearing::kOutputFormats);
  add_choices(d, bearing::kContactLoops);
  add_choices(d, bearing::kRingSources);
  add_choices(d, bearing::kBallSources);
  add_choices(d, bearing::kSummations);
  add_choices(d, bearing::kDefectLocations);
  add_choices(d, bearing::kDefectProfiles);
  for (const std::string& p : bearing::preset_names()) d.add("\"" + p + "\"");
  // The files in examples/ the harness's case can name (relative to examples/).
  d.add("\"seed003_inner_waviness.csv\"");
  d.add("\"seed003_6308_calibration.json\"");
  for (const char* t : {"#--set\n", "true", "false",   "[\"",   "\", \"", "\"]", "nan",
                        "inf",      "-0",   "1e308",   "e-320", "0x",     "'''", "\"\"\"",
                        "{ ",       " }",   "\\u00b5", "µ",     "°",      "·",   "="})
    d.add(t);
}

// Every key and fixed string of a calibration file, from the text the library writes.
void calibration_dictionary(Dictionary& d) {
  bearing::CalibrationDocument doc;
  doc.calibration.load_min = 1;
  doc.calibration.load_max = 2;
  doc.calibration.geometry = "hertz";
  doc.calibration.inner.fit_residual = 0;
  const auto walk = [&d](const nlohmann::json& j, const auto& self) -> void {
    if (j.is_object())
      for (const auto& [k, v] : j.items()) {
        d.add("\"" + k + "\":");
        self(v, self);
      }
    if (j.is_array())
      for (const auto& v : j) self(v, self);
    if (j.is_string() && !j.get<std::string>().empty()) d.add(j.dump());
  };
  walk(nlohmann::json::parse(bearing::calibration_text(doc)), walk);
  d.add("\"groove\"");
  for (const char* t : {"true", "false", "null", "1e308", "1e309", "-0", "1.5", "[", "]", "{", "}",
                        "\\u0000", "\\ud800"})
    d.add(t);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string_view what = argc == 2 ? argv[1] : "";
  Dictionary d;
  if (what == "case")
    case_dictionary(d);
  else if (what == "calibration")
    calibration_dictionary(d);
  else {
    std::fprintf(stderr, "usage: fuzz_dictionary case|calibration\n");
    return 2;
  }
  d.print();
  return 0;
}
