#include "bearing/records/npy_record.h"

#include <cctype>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <vector>

#include "bearing/records/channel_choice.h"
#include "file_bytes.h"

namespace bearing {

namespace {

// The header dict as numpy writes it: {'descr': '<f8', 'fortran_order': False, 'shape': (n,), }.
// A small parser of exactly that Python literal: string keys; values a string, True/False or a
// tuple of integers.
struct NpyHeader {
  std::string descr;
  bool fortran_order = false;
  std::vector<std::size_t> shape;
  bool has_descr = false, has_order = false, has_shape = false;
};

class DictParser {
 public:
  DictParser(std::string_view text, const std::string& file) : s_(text), file_(file) {}

  NpyHeader parse() {
    NpyHeader h;
    expect('{');
    while (true) {
      skip();
      if (peek() == '}') break;
      const std::string key = string();
      expect(':');
      skip();
      if (key == "descr") {
        h.descr = string();
        h.has_descr = true;
      } else if (key == "fortran_order") {
        h.fortran_order = boolean();
        h.has_order = true;
      } else if (key == "shape") {
        h.shape = tuple();
        h.has_shape = true;
      } else {
        fail("unknown key '" + key + "'");
      }
      skip();
      if (peek() == ',') {
        ++i_;
        continue;
      }
      if (peek() != '}') fail("expected ',' or '}'");
    }
    if (!h.has_descr || !h.has_order || !h.has_shape)
      fail("it lacks one of 'descr', 'fortran_order', 'shape'");
    return h;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw record_error(file_, "", "not a .npy file numpy writes: header dict: " + what);
  }
  void skip() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  char peek() const { return i_ < s_.size() ? s_[i_] : '\0'; }
  void expect(char c) {
    skip();
    if (peek() != c) fail(std::string("expected '") + c + "'");
    ++i_;
  }
  std::string string() {
    skip();
    const char q = peek();
    if (q != '\'' && q != '"') fail("expected a quoted string");
    const std::size_t end = s_.find(q, i_ + 1);
    if (end == std::string_view::npos) fail("a string is not closed");
    std::string out(s_.substr(i_ + 1, end - i_ - 1));
    i_ = end + 1;
    return out;
  }
  bool boolean() {
    for (const bool value : {true, false}) {
      const std::string_view word = value ? "True" : "False";
      if (s_.substr(i_, word.size()) == word) {
        i_ += word.size();
        return value;
      }
    }
    fail("fortran_order must be True or False");
  }
  std::vector<std::size_t> tuple() {
    expect('(');
    std::vector<std::size_t> out;
    while (true) {
      skip();
      if (peek() == ')') break;
      std::size_t v = 0;
      bool digits = false;
      while (std::isdigit(static_cast<unsigned char>(peek()))) {
        const std::size_t d = static_cast<std::size_t>(peek() - '0');
        if (v > (std::numeric_limits<std::size_t>::max() - d) / 10) fail("a dimension overflows");
        v = v * 10 + d;
        digits = true;
        ++i_;
      }
      if (!digits) fail("shape must be a tuple of integers");
      out.push_back(v);
      skip();
      if (peek() == ',')
        ++i_;
      else if (peek() != ')')
        fail("expected ',' or ')' in shape");
      if (out.size() > 32) fail("shape has more than 32 dimensions");
    }
    ++i_;
    return out;
  }

  std::string_view s_;
  const std::string& file_;
  std::size_t i_ = 0;
};

std::uint32_t little_endian(std::string_view b, std::size_t at, std::size_t bytes) {
  std::uint32_t v = 0;
  for (std::size_t k = 0; k < bytes; ++k)
    v |= static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + k])) << (8 * k);
  return v;
}

// Element `index` of a float array of `size` bytes (4 or 8) in byte order `big`.
double element(const char* data, std::size_t index, std::size_t size, bool big) {
  unsigned char b[8];
  std::memcpy(b, data + index * size, size);
  if (big)
    for (std::size_t k = 0; k < size / 2; ++k) std::swap(b[k], b[size - 1 - k]);
  if (size == 4) {
    std::uint32_t u = 0;
    for (std::size_t k = 0; k < 4; ++k) u |= static_cast<std::uint32_t>(b[k]) << (8 * k);
    float f;
    std::memcpy(&f, &u, 4);
    return f;
  }
  std::uint64_t u = 0;
  for (std::size_t k = 0; k < 8; ++k) u |= static_cast<std::uint64_t>(b[k]) << (8 * k);
  double d;
  std::memcpy(&d, &u, 8);
  return d;
}

}  // namespace

RawChannel parse_npy_record(std::string_view bytes, const std::string& file,
                            const RecordOptions& options) {
  const auto bad = [&](const std::string& what) {
    return record_error(file, "", "not a .npy file numpy writes: " + what);
  };
  if (bytes.size() < 10 || bytes.substr(0, 6) != "\x93NUMPY") throw bad("no \\x93NUMPY magic");
  const int major = static_cast<unsigned char>(bytes[6]);
  if (major < 1 || major > 3) throw bad("version " + std::to_string(major) + " (known: 1, 2, 3)");
  const std::size_t length_bytes = major == 1 ? 2 : 4;
  if (bytes.size() < 8 + length_bytes) throw bad("the header is cut short");
  const std::size_t header_length = little_endian(bytes, 8, length_bytes);
  const std::size_t data_start = 8 + length_bytes + header_length;
  if (bytes.size() < data_start) throw bad("the header is cut short");
  const NpyHeader h = DictParser(bytes.substr(8 + length_bytes, header_length), file).parse();

  if (h.descr.size() != 3 || (h.descr[0] != '<' && h.descr[0] != '>') || h.descr[1] != 'f' ||
      (h.descr[2] != '4' && h.descr[2] != '8'))
    throw record_error(file, "",
                       "dtype '" + h.descr +
                           "': allowed float32 or float64 ('<f4', '<f8', "
                           "'>f4', '>f8')");
  const std::size_t size = h.descr[2] == '4' ? 4 : 8;
  const bool big = h.descr[0] == '>';

  // (n,), (n, 1) and (1, n): one channel; (n, k): k columns.
  std::size_t rows = 0, columns = 1;
  if (h.shape.size() == 1) {
    rows = h.shape[0];
  } else if (h.shape.size() == 2 && (h.shape[0] == 1 || h.shape[1] == 1)) {
    rows = h.shape[0] * h.shape[1];
  } else if (h.shape.size() == 2) {
    rows = h.shape[0];
    columns = h.shape[1];
  } else {
    throw record_error(file, "",
                       "an array of " + std::to_string(h.shape.size()) +
                           " dimensions: a record is 1-D (one channel) or 2-D (a column per "
                           "channel)");
  }
  const std::size_t available = bytes.size() - data_start;
  if (columns != 0 && rows > available / size / columns)
    throw record_error(file, "",
                       "the data is cut short: the shape needs more than the " +
                           std::to_string(available) + " bytes after the header");
  if (rows * columns * size != available)
    throw record_error(file, "",
                       std::to_string(available - rows * columns * size) +
                           " bytes after the array its shape describes");

  std::vector<std::string> names;
  for (std::size_t k = 0; k < columns; ++k) names.push_back(std::to_string(k));
  const std::size_t column = choose_channel(names, options, file, "column");
  RawChannel raw;
  raw.channel = names[column];
  raw.values.resize(rows);
  const char* data = bytes.data() + data_start;
  for (std::size_t i = 0; i < rows; ++i) {
    const std::size_t index = h.fortran_order ? column * rows + i : i * columns + column;
    raw.values[i] = element(data, index, size, big);
  }
  return raw;
}

RawChannel read_npy_record(const std::filesystem::path& file, const RecordOptions& options) {
  return parse_npy_record(records_detail::file_bytes(file), file.string(), options);
}

}  // namespace bearing
