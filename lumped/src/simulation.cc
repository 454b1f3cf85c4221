#include "bearing/simulation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "bearing/errors.h"
#include "bearing/models/ball_dofs.h"
#include "bearing/models/quasi_static.h"
#include "bearing/models/three_dof.h"
#include "bearing/models/two_dof.h"

namespace bearing {

const std::vector<double>& Response::channel(const std::string& name) const {
  for (std::size_t i = 0; i < channels.size(); ++i)
    if (channels[i] == name) return values[i];
  throw std::out_of_range("response has no channel \"" + name + "\"");
}

std::vector<double> Response::steady(const std::string& name) const {
  const auto& v = channel(name);
  return std::vector<double>(v.begin() + static_cast<std::ptrdiff_t>(first_steady), v.end() - 1);
}

ModelInputs model_inputs(const Case& c) {
  ModelInputs in;
  in.bearing = c.bearing;
  in.hertz_method = hertz_shape_method(c.model);
  in.contact = contact_constants(c);
  in.inner_speed = c.operation.speed;
  in.load = c.operation.load;
  in.axial_load = c.operation.axial_load;
  in.unbalance = c.operation.unbalance;
  in.gravity = c.operation.gravity;
  in.mass = c.rotor.mass;
  in.damping = c.rotor.damping;
  in.axial_mass = c.rotor.axial_mass;
  in.axial_damping = c.rotor.axial_damping;
  in.inner_waviness.harmonics = c.excitation.inner_waviness;
  in.outer_waviness.harmonics = c.excitation.outer_waviness;
  in.ball_size_errors = c.excitation.ball_size_errors;
  in.waviness_stiffness = c.model.waviness_stiffness;
  in.cage_slip = c.cage.slip;
  in.traction = make_traction_curve(c.cage.friction, c.cage.slide_speed);
  in.ball_mass = c.ball.mass;
  in.ball_inertia = c.ball.inertia;
  in.ball_damping = c.ball.damping;
  in.centrifugal = c.ball.centrifugal;
  return in;
}

std::unique_ptr<BearingModel> make_model(const Case& c) {
  const ModelInputs in = model_inputs(c);
  switch (c.model.kind) {
    case ModelKind::two_dof:
      return make_two_dof_model(in);
    case ModelKind::three_dof:
      return make_three_dof_model(in);
    case ModelKind::balls:
      return make_ball_dof_model(in);
    case ModelKind::quasi_static:
      break;
  }
  throw InputError(
      "model.kind = \"quasistatic\" has no equations of motion (no integrator "
      "runs it): make_quasi_static_model builds it");
}

bool is_ball_channel(const std::string& name) {
  // Longest stems first, so "vr1" is not read as a stem "v" and "Qo1" not as "Q".
  for (const char* stem : {"Qo", "vr", "wb", "Fi", "Fo", "Q", "d", "r"}) {
    const std::size_t n = std::char_traits<char>::length(stem);
    if (name.size() <= n || name.compare(0, n, stem) != 0) continue;
    return std::all_of(name.begin() + static_cast<std::ptrdiff_t>(n), name.end(),
                       [](char ch) { return ch >= '0' && ch <= '9'; });
  }
  return false;
}

namespace {

// Bearing frequencies as the model runs them: a preloaded 3-DOF bearing turns at its loaded
// contact angle.
BearingFrequencies run_frequencies(const Case& c) {
  Bearing b = c.bearing;
  if (c.model.kind == ModelKind::three_dof ||
      (c.model.kind == ModelKind::balls && c.operation.axial_load != 0))
    b.contact_angle = solve_axial_preload(model_inputs(c)).contact_angle;
  const double slip = c.model.kind == ModelKind::balls ? c.cage.slip : 0.0;
  return bearing_frequencies(b, c.operation.speed, 0.0, slip);
}

// The ball-motion channels are written when asked for, and when the acoustics needs them (the
// balls as sound sources).
bool wants_ball_motion(const Case& c) {
  return c.output.ball_motion ||
         (c.acoustics.enabled && c.acoustics.ball_source != BallSource::none);
}

// The channels of a run: the DOFs, their velocities and accelerations, then Q1..QZ
// (output.ball_loads), d1..dZ (output.ball_approach), r1..rZ and vr1..vrZ (output.ball_motion);
// and the output times k / rate
// (the sample count from the duration, rounded to whole samples).
void lay_out(const Case& c, const std::vector<std::string>& dofs, int Z, Response& out) {
  for (const auto& q : dofs) out.channels.push_back(q), out.units.push_back("m");
  for (const auto& q : dofs) out.channels.push_back("v" + q), out.units.push_back("m/s");
  for (const auto& q : dofs) out.channels.push_back("a" + q), out.units.push_back("m/s^2");
  const auto per_ball = [&](const std::string& stem, const char* unit) {
    for (int j = 0; j < Z; ++j)
      out.channels.push_back(stem + std::to_string(j + 1)), out.units.push_back(unit);
  };
  if (c.output.ball_loads) per_ball("Q", "N");
  if (c.output.ball_approach) per_ball("d", "m");
  if (wants_ball_motion(c)) per_ball("r", "m"), per_ball("vr", "m/s");
  if (c.output.ball_dynamics)
    per_ball("wb", "rad/s"), per_ball("Qo", "N"), per_ball("Fi", "N"), per_ball("Fo", "N");
  const auto samples =
      static_cast<std::size_t>(std::floor(c.solver.duration * c.solver.output_rate + 1e-9)) + 1;
  out.time.resize(samples);
  for (std::size_t k = 0; k < samples; ++k)
    out.time[k] = static_cast<double>(k) / c.solver.output_rate;
  out.first_steady =
      static_cast<std::size_t>(std::ceil(c.solver.transient * c.solver.output_rate - 1e-9));
  out.values.assign(out.channels.size(), std::vector<double>(samples));
}

// One output sample's per-ball values, Z entries each (lay_out's channels).
struct BallSample {
  explicit BallSample(int Z)
      : loads(static_cast<std::size_t>(Z)),
        approaches(loads),
        r(loads),
        vr(loads),
        spin(loads),
        outer_load(loads),
        friction_inner(loads),
        friction_outer(loads) {}
  std::vector<double> loads, approaches, r, vr, spin, outer_load, friction_inner, friction_outer;
};

// Writes the per-ball channels of sample k from column `first` on (lay_out's order).
void store_balls(const Case& c, std::size_t first, std::size_t k, const BallSample& b,
                 Response& out) {
  std::size_t i = first;
  const auto put = [&](const std::vector<double>& values) {
    for (double value : values) out.values[i++][k] = value;
  };
  if (c.output.ball_loads) put(b.loads);
  if (c.output.ball_approach) put(b.approaches);
  if (wants_ball_motion(c)) put(b.r), put(b.vr);
  if (c.output.ball_dynamics)
    put(b.spin), put(b.outer_load), put(b.friction_inner), put(b.friction_outer);
}

// RK4 beyond its stability limit does not blow up here: the contacts' nonlinearity keeps the
// unstable mode bounded, and the run would end with plausible-looking nonsense (the ball-DOF
// model at seed 004's 10 µs: x acceleration 3000 times too large; at 5 µs with μ_m = 0.05, where
// the balls' spin relaxes onto its traction equilibrium at ~1e6 1/s: 80 times). So a fixed
// explicit step is checked against the linearised system at the start (the static state); a step
// that is stable there but not at a later, harder impact still shows up as a blow-up or in a dt
// convergence check.
void check_explicit_step(const Case& c, const BearingModel& model, const std::vector<double>& q0,
                         const std::vector<double>& v0) {
  if (c.solver.method != IntegratorMethod::rk4) return;
  const StepLimit limit = rk4_step_limit(model, 0.0, q0.data(), v0.data());
  if (c.solver.dt <= limit.step) return;
  const auto g3 = [](double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return std::string(buf);
  };
  const bool relaxation = limit.imag < 1e-3 * std::abs(limit.real);
  const std::string mode = relaxation
                               ? "a relaxation at rate " + g3(-limit.real) +
                                     " 1/s (stiff damping or traction, e.g. a ball's spin)"
                               : "an oscillation at " + g3(limit.imag) + " rad/s (" +
                                     g3(limit.imag / 6.283185307179586) + " Hz, a stiff contact)";
  throw InputError("solver.dt = " + g3(c.solver.dt * 1e6) + " us: RK4 is unstable above dt = " +
                   g3(limit.step * 1e6) + " us for the fastest mode of this case at its static " +
                   "state, " + mode + "; use solver.dt <= " + g3(0.9 * limit.step * 1e6) +
                   " us, or solver.method = \"newmark\" (stable at any step)");
}

// A dynamic model (2dof, 3dof, balls) through the case's integrator. The ring's DOFs (the first
// dof_names().size()) get channels of their own; ball DOFs reach the output as per-ball channels.
void run_dynamic(const Case& c, const Progress& progress, SimulationResult& r) {
  const auto model = make_model(c);
  const std::vector<double> q0 = model->initial_displacement();
  const std::vector<double> v0 = model->initial_velocity();

  // One tolerance for the user: the absolute tolerance on displacements is solver.tolerance times
  // the displacement scale of the problem (the static deflection, the per-ball gap, at least
  // 1 µm), so tightening the tolerance is never capped by a fixed absolute floor.
  double scale = std::max(1e-6, c.bearing.ball_gap());
  for (int i = 0; i < model->dofs(); ++i)
    if (!model->cyclic(i)) scale = std::max(scale, std::fabs(q0[static_cast<std::size_t>(i)]));
  IntegratorSettings settings;
  settings.method = c.solver.method;
  settings.dt = c.solver.dt;
  settings.rtol = c.solver.tolerance;
  settings.atol = c.solver.tolerance * scale;
  settings.max_displacement = c.solver.max_displacement;
  const auto integrator = make_integrator(settings);
  check_explicit_step(c, *model, q0, v0);

  const int Z = model->balls();
  Response& out = r.response;
  const std::vector<std::string> ring = model->dof_names();
  const auto n = static_cast<int>(ring.size());
  lay_out(c, ring, Z, out);
  const std::size_t samples = out.time.size();

  BallSample balls(Z);
  std::size_t k = 0;
  const Observer observe = [&](double t, const double* q, const double* v, const double* a) {
    for (int i = 0; i < n; ++i) {
      out.values[static_cast<std::size_t>(i)][k] = q[i];
      out.values[static_cast<std::size_t>(n + i)][k] = v[i];
      out.values[static_cast<std::size_t>(2 * n + i)][k] = a[i];
    }
    if (c.output.ball_loads) model->ball_loads(t, q, balls.loads.data());
    if (c.output.ball_approach) model->ball_approaches(t, q, balls.approaches.data());
    if (wants_ball_motion(c)) model->ball_motion(t, q, v, balls.r.data(), balls.vr.data());
    if (c.output.ball_dynamics)
      model->ball_dynamics(t, q, v, balls.spin.data(), balls.outer_load.data(),
                           balls.friction_inner.data(), balls.friction_outer.data());
    store_balls(c, static_cast<std::size_t>(3 * n), k, balls, out);
    ++k;
  };
  r.stats = integrator->integrate(*model, 0.0, q0, v0, out.time, observe, progress);
  if (k != samples)
    throw SolverError("the integrator delivered " + std::to_string(k) + " of " +
                      std::to_string(samples) + " output samples");
}

// The quasi-static model: the equilibrium followed through the output times. It has no
// acceleration of its own (no inertia); ax, ay are the centred differences of the analytic
// velocities, (v_{k+1} − v_{k−1}) / (2Δt), the mean acceleration over [t_{k−1}, t_{k+1}]
// (one-sided at the ends), so spectra of a* work as for the dynamic models.
void run_quasi_static(const Case& c, const Progress& progress, SimulationResult& r) {
  const auto model = make_quasi_static_model(model_inputs(c));
  const int Z = model->balls();
  Response& out = r.response;
  lay_out(c, {"x", "y"}, Z, out);
  BallSample balls(Z);
  std::size_t k = 0;
  const auto observe = [&](const QuasiStaticPoint& pt) {
    for (int i = 0; i < 2; ++i) {
      out.values[static_cast<std::size_t>(i)][k] = pt.position[i];
      out.values[static_cast<std::size_t>(2 + i)][k] = pt.velocity[i];
    }
    if (c.output.ball_loads) model->ball_loads(pt.t, pt.position, balls.loads.data());
    if (c.output.ball_approach) model->ball_approaches(pt.t, pt.position, balls.approaches.data());
    if (wants_ball_motion(c)) model->ball_motion(pt, balls.r.data(), balls.vr.data());
    store_balls(c, 6, k, balls, out);
    ++k;
  };
  QuasiStaticStats st = follow_equilibrium(*model, out.time, observe, progress);
  const std::size_t m = out.time.size();
  for (int i = 0; i < 2; ++i) {
    const auto& v = out.values[static_cast<std::size_t>(2 + i)];
    auto& a = out.values[static_cast<std::size_t>(4 + i)];
    for (std::size_t s = 0; s < m; ++s) {
      const std::size_t lo = s == 0 ? 0 : s - 1, hi = s + 1 == m ? s : s + 1;
      a[s] = hi > lo ? (v[hi] - v[lo]) / (out.time[hi] - out.time[lo]) : 0.0;
    }
  }
  r.stats.steps = st.steps;
  r.quasi_static = st;
}

}  // namespace

SimulationResult simulate(const Case& c, const Progress& progress) {
  SimulationResult r;
  r.contact = contact_constants(c);
  r.frequencies = run_frequencies(c);
  if (c.model.kind == ModelKind::quasi_static)
    run_quasi_static(c, progress, r);
  else
    run_dynamic(c, progress, r);
  return r;
}

RunSummary summarize(const Case& c, const SimulationResult& result) {
  const Response& resp = result.response;
  RunSummary s;
  const Window window = c.output.window;
  const double rate = c.solver.output_rate;
  const auto& f = result.frequencies;
  const auto names = bearing_frequency_names(f.shaft, f.ftf, f.bpfo, f.bpfi, f.bsf);
  std::unique_ptr<SpectrumPlan> plan;  // one window and FFT table for all channels
  for (std::size_t i = 0; i < resp.channels.size(); ++i) {
    ChannelSummary ch;
    ch.name = resp.channels[i];
    ch.unit = resp.units[i];
    const std::vector<double> x = resp.steady(ch.name);
    ch.statistics = channel_statistics(x);
    if (!is_ball_channel(ch.name)) {
      if (!plan) plan = std::make_unique<SpectrumPlan>(x.size(), rate, window);
      Spectrum spectrum = (*plan)(x);
      ch.peaks = find_peaks(spectrum, names, c.output.peaks);
      s.spectrum_channels.push_back(ch.name);
      s.spectra.push_back(std::move(spectrum));
    }
    s.channels.push_back(std::move(ch));
  }
  if (c.acoustics.enabled)
    s.noise = bearing_noise(c, resp, 2 * 3.14159265358979323846 * result.frequencies.ftf);
  return s;
}

}  // namespace bearing
