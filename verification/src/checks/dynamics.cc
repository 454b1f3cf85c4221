// Dynamics checks at zero speed, where the ring on its Hertz contacts is a conservative (or
// viscously damped) oscillator with closed-form references: energy conservation, the static limit
// of a long damped run, the convergence orders of RK4 and Newmark against the linearised free
// vibration, the natural frequency and the damping ratio of a free decay. The spectral lines and
// the model reductions are in dynamics_spectra.cc.
//
// The setting of all of them: a preset (mostly the 6308 of seed 003) at rest under F_y = −300 N,
// ball 0 at the bottom so the ball set is symmetric about the load. An outer-race waviness
// harmonic, absent from the model's initial state (the static solution of the perfect bearing),
// moves the equilibrium and so starts the motion. Order 1, A sin θ, is a pure shift of the race by
// A along y: the ring swings about y₀ − A, in y alone.

#include <array>
#include <cmath>

#include "../families.h"
#include "bearing/presets.h"
#include "dynamics_closed_forms.h"
#include "dynamics_runs.h"

namespace bearing::verify {

namespace {

using namespace dynamics;
namespace cf = closed_form;

constexpr double kLoad = -300.0;  // F_y [N]

ModelInputs at_rest(const Context& ctx, double damping, const std::string& bearing = "6308") {
  return case_inputs(ctx, {"bearing.preset=" + bearing, "operation.speed=0rpm",
                           "operation.load=[0, -300]", "rotor.damping=" + fmt(damping, 17)});
}

// A perfect preset at rest: its balls, the closed-form constant and the static state.
struct RestState {
  Bearing b;
  cf::RingContacts ring;
  std::array<double, 2> q{};
  double kyy = 0;
};
RestState rest_state(const std::string& bearing = "6308") {
  RestState s;
  s.b = preset(bearing);
  const double K = cf::ball_constant(s.b);
  s.ring = cf::ring_contacts(s.b, K, kBottom);
  // Start below the equilibrium (the bottom ball alone carrying the load), in contact.
  s.q = s.ring.equilibrium(0.0, kLoad, 0.0, -(s.ring.gap + std::pow(-kLoad / K, 2.0 / 3.0)));
  std::array<double, 2> f;
  std::array<double, 3> k;
  s.ring.force(s.q[0], s.q[1], f, k);
  s.kyy = k[2];
  return s;
}

// ---------------------------------------------------------------------------------------------
// Energy: no damping, constant load, released by a 2 µm order-1 waviness (x and y swing).

constexpr double kEnergyAmplitude = 2e-6, kEnergyPhase = 0.6, kEnergyTime = 0.02;

struct EnergyRun {
  double drift = 0;  // max |E − E₀| / max kinetic energy
  double bound = 0;  // ω T (ω h)⁴/60
};

EnergyRun energy_run(const Context& ctx, double dt) {
  ModelInputs in = at_rest(ctx, 0.0);
  add_waviness(in, false, 1, kEnergyAmplitude, kEnergyPhase);
  const double mass = in.mass;  // the case's mass, before any mutation
  RunSpec s;
  s.dt = dt;
  s.duration = kEnergyTime;
  s.rate = 50000.0;
  const Response r = run(ctx, in, s);
  RestState st = rest_state();
  for (std::size_t j = 0; j < st.ring.theta.size(); ++j)
    st.ring.offset[j] = kEnergyAmplitude * std::sin(st.ring.theta[j] + kEnergyPhase);
  const auto &x = r.channel("x"), &y = r.channel("y"), &vx = r.channel("vx"), &vy = r.channel("vy");
  double e0 = 0, drift = 0, kinetic = 0, kmax = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double ke = 0.5 * mass * (vx[i] * vx[i] + vy[i] * vy[i]);
    const double e = ke + st.ring.potential(x[i], y[i]) - kLoad * y[i];
    if (i == 0) e0 = e;
    drift = std::max(drift, std::fabs(e - e0));
    kinetic = std::max(kinetic, ke);
    std::array<double, 2> f;
    std::array<double, 3> k;
    st.ring.force(x[i], y[i], f, k);
    const double tr = k[0] + k[2], det = k[0] * k[2] - k[1] * k[1];
    kmax = std::max(kmax, 0.5 * tr + std::sqrt(std::max(0.0, 0.25 * tr * tr - det)));
  }
  EnergyRun e;
  e.drift = kinetic > 0 ? drift / kinetic : 1.0;
  const double w = std::sqrt(kmax / mass);
  e.bound = w * kEnergyTime * std::pow(w * dt, 4) / 60.0;
  return e;
}

Outcome energy_conservation(const Context& ctx) {
  Figure fig{"dynamics-energy-drift",
             "Energy drift of an undamped run (RK4) vs step",
             "dt [s]",
             "max|E - E0| / max kinetic energy [-]",
             true,
             true,
             {},
             {}};
  Series drift{"measured drift", {}, {}, "line+marker"}, bound{"RK4 bound", {}, {}, "line"};
  EnergyRun last;
  for (double dt : {20e-6, 10e-6, 5e-6}) {
    last = energy_run(ctx, dt);
    drift.x.push_back(dt), drift.y.push_back(std::max(last.drift, 1e-300));
    bound.x.push_back(dt), bound.y.push_back(last.bound);
  }
  fig.series = {drift, bound};
  Outcome o;
  o.value = last.drift;
  o.reference = 0.0;
  o.detail = "drift at dt = 20, 10, 5 us: " + fmt(drift.y[0], 3) + ", " + fmt(drift.y[1], 3) +
             ", " + fmt(drift.y[2], 3) + " (ratio " + fmt(drift.y[1] / drift.y[2], 3) +
             " per halving); bound at 5 us " + fmt(last.bound, 3);
  o.figures = {fig};
  return o;
}

// The ball-DOF model (seed 004) at rest without friction or damping: the ring and the balls'
// radial motion exchange energy through the two contacts of each ball, K_i δ_i^{5/2}/(5/2) +
// K_o δ_o^{5/2}/(5/2) with δ_o = r_j + Π_o(θ_j), δ_i = x cos θ_j + y sin θ_j − r_j − γ
// (ball_dofs.h), K per race in closed form, m_b = ρ π D³/6 of the preset's steel.

Outcome ball_energy_conservation(const Context& ctx) {
  ModelInputs in = case_inputs(
      ctx, {"model.kind=balls", "operation.speed=0rpm", "operation.load=[0, -300]",
            "rotor.damping=0", "ball.damping=0", "ball.centrifugal=false", "cage.friction=0"});
  add_waviness(in, false, 1, kEnergyAmplitude, kEnergyPhase);
  const double mass = in.mass, dt = 0.5e-6, duration = 0.005;
  RunSpec s;
  s.kind = ModelKind::balls;
  s.dt = dt;
  s.duration = duration;
  s.rate = 50000.0;
  OutputRequest request;
  request.ball_motion = true;
  const Response r = ctx.simulate(s.kind, ctx.perturbed(in), solver_settings(s), request).response;
  const Bearing b = preset("6308");
  const double Ki = cf::race_constant(b, true), Ko = cf::race_constant(b, false);
  const double D = b.ball_diameter, mb = b.ball.density * cf::kPi / 6 * D * D * D;
  const int Z = b.balls;
  const auto &x = r.channel("x"), &y = r.channel("y"), &vx = r.channel("vx"), &vy = r.channel("vy");
  double e0 = 0, drift = 0, kinetic = 0, w2 = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    double ke = 0.5 * mass * (vx[i] * vx[i] + vy[i] * vy[i]), u = 0, kyy = 0;
    for (int j = 0; j < Z; ++j) {
      const double th = kBottom + 2 * cf::kPi * j / Z;
      const double rj = r.channel("r" + std::to_string(j + 1))[i];
      const double vr = r.channel("vr" + std::to_string(j + 1))[i];
      const double dout = rj + kEnergyAmplitude * std::sin(th + kEnergyPhase);
      const double din = x[i] * std::cos(th) + y[i] * std::sin(th) - rj - 0.5 * b.clearance;
      ke += 0.5 * mb * vr * vr;
      double kb = 0;
      if (dout > 0) u += Ko * std::pow(dout, 2.5) / 2.5, kb += 1.5 * Ko * std::sqrt(dout);
      if (din > 0) u += Ki * std::pow(din, 2.5) / 2.5, kb += 1.5 * Ki * std::sqrt(din);
      if (din > 0) kyy += 1.5 * Ki * std::sqrt(din);
      w2 = std::max(w2, kb / mb);
    }
    w2 = std::max(w2, kyy / mass);
    const double e = ke + u - kLoad * y[i];
    if (i == 0) e0 = e;
    drift = std::max(drift, std::fabs(e - e0));
    kinetic = std::max(kinetic, ke);
  }
  const double w = std::sqrt(w2);
  Outcome o;
  o.value = kinetic > 0 ? drift / kinetic : 1.0;
  o.reference = 0.0;
  o.detail = "stiffest mode w = " + fmt(w, 4) +
             " rad/s, bound w T (w h)^4/60 = " + fmt(w * duration * std::pow(w * dt, 4) / 60, 3) +
             "; ball mass " + fmt(mb, 6) + " kg";
  return o;
}

// ---------------------------------------------------------------------------------------------
// Static limit: 0.3 s with the case's damping (ζω_n = c/2m = 167 1/s, the transient decays by
// e^-50) under a waviness harmonic, against the equilibrium of the closed-form contacts.

Outcome static_limit(const Context& ctx, int order, bool tvds,
                     ContactLoop loop = ContactLoop::simd) {
  const double amplitude = 2e-6, phase = 0.3;
  ModelInputs in = at_rest(ctx, 200.0);
  in.contact_loop = loop;
  add_waviness(in, false, order, amplitude, phase);
  in.waviness_stiffness = tvds;
  RunSpec s;
  s.duration = 0.3;
  s.rate = 1000.0;
  const Response r = run(ctx, in, s);
  RestState st = rest_state();
  for (std::size_t j = 0; j < st.ring.theta.size(); ++j) {
    const double th = st.ring.theta[j];
    st.ring.offset[j] = amplitude * std::sin(order * th + phase);
    if (tvds)
      st.ring.K[j] = cf::ball_constant(
          st.b, 0.0, cf::tvds_curvature_change(st.b, false, order, amplitude, phase, th));
  }
  const auto q = st.ring.equilibrium(0.0, kLoad, st.q[0], st.q[1]);
  Outcome o;
  o.value = r.channel("y").back();
  o.reference = q[1];
  o.detail = "x = " + fmt(r.channel("x").back(), 9) + " m vs " + fmt(q[0], 9) +
             " m; perfect bearing y = " + fmt(st.q[1], 9) + " m";
  return o;
}

// ---------------------------------------------------------------------------------------------
// Free vibration about the shifted equilibrium: y(t) = y₀ − A + u(t), u the free decay of
// m ü + c u̇ + k_yy u = 0 from u(0) = A, k_yy the closed-form Hertz stiffness at y₀.

Response free_vibration(const Context& ctx, double amplitude, double damping, const RunSpec& s,
                        const std::string& bearing = "6308") {
  ModelInputs in = at_rest(ctx, damping, bearing);
  add_waviness(in, false, 1, amplitude, 0.0);
  return run(ctx, in, s);
}

// max_t |y(t) − y_lin(t)| / A.
double linear_error(const Response& r, double amplitude, double mass, double damping, double kyy) {
  const auto& y = r.channel("y");
  double e = 0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    const double lin = y[0] - amplitude + cf::free_decay(amplitude, mass, damping, kyy, r.time[i]);
    e = std::max(e, std::fabs(y[i] - lin));
  }
  return e / amplitude;
}

struct OrderStudy {
  IntegratorMethod method;
  const char* name;
  double amplitude;  // small enough that the linearisation error is ~1 % of the finest error
  double h;          // the coarsest step; then h/2, h/4
  double order;
};

Outcome observed_order(const Context& ctx, const OrderStudy& study) {
  const RestState st = rest_state();
  const double mass = at_rest(ctx, 200.0).mass;
  Series err{std::string(study.name) + " error", {}, {}, "line+marker"};
  Series slope{"slope " + fmt(study.order, 2), {}, {}, "line"};
  for (double h : {study.h, study.h / 2, study.h / 4}) {
    RunSpec s;
    s.method = study.method;
    s.dt = h;
    s.duration = 0.01;
    s.rate = 5000.0;
    s.tolerance = 1e-10;  // Newmark's Newton far below its truncation error
    const double e = linear_error(free_vibration(ctx, study.amplitude, 200.0, s), study.amplitude,
                                  mass, 200.0, st.kyy);
    err.x.push_back(h), err.y.push_back(std::max(e, 1e-300));
  }
  for (double h : err.x)
    slope.x.push_back(h), slope.y.push_back(err.y[2] * std::pow(h / err.x[2], study.order));
  Outcome o;
  o.value = std::log2(err.y[1] / err.y[2]);
  o.reference = study.order;
  o.detail = "max|y - y_lin|/A at h, h/2, h/4 = " + fmt(err.y[0], 3) + ", " + fmt(err.y[1], 3) +
             ", " + fmt(err.y[2], 3) + " (h = " + fmt(study.h, 3) +
             " s); order from the "
             "coarse pair " +
             fmt(std::log2(err.y[0] / err.y[1]), 4);
  Figure fig{std::string("dynamics-order-") + study.name,
             std::string(study.name) + ": error against the linearised free vibration",
             "dt [s]",
             "max|y - y_lin| / A [-]",
             true,
             true,
             {err, slope},
             {}};
  o.figures = {fig};
  return o;
}

// ---------------------------------------------------------------------------------------------
// Natural frequency and damping ratio of a free decay (A = 1 nm: the Hertz nonlinearity shifts
// the frequency by O((A/δ)²) ≈ 1e-8).

struct Decay {
  double frequency = 0;  // damped, from the extrema's spacing [Hz]
  double sigma = 0;      // decay rate ζω_n from ln of the half-swings [1/s]
  int extrema = 0;
  Series motion{"model: y - y(0) + A", {}, {}, "line"};
};

Decay measure_decay(const Context& ctx, const std::string& bearing) {
  RunSpec s;
  s.dt = 2e-6;
  s.duration = 0.025;
  s.rate = 100000.0;
  const Response r = free_vibration(ctx, 1e-9, 200.0, s, bearing);
  const auto ext = extrema(r.time, r.channel("y"));
  Decay d;
  const auto& y = r.channel("y");
  for (std::size_t i = 0; i < y.size() && r.time[i] <= 0.005; ++i)
    d.motion.x.push_back(r.time[i]), d.motion.y.push_back(y[i] - y[0] + 1e-9);
  d.extrema = int(ext.size());
  if (ext.size() < 6) return d;
  d.frequency = 0.5 * double(ext.size() - 1) / (ext.back().t - ext.front().t);
  // Least-squares slope of ln|y_{k+1} − y_k| over the mid-time of each half-swing.
  double st = 0, sl = 0, stt = 0, stl = 0;
  const double n = double(ext.size() - 1);
  for (std::size_t k = 0; k + 1 < ext.size(); ++k) {
    const double t = 0.5 * (ext[k].t + ext[k + 1].t);
    const double l = std::log(std::fabs(ext[k + 1].value - ext[k].value));
    st += t, sl += l, stt += t * t, stl += t * l;
  }
  d.sigma = -(n * stl - st * sl) / (n * stt - st * st);
  return d;
}

Outcome natural_frequency(const Context& ctx, const std::string& bearing) {
  const RestState st = rest_state(bearing);
  const double m = at_rest(ctx, 200.0, bearing).mass, c = 200.0;
  const double wn = std::sqrt(st.kyy / m), zeta = c / (2 * m * wn);
  const Decay d = measure_decay(ctx, bearing);
  Outcome o;
  o.value = d.frequency;
  o.reference = wn * std::sqrt(1 - zeta * zeta) / (2 * cf::kPi);
  Series lin{"closed form: linear free decay", {}, {}, "line"};
  for (double t : d.motion.x)
    lin.x.push_back(t), lin.y.push_back(cf::free_decay(1e-9, m, c, st.kyy, t));
  o.figures = {Figure{"dynamics-free-decay-" + bearing,
                      "Free decay of the " + bearing + " at rest, 300 N, 1 nm release",
                      "t [s]",
                      "y - y_eq [m]",
                      false,
                      false,
                      {lin, d.motion},
                      {},
                      Panel::trace}};
  o.detail = "f_n = " + fmt(wn / (2 * cf::kPi), 9) + " Hz (k_yy = " + fmt(st.kyy, 9) +
             " N/m, zeta = " + fmt(zeta, 6) + "), " + std::to_string(d.extrema) + " extrema";
  return o;
}

Outcome damping_ratio(const Context& ctx) {
  const RestState st = rest_state();
  const double m = at_rest(ctx, 200.0).mass, c = 200.0;
  const Decay d = measure_decay(ctx, "6308");
  const double wd = 2 * cf::kPi * d.frequency;
  Outcome o;
  o.value = d.extrema >= 6 ? d.sigma / std::sqrt(d.sigma * d.sigma + wd * wd) : 0.0;
  o.reference = c / (2 * m * std::sqrt(st.kyy / m));
  o.detail = "decay rate " + fmt(d.sigma, 9) + " 1/s over " + std::to_string(d.extrema) +
             " extrema; log decrement " + fmt(d.sigma / d.frequency, 6);
  return o;
}

// The conservation and static-limit rows.
std::vector<Check> conservation_and_limit_checks() {
  return {
      {"dynamics.energy-conservation.balls.6308",
       "dynamics",
       ReferenceKind::conservation,
       "value: max |E(t) - E(0)| / max kinetic energy of an undamped, frictionless ball-DOF run "
       "at rest (RK4, dt 0.5 us, 5 ms), E = ring and ball kinetic energies + both contacts' "
       "Hertz potentials (closed-form K_i, K_o) - F.q; reference: 0",
       "energy drift",
       "-",
       absolute(1.6e-4,
                "the RK4 bound w T (w h)^4/60 of dynamics.energy-conservation.rk4 with the "
                "stiffest mode a loaded ball between its contacts, w = 1.25e5 rad/s "
                "(dt 0.5 us, T 5 ms)"),
       Level::quick,
       0.3,
       {"mass-x1.05", "contact-constant-x1.03", "contact-exponent+0.05", "waviness-sign-swapped",
        "pitch-diameter-x1.01"},
       ball_energy_conservation},
      {"dynamics.energy-conservation.rk4.6308",
       "dynamics",
       ReferenceKind::conservation,
       "value: max |E(t) - E(0)| / max kinetic energy of an undamped 2-DOF run at rest (RK4, "
       "dt = 5 us, 20 ms), E = m v^2/2 + sum K delta^2.5/2.5 - F.q written here with the closed-"
       "form Hertz K and the case's mass; reference: 0 (a conservative system)",
       "energy drift",
       "-",
       absolute(6.5e-5,
                "RK4's local error is at most (w h)^5/120 of the motion per step for a motion "
                "of angular frequency w; over T/h steps the energy (quadratic) drifts by at most "
                "w T (w h)^4/60, w the stiffest linearised mode reached in the run (1.24e4 "
                "rad/s, dt 5 us, T 20 ms: 6.2e-5; the figure shows the measured drift falling "
                "with dt)"),
       Level::quick,
       0.3,
       {"mass-x1.05", "contact-constant-x1.03", "contact-exponent+0.05", "waviness-sign-swapped",
        "pitch-diameter-x1.01"},
       energy_conservation},
      {"dynamics.static-limit.6308",
       "dynamics",
       ReferenceKind::limit,
       "value: y of the 6308 after 0.3 s of a damped 2-DOF run at rest under F_y = -300 N and an "
       "outer waviness of order 3 (2 um), started from the perfect bearing's equilibrium; "
       "reference: the static equilibrium of the closed-form Hertz contacts with the waviness "
       "(Newton, written here)",
       "y",
       "m",
       relative(1e-8,
                "the transient has decayed by exp(-c T/2m) = e^-50; Newton's residual 1e-13 of "
                "the load; the closed-form Hertz K and the toolkit's agree to the root "
                "tolerances (1e-12); the RK4 fixed point is the exact equilibrium"),
       Level::quick,
       0.2,
       {"contact-constant-x1.03", "contact-exponent+0.05", "waviness-sign-swapped",
        "pitch-diameter-x1.01"},
       [](const Context& ctx) { return static_limit(ctx, 3, false); }},
      {"dynamics.static-limit.scalar-loop.6308",
       "dynamics",
       ReferenceKind::limit,
       "value: as dynamics.static-limit.6308 with solver.contact_loop = scalar, the scalar "
       "reference kernels (ball angles, contact forces), which every other run leaves to the "
       "SIMD ones; reference: the same closed-form equilibrium",
       "y",
       "m",
       relative(1e-8,
                "as dynamics.static-limit.6308: the scalar and SIMD loops give the same bits"),
       Level::quick,
       0.2,
       {"contact-constant-x1.03", "contact-exponent+0.05", "waviness-sign-swapped",
        "pitch-diameter-x1.01"},
       [](const Context& ctx) { return static_limit(ctx, 3, false, ContactLoop::scalar); }},
      {"dynamics.static-limit.tvds.6308",
       "dynamics",
       ReferenceKind::limit,
       "value: y of the 6308 after 0.3 s of a damped 2-DOF run at rest with TVDS and an outer "
       "waviness of order 33 (2 um); reference: the static equilibrium of the closed-form "
       "contacts whose K_j are recomputed from the race curvature 1/R - A(N^2-1) sin/R^2 "
       "(docs/model.md §3), Newton written here",
       "y",
       "m",
       relative(1e-8,
                "as dynamics.static-limit; the toolkit's TVDS table interpolates g(delta) to "
                "~1e-10 (cubic Hermite, 64 intervals)"),
       Level::quick,
       0.2,
       {"tvds-dropped", "waviness-sign-swapped", "contact-constant-x1.03", "contact-exponent+0.05"},
       [](const Context& ctx) { return static_limit(ctx, 33, true); }}};
}

}  // namespace

std::vector<Check> dynamics_checks() {
  const auto order = [](OrderStudy study) {
    return [study](const Context& ctx) { return observed_order(ctx, study); };
  };
  std::vector<Check> checks = {
      {"dynamics.order.rk4.6308",
       "dynamics",
       ReferenceKind::convergence,
       "value: observed order log2(e(h/2)/e(h/4)) of RK4 (h = 40 us) on the damped free "
       "vibration of the 6308 at rest, e = max|y - y_lin|/A against the closed-form linear "
       "decay (k_yy from the closed-form Hertz K, the case's m and c; A = 10 pm); reference: 4",
       "order",
       "-",
       absolute(0.1,
                "the next term of RK4's phase error is O((w h)^2) of the leading one, 0.01-0.05 "
                "at the finest pair (w h = 0.12, 0.23; w = 1.16e4 rad/s): < 0.07 in the order; "
                "the linearisation error A/(4 delta) = 4e-7 (delta = 6.7 um) is 1 % of the "
                "finest error: < 0.015"),
       Level::quick,
       0.2,
       {"mass-x1.05", "contact-constant-x1.03", "damping-x2", "waviness-sign-swapped"},
       order({IntegratorMethod::rk4, "rk4", 1e-11, 40e-6, 4.0})},
      {"dynamics.order.newmark.6308",
       "dynamics",
       ReferenceKind::convergence,
       "value: observed order log2(e(h/2)/e(h/4)) of Newmark (average acceleration, h = 10 us) "
       "on the damped free vibration of the 6308 at rest against the closed-form linear decay "
       "(A = 1 nm); reference: 2",
       "order",
       "-",
       absolute(0.1,
                "the next term of the trapezoidal rule's phase error is O((w h)^2) of the "
                "leading one, < 0.004 at the finest pair (w h = 0.03, 0.06): < 0.01 in the "
                "order; the linearisation error A/(4 delta) = 4e-5 is 2 % of the finest error: "
                "< 0.03; Newton at tolerance 1e-10"),
       Level::quick,
       0.3,
       {"mass-x1.05", "contact-constant-x1.03", "damping-x2", "waviness-sign-swapped"},
       order({IntegratorMethod::newmark, "newmark", 1e-9, 10e-6, 2.0})},
      {"dynamics.damping-ratio.6308",
       "dynamics",
       ReferenceKind::closed_form,
       "value: the damping ratio of the same free decay from its logarithmic decrement (least-"
       "squares slope of ln of the half-swings); reference: c/(2 m w_n), w_n of the closed-form "
       "Hertz stiffness",
       "zeta",
       "-",
       relative(2e-5,
                "a linear viscous decay's half-swings fall exactly as exp(-zeta w_n t); "
                "parabolic extremum values err by (w dt_out)^4/... < 1e-6 of the swing; the "
                "Hertz nonlinearity at A/delta = 1e-4 changes the decay rate by < 1e-5"),
       Level::quick,
       0.2,
       {"damping-x2", "mass-x1.05", "contact-constant-x1.03"},
       damping_ratio},
  };
  const std::vector<Check> first = conservation_and_limit_checks();
  checks.insert(checks.begin(), first.begin(), first.end());
  for (const std::string bearing : {"608", "6304", "6308", "6205", "209"})
    checks.push_back(
        {"dynamics.natural-frequency." + bearing,
         "dynamics",
         ReferenceKind::closed_form,
         "value: the damped frequency of the free decay of the " + bearing +
             " at rest under 300 N (1 nm "
             "release, RK4 dt 2 us), from its extrema's spacing; reference: f_n sqrt(1 - zeta^2), "
             "f_n = sqrt(k_yy/m)/2pi with k_yy = sum 1.5 K delta_j^0.5 sin^2 theta_j of the "
             "closed-form Hertz K at the closed-form equilibrium",
         "f_d",
         "Hz",
         relative(
             1e-5,
             "RK4 phase error (w dt)^4/120 = 1e-9; Hertz nonlinearity (A/delta)^2 = 1e-8; "
             "parabolic extremum times at >= 50 samples a period err by < 1e-8 s each, over 15 "
             "ms: < 1e-6"),
         Level::quick,
         0.2,
         {"mass-x1.05", "contact-constant-x1.03", "contact-exponent+0.05", "damping-x2",
          "pitch-diameter-x1.01"},
         [bearing](const Context& ctx) { return natural_frequency(ctx, bearing); }});
  return checks;
}

}  // namespace bearing::verify
