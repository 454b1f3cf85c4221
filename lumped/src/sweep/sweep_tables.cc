// The tables of `sweep --save` (sweep_tables.h).

#include "bearing/sweep_tables.h"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <utility>

#include "bearing/errors.h"
#include "bearing/output.h"

namespace bearing {

namespace {

constexpr std::pair<SweepSave, const char*> kSaveNames[] = {{SweepSave::response, "response"},
                                                            {SweepSave::spectrum, "spectrum"},
                                                            {SweepSave::envelope, "envelope"},
                                                            {SweepSave::summary, "summary"}};

// The abscissa `x` [x_unit] then one column per name with column(i)[k]: the layout of the .npy
// tables of output.cc (write_table there), whose names and units columns.json lists.
template <class Column>
SweepTable make_table(const std::string& x_name, const std::string& x_unit,
                      const std::vector<double>& x, const std::vector<std::string>& names,
                      const std::vector<std::string>& units, const Column& column) {
  SweepTable t;
  t.rows = x.size();
  t.columns.push_back(x_name);
  t.units.push_back(x_unit);
  t.columns.insert(t.columns.end(), names.begin(), names.end());
  t.units.insert(t.units.end(), units.begin(), units.end());
  const std::size_t width = t.columns.size();
  t.values.resize(t.rows * width);
  for (std::size_t k = 0; k < t.rows; ++k) t.values[k * width] = x[k];
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::vector<double>& v = column(i);
    for (std::size_t k = 0; k < t.rows; ++k) t.values[k * width + 1 + i] = v[k];
  }
  return t;
}

SweepTable response_table(const Response& r) {
  std::vector<std::string> names, units;
  for (const Channel& ch : r.channels) names.push_back(ch.name), units.push_back(ch.unit);
  return make_table("t", "s", r.time, names, units,
                    [&](std::size_t i) -> const std::vector<double>& { return r.values[i]; });
}

std::string unit_of(const Response& r, const std::string& name) {
  for (const Channel& ch : r.channels)
    if (ch.name == name) return ch.unit;
  return "";
}

SweepTable spectrum_table(const Response& r, const RunSummary& s) {
  static const std::vector<double> none;
  std::vector<std::string> units;
  for (const auto& name : s.spectrum_channels) units.push_back(unit_of(r, name));
  return make_table("frequency", "Hz", s.spectra.empty() ? none : s.spectra.front().frequency,
                    s.spectrum_channels, units, [&](std::size_t i) -> const std::vector<double>& {
                      return s.spectra[i].amplitude;
                    });
}

SweepTable envelope_table(const RunSummary& s) {
  std::vector<std::string> names, units;
  for (const EnvelopeSummary& e : s.envelopes)
    names.push_back("env_" + e.channel), units.push_back(e.unit);
  return make_table("frequency", "Hz", s.envelopes.front().spectrum.frequency, names, units,
                    [&](std::size_t i) -> const std::vector<double>& {
                      return s.envelopes[i].spectrum.amplitude;
                    });
}

// summary: (5, channels), rows mean, rms, ptp, kurtosis, crest.
SweepTable summary_table(const RunSummary& s) {
  SweepTable t;
  t.row_names = {"mean", "rms", "ptp", "kurtosis", "crest"};
  t.rows = t.row_names.size();
  for (const ChannelSummary& ch : s.channels)
    t.columns.push_back(ch.name), t.units.push_back(ch.unit);
  const std::size_t width = t.columns.size();
  t.values.resize(t.rows * width);
  for (std::size_t i = 0; i < width; ++i) {
    const auto& st = s.channels[i].statistics;
    const double v[] = {st.mean, st.rms, st.ptp, st.kurtosis, st.crest};
    for (std::size_t k = 0; k < t.rows; ++k) t.values[k * width + i] = v[k];
  }
  return t;
}

bool has(const std::vector<SweepSave>& what, SweepSave w) {
  return std::find(what.begin(), what.end(), w) != what.end();
}

}  // namespace

std::vector<SweepSave> parse_sweep_save(const std::vector<std::string>& texts) {
  std::vector<SweepSave> out;
  for (const std::string& text : texts) {
    std::string_view rest = text;
    while (true) {
      const std::size_t comma = rest.find(',');
      const std::string_view name = rest.substr(0, comma);
      bool found = false;
      for (const auto& [w, n] : kSaveNames)
        if (name == n) {
          found = true;
          if (!has(out, w)) out.push_back(w);
        }
      if (!found)
        throw InputError("--save " + text + ": unknown \"" + std::string(name) +
                         "\"; allowed: response, spectrum, envelope, summary (a comma list, or "
                         "--save repeated)");
      if (comma == std::string_view::npos) break;
      rest.remove_prefix(comma + 1);
    }
  }
  return out;
}

const char* sweep_save_name(SweepSave what) {
  for (const auto& [w, n] : kSaveNames)
    if (w == what) return n;
  return "";
}

SweepCaseTables sweep_case_tables(const Case& c, const SimulationResult& r, const RunSummary& s,
                                  const std::vector<SweepSave>& what) {
  const bool summary = has(what, SweepSave::summary);
  return sweep_case_tables(case_to_toml(c), r.response, s,
                           summary ? summary_json(c, r, s).dump(2) + "\n" : std::string(), what);
}

SweepCaseTables sweep_case_tables(std::string case_toml, const Response& response,
                                  const RunSummary& s, std::string summary_json,
                                  const std::vector<SweepSave>& what) {
  SweepCaseTables out;
  out.case_toml = std::move(case_toml);
  for (SweepSave w : what) {
    SweepTable t;
    if (w == SweepSave::response) t = response_table(response);
    if (w == SweepSave::spectrum) t = spectrum_table(response, s);
    if (w == SweepSave::envelope) {
      if (s.envelopes.empty()) continue;
      t = envelope_table(s);
    }
    if (w == SweepSave::summary) {
      t = summary_table(s);
      out.summary_json = std::move(summary_json);
    }
    t.name = sweep_save_name(w);
    // As run's files (output.cc): no NaN or Inf reaches sweep.h5; the case is reported failed.
    for (double v : t.values)
      if (!std::isfinite(v))
        throw SolverError("--save: the " + t.name + " table of this case holds a non-finite value");
    out.tables.push_back(std::move(t));
  }
  return out;
}

}  // namespace bearing
