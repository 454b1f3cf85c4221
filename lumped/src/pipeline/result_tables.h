#pragma once
// Private to the writers of result folders (output.cc: `run`; record_output.cc: an analysed
// record): their tables as CSV or .npy, streamed through a buffer with every value checked, and
// columns.json describing the .npy files. The folder's all-or-nothing commit is AtomicFileSet's.

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "bearing/case_file.h"
#include "bearing/decimal.h"
#include "bearing/errors.h"
#include "bearing/npy.h"

namespace bearing {

// Significant digits of the numbers in response.csv and spectrum.csv: a relative resolution of
// 5e-12, far below the integrators' error, and the same text as printf("%.12g").
constexpr int kCsvDigits = 12;

// A file written through a 1 MB buffer; numbers with kCsvDigits significant digits (decimal.h:
// ~20 ns each, where the shortest exact form costs ~45 ns and needs 17 digits for simulated data),
// formatted straight into the buffer. Streaming keeps a 24 000-row response from being built as
// one big string.
class BufferedFile {
 public:
  explicit BufferedFile(const std::filesystem::path& path)
      : path_(path), file_(std::fopen(path.c_str(), "wb")), buffer_(new char[kCapacity]) {
    if (!file_) fail();
  }
  ~BufferedFile() {
    if (file_) std::fclose(file_);
  }
  BufferedFile(const BufferedFile&) = delete;
  BufferedFile& operator=(const BufferedFile&) = delete;

  void text(std::string_view s) {
    while (!s.empty()) {
      room(1);
      const std::size_t n = std::min(s.size(), kCapacity - used_);
      std::memcpy(buffer_.get() + used_, s.data(), n);
      used_ += n;
      s.remove_prefix(n);
    }
  }
  void number(double v) {
    room(kDecimalBufferSize);
    used_ = static_cast<std::size_t>(write_decimal(buffer_.get() + used_, v, kCsvDigits) -
                                     buffer_.get());
  }
  void character(char c) {
    room(1);
    buffer_[used_++] = c;
  }
  /// `v` as 8 little-endian bytes (.npy '<f8').
  void f8(double v) {
    room(8);
    store_f8_le(buffer_.get() + used_, v);
    used_ += 8;
  }
  void close() {
    flush();
    const bool failed = std::fclose(file_) != 0;
    file_ = nullptr;
    if (failed) fail();
  }

 private:
  static constexpr std::size_t kCapacity = 1 << 20;
  void room(std::size_t n) {
    if (used_ + n > kCapacity) flush();
  }
  void flush() {
    if (used_ > 0 && std::fwrite(buffer_.get(), 1, used_, file_) != used_) fail();
    used_ = 0;
  }
  // errno says why: "No space left on device", "Permission denied", ...
  [[noreturn]] void fail() const;
  std::filesystem::path path_;
  std::FILE* file_;
  std::unique_ptr<char[]> buffer_;
  std::size_t used_ = 0;
};

// `what` builds the message only when it is needed (the check runs for every value written).
template <class What>
void require_finite_value(double v, const What& what) {
  if (!std::isfinite(v)) throw SolverError(what() + " is not finite; no result files were written");
}

// A result table as written: its rows and each column's name and SI unit (columns.json describes
// the .npy files by these).
struct TableLayout {
  std::size_t rows = 0;
  std::vector<std::string> columns;  ///< the abscissa first
  std::vector<std::string> units;
};

// A table: the abscissa column `x_name` [x_unit] = x[k], then one column per name [unit] with
// value(i, k). As CSV: a header row and kCsvDigits digits; as .npy: the full doubles, shape
// (rows, 1 + names), no names (they go to columns.json). A non-finite value stops the write,
// named by what(i, k).
template <class Value, class What>
TableLayout write_table(const std::filesystem::path& path, OutputFormat format,
                        const std::string& x_name, const std::string& x_unit,
                        const std::vector<double>& x, const std::vector<std::string>& names,
                        const std::vector<std::string>& units, const Value& value,
                        const What& what) {
  BufferedFile f(path);
  if (format == OutputFormat::npy) {
    f.text(npy_header(x.size(), names.size() + 1));
    for (std::size_t k = 0; k < x.size(); ++k) {
      f.f8(x[k]);
      for (std::size_t i = 0; i < names.size(); ++i) {
        const double v = value(i, k);
        require_finite_value(v, [&] { return what(i, k); });
        f.f8(v);
      }
    }
  } else {
    f.text(x_name);
    for (const auto& name : names) f.character(','), f.text(name);
    f.character('\n');
    for (std::size_t k = 0; k < x.size(); ++k) {
      f.number(x[k]);
      for (std::size_t i = 0; i < names.size(); ++i) {
        const double v = value(i, k);
        require_finite_value(v, [&] { return what(i, k); });
        f.character(',');
        f.number(v);
      }
      f.character('\n');
    }
  }
  f.close();
  TableLayout layout{x.size(), {x_name}, {x_unit}};
  layout.columns.insert(layout.columns.end(), names.begin(), names.end());
  layout.units.insert(layout.units.end(), units.begin(), units.end());
  return layout;
}

/// columns.json beside the .npy files: per file its shape and its columns' names and SI units.
std::string columns_json(const std::vector<std::string>& files,
                         const std::vector<TableLayout>& tables);

/// `text` into the file at `path` through a BufferedFile (OutputError if it cannot be written).
void write_text(const std::filesystem::path& path, const std::string& text);

}  // namespace bearing
