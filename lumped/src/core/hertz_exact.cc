// Exact Hertz point-contact solution: the ellipticity κ = a/b from F(ρ) by bracketed root finding,
// the complete elliptic integrals K(e), E(e) from GSL. Also the shape formulas shared by every
// method and the factory that selects a method by its case-file name.

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <string_view>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_sf_ellint.h>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/hertz.h"
#include "bearing/numerics/roots.h"
#include "hertz_internal.h"

namespace bearing {

namespace detail {

void require_curvature_difference(double f_rho, std::string_view method) {
  if (std::isfinite(f_rho) && f_rho >= 0.0 && f_rho < 1.0) return;
  std::ostringstream s;
  s.precision(17);
  s << "curvature difference F(rho) = " << f_rho << " given to the " << method
    << " Hertz solution: it must be a finite number in [0, 1) (F = 0 for a sphere on a plane or "
       "sphere, F -> 1 for an infinitely long contact ellipse)";
  throw InputError(s.str());
}

}  // namespace detail

HertzShape hertz_shape_from(double ellipticity, double elliptic_K, double elliptic_E) {
  if (!(std::isfinite(ellipticity) && ellipticity >= 1.0 && std::isfinite(elliptic_K) &&
        elliptic_K > 0.0 && std::isfinite(elliptic_E) && elliptic_E > 0.0)) {
    std::ostringstream s;
    s << "hertz_shape_from: ellipticity " << ellipticity << ", K(e) " << elliptic_K << ", E(e) "
      << elliptic_E << ": need a finite ellipticity >= 1 and positive, finite K and E";
    throw InputError(s.str());
  }
  HertzShape h;
  h.ellipticity = ellipticity;
  h.elliptic_K = elliptic_K;
  h.elliptic_E = elliptic_E;
  const double k2E = ellipticity * ellipticity * elliptic_E;
  h.delta_star = (2.0 * elliptic_K / pi) * std::cbrt(pi / (2.0 * k2E));
  h.a_star = std::cbrt(2.0 * k2E / pi);
  h.b_star = std::cbrt(2.0 * elliptic_E / (pi * ellipticity));
  return h;
}

namespace {

// Complete elliptic integrals in Carlson's symmetric form with the complementary parameter
// e'² = 1 − e² = 1/κ² passed directly:
//     K = R_F(0, 1/κ², 1),   K − E = (e²/3) R_D(0, 1/κ², 1)          (DLMF 19.25.1).
// This is the same GSL code path gsl_sf_ellint_Kcomp/Ecomp use, but it avoids forming
// e = sqrt(1 − 1/κ²) and then 1 − e² again (which loses 1/κ² in rounding for large κ), and it
// gives K − E without cancellation as κ → 1. The unit tests compare with Kcomp/Ecomp(e).
struct EllipticPair {
  double K;
  double E;
  double rd;  // R_D(0, 1/κ², 1)
};

EllipticPair elliptic_integrals(double kappa) {
  const double y = 1.0 / (kappa * kappa);
  const double e2 = (kappa - 1.0) * (kappa + 1.0) * y;  // 1 − 1/κ², accurate near κ = 1
  const double K = gsl_sf_ellint_RF(0.0, y, 1.0, GSL_PREC_DOUBLE);
  const double rd = gsl_sf_ellint_RD(0.0, y, 1.0, GSL_PREC_DOUBLE);
  return {K, K - e2 * rd / 3.0, rd};
}

// 1 − F(κ). From F = [(κ²+1)E − 2K]/[(κ²−1)E] we get 1 − F = 2(K − E)/[(κ²−1)E], and with the
// Carlson form of K − E and κ² − 1 = e²κ² this is 2 R_D(0, 1/κ², 1) / (3κ² E): no cancellation at
// either end (1 − F → 1 as κ → 1, → 2(ln 4κ − 1)/κ² as κ → ∞).
double one_minus_f(double kappa) {
  const EllipticPair p = elliptic_integrals(kappa);
  return 2.0 * p.rd / (3.0 * kappa * kappa * p.E);
}

// Root function in u = ln κ: ln(1 − F(e^u)) − ln(1 − F_target). Decreasing in u, with slope
// between −3/4 (κ = 1) and −2 (κ → ∞), so a fixed absolute tolerance on u is a uniform relative
// tolerance on κ over the whole range.
struct RootData {
  double log_target;  // ln(1 − F_target)
};

double root_function(double u, void* params) {
  const auto* d = static_cast<const RootData*>(params);
  return std::log(one_minus_f(std::exp(u))) - d->log_target;
}

double solve_ellipticity(double f_rho) {
  RootData data{std::log1p(-f_rho)};
  gsl_function fn{&root_function, &data};

  // Bracket: φ(0) = −ln(1 − F) > 0; double u until φ < 0. For the largest F < 1 in double
  // precision κ ≈ 6e8 (u ≈ 20), so the cap of u = 64 is never reached for valid input.
  const numerics::Bracket b = numerics::grow_bracket(
      0.0, 1.0, [&](double u) { return root_function(u, &data) >= 0.0; }, 6);
  if (!b.found) throw SolverError("exact Hertz solution: could not bracket the ellipticity");
  double lo = b.lo;
  double hi = b.hi;

  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  gsl_root_fsolver_set(solver.get(), &fn, lo, hi);
  // |Δu| ≤ 1e-15 means |Δκ|/κ ≤ 1e-15, well inside the 1e-10 the library promises.
  for (int iter = 0; iter < 200; ++iter) {
    gsl_root_fsolver_iterate(solver.get());
    lo = gsl_root_fsolver_x_lower(solver.get());
    hi = gsl_root_fsolver_x_upper(solver.get());
    if (gsl_root_test_interval(lo, hi, 1e-15, 0.0) == GSL_SUCCESS) {
      return std::exp(gsl_root_fsolver_root(solver.get()));
    }
  }
  std::ostringstream s;
  s.precision(17);
  s << "exact Hertz solution: Brent iteration for the ellipticity at F(rho) = " << f_rho
    << " did not converge in 200 iterations (bracket ln(kappa) in [" << lo << ", " << hi << "])";
  throw SolverError(s.str());
}

class ExactHertz final : public HertzSolution {
 public:
  HertzShape shape(double f_rho) const override {
    detail::require_curvature_difference(f_rho, name());
    // Sphere on sphere/plane: the F equation is 0/0 at κ = 1; its limit is F = 0.
    if (f_rho == 0.0) return hertz_shape_from(1.0, pi / 2, pi / 2);
    const double kappa = solve_ellipticity(f_rho);
    const EllipticPair p = elliptic_integrals(kappa);
    return hertz_shape_from(kappa, p.K, p.E);
  }
  HertzMethod method() const override { return HertzMethod::exact; }
};

}  // namespace

std::unique_ptr<HertzSolution> make_exact_hertz() {
  return std::make_unique<ExactHertz>();
}

std::unique_ptr<HertzSolution> make_hertz_solution(HertzMethod method) {
  switch (method) {
    case HertzMethod::hamrock_brewe:
      return make_hamrock_brewe_hertz();
    case HertzMethod::harris_table:
      return make_harris_table_hertz();
    case HertzMethod::exact:
      break;
  }
  return make_exact_hertz();
}

std::unique_ptr<HertzSolution> make_hertz_solution(std::string_view name, const std::string& key) {
  return make_hertz_solution(parse_named(kHertzMethods, name, key, "Hertz contact method"));
}

}  // namespace bearing
