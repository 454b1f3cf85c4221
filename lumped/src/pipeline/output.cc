#include "bearing/output.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string_view>
#include <system_error>
#include <vector>

#include "bearing/acoustics/sources.h"
#include "bearing/atomic_file_set.h"
#include "bearing/constants.h"
#include "bearing/decimal.h"
#include "bearing/errors.h"
#include "bearing/json_helpers.h"
#include "bearing/npy.h"
#include "envelope_report.h"
#include "result_tables.h"

namespace bearing {

namespace fs = std::filesystem;

namespace {

// The run has a cage of its own (the [cage] table's kinds): its slip, speed and traction.
bool has_cage(const Case& c) {
  return model_descriptor(c.model.kind).owns("cage");
}

TableLayout write_response(const fs::path& path, OutputFormat format, const Response& r) {
  std::vector<std::string> names, units;
  for (const Channel& ch : r.channels) names.push_back(ch.name), units.push_back(ch.unit);
  return write_table(
      path, format, "t", "s", r.time, names, units,
      [&](std::size_t i, std::size_t k) { return r.values[i][k]; },
      [&](std::size_t i, std::size_t k) {
        return "response " + r.channels[i].name + " at t = " + std::to_string(r.time[k]) + " s";
      });
}

// The SI unit of the response channel `name` ("" if there is none of that name).
std::string unit_of(const Response& r, const std::string& name) {
  for (const Channel& ch : r.channels)
    if (ch.name == name) return ch.unit;
  return "";
}

// spectrum: frequency [Hz], then each ring channel's amplitude spectrum [unit of the channel].
TableLayout write_spectrum(const fs::path& path, OutputFormat format, const Response& r,
                           const RunSummary& s) {
  static const std::vector<double> none;
  std::vector<std::string> units;
  for (const auto& name : s.spectrum_channels) units.push_back(unit_of(r, name));
  return write_table(
      path, format, "frequency", "Hz", s.spectra.empty() ? none : s.spectra.front().frequency,
      s.spectrum_channels, units,
      [&](std::size_t i, std::size_t b) { return s.spectra[i].amplitude[b]; },
      [&](std::size_t i, std::size_t) { return "spectrum of " + s.spectrum_channels[i]; });
}

// envelope: frequency [Hz], then env_<channel> per ring acceleration (the envelope spectra) [unit
// of the channel].
TableLayout write_envelope(const fs::path& path, OutputFormat format, const RunSummary& s) {
  std::vector<std::string> names, units;
  for (const EnvelopeSummary& e : s.envelopes)
    names.push_back("env_" + e.channel), units.push_back(e.unit);
  return write_table(
      path, format, "frequency", "Hz", s.envelopes.front().spectrum.frequency, names, units,
      [&](std::size_t i, std::size_t b) { return s.envelopes[i].spectrum.amplitude[b]; },
      [&](std::size_t i, std::size_t) { return "envelope spectrum of " + s.envelopes[i].channel; });
}

// pressure: t over the analysis window [s], then p1…pM (one column per microphone) [Pa].
TableLayout write_pressure(const fs::path& path, OutputFormat format, const BearingNoise& noise) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < noise.pressure.size(); ++i)
    names.push_back("p" + std::to_string(i + 1));
  return write_table(
      path, format, "t", "s", noise.time, names, std::vector<std::string>(names.size(), "Pa"),
      [&](std::size_t i, std::size_t k) { return noise.pressure[i][k]; },
      [&](std::size_t i, std::size_t k) {
        return "sound pressure at microphone " + std::to_string(i + 1) +
               " at t = " + std::to_string(noise.time[k]) + " s";
      });
}

nlohmann::json acoustics_json(const Case& c, const BearingNoise& noise) {
  using nlohmann::json;
  const AcousticsOptions& ac = c.acoustics;
  const auto optional = [](const std::optional<double>& v) { return v ? json(*v) : json(nullptr); };
  json mics = json::array();
  for (const MicrophoneLevels& m : noise.microphones)
    mics.push_back({{"position", {m.position.x(), m.position.y()}},
                    {"radius", m.microphone.radius},
                    {"angle", m.microphone.angle},
                    {"p_rms", m.p_rms},
                    {"p_rms_ring", m.p_rms_ring},
                    {"p_rms_balls", m.p_rms_balls},
                    {"spl_total", optional(m.spl_total)},
                    {"spl_ring", optional(m.spl_ring)},
                    {"spl_balls", optional(m.spl_balls)},
                    {"nearest_ball_surface", optional(m.nearest_ball_surface)}});
  return {{"ring_source", name_of(kRingSources, ac.ring_source)},
          {"ring_model", source_model_name(ac.ring_source)},
          {"ball_source", name_of(kBallSources, ac.ball_source)},
          {"ball_model", source_model_name(ac.ball_source)},
          {"summation", name_of(kSummations, ac.summation)},
          {"ring_radius", ac.ring_radius},
          {"ball_radius", 0.5 * c.bearing.ball_diameter},
          {"ring_centre", {noise.ring_centre.x(), noise.ring_centre.y()}},
          {"density", ac.density},
          {"sound_speed", ac.sound_speed},
          {"band", {noise.band_low, noise.band_high}},
          {"reference_pressure", kReferencePressure},
          {"microphones", mics}};
}

// The case as it ran: its source, bearing, kind, law, operation and solver times.
nlohmann::json case_json(const Case& c, const SimulationResult& r) {
  nlohmann::json j = {{"source", c.source},
                      {"bearing", c.bearing.designation},
                      {"model", name_of(kModelKinds, c.model.kind)},
                      {"contact", name_of(kContactLaws, c.model.contact)},
                      {"speed", c.operation.speed},
                      {"load", {c.operation.load.x(), c.operation.load.y()}},
                      {"axial_load", c.operation.axial_load},
                      {"duration", c.solver.duration},
                      {"transient", c.solver.transient},
                      {"output_rate", c.solver.output_rate}};
  if (c.model.calibration) j["calibration"] = calibration_json(*c.model.calibration, r.contact);
  return j;
}

// Each channel's statistics and (but for the balls') its named peaks, into j.
void add_channels(const RunSummary& s, nlohmann::json& j) {
  using nlohmann::json;
  j["channels"] = json::object();
  j["peaks"] = json::object();
  for (const auto& ch : s.channels) {
    const auto& st = ch.statistics;
    j["channels"][ch.name] = {{"mean", st.mean},         {"rms", st.rms},     {"ptp", st.ptp},
                              {"kurtosis", st.kurtosis}, {"crest", st.crest}, {"unit", ch.unit}};
    if (ch.group == ChannelGroup::ball) continue;
    json peaks = json::array();
    for (const auto& p : ch.peaks)
      peaks.push_back({{"frequency", p.frequency},
                       {"amplitude", p.amplitude},
                       {"label", p.label},
                       {"label_error", p.label_error}});
    j["peaks"][ch.name] = peaks;
  }
}

// How the run was solved: the integrator's statistics, or the quasi-static Newton's (no
// integrator ran: solver.method, dt and tolerance did not matter), with their units.
void add_solver(const Case& c, const SimulationResult& r, nlohmann::json& j) {
  if (!r.quasi_static) {
    j["solver"] = {{"method", name_of(kIntegratorMethods, c.solver.method)},
                   {"dt", c.solver.dt},
                   {"tolerance", c.solver.tolerance},
                   {"steps", r.stats.steps},
                   {"rejected_steps", r.stats.rejected_steps},
                   {"force_evaluations", r.stats.force_evaluations}};
    return;
  }
  const QuasiStaticStats& q = *r.quasi_static;
  j["solver"] = {{"method", "quasistatic newton"},
                 {"steps", q.steps},
                 {"newton_iterations", q.newton_iterations},
                 {"fallbacks", q.fallbacks},
                 {"max_relative_residual", q.max_relative_residual},
                 {"min_loaded_balls", q.min_loaded_balls},
                 {"contact_changes", q.contact_changes},
                 {"jumps", q.jumps},
                 {"largest_jump", q.largest_jump},
                 {"minimum_load", q.minimum_load}};
  // F_smooth is infinite for Z <= 4 (JSON has no infinity): left out there.
  if (std::isfinite(q.smooth_load)) j["solver"]["smooth_load"] = q.smooth_load;
  j["units"]["solver.largest_jump"] = "m";
  j["units"]["solver.minimum_load"] = "N";
  j["units"]["solver.smooth_load"] = "N";
}

}  // namespace

nlohmann::json summary_json(const Case& c, const SimulationResult& r, const RunSummary& s) {
  using nlohmann::json;
  json j;
  j["case"] = case_json(c, r);
  // The contact law the run used: Q = K δ^n per race and for the ball between both races.
  const auto law = [](double K, double n) { return json{{"K", K}, {"exponent", n}}; };
  j["contact"] = law(r.contact.K, r.contact.exponent);
  j["contact"]["method"] = name_of(kContactLaws, r.contact.method);
  j["contact"]["inner"] = law(r.contact.inner.K, r.contact.inner.exponent);
  j["contact"]["outer"] = law(r.contact.outer.K, r.contact.outer.exponent);
  const auto& f = r.frequencies;
  j["frequencies"] = {
      {"shaft", f.shaft}, {"ftf", f.ftf}, {"bpfo", f.bpfo}, {"bpfi", f.bpfi}, {"bsf", f.bsf}};
  // The ball-DOF model's cage as it ran: the frequencies above already turn at ω_ca.
  if (has_cage(c))
    j["cage"] = {{"slip", c.cage.slip},
                 {"speed", r.cage_speed},
                 {"friction", c.cage.friction},
                 {"slide_speed", c.cage.slide_speed},
                 {"ball_mass", c.ball.mass},
                 {"ball_inertia", c.ball.inertia},
                 {"ball_damping", c.ball.damping},
                 {"centrifugal", c.ball.centrifugal}};
  // The outer ring's support as it ran (housing.h); absent when the outer ring is fixed.
  if (c.housing.enabled) j["housing"] = housing_json(c.housing);
  // The cage's random slip as it ran (random_slip.h): its correlation time resolved (the default,
  // one ball pass, is 1/BPFO at the model's cage speed).
  if (c.slip.enabled()) j["slip"] = slip_json(c.slip, f.bpfo);
  add_channels(s, j);
  // The families the peaks were named after (those the case's excitations make): a peak no
  // family explains stays unnamed.
  j["peak_families"] = line_family_names(s.peak_families);
  j["units"] = {{"frequencies", "Hz"},
                {"channels", "see channels.<name>.unit (kurtosis and crest: 1)"},
                {"peaks.frequency", "Hz"},
                {"peaks.amplitude", "unit of the channel"},
                {"peaks.label_error", "Hz"},
                {"case.speed", "rad/s"},
                {"case.load", "N"},
                {"case.duration", "s"},
                {"contact.K", "N/m^exponent (contact.exponent)"},
                {"contact.*.K", "N/m^exponent"}};
  add_solver(c, r, j);
  if (c.model.calibration) j["units"]["case.calibration.load_range"] = "N";
  if (has_cage(c)) {
    j["units"]["cage.speed"] = "rad/s";
    j["units"]["cage.slide_speed"] = "m/s";
    j["units"]["cage.ball_mass"] = "kg";
    j["units"]["cage.ball_inertia"] = "kg m^2";
    j["units"]["cage.ball_damping"] = "N s/m";
  }
  if (c.housing.enabled) add_housing_units(c.housing, j["units"]);
  if (c.slip.enabled()) add_slip_units(j["units"]);
  if (!s.envelopes.empty()) {
    j["envelope"] = envelope_json(s.envelopes);
    add_envelope_units(j["units"]);
  }
  if (s.diagnosis) j["diagnosis"] = diagnosis_json(*s.diagnosis);
  if (s.noise) {
    j["acoustics"] = acoustics_json(c, *s.noise);
    j["units"]["acoustics.microphones.spl_*"] = "dB re 20 uPa (null: source \"none\", or silent)";
    j["units"]["acoustics.microphones.p_rms*"] = "Pa";
    j["units"]["acoustics.microphones.{position,radius,nearest_ball_surface}"] = "m";
    j["units"]["acoustics.microphones.angle"] = "rad";
    j["units"]["acoustics.{ring_radius,ball_radius,ring_centre}"] = "m";
    j["units"]["acoustics.band"] = "Hz";
    j["units"]["acoustics.{density,sound_speed,reference_pressure}"] = "kg/m^3, m/s, Pa";
  }
  require_finite(j);
  return j;
}

std::string summary_text(const Case& c, const SimulationResult& r, const RunSummary& s) {
  std::ostringstream o;
  char buf[256];
  const auto& f = r.frequencies;
  o << "Case: " << c.source << " — bearing " << c.bearing.designation << ", model "
    << name_of(kModelKinds, c.model.kind) << ", "
    << (r.quasi_static ? "quasistatic newton" : name_of(kIntegratorMethods, c.solver.method))
    << "\n";
  std::snprintf(
      buf, sizeof buf,
      "Frequencies: shaft %.3f Hz, FTF %.3f Hz, BPFO %.3f Hz, BPFI %.3f Hz, BSF %.3f Hz\n", f.shaft,
      f.ftf, f.bpfo, f.bpfi, f.bsf);
  o << buf;
  if (has_cage(c)) {
    std::snprintf(buf, sizeof buf,
                  "Cage: slip %.4g %% (speed %.4g rad/s); traction mu_m %.4g at %.4g m/s; ball "
                  "%.4g g, %.4g kg m^2, damping %.4g N s/m, centrifugal %s\n",
                  100 * c.cage.slip, r.cage_speed, c.cage.friction, c.cage.slide_speed,
                  1e3 * c.ball.mass, c.ball.inertia, c.ball.damping,
                  c.ball.centrifugal ? "on" : "off");
    o << buf;
  }
  if (c.slip.enabled()) o << slip_line(c.slip, r.frequencies.bpfo);
  if (c.housing.enabled && c.housing.modal()) {
    const StructureModes& m = *c.housing.modes;
    std::snprintf(buf, sizeof buf, "Housing: %d structure modes, %.4g to %.4g Hz alone (%s)\n",
                  m.count(), m.frequencies.front(), m.frequencies.back(), m.path.c_str());
    o << buf;
  } else if (c.housing.enabled) {
    std::snprintf(buf, sizeof buf,
                  "Housing: %.4g kg at %.4g Hz on its support alone, damping ratio %.4g "
                  "(k %.4g N/m, c %.4g N s/m)\n",
                  c.housing.mass, c.housing.frequency, c.housing.damping_ratio,
                  c.housing.stiffness(), c.housing.damping());
    o << buf;
  }
  std::snprintf(buf, sizeof buf, "Statistics over %.4g s after a %.4g s transient:\n",
                c.solver.duration - c.solver.transient, c.solver.transient);
  o << buf;
  int width = 3;  // the names in one column: x, vy, ... and ay_housing
  for (const auto& ch : s.channels)
    if (ch.group != ChannelGroup::ball) width = std::max(width, static_cast<int>(ch.name.size()));
  for (const auto& ch : s.channels) {
    if (ch.group == ChannelGroup::ball) continue;
    const auto& st = ch.statistics;
    std::snprintf(buf, sizeof buf,
                  "  %-*s mean %11.4g  rms %11.4g  ptp %11.4g %-6s kurtosis %6.3f  crest %6.3f",
                  width, ch.name.c_str(), st.mean, st.rms, st.ptp, ch.unit.c_str(), st.kurtosis,
                  st.crest);
    o << buf;
    if (!ch.peaks.empty()) {
      const auto& p = ch.peaks.front();
      std::snprintf(buf, sizeof buf, "  peak %.2f Hz %s", p.frequency,
                    p.label.empty() ? "(unlabelled)" : p.label.c_str());
      o << buf;
    }
    o << "\n";
  }
  std::string families;
  for (const std::string& name : line_family_names(s.peak_families))
    families += (families.empty() ? "" : ", ") + name;
  o << "  (peaks named after the case's line families: " << families << ")\n";
  o << envelope_text(s);
  if (r.quasi_static)
    std::snprintf(buf, sizeof buf,
                  "Solver: quasi-static Newton, %ld instants, %ld iterations, %ld fallbacks, "
                  "max residual %.2g, min %d loaded balls, %ld jumps\n",
                  r.quasi_static->steps, r.quasi_static->newton_iterations,
                  r.quasi_static->fallbacks, r.quasi_static->max_relative_residual,
                  r.quasi_static->min_loaded_balls, r.quasi_static->jumps);
  else
    std::snprintf(buf, sizeof buf, "Solver: %ld steps, %ld force evaluations\n", r.stats.steps,
                  r.stats.force_evaluations);
  o << buf;
  if (s.noise) {
    const AcousticsOptions& ac = c.acoustics;
    std::snprintf(buf, sizeof buf,
                  "Sound (dB re 20 uPa, %s sum, %.4g Hz … %.4g kHz; ring %s, balls %s):\n",
                  name_of(kSummations, ac.summation), s.noise->band_low, s.noise->band_high / 1e3,
                  name_of(kRingSources, ac.ring_source), name_of(kBallSources, ac.ball_source));
    o << buf;
    // A missing level is a source left out ("none") or one that did not move (SPL −∞).
    const auto db = [](const std::optional<double>& v, bool present) {
      char b[32];
      if (v)
        std::snprintf(b, sizeof b, "%6.1f dB", *v);
      else
        std::snprintf(b, sizeof b, "%9s", present ? "silent" : "none");
      return std::string(b);
    };
    const bool ring = ac.ring_source != RingSource::none;
    const bool balls = ac.ball_source != BallSource::none;
    for (std::size_t i = 0; i < s.noise->microphones.size(); ++i) {
      const MicrophoneLevels& m = s.noise->microphones[i];
      std::snprintf(buf, sizeof buf, "  microphone %zu at %.4g mm, %.4g deg:", i + 1,
                    m.microphone.radius * 1e3, m.microphone.angle * 180 / pi);
      o << buf << "  total " << db(m.spl_total, true) << "  ring " << db(m.spl_ring, ring)
        << "  balls " << db(m.spl_balls, balls);
      std::snprintf(buf, sizeof buf, "  (p_rms %.3g Pa)\n", m.p_rms);
      o << buf;
    }
  }
  return o.str();
}

void write_run(const std::string& dir, const Case& c, const SimulationResult& r,
               const RunSummary& s) {
  // The small files are formatted (and checked for non-finite values) first; the large ones are
  // checked while they stream. Every file goes to a temporary name; the set is renamed into place
  // only when all are complete, and a failure removes what was written.
  const std::string summary = summary_json(c, r, s).dump(2) + "\n";
  const std::string resolved = case_to_toml(c);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError("--out " + dir + ": cannot create the folder (" + ec.message() + ")");
  const OutputFormat format = c.output.format;
  const std::string ext = format == OutputFormat::npy ? ".npy" : ".csv";
  std::vector<std::string> names = {"response" + ext, "spectrum" + ext, "summary.json",
                                    "case.toml"};
  if (s.noise) names.push_back("pressure" + ext);
  if (!s.envelopes.empty()) names.push_back("envelope" + ext);
  if (format == OutputFormat::npy) names.push_back("columns.json");
  // Every result file a run can write: those not in this set are an earlier run's (another
  // format, no acoustics or envelope now) and go, with their temporaries a killed run left.
  std::vector<std::string> stale;
  for (const char* stem : {"response", "spectrum", "pressure", "envelope"})
    for (const char* e : {".csv", ".npy"}) stale.push_back(std::string(stem) + e);
  for (const char* other : {"summary.json", "case.toml", "columns.json"}) stale.push_back(other);
  stale.erase(std::remove_if(stale.begin(), stale.end(),
                             [&](const std::string& n) {
                               return std::find(names.begin(), names.end(), n) != names.end();
                             }),
              stale.end());
  // Runs into one folder write and commit one at a time (two at once would write the same
  // temporary files); a failure removes what was written.
  AtomicFileSet files(dir, names, stale, "--out " + dir);
  std::vector<fs::path> temporary;
  for (const auto& name : names) temporary.push_back(files.temporary(name));
  std::vector<std::string> table_files;
  std::vector<TableLayout> tables;
  const auto table = [&](std::size_t i, TableLayout layout) {
    table_files.push_back(names[i]);
    tables.push_back(std::move(layout));
  };
  table(0, write_response(temporary[0], format, r.response));
  table(1, write_spectrum(temporary[1], format, r.response, s));
  write_text(temporary[2], summary);
  write_text(temporary[3], resolved);
  std::size_t next = 4;
  if (s.noise) table(next, write_pressure(temporary[next], format, *s.noise)), ++next;
  if (!s.envelopes.empty()) table(next, write_envelope(temporary[next], format, s)), ++next;
  if (format == OutputFormat::npy) write_text(temporary[next], columns_json(table_files, tables));
  files.commit();
}

}  // namespace bearing
