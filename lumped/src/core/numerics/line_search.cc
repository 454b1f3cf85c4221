// Line search on a convex ray (line_search.h).

#include "bearing/numerics/line_search.h"

#include <cmath>

namespace bearing::numerics {

bool convex_line_search(double slope, const std::function<double(double)>& derivative,
                        const std::function<bool(double)>& accept, const LineSearchOptions& o) {
  const double target = o.curvature * std::abs(slope);
  double lo = 0.0, d_lo = slope;  // φ'(lo) < 0
  double hi = 1.0, d_hi = derivative(hi);
  const bool unit = o.unit_step == UnitStep::wolfe ? std::abs(d_hi) <= target : !(d_hi > 0);
  if (unit && accept(hi)) return true;
  // Expand until φ' ≥ 0: Φ is coercive, so this ends (overflow to inf ends it first only for
  // nonsense input, and then the search reports failure).
  for (int k = 0; d_hi < 0 && k < o.max_expansions; ++k) {
    lo = hi, d_lo = d_hi;
    hi *= 2.0;
    d_hi = derivative(hi);
    if (std::abs(d_hi) <= target && accept(hi)) return true;
  }
  if (!(d_hi >= 0)) return false;
  const RegulaFalsiResult z = regula_falsi(
      derivative, lo, d_lo, hi, d_hi,
      [&](double alpha, double d) { return std::abs(d) <= target && accept(alpha); }, o.zoom);
  if (z.converged) return true;
  if (!o.fallback_to_lower_end) return accept(z.x);
  // The bracket has collapsed onto the minimum on the ray to within rounding.
  if (!(z.lo > 0)) return false;
  derivative(z.lo);
  return accept(z.lo);
}

}  // namespace bearing::numerics
