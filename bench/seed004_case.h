#pragma once
// Issue 7's benchmark case, shared by bearing_bench and bearing_bench_simd: seed 004's SKF 6304
// (examples/seed004_6304.toml: 2000 rpm, 2000 N along +x, clearance 30 um, m = 0.4 kg,
// c = 350 N s/m), read from the example file itself (BEARING_EXAMPLES_DIR, set by
// bench/CMakeLists.txt). The 2-DOF variant is the same file with model.kind = "2dof" and without
// its [cage] and [ball] tables, which the case reader accepts only for model.kind = "balls".

#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bearing/case_file.h"

namespace bench {

inline std::string seed004_path() {
  return std::string(BEARING_EXAMPLES_DIR) + "/seed004_6304.toml";
}

inline std::string seed004_toml(bool balls) {
  std::ifstream in(seed004_path());
  if (!in) throw std::runtime_error("cannot read " + seed004_path());
  std::string text, line;
  bool skip = false;
  while (std::getline(in, line)) {
    const auto first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line[first] == '[') {
      const std::string header = line.substr(first, line.find(']', first) + 1 - first);
      skip = !balls && (header == "[cage]" || header == "[ball]");
    }
    if (!skip) text += line + '\n';
  }
  return text;
}

/// The ball-DOF case (`balls`) or its 2-DOF variant, with `overrides` on top.
inline bearing::Case seed004_case(bool balls, std::vector<bearing::Override> overrides = {}) {
  if (!balls) overrides.insert(overrides.begin(), {"model.kind", "2dof"});
  return bearing::parse_case(seed004_toml(balls), seed004_path(), overrides, BEARING_EXAMPLES_DIR);
}

}  // namespace bench
