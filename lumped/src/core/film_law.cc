// A contact's load–approach law with its EHL film in series (film_law.h).

#include "bearing/film_law.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "bearing/ehl_film.h"
#include "bearing/errors.h"
#include "bearing/units.h"

namespace bearing {

namespace {

constexpr double kE = kCentralFilmLoadExponent;

// g(s) = (e^s/K)^{1/n} − H e^{−e s} − δ and its derivative, s = ln Q.
struct Residual {
  double g, slope;
};

Residual residual(const FilmLaw& f, double s, double approach) {
  const double hertz = std::pow(std::exp(s) / f.K, 1.0 / f.exponent);
  const double film = f.H * std::exp(-kE * s);
  return {hertz - film - approach, hertz / f.exponent + kE * film};
}

}  // namespace

double FilmLaw::load(double approach) const {
  if (!std::isfinite(approach))
    throw SolverError("film law: the approach " + format_number(approach) + " m is not finite");
  if (H == 0.0) return approach > 0 ? K * std::pow(approach, exponent) : 0.0;
  // A start near the root: Hertz alone with the film's gap added (δ > 0); for δ ≤ 0 the smaller
  // of the film alone (h_c = −δ) and the load Q* where δ_H = h_c (δ = 0), both at or above the
  // root. (The film alone by itself is far above the root when −δ ≪ h_c(Q*): at δ = 0 it started
  // at ln Q ~ 1e4, and Newton's steps of n in ln Q ran out of iterations far from the root.)
  double s;
  if (approach > 0) {
    s = std::log(K * std::pow(approach, exponent));
    s = std::log(K * std::pow(approach + H * std::exp(-kE * s), exponent));
  } else {
    // (Q/K)^{1/n} = H Q^−e: ln Q* = (ln H + ln K / n) / (1/n + e).
    const double s_star = (std::log(H) + std::log(K) / exponent) / (1.0 / exponent + kE);
    s = std::min(s_star, std::log(H / std::max(-approach, 1e-300)) / kE);
  }
  // Bracket the root (g rises with s), then Newton kept inside the bracket.
  double lo = s, hi = s;
  while (residual(*this, lo, approach).g > 0) lo -= 2.0;
  while (residual(*this, hi, approach).g < 0) hi += 2.0;
  bool converged = false;
  for (int it = 0; it < 200 && !converged; ++it) {
    const Residual r = residual(*this, s, approach);
    if (r.g == 0) {
      converged = true;
      break;
    }
    (r.g < 0 ? lo : hi) = s;
    double next = s - r.g / r.slope;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::fabs(next - s) <= 1e-15 * std::max(1.0, std::fabs(s)) ||
        hi - lo <= 1e-15 * std::max(1.0, std::fabs(s))) {
      s = next;
      converged = true;
      break;
    }
    s = next;
  }
  if (!converged)
    throw SolverError("film law: no root for the approach " + format_number(approach) +
                      " m in 200 iterations");
  const double q = std::exp(s);
  return q < std::numeric_limits<double>::min() ? 0.0 : q;
}

double FilmLaw::tangent(double load) const {
  if (!(load > 0)) return 0.0;
  const double hertz = std::pow(load / K, 1.0 / exponent);
  return load / (hertz / exponent + kE * film(load));
}

double FilmLaw::energy(double load) const {
  if (!(load > 0)) return 0.0;
  const double hertz = std::pow(load / K, 1.0 / exponent);
  return load * hertz / (exponent + 1.0) + kE / (1.0 - kE) * load * film(load);
}

double FilmLaw::film(double load) const {
  return H == 0.0 || !(load > 0) ? 0.0 : H * std::pow(load, -kE);
}

}  // namespace bearing
