#pragma once
// Private to the gmsh reader: the .msh text as numbered lines of whitespace-separated tokens, and
// the InputError that names the file and the line.

#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>

#include "bearing/errors.h"

namespace bearing::fem::gmsh {

/// The text, one line at a time, with its number (1-based) for messages.
class Lines {
 public:
  Lines(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  /// The next line without its end ('\n', "\r\n"); false at the end of the text.
  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    const std::size_t end = text_.find('\n', pos_);
    const std::size_t stop = end == std::string_view::npos ? text_.size() : end;
    line = text_.substr(pos_, stop - pos_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos_ = stop + 1;
    ++number_;
    return true;
  }
  /// The next line, which must exist: `expected` says what it should hold.
  std::string_view require(const char* expected) {
    std::string_view line;
    if (!next(line)) fail(std::string("the file ends where ") + expected + " should follow");
    return line;
  }
  int number() const { return number_; }
  const std::string& file() const { return file_; }
  /// "FILE:LINE: what" as an InputError.
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(file_ + ":" + std::to_string(number_) + ": " + what);
  }

 private:
  std::string_view text_;
  const std::string& file_;
  std::size_t pos_ = 0;
  int number_ = 0;
};

/// The whitespace-separated tokens of one line; each read names what it reads in its message.
class Tokens {
 public:
  Tokens(std::string_view line, const Lines& lines) : rest_(line), lines_(lines) {}

  bool empty() {
    skip_space();
    return rest_.empty();
  }
  std::string_view word(const char* what) {
    skip_space();
    if (rest_.empty()) lines_.fail(std::string("missing ") + what);
    std::size_t n = 0;
    while (n < rest_.size() && !is_space(rest_[n])) ++n;
    const std::string_view w = rest_.substr(0, n);
    rest_.remove_prefix(n);
    return w;
  }
  /// An integer in [low, high].
  long long integer(const char* what, long long low, long long high) {
    const std::string_view w = word(what);
    long long v = 0;
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (ec != std::errc() || end != w.data() + w.size())
      lines_.fail(std::string(what) + " \"" + shown(w) + "\" is not an integer");
    if (v < low || v > high)
      lines_.fail(std::string(what) + " " + std::to_string(v) + " is outside [" +
                  std::to_string(low) + ", " + std::to_string(high) + "]");
    return v;
  }
  /// A finite real number.
  double real(const char* what) {
    const std::string_view w = word(what);
    double v = 0;
    const char* begin = w.data() + (!w.empty() && w.front() == '+' ? 1 : 0);
    const auto [end, ec] = std::from_chars(begin, w.data() + w.size(), v);
    if (ec != std::errc() || end != w.data() + w.size() || !std::isfinite(v))
      lines_.fail(std::string(what) + " \"" + shown(w) + "\" is not a finite number");
    return v;
  }
  /// Fails if anything but whitespace is left: `what` names the line's content.
  void finish(const char* what) {
    if (!empty()) lines_.fail(std::string("unexpected \"") + shown(word("")) + "\" after " + what);
  }

  /// At most 40 characters of `w`, printable ASCII only (a message is one line).
  static std::string shown(std::string_view w) {
    std::string s;
    for (char c : w.substr(0, 40)) s += (c >= 32 && c < 127) ? c : '?';
    return w.size() > 40 ? s + "..." : s;
  }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v'; }
  void skip_space() {
    while (!rest_.empty() && is_space(rest_.front())) rest_.remove_prefix(1);
  }
  std::string_view rest_;
  const Lines& lines_;
};

constexpr long long kMaxTag = std::numeric_limits<int>::max();
constexpr long long kMaxNodeTag = 1LL << 62;

}  // namespace bearing::fem::gmsh
