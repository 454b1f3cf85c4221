// Stiffness family (issue 32): the 5-DOF static solution's stiffness (five_dof_static.h) of every
// preset against closed forms written here — the zero-clearance radial stiffness of Stribeck's
// load distribution (Harris's K_r = 1.5 Z K J_r δ^{1/2}, J_r the load-distribution integral) and
// the axial stiffness of a preloaded deep-groove bearing (the derivative of Harris's
// F_z = Z K [A₀ (cos α₀ / cos α − 1)]^{3/2} sin α along the axial approach). The contact constant
// of the references is the checks' own exact Hertz solution (hertz_reference.h), so a wrong K, n
// or d_m in the toolkit shows. Then the whole matrix under a combined load against central
// differences of the checks' own ring on balls (stiffness_reference.h: the groove centres as
// points, never an analytic Hessian), its definiteness, and its reductions to the 2-DOF static
// solution (the checks' closed form, dynamics_closed_forms.h) and the 3-DOF one. At speed and
// over a ball pass the unit-test rows judge (FiveDofStatic, BallPassStiffness, unit_tests.cc).

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <Eigen/Eigenvalues>

#include "../context.h"
#include "../families.h"
#include "bearing/five_dof_static.h"
#include "bearing/presets.h"
#include "check_util.h"
#include "dynamics_closed_forms.h"
#include "hertz_reference.h"
#include "stiffness_reference.h"

namespace bearing::verify {

namespace {

constexpr double kAxialLoad = 400.0;  // F_z of the axial checks [N]
constexpr int kPhases = 64;           // cage angles per pitch of the radial check's average

Check row(std::string id, ReferenceKind kind, std::string compares, std::string quantity,
          std::string unit, Tolerance tol, std::vector<std::string> catches) {
  Check c;
  c.id = std::move(id);
  c.family = "stiffness";
  c.reference = kind;
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
  Check c = row("stiffness.radial-zero-clearance." + name, ReferenceKind::closed_form,
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
  Check c = row("stiffness.axial-preload." + name, ReferenceKind::closed_form,
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

// ---- the whole matrix, its definiteness, the reductions --------------------------------

namespace cf = closed_form;

constexpr double kRadial = 500.0;      // F_r of these checks [N]
constexpr double kAxial = 500.0;       // F_z of the combined load [N]
constexpr double kPhase = 0.1;         // ball 0's angle: no ball on a symmetry line [rad]
constexpr double kMatrixTol = 1e-7;    // stiffness.matrix.*: the derived bound must stay under it
constexpr double kMaxCondition = 100;  // the premise on max|K| / λ_min of definite, reductions
// The reference's Newton starts 5 % beyond the toolkit's displacement: its energy is convex, so
// the root it finds does not depend on the start, and it must move to reach it.
constexpr double kStart = 1.05;

// (Fx, Fy, Fz, Mx, My): a radial load off the axes, an axial one and moments that tilt the ring
// about as much as the radial load moves it (M = 0.3 F_r ρ_i).
Vector5 combined_load(const reference::RingOnBalls& r) {
  const double M = 0.3 * kRadial * r.inner_rho;
  Vector5 F;
  F << 0.3 * kRadial, -kRadial, kAxial, M, -0.5 * M;
  return F;
}

Vector5 scales(const reference::RingOnBalls& r) {
  Vector5 s;
  s << 1, 1, 1, 1 / r.inner_rho, 1 / r.inner_rho;
  return s;
}

// Both matrices at their own equilibria, in the coordinates where every entry is in N/m (tilts
// times ρ_i), and what bounds the reference's error.
struct MatrixPair {
  Matrix5 toolkit, reference;
  double bound = 0;  // derived bound on max|reference − exact| / max|exact|
  int loaded = 0;
  double kink = 0;  // nearest kink [m]
};

// The reference's error, relative to max|K|, is bounded by the sum of (each ball's error relative
// to its own stiffness ≤ max|K|, so Z times the per-ball bound):
//  - truncation of the central difference: Q = K δ^{3/2} has |Q'''/Q'| = 1/(4δ²), so each ball's
//    column is off by ≤ h²/(24 δ²) ≤ Z h²/(24 k²) with k the nearest kink (δ ≥ k on both sides);
//    ∂δ/∂q's own curvature is 1/L ≤ 1/(A0 − P_d/2), smaller by (k/A0)², left out;
//  - rounding: δ = L − A₀ is formed to ε A₀, so each difference quotient to ε A₀/(2h);
//  - the two equilibria, each balanced to 1e-12 |F|: they differ by ≤ 2e-12 |F|/λ_min, which
//    moves each ball's K_j ∝ δ^{1/2} by half of that over k.
// (A ball's K_j is positive semidefinite and K their sum, so max|K_j| ≤ max|K|.)
MatrixPair matrices(const Context& ctx, const Bearing& b) {
  const Bearing seen = ctx.bearing(b);
  const FiveDofBearing f = five_dof_bearing(seen, ctx.contact(seen, HertzMethod::exact), kPhase);
  const reference::RingOnBalls r = reference::ring_on_balls(b, reference_K(b), kPhase);
  const Vector5 F = combined_load(r);
  const FiveDofSolution s = solve_five_dof(f, F);
  const Vector5 q = r.equilibrium(F, kStart * s.displacement);
  MatrixPair m;
  m.kink = r.nearest_kink(q);
  const double h = 1e-4 * m.kink;
  const Vector5 S = scales(r);
  m.toolkit = S.asDiagonal() * s.at.stiffness * S.asDiagonal();
  m.reference = S.asDiagonal() * r.stiffness(q, h) * S.asDiagonal();
  for (double Q : s.at.ball_loads) m.loaded += Q > 0;
  const double lmin =
      Eigen::SelfAdjointEigenSolver<Matrix5>(0.5 * (m.reference + m.reference.transpose()))
          .eigenvalues()(0);
  const double eps = std::numeric_limits<double>::epsilon();
  m.bound = b.balls * (h * h / (24 * m.kink * m.kink) + eps * r.A0 / (2 * h) +
                       0.5 * 2e-12 * S.cwiseProduct(F).norm() / (lmin * m.kink));
  return m;
}

Check matrix(const std::string& name) {
  Check c = row(
      "stiffness.matrix." + name, ReferenceKind::closed_form,
      "value: max |K - K_ref| / max |K_ref| over the 25 entries of the " + name +
          "'s 5-DOF tangent stiffness at its equilibrium under (Fx, Fy, Fz, Mx, My) = (150 N, "
          "-500 N, 500 N, 0.3 F_r rho_i, -0.15 F_r rho_i), tilts times rho_i so every entry is "
          "in N/m; reference: the central differences of the checks' own ring on balls (the "
          "groove centres as points, Q = K delta^1.5 along their line, K the exact Hertz "
          "constant) at its own Newton equilibrium (from 1.05 times the toolkit's q), step 1e-4 of "
          "the nearest ball's |delta|",
      "max |dK| / max |K|", "-",
      absolute(kMatrixTol,
               "the reference's error: the central difference's truncation Z h^2/(24 k^2) (k "
               "the nearest |delta_j|, h = 1e-4 k: 4.2e-10 Z), the rounding of delta = L - A0, "
               "Z eps A0/(2h), and the two equilibria's balance 2e-12 |F| through K ~ delta^(1/2); "
               "their sum is computed in every run and must stay below 1e-7, else the check "
               "fails on its premise"),
      {"contact-constant-x1.03", "contact-exponent+0.05", "pitch-diameter-x1.01"});
  c.measure = [name](const Context& ctx) {
    const MatrixPair m = matrices(ctx, preset(name));
    if (!(m.bound <= kMatrixTol))
      throw std::runtime_error(
          fmt("the reference's error bound %.3g exceeds %.0e", m.bound, kMatrixTol));
    const double dev =
        (m.toolkit - m.reference).cwiseAbs().maxCoeff() / m.reference.cwiseAbs().maxCoeff();
    const double asym = (m.reference - m.reference.transpose()).cwiseAbs().maxCoeff() /
                        m.reference.cwiseAbs().maxCoeff();
    return Outcome{dev,
                   0.0,
                   fmt("%.0f balls loaded; nearest |delta| %.3g um; the reference's derived error "
                       "bound %.2g; its own asymmetry %.2g (K_ref is a difference of a "
                       "gradient: symmetric to that bound)",
                       m.loaded, m.kink * 1e6, m.bound, asym),
                   {}};
  };
  return c;
}

// Weyl: |λ_min(K) − λ_min(K_ref)| ≤ ‖K − K_ref‖₂ ≤ 5 max|K − K_ref| (the 5×5 Frobenius norm
// bounds the 2-norm). With stiffness.matrix's 1e-7 on each side that is ≤ 1e-6 max|K|, so
// ≤ 1e-6 κ of λ_min with κ = max|K_ref| / λ_min(K_ref) ≤ kMaxCondition, checked in the run.
Check definite(const std::string& name) {
  Check c = row("stiffness.definite." + name, ReferenceKind::closed_form,
                "value: the smallest eigenvalue of the " + name +
                    "'s 5-DOF stiffness (tilts times rho_i, N/m) under stiffness.matrix's "
                    "combined load, > 0: positive definite; reference: that of the checks' own "
                    "ring on balls (central differences, symmetrised)",
                "lambda_min", "N/m",
                relative(1e-6 * kMaxCondition,
                         "Weyl's inequality: |d lambda| <= 5 max |dK| <= 1e-6 max |K| when "
                         "both matrices are within stiffness.matrix's bound of the exact one, "
                         "over lambda_min: 1e-6 times max |K| / lambda_min <= 100 (checked in "
                         "the run)"),
                {"contact-constant-x1.03", "contact-exponent+0.05", "pitch-diameter-x1.01"});
  c.measure = [name](const Context& ctx) {
    const MatrixPair m = matrices(ctx, preset(name));
    const auto lowest = [](const Matrix5& K) {
      return Eigen::SelfAdjointEigenSolver<Matrix5>(0.5 * (K + K.transpose())).eigenvalues()(0);
    };
    const double ref = lowest(m.reference);
    const double kappa = m.reference.cwiseAbs().maxCoeff() / ref;
    if (!(kappa > 0 && kappa <= kMaxCondition))
      throw std::runtime_error(fmt("max |K_ref| / lambda_min = %.3g: outside the premise (0, %.0f]",
                                   kappa, kMaxCondition));
    return Outcome{lowest(m.toolkit),
                   ref,
                   fmt("%.0f balls loaded; max |K_ref| / lambda_min = %.1f", m.loaded, kappa),
                   {}};
  };
  return c;
}

// The reductions' premise: the stiffness's condition number at the equilibrium (κ ≤ 100).
void premise_condition(double kappa) {
  if (!(kappa >= 1 && kappa <= kMaxCondition))
    throw std::runtime_error(
        fmt("the stiffness's condition number %.3g: outside the premise "
            "[1, %.0f] of the tolerance",
            kappa, kMaxCondition));
}

// Both equilibria are balanced to ≤ 1e-12 |F| (the toolkit's) and 1e-13 |F| (the reference's), so
// they differ by ≤ 1.1e-12 |F| / λ_min; relative to |q| that is ≤ 1.1e-12 κ (|F| ≤ λ_max |q|
// for the convex, stiffening contact law), κ = λ_max / λ_min ≤ 1e2 for these loads: 1e-10,
// rounded up to 1e-9 for the rounding of q's own evaluation.
Check reduction_2dof(const std::string& name) {
  Check c = row("stiffness.reduction-2dof." + name, ReferenceKind::limit,
                "value: the " + name +
                    "'s 5-DOF displacement toward the load (every DOF free) under a radial load "
                    "of 500 N at -y, its clearance, ball 0 at 0.1 rad; reference: the 2-DOF "
                    "static equilibrium sum K (x cos psi + y sin psi - P_d/2)^1.5 (cos, sin) = F "
                    "of the checks' closed forms (Newton), K the exact Hertz constant",
                "y", "m",
                relative(1e-9,
                         "both equilibria balanced to 1e-12 |F|: they differ by <= 1.1e-12 "
                         "kappa |q|, kappa = lambda_max/lambda_min of the 2x2 stiffness, < 100 "
                         "here: 1.1e-10, rounded up"),
                {"contact-constant-x1.03", "contact-exponent+0.05", "pitch-diameter-x1.01"});
  c.measure = [name](const Context& ctx) {
    const Bearing b = preset(name), seen = ctx.bearing(b);
    const FiveDofBearing f = five_dof_bearing(seen, ctx.contact(seen, HertzMethod::exact), kPhase);
    Vector5 F = Vector5::Zero();
    F(1) = -kRadial;
    const FiveDofSolution s = solve_five_dof(f, F);
    const cf::RingContacts ring = cf::ring_contacts(b, reference_K(b), kPhase);
    const auto q = ring.equilibrium(0, -kRadial, 0, 0);
    std::array<double, 2> force;
    std::array<double, 3> k;
    ring.force(q[0], q[1], force, k);
    const Eigen::Matrix2d k2{{k[0], k[1]}, {k[1], k[2]}};
    const Eigen::Vector2d l = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(k2).eigenvalues();
    premise_condition(l(1) / l(0));
    const double off_plane = s.displacement.tail<3>().cwiseAbs().maxCoeff();
    return Outcome{s.displacement(1),
                   q[1],
                   fmt("x: 5-DOF %.6g um, 2-DOF %.6g um; the 5-DOF's largest z, gx, gy %.2g "
                       "(0 by symmetry)",
                       s.displacement(0) * 1e6, q[0] * 1e6, off_plane),
                   {}};
  };
  return c;
}

Check reduction_3dof(const std::string& name) {
  Check c = row("stiffness.reduction-3dof." + name, ReferenceKind::limit,
                "value: the " + name +
                    "'s 5-DOF axial displacement with both tilts held (the 3-DOF static state) "
                    "under (150 N, -500 N, 500 N); reference: the checks' own ring on balls "
                    "with the tilts held, solved by Newton on its central differences from 1.05 "
                    "times the toolkit's q",
                "z", "m",
                relative(1e-9,
                         "both equilibria balanced to 1e-12 |F|: they differ by <= 2e-12 "
                         "kappa |q|, kappa < 100 of the 3x3 stiffness here, rounded up"),
                {"contact-constant-x1.03", "contact-exponent+0.05", "pitch-diameter-x1.01"});
  c.measure = [name](const Context& ctx) {
    const Bearing b = preset(name), seen = ctx.bearing(b);
    const FiveDofBearing f = five_dof_bearing(seen, ctx.contact(seen, HertzMethod::exact), kPhase);
    const reference::RingOnBalls r = reference::ring_on_balls(b, reference_K(b), kPhase);
    Vector5 F = combined_load(r);
    F(3) = F(4) = 0;
    const HeldDofs tilts_held = {false, false, false, true, true};
    const FiveDofSolution s = solve_five_dof(f, F, tilts_held);
    const Vector5 q = r.equilibrium(F, kStart * s.displacement, tilts_held);
    const Eigen::Matrix3d k3 = r.stiffness(q, 1e-4 * r.nearest_kink(q)).topLeftCorner<3, 3>();
    const Eigen::Vector3d l =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(0.5 * (k3 + k3.transpose())).eigenvalues();
    premise_condition(l(2) / l(0));
    return Outcome{s.displacement(2),
                   q(2),
                   fmt("x, y: 5-DOF %.6g, %.6g um; reference %.6g, %.6g um",
                       s.displacement(0) * 1e6, s.displacement(1) * 1e6, q(0) * 1e6, q(1) * 1e6),
                   {}};
  };
  return c;
}

}  // namespace

std::vector<Check> stiffness_checks() {
  std::vector<Check> all;
  for (const std::string& name : preset_names()) all.push_back(radial_zero_clearance(name));
  for (const std::string& name : preset_names()) all.push_back(axial_preload(name));
  for (const std::string& name : preset_names()) all.push_back(matrix(name));
  for (const std::string& name : preset_names()) all.push_back(definite(name));
  for (const std::string& name : preset_names()) all.push_back(reduction_2dof(name));
  for (const std::string& name : preset_names()) all.push_back(reduction_3dof(name));
  return all;
}

}  // namespace bearing::verify
