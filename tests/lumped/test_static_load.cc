// Static load distribution (static_load.h).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_gamma.h>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/static_load.h"

namespace bearing {
namespace {

constexpr double K6308 = 1.28e10;  // series constant of the 6308 [N/m^1.5] (test_contact.cc)

Eigen::Vector2d polar(double r, double angle) {
  return r * Eigen::Vector2d(std::cos(angle), std::sin(angle));
}

// Everything a solution must satisfy, recomputed from its outputs only.
void expect_consistent(const StaticLoadResult& r, int Z, double K, double gap,
                       const Eigen::Vector2d& F, double n, double tol, const std::string& what) {
  ASSERT_EQ(static_cast<int>(r.ball_loads.size()), Z) << what;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  double qmax = 0;
  const double scale = gap + r.deflection.norm();
  for (int j = 0; j < Z; ++j) {
    const double th = r.ball_angles[j];
    const double delta = r.deflection.dot(Eigen::Vector2d(std::cos(th), std::sin(th))) - gap;
    EXPECT_NEAR(r.ball_approach[j], delta, 1e-12 * scale + 1e-300) << what << " ball " << j;
    const double q = r.ball_approach[j] > 0 ? K * std::pow(r.ball_approach[j], n) : 0.0;
    EXPECT_NEAR(r.ball_loads[j], q, 1e-12 * F.norm() + 1e-12 * q) << what << " ball " << j;
    EXPECT_GE(r.ball_loads[j], 0.0);
    sum += r.ball_loads[j] * Eigen::Vector2d(std::cos(th), std::sin(th));
    qmax = std::max(qmax, r.ball_loads[j]);
  }
  EXPECT_EQ(r.q_max, qmax) << what;
  const double residual = (sum - F).norm() / F.norm();
  EXPECT_LT(residual, tol) << what;
  EXPECT_NEAR(r.residual, residual, 1e-14) << what;
}

TEST(StaticLoad, ZeroLoadGivesZero) {
  const StaticLoadResult r = solve_static_load(8, K6308, 5e-6, Eigen::Vector2d::Zero());
  EXPECT_EQ(r.deflection, Eigen::Vector2d::Zero());
  EXPECT_EQ(r.q_max, 0.0);
  EXPECT_EQ(r.residual, 0.0);
  EXPECT_EQ(r.iterations, 0);
  ASSERT_EQ(r.ball_loads.size(), 8u);
  for (int j = 0; j < 8; ++j) {
    EXPECT_EQ(r.ball_loads[j], 0.0);
    EXPECT_EQ(r.ball_approach[j], -5e-6);
    EXPECT_NEAR(r.ball_angles[j], two_pi * j / 8, 1e-15);
  }
}

TEST(StaticLoad, BallAnglesStartAtPhase) {
  StaticLoadOptions o;
  o.phase = 0.3;
  const StaticLoadResult r = solve_static_load(9, K6308, 0, Eigen::Vector2d(0, -500), o);
  for (int j = 0; j < 9; ++j) EXPECT_NEAR(r.ball_angles[j], 0.3 + two_pi * j / 9, 1e-15);
}

// Independent check of a symmetric case: with ball 0 on the load line the ring moves along it,
// and x solves the scalar equation Σ_j K [x cos θ_j − γ]_+^n cos θ_j = F (bisection here).
TEST(StaticLoad, SymmetricCaseMatchesScalarEquation) {
  for (double gap : {0.0, 1e-6, 20e-6}) {
    for (double F : {1.0, 300.0, 5000.0, 1e5}) {
      const int Z = 9;
      StaticLoadOptions o;
      o.phase = -pi / 2;  // ball 0 at the bottom
      const StaticLoadResult r = solve_static_load(Z, K6308, gap, Eigen::Vector2d(0, -F), o);
      auto force = [&](double x) {
        double s = 0;
        for (int j = 0; j < Z; ++j) {
          const double c = std::cos(two_pi * j / Z);
          if (x * c > gap) s += K6308 * std::pow(x * c - gap, 1.5) * c;
        }
        return s;
      };
      double lo = gap, hi = gap + 1.0;
      for (int k = 0; k < 200; ++k) (force(0.5 * (lo + hi)) < F ? lo : hi) = 0.5 * (lo + hi);
      const double x = 0.5 * (lo + hi);
      EXPECT_NEAR(r.deflection.y(), -x, 1e-12 * x) << gap << " " << F;
      EXPECT_NEAR(r.deflection.x(), 0.0, 1e-12 * x) << gap << " " << F;
      expect_consistent(r, Z, K6308, gap, Eigen::Vector2d(0, -F), 1.5, 1e-12, "symmetric");
    }
  }
}

// Stribeck: zero clearance, many balls, Q_max Z / F_r → 1 / J_r(0.5) with Sjövall's integral
// J_r(0.5) = (1/2π) ∫_{−π/2}^{π/2} cos^{5/2} θ dθ = 0.228828, so the limit is 4.37010 (the often
// quoted 4.3707 is 1/0.2288, the reciprocal of the rounded table value). With ball 0 on
// the load line the finite-Z ratio is the trapezoidal rule for that integral, so it converges
// fast (the integrand's only roughness is cos^{5/2} at ±π/2).
TEST(StaticLoad, StribeckLimitForManyBalls) {
  gsl_integration_workspace* ws = gsl_integration_workspace_alloc(200);
  gsl_function fn;
  fn.function = [](double th, void*) { return std::pow(std::cos(th), 2.5); };
  fn.params = nullptr;
  double integral = 0, err = 0;
  gsl_integration_qags(&fn, -pi / 2, pi / 2, 0, 1e-13, 200, ws, &integral, &err);
  gsl_integration_workspace_free(ws);
  // Cross-check the quadrature with the Beta-function closed form √π Γ(7/4)/Γ(9/4).
  EXPECT_NEAR(integral, std::sqrt(pi) * gsl_sf_gamma(1.75) / gsl_sf_gamma(2.25), 1e-12);
  const double limit = two_pi / integral;
  EXPECT_NEAR(1.0 / limit, 0.2288, 5e-5);  // the tabulated J_r(0.5), to its printed digits
  EXPECT_NEAR(limit, 4.37010, 5e-6);

  double previous_error = 1.0;
  for (int Z : {25, 200, 1000}) {
    const double angle = -pi / 2;
    StaticLoadOptions o;
    o.phase = angle;
    const Eigen::Vector2d F = polar(2000.0, angle);
    const StaticLoadResult r = solve_static_load(Z, K6308, 0.0, F, o);
    expect_consistent(r, Z, K6308, 0.0, F, 1.5, 1e-12, "Stribeck Z = " + std::to_string(Z));
    const double ratio = r.q_max * Z / F.norm();
    const double error = std::abs(ratio - limit) / limit;
    std::printf("Stribeck: Z = %4d  Q_max Z / F = %.8f  (limit %.8f, rel. difference %.2e)\n", Z,
                ratio, limit, error);
    EXPECT_LT(error, previous_error / 10) << Z;
    previous_error = error;
  }
  EXPECT_LT(previous_error, 1e-6);  // Z = 1000
}

TEST(StaticLoad, ForceBalanceForManyLoadsAndClearances) {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> U(0, 1);
  int worst_iterations = 0;
  for (int Z : {3, 4, 7, 8, 9, 13, 40}) {
    for (int trial = 0; trial < 300; ++trial) {
      const double K = std::pow(10.0, 9 + 2 * U(rng));
      const double gap = trial % 5 == 0 ? 0.0 : std::pow(10.0, -8 + 4 * U(rng));
      const double Fm = std::pow(10.0, -6 + 11 * U(rng));  // 1 µN … 100 kN
      // A quarter of the loads point exactly at a ball or exactly between two.
      StaticLoadOptions o;
      o.phase = two_pi * U(rng);
      const double angle = trial % 4 == 0   ? o.phase + two_pi * (trial % Z) / Z
                           : trial % 4 == 1 ? o.phase + pi * (2 * (trial % Z) + 1) / Z
                                            : two_pi * U(rng);
      const Eigen::Vector2d F = polar(Fm, angle);
      const StaticLoadResult r = solve_static_load(Z, K, gap, F, o);
      expect_consistent(r, Z, K, gap, F, 1.5, 1e-9,
                        "Z " + std::to_string(Z) + " trial " + std::to_string(trial));
      EXPECT_LE(r.residual, o.tolerance);
      worst_iterations = std::max(worst_iterations, r.iterations);
    }
  }
  std::printf("force balance: at most %d Newton iterations\n", worst_iterations);
  EXPECT_LE(worst_iterations, 30);
}

TEST(StaticLoad, OtherExponentsConverge) {
  for (double n : {1.0, 10.0 / 9.0, 1.5, 2.0}) {
    for (double gap : {0.0, 3e-6}) {
      StaticLoadOptions o;
      o.exponent = n;
      const Eigen::Vector2d F(123.0, -456.0);
      const StaticLoadResult r = solve_static_load(11, 1e9, gap, F, o);
      expect_consistent(r, 11, 1e9, gap, F, n, 1e-12, "n = " + std::to_string(n));
    }
  }
}

// Without clearance the problem is homogeneous: δ ∝ F^{1/n}, so 8F moves the ring 4 times as far.
TEST(StaticLoad, ZeroClearanceDeflectionScalesAsTwoThirdsPower) {
  for (double angle : {-pi / 2, 0.1234, 2.5}) {
    const Eigen::Vector2d F = polar(700.0, angle);
    const StaticLoadResult r1 = solve_static_load(8, K6308, 0.0, F);
    const StaticLoadResult r8 = solve_static_load(8, K6308, 0.0, 8.0 * F);
    EXPECT_NEAR((r8.deflection - 4.0 * r1.deflection).norm() / r8.deflection.norm(), 0.0, 1e-12);
    for (int j = 0; j < 8; ++j) {
      EXPECT_NEAR(r8.ball_loads[j], 8.0 * r1.ball_loads[j], 1e-12 * 8 * F.norm());
    }
  }
}

// A load far below what closes the clearance: the ring crosses the gap and rests on one or two
// balls, with approaches many orders of magnitude below the gap.
TEST(StaticLoad, TinyLoadWithClearanceConverges) {
  const double gap = 10e-6;
  for (double Fm : {1e-9, 1e-6, 1e-3}) {
    for (double angle : {-pi / 2, -pi / 2 + pi / 8, 0.3, 1.0}) {
      const Eigen::Vector2d F = polar(Fm, angle);
      const StaticLoadResult r = solve_static_load(8, K6308, gap, F);
      expect_consistent(r, 8, K6308, gap, F, 1.5, 1e-9, "tiny load");
      int loaded = 0;
      for (double q : r.ball_loads) loaded += q > 0;
      EXPECT_GE(loaded, 1);
      EXPECT_LE(loaded, 2);
      EXPECT_GE(r.deflection.norm(), gap);
      EXPECT_LE(r.deflection.norm(), gap / std::cos(pi / 8) * (1 + 1e-3));
      EXPECT_LT(*std::max_element(r.ball_approach.begin(), r.ball_approach.end()), 1e-3 * gap);
    }
  }
}

TEST(StaticLoad, HugeLoadConverges) {
  for (double gap : {0.0, 10e-6}) {
    const Eigen::Vector2d F = polar(1e9, -1.0);
    const StaticLoadResult r = solve_static_load(8, K6308, gap, F);
    expect_consistent(r, 8, K6308, gap, F, 1.5, 1e-12, "huge load");
  }
}

// Rotating the load and the ball set together rotates the solution.
TEST(StaticLoad, RotatingLoadAndBallsRotatesSolution) {
  const double gap = 4e-6;
  for (double Fm : {1e-3, 50.0, 3000.0}) {
    StaticLoadOptions base;
    base.phase = 0.2;
    const Eigen::Vector2d F = polar(Fm, -1.1);
    const StaticLoadResult r0 = solve_static_load(9, K6308, gap, F, base);
    for (double phi : {0.7, 2.0, -2.9}) {
      StaticLoadOptions o = base;
      o.phase += phi;
      const Eigen::Rotation2Dd R(phi);
      const StaticLoadResult r = solve_static_load(9, K6308, gap, R * F, o);
      EXPECT_NEAR((r.deflection - R * r0.deflection).norm() / r0.deflection.norm(), 0.0, 1e-12);
      for (int j = 0; j < 9; ++j) {
        EXPECT_NEAR(r.ball_loads[j], r0.ball_loads[j], 1e-11 * Fm) << Fm << " " << phi << " " << j;
      }
    }
  }
}

TEST(StaticLoad, RejectsInvalidInput) {
  const Eigen::Vector2d F(0, -100);
  EXPECT_THROW(solve_static_load(2, K6308, 0, F), InputError);
  EXPECT_THROW(solve_static_load(8, 0.0, 0, F), InputError);
  EXPECT_THROW(solve_static_load(8, -1.0, 0, F), InputError);
  EXPECT_THROW(solve_static_load(8, K6308, -1e-6, F), InputError);
  EXPECT_THROW(solve_static_load(8, K6308, 0, Eigen::Vector2d(NAN, 1)), InputError);
  EXPECT_THROW(solve_static_load(8, K6308, 0, Eigen::Vector2d(INFINITY, 1)), InputError);
  StaticLoadOptions o;
  o.exponent = 0.5;
  EXPECT_THROW(solve_static_load(8, K6308, 0, F, o), InputError);
  o = {};
  o.tolerance = 0;
  EXPECT_THROW(solve_static_load(8, K6308, 0, F, o), InputError);
  o = {};
  o.max_iterations = 0;
  EXPECT_THROW(solve_static_load(8, K6308, 0, F, o), InputError);
}

TEST(StaticLoad, ReportsWhyItStopped) {
  // One Newton iteration is not enough for an off-symmetric load with clearance.
  StaticLoadOptions o;
  o.max_iterations = 1;
  o.phase = 0.1;
  try {
    const StaticLoadResult r = solve_static_load(5, K6308, 5e-6, polar(800, 2.0), o);
    ADD_FAILURE() << "expected SolverError, got residual " << r.residual;
  } catch (const SolverError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("after 1 Newton iteration"), std::string::npos) << msg;
    EXPECT_NE(msg.find("residual"), std::string::npos) << msg;
  }
}

}  // namespace
}  // namespace bearing
