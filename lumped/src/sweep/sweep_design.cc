// The three designs of a sweep (grid, random, list) and their JSON records.

#include "bearing/sweep_design.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "bearing/errors.h"
#include "bearing/sweep.h"

namespace bearing {

namespace {

using nlohmann::json;

// `where` names the option (and file, line) in the message of a key that is not numeric.
SweepKey key_of(const std::string& key, const std::string& where = "") {
  try {
    return {key, key_dimension(key), key_is_integer(key)};
  } catch (const InputError& e) {
    if (where.empty()) throw;
    throw InputError(where + ": " + e.what());
  }
}

json keys_json(const std::vector<SweepKey>& keys) {
  json out = json::array();
  for (const auto& k : keys) out.push_back(k.key);
  return out;
}

// The Cartesian product of --vary axes (sweep_point).
class GridDesign final : public SweepDesign {
 public:
  explicit GridDesign(std::vector<SweepAxis> axes) : axes_(std::move(axes)) {
    for (const auto& a : axes_) keys_.push_back({a.key, a.dimension, a.integer});
    size_ = sweep_size(axes_);
  }
  std::size_t size() const override { return size_; }
  const std::vector<SweepKey>& keys() const override { return keys_; }
  SweepPoint point(std::size_t index) const override { return sweep_point(axes_, index); }
  std::string json() const override {
    nlohmann::json axes = nlohmann::json::array();
    for (const auto& a : axes_) axes.push_back({{"key", a.key}, {"values", a.values}});
    return nlohmann::json{{"kind", "grid"}, {"axes", axes}}.dump();
  }

 private:
  std::vector<SweepAxis> axes_;
  std::vector<SweepKey> keys_;
  std::size_t size_ = 0;
};

// --sample: every key drawn afresh for each case from (seed, case, key).
class RandomDesign final : public SweepDesign {
 public:
  RandomDesign(std::vector<SweepSample> samples, std::size_t cases, std::uint64_t seed)
      : samples_(std::move(samples)), cases_(cases), seed_(seed) {
    for (const auto& s : samples_) keys_.push_back(s.key);
  }
  std::size_t size() const override { return cases_; }
  const std::vector<SweepKey>& keys() const override { return keys_; }
  SweepPoint point(std::size_t index) const override {
    SweepPoint p;
    for (const auto& s : samples_) {
      const double v = draw(s, index);
      p.values.push_back(v);
      p.overrides.push_back({s.key.key, sweep_value_text(v, s.key)});
    }
    return p;
  }
  std::string json() const override {
    nlohmann::json samples = nlohmann::json::array();
    for (const auto& s : samples_)
      samples.push_back(
          {{"key", s.key.key}, {"distribution", s.distribution}, {"parameters", {s.p1, s.p2}}});
    return nlohmann::json{
        {"kind", "random"}, {"seed", seed_}, {"samples", cases_}, {"keys", samples}}
        .dump();
  }

 private:
  // Uniform: a + (b − a)·u; log-uniform: exp of that on ln a … ln b; normal: Box–Muller on two
  // independent streams.
  double draw(const SweepSample& s, std::size_t index) const {
    const double u = sweep_uniform(seed_, index, s.key.key, 0);
    if (s.distribution == "uniform") {
      if (s.key.integer) return std::min(s.p2, std::floor(s.p1 + u * (s.p2 - s.p1 + 1.0)));
      return s.p1 + (s.p2 - s.p1) * u;
    }
    double v = 0;
    if (s.distribution == "loguniform") {
      v = std::exp(std::log(s.p1) + (std::log(s.p2) - std::log(s.p1)) * u);
    } else {
      const double u2 = sweep_uniform(seed_, index, s.key.key, 1);
      v = s.p1 + s.p2 * std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * M_PI * u2);
    }
    return s.key.integer ? std::round(v) : v;
  }
  std::vector<SweepSample> samples_;
  std::vector<SweepKey> keys_;
  std::size_t cases_;
  std::uint64_t seed_;
};

// --cases FILE.csv: the rows as given (SI).
class ListDesign final : public SweepDesign {
 public:
  ListDesign(std::vector<SweepKey> keys, std::vector<std::vector<double>> rows)
      : keys_(std::move(keys)), rows_(std::move(rows)) {}
  std::size_t size() const override { return rows_.size(); }
  const std::vector<SweepKey>& keys() const override { return keys_; }
  SweepPoint point(std::size_t index) const override {
    SweepPoint p;
    p.values = rows_.at(index);
    for (std::size_t k = 0; k < keys_.size(); ++k)
      p.overrides.push_back({keys_[k].key, sweep_value_text(p.values[k], keys_[k])});
    return p;
  }
  std::string json() const override {
    return nlohmann::json{{"kind", "list"}, {"keys", keys_json(keys_)}, {"rows", rows_}}.dump();
  }

 private:
  std::vector<SweepKey> keys_;
  std::vector<std::vector<double>> rows_;
};

std::uint64_t splitmix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

std::string trim(std::string s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  s = s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
  return s;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    const auto comma = line.find(',', start);
    out.push_back(trim(line.substr(start, comma - start)));
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

// A value of `key` as text: a whole number for whole-number keys, else a quantity with units.
double parse_value(const std::string& text, const SweepKey& key, const std::string& where) {
  if (key.integer) {
    long long v = 0;
    const auto res = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || res.ec != std::errc() || res.ptr != text.data() + text.size())
      throw InputError(where + " = \"" + text + "\": " + key.key + " takes whole numbers");
    return static_cast<double>(v);
  }
  // A plain number is SI (as in a case file), except for angles and speeds, which need a unit.
  double v = 0;
  const auto res = std::from_chars(text.data(), text.data() + text.size(), v);
  if (!text.empty() && res.ec == std::errc() && res.ptr == text.data() + text.size() &&
      (bare_number_is_si(key.dimension) || v == 0))
    return v;
  return parse_quantity(text, key.dimension, where);
}

}  // namespace

std::string sweep_value_text(double v, const SweepKey& key) {
  char buf[64];
  if (key.integer) {
    std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(std::llround(v)));
    return buf;
  }
  std::snprintf(buf, sizeof buf, "%.17g", v);
  const std::string unit(si_unit(key.dimension));
  // Angles and speeds need a unit even in SI; others read plain numbers as SI.
  return unit.empty() ? std::string(buf) : "\"" + std::string(buf) + " " + unit + "\"";
}

double sweep_uniform(std::uint64_t seed, std::size_t index, std::string_view key,
                     std::uint64_t stream) {
  std::uint64_t h = 0xcbf29ce484222325ULL;  // FNV-1a of the key
  for (const char ch : key) h = (h ^ static_cast<unsigned char>(ch)) * 0x100000001b3ULL;
  std::uint64_t x = splitmix(seed);
  x = splitmix(x ^ h);
  x = splitmix(x ^ static_cast<std::uint64_t>(index));
  x = splitmix(x ^ stream);
  return (static_cast<double>(x >> 11) + 0.5) * 0x1.0p-53;  // in (0, 1), never 0 or 1
}

std::unique_ptr<SweepDesign> grid_design(std::vector<SweepAxis> axes) {
  return std::make_unique<GridDesign>(std::move(axes));
}

std::unique_ptr<SweepDesign> random_design(std::vector<SweepSample> samples, std::size_t cases,
                                           std::uint64_t seed) {
  return std::make_unique<RandomDesign>(std::move(samples), cases, seed);
}

SweepSample parse_sample(std::string_view text) {
  const std::string t(text);
  const std::string usage =
      "--sample " + t +
      ": expected KEY=DIST(P1, P2) with DIST uniform(a, b), normal(mean, sd) or "
      "loguniform(a, b), e.g. operation.speed=uniform(1000rpm, 3000rpm)";
  const auto eq = t.find('=');
  const auto open = t.find('(', eq == std::string::npos ? 0 : eq);
  const auto comma = t.find(',', open == std::string::npos ? 0 : open);
  if (eq == std::string::npos || eq == 0 || open == std::string::npos ||
      comma == std::string::npos || t.back() != ')')
    throw InputError(usage);
  SweepSample s;
  s.key = key_of(t.substr(0, eq), "--sample " + t);
  s.distribution = trim(t.substr(eq + 1, open - eq - 1));
  if (s.distribution != "uniform" && s.distribution != "normal" && s.distribution != "loguniform")
    throw InputError("--sample " + t + ": unknown distribution \"" + s.distribution +
                     "\"; allowed: uniform(a, b), normal(mean, sd), loguniform(a, b)");
  const std::string a = trim(t.substr(open + 1, comma - open - 1));
  const std::string b = trim(t.substr(comma + 1, t.size() - comma - 2));
  const SweepKey as_real{s.key.key, s.key.dimension, false};
  s.p1 = parse_value(a, as_real, "--sample " + s.key.key + " (first parameter)");
  s.p2 = parse_value(b, as_real, "--sample " + s.key.key + " (second parameter)");
  if (s.distribution == "normal" && !(s.p2 >= 0))
    throw InputError("--sample " + t + ": the standard deviation must be ≥ 0");
  if (s.distribution != "normal" && !(s.p1 <= s.p2))
    throw InputError("--sample " + t + ": needs a ≤ b");
  if (s.distribution == "loguniform" && !(s.p1 > 0))
    throw InputError("--sample " + t + ": loguniform needs 0 < a ≤ b");
  return s;
}

std::unique_ptr<SweepDesign> list_design_from_csv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("--cases " + path + ": cannot read the file");
  std::string line;
  std::vector<SweepKey> keys;
  std::vector<std::vector<double>> rows;
  std::size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (trim(line).empty()) continue;
    const auto fields = split(line);
    const std::string where = "--cases " + path + " line " + std::to_string(number);
    if (keys.empty()) {
      for (const auto& f : fields) {
        if (f.empty()) throw InputError(where + ": an empty column name in the header");
        keys.push_back(key_of(f, where));
      }
      continue;
    }
    if (fields.size() != keys.size())
      throw InputError(where + ": " + std::to_string(fields.size()) + " fields, the header has " +
                       std::to_string(keys.size()));
    std::vector<double> row;
    for (std::size_t k = 0; k < keys.size(); ++k)
      row.push_back(parse_value(fields[k], keys[k], where + ", " + keys[k].key));
    rows.push_back(std::move(row));
  }
  if (keys.empty() || rows.empty())
    throw InputError("--cases " + path +
                     ": expected a header of case-file keys and at least one row of values");
  return std::make_unique<ListDesign>(std::move(keys), std::move(rows));
}

std::unique_ptr<SweepDesign> design_from_json(const std::string& json_text) {
  try {
    const json j = json::parse(json_text);
    const std::string kind = j.at("kind");
    if (kind == "grid") {
      std::vector<SweepAxis> axes;
      for (const auto& a : j.at("axes")) {
        const SweepKey k = key_of(a.at("key"));
        axes.push_back({k.key, a.at("values").get<std::vector<double>>(), k.dimension, k.integer});
      }
      return grid_design(std::move(axes));
    }
    if (kind == "random") {
      std::vector<SweepSample> samples;
      for (const auto& s : j.at("keys"))
        samples.push_back({key_of(s.at("key")), s.at("distribution"), s.at("parameters").at(0),
                           s.at("parameters").at(1)});
      return random_design(std::move(samples), j.at("samples"), j.at("seed"));
    }
    if (kind == "list") {
      std::vector<SweepKey> keys;
      for (const auto& k : j.at("keys")) keys.push_back(key_of(k));
      return std::make_unique<ListDesign>(std::move(keys),
                                          j.at("rows").get<std::vector<std::vector<double>>>());
    }
    throw InputError("unknown design kind \"" + kind + "\"");
  } catch (const json::exception& e) {
    throw InputError(std::string("not a sweep design: ") + e.what());
  }
}

}  // namespace bearing
