#include "bearing/output.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "bearing/errors.h"
#include "bearing/info_report.h"

namespace bearing {

namespace fs = std::filesystem;

namespace {

// Shortest text that reads back to the same double (std::to_chars), for CSV.
void append(std::string& line, double v) {
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  line.append(buf, res.ptr);
}

// `what` builds the message only when it is needed (the check runs for every value written).
template <class What>
void require_finite_value(double v, const What& what) {
  if (!std::isfinite(v)) throw SolverError(what() + " is not finite; no result files were written");
}

std::string response_csv(const Response& r) {
  std::string out = "t";
  for (std::size_t i = 0; i < r.channels.size(); ++i) out += "," + r.channels[i];
  out += "\n";
  out.reserve(out.size() + r.time.size() * (r.channels.size() + 1) * 14);
  for (std::size_t k = 0; k < r.time.size(); ++k) {
    append(out, r.time[k]);
    for (std::size_t i = 0; i < r.channels.size(); ++i) {
      const double v = r.values[i][k];
      require_finite_value(v, [&] {
        return "response " + r.channels[i] + " at t = " + std::to_string(r.time[k]) + " s";
      });
      out += ',';
      append(out, v);
    }
    out += '\n';
  }
  return out;
}

std::string spectrum_csv(const RunSummary& s) {
  std::string out = "frequency";
  for (const auto& name : s.spectrum_channels) out += "," + name;
  out += "\n";
  if (s.spectra.empty()) return out;
  const std::size_t bins = s.spectra.front().frequency.size();
  for (std::size_t b = 0; b < bins; ++b) {
    append(out, s.spectra.front().frequency[b]);
    for (std::size_t i = 0; i < s.spectra.size(); ++i) {
      const double v = s.spectra[i].amplitude[b];
      require_finite_value(v, [&] { return "spectrum of " + s.spectrum_channels[i]; });
      out += ',';
      append(out, v);
    }
    out += '\n';
  }
  return out;
}

void write_file(const fs::path& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  if (!f) throw InputError("cannot write " + path.string());
  f << text;
  f.close();
  if (!f) throw InputError("cannot write " + path.string() + " (disk full?)");
}

}  // namespace

nlohmann::json summary_json(const Case& c, const SimulationResult& r, const RunSummary& s) {
  using nlohmann::json;
  json j;
  j["case"] = {{"source", c.source},
               {"bearing", c.bearing.designation},
               {"model", c.model.kind},
               {"contact", c.model.contact},
               {"speed", c.operation.speed},
               {"load", {c.operation.load.x(), c.operation.load.y()}},
               {"axial_load", c.operation.axial_load},
               {"duration", c.solver.duration},
               {"transient", c.solver.transient},
               {"output_rate", c.solver.output_rate}};
  const auto& f = r.frequencies;
  j["frequencies"] = {
      {"shaft", f.shaft}, {"ftf", f.ftf}, {"bpfo", f.bpfo}, {"bpfi", f.bpfi}, {"bsf", f.bsf}};
  j["channels"] = json::object();
  j["peaks"] = json::object();
  for (const auto& ch : s.channels) {
    const auto& st = ch.statistics;
    j["channels"][ch.name] = {{"mean", st.mean},         {"rms", st.rms},     {"ptp", st.ptp},
                              {"kurtosis", st.kurtosis}, {"crest", st.crest}, {"unit", ch.unit}};
    if (ch.name.front() == 'Q') continue;
    json peaks = json::array();
    for (const auto& p : ch.peaks)
      peaks.push_back({{"frequency", p.frequency}, {"amplitude", p.amplitude}, {"label", p.label}});
    j["peaks"][ch.name] = peaks;
  }
  j["solver"] = {{"method", c.solver.method},
                 {"dt", c.solver.dt},
                 {"tolerance", c.solver.tolerance},
                 {"steps", r.stats.steps},
                 {"rejected_steps", r.stats.rejected_steps},
                 {"force_evaluations", r.stats.force_evaluations}};
  j["units"] = {
      {"frequencies", "Hz"},     {"channels", "see channels.<name>.unit (kurtosis and crest: 1)"},
      {"peaks.frequency", "Hz"}, {"peaks.amplitude", "unit of the channel"},
      {"case.speed", "rad/s"},   {"case.load", "N"},
      {"case.duration", "s"}};
  require_finite(j);
  return j;
}

std::string summary_text(const Case& c, const SimulationResult& r, const RunSummary& s) {
  std::ostringstream o;
  char buf[256];
  const auto& f = r.frequencies;
  o << "Case: " << c.source << " — bearing " << c.bearing.designation << ", model " << c.model.kind
    << ", " << c.solver.method << "\n";
  std::snprintf(
      buf, sizeof buf,
      "Frequencies: shaft %.3f Hz, FTF %.3f Hz, BPFO %.3f Hz, BPFI %.3f Hz, BSF %.3f Hz\n", f.shaft,
      f.ftf, f.bpfo, f.bpfi, f.bsf);
  o << buf;
  std::snprintf(buf, sizeof buf, "Statistics over %.4g s after a %.4g s transient:\n",
                c.solver.duration - c.solver.transient, c.solver.transient);
  o << buf;
  for (const auto& ch : s.channels) {
    if (ch.name.front() == 'Q') continue;
    const auto& st = ch.statistics;
    std::snprintf(buf, sizeof buf,
                  "  %-3s mean %11.4g  rms %11.4g  ptp %11.4g %-6s kurtosis %6.3f  crest %6.3f",
                  ch.name.c_str(), st.mean, st.rms, st.ptp, ch.unit.c_str(), st.kurtosis, st.crest);
    o << buf;
    if (!ch.peaks.empty()) {
      const auto& p = ch.peaks.front();
      std::snprintf(buf, sizeof buf, "  peak %.2f Hz %s", p.frequency,
                    p.label.empty() ? "(unlabelled)" : p.label.c_str());
      o << buf;
    }
    o << "\n";
  }
  std::snprintf(buf, sizeof buf, "Solver: %ld steps, %ld force evaluations\n", r.stats.steps,
                r.stats.force_evaluations);
  o << buf;
  return o.str();
}

void write_run(const std::string& dir, const Case& c, const SimulationResult& r,
               const RunSummary& s) {
  // Everything is formatted (and checked for non-finite values) before anything is written.
  const std::vector<std::pair<std::string, std::string>> files = {
      {"response.csv", response_csv(r.response)},
      {"spectrum.csv", spectrum_csv(s)},
      {"summary.json", summary_json(c, r, s).dump(2) + "\n"},
      {"case.toml", case_to_toml(c)}};
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError("--out " + dir + ": cannot create the folder (" + ec.message() + ")");
  std::vector<fs::path> temporary;
  try {
    for (const auto& [name, text] : files) {
      const fs::path tmp = fs::path(dir) / ("." + name + ".partial");
      temporary.push_back(tmp);
      write_file(tmp, text);
    }
    for (std::size_t i = 0; i < files.size(); ++i)
      fs::rename(temporary[i], fs::path(dir) / files[i].first);
  } catch (const fs::filesystem_error& e) {
    for (const auto& t : temporary) fs::remove(t, ec);
    throw InputError("--out " + dir + ": " + e.what());
  } catch (...) {
    for (const auto& t : temporary) fs::remove(t, ec);
    throw;
  }
}

}  // namespace bearing
