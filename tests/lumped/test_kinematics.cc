// Bearing defect frequencies (kinematics.h, docs/model.md §2).

#include <gtest/gtest.h>

#include <cmath>

#include "bearing/bearing.h"
#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/kinematics.h"
#include "bearing/presets.h"

namespace bearing {
namespace {

double rpm(double n) {
  return two_pi * n / 60;
}

// The 6308 of seed 003 Table 1 (conformity 0.52 and steel assumed; see presets.cc).
Bearing bearing_6308() {
  return preset("6308");
}

// Seed 003 (003_790048304106e649.txt) Table 2, 6308 at 2000 r/min: f_bs 70.0 Hz, f_c 12.8 Hz,
// f_bpo 102.4 Hz, f_bpi 164.3 Hz, printed to 0.1 Hz.
TEST(Kinematics, Seed003Table2For6308At2000Rpm) {
  const BearingFrequencies f = bearing_frequencies(bearing_6308(), rpm(2000));
  EXPECT_NEAR(f.shaft, 2000.0 / 60, 1e-12);
  EXPECT_NEAR(f.ftf, 12.8, 0.05);
  EXPECT_NEAR(f.bpfo, 102.4, 0.05);
  EXPECT_NEAR(f.bpfi, 164.3, 0.05);
  // Ball spin: (d_m / 2D) f_i (1 − (D/d_m)²) = 67.97 Hz. The paper's 70.0 Hz matches neither BSF
  // (3 % off) nor 2·BSF = 135.9 Hz (the ball-defect frequency); it is reported, not reproduced.
  EXPECT_NEAR(f.bsf, 67.97, 0.005);
  EXPECT_GT(std::abs(f.bsf - 70.0), 0.05);
  EXPECT_GT(std::abs(2 * f.bsf - 70.0), 0.05);
}

TEST(Kinematics, CageSpeedFormula) {
  Bearing b = bearing_6308();
  b.contact_angle = 15 * pi / 180;
  const double g = b.ball_diameter * std::cos(b.contact_angle) / b.pitch_diameter;
  EXPECT_NEAR(cage_speed(b, 100.0), 50.0 * (1 - g), 1e-12);
  EXPECT_NEAR(cage_speed(b, 100.0, 40.0), 50.0 * (1 - g) + 20.0 * (1 + g), 1e-12);
  EXPECT_NEAR(cage_speed(b, 0.0, 40.0), 20.0 * (1 + g), 1e-12);
}

TEST(Kinematics, BallPassFrequenciesAddUpToZTimesShaft) {
  for (double slip : {0.0, 0.02, 0.3}) {
    for (double n : {300.0, 2000.0, 12000.0}) {
      const BearingFrequencies f = bearing_frequencies(bearing_6308(), rpm(n), 0.0, slip);
      EXPECT_NEAR((f.bpfo + f.bpfi) / (8 * f.shaft), 1.0, 1e-14) << n << " rpm, slip " << slip;
    }
  }
}

TEST(Kinematics, CageSlipScalesCageDrivenFrequencies) {
  const Bearing b = bearing_6308();
  const BearingFrequencies f0 = bearing_frequencies(b, rpm(2000));
  for (double s : {0.01, 0.05, 0.2}) {
    const BearingFrequencies f = bearing_frequencies(b, rpm(2000), 0.0, s);
    EXPECT_NEAR(f.ftf, (1 - s) * f0.ftf, 1e-12);
    EXPECT_NEAR(f.bpfo, (1 - s) * f0.bpfo, 1e-12);
    EXPECT_NEAR(f.bsf, (1 - s) * f0.bsf, 1e-12);  // rolling on the (fixed) outer race
    EXPECT_NEAR(f.bpfi, 8 * (f.shaft - f.ftf), 1e-12);
    EXPECT_NEAR(f.shaft, f0.shaft, 0.0);
  }
  EXPECT_THROW(bearing_frequencies(b, rpm(2000), 0.0, -0.1), InputError);
  EXPECT_THROW(bearing_frequencies(b, rpm(2000), 0.0, 1.0), InputError);
  EXPECT_THROW(bearing_frequencies(b, NAN), InputError);
}

// Inner ring fixed, outer ring turning at Ω: the cage turns at ½ Ω (1 + g), a ball passes a
// point of the outer race at Z |f_c − f_o| = Z f_o (1 − g)/2 and of the inner race at Z f_c.
TEST(Kinematics, OuterRingRotation) {
  const Bearing b = bearing_6308();
  const double g = b.ball_diameter / b.pitch_diameter;
  const double Omega = rpm(1500), fo = 1500.0 / 60;
  const BearingFrequencies f = bearing_frequencies(b, 0.0, Omega);
  EXPECT_NEAR(f.shaft, fo, 1e-12);
  EXPECT_NEAR(f.ftf, 0.5 * fo * (1 + g), 1e-12);
  EXPECT_NEAR(f.bpfo, 8 * 0.5 * fo * (1 - g), 1e-12);
  EXPECT_NEAR(f.bpfi, 8 * 0.5 * fo * (1 + g), 1e-12);
  EXPECT_NEAR(f.bsf, b.pitch_diameter / (2 * b.ball_diameter) * fo * (1 - g * g), 1e-12);
  EXPECT_NEAR(f.bpfo + f.bpfi, 8 * f.shaft, 1e-12);
}

// Only the relative speed of the rings matters for what the races see: adding a common rotation
// Ω leaves BPFO, BPFI, BSF and the shaft frequency unchanged and moves the cage by Ω/2π.
TEST(Kinematics, CommonRotationOnlyShiftsTheCage) {
  const Bearing b = bearing_6308();
  const BearingFrequencies f0 = bearing_frequencies(b, rpm(2000));
  const double Omega = rpm(700);
  const BearingFrequencies f = bearing_frequencies(b, rpm(2000) + Omega, Omega);
  EXPECT_NEAR(f.shaft, f0.shaft, 1e-11);
  EXPECT_NEAR(f.bpfo, f0.bpfo, 1e-11);
  EXPECT_NEAR(f.bpfi, f0.bpfi, 1e-11);
  EXPECT_NEAR(f.bsf, f0.bsf, 1e-11);
  EXPECT_NEAR(f.ftf, f0.ftf + 700.0 / 60, 1e-11);
}

}  // namespace
}  // namespace bearing
