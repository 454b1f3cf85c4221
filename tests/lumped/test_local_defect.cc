// The geometry of a spall (local_defect.h) against its limits and an independent construction.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/kinematics.h"
#include "bearing/local_defect.h"
#include "bearing/presets.h"

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

// Independent construction for a ball defect: the ball at the origin, the slot's edges at
// (R cos φ, ±R sin φ), φ = w/2R. The inner race (convex, radius ρ) has its centre at (c, 0) beyond
// the ball, c = R + ρ on the intact ball; the outer race (concave) at (−c, 0), c = ρ − R intact.
// Resting on both edges, |centre − edge| = ρ: bisection on c, and the race surface's advance
// toward the ball centre against the intact ball.
double construct_ball_drop(Race race, double rho, double w) {
  const double phi = w / (2 * kR), ex = kR * std::cos(phi), ey = kR * std::sin(phi);
  const double sign = race == Race::inner ? 1.0 : -1.0;
  auto f = [&](double c) { return std::hypot(sign * c - ex, ey) - rho; };  // < 0 at lo, > 0 at hi
  double lo = race == Race::inner ? ex : rho - 2 * kR, hi = race == Race::inner ? kR + rho : rho;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0 ? lo : hi) = mid;
  }
  const double c = 0.5 * (lo + hi);
  return race == Race::inner ? (kR + rho) - c : c - (rho - kR);
}

LocalDefect spall(DefectLocation where, double width, double depth,
                  DefectProfile profile = DefectProfile::rectangular) {
  LocalDefect d;
  d.location = where;
  d.width = width;
  d.depth = depth;
  d.profile = profile;
  return d;
}

TEST(LocalDefect, ABallDefectMatchesTheConstructedRacePosition) {
  const Bearing b = preset("6205");
  ASSERT_NEAR(b.ball_diameter, kD, 1e-5);
  const double R = 0.5 * b.ball_diameter, ri = 0.5 * b.inner_raceway_diameter(),
               ro = 0.5 * b.outer_raceway_diameter();
  for (double w : {0.1e-3, 0.53e-3, 2e-3, 5e-3}) {
    const LocalDefect d = spall(DefectLocation::ball, w, 1.0e-3);
    const DefectPath inner(b, d, Race::inner), outer(b, d, Race::outer);
    // The construction with this bearing's radii (kR differs from R by the preset's rounding).
    const double phi = w / (2 * R), a = R * std::sin(phi);
    const double inner_expected = R * (1 - std::cos(phi)) + ri - std::sqrt(ri * ri - a * a);
    const double outer_expected = R * (1 - std::cos(phi)) - (ro - std::sqrt(ro * ro - a * a));
    EXPECT_NEAR(inner.max_drop(), std::min(inner_expected, 1.0e-3), 1e-15) << w;
    EXPECT_NEAR(outer.max_drop(), std::min(outer_expected, 1.0e-3), 1e-15) << w;
  }
  // and against the bisection construction at kR (the test's own 6205 radii)
  for (double w : {0.1e-3, 0.53e-3, 2e-3}) {
    const double phi = w / (2 * kR), a = kR * std::sin(phi);
    EXPECT_NEAR(construct_ball_drop(Race::inner, kInner, w),
                kR * (1 - std::cos(phi)) + kInner - std::sqrt(kInner * kInner - a * a), 1e-14);
    EXPECT_NEAR(construct_ball_drop(Race::outer, kOuter, w),
                kR * (1 - std::cos(phi)) - (kOuter - std::sqrt(kOuter * kOuter - a * a)), 1e-14);
  }
  // Narrow: the same relative sag (w²/8)(1/R ± 1/ρ) as a race defect of that width.
  const double w = 1e-5;
  const LocalDefect d = spall(DefectLocation::ball, w, 1.5e-3);
  EXPECT_NEAR(DefectPath(b, d, Race::inner).max_drop(), w * w / 8 * (1 / R + 1 / ri),
              1e-3 * w * w / 8 / R);
  EXPECT_NEAR(DefectPath(b, d, Race::outer).max_drop(), w * w / 8 * (1 / R - 1 / ro),
              1e-3 * w * w / 8 / R);
}

TEST(LocalDefect, TheSmoothProfileIsAHalfSineOfTheSameDepth) {
  const Bearing b = preset("6205");
  const double w = 0.8e-3;
  const LocalDefect sharp = spall(DefectLocation::outer, w, 20e-6);
  const LocalDefect round = spall(DefectLocation::outer, w, 20e-6, DefectProfile::smooth);
  const DefectPath ps(b, sharp, Race::outer), pr(b, round, Race::outer);
  EXPECT_EQ(pr.max_drop(), ps.max_drop());
  for (double f : {0.1, 0.25, 0.5, 0.9})
    EXPECT_NEAR(pr.drop(f * w), ps.max_drop() * std::sin(pi * f), 1e-18) << f;
  EXPECT_EQ(pr.drop(0.0), 0.0);
  EXPECT_EQ(pr.drop(w), 0.0);
}

TEST(LocalDefect, TheSlopeIsTheDropsDerivative) {
  const Bearing b = preset("6205");
  struct Case {
    LocalDefect d;
    Race contact;
  };
  const std::vector<Case> cases{
      {spall(DefectLocation::outer, 0.53e-3, 1.5e-3), Race::outer},
      {spall(DefectLocation::inner, 0.53e-3, 1.5e-3), Race::inner},
      {spall(DefectLocation::inner, 2e-3, 3e-6), Race::inner},  // floor reached: flat middle
      {spall(DefectLocation::ball, 1e-3, 1.5e-3), Race::inner},
      {spall(DefectLocation::ball, 1e-3, 1.5e-3), Race::outer},
      {spall(DefectLocation::outer, 0.53e-3, 1.5e-3, DefectProfile::smooth), Race::outer}};
  for (const Case& c : cases) {
    const DefectPath p(b, c.d, c.contact);
    const double w = c.d.width, h = 1e-7 * w;
    for (double f : {0.05, 0.2, 0.37, 0.61, 0.8, 0.95}) {
      const double u = f * w;
      const double fd = (p.drop(u + h) - p.drop(u - h)) / (2 * h);
      EXPECT_NEAR(p.slope(u), fd, 1e-6 * std::max(1e-3, std::abs(fd)))
          << name_of(kDefectLocations, c.d.location) << " f " << f;
    }
  }
}

TEST(LocalDefect, TransitTimesFollowTheDefectFrequencies) {
  // A ball covers one ball spacing of a race (2πρ/Z) per ball pass, and the ball's circumference
  // πD per ball revolution (1/BSF): the crossing of a width w takes w/(that length × frequency).
  const Bearing b = preset("6205");
  const double wi = 1797 * two_pi / 60, wc = cage_speed(b, wi);
  const BearingFrequencies f = bearing_frequencies(b, wi);
  const double w = 0.53e-3, Z = b.balls;
  const double ro = 0.5 * b.outer_raceway_diameter(), ri = 0.5 * b.inner_raceway_diameter();
  EXPECT_NEAR(defect_transit_time(spall(DefectLocation::outer, w, 1e-4), b, wi, wc, 0.0),
              w / (two_pi * ro / Z * f.bpfo), 1e-15);
  EXPECT_NEAR(defect_transit_time(spall(DefectLocation::inner, w, 1e-4), b, wi, wc, 0.0),
              w / (two_pi * ri / Z * f.bpfi), 1e-15);
  EXPECT_NEAR(defect_transit_time(spall(DefectLocation::ball, w, 1e-4), b, wi, wc, 0.0),
              w / (pi * b.ball_diameter * f.bsf), 1e-15);
  EXPECT_NEAR(ball_spin_speed(b, wc, 0.0), two_pi * f.bsf, 1e-9);
  EXPECT_TRUE(std::isinf(defect_transit_time(spall(DefectLocation::outer, w, 1e-4), b, 0, 0, 0)));
}

TEST(LocalDefect, CheckDefectsNamesTheEntryFieldAndRange) {
  const Bearing b = preset("6205");
  const auto message = [&](LocalDefect d) {
    try {
      check_defects({spall(DefectLocation::outer, 1e-3, 1e-4), d}, b);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(spall(DefectLocation::outer, 9e-3, 1e-4))
                .find("defects[1].width = 9 mm: must "
                      "lie in (0, D = 7.94004 mm]"),
            std::string::npos)
      << message(spall(DefectLocation::outer, 9e-3, 1e-4));
  EXPECT_NE(message(spall(DefectLocation::inner, 1e-3, 0.0)).find("defects[1].depth = 0 mm"),
            std::string::npos);
  LocalDefect ball = spall(DefectLocation::ball, 1e-3, 1e-4);
  ball.ball = 9;
  EXPECT_NE(message(ball).find("defects[1].ball = 9: must lie in [0, 8]"), std::string::npos)
      << message(ball);
  LocalDefect nan_position = spall(DefectLocation::outer, 1e-3, 1e-4);
  nan_position.position = NAN;
  EXPECT_NE(message(nan_position).find("defects[1].position"), std::string::npos);
  EXPECT_EQ(message(spall(DefectLocation::outer, 1e-3, 1e-4)), "no error");
}

}  // namespace
}  // namespace bearing
