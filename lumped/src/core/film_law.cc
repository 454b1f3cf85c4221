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

// The root in ln Q, bracketed and safeguarded: slow, but sure (the fallback of FilmLaw::load).
double load_in_log(const FilmLaw& f, double approach) {
  const double K = f.K, H = f.H, exponent = f.exponent;
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
  // g rises from −∞ to +∞ over ln Q: 2000 steps of 2 span any double's range.
  for (int k = 0; residual(f, lo, approach).g > 0; ++k)
    if (k == 2000)
      throw SolverError("film law: no lower bracket for " + format_number(approach) + " m");
    else
      lo -= 2.0;
  for (int k = 0; residual(f, hi, approach).g < 0; ++k)
    if (k == 2000)
      throw SolverError("film law: no upper bracket for " + format_number(approach) + " m");
    else
      hi += 2.0;
  bool converged = false;
  for (int it = 0; it < 200 && !converged; ++it) {
    const Residual r = residual(f, s, approach);
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

}  // namespace

double FilmLaw::load(double approach) const {
  if (!std::isfinite(approach))
    throw SolverError("film law: the approach " + format_number(approach) + " m is not finite");
  if (H == 0.0) return approach > 0 ? K * std::pow(approach, exponent) : 0.0;
  // Newton in the Hertz deflection t = δ_H = (Q/K)^{1/n}: with the film h = A t^−m
  // (A = H K^−e, m = n e), g(t) = t − A t^−m − δ rises and is concave in t > 0, so from a start
  // at or right of the root one step lands left of it and the rest climb to it monotonically and
  // quadratically (a tangent of a concave function lies above it): 3–5 steps, one pow each.
  // Starts, each with g ≥ 0: δ > 0, t = δ + A δ^−m (the film at the dry deflection); δ ≤ 0, the
  // smaller of the film alone, A t^−m = −δ, and the root at δ = 0, t* = A^{1/(1+m)}.
  const double m = exponent * kE;
  const double A = H * std::pow(K, -kE);
  double t = approach > 0 ? approach + A * std::pow(approach, -m) : std::pow(A, 1.0 / (1.0 + m));
  if (approach < 0) t = std::min(t, std::pow(A / -approach, 1.0 / m));
  for (int it = 0; it < 40 && std::isfinite(t) && t > 0; ++it) {
    const double film = A * std::pow(t, -m);
    double next = t - (t - film - approach) / (1.0 + m * film / t);
    if (!(next > 0)) next = 0.5 * t;  // overshot past 0 from the right: halve, and go on
    if (std::fabs(next - t) <= 4e-15 * t) {
      const double q = K * std::pow(next, exponent);
      return q < std::numeric_limits<double>::min() ? 0.0 : q;
    }
    t = next;
  }
  return load_in_log(*this, approach);
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
