// Stiffness family (issue 32): the 5-DOF static solution's stiffness (five_dof_static.h) of every
// preset against closed forms written here — the zero-clearance radial stiffness of Stribeck's
// load distribution (Harris's K_r = 1.5 Z K J_r δ^{1/2}, J_r the load-distribution integral) and
// the axial stiffness of a preloaded deep-groove bearing (the derivative of Harris's
// F_z = Z K [A₀ (cos α₀ / cos α − 1)]^{3/2} sin α along the axial approach). The contact constant
// of the references is the checks' own exact Hertz solution (hertz_reference.h). The whole
// matrix against central differences of the checks' own ring on balls, its definiteness and the
// 2-DOF/3-DOF reductions are in stiffness_matrix.cc; at speed and over a ball pass the unit-test
// rows judge (FiveDofStatic, BallPassStiffness in checks/unit_tests.cc).

#include <cmath>
#include <string>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "../context.h"
#include "../families.h"
#include "bearing/five_dof_static.h"
#include "bearing/presets.h"
#include "check_util.h"
#include "hertz_reference.h"

namespace bearing::verify {

namespace {

constexpr double kAxialLoad = 400.0;  // F_z of the axial checks [N]
constexpr int kPhases = 64;           // cage angles per pitch of the radial check's average

Check row(std::string id, std::string compares, std::string quantity, std::string unit,
          Tolerance tol, std::vector<std::string> catches) {
  Check c;
  c.id = std::move(id);
  c.family = "stiffness";
  c.reference = ReferenceKind::closed_form;
  c.compares = std::move(compares);
  c.quantity = std::move(quantity);
  c.unit = std::move(unit);
  c.tolerance = std::move(tol);
  c.catches = std::move(catches);
  return c;
}

// The checks' own series constant of one ball of `b` (exact Hertz of both races, in series).
double reference_K(const Bearing& b) {
  return reference::series_constant(reference::exact_hertz(b, Race::inner).K,
                                    reference::exact_hertz(b, Race::outer).K);
}

// Zero clearance, the ring pushed by δ toward −y: ball j at ψ_j carries K (δ |sin ψ_j|)^{3/2}
// where sin ψ_j < 0, along its radial line (α = 0: the turn of the line adds axial and tilt
// terms only), so k_yy = Σ 1.5 K δ^{1/2} |sin ψ_j|^{1/2} sin²ψ_j. Averaged over the cage angle
// this is (Z/2π) ∫ of one ball's term: k̄_yy = 1.5 Z K J_r δ^{1/2} with
// J_r = (1/2π) ∫_{−π/2}^{π/2} cos^{5/2}ψ dψ = Γ(7/4) / (2 √π Γ(9/4)) — Stribeck's
// F_r = Z K J_r δ^{3/2} differentiated (J_r(ε = 0.5) ≈ 0.2288). The average is taken over kPhases
// cage angles a pitch: the periodic trapezoidal rule, whose error is the aliased Fourier
// coefficients (at multiples of Z N) of one ball's term, whose two edges at the load zone's ends
// go as |x|^{5/2}: |ĝ(k)| ≈ 2 Γ(7/2)/(2π k^{7/2}) to leading order, so the relative error is
// ≤ 2 ζ(7/2) 2 Γ(7/2)/(2π J_r) (Z N)^{−7/2} ≈ 10.4 (Z N)^{−7/2} = 5.4e-9 for Z N = 7·64 (the
// fewest balls of the presets).
Check radial_zero_clearance(const std::string& name) {
  Check c = row("stiffness.radial-zero-clearance." + name,
                "value: the 5-DOF k_yy of the " + name +
                    " with zero clearance, the ring moved 10 um toward -y, averaged over 64 cage "
                    "angles a pitch; reference: 1.5 Z K J_r delta^(1/2), J_r = (1/2pi) int "
                    "cos^(5/2) = Gamma(7/4)/(2 sqrt(pi) Gamma(9/4)) (Stribeck's load "
                    "distribution), K the checks' exact Hertz constant",
                "k_yy", "N/m",
                relative(1e-8,
                         "the periodic trapezoidal rule over N = 64 cage angles a pitch: the "
                         "aliasing of the load zone's |x|^(5/2) edges, 10.4 (Z N)^(-7/2) to "
                         "leading order, 5.4e-9 for the fewest balls (Z = 7), rounded up"),
                {"contact-constant-x1.03", "contact-exponent+0.05", "pitch-diameter-x1.01"});
  c.measure = [name](const Context& ctx) {
    Bearing b = preset(name);
    b.clearance = 0;
    const Bearing seen = ctx.bearing(b);
    const FiveDofBearing f = five_dof_bearing(seen, ctx.contact(seen, HertzMethod::exact));
    const double delta = 10e-6;
    double mean = 0;
    for (int k = 0; k < kPhases; ++k) {
      FiveDofBearing at = f;
      at.phase = 2 * M_PI / f.balls * k / kPhases;
      Vector5 q = Vector5::Zero();
      q(1) = -delta;
      mean += five_dof_point(at, q).stiffness(1, 1) / kPhases;
    }
    const double Jr = std::tgamma(1.75) / (2 * std::sqrt(M_PI) * std::tgamma(2.25));
    const double ref = 1.5 * b.balls * reference_K(b) * Jr * std::sqrt(delta);
    return Outcome{mean, ref, fmt("Z = %.0f, J_r = %.6f", b.balls, Jr), {}};
  };
  return c;
}

// Harris's pure axial load: F_z(α) = Z K [A₀ (cos α₀ / cos α − 1)]^{3/2} sin α, α by Brent on it.
struct Axial {
  double Z, K, A0, cos0;
};
double harris_axial(double alpha, void* p) {
  const Axial& a = *static_cast<const Axial*>(p);
  const double d = a.A0 * (a.cos0 / std::cos(alpha) - 1);
  return a.Z * a.K * std::pow(std::max(d, 0.0), 1.5) * std::sin(alpha) - kAxialLoad;
}
double solve_alpha(const Axial& a) {
  gsl_function fn{&harris_axial, const_cast<Axial*>(&a)};
  gsl_root_fsolver* s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  gsl_root_fsolver_set(s, &fn, std::acos(a.cos0) + 1e-12, 1.5);
  double alpha = 0;
  for (int i = 0; i < 200; ++i) {
    gsl_root_fsolver_iterate(s);
    alpha = gsl_root_fsolver_root(s);
    if (gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s), 0,
                               1e-15) == GSL_SUCCESS)
      break;
  }
  gsl_root_fsolver_free(s);
  return alpha;
}

// Under a pure axial load every ball is at α; with the axial approach δz = L sin α,
// L = A₀ cos α₀ / cos α, dδ/dδz = sin α and d sin α/dδz = cos²α / L, so
// k_zz = Z (1.5 K δ^{1/2} sin²α + K δ^{3/2} cos²α / L).
Check axial_preload(const std::string& name) {
  Check c = row("stiffness.axial-preload." + name,
                "value: the 5-DOF k_zz of the " + name +
                    " under a pure axial load of 400 N (its clearance); reference: the "
                    "derivative along the axial approach of Harris's F_z = Z K [A0 (cos a0 / cos "
                    "a - 1)]^(3/2) sin a, a solved by Brent, K the checks' exact Hertz constant",
                "k_zz", "N/m",
                relative(1e-8,
                         "the 5-DOF balance to 1e-12 of the load and Brent's root to 1e-15 rad, "
                         "carried through k_zz's derivative (a condition number below 1e3)"),
                {"contact-constant-x1.03", "contact-exponent+0.05", "pitch-diameter-x1.01"});
  c.measure = [name](const Context& ctx) {
    const Bearing b = preset(name);
    const Bearing seen = ctx.bearing(b);
    const FiveDofBearing f = five_dof_bearing(seen, ctx.contact(seen, HertzMethod::exact));
    Vector5 F = Vector5::Zero();
    F(2) = kAxialLoad;
    const double kzz = solve_five_dof(f, F).at.stiffness(2, 2);
    Axial a;
    a.Z = b.balls;
    a.K = reference_K(b);
    a.A0 = (b.inner_conformity + b.outer_conformity - 1) * b.ball_diameter;
    a.cos0 = 1 - b.clearance / (2 * a.A0);
    const double alpha = solve_alpha(a);
    const double d = a.A0 * (a.cos0 / std::cos(alpha) - 1);
    const double L = a.A0 * a.cos0 / std::cos(alpha);
    const double ref = a.Z * (1.5 * a.K * std::sqrt(d) * std::pow(std::sin(alpha), 2) +
                              a.K * std::pow(d, 1.5) * std::pow(std::cos(alpha), 2) / L);
    return Outcome{kzz, ref, fmt("contact angle %.4f deg", alpha * 180 / M_PI), {}};
  };
  return c;
}

}  // namespace

std::vector<Check> stiffness_checks() {
  std::vector<Check> all;
  for (const std::string& name : preset_names()) all.push_back(radial_zero_clearance(name));
  for (const std::string& name : preset_names()) all.push_back(axial_preload(name));
  for (Check& c : stiffness_matrix_checks()) all.push_back(std::move(c));
  return all;
}

}  // namespace bearing::verify
