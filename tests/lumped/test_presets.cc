#include <cmath>

#include <gtest/gtest.h>

#include "bearing/errors.h"
#include "bearing/kinematics.h"
#include "bearing/presets.h"

using bearing::preset;

TEST(Presets, EveryPresetLoadsValidatesAndNamesItsSource) {
  for (const auto& name : bearing::preset_names()) {
    const bearing::Bearing b = preset(name);
    EXPECT_EQ(b.designation, name);
    EXPECT_NO_THROW(b.validate()) << name;
    EXPECT_FALSE(bearing::preset_source(name).empty()) << name;
  }
}

TEST(Presets, Seed000Bearing608) {
  const auto b = preset("608");
  EXPECT_EQ(b.balls, 7);
  EXPECT_DOUBLE_EQ(b.ball_diameter, 3.969e-3);
  EXPECT_NEAR(b.pitch_diameter, 15.55e-3, 1e-12);
  EXPECT_NEAR(b.inner_conformity * b.ball_diameter, 2.044e-3, 1e-12);  // groove radius r_i
  EXPECT_NEAR(b.outer_conformity * b.ball_diameter, 2.084e-3, 1e-12);
  EXPECT_NEAR(b.clearance, 5e-6, 1e-15);
}

TEST(Presets, Seed003Bearing6308HasItsRacewaysPutRight) {
  const auto b = preset("6308");
  EXPECT_EQ(b.balls, 8);
  // Seed 003 Table 1 prints inner 80.088 mm, outer 49.912 mm: swapped. The smaller one is inner.
  EXPECT_LT(b.inner_raceway_diameter(), b.outer_raceway_diameter());
  // With the clearance split evenly, the groove bottoms sit P_d/2 beyond d_m -/+ D.
  EXPECT_NEAR(b.inner_raceway_diameter() - b.clearance / 2, 49.912e-3, 1e-9);
  EXPECT_NEAR(b.outer_raceway_diameter() + b.clearance / 2, 80.088e-3, 1e-9);
  EXPECT_NEAR(b.clearance, 14e-6, 1e-12);
}

TEST(Presets, Seed004Bearing6304) {
  const auto b = preset("6304");
  EXPECT_EQ(b.balls, 7);
  EXPECT_DOUBLE_EQ(b.ball_diameter, 9.525e-3);
  EXPECT_DOUBLE_EQ(b.pitch_diameter, 36e-3);
  EXPECT_NEAR(b.clearance, 15e-6, 1e-15);
  EXPECT_DOUBLE_EQ(b.ball.young, 2.07e11);
  EXPECT_DOUBLE_EQ(b.rings.poisson, 0.3);
}

// The CWRU fan-end bearing: the data set's geometry and the defect frequencies that follow from it
// (multiples of the shaft speed, contact angle 0). The data set prints BPFI 4.9469 (the same to
// its digits), BPFO 3.0530, FTF 0.3817 and 2·BSF 3.9900, which differ from its own geometry's by
// 0.004 %, 0.016 % and 0.06 %: its rounding, not this preset's (presets.cc).
TEST(Presets, CwruFanEndBearing6203) {
  const auto b = preset("6203");
  EXPECT_EQ(b.balls, 8);
  EXPECT_NEAR(b.ball_diameter, 6.74624e-3, 1e-12);
  EXPECT_NEAR(b.pitch_diameter, 28.4988e-3, 1e-12);
  EXPECT_NEAR(b.clearance, 10.5e-6, 1e-15);
  const bearing::BearingFrequencies f = bearing::bearing_frequencies(b, 2 * M_PI);  // f_r = 1 Hz
  const double r = 0.2656 / 1.122;  // D / d_m
  EXPECT_NEAR(f.shaft, 1.0, 1e-12);
  EXPECT_NEAR(f.bpfi, 4 * (1 + r), 1e-12);
  EXPECT_NEAR(f.bpfi, 4.9469, 0.5e-4);  // the data set's, to its printed digits
  EXPECT_NEAR(f.bpfo, 4 * (1 - r), 1e-12);
  EXPECT_NEAR(f.ftf, 0.5 * (1 - r), 1e-12);
  EXPECT_NEAR(2 * f.bsf, (1 - r * r) / r, 1e-12);
}

TEST(Presets, HarrisBearing209) {
  const auto b = preset("209");
  EXPECT_EQ(b.balls, 9);
  EXPECT_NEAR(b.pitch_diameter, 65e-3, 2e-6);
  EXPECT_NEAR(b.clearance, 15e-6, 1e-9);
}

TEST(Presets, UnknownDesignationListsTheKnownOnes) {
  try {
    preset("6309");
    FAIL();
  } catch (const bearing::InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("bearing.preset"), std::string::npos);
    EXPECT_NE(m.find("6309"), std::string::npos);
    EXPECT_NE(m.find("6308"), std::string::npos);
  }
}
