// Sliding speeds and traction of seed 004 (traction.h), against independent references: the
// ball spin frequency of kinematics.h, the closed forms with slip, the surface speeds of seed
// 004's eqs. 4–6 (power balance of the forces), and the traction curve's shape.

#include <gtest/gtest.h>

#include <cmath>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/kinematics.h"
#include "bearing/presets.h"
#include "bearing/traction.h"

namespace {

using namespace bearing;

Bearing bearing_with_angle(const char* name, double alpha) {
  Bearing b = preset(name);
  b.contact_angle = alpha;
  return b;
}

// Pure rolling: with the kinematic cage speed and the rolling spin, nothing slides, for radial
// and angular-contact geometry; and the rolling spin is 2π·BSF of kinematics.h (÷ cos α).
TEST(Traction, NothingSlidesAtPureRolling) {
  for (const char* name : {"6304", "608", "6308"})
    for (double alpha : {0.0, 0.3}) {
      const Bearing b = bearing_with_angle(name, alpha);
      const double w = 2000 * two_pi / 60;
      const double spin = rolling_ball_spin(b, w);
      const SlidingSpeeds s = sliding_speeds(b, w, cage_speed(b, w), spin);
      const double scale = 0.5 * w * b.pitch_diameter;  // the inner race's surface speed, about
      EXPECT_NEAR(s.inner / scale, 0.0, 1e-14) << name << " " << alpha;
      EXPECT_NEAR(s.outer / scale, 0.0, 1e-14) << name << " " << alpha;
      // kinematics.h's BSF spins about an axis normal to the contact line (lever arm D/2),
      // seed 004 about one parallel to the bearing axis (lever arm (D/2) cos α).
      EXPECT_NEAR(spin * std::cos(alpha), two_pi * bearing_frequencies(b, w).bsf, 1e-12 * spin)
          << name;
    }
}

// With the rolling spin and a cage slip s_c: Δv_i = ½ s_c ω_c d_m (1 − g), Δv_o = −½ s_c ω_c
// d_m (1 + g) — the inner race drives, the outer holds back.
TEST(Traction, SlipMakesTheInnerRaceDriveAndTheOuterRaceBrake) {
  const Bearing b = preset("6304");
  const double w = 2000 * two_pi / 60, wc = cage_speed(b, w);
  const double g = b.ball_diameter * std::cos(b.contact_angle) / b.pitch_diameter;
  for (double slip : {0.0, 0.02, 0.05}) {
    const SlidingSpeeds s = sliding_speeds(b, w, (1 - slip) * wc, rolling_ball_spin(b, w));
    EXPECT_NEAR(s.inner, 0.5 * slip * wc * b.pitch_diameter * (1 - g), 1e-12);
    EXPECT_NEAR(s.outer, -0.5 * slip * wc * b.pitch_diameter * (1 + g), 1e-12);
    if (slip > 0) {
      EXPECT_GT(s.inner, 0);
      EXPECT_LT(s.outer, 0);
    }
  }
}

TEST(Traction, CurveIsOddLinearThenSaturated) {
  const TractionCurve c = make_traction_curve(0.05, 0.2);
  EXPECT_EQ(c.coefficient(0.0), 0.0);
  EXPECT_DOUBLE_EQ(c.coefficient(0.1), 0.025);
  EXPECT_DOUBLE_EQ(c.coefficient(-0.1), -0.025);
  EXPECT_DOUBLE_EQ(c.coefficient(0.2), 0.05);  // continuous at Δv_m
  EXPECT_DOUBLE_EQ(c.coefficient(3.0), 0.05);
  EXPECT_DOUBLE_EQ(c.coefficient(-3.0), -0.05);
}

// The forces' power, computed from the surface speeds of seed 004's eqs. 4–6 written out here,
// is minus the dissipated power, and the dissipated power is non-negative: the directions of
// traction.h are those of friction (it never feeds energy in).
TEST(Traction, ForcesDissipateExactlyTheReportedPower) {
  const Bearing b = preset("6304");
  const double w = 2000 * two_pi / 60, wc = cage_speed(b, w);
  const double g = b.ball_diameter * std::cos(b.contact_angle) / b.pitch_diameter;
  const double half_d = 0.5 * b.ball_diameter * std::cos(b.contact_angle);
  const TractionCurve curve = make_traction_curve(0.01, 0.05);
  for (double slip : {0.0, 0.01, 0.05})
    for (double spin_factor : {0.9, 1.0, 1.1}) {
      const double wca = (1 - slip) * wc, wb = spin_factor * rolling_ball_spin(b, w);
      const double v_ii = 0.5 * w * b.pitch_diameter * (1 - g);
      const double v_ib = 0.5 * wca * b.pitch_diameter * (1 - g) + wb * half_d;
      const double v_ob = 0.5 * wca * b.pitch_diameter * (1 + g) - wb * half_d;
      const ContactTraction t =
          contact_traction(curve, sliding_speeds(b, w, wca, wb), 800.0, 950.0);
      const double input = t.on_ball_inner * v_ib + t.on_inner_race * v_ii +
                           t.on_ball_outer * v_ob;  // the outer race does not move
      EXPECT_NEAR(input, -t.power, 1e-12 * (1 + std::abs(t.power)));
      EXPECT_GE(t.power, 0.0);
      EXPECT_DOUBLE_EQ(t.on_inner_race, -t.on_ball_inner);
    }
}

TEST(Traction, RejectsBadCurvesAndLoadsNamingTheField) {
  try {
    make_traction_curve(-0.1, 0.1);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cage.friction"), std::string::npos) << e.what();
  }
  try {
    make_traction_curve(0.1, 0.0);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cage.slide_speed"), std::string::npos) << e.what();
  }
  EXPECT_THROW(contact_traction(make_traction_curve(0.1, 0.1), {}, -1.0, 0.0), InputError);
  EXPECT_THROW(sliding_speeds(preset("6304"), NAN, 0, 0), InputError);
}

}  // namespace
