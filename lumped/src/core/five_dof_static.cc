// The 5-DOF static solution and stiffness (five_dof_static.h has the equations).

#include "bearing/five_dof_static.h"

#include <cmath>
#include <string>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/numerics/newton.h"
#include "bearing/units.h"

namespace bearing {

namespace {

// The solver's coordinates: the tilts times ℜ_i, so that every coordinate is a length [m] and
// every component of the gradient a force [N] (one tolerance for all).
Vector5 scales(const FiveDofBearing& b) {
  Vector5 s;
  s << 1, 1, 1, 1 / b.groove_radius, 1 / b.groove_radius;
  return s;
}

}  // namespace

FiveDofBearing five_dof_bearing(const Bearing& b, const ContactConstants& c, double phase) {
  FiveDofBearing f;
  f.balls = b.balls;
  f.K = c.K;
  f.exponent = c.exponent;
  f.A0 = (b.inner_conformity + b.outer_conformity - 1.0) * b.ball_diameter;
  f.clearance = b.clearance;
  if (!(f.A0 > 0 && 0.5 * b.clearance < f.A0))
    throw InputError("bearing.clearance = " + format_number(b.clearance) +
                     " m: the 5-DOF solution needs P_d < 2 A0 = " + format_number(2 * f.A0) +
                     " m (A0 = (f_i + f_o - 1) D), i.e. a free contact angle below 90 deg");
  f.groove_radius =
      0.5 * b.pitch_diameter + (b.inner_conformity - 0.5) * b.ball_diameter - 0.25 * b.clearance;
  f.phase = phase;
  return f;
}

FiveDofPoint five_dof_point(const FiveDofBearing& b, const Vector5& q) {
  FiveDofPoint p;
  const int Z = b.balls;
  const double half = 0.5 * b.clearance;
  const double u = b.A0 - half;                           // radial offset of the centres, centred
  const double w0 = std::sqrt(half * (2 * b.A0 - half));  // axial offset where a ball touches
  const double n = b.exponent, R = b.groove_radius;
  p.ball_angles.resize(Z);
  p.approaches.resize(Z);
  p.ball_loads.resize(Z);
  p.contact_angles.resize(Z);
  for (int j = 0; j < Z; ++j) {
    const double psi = b.phase + two_pi * j / Z, c = std::cos(psi), s = std::sin(psi);
    const double r = q(0) * c + q(1) * s;
    const double ax = q(2) + R * (q(3) * s - q(4) * c);
    const double L = std::hypot(u + r, ax);
    // δ = L − A₀ without the cancellation: L² − A₀² = (s − w₀)(s + w₀) + r (2u + r).
    const double delta = ((ax - w0) * (ax + w0) + r * (2 * u + r)) / (L + b.A0);
    const double ca = (u + r) / L, sa = ax / L;
    p.ball_angles[j] = psi;
    p.approaches[j] = delta;
    p.contact_angles[j] = std::atan2(ax, u + r);
    if (delta <= 0) continue;
    const double Q = b.K * std::pow(delta, n);
    p.ball_loads[j] = Q;
    p.energy += Q * delta / (n + 1);
    Vector5 g, h;  // Bᵀ e and Bᵀ t
    g << ca * c, ca * s, sa, sa * R * s, -sa * R * c;
    h << -sa * c, -sa * s, ca, ca * R * s, -ca * R * c;
    p.force += Q * g;
    // The lower triangle only, mirrored below: K is symmetric to the bit, as theory says.
    p.stiffness.selfadjointView<Eigen::Lower>().rankUpdate(g, n * Q / delta);
    p.stiffness.selfadjointView<Eigen::Lower>().rankUpdate(h, Q / L);
  }
  p.stiffness = p.stiffness.selfadjointView<Eigen::Lower>();
  return p;
}

FiveDofSolution solve_five_dof(const FiveDofBearing& b, const Vector5& load, const HeldDofs& held) {
  FiveDofSolution sol;
  const Vector5 S = scales(b);  // q = S q', F' = S F (moments over ℜ_i)
  Vector5 free;                 // 1 for a free DOF, 0 for a held one
  for (int i = 0; i < 5; ++i) free(i) = held[i] ? 0.0 : 1.0;
  const Vector5 Fs = S.cwiseProduct(load).cwiseProduct(free);
  const double Fn = Fs.norm();
  if (Fn == 0) {
    sol.at = five_dof_point(b, sol.displacement);
    return sol;
  }
  // The scale of the Hessian at the solution: Z balls at the deflection that carries |F|.
  const double n = b.exponent;
  const double delta = std::pow(Fn / (b.balls * b.K), 1 / n);
  numerics::LevenbergOptions o;
  o.tolerance = 1e-12 * Fn;
  o.stiffness = n * b.balls * b.K * std::pow(delta, n - 1);
  // A held DOF: no gradient and a unit row of the Hessian (times its scale), so no step moves it.
  const auto evaluate = [&](const Vector5& qs) {
    const FiveDofPoint p = five_dof_point(b, S.cwiseProduct(qs));
    numerics::PotentialPoint<5> pt;
    pt.value = p.energy - Fs.dot(qs);
    pt.gradient = (S.cwiseProduct(p.force) - Fs).cwiseProduct(free);
    pt.hessian =
        free.asDiagonal() * (S.asDiagonal() * p.stiffness * S.asDiagonal()) * free.asDiagonal();
    for (int i = 0; i < 5; ++i)
      if (held[i]) pt.hessian(i, i) = o.stiffness;
    return pt;
  };
  Vector5 qs = Vector5::Zero();
  numerics::PotentialPoint<5> at = evaluate(qs);
  sol.iterations = numerics::levenberg_minimize<5>(qs, at, evaluate, o);
  sol.displacement = S.cwiseProduct(qs);
  sol.at = five_dof_point(b, sol.displacement);
  sol.residual = at.gradient.norm() / Fn;
  if (!(sol.residual <= 1e-10))
    throw SolverError("5-DOF static solution: the load (" + format_number(load(0)) + ", " +
                      format_number(load(1)) + ", " + format_number(load(2)) + " N; " +
                      format_number(load(3)) + ", " + format_number(load(4)) +
                      " N m) is balanced only to " + format_number(sol.residual) +
                      " of its size after " + std::to_string(sol.iterations) + " iterations");
  return sol;
}

}  // namespace bearing
