// Static-load family: the rolling kinematics and the static load distribution of every preset
// against textbook closed forms written here — the defect frequencies (docs/model.md §2),
// Stribeck's Q_max·Z/F_r and the radial deflection at zero clearance (Harris, ISO 16281), and with
// clearance the load-zone extent ε and Sjövall's J_r(ε). The contact constant of the references is
// the checks' own exact Hertz solution (hertz_reference.h).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_roots.h>

#include "../context.h"
#include "../families.h"
#include "bearing/local_defect.h"
#include "bearing/presets.h"
#include "bearing/traction.h"
#include "check_util.h"
#include "hertz_reference.h"

namespace bearing::verify {

namespace {

constexpr double kRadialLoad = 500.0;  // F_r of every load-distribution check [N]
constexpr double kShaftRpm = 2000.0;   // inner-ring speed of the kinematics checks

Check row(std::string id, ReferenceKind kind, std::string compares, std::string quantity,
          std::string unit, Tolerance tol, std::vector<std::string> catches) {
  Check c;
  c.id = std::move(id);
  c.family = "static-load";
  c.reference = kind;
  c.compares = std::move(compares);
  c.quantity = std::move(quantity);
  c.unit = std::move(unit);
  c.tolerance = std::move(tol);
  c.catches = std::move(catches);
  return c;
}

// ---- kinematics --------------------------------------------------------------------------

// The textbook FTF, BPFO, BPFI, BSF [Hz] of `b` with the inner ring at fi and the outer at fo [Hz]:
// FTF = |f_i (1-g) + f_o (1+g)| / 2, BPFO = Z (f_i - f_o)(1-g)/2, BPFI = Z (f_i - f_o)(1+g)/2,
// BSF = d_m/(2D) (f_i - f_o)(1-g^2), g = D cos(a)/d_m.
std::array<double, 4> textbook_rates(const Bearing& b, double fi, double fo) {
  const double g = b.ball_diameter * std::cos(b.contact_angle) / b.pitch_diameter;
  return {std::abs(0.5 * fi * (1 - g) + 0.5 * fo * (1 + g)), 0.5 * b.balls * (fi - fo) * (1 - g),
          0.5 * b.balls * (fi - fo) * (1 + g),
          b.pitch_diameter / (2 * b.ball_diameter) * (fi - fo) * (1 - g * g)};
}

// Of the four rates, the one farthest (relatively) from its reference, as an Outcome.
Outcome farthest_rate(const BearingFrequencies& v, const std::array<double, 4>& ref,
                      const std::string& who) {
  const double val[4] = {v.ftf, v.bpfo, v.bpfi, v.bsf};
  const char* names[4] = {"FTF", "BPFO", "BPFI", "BSF"};
  int worst = 0;
  for (int i = 1; i < 4; ++i)
    if (std::abs(val[i] / ref[i] - 1) > std::abs(val[worst] / ref[worst] - 1)) worst = i;
  return {val[worst], ref[worst], who + names[worst] + " is the farthest", {}};
}

// The four frequencies; the value is the one farthest from its textbook formula.
Check kinematics(const std::string& name) {
  Check c = row("static-load.kinematics." + name, ReferenceKind::closed_form,
                "value: the lumped FTF, BPFO, BPFI, BSF of the " + name +
                    " at 2000 rpm (the one farthest from its formula); reference: FTF = f/2 (1-g), "
                    "BPFO = Z FTF, BPFI = Z f/2 (1+g), BSF = d_m/(2D) f (1-g^2), g = D cos(a)/d_m",
                "frequency", "Hz",
                relative(1e-12, "the same arithmetic in a different order: round-off only"),
                {"pitch-diameter-x1.01"});
  c.measure = [name](const Context& ctx) {
    const double f = kShaftRpm / 60.0;
    const BearingFrequencies v = ctx.frequencies(ctx.bearing(name), 2.0 * M_PI * f);
    Outcome o = farthest_rate(v, textbook_rates(preset(name), f, 0.0), "");
    o.detail += fmt("; FTF %.4f, BPFO %.4f, BPFI %.4f, BSF %.4f Hz", v.ftf, v.bpfo, v.bpfi, v.bsf);
    return o;
  };
  return c;
}

// With the outer ring turning too (the library's bearing_frequencies(b, ω_i, ω_o)): the rates
// relative to each ring depend on f_i − f_o only. Catches a cage speed that mistreats ω_o (code
// mutant kinematics-eeb13c2a: ω_o / (1 + g) for ω_o (1 + g)), which no fixed-outer row can see.
Check kinematics_outer_ring() {
  Check c = row("static-load.kinematics-outer-ring", ReferenceKind::closed_form,
                "value: the lumped FTF, BPFO, BPFI, BSF of every preset with the inner ring at "
                "2000 rpm and the outer ring at -500 rpm (the one farthest from its formula); "
                "reference: FTF = |f_i (1-g) + f_o (1+g)| / 2, BPFO = Z (f_i - f_o)(1-g)/2, "
                "BPFI = Z (f_i - f_o)(1+g)/2, BSF = d_m/(2D) (f_i - f_o)(1-g^2)",
                "frequency", "Hz",
                relative(1e-12, "the same arithmetic in a different order: round-off only"),
                {"pitch-diameter-x1.01"});
  c.measure = [](const Context& ctx) {
    const double fi = kShaftRpm / 60.0, fo = -500.0 / 60.0;
    Outcome o;
    double worst = -1;
    for (const auto& name : preset_names()) {
      const BearingFrequencies v =
          bearing_frequencies(ctx.bearing(name), 2.0 * M_PI * fi, 2.0 * M_PI * fo);
      const Outcome w = farthest_rate(v, textbook_rates(preset(name), fi, fo), name + " ");
      if (std::abs(w.value / w.reference - 1) > worst) {
        worst = std::abs(w.value / w.reference - 1);
        o = w;
      }
    }
    return o;
  };
  return c;
}

// Pure rolling has no sliding: seed 004's sliding speeds (bearing/traction.h, the ball-DOF
// model's traction law) at the check's own pure-rolling cage speed and ball spin, and at the
// library's rolling_ball_spin, for contact angles 0 and 20 deg. No quick run reaches this code
// otherwise (code mutants traction-84c77b1b, traction-297e717e survived).
Check pure_rolling_sliding() {
  Check c = row("static-load.pure-rolling-sliding", ReferenceKind::closed_form,
                "value: the largest |sliding speed| (inner, outer contact) of every preset at "
                "2000 rpm, contact angle 0 and 20 deg, with the cage at w_i (1-g)/2 and the ball "
                "spin w_i d_m (1-g^2) / (2 D cos a) (the check's, then the library's "
                "rolling_ball_spin); reference: 0 (pure rolling)",
                "sliding speed", "m/s",
                absolute(1e-12,
                         "surface speeds ~6 m/s cancel: a few ulps (1e-15 m/s) of round-off, "
                         "with a wide margin"),
                {"pitch-diameter-x1.01"});
  c.measure = [](const Context& ctx) {
    const double wi = 2.0 * M_PI * kShaftRpm / 60.0;
    Outcome o{0, 0, "", {}};
    for (const auto& name : preset_names())
      for (double alpha : {0.0, 20.0 * M_PI / 180.0}) {
        Bearing b = ctx.bearing(name), ref = preset(name);
        b.contact_angle = ref.contact_angle = alpha;
        const double g = ref.ball_diameter * std::cos(alpha) / ref.pitch_diameter;
        const double cage = 0.5 * wi * (1 - g);
        const double spin =
            wi * ref.pitch_diameter * (1 - g * g) / (2 * ref.ball_diameter * std::cos(alpha));
        for (double w_b : {spin, rolling_ball_spin(b, wi)}) {
          const SlidingSpeeds v = sliding_speeds(b, wi, cage, w_b);
          for (double x : {v.inner, v.outer})
            if (std::abs(x) > std::abs(o.value)) {
              o.value = x;
              o.detail = name + fmt(" at %.0f deg is the farthest", alpha * 180 / M_PI);
            }
        }
      }
    return o;
  };
  return c;
}

// The ball's spin relative to the cage (local_defect.h, what a ball defect turns at) under a
// contact angle: every other run has α = 0, where cos α is 1 (code mutant local_defect-37e43c8e,
// D / cos α for D cos α, survived).
Check ball_spin_angular() {
  Check c = row("static-load.ball-spin-angular", ReferenceKind::closed_form,
                "value: the ball spin relative to the cage (ball_spin_speed) of every preset at "
                "contact angle 20 deg, cage at w_i (1-g)/2, 2000 rpm (the one farthest from its "
                "formula); reference: 2 pi BSF = w_i d_m/(2D) (1-g^2), g = D cos a / d_m",
                "ball spin", "rad/s",
                relative(1e-12, "the same arithmetic in a different order: round-off only"),
                {"pitch-diameter-x1.01"});
  c.measure = [](const Context& ctx) {
    const double wi = 2.0 * M_PI * kShaftRpm / 60.0, alpha = 20.0 * M_PI / 180.0;
    Outcome o{0, 1, "", {}};
    double worst = -1;
    for (const auto& name : preset_names()) {
      const Bearing ref = preset(name);
      const double g = ref.ball_diameter * std::cos(alpha) / ref.pitch_diameter;
      const double v = ball_spin_speed(ctx.bearing(name), 0.5 * wi * (1 - g), alpha);
      const double r = wi * ref.pitch_diameter / (2 * ref.ball_diameter) * (1 - g * g);
      if (std::abs(v / r - 1) > worst) {
        worst = std::abs(v / r - 1);
        o = {v, r, name + " is the farthest", {}};
      }
    }
    return o;
  };
  return c;
}

// ---- zero clearance ------------------------------------------------------------------------

// Σ_j [cos ψ_j]_+^{n+1} over the balls at ψ_j = 2πj/Z + phase (the load along ψ = 0): at zero
// clearance δ_j = δ_r cos ψ_j, so F_r = Q_max Σ cos^{n+1} ψ_j exactly (finite Z).
double cos_sum(int z, double phase, double n) {
  double s = 0;
  for (int j = 0; j < z; ++j) {
    const double c = std::cos(2.0 * M_PI * j / z + phase);
    if (c > 0) s += std::pow(c, n + 1.0);
  }
  return s;
}

// Sjövall's J_r(ε) = (1/2π) ∫_{−ψ_l}^{ψ_l} [1 − (1 − cos ψ)/(2ε)]^n cos ψ dψ by GSL QAGS
// (ε ≤ 0.5, ψ_l = arccos(1 − 2ε)); the Z → ∞ limit of F_r / (Z Q_max).
struct SjovallParams {
  double eps, n;
};
double sjovall_integrand(double psi, void* p) {
  const auto* s = static_cast<SjovallParams*>(p);
  const double q = 1.0 - (1.0 - std::cos(psi)) / (2.0 * s->eps);
  return q > 0 ? std::pow(q, s->n) * std::cos(psi) : 0.0;
}
double sjovall_jr(double eps, double n) {
  SjovallParams p{eps, n};
  gsl_function fn{&sjovall_integrand, &p};
  const double psi_l = std::acos(std::max(-1.0, 1.0 - 2.0 * eps));
  gsl_integration_workspace* w = gsl_integration_workspace_alloc(200);
  double result = 0, err = 0;
  gsl_integration_qags(&fn, 0.0, psi_l, 1e-13, 1e-12, 200, w, &result, &err);
  gsl_integration_workspace_free(w);
  return 2.0 * result / (2.0 * M_PI);
}

Check stribeck(const std::string& name) {
  Check c = row(
      "static-load.stribeck." + name, ReferenceKind::closed_form,
      "value: min(Q_1, Q_2) Z / F_r (balls 1 and 2 carry Q_max) of the lumped static solution "
      "of the " +
          name +
          " at zero clearance (F_r = 500 N toward ball 0; the ratio depends on Z only: 608 and "
          "6304 have Z = 7, 6308 Z = 8, 6205 and 209 Z = 9); reference: Z / sum_j cos^2.5(psi_j) "
          "over the loaded balls, the exact finite-Z form of Stribeck's constant (4.37 = "
          "1/J_r(0.5) is its Z -> infinity limit)",
      "Q_max Z / F_r", "-",
      relative(1e-9,
               "the toolkit's Newton stops at a force residual of 1e-12 relative; the reference "
               "is a finite sum"),
      {"contact-exponent+0.05"});
  c.measure = [name](const Context& ctx) {
    const Bearing b = ctx.bearing(name);
    const int z = b.balls;
    const StaticLoadResult s =
        ctx.static_load(z, ctx.contact(b, HertzMethod::exact), 0.0, {kRadialLoad, 0.0}, 0.0);
    const double ref = z / cos_sum(z, 0.0, 1.5);
    const double limit = 1.0 / sjovall_jr(0.5, 1.5);
    Outcome o{s.q_max * z / kRadialLoad,
              ref,
              fmt("Z = %.0f: finite-Z %.4f, large-Z limit 1/J_r(0.5) = %.4f (%+.2f %%); "
                  "Stribeck's design value 5",
                  z, ref, limit, 100 * (ref / limit - 1)),
              {}};
    if (name == "6308") {
      Figure f;
      f.name = "static-load-stribeck-vs-z";
      f.title = "Zero clearance: Q_max Z / F_r against the number of balls";
      f.x_label = "number of balls Z [-]";
      f.y_label = "Q_max Z / F_r [-]";
      Series on{"ball under the load (closed form)", {}, {}, "line+marker"};
      Series between{"load between two balls (closed form)", {}, {}, "line+marker"};
      Series lim{"large-Z limit 1/J_r(0.5) = 4.37", {}, {}, "line"};
      for (int k = 4; k <= 24; ++k) {
        on.x.push_back(k);
        on.y.push_back(k / cos_sum(k, 0.0, 1.5));
        between.x.push_back(k);
        // The most loaded balls sit π/k off the load: Q_max = F cos^{3/2}(π/k) / Σ cos^{5/2}.
        between.y.push_back(k * std::pow(std::cos(M_PI / k), 1.5) / cos_sum(k, M_PI / k, 1.5));
        lim.x.push_back(k);
        lim.y.push_back(limit);
      }
      Series lumped{"lumped, ball under the load", {}, {}, "marker"};
      for (const auto& p : preset_names()) {
        const Bearing pb = ctx.bearing(p);
        const StaticLoadResult r = ctx.static_load(pb.balls, ctx.contact(pb, HertzMethod::exact),
                                                   0.0, {kRadialLoad, 0.0}, 0.0);
        lumped.x.push_back(pb.balls);
        lumped.y.push_back(r.q_max * pb.balls / kRadialLoad);
      }
      f.series = {on, between, lim, lumped};
      o.figures.push_back(f);
    }
    return o;
  };
  return c;
}

// The load turned off the x axis, midway between balls 1 and 2 (φ = 3π/Z): by symmetry the
// deflection follows the load, balls 1 and 2 carry Q_max and
// Q_max Z / F_r = Z cos^{3/2}(π/Z) / Σ cos^{5/2}(ψ_j − φ). The other rows load along x only,
// where the solver's turn into the load's frame is idle: this row catches a frame turned the wrong
// way (sin Δ → −sin Δ loads the mirror-image pair with the same Q_max), which they pass.
Check stribeck_turned(const std::string& name) {
  Check c = row(
      "static-load.stribeck-turned." + name, ReferenceKind::closed_form,
      "value: min(Q_1, Q_2) Z / F_r (balls 1 and 2 carry Q_max) of the lumped static solution "
      "of the " +
          name +
          " at zero clearance with F_r = 500 N at 3 pi / Z from the x axis (midway between balls "
          "1 and 2); reference: Z cos^1.5(pi/Z) / sum_j cos^2.5(psi_j - 3 pi / Z) over the loaded "
          "balls (Q_j = Q_max (cos psi_j / cos(pi/Z))^1.5: the two most loaded balls sit pi/Z "
          "off the load)",
      "Q_1 Z / F_r", "-",
      relative(1e-9,
               "the toolkit's Newton stops at a force residual of 1e-12 relative; the reference "
               "is a finite sum"),
      {"contact-exponent+0.05"});
  c.measure = [name](const Context& ctx) {
    const Bearing b = ctx.bearing(name);
    const int z = b.balls;
    const double phi = 3.0 * M_PI / z;
    const StaticLoadResult s =
        ctx.static_load(z, ctx.contact(b, HertzMethod::exact), 0.0,
                        {kRadialLoad * std::cos(phi), kRadialLoad * std::sin(phi)}, 0.0);
    const double angle = std::atan2(s.deflection.y(), s.deflection.x());
    // The two most loaded balls sit π/Z off the load: Q_j = Q_max (cos ψ_j / cos(π/Z))^{3/2}.
    const double ref = z * std::pow(std::cos(M_PI / z), 1.5) / cos_sum(z, -phi, 1.5);
    // Balls 1 and 2 must be the most loaded, equally: the smaller of their loads, so that a
    // solver loading the mirror-image pair (the same Q_max) fails too.
    return Outcome{std::min(s.ball_loads[1], s.ball_loads[2]) * z / kRadialLoad,
                   ref,
                   fmt("deflection at %.6f rad, the load at %.6f rad", angle, phi),
                   {}};
  };
  return c;
}

// Reference series constant of the ball between both races (exact Hertz, the check's own).
double reference_series_k(const std::string& name) {
  const Bearing b = preset(name);
  return reference::series_constant(reference::exact_hertz(b, Race::inner).K,
                                    reference::exact_hertz(b, Race::outer).K);
}

Check deflection(const std::string& name) {
  Check c =
      row("static-load.deflection." + name, ReferenceKind::closed_form,
          "value: the radial deflection of the lumped static solution of the " + name +
              " at zero clearance, F_r = 500 N; reference: Harris / ISO 16281 delta_r = "
              "(Q_max / K)^(2/3) with Q_max = F_r / sum_j cos^2.5(psi_j) and K the check's exact "
              "series Hertz constant",
          "delta_r", "m",
          relative(1e-9,
                   "Newton's force residual 1e-12 and the reference Hertz root 1e-14, through "
                   "delta ~ F^(2/3): round-off"),
          {"contact-constant-x1.03", "contact-exponent+0.05", "pitch-diameter-x1.01"});
  c.measure = [name](const Context& ctx) {
    const Bearing b = ctx.bearing(name);
    const StaticLoadResult s =
        ctx.static_load(b.balls, ctx.contact(b, HertzMethod::exact), 0.0, {kRadialLoad, 0.0}, 0.0);
    const int z = preset(name).balls;
    const double k = reference_series_k(name);
    const double q_max = kRadialLoad / cos_sum(z, 0.0, 1.5);
    const double ref = std::pow(q_max / k, 2.0 / 3.0);
    const double stribeck5 = std::pow(5.0 * kRadialLoad / z / k, 2.0 / 3.0);
    Outcome o{s.deflection.x(),
              ref,
              fmt("Q_max = %.2f N (toolkit %.2f N); with Stribeck's Q_max = 5 F_r/Z: %.4g m "
                  "(%+.1f %%); y deflection %.1e m",
                  q_max, s.q_max, stribeck5, 100 * (stribeck5 / ref - 1), s.deflection.y()),
              {}};
    return o;
  };
  return c;
}

// ---- with clearance ------------------------------------------------------------------------

// Ball 0 under the load (ψ = 0): the ball set is symmetric about the load, so the ring moves
// along it, and the most loaded ball is Sjövall's Q_max at ψ = 0.
double load_phase(int /*z*/) {
  return 0.0;
}

struct Equilibrium {
  double k, gap, n;
  int z;
  double phase;
};

// Σ_j K [δ_r cos ψ_j − γ]_+^n cos ψ_j − F_r: the discrete equilibrium along the load.
double residual(double dr, void* p) {
  const auto* e = static_cast<Equilibrium*>(p);
  double f = 0;
  for (int j = 0; j < e->z; ++j) {
    const double c = std::cos(2.0 * M_PI * j / e->z + e->phase);
    const double d = dr * c - e->gap;
    if (d > 0) f += e->k * std::pow(d, e->n) * c;
  }
  return f - kRadialLoad;
}

// δ_r of the discrete equilibrium by Brent (bracket [γ, γ + (F_r/K)^{2/3}·10]).
double reference_deflection(Equilibrium e) {
  gsl_function fn{&residual, &e};
  gsl_root_fsolver* s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  gsl_root_fsolver_set(s, &fn, e.gap, e.gap + 10.0 * std::pow(kRadialLoad / e.k, 1.0 / e.n));
  double root = NAN;
  for (int i = 0; i < 300; ++i) {
    gsl_root_fsolver_iterate(s);
    const double lo = gsl_root_fsolver_x_lower(s), hi = gsl_root_fsolver_x_upper(s);
    if (gsl_root_test_interval(lo, hi, 0.0, 1e-15) == GSL_SUCCESS) {
      root = gsl_root_fsolver_root(s);
      break;
    }
  }
  gsl_root_fsolver_free(s);
  return root;
}

double epsilon_of(double dr, double gap) {
  return 0.5 * (1.0 - gap / dr);
}

Check load_zone(const std::string& name) {
  Check c = row(
      "static-load.load-zone." + name, ReferenceKind::closed_form,
      "value: the load-zone extent eps = (1 - gamma/delta_r)/2 of the lumped static solution of "
      "the " +
          name +
          " with its clearance, F_r = 500 N toward ball 0; reference: eps from the check's "
          "own root of F_r = K sum_j [delta_r cos psi_j - gamma]_+^1.5 cos psi_j (exact Hertz K)",
      "eps", "-",
      relative(1e-8,
               "Newton's force residual 1e-12, the reference root 1e-15 relative in delta_r, "
               "amplified by d(eps)/eps = (gamma/delta_r)/(1 - gamma/delta_r) d(delta_r)/delta_r "
               "(< 10 here)"),
      {"contact-constant-x1.03", "contact-exponent+0.05", "pitch-diameter-x1.01"});
  c.measure = [name](const Context& ctx) {
    const Bearing b = ctx.bearing(name);
    const int z = b.balls;
    const double gap = b.ball_gap();
    const StaticLoadResult s = ctx.static_load(z, ctx.contact(b, HertzMethod::exact), gap,
                                               {kRadialLoad, 0.0}, load_phase(z));
    const Bearing t = preset(name);
    const double dr = reference_deflection(
        {reference_series_k(name), t.ball_gap(), 1.5, t.balls, load_phase(t.balls)});
    const double eps = epsilon_of(s.deflection.x(), gap);
    Outcome o{eps,
              epsilon_of(dr, t.ball_gap()),
              fmt("delta_r = %.5g m (reference %.5g m), gamma = %.3g m; Sjovall J_r(eps) = "
                  "%.5f by quadrature (large Z), this Z: F_r/(Z Q_max) = %.5f",
                  s.deflection.x(), dr, gap, sjovall_jr(eps, 1.5), kRadialLoad / (z * s.q_max)),
              {}};
    return o;
  };
  return c;
}

// J = F_r / (Z Q_max) of the toolkit against the finite-Z Sjövall sum at the toolkit's own ε
// (so K cancels and the load law's shape [1 − (1 − cos ψ)/(2ε)]^n is what is checked).
Check sjovall(const std::string& name) {
  Check c = row(
      "static-load.sjovall-jr." + name, ReferenceKind::closed_form,
      "value: F_r / (Z Q_max) of the lumped static solution of the " + name +
          " with its clearance; reference: Sjovall's (1/Z) sum_j [1 - (1 - cos psi_j)/(2 "
          "eps)]_+^1.5 "
          "cos psi_j at the solution's eps (the finite-Z form of J_r(eps); the integral is shown "
          "beside it)",
      "J_r", "-", relative(1e-9, "force balance to 1e-12 relative; the reference is a finite sum"),
      {"contact-exponent+0.05"});
  c.measure = [name](const Context& ctx) {
    const Bearing b = ctx.bearing(name);
    const int z = b.balls;
    const double gap = b.ball_gap();
    const StaticLoadResult s = ctx.static_load(z, ctx.contact(b, HertzMethod::exact), gap,
                                               {kRadialLoad, 0.0}, load_phase(z));
    const double eps = epsilon_of(s.deflection.x(), gap);
    double sum = 0;
    for (int j = 0; j < z; ++j) {
      const double psi = 2.0 * M_PI * j / z + load_phase(z);
      const double q = 1.0 - (1.0 - std::cos(psi)) / (2.0 * eps);
      if (q > 0) sum += std::pow(q, 1.5) * std::cos(psi);
    }
    const double jr = sjovall_jr(eps, 1.5);
    Outcome o{kRadialLoad / (z * s.q_max),
              sum / z,
              fmt("eps = %.4f; Sjovall's integral J_r(eps) = %.5f (Z -> infinity), this Z differs "
                  "from it by %+.2f %%",
                  eps, jr, 100 * (sum / z / jr - 1)),
              {}};
    if (name == "6308") {
      Figure f;
      f.name = "static-load-sjovall-jr";
      f.title = "Sjovall's J_r(eps): integral (quadrature) and the lumped solution";
      f.x_label = "load-zone extent eps [-]";
      f.y_label = "J_r = F_r / (Z Q_max) [-]";
      Series integral{"J_r(eps), Sjovall integral (n = 1.5)", {}, {}, "line"};
      for (int i = 1; i <= 50; ++i) {
        integral.x.push_back(0.01 * i);
        integral.y.push_back(sjovall_jr(0.01 * i, 1.5));
      }
      Series lumped{"lumped 6308 (Z = 8), F_r = 100 N ... 20 kN", {}, {}, "marker"};
      const ContactConstants k = ctx.contact(b, HertzMethod::exact);
      for (double fr : {100.0, 300.0, 1000.0, 3000.0, 10000.0, 20000.0}) {
        const StaticLoadResult r = ctx.static_load(z, k, gap, {fr, 0.0}, load_phase(z));
        lumped.x.push_back(epsilon_of(r.deflection.x(), gap));
        lumped.y.push_back(fr / (z * r.q_max));
      }
      f.series = {integral, lumped};
      o.figures.push_back(f);
    }
    return o;
  };
  return c;
}

}  // namespace

std::vector<Check> static_load_checks() {
  std::vector<Check> all;
  for (const auto& name : preset_names()) all.push_back(kinematics(name));
  all.push_back(kinematics_outer_ring());
  all.push_back(pure_rolling_sliding());
  all.push_back(ball_spin_angular());
  for (const auto& name : {"608", "6308", "6205"}) all.push_back(stribeck(name));
  for (const auto& name : {"6308", "6205"}) all.push_back(stribeck_turned(name));
  for (const auto& name : preset_names()) all.push_back(deflection(name));
  for (const auto& name : preset_names()) all.push_back(load_zone(name));
  for (const auto& name : {"6304", "6308", "209"}) all.push_back(sjovall(name));
  return all;
}

}  // namespace bearing::verify
