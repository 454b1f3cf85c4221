// Fuzz target: the case-file reader (TOML, units, the schema's checks) and bearing-sim's --set
// overrides. The input is a case file, optionally followed by a line "#--set" and one override
// "TABLE.KEY=VALUE" per line, as `bearing-sim run CASE --set ...` would pass them
// (parse_override, then parse_case). Relative waviness tables and calibration files are looked
// up in examples/, so the fuzzer can reach the ones there.
//
// After a successful parse it checks what case_file.h promises and the CLI relies on: the
// resolved case written by case_to_toml reads back, and writes the same text again (the
// property WrittenCaseIsAFixedPointForEveryExample tests on the examples), and the case's
// contact constants (what `info` computes first) are found or refused with an InputError or
// SolverError.

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "bearing/case_file.h"
#include "fuzz_harness.h"

namespace {

constexpr const char* kTarget = "fuzz_case_file";
constexpr std::string_view kSeparator = "#--set";

struct Input {
  std::string_view toml;
  std::vector<std::string_view> sets;  // one --set argument each
};

// The TOML before a line "#--set", the lines after it as --set arguments.
Input split(std::string_view text) {
  Input in{text, {}};
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    if (text.substr(start, end - start) == kSeparator) {
      in.toml = text.substr(0, start);
      for (std::size_t s = end + 1; s < text.size();) {
        const std::size_t e = std::min(text.find('\n', s), text.size());
        if (e > s) in.sets.push_back(text.substr(s, e - s));
        s = e + 1;
      }
      break;
    }
    start = end + 1;
  }
  return in;
}

// The written case without its comment lines (the source, how ball errors were drawn).
std::string body(const std::string& text) {
  std::istringstream in(text);
  std::string out;
  for (std::string line; std::getline(in, line);)
    if (line.rfind('#', 0) != 0) out += line + "\n";
  return out;
}

void check_round_trip(const bearing::Case& a, const std::string& base_dir) {
  const std::string text = bearing::case_to_toml(a);
  bearing::Case b;
  try {
    b = bearing::parse_case(text, "case.toml", {}, base_dir);
  } catch (const bearing::InputError& e) {
    bearing::fuzz::property_failed(
        kTarget, std::string("case_to_toml's text does not read back: ") + e.what() + "\n" + text);
  }
  const std::string again = bearing::case_to_toml(b);
  if (body(again) != body(text))
    bearing::fuzz::property_failed(kTarget, "case_to_toml(parse_case(case_to_toml(c))) differs:\n" +
                                                text + "\n--- read back and written again ---\n" +
                                                again);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const Input in = split(text);
  const std::string base_dir = BEARING_FUZZ_EXAMPLES;
  bearing::fuzz::expect_only_input_errors(kTarget, [&] {
    std::vector<bearing::Override> overrides;
    for (std::string_view s : in.sets) {
      overrides.push_back(bearing::parse_override(s));
      // What a sweep asks of a --set key before it varies it.
      try {
        bearing::key_dimension(overrides.back().key);
      } catch (const bearing::InputError&) {
      }
    }
    const bearing::Case c = bearing::parse_case(in.toml, "fuzz.toml", overrides, base_dir);
    check_round_trip(c, base_dir);
    try {
      bearing::contact_constants(c);
    } catch (const bearing::SolverError&) {  // a documented answer of a numerical procedure
    }
  });
  return 0;
}
