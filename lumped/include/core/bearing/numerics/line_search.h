#pragma once
// Line search on a convex ray φ(α) = Φ(x + α p), p a descent direction (φ'(0) < 0).
//
// φ' is nondecreasing, so the minimum on the ray is the root of φ'; the search looks for α with
// |φ'(α)| ≤ c |φ'(0)| (the strong Wolfe curvature condition, which brackets that root) by
// regula falsi on φ'. Derivatives rather than values decide, so it still works where the
// changes of Φ are below its rounding (a stiff Hertzian contact near equilibrium).

#include <functional>

#include "bearing/numerics/roots.h"

namespace bearing::numerics {

/// How the unit step α = 1 (the Newton step) is judged.
enum class UnitStep {
  wolfe,            ///< taken if |φ'(1)| ≤ c |φ'(0)|, like any other α
  short_of_minimum  ///< taken whenever φ'(1) ≤ 0 (it does not pass the minimum)
};

/// Options of convex_line_search.
struct LineSearchOptions {
  double curvature = 0.1;  ///< c of the curvature condition [-]
  UnitStep unit_step = UnitStep::wolfe;
  int max_expansions = 0;   ///< doublings of α beyond 1 while φ' < 0
  RegulaFalsiOptions zoom;  ///< the root of φ' inside the bracket
  /// If the zoom ends without meeting the condition: take its lower end (only if > 0: the last α
  /// with φ' < 0, and only if `accept` agrees), instead of the last α evaluated.
  bool fallback_to_lower_end = false;
};

/// Searches α > 0 along the ray. `derivative(α)` evaluates the point x + α p (the caller keeps
/// it) and returns φ'(α); `accept(α)` is then asked to take the point last evaluated, at α, and
/// may refuse (e.g. if Φ rose above its rounding). `slope` = φ'(0) < 0. Steps: α = 1; doubling
/// while φ' < 0 (at most max_expansions); regula falsi on φ' in the bracket; the fallback.
/// Returns whether a point was accepted.
bool convex_line_search(double slope, const std::function<double(double)>& derivative,
                        const std::function<bool(double)>& accept,
                        const LineSearchOptions& options);

}  // namespace bearing::numerics
