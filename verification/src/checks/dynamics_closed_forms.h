#pragma once
// The references of the dynamics checks, written here from the textbook formulas and never taken
// from the toolkit: Hertz's exact point contact (docs/model.md §3, the ellipticity by root finding
// on GSL's complete elliptic integrals), the series law of a ball between two races, TVDS's
// first-order raceway curvature change, pure-rolling kinematics (docs/model.md §2), the static
// equilibrium of the ring on its Hertz contacts (Newton on the convex contact potential), and the
// free vibration of a linear damped oscillator.

#include <array>
#include <cmath>
#include <vector>

#include <gsl/gsl_sf_ellint.h>

#include "bearing/bearing.h"

namespace bearing::verify::closed_form {

inline constexpr double kPi = 3.14159265358979323846;

/// Hertz's ellipticity function F(κ) = [(κ²+1)E − 2K]/[(κ²−1)E], e² = 1 − 1/κ².
inline double ellipticity_function(double kappa) {
  const double e = std::sqrt(1.0 - 1.0 / (kappa * kappa));
  const double K = gsl_sf_ellint_Kcomp(e, GSL_PREC_DOUBLE);
  const double E = gsl_sf_ellint_Ecomp(e, GSL_PREC_DOUBLE);
  return ((kappa * kappa + 1.0) * E - 2.0 * K) / ((kappa * kappa - 1.0) * E);
}

/// Q = K δ^{3/2} of one ball on one race whose rolling-direction curvature is changed by
/// `delta_rho1` [1/m] (TVDS; 0 for the perfect race) [N/m^1.5]. Exact Hertz: κ from F(ρ) by
/// bisection in log κ to machine precision, δ* = (2K/π)(π/(2κ²E))^{1/3},
/// K = 2^{5/2}/(3 η δ*^{3/2} Σρ^{1/2}).
inline double race_constant(const Bearing& b, bool inner, double delta_rho1 = 0.0) {
  const double D = b.ball_diameter;
  const double g = D * std::cos(b.contact_angle) / b.pitch_diameter;
  const double rho_ball = 2.0 / D;
  const double rho_race1 =
      (inner ? (2.0 / D) * g / (1.0 - g) : -(2.0 / D) * g / (1.0 + g)) + delta_rho1;
  const double rho_race2 = -1.0 / ((inner ? b.inner_conformity : b.outer_conformity) * D);
  const double sum = 2.0 * rho_ball + rho_race1 + rho_race2;
  const double f = (rho_race1 - rho_race2) / sum;
  double lo = std::log(1.0 + 1e-9), hi = std::log(1e3);
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    const double mid = 0.5 * (lo + hi);
    (ellipticity_function(std::exp(mid)) < f ? lo : hi) = mid;
  }
  const double kappa = std::exp(0.5 * (lo + hi));
  const double e = std::sqrt(1.0 - 1.0 / (kappa * kappa));
  const double Kc = gsl_sf_ellint_Kcomp(e, GSL_PREC_DOUBLE);
  const double Ec = gsl_sf_ellint_Ecomp(e, GSL_PREC_DOUBLE);
  const double delta_star = (2.0 * Kc / kPi) * std::cbrt(kPi / (2.0 * kappa * kappa * Ec));
  const double eta = (1.0 - b.ball.poisson * b.ball.poisson) / b.ball.young +
                     (1.0 - b.rings.poisson * b.rings.poisson) / b.rings.young;
  return std::pow(2.0, 2.5) / (3.0 * eta * std::pow(delta_star, 1.5) * std::sqrt(sum));
}

/// Springs in series, both Q = K δ^{3/2}: K = (K_i^{−2/3} + K_o^{−2/3})^{−3/2}.
inline double series(double k_inner, double k_outer) {
  return std::pow(std::pow(k_inner, -2.0 / 3.0) + std::pow(k_outer, -2.0 / 3.0), -1.5);
}

/// The ball's series constant, with TVDS curvature changes per race [N/m^1.5].
inline double ball_constant(const Bearing& b, double drho_inner = 0.0, double drho_outer = 0.0) {
  return series(race_constant(b, true, drho_inner), race_constant(b, false, drho_outer));
}

/// TVDS's first-order change of the rolling-direction curvature of a race carrying the harmonic
/// A sin(Nφ + ψ) at the contact angle φ: Δρ_II1 = A (N² − 1) sin(Nφ + ψ)/R², R the raceway
/// radius (d_m ∓ D)/2 (docs/model.md §3; crests make the inner race more convex, the outer race
/// less concave) [1/m].
inline double tvds_curvature_change(const Bearing& b, bool inner, int order, double amplitude,
                                    double phase, double phi) {
  const double R =
      0.5 * (inner ? b.pitch_diameter - b.ball_diameter : b.pitch_diameter + b.ball_diameter);
  return amplitude * (double(order) * order - 1.0) * std::sin(order * phi + phase) / (R * R);
}

/// Pure-rolling kinematics, outer ring fixed (docs/model.md §2) [Hz].
struct Kinematics {
  double shaft = 0, cage = 0, bpfo = 0, bpfi = 0;
};
inline Kinematics kinematics(const Bearing& b, double shaft_hz) {
  const double g = b.ball_diameter * std::cos(b.contact_angle) / b.pitch_diameter;
  Kinematics k;
  k.shaft = shaft_hz;
  k.cage = 0.5 * shaft_hz * (1.0 - g);
  k.bpfo = b.balls * k.cage;
  k.bpfi = b.balls * (shaft_hz - k.cage);
  return k;
}

/// A ring on Z Hertz contacts at fixed angles θ_j: δ_j = x cos θ_j + y sin θ_j − γ + e_j.
struct RingContacts {
  std::vector<double> theta;   ///< [rad]
  std::vector<double> K;       ///< per ball [N/m^1.5]
  std::vector<double> offset;  ///< e_j [m] (waviness, size errors)
  double gap = 0;              ///< γ [m]

  double approach(int j, double x, double y) const {
    return x * std::cos(theta[j]) + y * std::sin(theta[j]) - gap + offset[j];
  }
  /// Σ_j K_j [δ_j]_+^{5/2}/(5/2) [J].
  double potential(double x, double y) const {
    double u = 0;
    for (std::size_t j = 0; j < theta.size(); ++j) {
      const double d = approach(int(j), x, y);
      if (d > 0) u += K[j] * std::pow(d, 2.5) / 2.5;
    }
    return u;
  }
  /// The contact force on the ring (−∇U) and the stiffness ∇∇U at (x, y).
  void force(double x, double y, std::array<double, 2>& f, std::array<double, 3>& k) const {
    f = {0, 0};
    k = {0, 0, 0};
    for (std::size_t j = 0; j < theta.size(); ++j) {
      const double d = approach(int(j), x, y);
      if (d <= 0) continue;
      const double c = std::cos(theta[j]), s = std::sin(theta[j]);
      const double q = K[j] * std::pow(d, 1.5), kj = 1.5 * K[j] * std::sqrt(d);
      f[0] -= q * c;
      f[1] -= q * s;
      k[0] += kj * c * c;
      k[1] += kj * c * s;
      k[2] += kj * s * s;
    }
  }
  /// The equilibrium under the load (F_x, F_y): Newton on the convex potential U − F·q, halving
  /// the step until the potential falls, to |residual| ≤ 1e-13 |F| (a few ulp of the forces).
  std::array<double, 2> equilibrium(double fx, double fy, double x, double y) const {
    const double scale = std::hypot(fx, fy);
    const auto energy = [&](double a, double b) { return potential(a, b) - fx * a - fy * b; };
    for (int it = 0; it < 200; ++it) {
      std::array<double, 2> f;
      std::array<double, 3> k;
      force(x, y, f, k);
      const double rx = f[0] + fx, ry = f[1] + fy;
      if (std::hypot(rx, ry) <= 1e-13 * scale) break;
      const double det = k[0] * k[2] - k[1] * k[1];
      double dx = (k[2] * rx - k[1] * ry) / det, dy = (k[0] * ry - k[1] * rx) / det;
      if (!std::isfinite(dx) || !std::isfinite(dy)) {  // no contact yet: move along the load
        dx = 1e-6 * fx / scale;
        dy = 1e-6 * fy / scale;
      }
      const double e0 = energy(x, y);
      double t = 1.0;
      while (t > 1e-12 && energy(x + t * dx, y + t * dy) > e0) t *= 0.5;
      x += t * dx;
      y += t * dy;
    }
    return {x, y};
  }
};

/// Z balls at θ_j = φ₀ + 2πj/Z, all with the constant K, no offsets.
inline RingContacts ring_contacts(const Bearing& b, double K, double phase0 = 0.0) {
  RingContacts r;
  r.gap = 0.5 * b.clearance;
  for (int j = 0; j < b.balls; ++j) {
    r.theta.push_back(phase0 + 2.0 * kPi * j / b.balls);
    r.K.push_back(K);
    r.offset.push_back(0.0);
  }
  return r;
}

/// Free decay of m ü + c u̇ + k u = 0 from u(0) = u0, u̇(0) = 0 (underdamped).
inline double free_decay(double u0, double m, double c, double k, double t) {
  const double wn = std::sqrt(k / m), zeta = c / (2.0 * std::sqrt(k * m));
  const double wd = wn * std::sqrt(1.0 - zeta * zeta);
  return u0 * std::exp(-zeta * wn * t) * (std::cos(wd * t) + zeta * wn / wd * std::sin(wd * t));
}

}  // namespace bearing::verify::closed_form
