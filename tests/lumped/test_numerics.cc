// The shared solvers (numerics/roots.h, line_search.h, newton.h) against closed forms.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Dense>

#include "bearing/numerics/line_search.h"
#include "bearing/numerics/newton.h"
#include "bearing/numerics/roots.h"

namespace bearing::numerics {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// --- roots.h ------------------------------------------------------------------------------------

TEST(GrowBracket, DoublesUntilTheRootIsInside) {
  int calls = 0;
  const Bracket b = grow_bracket(
      0.0, 1.0, [&](double x) { return ++calls, x < 37.5; }, 100);
  EXPECT_TRUE(b.found);
  EXPECT_EQ(b.lo, 32.0);
  EXPECT_EQ(b.hi, 64.0);
  EXPECT_EQ(calls, 7);  // 1, 2, ..., 64
  const Bracket at_once = grow_bracket(
      0.0, 1.0, [](double x) { return x < 0.5; }, 100);
  EXPECT_TRUE(at_once.found);
  EXPECT_EQ(at_once.lo, 0.0);
  EXPECT_EQ(at_once.hi, 1.0);
}

TEST(GrowBracket, ReportsNoBracketAfterTheLastDoubling) {
  int calls = 0;
  const Bracket b = grow_bracket(
      0.0, 1.0, [&](double) { return ++calls, true; }, 6);  // no sign change at all
  EXPECT_FALSE(b.found);
  EXPECT_EQ(b.lo, 32.0);
  EXPECT_EQ(b.hi, 64.0);  // 6 doublings, no seventh
  EXPECT_EQ(calls, 7);
}

TEST(Bisect, HalvesToTheClosedFormRoot) {
  const auto below = [](double x) { return x * x < 2.0; };
  const Bracket b = bisect(1.0, 2.0, below, BisectionOptions{});
  EXPECT_LE(b.hi - b.lo, 2 * kEps * b.hi);  // shrunk to rounding
  EXPECT_NEAR(0.5 * (b.lo + b.hi), std::sqrt(2.0), 2 * kEps);
  EXPECT_LT(b.lo * b.lo, 2.0);
  EXPECT_GE(b.hi * b.hi, 2.0);
}

TEST(Bisect, StopsAtTheWidthOrTheIterationCount) {
  int calls = 0;
  const auto below = [&](double x) { return ++calls, std::exp(x) < 3.0; };
  BisectionOptions o;
  o.max_iterations = 10;
  Bracket b = bisect(0.0, 2.0, below, o);
  EXPECT_EQ(calls, 10);
  EXPECT_DOUBLE_EQ(b.hi - b.lo, 2.0 / 1024);
  EXPECT_TRUE(b.lo < std::log(3.0) && std::log(3.0) <= b.hi);
  calls = 0;
  o = BisectionOptions{};
  o.abs_width = 1e-6;
  b = bisect(0.0, 2.0, below, o);
  EXPECT_EQ(calls, 21);  // 2/2^21 ≤ 1e-6 < 2/2^20
  calls = 0;
  o = BisectionOptions{};
  o.rel_width = 1e-9;
  b = bisect(0.0, 2.0, below, o);
  EXPECT_LE(b.hi - b.lo, 1e-9 * b.hi);
  EXPECT_GT(2 * (b.hi - b.lo), 1e-9 * b.hi);
}

TEST(RegulaFalsi, IllinoisConvergesSuperlinearlyWherePlainFalsePositionStalls) {
  // x³ − 2 is convex on [0, 4]: plain false position keeps the upper end forever.
  const auto f = [](double x) { return x * x * x - 2.0; };
  const double root = std::cbrt(2.0);
  const auto done = [](double, double fx) { return std::abs(fx) <= 1e-13; };
  RegulaFalsiOptions o;
  o.max_iterations = 500;
  const RegulaFalsiResult illinois = regula_falsi(f, 0.0, f(0.0), 4.0, f(4.0), done, o);
  ASSERT_TRUE(illinois.converged);
  EXPECT_NEAR(illinois.x, root, 1e-13);
  o.illinois = false;
  const RegulaFalsiResult plain = regula_falsi(f, 0.0, f(0.0), 4.0, f(4.0), done, o);
  ASSERT_TRUE(plain.converged);
  EXPECT_NEAR(plain.x, root, 1e-13);
  EXPECT_EQ(plain.hi, 4.0);  // never moved
  EXPECT_LT(illinois.iterations, 20);
  EXPECT_GT(plain.iterations, 3 * illinois.iterations);
}

TEST(RegulaFalsi, CollapsesOntoTheRootWhenNothingIsAccepted) {
  const auto f = [](double x) { return std::log(x) - 1.0; };  // root e
  const RegulaFalsiResult r = regula_falsi(
      f, 1.0, f(1.0), 10.0, f(10.0), [](double, double) { return false; }, RegulaFalsiOptions{});
  EXPECT_FALSE(r.converged);
  EXPECT_LE(r.hi - r.lo, 4 * kEps * r.hi);
  EXPECT_LE(r.lo, std::exp(1.0) * (1 + 4 * kEps));
  EXPECT_GE(r.hi, std::exp(1.0) * (1 - 4 * kEps));
}

TEST(RegulaFalsi, MarginKeepsPointsOffTheEnds) {
  // A step function: the secant point of (0, −1), (1, 1e9) would sit at 1e-9.
  std::vector<double> xs;
  const auto f = [&](double x) { return xs.push_back(x), x < 0.3 ? -1.0 : 1e9; };
  RegulaFalsiOptions o;
  o.max_iterations = 1;
  o.margin = 0.01;
  regula_falsi(
      f, 0.0, -1.0, 1.0, 1e9, [](double, double) { return false; }, o);
  ASSERT_EQ(xs.size(), 1u);
  EXPECT_EQ(xs[0], 0.5);  // the midpoint instead
  o.margin = 0;
  xs.clear();
  regula_falsi(
      f, 0.0, -1.0, 1.0, 1e9, [](double, double) { return false; }, o);
  EXPECT_DOUBLE_EQ(xs.at(0), 1.0 / (1.0 + 1e9));
}

TEST(NewtonBisection, ConvergesToTheClosedFormRoot) {
  int calls = 0;
  const auto f_df = [&](double x, double& f, double& df) {
    ++calls;
    f = std::exp(x) - 5.0;
    df = std::exp(x);
  };
  const double x = newton_bisection(f_df, 0.0, 4.0, 200);
  EXPECT_NEAR(x, std::log(5.0), 4 * kEps * std::log(5.0));
  EXPECT_LT(calls, 12);  // quadratic once close
}

TEST(NewtonBisection, BisectsWhereNewtonWouldLeaveTheBracket) {
  // atan(x − 1): Newton from x far from 1 overshoots far outside the bracket.
  const auto f_df = [](double x, double& f, double& df) {
    f = std::atan(x - 1.0);
    df = 1.0 / (1.0 + (x - 1.0) * (x - 1.0));
  };
  EXPECT_NEAR(newton_bisection(f_df, -30.0, 50.0, 200), 1.0, 1e-15);
  // An exact zero at the first point is returned at once.
  EXPECT_EQ(newton_bisection(f_df, 0.0, 2.0, 200), 1.0);
}

// --- line_search.h ------------------------------------------------------------------------------

// φ(α) = (α − m)²/2 on a ray: φ'(α) = α − m, φ'(0) = −m.
struct Parabola {
  double m;
  std::vector<double> evaluated;
  double last = 0;
  double derivative(double alpha) {
    evaluated.push_back(alpha);
    last = alpha;
    return alpha - m;
  }
};

TEST(ConvexLineSearch, ExpandsBeyondTheUnitStepAndZoomsOntoTheMinimum) {
  Parabola p{5.0};
  double taken = -1;
  LineSearchOptions o;
  o.max_expansions = 10;
  o.zoom.max_iterations = 50;
  const bool moved = convex_line_search(
      -p.m, [&](double a) { return p.derivative(a); }, [&](double a) { return taken = a, true; },
      o);
  ASSERT_TRUE(moved);
  EXPECT_LE(std::abs(taken - p.m), 0.1 * p.m);  // |φ'| ≤ 0.1 |φ'(0)|
  EXPECT_EQ(p.evaluated[0], 1.0);
  EXPECT_EQ(p.evaluated[1], 2.0);
  EXPECT_EQ(p.evaluated[2], 4.0);
  EXPECT_EQ(p.evaluated[3], 8.0);
  EXPECT_EQ(p.evaluated.size(), 5u);  // the secant of a linear φ' is exact
  EXPECT_EQ(taken, 5.0);
}

TEST(ConvexLineSearch, ShortUnitStepTakenAsItIsOrRefinedByTheWolfeRule) {
  Parabola p{3.0};
  double taken = -1;
  const auto accept = [&](double a) { return taken = a, true; };
  LineSearchOptions o;
  o.unit_step = UnitStep::short_of_minimum;
  ASSERT_TRUE(convex_line_search(
      -p.m, [&](double a) { return p.derivative(a); }, accept, o));
  EXPECT_EQ(taken, 1.0);  // φ'(1) = −2 < 0: not past the minimum
  o.unit_step = UnitStep::wolfe;
  o.max_expansions = 0;
  EXPECT_FALSE(convex_line_search(
      -p.m, [&](double a) { return p.derivative(a); }, accept, o));
}

TEST(ConvexLineSearch, OvershootIsZoomedBackInsideTheUnitInterval) {
  for (UnitStep rule : {UnitStep::wolfe, UnitStep::short_of_minimum}) {
    Parabola p{0.25};
    double taken = -1;
    LineSearchOptions o;
    o.unit_step = rule;
    ASSERT_TRUE(convex_line_search(
        -p.m, [&](double a) { return p.derivative(a); }, [&](double a) { return taken = a, true; },
        o));
    EXPECT_NEAR(taken, 0.25, 0.1 * 0.25);
  }
}

TEST(ConvexLineSearch, RefusedPointsMakeItFailOrFallBackToTheLowerEnd) {
  Parabola p{0.3};
  LineSearchOptions o;
  o.curvature = 1e-12;  // only the exact minimum 0.3 meets it, and it is refused below
  o.zoom.max_iterations = 5;
  EXPECT_FALSE(convex_line_search(
      -p.m, [&](double a) { return p.derivative(a); }, [](double) { return false; }, o));
  // Accepting only the lower end of the final bracket: the zoom never converges, the fallback
  // re-evaluates that end and takes it.
  double taken = -1;
  o.fallback_to_lower_end = true;
  ASSERT_TRUE(convex_line_search(
      -p.m, [&](double a) { return p.derivative(a); },
      [&](double a) { return a < p.m && (taken = a, p.last == a); }, o));
  EXPECT_GT(taken, 0.0);
  EXPECT_LT(taken, p.m);
}

// --- newton.h -----------------------------------------------------------------------------------

// Φ(x) = Σ_i [(2/5) [y_i + 1]_+^{5/2} − f_i y_i] with y = Rᵀ x, R a rotation: a Hertz-like
// potential, coupled in x, flat (H = 0) where all y_i ≤ −1. ∇Φ = R (([y+1]_+^{3/2} − f)), so
// the minimiser is y_i* = f_i^{2/3} − 1, x* = R y*, with H positive definite there.
template <int N>
struct Hertzlike {
  using Vector = Eigen::Matrix<double, N, 1>;
  using Matrix = Eigen::Matrix<double, N, N>;
  Matrix R;
  Vector f;
  int evaluations = 0;

  Hertzlike() {
    if constexpr (N == 2)
      R = Eigen::Rotation2Dd(0.7).toRotationMatrix();
    else
      R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    for (int i = 0; i < N; ++i) f(i) = 2.0 + 3.0 * i;
  }
  Vector minimiser() const {
    Vector y;
    for (int i = 0; i < N; ++i) y(i) = std::pow(f(i), 2.0 / 3.0) - 1.0;
    return R * y;
  }
  PotentialPoint<N> operator()(const Vector& x) {
    ++evaluations;
    const Vector y = R.transpose() * x;
    PotentialPoint<N> p;
    Vector gy, hy;
    for (int i = 0; i < N; ++i) {
      const double s = std::max(y(i) + 1.0, 0.0);
      p.value += 0.4 * std::pow(s, 2.5) - f(i) * y(i);
      gy(i) = std::pow(s, 1.5) - f(i);
      hy(i) = 1.5 * std::sqrt(s);
    }
    p.gradient = R * gy;
    p.hessian = R * hy.asDiagonal() * R.transpose();
    return p;
  }
};

template <int N>
NewtonOptions static_load_like() {
  NewtonOptions o;
  o.tolerance = 1e-12;
  o.max_iterations = 100;
  o.gradient_damping = 1;
  o.split_singular = true;
  o.line_search.max_expansions = 1100;
  o.line_search.zoom.max_iterations = 200;
  o.line_search.zoom.margin = 0.01;
  o.line_search.fallback_to_lower_end = true;
  return o;
}

const auto always = [](const auto&, const auto&, const auto&) { return true; };

TEST(NewtonMinimize, FindsTheClosedFormMinimiserFromTheFlatRegion) {
  Hertzlike<2> phi;
  Eigen::Vector2d x = phi.R * Eigen::Vector2d(-3.0, -2.0);  // H = 0 here
  auto at = phi(x);
  const NewtonResult r = newton_minimize(x, at, phi, always, static_load_like<2>());
  EXPECT_FALSE(r.stalled);
  EXPECT_LE(at.gradient.norm(), 1e-12);
  EXPECT_NEAR((x - phi.minimiser()).norm(), 0.0, 1e-13);
  EXPECT_LT(r.iterations, 30);
}

TEST(NewtonMinimize, ConvergesQuadraticallyNearTheMinimiser) {
  // The k-th iterate is the result of a run limited to k iterations (the solver is
  // deterministic); the order p = ln(e_{k+1}/e_k) / ln(e_k/e_{k−1}) tends to 2.
  Hertzlike<3> phi;
  const Eigen::Vector3d start = phi.minimiser() + Eigen::Vector3d(0.3, -0.2, 0.25);
  std::vector<double> e;
  for (int k = 0; k <= 6; ++k) {
    Eigen::Vector3d x = start;
    auto at = phi(x);
    NewtonOptions o = static_load_like<3>();
    o.tolerance = 0;
    o.max_iterations = k;
    newton_minimize(x, at, phi, always, o);
    e.push_back((x - phi.minimiser()).norm());
  }
  int measured = 0;
  for (std::size_t k = 2; k < e.size() && e[k] > 1e-12; ++k) {  // above rounding
    if (e[k - 1] > 0.05) continue;                              // not yet asymptotic
    const double p = std::log(e[k] / e[k - 1]) / std::log(e[k - 1] / e[k - 2]);
    EXPECT_NEAR(p, 2.0, 0.2) << "iteration " << k;
    EXPECT_LE(e[k], e[k - 1] * e[k - 1]) << "iteration " << k;
    ++measured;
  }
  EXPECT_GE(measured, 2);
  EXPECT_LT(e.back(), 1e-14);
}

TEST(NewtonMinimize, ThreeDofSettingsConvergeAndAStallIsReported) {
  Hertzlike<3> phi;
  NewtonOptions o;
  o.tolerance = 1e-12;
  o.line_search.unit_step = UnitStep::short_of_minimum;
  o.line_search.zoom.margin = 0.01;
  o.line_search.zoom.illinois = false;
  o.line_search.zoom.stop_on_collapse = false;
  Eigen::Vector3d x = phi.minimiser() + Eigen::Vector3d(2.0, 1.0, -1.5);
  auto at = phi(x);
  NewtonResult r = newton_minimize(x, at, phi, always, o);
  EXPECT_FALSE(r.stalled);
  EXPECT_NEAR((x - phi.minimiser()).norm(), 0.0, 1e-12);
  // A caller that accepts no point: the first iteration cannot move.
  x = phi.minimiser() + Eigen::Vector3d(2.0, 1.0, -1.5);
  at = phi(x);
  r = newton_minimize(
      x, at, phi, [](const auto&, const auto&, const auto&) { return false; },
      static_load_like<3>());
  EXPECT_TRUE(r.stalled);
  EXPECT_EQ(r.iterations, 1);
}

TEST(NewtonFullSteps, ConvergesFromNearAndStopsAtASingularHessian) {
  Hertzlike<2> phi;
  FullStepOptions o;
  o.tolerance = 1e-12;
  Eigen::Vector2d x = phi.minimiser() + Eigen::Vector2d(0.05, -0.05);
  auto at = phi(x);
  FullStepResult r = newton_full_steps(x, at, phi, o);
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.iterations, 6);
  EXPECT_NEAR((x - phi.minimiser()).norm(), 0.0, 1e-13);
  x = phi.R * Eigen::Vector2d(-3.0, -2.0);  // H = 0
  at = phi(x);
  r = newton_full_steps(x, at, phi, o);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.iterations, 0);
}

TEST(LevenbergMinimize, ConvergesFromAnyStart) {
  for (const Eigen::Vector2d& y0 :
       {Eigen::Vector2d(-3.0, -2.0), Eigen::Vector2d(40.0, -0.5), Eigen::Vector2d(-1.0, 1e3)}) {
    Hertzlike<2> phi;
    Eigen::Vector2d x = phi.R * y0;
    auto at = phi(x);
    LevenbergOptions o;
    o.tolerance = 1e-12;
    o.stiffness = 3.0;
    const int iterations = levenberg_minimize(x, at, phi, o);
    EXPECT_LE(at.gradient.norm(), 1e-12) << y0.transpose();
    EXPECT_NEAR((x - phi.minimiser()).norm(), 0.0, 1e-12) << y0.transpose();
    EXPECT_LT(iterations, 200);
  }
}

}  // namespace
}  // namespace bearing::numerics
