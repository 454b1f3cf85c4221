// A ball's radial motion on the outer race (lumped/src/models/ball_motion.h): r = δ_o − Π_o +
// ΔD/2 with δ_o = (Q/K_o)^{1/n_o}, and its rate, checked against the closed-form derivative for
// a load, an outer-race stiffness and a profile that change linearly in time (the rates TVDS and
// waviness give), and against the centred difference of r.

#include <cmath>

#include <gtest/gtest.h>

#include "../../lumped/src/models/ball_motion.h"

namespace {

struct Linear {
  double at0, rate;
  double operator()(double t) const { return at0 + rate * t; }
};

// r(t) from ball_motion.h at time t, for ball 3 of a set whose other entries are unused.
void motion(const Linear& Q, const Linear& Ko, const Linear& profile, double n, double t, double& r,
            double& vr) {
  bearing::detail::BallRates br{};
  const int j = 3;
  br.outer_stiffness[j] = Ko(t);
  br.outer_stiffness_rate[j] = Ko.rate;
  br.outer_profile[j] = profile(t);
  br.outer_profile_rate[j] = profile.rate;
  bearing::detail::outer_ball_motion(Q(t), Q.rate, br, j, n, 2e-6, r, vr);
}

}  // namespace

TEST(OuterBallMotion, RateFollowsTheLoadTheStiffnessAndTheProfile) {
  const double n = 1.5;
  // 400 N rising at 2e4 N/s on K_o = 8e9 N/m^1.5 falling at 3e10 N/(m^1.5 s) (TVDS), a profile
  // of 1 µm moving at 2 mm/s: each of the three rates moves vr by a comparable amount.
  const Linear Q{400.0, 2e4}, Ko{8e9, -3e10}, profile{1e-6, 2e-3};
  double r = 0, vr = 0;
  motion(Q, Ko, profile, n, 0.0, r, vr);
  const double d = std::pow(Q.at0 / Ko.at0, 1 / n);
  EXPECT_NEAR(r, d - profile.at0 + 1e-6, 1e-12 * d);
  const double closed = d / n * (Q.rate / Q.at0 - Ko.rate / Ko.at0) - profile.rate;
  EXPECT_NEAR(vr, closed, 1e-12 * std::abs(closed));
  // The same from r's centred difference (step 1 µs: truncation ~(1e-6 · rates)^2 ~ 1e-8).
  const double h = 1e-6;
  double rp = 0, rm = 0, unused = 0;
  motion(Q, Ko, profile, n, h, rp, unused);
  motion(Q, Ko, profile, n, -h, rm, unused);
  EXPECT_NEAR(vr, (rp - rm) / (2 * h), 1e-6 * std::abs(closed));
  // Each term's sign matters: the stiffness rate alone (no load rate, no profile rate).
  const Linear still{400.0, 0.0}, fixed{1e-6, 0.0};
  motion(still, Ko, fixed, n, 0.0, r, vr);
  EXPECT_NEAR(vr, -d / n * Ko.rate / Ko.at0, 1e-12 * std::abs(d / n * Ko.rate / Ko.at0));
  EXPECT_GT(vr, 0.0) << "a softening outer contact lets the ball move outwards";
}

TEST(OuterBallMotion, AnUnloadedBallSitsOnTheProfile) {
  double r = 0, vr = 0;
  motion(Linear{0.0, 0.0}, Linear{8e9, -3e10}, Linear{1e-6, 2e-3}, 1.5, 0.0, r, vr);
  EXPECT_DOUBLE_EQ(r, -1e-6 + 1e-6);
  EXPECT_DOUBLE_EQ(vr, -2e-3);
}
