// Excitations shared by every model (docs/model.md §5): raceway waviness, its harmonic tables, and
// ball-size errors drawn in a band.

#include "bearing/excitation.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/units.h"

namespace bearing {

// --- Waviness --------------------------------------------------------------------------------
// These evaluate the sums directly (one sin/cos per harmonic): they are the reference the models'
// recurrence-based evaluation is tested against, and are not used in any hot loop.

double Waviness::profile(double phi) const {
  double sum = 0.0;
  for (const WavinessHarmonic& h : harmonics)
    sum += h.amplitude * std::sin(h.order * phi + h.phase);
  return sum;
}

double Waviness::slope(double phi) const {
  double sum = 0.0;
  for (const WavinessHarmonic& h : harmonics)
    sum += h.amplitude * h.order * std::cos(h.order * phi + h.phase);
  return sum;
}

double Waviness::second_derivative(double phi) const {
  double sum = 0.0;
  for (const WavinessHarmonic& h : harmonics) {
    const double n = h.order;
    sum -= h.amplitude * n * n * std::sin(h.order * phi + h.phase);
  }
  return sum;
}

int Waviness::max_order() const {
  int n = 0;
  for (const WavinessHarmonic& h : harmonics) n = std::max(n, h.order);
  return n;
}

// --- Waviness tables -------------------------------------------------------------------------

namespace {

std::string trim(const std::string& s) {
  const char* ws = " \t\r\n";
  const std::size_t b = s.find_first_not_of(ws);
  if (b == std::string::npos) return std::string();
  const std::size_t e = s.find_last_not_of(ws);
  return s.substr(b, e - b + 1);
}

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(trim(field));
  if (!line.empty() && line.back() == ',') fields.emplace_back();  // trailing empty field
  return fields;
}

// Full-string number parse (no trailing garbage); false if not a finite number.
bool parse_double(const std::string& text, double& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && errno != ERANGE && std::isfinite(value);
}

bool parse_int(const std::string& text, long& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtol(text.c_str(), &end, 10);
  return end == text.c_str() + text.size() && errno != ERANGE;
}

bool looks_numeric(const std::string& text) {
  double v;
  return parse_double(text, v);
}

// Where a table error happened, for the messages: "<key> = "<file>", line <n>".
struct Where {
  const std::string& key;
  const std::string& path;
  int line;
  std::string str() const {
    return key + " = \"" + path + "\"" + (line > 0 ? ", line " + std::to_string(line) : "");
  }
};

enum class Column { order, amplitude, phase };

struct Layout {
  int order = 0;  // field index of each column
  int amplitude = 1;
  int phase = -1;  // -1: no phase column (phases 0)
  std::size_t fields = 2;
  double amplitude_factor = 1e-6;            // µm unless the header says otherwise
  double phase_factor = pi / 180.0;          // degrees unless the header says otherwise
  std::string columns = "order, amplitude";  // for messages
};

// Header cell "name" or "name_unit"; the unit goes through the case-file unit table.
Layout parse_header(const std::vector<std::string>& cells, const Where& where) {
  Layout layout;
  layout.order = layout.amplitude = layout.phase = -1;
  layout.fields = cells.size();
  for (std::size_t i = 0; i < cells.size(); ++i) {
    std::string cell = cells[i];
    std::transform(cell.begin(), cell.end(), cell.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const std::size_t us = cell.find('_');
    const std::string name = cell.substr(0, us);
    const std::string unit = us == std::string::npos ? std::string() : cell.substr(us + 1);
    int* slot = nullptr;
    if (name == "order") {
      slot = &layout.order;
      if (!unit.empty())
        throw InputError(where.str() + ": header column \"" + cells[i] +
                         "\": the order is a plain count of waves per revolution and takes no "
                         "unit; write \"order\"");
    } else if (name == "amplitude") {
      slot = &layout.amplitude;
      if (!unit.empty())
        layout.amplitude_factor = unit_factor(unit, Dimension::length,
                                              where.str() + ": header column \"" + cells[i] + "\"");
    } else if (name == "phase") {
      slot = &layout.phase;
      if (!unit.empty())
        layout.phase_factor = unit_factor(unit, Dimension::angle,
                                          where.str() + ": header column \"" + cells[i] + "\"");
    } else {
      throw InputError(where.str() + ": unknown header column \"" + cells[i] +
                       "\"; the columns are order, amplitude[_unit] and optionally phase[_unit] "
                       "(e.g. \"order,amplitude_um,phase_deg\")");
    }
    if (*slot >= 0)
      throw InputError(where.str() + ": header column \"" + cells[i] + "\" appears twice");
    *slot = static_cast<int>(i);
  }
  if (layout.order < 0) throw InputError(where.str() + ": the header has no \"order\" column");
  if (layout.amplitude < 0)
    throw InputError(where.str() + ": the header has no \"amplitude\" column");
  layout.columns.clear();
  for (const std::string& c : cells) layout.columns += (layout.columns.empty() ? "" : ", ") + c;
  return layout;
}

}  // namespace

std::vector<WavinessHarmonic> parse_waviness_table(std::string_view text, const std::string& path,
                                                   const std::string& key) {
  std::istringstream in{std::string(text)};
  std::vector<WavinessHarmonic> out;
  std::map<int, int> first_line_of_order;
  bool have_layout = false;
  Layout layout;
  std::string raw;
  int line_no = 0;
  while (std::getline(in, raw)) {
    ++line_no;
    if (line_no == 1 && raw.size() >= 3 && raw.compare(0, 3, "\xEF\xBB\xBF") == 0)
      raw.erase(0, 3);  // UTF-8 byte-order mark
    const std::size_t hash = raw.find('#');
    const std::string line = trim(hash == std::string::npos ? raw : raw.substr(0, hash));
    if (line.empty()) continue;
    const Where where{key, path, line_no};
    const std::vector<std::string> cells = split_fields(line);

    if (!have_layout) {
      have_layout = true;
      if (!looks_numeric(cells[0])) {  // a header row
        layout = parse_header(cells, where);
        continue;
      }
      // No header: order, amplitude [µm], optional phase [deg].
      if (cells.size() < 2 || cells.size() > 3)
        throw InputError(where.str() + ": \"" + line + "\" has " + std::to_string(cells.size()) +
                         " columns; a waviness table has order, amplitude [um] and optionally "
                         "phase [deg], or a header naming them");
      layout.fields = cells.size();
      if (cells.size() == 3) layout.phase = 2, layout.columns = "order, amplitude, phase";
    }

    if (cells.size() != layout.fields) {
      throw InputError(where.str() + ": \"" + line + "\" has " + std::to_string(cells.size()) +
                       " columns, expected " + std::to_string(layout.fields) + " (" +
                       layout.columns + ")");
    }

    WavinessHarmonic h;
    long order = 0;
    const std::string& order_text = cells[layout.order];
    if (!parse_int(order_text, order) || order < 1 || order > 1000000)
      throw InputError(where.str() + ": order = \"" + order_text +
                       "\": must be an integer from 1 to 1000000 (waves per revolution)");
    h.order = static_cast<int>(order);

    double amplitude = 0;
    const std::string& amp_text = cells[layout.amplitude];
    if (!parse_double(amp_text, amplitude) || amplitude < 0)
      throw InputError(where.str() + ": amplitude = \"" + amp_text +
                       "\": must be a finite number >= 0 (a phase of 180 deg gives the opposite "
                       "sign)");
    h.amplitude = amplitude * layout.amplitude_factor;

    if (layout.phase >= 0) {
      double phase = 0;
      const std::string& phase_text = cells[layout.phase];
      if (!parse_double(phase_text, phase))
        throw InputError(where.str() + ": phase = \"" + phase_text + "\": must be a finite number");
      h.phase = phase * layout.phase_factor;
    }

    const auto [it, inserted] = first_line_of_order.emplace(h.order, line_no);
    if (!inserted)
      throw InputError(where.str() + ": order " + std::to_string(h.order) +
                       " appears twice (first on line " + std::to_string(it->second) +
                       "); give each order once");
    out.push_back(h);
  }
  if (out.empty())
    throw InputError(key + " = \"" + path +
                     "\": the waviness table has no rows (expected order,amplitude[,phase])");
  return out;
}

std::vector<WavinessHarmonic> read_waviness_table(const std::string& path, const std::string& key) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(key + " = \"" + path + "\": is a directory, not a waviness table file");
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int err = errno;
    throw InputError(key + " = \"" + path + "\": cannot open the waviness table" +
                     (err != 0 ? std::string(" (") + std::strerror(err) + ")" : std::string()));
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(key + " = \"" + path + "\": read error");
  return parse_waviness_table(text.str(), path, key);
}

// --- Ball-size errors --------------------------------------------------------------------------
// xoshiro256** (Blackman & Vigna 2018), seeded through splitmix64 as its authors recommend; both
// are fixed integer recurrences, so a seed gives the same numbers on every platform and compiler.

namespace {

std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

class Xoshiro256ss {
 public:
  explicit Xoshiro256ss(std::uint64_t seed) {
    for (std::uint64_t& w : s_) w = splitmix64(seed);
  }
  std::uint64_t next() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }
  /// Uniform in [0, 1) with 53 random bits (exactly representable, no rounding).
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t s_[4];
};

}  // namespace

std::vector<double> ball_size_errors_from_band(int balls, double band, std::uint64_t seed) {
  if (balls < 1)
    throw InputError("bearing.balls = " + std::to_string(balls) +
                     ": ball-size errors need at least one ball");
  if (!(std::isfinite(band) && band >= 0))
    throw InputError("ball_errors.band = " + format_number(band) +
                     " m: the error band must be finite and >= 0");
  Xoshiro256ss rng(seed);
  std::vector<double> errors(balls);
  for (double& e : errors) e = band * (rng.uniform() - 0.5);
  return errors;
}

void check_waviness(const std::vector<WavinessHarmonic>& harmonics, const Bearing& bearing,
                    const std::string& key) {
  for (std::size_t i = 0; i < harmonics.size(); ++i) {
    const WavinessHarmonic& h = harmonics[i];
    const std::string entry = key + "[" + std::to_string(i) + "]";
    if (h.order < 1 || h.order > 100000)
      throw InputError(entry + ".order = " + std::to_string(h.order) +
                       ": waves per revolution must be an integer >= 1");
    if (!(std::isfinite(h.amplitude) && h.amplitude >= 0 &&
          h.amplitude < 0.01 * bearing.ball_diameter))
      throw InputError(entry + ".amplitude = " + format_number(h.amplitude) +
                       " m: must be >= 0 and below 1 % of the ball diameter (waviness is a few "
                       "um at most)");
    if (!std::isfinite(h.phase))
      throw InputError(entry + ".phase = " + format_number(h.phase) + " rad: must be finite");
  }
}

void check_ball_size_errors(const std::vector<double>& errors, const Bearing& bearing) {
  if (errors.empty()) return;
  if (static_cast<int>(errors.size()) != bearing.balls)
    throw InputError("ball_errors.values has " + std::to_string(errors.size()) +
                     " entries: expected one per ball (" + std::to_string(bearing.balls) + ")");
  for (std::size_t j = 0; j < errors.size(); ++j)
    if (!(std::fabs(errors[j]) < 0.01 * bearing.ball_diameter))
      throw InputError("ball_errors.values[" + std::to_string(j) +
                       "] = " + format_number(-errors[j]) +
                       " m: a ball-size error must be below 1 % of the ball diameter");
}

}  // namespace bearing
