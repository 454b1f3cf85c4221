#pragma once
// Scalar roots on a bracket: growing the bracket, bisection, regula falsi (Illinois) and
// safeguarded Newton. One implementation each for the whole toolkit (static load, 3-DOF axial
// preload, Hertz ellipticity, ball equilibrium, RK4 stability bound, PML growth, line searches).
//
// Every routine keeps the iterates its call sites had before they shared it — results are bit
// for bit the same — so the options name the small differences between those sites (stopping
// rule, safeguard) rather than hiding them. Callbacks are std::function: none of these runs in
// a force evaluation, and a few indirect calls per solve cost nothing measurable.
//
// GSL (gsl_roots.h) is used where it was already (Brent for the Hertz ellipticity, hertz_exact.cc)
// and not switched to elsewhere: its false-position solver has no Illinois rule and no
// safeguard, its bisection needs signed values at both ends (an error for a root at an end),
// and it has no bracketed Newton; each would change the iterates in the last bits.

#include <functional>

namespace bearing::numerics {

/// An interval [lo, hi] that contains a root.
struct Bracket {
  double lo = 0;       ///< lower end
  double hi = 0;       ///< upper end
  bool found = false;  ///< grow_bracket: the root lies in [lo, hi]
};

/// Grows [lo, hi] upward by doubling hi (lo moves to the old hi) while `beyond(hi)` says the
/// root lies above hi, at most `max_doublings` times. `found` is false if the root is still
/// beyond hi then. For hi > 0; `beyond` is evaluated once per hi tried.
Bracket grow_bracket(double lo, double hi, const std::function<bool(double)>& beyond,
                     int max_doublings);

/// Where bisection stops: after max_iterations halvings, or once hi − lo ≤ abs_width +
/// rel_width·|hi| (the defaults, 0: once the bracket cannot shrink any more).
struct BisectionOptions {
  int max_iterations = 200;
  double abs_width = 0;  ///< in the units of x
  double rel_width = 0;  ///< relative to |hi| [-]
};

/// Bisection of [lo, hi] on a predicate: `below(x)` is true where x lies below the root (lo
/// takes x) and false above it (hi takes x). Returns the final bracket; its midpoint
/// 0.5 (lo + hi) is the usual estimate.
Bracket bisect(double lo, double hi, const std::function<bool(double)>& below,
               const BisectionOptions& options);

/// Options of regula_falsi.
struct RegulaFalsiOptions {
  int max_iterations = 100;
  /// A secant point closer than margin·(hi − lo) to either end is replaced by the midpoint
  /// (0: only points outside the open bracket are).
  double margin = 0;
  /// Illinois rule: when the same end is kept twice, halve the other end's value, so that one
  /// end cannot stall (superlinear instead of linear convergence).
  bool illinois = true;
  /// Stop once hi − lo ≤ 4 ε hi (the bracket has collapsed to rounding).
  bool stop_on_collapse = true;
};

/// Result of regula_falsi.
struct RegulaFalsiResult {
  double x = 0;            ///< the last point evaluated
  double lo = 0, hi = 0;   ///< the final bracket
  bool converged = false;  ///< `done` accepted x
  int iterations = 0;      ///< evaluations of f
};

/// Regula falsi on [lo, hi] for an increasing f with f_lo = f(lo) < 0 ≤ f_hi = f(hi): the secant
/// point of the bracket ends, kept inside the bracket, so it cannot leave it. Each new point x
/// with value fx = f(x) is offered to `done(x, fx)` first (converged if it says so), then
/// replaces the end with the same sign (fx < 0: lo).
RegulaFalsiResult regula_falsi(const std::function<double(double)>& f, double lo, double f_lo,
                               double hi, double f_hi,
                               const std::function<bool(double, double)>& done,
                               const RegulaFalsiOptions& options);

/// Root of an increasing f on [lo, hi] with f(lo) < 0 ≤ f(hi): Newton steps while they stay
/// inside the bracket, bisection otherwise, from the midpoint. `f_df(x, f, df)` gives f(x) and
/// f'(x). Returns the root to within 4 ε (relative) — an exact zero at once — or the last
/// point after max_iterations.
double newton_bisection(const std::function<void(double, double&, double&)>& f_df, double lo,
                        double hi, int max_iterations);

}  // namespace bearing::numerics
