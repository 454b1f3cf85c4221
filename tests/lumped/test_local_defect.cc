// The geometry of a spall (local_defect.h) against its limits and an independent construction.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "bearing/errors.h"
#include "bearing/local_defect.h"

namespace bearing {
namespace {

// The 6205 (CWRU's bearing): D = 7.938 mm, d_m = 39.04 mm.
constexpr double kD = 7.938e-3, kR = kD / 2;
constexpr double kInner = (39.04e-3 - kD) / 2, kOuter = (39.04e-3 + kD) / 2;

// Independent construction: the ball centre on the slot's bisector at the distance from the race
// centre where it touches both edge points (bisection on the distance), against its distance on
// the intact race.
double construct_drop(Race race, double rho, double w) {
  const double phi = w / (2 * rho), ex = rho * std::cos(phi), ey = rho * std::sin(phi);
  const double nominal = race == Race::inner ? rho + kR : rho - kR;
  // |centre − edge| = R has two roots on the bisector, ex ± √(R² − ey²): the ball outside the
  // inner race, inside the outer one; bracket that one and bisect on the sign change.
  double lo = race == Race::inner ? ex : rho - 2 * kR;
  double hi = race == Race::inner ? rho + 2 * kR : ex;
  auto f = [&](double c) { return std::hypot(c - ex, ey) - kR; };
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    ((f(mid) > 0) == (f(lo) > 0) ? lo : hi) = mid;
  }
  const double c = 0.5 * (lo + hi);
  return race == Race::inner ? nominal - c : c - nominal;
}

TEST(LocalDefect, TheDropMatchesTheConstructedBallPosition) {
  for (double w : {0.1e-3, 0.53e-3, 2e-3, 5e-3}) {
    EXPECT_NEAR(defect_max_drop(kD, Race::inner, kInner, w, 1.0),
                construct_drop(Race::inner, kInner, w), 1e-14)
        << w;
    EXPECT_NEAR(defect_max_drop(kD, Race::outer, kOuter, w, 1.0),
                construct_drop(Race::outer, kOuter, w), 1e-14)
        << w;
  }
}

TEST(LocalDefect, ANarrowSlotGivesTheSagsAndVanishesWithItsWidth) {
  // (w²/8)(1/R ± 1/ρ) for w ≪ R: the ball's sag plus (inner) or minus (outer) the race's.
  for (double w : {1e-4, 1e-5}) {
    const double inner = w * w / 8 * (1 / kR + 1 / kInner);
    const double outer = w * w / 8 * (1 / kR - 1 / kOuter);
    EXPECT_NEAR(defect_max_drop(kD, Race::inner, kInner, w, 1.0), inner, 2e-3 * inner) << w;
    EXPECT_NEAR(defect_max_drop(kD, Race::outer, kOuter, w, 1.0), outer, 2e-3 * outer) << w;
  }
  EXPECT_EQ(defect_max_drop(kD, Race::outer, kOuter, 0.0, 1e-3), 0.0);
  // A flat race (ρ → ∞): the chord sag R − √(R² − w²/4) of the model.
  const double w = 0.53e-3;
  EXPECT_NEAR(defect_max_drop(kD, Race::outer, 1e6, w, 1.0), kR - std::sqrt(kR * kR - w * w / 4),
              1e-12);
}

TEST(LocalDefect, AWideDeepSlotGivesTheFullDepth) {
  EXPECT_EQ(defect_max_drop(kD, Race::outer, kOuter, 2 * kD, 50e-6), 50e-6);  // wider than the ball
  EXPECT_EQ(defect_max_drop(kD, Race::inner, kInner, 0.5 * kD, 10e-6), 10e-6);  // floor reached
}

TEST(LocalDefect, TheDropAlongTheSlotIsContinuousSymmetricAndPeaksMidway) {
  const double w = 1e-3, h = 1.0;
  for (double u : {-1e-4, 0.0, w, 2 * w})
    EXPECT_EQ(defect_drop(kD, Race::outer, kOuter, w, h, u), 0.0);
  double previous = 0;
  for (int i = 1; i <= 50; ++i) {
    const double u = w * i / 100.0, d = defect_drop(kD, Race::outer, kOuter, w, h, u);
    EXPECT_GE(d, previous);
    EXPECT_NEAR(d, defect_drop(kD, Race::outer, kOuter, w, h, w - u), 1e-18);
    previous = d;
  }
  EXPECT_DOUBLE_EQ(previous, defect_max_drop(kD, Race::outer, kOuter, w, h));
  EXPECT_EQ(defect_drop(kD, Race::inner, kInner, w, 5e-6, 0.4 * w), 5e-6);  // flat at the floor
}

TEST(LocalDefect, RejectsBadSizesNamingTheField) {
  try {
    defect_max_drop(kD, Race::outer, kOuter, -1e-3, 1e-5);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("defects.width"), std::string::npos);
  }
  EXPECT_THROW(defect_max_drop(kD, Race::outer, kOuter, 1e-3, NAN), InputError);
  EXPECT_THROW(defect_drop(kD, Race::outer, 1e-3, 1e-3, 1e-5, 0), InputError);  // race < ball
}

}  // namespace
}  // namespace bearing
