// Dynamics checks of the running bearing: spectral lines at the classical frequencies, written
// from the textbook kinematics of the true preset geometry (docs/model.md §2), and the reductions
// of the 3-DOF and ball-DOF models to the 2-DOF model.
//
// Where the lines are. The system is periodic in the ball passage and, with inner waviness, in
// the shaft rotation. A fixed-frame load zone weights ball j by Σ_m c_m e^{imθ_j}; the excitation
// of an outer harmonic of order N, e^{iNθ_j}, summed over the Z balls survives only for
// m + N ≡ 0 (mod Z), so outer waviness drives only BPFO multiples, the strongest q·BPFO with
// |qZ − N| smallest (N = 2Z + 1: 2·BPFO). An inner harmonic, e^{iN(θ_j − ω_i t)}, gives lines at
// N f_r − p·BPFO; the strongest, |pZ − N| = 1, for N = Z + 1 is BPFI + f_r (BPFI = Z (f_r − f_c)).
// The varying compliance of the perfect bearing is BPFO = Z f_c itself; cage slip s_c turns
// every cage-driven line to (1 − s_c)·f (seed 004 eq. 26).

#include <algorithm>
#include <array>
#include <cmath>

#include "../families.h"
#include "bearing/presets.h"
#include "bearing/signal/peaks.h"
#include "bearing/signal/spectrum.h"
#include "dynamics_closed_forms.h"
#include "dynamics_runs.h"

namespace bearing::verify {

namespace {

using namespace dynamics;
namespace cf = closed_form;

constexpr double kShaft = 2000.0 / 60.0;  // the default case's 2000 rpm [Hz]

cf::Kinematics true_kinematics(const std::string& bearing = "6308") {
  return cf::kinematics(preset(bearing), kShaft);
}

// The strongest spectral line within ±5 % of `expected`, from a record of whole periods of the
// expected frequency (so a line at it sits on a bin, where the parabolic refinement of the Hann
// spectrum is unbiased).
struct Line {
  double frequency = 0;
  Spectrum spectrum;
};
Line strongest_line(const Response& r, const std::string& channel, double expected) {
  const std::vector<double> steady = r.steady(channel);
  const double periods = std::floor(double(steady.size()) * expected / r.rate);
  const auto n = static_cast<std::size_t>(std::lround(periods * r.rate / expected));
  const std::vector<double> x(steady.begin(), steady.begin() + long(std::min(n, steady.size())));
  Line line;
  line.spectrum = amplitude_spectrum(x, r.rate, Window::hann);
  double best = 0;
  for (const Peak& p : find_peaks(line.spectrum, {}, 200, 1e-9))
    if (std::fabs(p.frequency / expected - 1) < 0.05 && p.amplitude > best)
      best = p.amplitude, line.frequency = p.frequency;
  return line;
}

Figure spectrum_figure(const std::string& name, const std::string& title, const Spectrum& sp,
                       double f_max, std::vector<Marker> markers) {
  Series s{"|Y(f)|", {}, {}, "line"};
  for (std::size_t k = 1; k < sp.frequency.size() && sp.frequency[k] <= f_max; ++k)
    s.x.push_back(sp.frequency[k]), s.y.push_back(std::max(sp.amplitude[k], 1e-16));
  Figure f{name, title, "frequency [Hz]", "amplitude of y [m]", false, true, {s}, markers};
  f.panel = Panel::spectrum;
  return f;
}

Outcome line_outcome(const Line& line, double expected, Figure fig) {
  Outcome o;
  o.value = line.frequency;
  o.reference = expected;
  o.detail = "record of " + std::to_string(line.spectrum.amplitude.size() * 2 - 2) +
             " samples, bin " + fmt(line.spectrum.resolution, 6) + " Hz";
  o.figures = {std::move(fig)};
  return o;
}

RunSpec running(double duration = 0.5) {
  RunSpec s;
  s.duration = duration;
  s.transient = 0.1;
  s.rate = 20000.0;
  return s;
}

// ---------------------------------------------------------------------------------------------

Outcome bpfo_line(const Context& ctx, const std::string& bearing) {
  const cf::Kinematics k = true_kinematics(bearing);
  const Response r = run(ctx, case_inputs(ctx, {"bearing.preset=" + bearing}), running());
  const Line line = strongest_line(r, "y", k.bpfo);
  return line_outcome(
      line, k.bpfo,
      spectrum_figure("dynamics-spectrum-bpfo-" + bearing,
                      bearing + ", 20 N, 2000 rpm: varying compliance", line.spectrum, 4.5 * k.bpfo,
                      {{k.bpfo, "BPFO"},
                       {2 * k.bpfo, "2xBPFO"},
                       {3 * k.bpfo, "3xBPFO"},
                       {4 * k.bpfo, "4xBPFO"}}));
}

Outcome waviness_line(const Context& ctx, bool inner) {
  const cf::Kinematics k = true_kinematics();
  ModelInputs in = case_inputs(ctx, {});
  const int Z = in.bearing.balls;
  add_waviness(in, inner, inner ? Z + 1 : 2 * Z + 1, 1e-6, 0.0);
  const Response r = run(ctx, in, running());
  const double expected = inner ? k.bpfi + k.shaft : 2 * k.bpfo;
  const Line line = strongest_line(r, "y", expected);
  std::vector<Marker> m =
      inner ? std::vector<Marker>{{k.bpfo, "BPFO"},
                                  {k.bpfi - k.shaft, "BPFI-fr"},
                                  {k.bpfi, "BPFI"},
                                  {k.bpfi + k.shaft, "BPFI+fr"},
                                  {(Z + 1) * k.shaft - 2 * k.bpfo, "9fr-2BPFO"}}
            : std::vector<Marker>{{k.bpfo, "BPFO"}, {2 * k.bpfo, "2xBPFO"}, {3 * k.bpfo, "3xBPFO"}};
  const std::string race = inner ? "inner" : "outer";
  return line_outcome(line, expected,
                      spectrum_figure("dynamics-spectrum-waviness-" + race,
                                      "6308, " + race + " waviness of order " +
                                          std::to_string(inner ? Z + 1 : 2 * Z + 1) + " (1 um)",
                                      line.spectrum, 1.6 * expected, m));
}

Outcome cage_slip_line(const Context& ctx) {
  const double slip = 0.05;
  const cf::Kinematics k = true_kinematics();
  ModelInputs in =
      case_inputs(ctx, {"model.kind=balls", "cage.slip=0.05", "ball.centrifugal=false"});
  RunSpec s = running();
  s.kind = ModelKind::balls;
  const Response r = run(ctx, in, s);
  const double expected = (1 - slip) * k.bpfo;
  const Line line = strongest_line(r, "y", expected);
  return line_outcome(
      line, expected,
      spectrum_figure("dynamics-spectrum-cage-slip", "6308 ball-DOF model, cage slip 5 %",
                      line.spectrum, 2.5 * k.bpfo,
                      {{expected, "(1-s)BPFO"}, {k.bpfo, "BPFO"}, {2 * expected, "2(1-s)BPFO"}}));
}

// The quasi-static limit of a running bearing: the ball passage (BPFO ~ 100 Hz) is far below the
// contact resonance (~2 kHz), so the mean of y over whole ball-pass periods is the static
// equilibrium averaged over one ball pass. The time average of m ÿ + c ẏ over a period is zero,
// so the mean contact force is the load exactly; the mean deflection differs from the averaged
// static one only through the dynamic part of the ripple, (f_BPFO/f_n)² of it, times the
// curvature of the force law: (f/f_n)² × ripple/δ relative, ~1e-5 here.

// The models a reduction row compares with the 2-DOF model, in the reduction's configuration
// but under 500 N without waviness: each must reach the same closed-form static limit on its own,
// so that a reduction never rests on code the two models share (contact law, kinematics) alone.
// 3-DOF: centred, no axial load. Balls: 1 mg, c_b 0.2 N s/m, no friction, slip or centrifugal
// load, Newmark (the light balls are stiff).
Outcome mean_deflection_of(const Context& ctx, ModelKind kind) {
  const cf::Kinematics k = true_kinematics();
  std::vector<std::string> sets = {"operation.load=[0, -500]"};
  RunSpec spec = running();
  spec.kind = kind;
  if (kind == ModelKind::balls) {
    for (const char* s : {"model.kind=balls", "cage.friction=0", "ball.mass=1e-6kg",
                          "ball.damping=0.2", "ball.centrifugal=false"})
      sets.push_back(s);
    spec.method = IntegratorMethod::newmark;
  }
  ModelInputs in = case_inputs(ctx, sets);
  const Response r = run(ctx, in, spec);
  const std::vector<double> y = r.steady("y");
  const auto n = static_cast<std::size_t>(
      std::lround(std::floor(double(y.size()) * k.bpfo / r.rate) * r.rate / k.bpfo));
  double mean = 0;
  for (std::size_t i = 0; i < n; ++i) mean += y[i] / double(n);
  const Bearing b = preset("6308");
  const double K = cf::ball_constant(b);
  const int steps = 400;
  double average = 0, lo = 1e300, hi = -1e300;
  std::array<double, 2> q = {0.0, -(0.5 * b.clearance + std::pow(500.0 / K, 2.0 / 3.0))};
  for (int s = 0; s < steps; ++s) {
    const cf::RingContacts ring =
        cf::ring_contacts(b, K, kBottom + 2 * cf::kPi / b.balls * s / steps);
    q = ring.equilibrium(0.0, -500.0, q[0], q[1]);
    average += q[1] / steps;
    lo = std::min(lo, q[1]), hi = std::max(hi, q[1]);
  }
  Outcome o;
  o.value = mean;
  o.reference = average;
  o.detail = "static ripple over a ball pass " + fmt(hi - lo, 4) + " m; mean over " +
             std::to_string(n) + " samples (whole BPFO periods)";
  return o;
}

Outcome mean_deflection(const Context& ctx) {
  return mean_deflection_of(ctx, ModelKind::two_dof);
}

// ---------------------------------------------------------------------------------------------
// Reductions: the model under test through the Context, the 2-DOF model as the reference
// (unperturbed, run_reference), max|y − y_2DOF| over the record against the 2-DOF peak-to-peak.

Outcome reduction(const Context& ctx, const ModelInputs& in, RunSpec s, ModelKind kind) {
  s.kind = kind;
  const Response a = run(ctx, in, s);
  s.kind = ModelKind::two_dof;
  const Response b = run_reference(in, s);
  const std::vector<double> ya = a.steady("y"), yb = b.steady("y");
  double diff = 0, lo = 1e300, hi = -1e300;
  for (std::size_t i = 0; i < std::min(ya.size(), yb.size()); ++i) {
    diff = std::max(diff, std::fabs(ya[i] - yb[i]));
    lo = std::min(lo, yb[i]), hi = std::max(hi, yb[i]);
  }
  Outcome o;
  o.value = hi > lo ? diff / (hi - lo) : 1.0;
  o.reference = 0.0;
  o.detail =
      "max |y - y_2dof| = " + fmt(diff, 4) + " m, 2-DOF peak-to-peak " + fmt(hi - lo, 4) + " m";
  Series sa{"model under test", {}, {}, "line"}, sb{"2-DOF reference", {}, {}, "line"};
  for (std::size_t i = 0; i < std::min<std::size_t>(ya.size(), 400); ++i) {
    const double t = s.transient + double(i) / s.rate;
    sa.x.push_back(t), sa.y.push_back(ya[i]);
    sb.x.push_back(t), sb.y.push_back(yb[i]);
  }
  o.figures = {
      Figure{std::string("dynamics-reduction-") + (kind == ModelKind::balls ? "balls" : "3dof"),
             "y of the reduced model and of the 2-DOF model",
             "t [s]",
             "y [m]",
             false,
             false,
             {sb, sa},
             {},
             Panel::trace}};
  return o;
}

Outcome reduction_3dof(const Context& ctx) {
  ModelInputs in = case_inputs(ctx, {});
  add_waviness(in, true, 9, 0.5e-6, 0.0);
  return reduction(ctx, in, running(0.2), ModelKind::three_dof);
}

Outcome reduction_balls(const Context& ctx) {
  ModelInputs in = case_inputs(ctx, {"model.kind=balls", "cage.friction=0", "ball.mass=1e-6kg",
                                     "ball.damping=0.2", "ball.centrifugal=false"});
  add_waviness(in, false, 9, 0.3e-6, 0.0);
  RunSpec s = running(0.2);
  s.method = IntegratorMethod::newmark;  // the 1 mg balls are stiff
  return reduction(ctx, in, s, ModelKind::balls);
}

}  // namespace

std::vector<Check> dynamics_spectra_checks() {
  const char* line_why =
      "the record holds whole periods of the expected line, so a line there sits on a bin and "
      "the parabolic vertex of the Hann log-spectrum is unbiased; the other lines (>= 40 bins "
      "away, Hann sidelobes ~k^-3) shift it by < 1e-3 bin; bound 0.01 bin of the 0.4 s record";
  std::vector<Check> checks = {
      {"dynamics.mean-deflection.6308",
       "dynamics",
       ReferenceKind::limit,
       "value: mean of y over whole BPFO periods of the perfect 6308 at 2000 rpm under 500 N "
       "(2-DOF, RK4 5 us); reference: the closed-form static equilibrium (Hertz K and Newton "
       "written here) averaged over 400 ball phases of one ball pass",
       "mean y",
       "m",
       relative(1e-4,
                "the mean contact force equals the load exactly over whole periods; the mean "
                "deflection departs from the averaged static one by (f_BPFO/f_n)^2 x ripple/delta "
                "times a factor of order one: (102 Hz/2.1 kHz)^2 x 6.8e-8 m/8.9e-6 m = 1.8e-5; "
                "the 400-phase trapezoid average of a smooth periodic function is spectrally "
                "exact"),
       Level::quick,
       0.3,
       {"contact-constant-x1.03", "contact-exponent+0.05"},
       mean_deflection},
      {"dynamics.mean-deflection.3dof.6308",
       "dynamics",
       ReferenceKind::limit,
       "value: as dynamics.mean-deflection.6308 with the 3-DOF model (centred, no axial load), "
       "the anchor of dynamics.reduction.3dof-to-2dof: the reduced model reaches the closed form "
       "on its own; reference: the same closed-form static equilibrium",
       "mean y",
       "m",
       relative(1e-4,
                "as dynamics.mean-deflection.6308: the 3-DOF model without axial load or offset "
                "is the 2-DOF model to rounding (three_dof.h reduction (b))"),
       Level::quick,
       0.3,
       {"contact-constant-x1.03", "contact-exponent+0.05"},
       [](const Context& ctx) { return mean_deflection_of(ctx, ModelKind::three_dof); }},
      {"dynamics.mean-deflection.balls.6308",
       "dynamics",
       ReferenceKind::limit,
       "value: as dynamics.mean-deflection.6308 with the ball-DOF model of "
       "dynamics.reduction.balls-to-2dof (1 mg balls, c_b 0.2 N s/m, no friction, slip or "
       "centrifugal load, Newmark 5 us), its anchor: the reduced model reaches the closed form "
       "on its own; reference: the same closed-form static equilibrium",
       "mean y",
       "m",
       relative(1e-4,
                "over whole periods the ball's mean net force is zero (its inertia and damping "
                "average out), so each ball passes the mean contact force as the 2-DOF contact "
                "does; the bound of dynamics.mean-deflection.6308 (1.8e-5) holds, the ball "
                "inertia Z m_b/m = 1.3e-5 adding to the dynamic ripple's share"),
       Level::quick,
       1.0,
       {"contact-constant-x1.03", "contact-exponent+0.05"},
       [](const Context& ctx) { return mean_deflection_of(ctx, ModelKind::balls); }},
      {"dynamics.waviness-line.outer.6308",
       "dynamics",
       ReferenceKind::closed_form,
       "value: frequency of the strongest line of y near 2 BPFO with an outer waviness of order "
       "2Z+1 = 17 (1 um); reference: 2 BPFO of the preset geometry (outer waviness drives only "
       "BPFO multiples, q BPFO for N = qZ +- 1)",
       "2xBPFO line",
       "Hz",
       absolute(0.025, line_why),
       Level::quick,
       0.3,
       {"pitch-diameter-x1.01"},
       [](const Context& ctx) { return waviness_line(ctx, false); }},
      {"dynamics.waviness-line.inner.6308",
       "dynamics",
       ReferenceKind::closed_form,
       "value: frequency of the strongest line of y near BPFI + f_r with an inner waviness of "
       "order Z+1 = 9 (1 um); reference: BPFI + f_r = Z (f_r - f_c) + f_r of the preset geometry",
       "BPFI+fr line",
       "Hz",
       absolute(0.025, line_why),
       Level::quick,
       0.3,
       {"pitch-diameter-x1.01"},
       [](const Context& ctx) { return waviness_line(ctx, true); }},
      {"dynamics.cage-slip-line.6308",
       "dynamics",
       ReferenceKind::closed_form,
       "value: frequency of the strongest line of y near (1 - s_c) BPFO, ball-DOF model with "
       "cage slip s_c = 0.05, perfect 6308, 20 N, 2000 rpm; reference: (1 - s_c) BPFO of the "
       "preset geometry (seed 004 eq. 26)",
       "(1-s)BPFO line",
       "Hz",
       absolute(0.025, line_why),
       Level::quick,
       1.0,
       {"cage-speed-1pct-slow", "pitch-diameter-x1.01"},
       cage_slip_line},
      {"dynamics.reduction.3dof-to-2dof.6308",
       "dynamics",
       ReferenceKind::limit,
       "value: max |y_3DOF - y_2DOF| / peak-to-peak of y_2DOF over 0.1 s, 6308 at 2000 rpm with "
       "inner waviness of order 9, no axial load (the 3-DOF model centred, alpha = 0); "
       "reference: 0 (three_dof.h reduction (b): exactly the 2-DOF model, run unperturbed); "
       "the models share the contact law and kinematics, so the 3-DOF model is also anchored "
       "to the closed form by dynamics.mean-deflection.3dof.6308",
       "difference",
       "-",
       absolute(1e-8,
                "reduction (b) is exact: the models differ by the rounding of L_j - A_0 "
                "(eps A_0 / delta = 1e-13 of the approach) and of the axial offset"),
       Level::quick,
       0.5,
       {"mass-x1.05", "damping-x2", "contact-constant-x1.03"},
       reduction_3dof},
      {"dynamics.reduction.balls-to-2dof.6308",
       "dynamics",
       ReferenceKind::limit,
       "value: max |y_balls - y_2DOF| / peak-to-peak of y_2DOF over 0.1 s, ball-DOF model with "
       "1 mg balls (c_b 0.2 N s/m), no friction, no slip, no centrifugal load, outer waviness "
       "order 9 (Newmark "
       "5 us); reference: 0 (massless frictionless balls are the 2-DOF contacts, run "
       "unperturbed); the models share the contact law and kinematics, so the ball-DOF model is "
       "also anchored to the closed form by dynamics.mean-deflection.balls.6308",
       "difference",
       "-",
       absolute(4e-3,
                "the ball damping c_b = 0.2 N s/m on at most Z balls in series with the ring adds "
                "at most Z c_b/2 = 0.8 N s/m to the ring's 200; a response changes by at most "
                "that fraction, 4e-3 (the resonant part goes as 1/c, the quasi-static part less); "
                "the ball inertia Z m_b/m = 1.3e-5"),
       Level::quick,
       1.0,
       {"cage-speed-1pct-slow", "mass-x1.05"},
       reduction_balls},
  };
  for (const std::string bearing : {"608", "6304", "6308", "6205", "209"})
    checks.push_back({"dynamics.bpfo-line." + bearing,
                      "dynamics",
                      ReferenceKind::closed_form,
                      "value: frequency of the strongest line of y near BPFO, perfect " + bearing +
                          ", 20 N, 2000 rpm "
                          "(2-DOF, varying compliance); reference: BPFO = Z f_r (1 - D cos "
                          "a/d_m)/2 of the preset "
                          "geometry",
                      "BPFO line",
                      "Hz",
                      absolute(0.025, line_why),
                      Level::quick,
                      0.3,
                      {"pitch-diameter-x1.01"},
                      [bearing](const Context& ctx) { return bpfo_line(ctx, bearing); }});
  return checks;
}

}  // namespace bearing::verify
