// The result folder of an analysed record: summary.json, the readable summary, the tables.

#include "bearing/record_output.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>

#include "bearing/atomic_file_set.h"
#include "bearing/constants.h"
#include "bearing/json_helpers.h"
#include "bearing/units.h"
#include "coherence_report.h"
#include "envelope_report.h"
#include "result_tables.h"

namespace bearing {

namespace {

using nlohmann::json;

const char* kRefinement =
    "f_r = sum(k f_k) / sum(k^2) over the used harmonics (least squares of f_k = k f_r), each "
    "f_k refined by a parabola through the log amplitudes of the three bins around its peak";

json speed_json(const RecordAnalysis& a, const RecordOrigin& origin) {
  const RecordSpeed& sp = a.speed;
  json j = {{"value", sp.speed},
            {"shaft", sp.speed / two_pi},
            {"rpm", sp.speed * 60 / two_pi},
            {"source", name_of(kSpeedSources, sp.source)},
            {"origin", origin.speed_origin}};
  if (sp.given) j["given"] = *sp.given;
  if (sp.estimate) {
    const FundamentalEstimate& e = *sp.estimate;
    json harmonics = json::array();
    for (const HarmonicLine& h : e.harmonics)
      harmonics.push_back({{"order", h.order},
                           {"frequency", h.frequency},
                           {"amplitude", h.amplitude},
                           {"level", h.level},
                           {"used", h.used}});
    j["estimate"] = {{"nominal", two_pi * e.nominal}, {"tolerance", e.tolerance},
                     {"harmonics", harmonics},        {"evidence", e.comb.evidence},
                     {"threshold", e.comb.threshold}, {"false_alarm", e.comb.false_alarm},
                     {"refinement", kRefinement}};
  }
  return j;
}

json family_json(const FamilyLines& f) {
  json lines = json::array();
  for (std::size_t i = 0; i < f.comb.lines.size(); ++i) {
    const CombLine& l = f.comb.lines[i];
    lines.push_back({{"label", f.labels[i]},
                     {"harmonic", l.harmonic},
                     {"sideband", l.sideband},
                     {"nominal", l.nominal},
                     {"frequency", l.frequency},
                     {"amplitude", l.amplitude},
                     {"floor", l.floor},
                     {"floor_samples", l.floor_samples},
                     {"level", l.level},
                     {"rated", l.rated},
                     {"excluded", l.excluded}});
  }
  json excluding = json::array();
  for (FaultFamily e : f.excluding) excluding.push_back(name_of(kFaultFamilies, e));
  return {{"nominal", f.nominal},
          {"modulation", f.modulation},
          {"carrier", f.comb.carrier},
          {"offset", f.comb.offset},
          {"evidence", f.comb.evidence},
          {"threshold", f.comb.threshold},
          {"trials", f.comb.trials},
          {"rated_harmonics", f.comb.rated_harmonics},
          {"detected", f.comb.detected},
          {"excluding", excluding},
          {"lines", lines}};
}

json settings_json(const FaultLineSettings& s) {
  return {{"slip", s.slip},
          {"harmonics", s.harmonics},
          {"false_alarm", s.false_alarm},
          {"shaft_exclusion", s.shaft_exclusion}};
}

json fault_lines_json(const LineDiagnosis& d) {
  json j = {{"settings", settings_json(d.settings)}};
  for (const FamilyLines& f : d.families) j[name_of(kFaultFamilies, f.family)] = family_json(f);
  return j;
}

json line_diagnosis_json(const RecordAnalysis& a) {
  const LineDiagnosis& d = *a.lines;
  const EnvelopeSummary& e = a.summary.envelopes.front();
  json evidence = json::array();
  double level = 0, threshold = 0;
  for (const FamilyLines& f : d.families) {
    if (f.family != d.family) continue;
    level = f.comb.evidence, threshold = f.comb.threshold;
    for (std::size_t i : evidence_lines(f))
      evidence.push_back({{"label", f.labels[i]},
                          {"frequency", f.comb.lines[i].frequency},
                          {"amplitude", f.comb.lines[i].amplitude},
                          {"level", f.comb.lines[i].level}});
  }
  return {{"family", name_of(kFaultFamilies, d.family)},
          {"rule", name_of(kDiagnosisRules, DiagnosisRule::line_to_floor)},
          {"channel", e.channel},
          {"unit", "(" + e.unit + ")^2"},
          {"band", {e.band.low, e.band.high}},
          {"band_source", name_of(kEnvelopeBandSources, e.source)},
          {"spectral_kurtosis", e.spectral_kurtosis},
          {"prewhitened", a.prewhitened},
          {"evidence", evidence},
          {"evidence_level", level},
          {"threshold", threshold},
          {"margin", d.margin},
          {"reason", d.reason},
          {"thresholds", settings_json(d.settings)}};
}

void add_record_units(json& units, bool envelope) {
  units["record.rate"] = "Hz";
  units["record.duration"] = "s";
  units["case.speed"] = "rad/s";
  units["speed.{value,given}"] = "rad/s";
  units["speed.shaft"] = "Hz";
  units["speed.rpm"] = "rpm";
  units["speed.estimate.nominal"] = "rad/s";
  units["speed.estimate.harmonics.frequency"] = "Hz";
  units["speed.estimate.harmonics.amplitude"] = "unit of the channel";
  units["speed.estimate.{harmonics.level,evidence,threshold}"] = "dB";
  units["frequencies"] = "Hz";
  units["peaks.frequency"] = "Hz";
  units["peaks.amplitude"] = "unit of the channel";
  units["peaks.label_error"] = "Hz";
  units["channels"] = "see channels.<name>.unit (kurtosis and crest: 1)";
  if (!envelope) return;
  add_envelope_units(units);
  units["fault_lines.*.{nominal,modulation,carrier}"] = "Hz";
  units["fault_lines.*.{evidence,threshold}"] = "dB";
  units["fault_lines.*.lines.{nominal,frequency}"] = "Hz";
  units["fault_lines.*.lines.{amplitude,floor}"] = "unit of the channel, squared";
  units["fault_lines.*.lines.level"] = "dB";
  units["diagnosis.evidence.level"] = "dB";
  units["diagnosis.{evidence_level,threshold,margin}"] = "dB";
  add_coherence_units(units);
}

// printf into a string; the arguments' types must match the pattern's.
template <class... Args>
std::string format(const char* pattern, Args... args) {
  char buf[128];
  std::snprintf(buf, sizeof buf, pattern, args...);
  return buf;
}

std::string speed_text(const RecordAnalysis& a) {
  const RecordSpeed& sp = a.speed;
  std::string out = "Speed: " + format("%.6g rpm", sp.speed * 60 / two_pi) +
                    format(" (f_r %.5g Hz)", sp.speed / two_pi);
  switch (sp.source) {
    case SpeedSource::option:
      out += ", given";
      break;
    case SpeedSource::case_file:
      out += ", the case's operation.speed";
      break;
    case SpeedSource::record:
      out += ", stored in the record";
      break;
    case SpeedSource::estimate:
      break;
  }
  if (!sp.estimate) return out + "\n";
  const FundamentalEstimate& e = *sp.estimate;
  if (sp.given) out += format(", refined from %.6g rpm", *sp.given * 60 / two_pi);
  out += ", estimated within ±" + format("%.3g %%", 100 * e.tolerance) + " of " +
         format("%.6g rpm", e.nominal * 60) + " from the shaft harmonics";
  for (const HarmonicLine& h : e.harmonics)
    out += format(" %d×", h.order) + format(" %.5g Hz", h.frequency) +
           format(" (%.1f dB", h.level) + (h.used ? ")" : ", not used)");
  return out + "; comb " + format("%.1f dB", e.comb.evidence) + " over a threshold of " +
         format("%.1f dB", e.comb.threshold) + "\n";
}

std::string fault_lines_text(const LineDiagnosis& d) {
  std::string out = "Fault lines in the squared envelope spectrum (slip ±" +
                    format("%.3g %%", 100 * d.settings.slip) +
                    format(", %d harmonics", d.settings.harmonics) + ", false-alarm rate " +
                    format("%.3g", d.settings.false_alarm) + " per family):\n";
  for (const FamilyLines& f : d.families) {
    out += format("  %-6s", name_of(kFaultFamilies, f.family)) +
           format("%8.2f Hz", f.comb.carrier) + format(" (%+.2f %%)", 100 * f.comb.offset) +
           format(": %5.1f dB", f.comb.evidence) +
           format(" (threshold %.1f dB)", f.comb.threshold) + (f.comb.detected ? ", detected" : "");
    std::string lines;
    const std::vector<std::size_t> strongest = evidence_lines(f);
    for (std::size_t n = 0; n < std::min<std::size_t>(4, strongest.size()); ++n)
      lines += (n ? ", " : "") + f.labels[strongest[n]] +
               format(" %.1f dB", f.comb.lines[strongest[n]].level);
    out += (lines.empty() ? " — no line rated" : " — " + lines) + "\n";
  }
  return out;
}

}  // namespace

json record_summary_json(const RecordAnalysis& a, const RecordOrigin& origin) {
  json j;
  j["record"] = {{"file", origin.file},
                 {"channel", a.channel},
                 {"rate", a.rate},
                 {"rate_origin", origin.rate_origin},
                 {"samples", a.samples},
                 {"duration", static_cast<double>(a.samples) / a.rate},
                 {"unit", a.unit},
                 {"stored_unit", origin.stored_unit},
                 {"scale", origin.scale},
                 {"unit_origin", origin.unit_origin},
                 {"prewhitened", a.prewhitened}};
  j["case"] = {{"source", origin.case_source}, {"bearing", a.bearing}, {"speed", a.speed.speed}};
  j["speed"] = speed_json(a, origin);
  const BearingFrequencies& f = a.frequencies;
  j["frequencies"] = {
      {"shaft", f.shaft}, {"ftf", f.ftf}, {"bpfo", f.bpfo}, {"bpfi", f.bpfi}, {"bsf", f.bsf}};
  j["channels"] = json::object();
  j["peaks"] = json::object();
  for (const ChannelSummary& ch : a.summary.channels) {
    const ChannelStatistics& st = ch.statistics;
    j["channels"][ch.name] = {{"mean", st.mean},         {"rms", st.rms},     {"ptp", st.ptp},
                              {"kurtosis", st.kurtosis}, {"crest", st.crest}, {"unit", ch.unit}};
    json peaks = json::array();
    for (const Peak& p : ch.peaks)
      peaks.push_back({{"frequency", p.frequency},
                       {"amplitude", p.amplitude},
                       {"label", p.label},
                       {"label_error", p.label_error}});
    j["peaks"][ch.name] = peaks;
  }
  j["peak_families"] = line_family_names(a.summary.peak_families);
  j["units"] = json::object();
  const bool envelope = !a.summary.envelopes.empty();
  if (envelope) {
    j["envelope"] = envelope_json(a.summary.envelopes);
    j["envelope"][a.channel]["prewhitened"] = a.prewhitened;
    j["fault_lines"] = fault_lines_json(*a.lines);
    j["coherence"] = coherence_json(*a.coherence);
    if (a.settings.rule == DiagnosisRule::coherence) {
      j["diagnosis"] = coherence_diagnosis_json(*a.coherence);
    } else if (a.settings.rule == DiagnosisRule::line_to_floor) {
      j["diagnosis"] = line_diagnosis_json(a);
    } else {
      j["diagnosis"] = diagnosis_json(*a.summary.diagnosis);
      j["diagnosis"]["rule"] = name_of(kDiagnosisRules, DiagnosisRule::envelope_peaks);
    }
  }
  add_record_units(j["units"], envelope);
  require_finite(j);
  return j;
}

std::string record_summary_text(const RecordAnalysis& a, const RecordOrigin& origin) {
  std::ostringstream o;
  char buf[320];
  std::snprintf(buf, sizeof buf, "Record: %s, channel %s: %zu samples at %.6g Hz (%.4g s), %s\n",
                origin.file.empty() ? "(samples in memory)" : origin.file.c_str(),
                a.channel.c_str(), a.samples, a.rate, static_cast<double>(a.samples) / a.rate,
                a.unit.c_str());
  o << buf;
  if (!origin.stored_unit.empty())
    o << "  stored in " << origin.stored_unit
      << (origin.scale == 1.0 ? std::string() : " x " + format_number(origin.scale))
      << " (unit from " << origin.unit_origin << "), rate from " << origin.rate_origin << "\n";
  o << "Bearing " << a.bearing
    << (origin.case_source.empty() ? "" : " (case " + origin.case_source + ")") << "\n"
    << speed_text(a);
  const BearingFrequencies& f = a.frequencies;
  std::snprintf(
      buf, sizeof buf,
      "Frequencies: shaft %.3f Hz, FTF %.3f Hz, BPFO %.3f Hz, BPFI %.3f Hz, BSF %.3f Hz\n", f.shaft,
      f.ftf, f.bpfo, f.bpfi, f.bsf);
  o << buf;
  for (const ChannelSummary& ch : a.summary.channels) {
    const ChannelStatistics& st = ch.statistics;
    std::snprintf(buf, sizeof buf,
                  "  %s mean %11.4g  rms %11.4g  ptp %11.4g %-6s kurtosis %6.3f  crest %6.3f",
                  ch.name.c_str(), st.mean, st.rms, st.ptp, ch.unit.c_str(), st.kurtosis, st.crest);
    o << buf;
    if (!ch.peaks.empty())
      o << format("  peak %.2f Hz ", ch.peaks.front().frequency)
        << (ch.peaks.front().label.empty() ? "(unlabelled)" : ch.peaks.front().label);
    o << "\n";
  }
  if (a.summary.envelopes.empty()) return o.str() + "No envelope analysis (band none).\n";
  VibrationSummary envelopes_only = a.summary;  // the envelope lines without run's diagnosis line
  envelopes_only.diagnosis.reset();
  o << envelope_text(envelopes_only) << (a.prewhitened ? "  (of the pre-whitened record)\n" : "");
  o << fault_lines_text(*a.lines);
  if (a.settings.rule == DiagnosisRule::coherence) {
    o << coherence_text(*a.coherence);
  } else if (a.settings.rule == DiagnosisRule::line_to_floor) {
    o << "Diagnosis: " << fault_family_text(a.lines->family) << " — " << a.lines->reason << "\n";
  } else {
    VibrationSummary run_rule;
    run_rule.envelopes.push_back(a.summary.envelopes.front());
    run_rule.diagnosis = a.summary.diagnosis;
    const std::string text = envelope_text(run_rule);
    o << text.substr(text.find("Diagnosis:"));
  }
  return o.str();
}

void write_record_analysis(const std::string& dir, const RecordAnalysis& a,
                           const RecordOrigin& origin, OutputFormat format) {
  namespace fs = std::filesystem;
  // The summary is formatted (and checked for non-finite values) first; the tables are checked
  // while they stream. All or nothing: AtomicFileSet, as write_run.
  const std::string summary = record_summary_json(a, origin).dump(2) + "\n";
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError("--out " + dir + ": cannot create the folder (" + ec.message() + ")");
  const std::string ext = format == OutputFormat::npy ? ".npy" : ".csv";
  const VibrationSummary& s = a.summary;
  const bool envelope = !s.envelopes.empty();
  std::vector<std::string> names = {"spectrum" + ext, "summary.json"};
  if (envelope) names.push_back("envelope" + ext);
  if (format == OutputFormat::npy) names.push_back("columns.json");
  // What a run or an analysis may leave in the folder that this one does not write.
  std::vector<std::string> others;
  for (const char* stem : {"response", "spectrum", "pressure", "envelope"})
    for (const char* e : {".csv", ".npy"}) others.push_back(std::string(stem) + e);
  for (const char* other : {"summary.json", "case.toml", "columns.json"}) others.push_back(other);
  others.erase(std::remove_if(others.begin(), others.end(),
                              [&](const std::string& n) {
                                return std::find(names.begin(), names.end(), n) != names.end();
                              }),
               others.end());
  AtomicFileSet files(dir, names, others, "--out " + dir);
  std::vector<std::string> table_files = {names[0]};
  const Spectrum& sp = s.spectra.front();
  std::vector<TableLayout> tables = {write_table(
      files.temporary(names[0]), format, "frequency", "Hz", sp.frequency, {a.channel}, {a.unit},
      [&](std::size_t, std::size_t b) { return sp.amplitude[b]; },
      [&](std::size_t, std::size_t) { return "spectrum of " + a.channel; })};
  write_text(files.temporary("summary.json"), summary);
  if (envelope) {
    // envelope: the envelope spectrum [unit] and the squared envelope spectrum [unit²].
    const Spectrum& env = s.envelopes.front().spectrum;
    const Spectrum& ses = *a.squared_envelope;
    table_files.push_back(names[2]);
    tables.push_back(write_table(
        files.temporary(names[2]), format, "frequency", "Hz", env.frequency,
        {"env_" + a.channel, "ses_" + a.channel}, {a.unit, "(" + a.unit + ")^2"},
        [&](std::size_t i, std::size_t b) { return i == 0 ? env.amplitude[b] : ses.amplitude[b]; },
        [&](std::size_t i, std::size_t) {
          return (i == 0 ? "envelope spectrum of " : "squared envelope spectrum of ") + a.channel;
        }));
  }
  if (format == OutputFormat::npy)
    write_text(files.temporary("columns.json"), columns_json(table_files, tables));
  files.commit();
}

}  // namespace bearing
