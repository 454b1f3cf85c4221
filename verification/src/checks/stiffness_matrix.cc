// Stiffness family, the matrix (issue 32): the 5-DOF solution's whole tangent stiffness under a
// combined load, its definiteness, and its reductions to the 2-DOF and 3-DOF static solutions,
// each against the checks' own ring on balls (stiffness_reference.h: the groove centres as points,
// the stiffness by central differences, never an analytic Hessian) or the checks' 2-DOF closed
// form (dynamics_closed_forms.h). The contact constant of the references is the checks' exact
// Hertz solution (hertz_reference.h), so a wrong K, n or d_m in the toolkit shows.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

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

namespace cf = closed_form;

constexpr double kRadial = 500.0;    // F_r of these checks [N]
constexpr double kAxial = 500.0;     // F_z of the combined load [N]
constexpr double kPhase = 0.1;       // ball 0's angle: no ball on a symmetry line [rad]
constexpr double kMatrixTol = 1e-7;  // stiffness.matrix.*: the derived bound below must stay under
constexpr double kMaxCondition = 100;
// The reference's Newton starts 5 % beyond the toolkit's displacement: its energy is convex, so
// the root it finds does not depend on the start, and it must move to reach it.
constexpr double kStart = 1.05;  // stiffness.definite.*: its premise on max|K| / λ_min

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

double reference_K(const Bearing& b) {
  return reference::series_constant(reference::exact_hertz(b, Race::inner).K,
                                    reference::exact_hertz(b, Race::outer).K);
}

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
//    moves K_j ∝ δ^{1/2} by half of that over k.
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
  m.bound = b.balls * (h * h / (24 * m.kink * m.kink) + eps * r.A0 / (2 * h)) +
            0.5 * 2e-12 * S.cwiseProduct(F).norm() / (lmin * m.kink);
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

std::vector<Check> stiffness_matrix_checks() {
  std::vector<Check> all;
  for (const std::string& name : preset_names()) all.push_back(matrix(name));
  for (const std::string& name : preset_names()) all.push_back(definite(name));
  for (const std::string& name : preset_names()) all.push_back(reduction_2dof(name));
  for (const std::string& name : preset_names()) all.push_back(reduction_3dof(name));
  return all;
}

}  // namespace bearing::verify
