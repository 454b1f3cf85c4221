// The case-file schema: one row per key (case_schema.h), table by table in the order a case file
// is read, written and listed in --help. The rules that tie several keys of a table together sit
// in that table's row (before/after); the tables whose keys need more than a value each (bearing
// preset, waviness entries, ball errors, the calibration file, acoustics) have them in
// case_rules.cc.

#include <cmath>
#include <limits>

#include "bearing/constants.h"
#include "bearing/models/ball_dofs.h"
#include "bearing/models/model_registry.h"
#include "case_rules.h"
#include "key_builders.h"

namespace bearing::case_schema {

namespace {

using D = Dimension;

// Absent, a geometry key keeps the preset's value; without a preset it is required.
template <class At>
auto preset_or_required(std::string leaf, At at) {
  return [leaf, at](const Case& c) {
    if (c.preset.empty())
      throw InputError("bearing." + leaf +
                       " is missing: give it, or choose a catalogue bearing with bearing.preset (" +
                       "608, 6304, 6308, 6205, 6203, 209)");
    return at(c);
  };
}

template <class At>
Key geometry(const std::string& leaf, Dimension dim, std::string help, At at) {
  return quantity("bearing." + leaf, dim, std::move(help), at, unchecked(),
                  preset_or_required(leaf, at));
}

std::vector<Key> bearing_keys() {
  Key preset = described("bearing.preset", Kind::text, D::dimensionless,
                         "catalogue bearing (608, 6304, 6308, 6205, 6203, 209); other keys override it");
  preset.read = read_preset;
  // Written first, so the keys after it override every value it sets: the run of case.toml is
  // the same bearing under the same designation (summary.json's case.bearing), not "custom".
  preset.write = [](std::ostream& o, const Case& c) {
    if (!c.preset.empty()) o << "preset = " << quoted(c.preset) << "\n";
  };
  const auto balls = [](auto& c) -> auto& {
    return c.bearing.balls;
  };
  return {
      table("bearing", "geometry"),
      preset,
      geometry(
          "ball_diameter", D::length, "ball diameter D",
          [](auto& c) -> auto& { return c.bearing.ball_diameter; }),
      geometry(
          "pitch_diameter", D::length, "pitch diameter d_m",
          [](auto& c) -> auto& { return c.bearing.pitch_diameter; }),
      integer("bearing.balls", "number of balls Z (>= 3)", balls, unchecked(),
              preset_or_required("balls", balls)),
      geometry(
          "inner_conformity", D::dimensionless, "inner groove radius / D (> 0.5)",
          [](auto& c) -> auto& { return c.bearing.inner_conformity; }),
      geometry(
          "outer_conformity", D::dimensionless, "outer groove radius / D (> 0.5)",
          [](auto& c) -> auto& { return c.bearing.outer_conformity; }),
      geometry(
          "clearance", D::length,
          "ISO radial internal clearance P_d (diametral); each ball's gap is P_d/2",
          [](auto& c) -> auto& { return c.bearing.clearance; }),
      quantity(
          "bearing.contact_angle", D::angle, "free contact angle alpha",
          [](auto& c) -> auto& { return c.bearing.contact_angle; }),
  };
}

// One material table: [material.ball] or [material.rings].
template <class At>
std::vector<Key> material_keys(const std::string& name, const std::string& what, At at) {
  return {
      table("material." + name, what + " material (young, poisson, density)"),
      quantity(
          "material." + name + ".young", D::pressure,
          what + " Young's modulus", [at](auto& c) -> auto& { return at(c).young; }),
      quantity(
          "material." + name + ".poisson", D::dimensionless,
          what + " Poisson ratio", [at](auto& c) -> auto& { return at(c).poisson; }),
      quantity(
          "material." + name + ".density", D::density,
          what + " density", [at](auto& c) -> auto& { return at(c).density; }),
  };
}

std::vector<Key> material_keys() {
  Key t = table("material", "balls and rings");
  // Bearing::validate checks the geometry and both materials, once everything is read.
  t.after = [](Case& c) { c.bearing.validate(); };
  std::vector<Key> out{t};
  // The plain [material] keys set both materials.
  const auto both = [](std::string leaf, double Material::*member, Dimension dim,
                       std::string help) {
    Key k = described("material." + leaf, Kind::quantity, dim, std::move(help));
    k.read = [leaf, member](TableReader& r, Case& c, const ReadContext&) {
      if (const auto v = r.quantity(leaf)) c.bearing.ball.*member = c.bearing.rings.*member = *v;
    };
    return k;
  };
  out.push_back(both("young", &Material::young, D::pressure, "Young's modulus, balls and rings"));
  out.push_back(
      both("poisson", &Material::poisson, D::dimensionless, "Poisson ratio in (-1, 0.5)"));
  out.push_back(both("density", &Material::density, D::density, "density"));
  for (auto& k : material_keys(
           "ball", "ball", [](auto& c) -> auto& { return c.bearing.ball; }))
    out.push_back(std::move(k));
  for (auto& k : material_keys(
           "rings", "ring", [](auto& c) -> auto& { return c.bearing.rings; }))
    out.push_back(std::move(k));
  return out;
}

std::vector<Key> rotor_keys() {
  return {
      table("rotor", "inner ring and shaft"),
      quantity(
          "rotor.mass", D::mass, "inner ring + shaft mass (default 0.6 kg)",
          [](auto& c) -> auto& { return c.rotor.mass; }, limits::rotor_mass),
      quantity(
          "rotor.damping", D::damping, "radial damping (default 200 N s/m)",
          [](auto& c) -> auto& { return c.rotor.damping; }, limits::rotor_damping),
      quantity(
          "rotor.axial_mass", D::mass, "axial mass, 3dof (default: rotor.mass)",
          [](auto& c) -> auto& { return c.rotor.axial_mass; }, limits::rotor_axial_mass,
          [](const Case& c) { return c.rotor.mass; }),
      quantity(
          "rotor.axial_damping", D::damping, "axial damping, 3dof (default: rotor.damping)",
          [](auto& c) -> auto& { return c.rotor.axial_damping; }, limits::rotor_axial_damping,
          [](const Case& c) { return c.rotor.damping; }),
  };
}

std::vector<Key> operation_keys() {
  Key load = described("operation.load", Kind::vector2, D::force,
                       "radial load [Fx, Fy] on the inner ring (y up: Fy < 0 pushes down)");
  load.read = [](TableReader& r, Case& c, const ReadContext&) {
    if (const auto v = r.vector2("load")) c.operation.load = *v;
  };
  load.write = [](std::ostream& o, const Case& c) {
    o << "load = [" << num17(c.operation.load.x()) << ", " << num17(c.operation.load.y()) << "]\n";
  };
  Key moment =
      described("operation.moment", Kind::vector2, D::moment,
                "moments [Mx, My] on the inner ring, about +x and +y (default [0, 0]): used by "
                "`stiffness` and `info` (5-DOF static solution); `run` refuses a nonzero one, as "
                "no model kind has a tilt DOF");
  moment.read = [](TableReader& r, Case& c, const ReadContext&) {
    if (const auto v = r.vector2("moment")) c.operation.moment = *v;
  };
  // Written only when set: every case `run` writes has none.
  moment.write = [](std::ostream& o, const Case& c) {
    if (c.operation.moment.isZero(0.0)) return;
    o << "moment = [" << num17(c.operation.moment.x()) << ", " << num17(c.operation.moment.y())
      << "]\n";
  };
  return {
      table("operation", "operating conditions"),
      quantity(
          "operation.speed", D::angular_speed, "inner-ring speed",
          [](auto& c) -> auto& { return c.operation.speed; }, limits::operation_speed),
      load,
      quantity(
          "operation.axial_load", D::force,
          "axial load / preload Fz (run: 3dof, balls; the others refuse a nonzero one; "
          "stiffness and info carry it with any kind)",
          [](auto& c) -> auto& { return c.operation.axial_load; }),
      moment,
      quantity(
          "operation.unbalance", D::mass_length,
          "unbalance m_u e; force m_u e w^2 rotating with the shaft",
          [](auto& c) -> auto& { return c.operation.unbalance; }, limits::operation_unbalance),
      boolean(
          "operation.gravity", "add the rotor weight -m g to Fy",
          [](auto& c) -> auto& { return c.operation.gravity; }),
  };
}

std::vector<Key> waviness_keys() {
  Key t = table("waviness", "raceway waviness");
  t.write_table = write_waviness;
  std::vector<Key> out{t};
  for (const std::string race : {"inner", "outer"}) {
    const std::string name = "waviness." + race;
    Key entries =
        described(name, Kind::table_array, D::dimensionless,
                  "[[" + name + "]] entries: order, amplitude, phase; or table = \"file.csv\"");
    entries.read = [race](TableReader& r, Case& c, const ReadContext& context) {
      read_waviness(r, race, c, context);
    };
    out.push_back(entries);
    out.push_back(
        described(name + ".order", Kind::integer, D::dimensionless, "waves per revolution (>= 1)"));
    out.push_back(described(name + ".amplitude", Kind::quantity, D::length, "waviness amplitude"));
    out.push_back(described(name + ".phase", Kind::quantity, D::angle, "waviness phase"));
    out.push_back(described(name + ".table", Kind::text, D::dimensionless,
                            "CSV order,amplitude[,phase] (um, deg unless the header says)"));
  }
  return out;
}

std::vector<Key> ball_error_keys() {
  Key t = table("ball_errors", "ball-size errors");
  t.read = read_ball_errors;
  t.write_table = write_ball_errors;
  return {
      t,
      described("ball_errors.values", Kind::list, D::length,
                "each ball's diameter deviation D_j - D (one per ball)"),
      described("ball_errors.band", Kind::quantity, D::length,
                "draw D_j - D uniformly in [-band/2, band/2]"),
      described("ball_errors.seed", Kind::integer, D::dimensionless,
                "seed of the band draw (default 1)"),
  };
}

std::vector<Key> model_keys() {
  Key calibration = described("model.calibration", Kind::text, D::dimensionless,
                              "FE constants for contact = \"calibrated\": the JSON of bearing-fem "
                              "calibrate");
  calibration.read = read_calibration_file;
  calibration.write = [](std::ostream& o, const Case& c) {
    if (c.model.calibration) o << "calibration = " << quoted(c.model.calibration->path) << "\n";
  };
  // Whether model.kind carries the case's loads (an axial load, a moment) is checked where a
  // model is built (check_run_loads, simulation.h), not here: the static analyses (`stiffness`,
  // `info`) read the same case and carry every load whatever the kind.
  Key t = table("model", "model choices");
  return {
      t,
      choice(
          "model.kind",
          "2dof | 3dof | balls (seed 004: ball DOFs, cage slip, friction) | quasistatic (seed "
          "000: equilibrium per output instant, no [solver] method)",
          kModelKinds, "model", [](auto& c) -> auto& { return c.model.kind; }),
      choice(
          "model.contact", "contact law: exact | hamrock-brewe | harris-table | calibrated",
          kContactLaws, "contact law", [](auto& c) -> auto& { return c.model.contact; }),
      calibration,
      boolean(
          "model.waviness_stiffness",
          "TVDS: contact stiffness follows the waviness curvature (default false: TVD)",
          [](auto& c) -> auto& { return c.model.waviness_stiffness; }),
  };
}

std::vector<Key> defect_keys() {
  Key entries = described("defects", Kind::table_array, D::dimensionless,
                          "[[defects]] entries: local defects (spalls) on a race or a ball; "
                          "dynamic model kinds (2dof, 3dof, balls)");
  entries.read = read_defect;
  entries.after = check_defect_entries;
  entries.write_table = write_defects;
  entries.written = [](const Case& c) { return !c.excitation.defects.empty(); };
  const auto entry = [](const char* leaf, Kind kind, Dimension dim, const char* help) {
    return described(std::string("defects.") + leaf, kind, dim, help);
  };
  return {
      entries,
      entry("location", Kind::choice, D::dimensionless, "outer | inner | ball (required)"),
      entry("position", Kind::quantity, D::angle,
            "outer: centre angle in the housing from +x; inner: on the ring at t = 0 (required); "
            "ball: angle on the ball from its outer-race contact at t = 0 (default 90 deg)"),
      entry("ball", Kind::integer, D::dimensionless, "ball defects: which ball, 0 … Z-1"),
      entry("width", Kind::quantity, D::length,
            "along the rolling direction, in (0, D] (required)"),
      entry("depth", Kind::quantity, D::length, "in (0, D/4] (required)"),
      entry("profile", Kind::choice, D::dimensionless,
            "rectangular (sharp edges, default) | smooth (half-sine)"),
  };
}

// A table one model kind owns (model_registry.h); an error with any other kind, which would
// ignore it.
Key owned_table(const std::string& name, const std::string& help) {
  Key t = table(name, help);
  t.before = [name](const TableReader& r, Case& c) {
    if (!r.present() || model_descriptor(c.model.kind).owns(name)) return;
    std::string owners;
    for (const ModelDescriptor& d : model_registry())
      if (d.owns(name))
        owners += std::string(owners.empty() ? "" : " or ") + "model.kind = \"" +
                  name_of(kModelKinds, d.kind) + "\"";
    throw InputError("[" + name + "] is used by " + owners + " only (the case has " +
                     "model.kind = \"" + name_of(kModelKinds, c.model.kind) +
                     "\"): remove it or set kind");
  };
  t.written = [name](const Case& c) { return model_descriptor(c.model.kind).owns(name); };
  return t;
}

std::vector<Key> cage_keys() {
  return {
      owned_table("cage", "the cage and the traction at the ball contacts (balls)"),
      quantity(
          "cage.slip", D::dimensionless,
          "balls: cage slip s_c in [0, 1), cage at (1 - s_c) x its pure-rolling speed "
          "(default 0)",
          [](auto& c) -> auto& { return c.cage.slip; }, limits::cage_slip),
      quantity(
          "cage.friction", D::dimensionless,
          "balls: traction coefficient mu_m reached at cage.slide_speed (default 0.01)",
          [](auto& c) -> auto& { return c.cage.friction; }, limits::cage_friction),
      quantity(
          "cage.slide_speed", D::velocity,
          "balls: sliding speed where traction saturates (default 0.1 m/s)",
          [](auto& c) -> auto& { return c.cage.slide_speed; }, limits::cage_slide_speed),
  };
}

std::vector<Key> ball_keys() {
  return {
      owned_table("ball", "each ball's dynamics (balls)"),
      quantity(
          "ball.mass", D::mass, "balls: ball mass (default: density x pi D^3/6)",
          [](auto& c) -> auto& { return c.ball.mass; }, limits::ball_mass,
          [](const Case& c) { return default_ball_mass(c.bearing); }),
      quantity(
          "ball.inertia", D::inertia, "balls: ball moment of inertia (default: mass x D^2/10)",
          [](auto& c) -> auto& { return c.ball.inertia; }, limits::ball_inertia,
          [](const Case& c) { return default_ball_inertia(c.ball.mass, c.bearing.ball_diameter); }),
      quantity(
          "ball.damping", D::damping,
          "balls: damping of each ball's radial motion (default: rotor.damping)",
          [](auto& c) -> auto& { return c.ball.damping; }, limits::ball_damping,
          [](const Case& c) { return c.rotor.damping; }),
      boolean(
          "ball.centrifugal",
          "balls: centrifugal load m_b w_cage^2 d_m/2 on each ball (default true)",
          [](auto& c) -> auto& { return c.ball.centrifugal; }),
  };
}

// A [housing] key of the resonator: range-checked, and if `required` refused when missing, only
// when the table is there and gives no modes file (absent, the housing is off and its keys keep
// their defaults, unchecked; with modes, the modes stand in for mass and frequency, which must
// then be absent). A missing required key lands as NaN (the reader takes finite numbers only)
// and is reported by the check, after the table's unknown keys, so `mas = "1 kg"` is answered
// with "did you mean mass".
template <class At>
Key housing_quantity(std::string name, Dimension dim, std::string help, At at, const Limit& limit,
                     bool required) {
  Key k = quantity(
      std::move(name), dim, std::move(help), at, unchecked(), [at, required](const Case& c) {
        return c.housing.enabled && required ? std::numeric_limits<double>::quiet_NaN() : at(c);
      });
  require_own_limit(limit, k.name);
  k.check = [at, key = k.name, dim, limit, required](const Case& c) {
    if (!c.housing.enabled) return;
    if (c.housing.modal() && required) {
      if (!std::isnan(at(c)))
        throw InputError(key + " = " + fmt_si(at(c), dim) +
                         ": give either mass and frequency (one resonator) or modes (the "
                         "structure's modes file), not both");
      return;
    }
    if (std::isnan(at(c)))
      throw InputError(key +
                       " is missing: [housing] needs mass and frequency (the resonance the "
                       "sensor sees), e.g. mass = \"1 kg\", frequency = \"3 kHz\", or modes = "
                       "\"modes.json\" (bearing-fem modes)");
    check_limit(limit, key, at(c), dim);
  };
  const auto write = k.write;
  if (required)
    k.write = [write](std::ostream& o, const Case& c) {
      if (!c.housing.modal()) write(o, c);
    };
  return k;
}

std::vector<Key> housing_keys() {
  Key t = table("housing",
                "the outer ring on its own support: one resonator (mass, frequency) or the "
                "structure's FE modes (modes), and the sensors (2dof, 3dof); present: on");
  // The table's presence turns the housing on.
  t.before = [](const TableReader& r, Case& c) { c.housing.enabled = r.present(); };
  t.after = [](Case& c) {
    check_housing_supported(c.model.kind, c.housing);
    check_housing_table(c);
  };
  t.written = [](const Case& c) { return c.housing.enabled; };
  Key damping = housing_quantity(
      "housing.damping_ratio", D::dimensionless,
      "damping ratio in [0, 1) of the resonance, or of each mode: one number for all, or an "
      "array, one per mode (default 0.05)",
      [](auto& c) -> auto& { return c.housing.damping_ratio; }, limits::housing_damping_ratio,
      false);
  damping.read = read_housing_damping;
  damping.write = write_housing_damping;
  Key modes = described("housing.modes", Kind::text, D::dimensionless,
                        "the structure's natural modes, modes.json of bearing-fem modes (relative "
                        "to the case file), instead of mass and frequency");
  modes.read = read_housing_modes;
  modes.write = write_housing_modes;
  Key sensors = described("housing.sensors", Kind::text, D::dimensionless,
                          "with modes: the modes file's sensors written, e.g. [\"top\"] (default: "
                          "all); channels x_<name>, vx_<name>, ax_<name>, ...");
  sensors.read = read_housing_sensors;
  sensors.write = write_housing_sensors;
  return {
      t,
      housing_quantity(
          "housing.mass", D::mass,
          "modal mass of the outer ring with its housing and sensor, m_h (required without modes)",
          [](auto& c) -> auto& { return c.housing.mass; }, limits::housing_mass, true),
      housing_quantity(
          "housing.frequency", D::frequency,
          "natural frequency f_h of the housing on its support alone (required without modes)",
          [](auto& c) -> auto& { return c.housing.frequency; }, limits::housing_frequency, true),
      damping,
      modes,
      sensors,
  };
}

std::vector<Key> slip_keys() {
  Key t = table("slip",
                "the cage's random slip: its speed fluctuates about the kinematic mean (every "
                "model kind; off without rms)");
  t.written = [](const Case& c) { return c.slip.enabled(); };
  Key tau = quantity(
      "slip.correlation_time", D::time,
      "correlation time of the fluctuation in (0, 100 s] (default: one ball pass, 1/BPFO)",
      [](auto& c) -> auto& { return c.slip.correlation_time; },
      within(0, 100, false, false, "must lie in [0, 100 s] (0: one ball pass, the default)"));
  const auto write_tau = tau.write;
  tau.write = [write_tau](std::ostream& o, const Case& c) {
    if (c.slip.correlation_time > 0) write_tau(o, c);  // absent: one ball pass
  };
  return {
      t,
      quantity(
          "slip.rms", D::dimensionless,
          "RMS of the cage speed's fluctuation as a fraction of its mean in [0, 0.1] (0.01: 1 %; "
          "default 0: off)",
          [](auto& c) -> auto& { return c.slip.rms; }, limits::slip_rms),
      tau,
      integer(
          "slip.seed", "seed of the random path (an integer >= 0, default 1; same seed, same bits)",
          [](auto& c) -> auto& { return c.slip.seed; },
          within(0, 1e9, false, false, "must be an integer in [0, 1000000000]")),
  };
}

std::vector<Key> solver_keys() {
  Key t = table("solver", "time integration");
  t.after = check_solver_times;
  return {
      t,
      choice(
          "solver.method", "rk4 | rkf45 | rk8pd | rk8pd-events | newmark | bdf", kIntegratorMethods,
          "method", [](auto& c) -> auto& { return c.solver.method; }),
      quantity(
          "solver.dt", D::time, "time step, or first step (default 5 us)",
          [](auto& c) -> auto& { return c.solver.dt; }, limits::solver_dt),
      quantity(
          "solver.duration", D::time, "simulated time (default 1.2 s)",
          [](auto& c) -> auto& { return c.solver.duration; },
          within(0, 1000, true, false, "must lie in (0, 1000 s]")),
      quantity(
          "solver.transient", D::time, "discarded before statistics (default 0.2 s)",
          [](auto& c) -> auto& { return c.solver.transient; }),
      quantity(
          "solver.tolerance", D::dimensionless,
          "relative tolerance, adaptive/bdf/newmark (default 1e-6)",
          [](auto& c) -> auto& { return c.solver.tolerance; }, limits::solver_tolerance),
      quantity(
          "solver.output_rate", D::frequency, "samples written per second (20 kHz)",
          [](auto& c) -> auto& { return c.solver.output_rate; },
          within(0, 1e7, true, false, "must lie in (0, 10 MHz]")),
      quantity(
          "solver.max_displacement", D::length,
          "blow-up bound on the ring displacement (default 1 mm)",
          [](auto& c) -> auto& { return c.solver.max_displacement; },
          limits::solver_max_displacement),
      choice_unwritten_at(
          ContactLoop::simd, "solver.contact_loop",
          "simd | scalar: per-ball contact loop (same results)", kContactLoops, "contact loop",
          [](auto& c) -> auto& { return c.solver.contact_loop; }),
  };
}

std::vector<Key> output_keys() {
  Key dynamics = boolean(
      "output.ball_dynamics",
      "balls: write each ball's spin wb [rad/s], outer load Qo [N], friction Fi, Fo [N]",
      [](auto& c) -> auto& { return c.output.ball_dynamics; });
  dynamics.check = [](const Case& c) {
    if (c.output.ball_dynamics && !model_descriptor(c.model.kind).ball_dofs)
      throw InputError(
          "output.ball_dynamics = true: the spin, outer load and friction channels "
          "need model.kind = \"balls\" (the case has \"" +
          std::string(name_of(kModelKinds, c.model.kind)) + "\")");
  };
  Key film = boolean(
      "output.ball_film",
      "with [lubricant]: write each ball's central film thickness hi1.., ho1.. [m] at its inner "
      "and outer contact",
      [](auto& c) -> auto& { return c.output.ball_film; });
  // Written only when on: a case.toml written without the key stays byte for byte as before it.
  film.write = [](std::ostream& o, const Case& c) {
    if (c.output.ball_film) o << "ball_film = true\n";
  };
  film.check = [](const Case& c) {
    if (!c.output.ball_film) return;
    if (!c.lubricant.enabled)
      throw InputError("output.ball_film = true: the film channels need a [lubricant] table");
    if (c.model.kind == ModelKind::quasi_static)
      throw InputError(
          "output.ball_film = true: the film channels need a dynamic model.kind (2dof, 3dof, "
          "balls)");
  };
  Key envelope = described(
      "output.envelope_band", Kind::vector2, D::frequency,
      "\"none\" (default) | \"auto\" (fast kurtogram) | [low, high], e.g. [\"2 kHz\", \"8 kHz\"]: "
      "envelope spectra of the accelerations and a diagnosis");
  envelope.read = read_envelope_band;
  envelope.check = check_envelope_band;
  envelope.write = write_envelope_band;
  Key format = choice_unwritten_at(
      OutputFormat::csv, "output.format",
      "csv (default) | npy: the tables as NumPy .npy files of full doubles, their columns and "
      "units in columns.json",
      kOutputFormats, "output format", [](auto& c) -> auto& { return c.output.format; });
  return {
      table("output", "what run writes"),
      boolean(
          "output.ball_loads", "write each ball's load Q1..QZ",
          [](auto& c) -> auto& { return c.output.ball_loads; }),
      boolean(
          "output.ball_motion",
          "write each ball centre's radial displacement r1..rZ [m] and velocity vr1..vrZ [m/s]",
          [](auto& c) -> auto& { return c.output.ball_motion; }),
      boolean(
          "output.ball_approach",
          "write each ball's approach d1..dZ [m] (positive: elastic approach; negative: gap)",
          [](auto& c) -> auto& { return c.output.ball_approach; }),
      dynamics,
      film,
      choice(
          "output.window", "hann | flattop | rectangular", kWindows, "window",
          [](auto& c) -> auto& { return c.output.window; }),
      integer(
          "output.peaks", "peaks listed per channel (default 10)",
          [](auto& c) -> auto& { return c.output.peaks; },
          within(0, 1000, false, false, "allowed 0 to 1000")),
      envelope,
      format,
  };
}

// A [lubricant] key: checked only when the table is there (absent, the contacts are dry and the
// keys keep their defaults); `required` ones land as NaN when missing and are reported by the
// check, after the table's unknown keys.
template <class At>
Key lubricant_quantity(std::string name, Dimension dim, std::string help, At at,
                       const Limit& limit, bool required, std::string example = "") {
  Key k = quantity(std::move(name), dim, std::move(help), at, unchecked(),
                   [at, required](const Case& c) {
                     return c.lubricant.enabled && required
                                ? std::numeric_limits<double>::quiet_NaN()
                                : at(c);
                   });
  require_own_limit(limit, k.name);
  k.check = [at, key = k.name, dim, limit, required, example](const Case& c) {
    if (!c.lubricant.enabled) return;
    if (required && std::isnan(at(c)))
      throw InputError(key + " is missing: [lubricant] needs viscosity, pressure_viscosity and "
                             "roughness (e.g. " + example + ")");
    if (!std::isnan(at(c))) check_limit(limit, key, at(c), dim);
  };
  const auto write = k.write;
  k.write = [write, at](std::ostream& o, const Case& c) {
    if (!std::isnan(at(c))) write(o, c);
  };
  return k;
}

std::vector<Key> lubricant_keys() {
  Key t = table("lubricant",
                "the oil film at every ball contact: Hamrock-Dowson EHL film in series with "
                "Hertz, squeeze-film damping (2dof, 3dof, balls, stiffness); present: on");
  t.before = [](const TableReader& r, Case& c) { c.lubricant.enabled = r.present(); };
  // The rules between keys (the temperature law's); a missing key is its own check's to report.
  t.after = [](Case& c) {
    const Lubricant& l = c.lubricant;
    if (c.lubricant.enabled && !std::isnan(l.viscosity) && !std::isnan(l.pressure_viscosity) &&
        !std::isnan(l.roughness))
      l.validate();
  };
  t.written = [](const Case& c) { return c.lubricant.enabled; };
  return {
      t,
      lubricant_quantity(
          "lubricant.viscosity", D::viscosity,
          "dynamic viscosity eta0 at the operating temperature (with temperature: at "
          "reference_temperature), e.g. \"0.02 Pa s\" (required)",
          [](auto& c) -> auto& { return c.lubricant.viscosity; }, limits::lubricant_viscosity,
          true, "viscosity = \"20 mPa s\""),
      lubricant_quantity(
          "lubricant.pressure_viscosity", D::inverse_pressure,
          "pressure-viscosity coefficient alpha of Barus' law, e.g. \"2e-8 1/Pa\" (required)",
          [](auto& c) -> auto& { return c.lubricant.pressure_viscosity; },
          limits::lubricant_pressure_viscosity, true, "pressure_viscosity = \"2e-8 1/Pa\""),
      lubricant_quantity(
          "lubricant.roughness", D::length,
          "composite RMS roughness sqrt(s_ball^2 + s_race^2) for Lambda = h_min/s, e.g. "
          "\"0.1 um\" (required)",
          [](auto& c) -> auto& { return c.lubricant.roughness; }, limits::lubricant_roughness,
          true, "roughness = \"0.1 um\""),
      lubricant_quantity(
          "lubricant.temperature", D::temperature,
          "operating temperature; with it, viscosity is at reference_temperature and follows "
          "Reynolds' law exp(-viscosity_temperature (T - T_ref)) (optional)",
          [](auto& c) -> auto& { return c.lubricant.temperature; },
          limits::lubricant_temperature, false),
      lubricant_quantity(
          "lubricant.reference_temperature", D::temperature,
          "temperature where viscosity was measured, e.g. \"40 degC\" (with temperature)",
          [](auto& c) -> auto& { return c.lubricant.reference_temperature; },
          limits::lubricant_reference_temperature, false),
      lubricant_quantity(
          "lubricant.viscosity_temperature", D::inverse_temperature,
          "Reynolds' viscosity-temperature coefficient beta, e.g. \"0.03 1/K\" (with "
          "temperature)",
          [](auto& c) -> auto& { return c.lubricant.viscosity_temperature; },
          limits::lubricant_viscosity_temperature, false),
  };
}

std::vector<Key> acoustics_keys() {
  Key t = table("acoustics", "sound at microphones");
  // The table's presence turns the sound-pressure outputs on.
  t.before = [](const TableReader& r, Case& c) { c.acoustics.enabled = r.present(); };
  t.after = check_acoustics;
  t.written = [](const Case& c) { return c.acoustics.enabled; };
  Key microphones =
      described("acoustics.microphones", Kind::points, D::length,
                "[[r, angle], ...] in the bearing plane from the bearing centre, angle from +x "
                "towards +y");
  microphones.read = [](TableReader& r, Case& c, const ReadContext&) {
    if (const auto v = r.points("microphones")) c.acoustics.microphones = *v;
  };
  microphones.write = write_microphones;
  return {
      t,
      choice(
          "acoustics.ring_source", "inner ring as: cylinder-dipole (default) | paper | none",
          kRingSources, "ring source", [](auto& c) -> auto& { return c.acoustics.ring_source; }),
      choice(
          "acoustics.ball_source",
          "each ball as: oscillating-sphere (default) | pulsating-sphere | paper | none",
          kBallSources, "ball source", [](auto& c) -> auto& { return c.acoustics.ball_source; }),
      choice(
          "acoustics.summation",
          "coherent (default: sum of pressures) | energetic (seed 000: sqrt of summed squares)",
          kSummations, "summation", [](auto& c) -> auto& { return c.acoustics.summation; }),
      microphones,
      quantity(
          "acoustics.ring_radius", D::length,
          "radiating radius of the inner ring (default: inner raceway radius (d_m - D)/2)",
          [](auto& c) -> auto& { return c.acoustics.ring_radius; }, unchecked(),
          [](const Case& c) { return 0.5 * c.bearing.inner_raceway_diameter(); }),
      quantity(
          "acoustics.density", D::density, "air density (default 1.204 kg/m^3)",
          [](auto& c) -> auto& { return c.acoustics.density; },
          within(0, 2e4, true, false, "must lie in (0, 20000 kg/m^3]")),
      quantity(
          "acoustics.sound_speed", D::velocity, "speed of sound (default 343.2 m/s)",
          [](auto& c) -> auto& { return c.acoustics.sound_speed; },
          within(0, 1e4, true, false, "must lie in (0, 10000 m/s]")),
  };
}

std::vector<Key> all_keys() {
  std::vector<Key> out;
  for (auto part : {bearing_keys, material_keys, rotor_keys, operation_keys, waviness_keys,
                    ball_error_keys, model_keys, defect_keys, cage_keys, ball_keys, housing_keys,
                    slip_keys, lubricant_keys, solver_keys, output_keys, acoustics_keys})
    for (Key& k : part()) out.push_back(std::move(k));
  return out;
}

}  // namespace

const std::vector<Key>& keys() {
  static const std::vector<Key> all = all_keys();
  return all;
}

}  // namespace bearing::case_schema
