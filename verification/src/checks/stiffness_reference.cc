// The checks' own ring on balls (stiffness_reference.h).

#include "stiffness_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace bearing::verify::reference {

namespace {

constexpr double kTwoPi = 6.283185307179586;

// Tilts times ρ_i, moments over it: every coordinate a length, every load a force.
Vector5 scales(const RingOnBalls& r) {
  Vector5 s;
  s << 1, 1, 1, 1 / r.inner_rho, 1 / r.inner_rho;
  return s;
}

// Ball j's line of centres in its radial plane, (radial, axial) [m], and its derivatives.
struct Line {
  double radial = 0, axial = 0;
  Vector5 d_radial = Vector5::Zero(), d_axial = Vector5::Zero();
};

// The inner groove centre moves by d + γ × (ρ_i e_r) (a small rotation γ = (γx, γy, 0)); the
// outer one stays. Their offset is formed as (ρ_i − ρ_o) e_r plus that motion, never as the
// difference of two points near d_m/2 (which would lose the micrometres to rounding).
Line line_of(const RingOnBalls& r, int j, const Vector5& q) {
  const double psi = r.phase + kTwoPi * j / r.balls;
  const Eigen::Vector3d er(std::cos(psi), std::sin(psi), 0), ez(0, 0, 1);
  const Eigen::Vector3d arm = r.inner_rho * er;
  const Eigen::Vector3d dP[5] = {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                                 Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX().cross(arm),
                                 Eigen::Vector3d::UnitY().cross(arm)};
  Eigen::Vector3d w = (r.inner_rho - r.outer_rho) * er;
  Line l;
  for (int k = 0; k < 5; ++k) {
    w += q(k) * dP[k];
    l.d_radial(k) = dP[k].dot(er);
    l.d_axial(k) = dP[k].dot(ez);
  }
  l.radial = w.dot(er);
  l.axial = w.dot(ez);
  return l;
}

double energy(const RingOnBalls& r, const Vector5& q, const Vector5& F) {
  double e = -F.dot(q);
  for (int j = 0; j < r.balls; ++j) {
    const double d = r.approach(j, q);
    if (d > 0) e += r.K * std::pow(d, 2.5) / 2.5;
  }
  return e;
}

}  // namespace

double RingOnBalls::approach(int j, const Vector5& q) const {
  const Line l = line_of(*this, j, q);
  return std::hypot(l.radial, l.axial) - A0;
}

Vector5 RingOnBalls::load(const Vector5& q) const {
  Vector5 F = Vector5::Zero();
  for (int j = 0; j < balls; ++j) {
    const Line l = line_of(*this, j, q);
    const double L = std::hypot(l.radial, l.axial), delta = L - A0;
    if (delta <= 0) continue;
    F += K * std::pow(delta, 1.5) * (l.radial * l.d_radial + l.axial * l.d_axial) / L;
  }
  return F;
}

Matrix5 RingOnBalls::stiffness(const Vector5& q, double h) const {
  Matrix5 k;
  for (int i = 0; i < 5; ++i) {
    Vector5 dq = Vector5::Zero();
    dq(i) = i < 3 ? h : h / inner_rho;
    k.col(i) = (load(q + dq) - load(q - dq)) / (2 * dq(i));
  }
  return k;
}

double RingOnBalls::nearest_kink(const Vector5& q) const {
  double m = std::numeric_limits<double>::infinity();
  for (int j = 0; j < balls; ++j) m = std::min(m, std::abs(approach(j, q)));
  return m;
}

Vector5 RingOnBalls::equilibrium(const Vector5& F, Vector5 q,
                                 const std::array<bool, 5>& held) const {
  const Vector5 S = scales(*this);
  Vector5 free;
  for (int i = 0; i < 5; ++i) free(i) = held[i] ? 0.0 : 1.0;
  const double size = S.cwiseProduct(F).cwiseProduct(free).norm();
  for (int it = 0; it < 100; ++it) {
    const Vector5 r = S.cwiseProduct(load(q) - F).cwiseProduct(free);
    if (r.norm() <= 1e-12 * size) return q;
    const double h = std::max(1e-4 * nearest_kink(q), 1e-12 * A0);  // a ball on its kink
    Matrix5 J = S.asDiagonal() * stiffness(q, h) * S.asDiagonal();
    J = free.asDiagonal() * J * free.asDiagonal();
    for (int i = 0; i < 5; ++i)
      if (held[i]) J(i, i) = 1;
    const Vector5 step = S.cwiseProduct(J.ldlt().solve(-r));
    // Halve the step until the energy or the residual falls: near the root the energy's changes
    // are below its rounding, and the residual then judges.
    const auto residual = [&](const Vector5& at) {
      return S.cwiseProduct(load(at) - F).cwiseProduct(free).norm();
    };
    const Vector5 Ff = F.cwiseProduct(free);
    const double e0 = energy(*this, q, Ff), r0 = r.norm();
    double t = 1;
    while (t > 1e-12 && energy(*this, q + t * step, Ff) > e0 && residual(q + t * step) >= r0)
      t *= 0.5;
    q += t * step;
  }
  throw std::runtime_error("the reference ring on balls found no equilibrium in 100 Newton steps");
}

RingOnBalls ring_on_balls(const Bearing& b, double K, double phase) {
  RingOnBalls r;
  r.balls = b.balls;
  r.K = K;
  r.A0 = (b.inner_conformity + b.outer_conformity - 1) * b.ball_diameter;
  const double dm = b.pitch_diameter, D = b.ball_diameter, Pd = b.clearance;
  r.inner_rho = dm / 2 - D / 2 - Pd / 4 + b.inner_conformity * D;
  r.outer_rho = dm / 2 + D / 2 + Pd / 4 - b.outer_conformity * D;
  r.phase = phase;
  return r;
}

}  // namespace bearing::verify::reference
