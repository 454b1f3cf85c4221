#include "bearing/sweep.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>
#include <thread>
#include <variant>

#include "bearing/errors.h"

namespace bearing {

namespace fs = std::filesystem;

namespace {

double parse_end(const std::string& text, const SweepAxis& axis, const std::string& what) {
  const std::string key = "--vary " + axis.key + " (" + what + ")";
  if (axis.integer) {
    long long v = 0;
    const auto res = std::from_chars(text.data(), text.data() + text.size(), v);
    if (res.ec != std::errc() || res.ptr != text.data() + text.size())
      throw InputError(key + " = \"" + text + "\": " + axis.key + " takes whole numbers");
    return static_cast<double>(v);
  }
  // A plain number is SI, as in a case file and in --cases (0:200:3 N of operation.axial_load),
  // except for angles and speeds, which need a unit (0 needs none).
  double v = 0;
  const auto res = std::from_chars(text.data(), text.data() + text.size(), v);
  if (!text.empty() && res.ec == std::errc() && res.ptr == text.data() + text.size() &&
      std::isfinite(v) && (bare_number_is_si(axis.dimension) || v == 0))
    return v;
  return parse_quantity(text, axis.dimension, key);
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char ch : s) out += ch == '"' ? std::string("\"\"") : std::string(1, ch == '\n' ? ' ' : ch);
  return out + "\"";
}

}  // namespace

SweepAxis parse_vary(std::string_view text) {
  const std::string t(text);
  const auto eq = t.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--vary " + t +
                     ": expected KEY=FROM:TO:N, e.g. operation.speed=1000rpm:3000rpm:5");
  SweepAxis axis;
  axis.key = t.substr(0, eq);
  axis.dimension = key_dimension(axis.key);  // throws for a non-numeric key
  axis.integer = key_is_integer(axis.key);
  const std::string range = t.substr(eq + 1);
  const auto c1 = range.find(':');
  const auto c2 = c1 == std::string::npos ? std::string::npos : range.find(':', c1 + 1);
  if (c2 == std::string::npos || range.find(':', c2 + 1) != std::string::npos)
    throw InputError("--vary " + t + ": expected KEY=FROM:TO:N (three fields after '=')");
  const std::string from_text = range.substr(0, c1), to_text = range.substr(c1 + 1, c2 - c1 - 1);
  const double from = parse_end(from_text, axis, "FROM");
  const double to = parse_end(to_text, axis, "TO");
  long long n = 0;
  const std::string ns = range.substr(c2 + 1);
  const auto res = std::from_chars(ns.data(), ns.data() + ns.size(), n);
  if (res.ec != std::errc() || res.ptr != ns.data() + ns.size() || n < 1 || n > 100000)
    throw InputError("--vary " + t + ": N = \"" + ns +
                     "\" must be a whole number from 1 to 100000");
  // Interpolate in the user's unit when both ends share one, so "0um:20um:3" gives exactly what
  // the case reader makes of "10 um"; otherwise in SI.
  double a = from, b = to;
  std::string unit;
  if (!axis.integer) {
    char* end_a = nullptr;
    char* end_b = nullptr;
    const double na = std::strtod(from_text.c_str(), &end_a);
    const double nb = std::strtod(to_text.c_str(), &end_b);
    std::string ua(end_a), ub(end_b);
    ua.erase(0, ua.find_first_not_of(' '));
    ub.erase(0, ub.find_first_not_of(' '));
    if (ua == ub && !ua.empty()) a = na, b = nb, unit = ua;
  }
  for (long long i = 0; i < n; ++i) {
    const double u = n == 1 ? a : a + (b - a) * static_cast<double>(i) / static_cast<double>(n - 1);
    const double v = unit.empty() ? u : to_si(u, unit, axis.dimension, "--vary " + t);
    if (axis.integer && std::fabs(v - std::round(v)) > 1e-9)
      throw InputError("--vary " + t + ": " + axis.key + " takes whole numbers, but step " +
                       std::to_string(i) + " gives " + std::to_string(v) +
                       "; choose N so that (TO - FROM)/(N - 1) is whole");
    axis.values.push_back(axis.integer ? std::round(v) : v);
  }
  return axis;
}

std::size_t sweep_size(const std::vector<SweepAxis>& axes) {
  if (axes.empty()) return 0;
  std::size_t n = 1;
  for (const auto& axis : axes) {
    const std::size_t k = axis.values.size();
    if (k != 0 && n > std::numeric_limits<std::size_t>::max() / k)
      throw InputError("--vary: the product of the axes' N is too large (axis " + axis.key + ")");
    n *= k;
  }
  return n;
}

SweepPoint sweep_point(const std::vector<SweepAxis>& axes, std::size_t index) {
  // The index in mixed radix, the last axis the fastest digit.
  std::vector<std::size_t> digit(axes.size());
  for (std::size_t a = axes.size(); a-- > 0;) {
    digit[a] = index % axes[a].values.size();
    index /= axes[a].values.size();
  }
  SweepPoint p;
  for (std::size_t a = 0; a < axes.size(); ++a) {
    const double v = axes[a].values[digit[a]];
    p.values.push_back(v);
    p.overrides.push_back(
        {axes[a].key, sweep_value_text(v, {axes[a].key, axes[a].dimension, axes[a].integer})});
  }
  return p;
}

std::vector<SweepPoint> sweep_points(const std::vector<SweepAxis>& axes) {
  std::vector<SweepPoint> points;
  const std::size_t n = sweep_size(axes);
  points.reserve(n);
  for (std::size_t i = 0; i < n; ++i) points.push_back(sweep_point(axes, i));
  return points;
}

namespace {

SweepEnvelope sweep_envelope(const EnvelopeSummary& e) {
  SweepEnvelope out{e.channel, e.band, e.spectral_kurtosis, band_energy_fraction(e), std::nullopt};
  if (!e.peaks.empty()) out.peak = e.peaks.front();
  return out;
}

SweepRow run_point(const SweepLoader& load, const SweepPoint& point,
                   const std::vector<SweepSave>& save) {
  SweepRow row;
  row.values = point.values;
  try {
    const Case c = load(point.overrides);
    const SimulationResult r = simulate(c);
    RunSummary summary = summarize(c, r);
    if (!save.empty())
      row.tables = std::make_shared<const SweepCaseTables>(sweep_case_tables(c, r, summary, save));
    row.channels = std::move(summary.channels);
    if (summary.noise) row.microphones = std::move(summary.noise->microphones);
    for (const EnvelopeSummary& e : summary.envelopes) row.envelopes.push_back(sweep_envelope(e));
    row.diagnosis = std::move(summary.diagnosis);
    row.ok = true;
  } catch (const std::exception& e) {
    row.ok = false;
    row.error = e.what();
  }
  return row;
}

// Finished rows a worker may run ahead of the oldest unfinished one, per worker.
constexpr std::size_t kWindowPerWorker = 4;

}  // namespace

void run_sweep(const SweepLoader& load, std::size_t cases,
               const std::function<SweepPoint(std::size_t)>& point, int threads,
               const std::function<void(std::size_t, SweepRow&&)>& sink,
               const SweepProgress& progress, const std::vector<SweepSave>& save) {
  if (cases == 0) return;
  unsigned n = threads > 0 ? static_cast<unsigned>(threads) : std::thread::hardware_concurrency();
  n = static_cast<unsigned>(std::max<std::size_t>(1, std::min<std::size_t>(n, cases)));
  const std::size_t window = kWindowPerWorker * n;
  std::mutex mutex;
  std::condition_variable can_start;
  std::size_t next = 0;                     // the next case to start
  std::size_t handed = 0;                   // rows passed to sink (cases 0 … handed − 1)
  std::size_t done = 0;                     // cases finished
  std::map<std::size_t, SweepRow> waiting;  // finished rows behind an unfinished earlier one
  std::exception_ptr sink_error;
  const auto worker = [&] {
    for (;;) {
      std::size_t i = 0;
      {
        std::unique_lock<std::mutex> lock(mutex);
        can_start.wait(lock, [&] { return next >= cases || sink_error || next < handed + window; });
        if (next >= cases || sink_error) return;
        i = next++;
      }
      SweepRow row = run_point(load, point(i), save);
      std::lock_guard<std::mutex> lock(mutex);
      waiting.emplace(i, std::move(row));
      if (progress) progress(++done, cases);
      for (auto it = waiting.begin(); it != waiting.end() && it->first == handed && !sink_error;
           it = waiting.erase(it), ++handed) {
        try {
          sink(it->first, std::move(it->second));
        } catch (...) {
          sink_error = std::current_exception();
        }
      }
      can_start.notify_all();
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < n; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (sink_error) std::rethrow_exception(sink_error);
}

std::vector<SweepRow> run_sweep(const SweepLoader& load, const std::vector<SweepPoint>& points,
                                int threads, const SweepProgress& progress) {
  std::vector<SweepRow> rows;
  rows.reserve(points.size());
  run_sweep(
      load, points.size(), [&](std::size_t i) { return points[i]; }, threads,
      [&](std::size_t, SweepRow&& row) { rows.push_back(std::move(row)); }, progress);
  return rows;
}

SweepCsvWriter::SweepCsvWriter(const std::vector<SweepAxis>& axes,
                               std::function<void(std::string_view)> out)
    : out_(std::move(out)) {
  for (const auto& a : axes) keys_.push_back(a.key);
}

SweepCsvWriter::SweepCsvWriter(std::vector<std::string> keys,
                               std::function<void(std::string_view)> out)
    : keys_(std::move(keys)), out_(std::move(out)) {}

// The header is: keys, status, error, then the columns (sweep_columns.h).
void SweepCsvWriter::continue_after(std::string_view header) {
  started_ = true;
  columns_ = sweep_columns(header);
}

void SweepCsvWriter::add(const SweepRow& row) {
  if (!started_ && !row.ok) {
    SweepRow held;
    held.values = row.values;
    held.error = row.error;
    held_.push_back(std::move(held));
    return;
  }
  if (!started_) start(&row);
  write_row(row);
}

void SweepCsvWriter::finish() {
  if (!started_) start(nullptr);
}

// The header (its columns from `first_ok`, none without it), then the rows held so far.
void SweepCsvWriter::start(const SweepRow* first_ok) {
  started_ = true;
  if (first_ok) columns_ = sweep_columns(*first_ok);
  line_.clear();
  for (const auto& k : keys_) line_ += k + ",";
  line_ += "status,error";
  for (const auto& name : sweep_column_names(columns_)) line_ += "," + name;
  line_ += "\n";
  out_(line_);
  for (const auto& r : held_) write_row(r);
  held_.clear();
  held_.shrink_to_fit();
}

void SweepCsvWriter::write_row(const SweepRow& r) {
  std::string& out = line_;
  out.clear();
  for (double v : r.values) append_number(out, v), out += ",";
  out += r.ok ? std::string("ok,") : "failed," + csv_field(r.error);
  for (const SweepCell& cell : sweep_cells(columns_, r)) {
    out += ",";
    if (const double* v = std::get_if<double>(&cell))
      append_number(out, *v);
    else if (const std::string* text = std::get_if<std::string>(&cell))
      out += csv_field(*text);
  }
  out += "\n";
  out_(out);
}

std::string sweep_csv(const std::vector<SweepAxis>& axes, const std::vector<SweepRow>& rows) {
  std::string out;
  SweepCsvWriter writer(axes, [&](std::string_view s) { out.append(s); });
  for (const auto& r : rows) writer.add(r);
  writer.finish();
  return out;
}

}  // namespace bearing
