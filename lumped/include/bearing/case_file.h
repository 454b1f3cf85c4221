#pragma once
// Case files: TOML with units (DESIGN.md "Case file"), resolved into SI values.
//
// Precedence, lowest first: built-in defaults, the `bearing.preset` catalogue entry, the keys in
// the file, then `--set table.key=value` overrides. Unknown tables and keys are errors that suggest
// the nearest valid name; every error names the key, the value and what is allowed.

#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Dense>

#include "bearing/bearing.h"

namespace bearing {

/// Operating conditions. Outer ring fixed; x horizontal, y vertical (up).
struct Operation {
  double speed = 0.0;                              ///< inner-ring speed ω_i [rad/s]
  Eigen::Vector2d load = Eigen::Vector2d::Zero();  ///< radial load (F_x, F_y) on the inner ring [N]
};

/// Model choices.
struct ModelOptions {
  std::string contact = "exact";  ///< Hertz method: "exact" | "hamrock-brewe" | "harris-table"
};

struct Case {
  std::string source;  ///< file the case was read from, or "built-in default case"
  std::string preset;  ///< bearing.preset, empty if none
  Bearing bearing;
  Operation operation;
  ModelOptions model;
};

/// One command-line override `table.key=value` (the value is TOML, or else taken as a string, so
/// `operation.speed=3000 rpm` and `model.contact=exact` need no quotes).
struct Override {
  std::string key;    ///< dotted path, e.g. "material.ball.young"
  std::string value;  ///< the text after '='
};

/// Parses "table.key=value"; throws InputError if there is no '=' or no dotted key.
Override parse_override(std::string_view text);

/// Reads and resolves a case file. Throws InputError ("<path>: <key> = <value>: <what is
/// allowed>").
Case read_case_file(const std::string& path, const std::vector<Override>& overrides = {});

/// Resolves a case from TOML text; `source` names it in messages.
Case parse_case(std::string_view toml_text, const std::string& source,
                const std::vector<Override>& overrides = {});

/// TOML of the built-in default case: the 6308 of seed 003 at 2000 rpm under seed 002's 20 N
/// radial load, pointing down.
std::string_view default_case_toml();

/// The built-in default case with overrides applied.
Case default_case(const std::vector<Override>& overrides = {});

/// The names of every key the case reader accepts, as "table.key" (for --help and suggestions).
std::vector<std::string> known_keys();

/// One line per key: name, what it is and the units it accepts (for --help).
std::string case_keys_help();

}  // namespace bearing
