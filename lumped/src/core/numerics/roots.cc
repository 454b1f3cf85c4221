// Scalar roots on a bracket (roots.h).

#include "bearing/numerics/roots.h"

#include <cmath>
#include <limits>

namespace bearing::numerics {

namespace {
constexpr double kEps = std::numeric_limits<double>::epsilon();
}  // namespace

Bracket grow_bracket(double lo, double hi, const std::function<bool(double)>& beyond,
                     int max_doublings) {
  for (int k = 0; beyond(hi); ++k) {
    if (k == max_doublings) return {lo, hi, false};
    lo = hi;
    hi *= 2.0;
  }
  return {lo, hi, true};
}

Bracket bisect(double lo, double hi, const std::function<bool(double)>& below,
               const BisectionOptions& o) {
  for (int it = 0; it < o.max_iterations && hi - lo > o.abs_width + o.rel_width * std::abs(hi);
       ++it) {
    const double mid = 0.5 * (lo + hi);
    (below(mid) ? lo : hi) = mid;
  }
  return {lo, hi, true};
}

RegulaFalsiResult regula_falsi(const std::function<double(double)>& f, double lo, double f_lo,
                               double hi, double f_hi,
                               const std::function<bool(double, double)>& done,
                               const RegulaFalsiOptions& o) {
  RegulaFalsiResult r;
  r.x = hi;
  int side = 0;  // the end replaced last: −1 lo, +1 hi
  for (int it = 0; it < o.max_iterations; ++it) {
    double x = lo - f_lo * (hi - lo) / (f_hi - f_lo);
    const double width = hi - lo;
    if (!(x > lo + o.margin * width && x < hi - o.margin * width)) x = 0.5 * (lo + hi);
    const double fx = f(x);
    r.x = x;
    ++r.iterations;
    if (done(x, fx)) {
      r.converged = true;
      break;
    }
    if (fx < 0) {
      lo = x, f_lo = fx;
      if (o.illinois && side == -1) f_hi *= 0.5;
      side = -1;
    } else {
      hi = x, f_hi = fx;
      if (o.illinois && side == 1) f_lo *= 0.5;
      side = 1;
    }
    if (o.stop_on_collapse && hi - lo <= 4 * kEps * hi) break;
  }
  r.lo = lo;
  r.hi = hi;
  return r;
}

double newton_bisection(const std::function<void(double, double&, double&)>& f_df, double lo,
                        double hi, int max_iterations) {
  double t = 0.5 * (lo + hi), h = 0, dh = 0;
  for (int k = 0; k < max_iterations; ++k) {
    f_df(t, h, dh);
    if (h == 0) return t;
    (h < 0 ? lo : hi) = t;
    double next = dh > 0 ? t - h / dh : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (hi - lo <= 4 * kEps * std::abs(hi) || std::abs(next - t) <= 4 * kEps * std::abs(t))
      return next;
    t = next;
  }
  return t;
}

}  // namespace bearing::numerics
