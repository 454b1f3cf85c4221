// What toml++ 3.3.0 must not be given (toml_guard.h): a small scan of TOML's strings and comments.

#include "bearing/toml_guard.h"

#include <cstdio>
#include <vector>

namespace bearing::case_schema {

namespace {

bool non_ascii(char c) {
  return static_cast<unsigned char>(c) >= 0x80;
}

// TOML allows no control character but tab, line feed and carriage return, anywhere.
bool control(char c) {
  const auto u = static_cast<unsigned char>(c);
  return (u < 0x20 && c != '\t' && c != '\n' && c != '\r') || u == 0x7F;
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

// At the '[' of a table header: toml++ 3.3.0 assumes (TOML_ASSERT_ASSUME) that the header's first
// character, after "[" or "[[" and blanks, starts a key (`[(bearing]` is undefined behaviour;
// found by sanitize.fuzz). A premature ']' it reports itself.
std::optional<TomlTextProblem> table_header_start(const Cursor& at) {
  Cursor c = at;
  c.next();
  if (c.at() == '[') c.next();
  while (c.at() == ' ' || c.at() == '\t') c.next();
  const char k = c.at();
  const bool key = (k >= 'A' && k <= 'Z') || (k >= 'a' && k <= 'z') || (k >= '0' && k <= '9') ||
                   k == '_' || k == '-' || k == '"' || k == '\'' || k == ']';
  if (c.done() || key) return std::nullopt;
  return c.problem(
      "a table header starts with its name: letters, digits, '_' and '-', or a quoted name");
}

}  // namespace

std::optional<TomlTextProblem> unsafe_toml_text(std::string_view text) {
  // toml++ 3.3.0 assumes (TOML_ASSERT_ASSUME) that no control character starts a key: a NUL after
  // '[' is undefined behaviour (an assertion in a build with them; found by sanitize.fuzz).
  for (Cursor k{text}; !k.done(); k.next())
    if (control(k.at())) {
      char code[8];
      std::snprintf(code, sizeof code, "%02X", static_cast<unsigned char>(k.at()));
      return k.problem(std::string("a control character (U+00") + code +
                       "); TOML allows none but tab and line breaks");
    }
  Cursor c{text};
  // Where a quote opens a string for toml++: at the start of a key or of a value. Inside a bare
  // value (`300x=[["µ`) toml++ reads on to the next space, ',', ']', '}' or '#', testing each
  // character for whitespace, so '=', '[', '{' and quotes there are ordinary characters.
  bool in_key = true;      // reading a key (else a value)
  bool bare = false;       // inside a bare word: a quote opens no string
  std::vector<char> open;  // '[' array, '{' inline table, 'h' table header
  while (!c.done()) {
    const char ch = c.at();
    if (ch == '#') {
      while (!c.done() && c.at() != '\n') c.next();
      continue;
    }
    if (!bare && (ch == '"' || ch == '\'')) {
      const bool multi_line = c.starts(ch == '"' ? "\"\"\"" : "'''");
      c.skip(multi_line ? 3 : 1);
      if (ch == '"') {
        if (auto p = basic_string(c, multi_line)) return p;
      } else {
        while (!c.done() && !c.starts(multi_line ? "'''" : "'") && (multi_line || c.at() != '\n'))
          c.next();
        if (!c.done() && c.at() != '\n') c.skip(multi_line ? 3 : 1);
      }
      continue;
    }
    if (non_ascii(ch))
      return c.problem(
          "a non-ASCII character outside a string or comment (a unit goes inside the quotes "
          "with its number, e.g. \"30 deg\")");
    if (ch == '\n' || ch == ' ' || ch == '\t' || ch == '\r') {
      bare = false;
      if (ch == '\n' && open.empty()) in_key = true;
    } else if (ch == ',') {
      bare = false;
      in_key = !open.empty() && open.back() == '{';
    } else if (ch == ']' || ch == '}') {
      // toml++ 3.3.0 takes what starts an array element for a value, assuming (TOML_ASSERT_ASSUME)
      // it is none of a value's terminators: a '}' there (`[[}`) is undefined behaviour (found by
      // sanitize.fuzz). A bracket that closes what it did not open is refused, both ways.
      if (!open.empty() && (ch == '}') != (open.back() == '{'))
        return c.problem(std::string("a '") + ch + "' where " +
                         (open.back() == '{' ? "an inline table" : "an array or a table header") +
                         " is open");
      if (!open.empty()) open.pop_back();
      bare = true;                     // a value (or a header) ended: what follows opens no string
    } else if (ch == '=' && in_key) {  // the key ends, its value starts
      in_key = false;
      bare = false;
    } else if (ch == '.' && in_key) {  // between the parts of a dotted key
      bare = false;
    } else if (!bare && (ch == '[' || ch == '{')) {
      if (ch == '[' && in_key && open.empty())
        if (auto p = table_header_start(c)) return p;
      open.push_back(in_key ? 'h' : ch);
      in_key = in_key || ch == '{';
    } else {
      bare = true;
    }
    c.next();
  }
  return std::nullopt;
}

}  // namespace bearing::case_schema
