#pragma once
// Minimising a smooth convex potential Φ(x), x ∈ ℝᴺ (N = 2, 3: a ring's position), from its
// gradient g = ∇Φ and Hessian H = ∇²Φ. The contact problems of the lumped models are of this
// kind: Φ = Σ_j K/(n+1) [δ_j]_+^{n+1} − F·x is convex and coercive, but H is singular where no
// or one ball is loaded, so plain Newton needs help away from the solution. Three strategies,
// each for the callers that use it (their iterates are kept bit for bit):
//
//   newton_minimize    Newton with a Levenberg term and a derivative-based line search
//                      (line_search.h); optionally one eigen-direction at a time when H is
//                      singular. Static load distribution, 3-DOF static state.
//   newton_full_steps  undamped Newton, kept only while |g| falls: cheap continuation from a good
//                      guess. Quasi-static model, per instant.
//   levenberg_minimize Levenberg-damped Newton with Armijo backtracking on Φ and an adaptive
//                      damping: converges from any start. Quasi-static fallback.
//
// A Point type holds what the caller evaluates at one x: members `value` (Φ), `gradient` (g)
// and `hessian` (H), as in PotentialPoint, plus anything else the caller needs. GSL's multimin
// has no Newton method with a Hessian, so these are written here.

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "bearing/numerics/line_search.h"

namespace bearing::numerics {

/// Φ, ∇Φ and ∇²Φ at one point (units of Φ; per unit of x; per unit of x²).
template <int N>
struct PotentialPoint {
  double value = 0;
  Eigen::Matrix<double, N, 1> gradient = Eigen::Matrix<double, N, 1>::Zero();
  Eigen::Matrix<double, N, N> hessian = Eigen::Matrix<double, N, N>::Zero();
};

/// Options of newton_minimize.
struct NewtonOptions {
  double tolerance = 0;  ///< stop once |g| ≤ tolerance (units of g)
  int max_iterations = 100;
  /// Levenberg term μ = gradient_damping |g|² + 1e-12 tr H + 1e-300 added to H: keeps the step
  /// finite for a nearly singular H; with the |g|² part it vanishes at the solution fast enough
  /// that the rate stays quadratic.
  double gradient_damping = 0;
  /// Where H is singular to rounding (λ_min ≤ 1e-12 λ_max: one ball loaded, or none), Φ falls
  /// linearly along the null direction until another ball closes, possibly far away; a step
  /// mixing it with a stiff direction makes the line search trade one against the other. So
  /// step along each eigenvector in turn, stiff first, skipping components of g at most
  /// tolerance/4 (a rounding-level force must not send x sliding along the flat direction).
  bool split_singular = false;
  LineSearchOptions line_search;
};

/// Result of newton_minimize.
struct NewtonResult {
  int iterations = 0;    ///< Newton iterations, a final one that could not move included
  bool stalled = false;  ///< stopped because the line search could not move
};

/// Minimises Φ from x (at_x = evaluate(x) on entry; both updated). `evaluate(x)` returns a
/// Point; `acceptable(trial, at_x, x)` says whether the line search may move from x to a trial
/// point it found (e.g. Φ not raised beyond rounding); always true if Φ is not evaluated.
template <int N, class Point, class Evaluate, class Acceptable>
NewtonResult newton_minimize(Eigen::Matrix<double, N, 1>& x, Point& at_x, Evaluate&& evaluate,
                             Acceptable&& acceptable, const NewtonOptions& o) {
  using Vector = Eigen::Matrix<double, N, 1>;
  using Matrix = Eigen::Matrix<double, N, N>;
  // Line search along p from x; moves x and at_x if a point is accepted.
  const auto search = [&](const Vector& p) {
    const double slope = at_x.gradient.dot(p);
    if (!(p.allFinite() && slope < 0)) return false;
    Point trial;
    const auto derivative = [&](double alpha) {
      trial = evaluate(Vector(x + alpha * p));
      return trial.gradient.dot(p);
    };
    const auto accept = [&](double alpha) {
      if (!acceptable(trial, at_x, x)) return false;
      x += alpha * p;
      at_x = trial;
      return true;
    };
    return convex_line_search(slope, derivative, accept, o.line_search);
  };

  NewtonResult r;
  while (at_x.gradient.norm() > o.tolerance && r.iterations < o.max_iterations) {
    ++r.iterations;
    const Matrix H = at_x.hessian;
    const double gnorm = at_x.gradient.norm();
    const double mu = o.gradient_damping * gnorm * gnorm + 1e-12 * H.trace() + 1e-300;
    bool moved = false;
    Eigen::SelfAdjointEigenSolver<Matrix> eig;
    if (o.split_singular) eig.computeDirect(H);
    const Vector lambda =
        o.split_singular ? Vector(eig.eigenvalues().cwiseMax(0.0)) : Vector::Zero();  // ascending
    if (!o.split_singular || lambda(0) > 1e-12 * lambda(N - 1)) {
      moved = search(-(H + mu * Matrix::Identity()).ldlt().solve(at_x.gradient));
    } else {
      for (int i = N - 1; i >= 0; --i) {  // stiff first, then flat
        const Vector u = eig.eigenvectors().col(i);
        const double gi = at_x.gradient.dot(u);
        if (std::abs(gi) <= 0.25 * o.tolerance) continue;
        moved = search(-gi / (lambda(i) + mu) * u) || moved;
      }
    }
    if (!moved) {
      r.stalled = true;
      break;
    }
  }
  return r;
}

/// Options of newton_full_steps.
struct FullStepOptions {
  double tolerance = 0;    ///< converged once |g| ≤ tolerance (units of g)
  double good_enough = 0;  ///< also converged if a step stops reducing |g| below this
  int max_iterations = 30;
  double singular = 1e-12;  ///< H is singular if det H ≤ singular · (tr H)² [-]
};

/// Result of newton_full_steps.
struct FullStepResult {
  bool converged = false;
  int iterations = 0;  ///< steps evaluated
};

/// Undamped Newton x ← x − H⁻¹g from x (at_x = evaluate(x); both updated), a step kept only if
/// it reduces |g|. Stops unconverged at a singular H or after max_iterations.
template <int N, class Point, class Evaluate>
FullStepResult newton_full_steps(Eigen::Matrix<double, N, 1>& x, Point& at_x, Evaluate&& evaluate,
                                 const FullStepOptions& o) {
  using Vector = Eigen::Matrix<double, N, 1>;
  FullStepResult r;
  for (int it = 0; it < o.max_iterations; ++it) {
    if (at_x.gradient.norm() <= o.tolerance) {
      r.converged = true;
      break;
    }
    const double det = at_x.hessian.determinant();
    if (!(det > o.singular * at_x.hessian.trace() * at_x.hessian.trace())) break;
    const Vector next = x - at_x.hessian.inverse() * at_x.gradient;
    const Point at_next = evaluate(next);
    ++r.iterations;
    if (!(at_next.gradient.norm() < at_x.gradient.norm())) {
      // At rounding level the step no longer helps: done if the balance is good enough.
      r.converged = at_x.gradient.norm() <= o.good_enough;
      break;
    }
    x = next;
    at_x = at_next;
  }
  return r;
}

/// Options of levenberg_minimize.
struct LevenbergOptions {
  double tolerance = 0;  ///< stop once |g| ≤ tolerance (units of g)
  int max_iterations = 2000;
  /// Scale of H (e.g. tr H at a typical solution): the damping μ starts there, never falls
  /// below 1e-12 of it, and the search gives up when no step helps even above 1e12 of it.
  double stiffness = 1;
  int max_backtracks = 40;  ///< halvings of the step
  double armijo = 1e-4;     ///< sufficient decrease Φ(x + a d) ≤ Φ(x) + armijo a g·d [-]
};

/// Levenberg-damped Newton d = −(H + μI)⁻¹g with Armijo backtracking on Φ from x (at_x =
/// evaluate(x); both updated). A step is taken at the first halving that decreases Φ enough —
/// or, where differences of Φ drown in rounding, halves |g|; then μ ← max(μ/4, 1e-12 stiffness).
/// If none does, μ ← 10 μ. For a convex coercive Φ each damped step with a small enough
/// length decreases Φ, so this converges from any start. Returns the iterations.
template <int N, class Point, class Evaluate>
int levenberg_minimize(Eigen::Matrix<double, N, 1>& x, Point& at_x, Evaluate&& evaluate,
                       const LevenbergOptions& o) {
  using Vector = Eigen::Matrix<double, N, 1>;
  using Matrix = Eigen::Matrix<double, N, N>;
  int iterations = 0;
  double mu = o.stiffness;
  for (int it = 0; it < o.max_iterations && at_x.gradient.norm() > o.tolerance; ++it) {
    ++iterations;
    const Matrix A = at_x.hessian + mu * Matrix::Identity();
    const Vector d = -A.inverse() * at_x.gradient;
    const double slope = at_x.gradient.dot(d);  // < 0: A is positive definite
    double a = 1.0;
    bool moved = false;
    for (int ls = 0; ls < o.max_backtracks; ++ls, a *= 0.5) {
      const Vector next = x + a * d;
      const Point at_next = evaluate(next);
      if (at_next.value <= at_x.value + o.armijo * a * slope ||
          at_next.gradient.norm() < 0.5 * at_x.gradient.norm()) {
        x = next;
        at_x = at_next;
        moved = true;
        break;
      }
    }
    if (!moved) {
      if (mu > 1e12 * o.stiffness) break;  // no descent at all: rounding level
      mu *= 10.0;
      continue;
    }
    mu = std::max(mu * 0.25, 1e-12 * o.stiffness);
  }
  return iterations;
}

}  // namespace bearing::numerics
