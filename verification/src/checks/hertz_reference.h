#pragma once
// The checks' own exact Hertz solution of a ball on a raceway, written from the geometry without
// any of the toolkit's contact code (docs/model.md §3; Hamrock's form of Hertz's equations, not the
// toolkit's δ* form, so the two share nothing but the physics). Used as the reference of the
// hertz, hertz-fe and static-load families.

#include "bearing/bearing.h"
#include "bearing/contact.h"  // Race only

namespace bearing::verify::reference {

struct HertzContact {
  double sum_rho = 0;  ///< Σρ [1/m]
  double f_rho = 0;    ///< F(ρ) [-]
  double kappa = 1;    ///< ellipticity a/b [-]
  double elliptic_K = 0;
  double elliptic_E = 0;
  double eta = 0;            ///< (1−ν_b²)/E_b + (1−ν_r²)/E_r [1/Pa]
  double ball_radius = 0;    ///< D/2 [m]
  double groove_radius = 0;  ///< f D [m]
  double K = 0;              ///< Q = K δ^{3/2} [N/m^1.5]

  double semi_major(double load) const;     ///< a [m]
  double semi_minor(double load) const;     ///< b [m]
  double approach(double load) const;       ///< δ [m]
  double peak_pressure(double load) const;  ///< p0 = 3Q/(2πab) [Pa]
  /// The load whose peak pressure is p0 [N].
  double load_at_peak_pressure(double p0) const;
};

/// Exact Hertz for one race of `b`: curvatures as in docs/model.md §3, κ by Brent root finding on
/// Hertz's F(κ) with GSL's complete elliptic integrals, relative tolerance 1e-14 on κ.
HertzContact exact_hertz(const Bearing& b, Race race);

/// Ball between both races, springs in series: (K_i^{−2/3} + K_o^{−2/3})^{−3/2} [N/m^1.5].
double series_constant(double k_inner, double k_outer);

}  // namespace bearing::verify::reference
