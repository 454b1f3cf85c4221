#include "acoustics_reference.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <cmath>
#include <memory>

#include "bearing/constants.h"
#include "bearing/errors.h"

namespace bearing::verify::acoustic_reference {

namespace {

constexpr cd kI{0.0, 1.0};
constexpr std::size_t kIntervals = 4000;  // enough for x sin τ to oscillate 1000 times

struct Integrand {
  int n;
  double x;
};

using Workspace =
    std::unique_ptr<gsl_integration_workspace, decltype(&gsl_integration_workspace_free)>;

// The integrands of [0, π] are bounded by 2 and cancel down to |J_n|, |Y_n| ≥ ~0.03 at x ≤ 10³:
// an absolute tolerance; Schläfli's tail is positive (n = 0) or a difference of two decaying
// exponentials: a relative one.
double integrate(double (*f)(double, void*), Integrand& p, bool tail) {
  Workspace w(gsl_integration_workspace_alloc(kIntervals), &gsl_integration_workspace_free);
  gsl_function F{f, &p};
  double result = 0, error = 0;
  const int status = tail ? gsl_integration_qagiu(&F, 0.0, 0.0, kQuadratureTolerance, kIntervals,
                                                  w.get(), &result, &error)
                          : gsl_integration_qag(&F, 0.0, pi, kQuadratureTolerance, 0.0, kIntervals,
                                                GSL_INTEG_GAUSS61, w.get(), &result, &error);
  if (status != GSL_SUCCESS)
    throw SolverError(std::string("Hankel quadrature: ") + gsl_strerror(status));
  return result;
}

double bessel_j_integrand(double t, void* p) {
  const auto& q = *static_cast<Integrand*>(p);
  return std::cos(q.n * t - q.x * std::sin(t));
}
double bessel_y_integrand(double t, void* p) {
  const auto& q = *static_cast<Integrand*>(p);
  return std::sin(q.x * std::sin(t) - q.n * t);
}
// Schläfli's tail; e^{nt − x sinh t} written as one exponent so it never overflows.
double schlaefli_integrand(double t, void* p) {
  const auto& q = *static_cast<Integrand*>(p);
  const double s = q.x * std::sinh(t);
  return std::exp(q.n * t - s) + (q.n % 2 == 0 ? 1.0 : -1.0) * std::exp(-q.n * t - s);
}

}  // namespace

cd hankel(int n, double x) {
  Integrand p{n, x};
  const double j = integrate(&bessel_j_integrand, p, false) / pi;
  const double y =
      (integrate(&bessel_y_integrand, p, false) - integrate(&schlaefli_integrand, p, true)) / pi;
  return {j, -y};
}

cd hankel_derivative(int n, double x) {
  return n == 0 ? -hankel(1, x) : 0.5 * (hankel(n - 1, x) - hankel(n + 1, x));
}

cd spherical_hankel(int n, double x) {
  const cd e = std::polar(1.0, -x);
  return n == 0 ? kI * e / x : e * (kI - x) / (x * x);
}

cd spherical_hankel_derivative(int n, double x) {
  const cd e = std::polar(1.0, -x);
  return n == 0 ? e * (1.0 / x - kI / (x * x))
                : e * (kI / x + 2.0 / (x * x) - 2.0 * kI / (x * x * x));
}

cd cylinder_field(int order, double ka, double kr, double cos_angle) {
  const double pattern = order == 0 ? 1.0 : cos_angle;
  return -kI * kImpedance * pattern * hankel(order, kr) / hankel_derivative(order, ka);
}

cd sphere_field(int order, double ka, double kr, double cos_angle) {
  const double pattern = order == 0 ? 1.0 : cos_angle;
  return -kI * kImpedance * pattern * spherical_hankel(order, kr) /
         spherical_hankel_derivative(order, ka);
}

cd cylinder_dipole_low_ka(double ka, double kr, double cos_angle) {
  return 0.5 * pi * kImpedance * ka * ka * cos_angle * hankel(1, kr);
}

cd sphere_dipole_low_ka(double ka, double kr, double r_over_a, double cos_angle) {
  return -0.5 * kImpedance * ka * ka / r_over_a * cos_angle * (1.0 - kI / kr) *
         std::polar(1.0, -kr);
}

cd paper_cylinder_dipole(double ka, double kr, double cos_angle) {
  const cd h = kr / 2 + 2.0 * kI / (pi * kr);
  const cd dh = 0.5 - 2.0 * kI / (pi * ka * ka);
  return -kI * kImpedance * cos_angle * h / dh;
}

cd paper_pulsating_sphere(double ka, double r_over_a) {
  const double theta = std::atan(1.0 / ka);
  return kImpedance * ka / (r_over_a * std::sqrt(1 + ka * ka)) * std::polar(1.0, theta);
}

double small_argument_bound(double x) {
  return 0.5 * x * x * (std::abs(std::log(x / 2)) + 1.0);
}

double leading_order_bound(double x) {
  return 0.5 * x * x * (std::abs(std::log(x / 2)) + 2.0);
}

}  // namespace bearing::verify::acoustic_reference
