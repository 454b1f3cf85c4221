#pragma once
// What toml++ 3.3.0 (Debian's) must not be given; every reader of TOML files asks this first (the
// case reader, fem/'s structure-file reader). Its whitespace test for a non-ASCII character
// reaches __builtin_unreachable() for most code points (upstream issues marzer/tomlplusplus#190
// and #295, fixed after 3.3.0 by PR #305): undefined behaviour, found by tests/fuzz/. The parser
// asks that test of a character outside strings and comments (a quote inside a bare value,
// `-"µ"`, starts no string), and in a multi-line basic string of the character after a
// backslash. Neither is valid TOML (except a line-ending backslash followed on the next line by a
// non-ASCII character), so such text is refused here, before toml++ sees it.

#include <optional>
#include <string>
#include <string_view>

namespace bearing::case_schema {

/// Where toml++ 3.3.0 could not read the text safely (1-based, as its own errors) and why.
struct TomlTextProblem {
  int line = 1;
  int column = 1;
  std::string what;
};

/// The first such place of `text`, or nothing.
std::optional<TomlTextProblem> unsafe_toml_text(std::string_view text);

}  // namespace bearing::case_schema
