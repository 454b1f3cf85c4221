#include "hertz_reference.h"

#include <cmath>
#include <stdexcept>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_sf_ellint.h>

namespace bearing::verify::reference {

namespace {

struct Elliptic {
  double K, E;
};

// Complete elliptic integrals of the modulus e, e² = 1 − 1/κ² (κ = a/b ≥ 1).
Elliptic elliptic(double kappa) {
  const double e = std::sqrt(1.0 - 1.0 / (kappa * kappa));
  return {gsl_sf_ellint_Kcomp(e, GSL_PREC_DOUBLE), gsl_sf_ellint_Ecomp(e, GSL_PREC_DOUBLE)};
}

// Hertz's equation for the ellipticity: F(κ) = [(κ²+1)E − 2K] / [(κ²−1)E].
double hertz_f(double kappa) {
  const Elliptic el = elliptic(kappa);
  const double k2 = kappa * kappa;
  return ((k2 + 1.0) * el.E - 2.0 * el.K) / ((k2 - 1.0) * el.E);
}

double root_function(double log_kappa, void* target) {
  return hertz_f(std::exp(log_kappa)) - *static_cast<double*>(target);
}

// κ from F by Brent's method on ln κ ∈ [ln 1.001, ln 1000] (F from 0.0007 to 0.99999: every
// bearing groove; F is increasing in κ).
double ellipticity(double f_rho) {
  gsl_function fn{&root_function, &f_rho};
  gsl_root_fsolver* s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  gsl_root_fsolver_set(s, &fn, std::log(1.001), std::log(1000.0));
  double root = NAN;
  for (int i = 0; i < 200; ++i) {
    gsl_root_fsolver_iterate(s);
    const double lo = gsl_root_fsolver_x_lower(s), hi = gsl_root_fsolver_x_upper(s);
    if (gsl_root_test_interval(lo, hi, 1e-14, 0.0) == GSL_SUCCESS) {
      root = gsl_root_fsolver_root(s);
      break;
    }
  }
  gsl_root_fsolver_free(s);
  if (!std::isfinite(root)) throw std::runtime_error("reference Hertz: no ellipticity root");
  return std::exp(root);
}

// (3 Q η / (2 Σρ))^{1/3}·(2κ²E/π)^{1/3} etc. in Hamrock's form with R = 1/Σρ, E' = 2/η:
// a = (6κ²E Q R / (π E'))^{1/3}, b = (6E Q R / (π κ E'))^{1/3},
// δ = K [ (9 / (2 E R)) (Q / (π κ E'))² ]^{1/3}.
double hamrock_reduced_modulus(const HertzContact& h) {
  return 2.0 / h.eta;
}

}  // namespace

double HertzContact::semi_major(double load) const {
  const double R = 1.0 / sum_rho, Ep = hamrock_reduced_modulus(*this);
  return std::cbrt(6.0 * kappa * kappa * elliptic_E * load * R / (M_PI * Ep));
}

double HertzContact::semi_minor(double load) const {
  const double R = 1.0 / sum_rho, Ep = hamrock_reduced_modulus(*this);
  return std::cbrt(6.0 * elliptic_E * load * R / (M_PI * kappa * Ep));
}

double HertzContact::approach(double load) const {
  const double R = 1.0 / sum_rho, Ep = hamrock_reduced_modulus(*this);
  const double w = load / (M_PI * kappa * Ep);
  return elliptic_K * std::cbrt(9.0 / (2.0 * elliptic_E * R) * w * w);
}

double HertzContact::peak_pressure(double load) const {
  return 3.0 * load / (2.0 * M_PI * semi_major(load) * semi_minor(load));
}

double HertzContact::load_at_peak_pressure(double p0) const {
  // p0 ∝ Q^{1/3}: one evaluation at 1 N scales exactly.
  const double ratio = p0 / peak_pressure(1.0);
  return ratio * ratio * ratio;
}

HertzContact exact_hertz(const Bearing& b, Race race) {
  const double D = b.ball_diameter;
  const double g = D * std::cos(b.contact_angle) / b.pitch_diameter;
  const double f = race == Race::inner ? b.inner_conformity : b.outer_conformity;
  // Harris's convention: convex positive. Ball 2/D both ways; raceway along the rolling
  // direction (2/D)g/(1∓g) (inner convex, outer concave); groove −1/(fD).
  const double ball = 2.0 / D;
  const double race_1 = race == Race::inner ? ball * g / (1.0 - g) : -ball * g / (1.0 + g);
  const double race_2 = -1.0 / (f * D);
  HertzContact h;
  h.sum_rho = 2.0 * ball + race_1 + race_2;
  h.f_rho = std::abs((race_1 - race_2) / h.sum_rho);
  h.kappa = ellipticity(h.f_rho);
  const Elliptic el = elliptic(h.kappa);
  h.elliptic_K = el.K;
  h.elliptic_E = el.E;
  h.eta = (1.0 - b.ball.poisson * b.ball.poisson) / b.ball.young +
          (1.0 - b.rings.poisson * b.rings.poisson) / b.rings.young;
  h.ball_radius = 0.5 * D;
  h.groove_radius = f * D;
  // K = Q / δ^{3/2}, load-independent; evaluated at 1 N.
  h.K = 1.0 / std::pow(h.approach(1.0), 1.5);
  return h;
}

double series_constant(double k_inner, double k_outer) {
  return std::pow(std::pow(k_inner, -2.0 / 3.0) + std::pow(k_outer, -2.0 / 3.0), -1.5);
}

}  // namespace bearing::verify::reference
