#include "case_rules.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <string>
#include <vector>
#include "bearing/constants.h"

#include "bearing/calibration.h"
#include "bearing/models/model_registry.h"
#include "bearing/presets.h"
#include "key_builders.h"

namespace bearing::case_schema {

namespace {

std::string join_path(const std::string& base_dir, const std::string& path) {
  if (base_dir.empty() || path.empty() || path.front() == '/') return path;
  return base_dir + "/" + path;
}

// One [[waviness.<race>]] entry: a CSV table's rows, or one harmonic.
void read_waviness_entry(TableReader& r, const std::string& shown, const std::string& schema,
                         const ReadContext& context, std::vector<WavinessHarmonic>& out) {
  if (const auto table = r.text("table")) {
    for (const char* k : {"order", "amplitude", "phase"})
      if (r.has(k))
        throw InputError(r.full(k) +
                         ": give either table = \"file.csv\" or order/amplitude/"
                         "phase in one [[" +
                         schema + "]] entry, not both");
    const auto rows = read_waviness_table(join_path(context.base_dir, *table), r.full("table"));
    out.insert(out.end(), rows.begin(), rows.end());
    return;
  }
  const auto order = r.integer("order");
  const auto amplitude = r.quantity("amplitude");
  if (!order || !amplitude)
    throw InputError(shown +
                     ": each entry needs order and amplitude (phase optional), or "
                     "table = \"file.csv\"");
  if (*order < -1000000000LL || *order > 1000000000LL)  // the range is check_waviness's
    throw InputError(r.full("order") + " = " + std::to_string(*order) + ": too large");
  WavinessHarmonic h;
  h.order = static_cast<int>(*order);
  h.amplitude = *amplitude;
  h.phase = r.quantity("phase").value_or(0.0);
  out.push_back(h);
}

}  // namespace

void read_preset(TableReader& r, Case& c, const ReadContext&) {
  if (const auto p = r.text("preset", /*allow_integer=*/true)) {
    c.preset = *p;
    c.bearing = preset(*p);
  } else {
    c.bearing.designation = "custom";
  }
}

void read_waviness(TableReader& parent, const std::string& race, Case& c,
                   const ReadContext& context) {
  std::vector<WavinessHarmonic>& out =
      race == "inner" ? c.excitation.inner_waviness : c.excitation.outer_waviness;
  const toml::array* entries = parent.table_array(race);
  if (!entries) return;
  const std::string schema = "waviness." + race;
  for (std::size_t i = 0; i < entries->size(); ++i) {
    const std::string shown = schema + "[" + std::to_string(i) + "]";
    TableReader r(entries->get(i)->as_table(), shown, schema);
    read_waviness_entry(r, shown, schema, context, out);
    r.finish();
  }
  check_waviness(out, c.bearing, schema);
}

void write_waviness(std::ostream& o, const Case& c) {
  bool first = true;
  for (const auto& [race, list] : {std::pair{"inner", &c.excitation.inner_waviness},
                                   std::pair{"outer", &c.excitation.outer_waviness}})
    for (const auto& h : *list) {
      o << (first ? "" : "\n") << "[[waviness." << race << "]]\norder = " << h.order
        << "\namplitude = " << num17(h.amplitude)
        << "\nphase = " << quantity_text(h.phase, Dimension::angle) << "\n";
      first = false;
    }
}

void read_ball_errors(TableReader& r, Case& c, const ReadContext&) {
  const auto values = r.list("values");
  const auto band = r.quantity("band");
  const auto seed = r.integer("seed");
  r.finish();
  const Bearing& b = c.bearing;
  Excitations& e = c.excitation;
  if (values && band)
    throw InputError("ball_errors: give either values (one per ball) or band (+ seed), not both");
  if (seed && !band)
    throw InputError("ball_errors.seed = " + std::to_string(*seed) +
                     ": a seed needs ball_errors.band to draw from");
  if (values) {
    for (double v : *values) e.ball_size_errors.push_back(-v);  // ΔD_j = D − D_j
    check_ball_size_errors(e.ball_size_errors, b);
  }
  if (band) {
    require(*band >= 0 && *band < 0.02 * b.ball_diameter, "ball_errors.band", *band,
            Dimension::length, "must be >= 0 and below 2 % of the ball diameter");
    if (seed && *seed < 0)
      throw InputError("ball_errors.seed = " + std::to_string(*seed) + ": must be >= 0");
    e.ball_error_band = *band;
    e.ball_error_seed = seed ? static_cast<std::uint64_t>(*seed) : 1u;
    e.ball_size_errors = ball_size_errors_from_band(b.balls, *band, e.ball_error_seed);
  }
}

void write_ball_errors(std::ostream& o, const Case& c) {
  const Excitations& e = c.excitation;
  if (e.ball_size_errors.empty()) return;
  o << "[ball_errors]\n";
  if (e.ball_error_band > 0)
    o << "# drawn from band " << num17(e.ball_error_band) << " m with seed " << e.ball_error_seed
      << "\n";
  o << "values = [";  // D_j − D = −ΔD_j
  for (std::size_t j = 0; j < e.ball_size_errors.size(); ++j)
    o << (j ? ", " : "") << num17(-e.ball_size_errors[j]);
  o << "]\n";
}

void read_defect(TableReader& r, Case& c, const ReadContext&) {
  const auto location = r.text("location");
  const auto width = r.quantity("width"), depth = r.quantity("depth");
  if (!location || !width || !depth)
    throw InputError(r.shown() +
                     ": each [[defects]] entry needs location (\"outer\", \"inner\" or \"ball\"), "
                     "width and depth");
  LocalDefect d;
  d.location = parse_named(kDefectLocations, *location, r.full("location"), "defect location");
  d.width = *width;
  d.depth = *depth;
  if (const auto profile = r.text("profile"))
    d.profile = parse_named(kDefectProfiles, *profile, r.full("profile"), "defect profile");
  const auto position = r.quantity("position");
  const auto ball = r.integer("ball");
  if (d.location == DefectLocation::ball) {
    if (!ball)
      throw InputError(r.full("ball") + " is missing: a ball defect names its ball (0 … " +
                       std::to_string(c.bearing.balls - 1) + ")");
    // the range is check_defects's, once every entry is read
    d.ball = static_cast<int>(std::clamp<long long>(*ball, std::numeric_limits<int>::min(),
                                                    std::numeric_limits<int>::max()));
    d.position = position.value_or(0.5 * pi);  // between its contacts at t = 0
  } else {
    if (ball)
      throw InputError(r.full("ball") + " = " + std::to_string(*ball) +
                       ": only a ball defect (location = \"ball\") names a ball");
    if (!position)
      throw InputError(r.full("position") + " is missing: the angle of the defect's centre (" +
                       (d.location == DefectLocation::outer
                            ? "in the housing, from +x toward +y; the load zone is where the load "
                              "points"
                            : "on the inner ring at t = 0, from +x toward +y") +
                       "), e.g. position = \"-90 deg\"");
    d.position = *position;
  }
  c.excitation.defects.push_back(d);
}

void check_defect_entries(Case& c) {
  const std::vector<LocalDefect>& defects = c.excitation.defects;
  check_defects(defects, c.bearing);
  check_defects_supported(c.model.kind, defects);
}

void write_defects(std::ostream& o, const Case& c) {
  bool first = true;
  for (const LocalDefect& d : c.excitation.defects) {
    o << (first ? "" : "\n")
      << "[[defects]]\nlocation = " << quoted(name_of(kDefectLocations, d.location)) << "\n";
    if (d.location == DefectLocation::ball) o << "ball = " << d.ball << "\n";
    o << "position = " << quantity_text(d.position, Dimension::angle)
      << "\nwidth = " << num17(d.width) << "\ndepth = " << num17(d.depth)
      << "\nprofile = " << quoted(name_of(kDefectProfiles, d.profile)) << "\n";
    first = false;
  }
}

void read_calibration_file(TableReader& r, Case& c, const ReadContext& context) {
  // An empty string means none, so that `--set 'model.calibration=""'` can switch a calibrated
  // case back to a Hertz method.
  const auto calibration = r.text("calibration");
  const bool calibrated = c.model.contact == ContactLaw::calibrated;
  if (calibration && !calibration->empty()) {
    const std::string shown = "model.calibration = \"" + *calibration + "\"";
    if (!calibrated)
      throw InputError(shown +
                       ": a calibration file is only used with model.contact = "
                       "\"calibrated\" (the case has model.contact = \"" +
                       name_of(kContactLaws, c.model.contact) +
                       "\"); set both, or remove model.calibration");
    c.model.calibration = read_calibration(join_path(context.base_dir, *calibration), shown);
    check_calibration_bearing(*c.model.calibration, c.bearing, shown);
  } else if (calibrated) {
    throw InputError(
        "model.contact = \"calibrated\" needs model.calibration = \"calibration.json\", the FE "
        "constants written by bearing-fem calibrate for this bearing (a path relative to the case "
        "file)");
  }
}

void read_envelope_band(TableReader& r, Case& c, const ReadContext&) {
  const toml::node* n = r.node("envelope_band");
  if (!n) return;
  const std::string key = r.full("envelope_band");
  const auto bad = [&] {
    return InputError(key + " = " + shown_value(*n) +
                      ": expected \"none\", \"auto\" (the band of largest spectral kurtosis) or "
                      "a band [low, high], e.g. [\"2 kHz\", \"8 kHz\"]");
  };
  EnvelopeBandSetting& e = c.output.envelope_band;
  if (const auto* word = n->as_string()) {
    // "none" or "auto"; "given" is what summary.json calls a band given here as [low, high].
    const auto source = find_named(kEnvelopeBandSources, word->get());
    if (!source || *source == EnvelopeBandSource::given) throw bad();
    e = {*source, {}};
    return;
  }
  const toml::array* band = n->as_array();
  if (!band || band->size() != 2) throw bad();
  e.source = EnvelopeBandSource::given;
  e.band.low = read_quantity(*band->get(0), key + "[0] (low)", Dimension::frequency);
  e.band.high = read_quantity(*band->get(1), key + "[1] (high)", Dimension::frequency);
}

void check_envelope_band(const Case& c) {
  const EnvelopeBandSetting& e = c.output.envelope_band;
  if (e.source != EnvelopeBandSource::given) return;
  const double nyquist = 0.5 * c.solver.output_rate;
  if (!(e.band.low >= 0 && e.band.low < e.band.high && e.band.high <= nyquist))
    throw InputError("output.envelope_band = [" + fmt_si(e.band.low, Dimension::frequency) + ", " +
                     fmt_si(e.band.high, Dimension::frequency) + "]: allowed 0 <= low < high <= " +
                     fmt_si(nyquist, Dimension::frequency) + " (solver.output_rate / 2)");
}

void write_envelope_band(std::ostream& o, const Case& c) {
  const EnvelopeBandSetting& e = c.output.envelope_band;
  if (e.source == EnvelopeBandSource::automatic)
    o << "envelope_band = " << quoted(name_of(kEnvelopeBandSources, e.source)) << "\n";
  if (e.source == EnvelopeBandSource::given)
    o << "envelope_band = [" << num17(e.band.low) << ", " << num17(e.band.high) << "]\n";
}

void check_solver_times(Case& c) {
  const SolverOptions& s = c.solver;
  require(s.transient >= 0 && s.transient < s.duration, "solver.transient", s.transient,
          Dimension::time,
          "must be >= 0 and shorter than solver.duration (" + fmt_si(s.duration, Dimension::time) +
              ")");
  const double samples = s.output_rate * s.duration;
  require(samples <= 2e7, "solver.output_rate", s.output_rate, Dimension::frequency,
          "gives " + format_number(samples) + " samples over solver.duration; at most 2e7");
  require((s.duration - s.transient) * s.output_rate >= 16, "solver.output_rate", s.output_rate,
          Dimension::frequency,
          "gives fewer than 16 samples after the transient: raise it or solver.duration");
}

void check_acoustics(Case& c) {
  const AcousticsOptions& ac = c.acoustics;
  const Bearing& b = c.bearing;
  if (!ac.enabled) return;
  if (ac.microphones.empty())
    throw InputError(
        "acoustics.microphones is missing or empty: an [acoustics] table needs at least one "
        "microphone [r, angle] in the bearing plane, e.g. microphones = [[\"10 mm\", \"-90 "
        "deg\"]]");
  for (std::size_t i = 0; i < ac.microphones.size(); ++i) {
    const double r = ac.microphones[i].radius;
    require(r > 0 && r <= 100.0, "acoustics.microphones[" + std::to_string(i) + "] r", r,
            Dimension::length, "must lie in (0, 100 m]");
  }
  require(ac.ring_radius > 0 && ac.ring_radius < 0.5 * b.pitch_diameter, "acoustics.ring_radius",
          ac.ring_radius, Dimension::length,
          "must lie in (0, d_m/2 = " + fmt_si(0.5 * b.pitch_diameter, Dimension::length) + ")");
  // A microphone must lie outside every source: outside the ring, and outside the annulus the
  // balls sweep (its radii move by the micrometres of the run; radiate checks again).
  const double swept_in = 0.5 * (b.pitch_diameter - b.ball_diameter);
  const double swept_out = 0.5 * (b.pitch_diameter + b.ball_diameter);
  for (std::size_t i = 0; i < ac.microphones.size(); ++i) {
    const double r = ac.microphones[i].radius;
    const std::string key = "acoustics.microphones[" + std::to_string(i) + "] r";
    if (ac.ring_source != RingSource::none)
      require(r > ac.ring_radius, key, r, Dimension::length,
              "inside the ring source (acoustics.ring_radius = " +
                  fmt_si(ac.ring_radius, Dimension::length) +
                  "): a microphone must lie outside it");
    if (ac.ball_source != BallSource::none)
      require(r < swept_in || r > swept_out, key, r, Dimension::length,
              "inside the annulus the balls sweep, " + fmt_si(swept_in, Dimension::length) + " … " +
                  fmt_si(swept_out, Dimension::length) +
                  " ((d_m ∓ D)/2): a ball would pass through the microphone; move it, or set "
                  "acoustics.ball_source = \"none\"");
  }
  if (ac.ring_source == RingSource::none && ac.ball_source == BallSource::none)
    throw InputError(
        "acoustics: ring_source and ball_source are both \"none\": nothing radiates; choose a "
        "source or remove the [acoustics] table");
}

void write_microphones(std::ostream& o, const Case& c) {
  const auto& mics = c.acoustics.microphones;
  o << "microphones = [";
  for (std::size_t i = 0; i < mics.size(); ++i)
    o << (i ? ", " : "") << "[" << num17(mics[i].radius) << ", "
      << quantity_text(mics[i].angle, Dimension::angle) << "]";
  o << "]\n";
}

}  // namespace bearing::case_schema
