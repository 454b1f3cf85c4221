// The bearing's coefficients for a rotor model (rotor_coefficients.h, issue 43 item 6): K averaged
// over one ball pass, against the arithmetic mean of direct solves at the same cage angles, and the
// warnings when that mean is singular or near it (a load in the clearance, a block with a tiny
// smallest eigenvalue), and not for the examples' loads.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bearing/case_file.h"
#include "bearing/five_dof_static.h"
#include "bearing/rotor_coefficients.h"
#include "bearing/stiffness.h"

namespace {

using bearing::Matrix5;

const std::string kExample = std::string(BEARING_SOURCE_DIR) + "/examples/seed003_6308.toml";

bearing::Case example(const std::vector<std::string>& sets = {}) {
  std::vector<bearing::Override> overrides;
  for (const auto& s : sets) overrides.push_back(bearing::parse_override(s));
  return bearing::read_case_file(kExample, overrides);
}

// The mean of K over N cage angles through one pitch from the library's own pieces, not through
// the pipeline: each angle solved on its own (the example's cage phase is 0), summed, then
// divided once (another order of the sums than ball_pass_mean's).
Matrix5 direct_mean(const bearing::Case& c, int N) {
  const bearing::FiveDofBearing b0 =
      bearing::five_dof_bearing(c.bearing, bearing::contact_constants(c), 0.0,
                                bearing::ball_centrifugal_load(c.bearing, c.operation.speed));
  bearing::Vector5 f;
  f << c.operation.load.x(), c.operation.load.y(), c.operation.axial_load, c.operation.moment.x(),
      c.operation.moment.y();
  Matrix5 sum = Matrix5::Zero();
  for (int k = 0; k < N; ++k) {
    bearing::FiveDofBearing b = b0;
    b.phase = 2 * M_PI / b.balls * k / N;
    sum += bearing::solve_five_dof(b, f).at.stiffness;
  }
  return sum / N;
}

bool contains(const std::vector<std::string>& lines, const std::string& s) {
  for (const auto& l : lines)
    if (l.find(s) != std::string::npos) return true;
  return false;
}

// Seed 003's 6308 under 20 N in its clearance: one ball right under the load at the case's cage
// angle, so K there has no k_xx; the rotor's K is the mean over the pitch, the direct solves'
// arithmetic mean to round-off, and it does support the ring sideways.
TEST(RotorCoefficients, StiffnessIsTheArithmeticMeanOverTheBallPass) {
  const bearing::Case c = example();
  const int N = 16;
  const bearing::StiffnessPoint p = bearing::stiffness_point(c, N);
  ASSERT_TRUE(p.rotor.has_value());
  EXPECT_EQ(p.rotor->samples, N);
  const Matrix5 expected = direct_mean(c, N);
  const double scale = expected.cwiseAbs().maxCoeff();
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      EXPECT_NEAR(p.rotor->stiffness(i, j), expected(i, j), 1e-12 * scale) << i << j;
  // The same matrix as the ball pass's mean (stiffness.json's ball_pass.mean), bit for bit.
  EXPECT_EQ(p.rotor->stiffness, p.ball_pass->mean);
  const Matrix5& at_cage_angle = p.solution.at.stiffness;
  EXPECT_LT(std::abs(at_cage_angle(0, 0)), 1e-12 * at_cage_angle(1, 1));
  EXPECT_GT(p.rotor->stiffness(0, 0), 0.05 * p.rotor->stiffness(1, 1));
  EXPECT_TRUE(p.rotor->warnings.empty());
  EXPECT_FALSE(bearing::stiffness_point(c, 0).rotor.has_value());  // no ball pass, no mean
}

// ball_pass_mean, what a damping matrix will be averaged with too: entry by entry, Σ M_k / N.
TEST(RotorCoefficients, BallPassMeanIsTheArithmeticMean) {
  std::vector<Matrix5> samples;
  Matrix5 sum = Matrix5::Zero();
  for (int k = 0; k < 7; ++k) {
    Matrix5 M;
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < 5; ++j) M(i, j) = std::sin(1.0 + k + 5 * i + j) * std::pow(10.0, i + k);
    samples.push_back(M);
    sum += M;
  }
  const Matrix5 mean = bearing::ball_pass_mean(samples);
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      EXPECT_NEAR(mean(i, j), sum(i, j) / 7, 1e-14 * sum.cwiseAbs().maxCoeff()) << i << j;
  EXPECT_THROW(bearing::ball_pass_mean({}), std::logic_error);
}

// No load: the ring sits in the clearance, no ball is loaded at any cage angle, K = 0 at every
// one, and the warning says so; with or without clearance (balls just touching carry nothing).
TEST(RotorCoefficients, ALoadInTheClearanceWarns) {
  for (const std::string clearance : {"20um", "0um"}) {
    SCOPED_TRACE(clearance);
    const bearing::StiffnessPoint p = bearing::stiffness_point(
        example({"operation.load=[0, 0]", "bearing.clearance=" + clearance}), 8);
    ASSERT_TRUE(p.rotor.has_value());
    EXPECT_EQ(p.rotor->stiffness, Matrix5::Zero());
    ASSERT_EQ(p.rotor->warnings.size(), 1u);
    for (const char* s : {"no ball is loaded at any cage angle", "clearance", "operation.load"})
      EXPECT_TRUE(contains(p.rotor->warnings, s)) << s << ": " << p.rotor->warnings[0];
  }
}

// The example's load, a preload, a moment, at rest and at speed: the mean is not near singular.
TEST(RotorCoefficients, ANormalCaseDoesNotWarn) {
  for (const std::vector<std::string>& sets :
       {std::vector<std::string>{},
        {"operation.axial_load=100"},
        {"operation.speed=0rpm"},
        {"operation.load=[0, -500]", "bearing.clearance=0"},
        {"operation.axial_load=50", "operation.moment=[0.5, 0]"}}) {
    const bearing::StiffnessPoint p = bearing::stiffness_point(example(sets), 8);
    ASSERT_TRUE(p.rotor.has_value());
    EXPECT_TRUE(p.rotor->warnings.empty())
        << (sets.empty() ? "" : sets[0]) << ": " << p.rotor->warnings.front();
  }
}

Matrix5 diagonal(double xx, double yy, double zz, double gxgx, double gygy) {
  Matrix5 K = Matrix5::Zero();
  K.diagonal() << xx, yy, zz, gxgx, gygy;
  return K;
}

// The criterion on given matrices: per block (translations [N/m], tilts [N m/rad]) the smallest
// eigenvalue against 1e-9 of the largest, the direction named; no stiffness in a block at all.
TEST(RotorCoefficients, ANearSingularBlockWarnsNamingItsDirection) {
  EXPECT_TRUE(bearing::rotor_stiffness_warnings(diagonal(2e7, 3e7, 4e4, 40, 30)).empty());
  // z at 1e-12 of the radial stiffness: the translations, along z.
  auto w = bearing::rotor_stiffness_warnings(diagonal(2e7, 3e7, 3e-5, 40, 30));
  ASSERT_EQ(w.size(), 1u);
  for (const char* s : {"translations (x, y, z)", "along z", "1e-12", "3e+07 N/m", "1e-09"})
    EXPECT_NE(w[0].find(s), std::string::npos) << s << ": " << w[0];
  // Just either side of the threshold.
  EXPECT_TRUE(bearing::rotor_stiffness_warnings(diagonal(1e7, 1e7, 1.01e-2, 40, 30)).empty());
  EXPECT_EQ(bearing::rotor_stiffness_warnings(diagonal(1e7, 1e7, 0.99e-2, 40, 30)).size(), 1u);
  // The radial block singular along x − y (ROSS's kxx … kyy): a direction in the x–y plane.
  Matrix5 K = diagonal(1e7, 1e7, 4e4, 40, 30);
  K(0, 1) = K(1, 0) = 1e7;
  w = bearing::rotor_stiffness_warnings(K);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("along 0.71 x - 0.71 y"), std::string::npos) << w[0];
  // Tilts: gy unsupported; no tilt stiffness at all.
  w = bearing::rotor_stiffness_warnings(diagonal(2e7, 3e7, 4e4, 40, 0));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("tilts (gx, gy)"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("along gy"), std::string::npos) << w[0];
  w = bearing::rotor_stiffness_warnings(diagonal(2e7, 3e7, 4e4, 0, 0));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("no stiffness in the tilts"), std::string::npos) << w[0];
  // Both blocks at once: two warnings.
  EXPECT_EQ(bearing::rotor_stiffness_warnings(diagonal(2e7, 0, 4e4, 40, 0)).size(), 2u);
}

}  // namespace
