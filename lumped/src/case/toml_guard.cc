// What toml++ 3.3.0 must not be given (toml_guard.h): a small scan of TOML's strings and comments.

#include "toml_guard.h"

namespace bearing::case_schema {

namespace {

bool non_ascii(char c) {
  return static_cast<unsigned char>(c) >= 0x80;
}

bool blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

// Moves through the text keeping TOML's line and column (columns count characters, not bytes).
struct Cursor {
  std::string_view text;
  std::size_t i = 0;
  int line = 1, column = 1;

  bool done() const { return i >= text.size(); }
  char at(std::size_t ahead = 0) const { return i + ahead < text.size() ? text[i + ahead] : '\0'; }
  bool starts(std::string_view s) const { return text.substr(i, s.size()) == s; }
  void next() {
    if (done()) return;
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {
      ++column;  // not a UTF-8 continuation byte
    }
    ++i;
  }
  void skip(std::size_t n) {
    for (std::size_t k = 0; k < n && !done(); ++k) next();
  }
  TomlTextProblem problem(std::string what) const { return {line, column, std::move(what)}; }
};

// A basic string (after its opening quotes): escapes skipped; in a multi-line one, the first
// character after a backslash and its blanks must be ASCII.
std::optional<TomlTextProblem> basic_string(Cursor& c, bool multi_line) {
  while (!c.done()) {
    if (multi_line ? c.starts("\"\"\"") : c.at() == '"') {
      c.skip(multi_line ? 3 : 1);
      return std::nullopt;
    }
    if (!multi_line && c.at() == '\n') return std::nullopt;  // toml++ reports the open string
    if (c.at() == '\\') {
      c.next();
      if (multi_line) {
        const bool line_ending = blank(c.at());
        while (line_ending && !c.done() && blank(c.at())) c.next();
        if (non_ascii(c.at()))
          return c.problem(
              "a non-ASCII character right after a backslash (and blanks) in a multi-line "
              "string; this TOML reader cannot read it: write it as an escape such as \\u00b5 or "
              "join the lines");
        if (line_ending) continue;  // the next character is the string's again
      }
    }
    c.next();  // a character of the string, or the one a backslash escapes
  }
  return std::nullopt;
}

}  // namespace

std::optional<TomlTextProblem> unsafe_toml_text(std::string_view text) {
  Cursor c{text};
  // The last character outside strings and comments, blanks aside. A quote opens a string only
  // where a key or a value starts; elsewhere (`-"µ"`) toml++ reads it as part of a bare value,
  // testing each character for whitespace, so it is an ordinary character here too.
  char prev = '\n';
  while (!c.done()) {
    const char ch = c.at();
    const bool starts_string =
        prev == '\n' || prev == '=' || prev == '[' || prev == ',' || prev == '{' || prev == '.';
    if (ch == '#') {
      while (!c.done() && c.at() != '\n') c.next();
    } else if (starts_string && c.starts("\"\"\"")) {
      c.skip(3);
      if (auto p = basic_string(c, true)) return p;
      prev = '"';
    } else if (starts_string && ch == '"') {
      c.next();
      if (auto p = basic_string(c, false)) return p;
      prev = '"';
    } else if (starts_string && c.starts("'''")) {
      c.skip(3);
      while (!c.done() && !c.starts("'''")) c.next();
      c.skip(3);
      prev = '\'';
    } else if (starts_string && ch == '\'') {
      c.next();
      while (!c.done() && c.at() != '\'' && c.at() != '\n') c.next();
      if (c.at() == '\'') c.next();
      prev = '\'';
    } else if (non_ascii(ch)) {
      return c.problem(
          "a non-ASCII character outside a string or comment (a unit goes inside the quotes "
          "with its number, e.g. \"30 deg\")");
    } else {
      if (ch != ' ' && ch != '\t' && ch != '\r') prev = ch;
      c.next();
    }
  }
  return std::nullopt;
}

}  // namespace bearing::case_schema
