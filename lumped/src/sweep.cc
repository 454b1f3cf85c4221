#include "bearing/sweep.h"

#include <atomic>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <thread>

#include "bearing/errors.h"

namespace bearing {

namespace {

std::string si_text(double v, const SweepAxis& axis) {
  char buf[64];
  if (axis.integer) {
    std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(std::llround(v)));
    return buf;
  }
  std::snprintf(buf, sizeof buf, "%.17g", v);
  const std::string unit(si_unit(axis.dimension));
  // Angles and speeds need a unit even in SI; others read plain numbers as SI.
  return unit.empty() ? std::string(buf) : "\"" + std::string(buf) + " " + unit + "\"";
}

double parse_end(const std::string& text, const SweepAxis& axis, const std::string& what) {
  const std::string key = "--vary " + axis.key + " (" + what + ")";
  if (axis.integer) {
    long long v = 0;
    const auto res = std::from_chars(text.data(), text.data() + text.size(), v);
    if (res.ec != std::errc() || res.ptr != text.data() + text.size())
      throw InputError(key + " = \"" + text + "\": " + axis.key + " takes whole numbers");
    return static_cast<double>(v);
  }
  return parse_quantity(text, axis.dimension, key);
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char ch : s) out += ch == '"' ? std::string("\"\"") : std::string(1, ch == '\n' ? ' ' : ch);
  return out + "\"";
}

void append(std::string& line, double v) {
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  line.append(buf, res.ptr);
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

std::vector<SweepPoint> sweep_points(const std::vector<SweepAxis>& axes) {
  std::vector<SweepPoint> points(1);
  for (const auto& axis : axes) {
    std::vector<SweepPoint> next;
    for (const auto& p : points)
      for (double v : axis.values) {
        SweepPoint q = p;
        q.values.push_back(v);
        q.overrides.push_back({axis.key, si_text(v, axis)});
        next.push_back(std::move(q));
      }
    points = std::move(next);
  }
  return axes.empty() ? std::vector<SweepPoint>{} : points;
}

std::vector<SweepRow> run_sweep(const std::function<Case(const std::vector<Override>&)>& load,
                                const std::vector<SweepPoint>& points, int threads,
                                const std::function<void(std::size_t, std::size_t)>& progress) {
  std::vector<SweepRow> rows(points.size());
  std::atomic<std::size_t> next{0};
  std::size_t done = 0;
  std::mutex mutex;
  const auto worker = [&] {
    for (std::size_t i = next++; i < points.size(); i = next++) {
      SweepRow& row = rows[i];
      row.values = points[i].values;
      try {
        const Case c = load(points[i].overrides);
        const SimulationResult r = simulate(c);
        RunSummary summary = summarize(c, r);
        row.channels = std::move(summary.channels);
        if (summary.noise) row.microphones = std::move(summary.noise->microphones);
        row.ok = true;
      } catch (const std::exception& e) {
        row.ok = false;
        row.error = e.what();
      }
      if (progress) {
        std::lock_guard<std::mutex> lock(mutex);
        progress(++done, points.size());
      }
    }
  };
  unsigned n = threads > 0 ? static_cast<unsigned>(threads) : std::thread::hardware_concurrency();
  n = std::max(1u, std::min<unsigned>(n, static_cast<unsigned>(points.size())));
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < n; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  return rows;
}

std::string sweep_csv(const std::vector<SweepAxis>& axes, const std::vector<SweepRow>& rows) {
  std::vector<std::string> channels;
  std::size_t microphones = 0;
  for (const auto& r : rows)
    if (r.ok) {
      for (const auto& ch : r.channels)
        if (ch.group == ChannelGroup::ring) channels.push_back(ch.name);
      microphones = r.microphones.size();
      break;
    }
  std::string out;
  for (const auto& a : axes) out += a.key + ",";
  out += "status,error";
  for (const auto& ch : channels)
    for (const char* f : {"rms", "ptp", "kurtosis", "crest", "peak_frequency", "peak_label"})
      out += "," + ch + "." + f;
  for (std::size_t i = 1; i <= microphones; ++i)
    for (const char* f : {"spl_total", "spl_ring", "spl_balls"})
      out += ",mic" + std::to_string(i) + "." + f;
  out += "\n";
  for (const auto& r : rows) {
    for (double v : r.values) append(out, v), out += ",";
    out += r.ok ? std::string("ok,") : "failed," + csv_field(r.error);
    for (const auto& name : channels) {
      const ChannelSummary* ch = nullptr;
      for (const auto& c : r.channels)
        if (c.name == name) ch = &c;
      if (!ch) {
        out += ",,,,,,";
        continue;
      }
      for (double v : {ch->statistics.rms, ch->statistics.ptp, ch->statistics.kurtosis,
                       ch->statistics.crest}) {
        out += ",";
        append(out, v);
      }
      out += ",";
      if (!ch->peaks.empty()) append(out, ch->peaks.front().frequency);
      out += "," + csv_field(ch->peaks.empty() ? "" : ch->peaks.front().label);
    }
    for (std::size_t i = 0; i < microphones; ++i) {
      const MicrophoneLevels* m = i < r.microphones.size() ? &r.microphones[i] : nullptr;
      for (const std::optional<double>* v :
           {m ? &m->spl_total : nullptr, m ? &m->spl_ring : nullptr, m ? &m->spl_balls : nullptr}) {
        out += ",";
        if (v && *v) append(out, **v);
      }
    }
    out += "\n";
  }
  return out;
}

}  // namespace bearing
