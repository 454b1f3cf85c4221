// The 5-DOF static solution and its stiffness (five_dof_static.h, issue 32): the analytic
// stiffness against central differences of the force on every preset, with and without axial
// load and moment; symmetry and positive definiteness; the reductions to the 2-DOF static
// solution and the 3-DOF static state; Harris's closed form for a pure axial load.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "bearing/ball_pass_stiffness.h"
#include "bearing/contact.h"
#include "bearing/errors.h"
#include "bearing/five_dof_static.h"
#include "bearing/hertz.h"
#include "bearing/models/model_inputs.h"
#include "bearing/models/three_dof.h"
#include "bearing/presets.h"
#include "bearing/static_load.h"

namespace bearing {
namespace {

FiveDofBearing of_preset(const std::string& name, double phase = 0.1) {
  const Bearing b = preset(name);
  return five_dof_bearing(b, contact_constants(b, *make_exact_hertz()), phase);
}

// Loads scaled to the bearing: a radial load that loads a few balls, an axial one of half of
// it, moments that tilt the ring about as much as the radial load moves it.
std::vector<Vector5> loads(const FiveDofBearing& b) {
  const double Fr = 2e-3 * b.K * std::pow(10e-6, b.exponent);  // ~ a few hundred N
  const double M = 0.3 * Fr * b.groove_radius;
  std::vector<Vector5> out;
  Vector5 F;
  F << 0.3 * Fr, -Fr, 0, 0, 0;
  out.push_back(F);  // radial
  F << 0.3 * Fr, -Fr, 0.5 * Fr, 0, 0;
  out.push_back(F);  // radial and axial
  F << 0.3 * Fr, -Fr, 0.5 * Fr, M, -0.5 * M;
  out.push_back(F);  // with moments
  F << 0, 0, -Fr, 0, 0;
  out.push_back(F);  // axial only, toward the other shoulder
  return out;
}

// K against central differences of the force at the equilibrium s (see the test below).
void expect_stiffness_is_the_central_difference(const FiveDofBearing& b, const FiveDofSolution& s) {
  double dmax = 0;
  for (double d : s.at.approaches) dmax = std::max(dmax, d);
  ASSERT_GT(dmax, 0);
  const double h = 1e-4 * dmax;
  Matrix5 numeric;
  for (int i = 0; i < 5; ++i) {
    Vector5 dq = Vector5::Zero();
    dq(i) = i < 3 ? h : h / b.groove_radius;
    numeric.col(i) = (five_dof_point(b, s.displacement + dq).force -
                      five_dof_point(b, s.displacement - dq).force) /
                     (2 * dq(i));
  }
  const double scale = s.at.stiffness.cwiseAbs().maxCoeff();
  EXPECT_LE((numeric - s.at.stiffness).cwiseAbs().maxCoeff(), 1e-6 * scale);
}

// The analytic stiffness equals the central differences of the force at the equilibrium to
// 1e-6 of its largest entry. Step h = 1e-4 of the largest ball deflection (tilts: h/ℜ_i): the
// truncation error is ~ (h/δ)²/6 ≈ 2e-9 relative where a ball stays loaded; rounding adds
// ε F/h ≈ 1e-12 of K. A ball whose contact opens or closes within ±h would break the
// smoothness; none is that close at these loads (checked: the error bound holds).
TEST(FiveDofStatic, StiffnessIsTheCentralDifferenceOfTheForceOnEveryPreset) {
  for (const std::string& name : preset_names()) {
    const FiveDofBearing b = of_preset(name);
    for (const Vector5& F : loads(b)) {
      SCOPED_TRACE(name + ", F = " + std::to_string(F(0)) + ", " + std::to_string(F(1)) + ", " +
                   std::to_string(F(2)) + ", " + std::to_string(F(3)) + ", " +
                   std::to_string(F(4)));
      const FiveDofSolution s = solve_five_dof(b, F);
      expect_stiffness_is_the_central_difference(b, s);
    }
  }
}

// K = ∇²V is symmetric by construction (a sum of outer products): exactly, not to rounding.
// With three or more balls loaded it is positive definite (the loaded balls' g and h span the
// five directions); the smallest eigenvalue is compared in the solver's coordinates (tilts
// times ℜ_i) so that all five are in N/m.
TEST(FiveDofStatic, StiffnessIsSymmetricAndPositiveDefiniteUnderLoad) {
  int checked = 0;
  for (const std::string name : {"6308", "6205", "6304", "608"}) {
    const FiveDofBearing b = of_preset(name);
    for (const Vector5& F : loads(b)) {
      SCOPED_TRACE(name);
      const FiveDofSolution s = solve_five_dof(b, F);
      int loaded = 0;
      for (double Q : s.at.ball_loads) loaded += Q > 0;
      if (loaded < 3) continue;  // a radial load on two balls: no tilt stiffness about their line
      loaded = 0;
      for (double Q : s.at.ball_loads) loaded += Q > 0;
      ASSERT_GE(loaded, 3);
      const Matrix5& K = s.at.stiffness;
      EXPECT_EQ((K - K.transpose()).cwiseAbs().maxCoeff(), 0.0);
      Vector5 S;
      S << 1, 1, 1, 1 / b.groove_radius, 1 / b.groove_radius;
      const Matrix5 Ks = S.asDiagonal() * K * S.asDiagonal();
      const Eigen::SelfAdjointEigenSolver<Matrix5> eig(Ks);
      EXPECT_GT(eig.eigenvalues()(0), 1e-6 * eig.eigenvalues()(4));
      ++checked;
    }
  }
  EXPECT_GE(checked, 12);  // the loads with an axial part load every ball
}

// The equilibrium carries the load, moments included, and a moment tilts the ring its way.
TEST(FiveDofStatic, EquilibriumCarriesTheLoadAndAMomentTiltsTheRingItsWay) {
  const FiveDofBearing b = of_preset("6308");
  for (const Vector5& F : loads(b)) {
    const FiveDofSolution s = solve_five_dof(b, F);
    for (int i = 0; i < 5; ++i)
      EXPECT_NEAR(s.at.force(i), F(i), 1e-9 * F.head<3>().norm() * (i < 3 ? 1 : b.groove_radius));
  }
  const Vector5 with_moment = loads(b)[2];
  const Vector5 without = loads(b)[1];
  const Vector5 dq =
      solve_five_dof(b, with_moment).displacement - solve_five_dof(b, without).displacement;
  EXPECT_GT(dq(3) * with_moment(3), 0);  // Mx > 0 turns the ring by γx > 0
  EXPECT_GT(dq(4) * with_moment(4), 0);
}

// A radial load alone: δz = γx = γy = 0 and (δx, δy) is the 2-DOF static solution with the gap
// P_d/2 (five_dof_static.h: the axial offsets vanish, so δ_j = r_j − P_d/2 exactly).
TEST(FiveDofStatic, RadialLoadGivesTheTwoDofStaticSolution) {
  for (const std::string name : {"6308", "6205", "608"}) {
    SCOPED_TRACE(name);
    const FiveDofBearing b = of_preset(name, 0.3);
    const Vector5 F = loads(b)[0];
    const FiveDofSolution s = solve_five_dof(b, F);
    StaticLoadOptions o;
    o.phase = 0.3;
    o.exponent = b.exponent;
    const StaticLoadResult r =
        solve_static_load(b.balls, b.K, 0.5 * b.clearance, Eigen::Vector2d(F(0), F(1)), o);
    const double scale = r.deflection.norm();
    EXPECT_NEAR(s.displacement(0), r.deflection.x(), 1e-9 * scale);
    EXPECT_NEAR(s.displacement(1), r.deflection.y(), 1e-9 * scale);
    EXPECT_NEAR(s.displacement(2), 0, 1e-9 * scale);
    EXPECT_NEAR(s.displacement(3) * b.groove_radius, 0, 1e-9 * scale);
    EXPECT_NEAR(s.displacement(4) * b.groove_radius, 0, 1e-9 * scale);
    for (int j = 0; j < b.balls; ++j)
      EXPECT_NEAR(s.at.ball_loads[j], r.ball_loads[j], 1e-8 * F.norm());
  }
}

// A radial and an axial load with the tilts held: the 3-DOF model's static state (three_dof.h),
// whose axial coordinate starts where the balls just touch: z₃ = δz − w₀. Free to tilt, the
// ring tilts (the loaded side carries more of the axial load) and no moment remains.
TEST(FiveDofStatic, RadialAndAxialLoadGiveTheThreeDofStaticState) {
  const Bearing brg = preset("6308");
  ModelInputs in;
  in.bearing = brg;
  in.contact = contact_constants(brg, *make_exact_hertz());
  in.hertz_method = HertzMethod::exact;
  in.inner_speed = 100;
  in.mass = 0.6;
  in.damping = 200;
  in.load = Eigen::Vector2d(30, -200);
  in.axial_load = 150;
  const std::vector<double> q3 = make_three_dof_model(in)->initial_displacement();
  const FiveDofBearing b = five_dof_bearing(brg, in.contact, in.cage_phase);
  Vector5 F;
  F << 30, -200, 150, 0, 0;
  const FiveDofSolution s = solve_five_dof(b, F, {false, false, false, true, true});
  const double half = 0.5 * brg.clearance, w0 = std::sqrt(half * (2 * b.A0 - half));
  const double scale = std::abs(q3[2]) + w0;
  EXPECT_NEAR(s.displacement(0), q3[0], 1e-8 * scale);
  EXPECT_NEAR(s.displacement(1), q3[1], 1e-8 * scale);
  EXPECT_NEAR(s.displacement(2) - w0, q3[2], 1e-8 * scale);
  EXPECT_EQ(s.displacement(3), 0.0);
  EXPECT_EQ(s.displacement(4), 0.0);
  EXPECT_GT(std::abs(s.at.force(3)) + std::abs(s.at.force(4)), 1e-3 * b.groove_radius * 150);
  const FiveDofSolution tilting = solve_five_dof(b, F);
  EXPECT_GT(std::abs(tilting.displacement(3)) + std::abs(tilting.displacement(4)), 0);
  EXPECT_NEAR(tilting.at.force(3), 0, 1e-9 * 200 * b.groove_radius);
  EXPECT_NEAR(tilting.at.force(4), 0, 1e-9 * 200 * b.groove_radius);
}

// A pure axial load: every ball at the same contact angle α with Harris's
// F_z = Z K [A₀ (cos α₀ / cos α − 1)]^n sin α (cos α₀ = 1 − P_d/(2A₀)), and the axial stiffness
// dF_z/dδz = Z (n K δ^{n−1} sin²α + K δ^n cos²α / L), L = A₀ cos α₀ / cos α: the derivative of
// the closed form along δz = L sin α (dδ/dδz = sin α, d sin α/dδz = cos²α / L).
TEST(FiveDofStatic, PureAxialLoadFollowsHarrissClosedForm) {
  for (const std::string name : {"6308", "6205", "6304"}) {
    SCOPED_TRACE(name);
    const FiveDofBearing b = of_preset(name);
    Vector5 F;
    F << 0, 0, 400, 0, 0;
    const FiveDofSolution s = solve_five_dof(b, F);
    const double alpha = s.at.contact_angles[0];
    for (double a : s.at.contact_angles) EXPECT_NEAR(a, alpha, 1e-12);
    const double cos0 = 1 - b.clearance / (2 * b.A0);
    const double delta = b.A0 * (cos0 / std::cos(alpha) - 1);
    const double n = b.exponent;
    EXPECT_NEAR(b.balls * b.K * std::pow(delta, n) * std::sin(alpha), 400, 1e-9 * 400);
    const double L = b.A0 * cos0 / std::cos(alpha);
    const double kzz = b.balls * (n * b.K * std::pow(delta, n - 1) * std::pow(std::sin(alpha), 2) +
                                  b.K * std::pow(delta, n) * std::pow(std::cos(alpha), 2) / L);
    EXPECT_NEAR(s.at.stiffness(2, 2), kzz, 1e-9 * kzz);
    // The radial terms of a uniformly loaded ring: kxx = kyy, no coupling to z.
    EXPECT_NEAR(s.at.stiffness(0, 0), s.at.stiffness(1, 1), 1e-9 * s.at.stiffness(0, 0));
    EXPECT_NEAR(s.at.stiffness(0, 2), 0, 1e-9 * kzz);
    // The tilt stiffness of a uniformly loaded ring: each ball's axial stiffness at the arm
    // ℜ_i sin ψ_j, and Σ sin²ψ_j = Z/2 (Z ≥ 3): k_γγ = ℜ_i² k_zz / 2 about either axis.
    const double R = b.groove_radius;
    EXPECT_NEAR(s.at.stiffness(3, 3), 0.5 * R * R * kzz, 1e-9 * R * R * kzz);
    EXPECT_NEAR(s.at.stiffness(4, 4), 0.5 * R * R * kzz, 1e-9 * R * R * kzz);
    EXPECT_NEAR(s.at.stiffness(2, 3), 0, 1e-9 * R * kzz);
  }
}

// ℜ_i is the radius of the inner groove's curvature centre: the groove bottom, at
// d_i/2 = (d_m − D − P_d/2)/2 from the axis (the clearance split evenly between the races, so
// that P_d = d_o − d_i − 2D), plus the groove radius f_i D.
TEST(FiveDofStatic, TheTiltArmIsTheInnerGrooveCentresRadius) {
  const Bearing brg = preset("6308");
  const FiveDofBearing b = five_dof_bearing(brg, contact_constants(brg, *make_exact_hertz()));
  const double d_i = brg.pitch_diameter - brg.ball_diameter - 0.5 * brg.clearance;
  EXPECT_NEAR(b.groove_radius, 0.5 * d_i + brg.inner_conformity * brg.ball_diameter, 1e-15);
}

// --- At speed: each ball its own centre (races apart) -------------------------------------

// The two-contact form at rest (F_c = 0) is the one-contact form with the series constant: the
// ball lies on the line of centres and both contacts carry the same load. Equal to the Newton
// tolerances (1e-13 of the load per ball, 1e-12 of |F| for the ring): 1e-8 relative.
TEST(FiveDofStatic, TwoContactsAtRestAreTheSeriesLaw) {
  for (const std::string name : {"6308", "6205", "6304"}) {
    const FiveDofBearing one = of_preset(name);
    FiveDofBearing two = one;
    two.races_apart = true;
    for (const Vector5& F : loads(one)) {
      SCOPED_TRACE(name);
      const FiveDofSolution a = solve_five_dof(one, F), b = solve_five_dof(two, F);
      const double qs = a.displacement.head<3>().norm();
      for (int i = 0; i < 5; ++i)
        EXPECT_NEAR(b.displacement(i), a.displacement(i),
                    1e-8 * (i < 3 ? qs : qs / one.groove_radius));
      const double ks = a.at.stiffness.cwiseAbs().maxCoeff();
      EXPECT_LE((b.at.stiffness - a.at.stiffness).cwiseAbs().maxCoeff(), 1e-8 * ks);
      for (int j = 0; j < one.balls; ++j) {
        EXPECT_NEAR(b.at.ball_loads[j], a.at.ball_loads[j], 1e-8 * F.head<3>().norm());
        EXPECT_NEAR(b.at.outer_loads[j], a.at.ball_loads[j], 1e-8 * F.head<3>().norm());
      }
    }
  }
}

FiveDofBearing at_speed(const std::string& name, double rpm) {
  const Bearing brg = preset(name);
  const double Fc = ball_centrifugal_load(brg, rpm * 2 * 3.14159265358979323846 / 60);
  return five_dof_bearing(brg, contact_constants(brg, *make_exact_hertz()), 0.1, Fc);
}

// F_c = m_b ω_c² d_m/2, by hand for the 6308 at 12 000 rpm: m_b = ρ π D³/6, ω_c from the
// pitch-line kinematics ω_c = ω_i (1 − D/d_m)/2 at a zero contact angle.
TEST(FiveDofStatic, CentrifugalLoadByHand) {
  const Bearing brg = preset("6308");
  const double wi = 12000 * 2 * 3.14159265358979323846 / 60;
  const double wc = 0.5 * wi * (1 - brg.ball_diameter / brg.pitch_diameter);
  const double m = brg.ball.density * 3.14159265358979323846 * std::pow(brg.ball_diameter, 3) / 6;
  EXPECT_NEAR(ball_centrifugal_load(brg, wi), m * wc * wc * 0.5 * brg.pitch_diameter,
              1e-12 * m * wc * wc * brg.pitch_diameter);
}

// The condensed stiffness at speed (the two contacts in series through the ball's own
// equilibrium) against central differences of the ring force, as at rest.
TEST(FiveDofStatic, StiffnessAtSpeedIsTheCentralDifferenceOfTheForce) {
  for (const std::string name : {"6308", "6205", "6304"}) {
    const FiveDofBearing b = at_speed(name, 15000);
    ASSERT_GT(b.centrifugal, 0);
    for (const Vector5& F : loads(b)) {
      SCOPED_TRACE(name);
      const FiveDofSolution s = solve_five_dof(b, F);
      expect_stiffness_is_the_central_difference(b, s);
      EXPECT_EQ((s.at.stiffness - s.at.stiffness.transpose()).cwiseAbs().maxCoeff(), 0.0);
    }
  }
}

// Jones's ball equilibrium from the reported loads and angles: Q_o cos α_o − Q_i cos α_i = F_c
// and Q_o sin α_o = Q_i sin α_i, for every ball; under an axial load the centrifugal load turns
// the outer contact toward the radial and the inner one away from it (α_o < α_i), and the
// radial stiffness differs from the one at rest.
TEST(FiveDofStatic, EachBallAtSpeedIsInJonessEquilibrium) {
  const FiveDofBearing b = at_speed("6308", 15000);
  Vector5 F;
  F << 100, -300, 500, 0, 0;
  const FiveDofSolution s = solve_five_dof(b, F);
  for (int j = 0; j < b.balls; ++j) {
    const double Qi = s.at.ball_loads[j], Qo = s.at.outer_loads[j];
    const double ai = s.at.contact_angles[j], ao = s.at.outer_contact_angles[j];
    EXPECT_NEAR(Qo * std::cos(ao) - Qi * std::cos(ai), b.centrifugal, 1e-9 * (Qo + b.centrifugal));
    EXPECT_NEAR(Qo * std::sin(ao), Qi * std::sin(ai), 1e-9 * (Qo + b.centrifugal));
    if (Qi > 0) EXPECT_LT(ao, ai);
  }
  const FiveDofBearing rest = of_preset("6308");
  const FiveDofSolution r = solve_five_dof(rest, F);
  EXPECT_GT(std::abs(s.at.stiffness(0, 0) - r.at.stiffness(0, 0)), 1e-3 * r.at.stiffness(0, 0));
}

// --- Over a ball pass (ball_pass_stiffness.h) --------------------------------------------

// A uniformly loaded ring (pure axial load) looks the same at every cage angle: Σ cos²ψ_j and
// its kin do not depend on the phase for Z ≥ 3, so K has no ripple and no harmonic.
TEST(BallPassStiffness, AnAxialLoadHasNoRipple) {
  const FiveDofBearing b = of_preset("6308");
  Vector5 F;
  F << 0, 0, 300, 0, 0;
  const BallPassStiffness r = ball_pass_stiffness(b, F, 16);
  const double scale = r.mean.cwiseAbs().maxCoeff();
  EXPECT_LE((r.max - r.min).cwiseAbs().maxCoeff(), 1e-9 * scale);
  for (const Matrix5& h : r.harmonics) EXPECT_LE(h.cwiseAbs().maxCoeff(), 1e-9 * scale);
}

// Under a radial load with clearance a few balls carry it and K ripples as they pass: periodic in
// one pitch (the ball set one pitch on is the same set), and each entry's harmonics hold its
// variance (Parseval: the mean square of the ripple is Σ c_m²/2 plus the Nyquist term).
TEST(BallPassStiffness, ARadialLoadRipplesWithThePitchAndParsevalHolds) {
  const FiveDofBearing b = of_preset("6308", 0.0);
  Vector5 F;
  F << 0, -300, 0, 0, 0;
  const int N = 16;
  const BallPassStiffness r = ball_pass_stiffness(b, F, N);
  EXPECT_GT(r.max(1, 1) - r.min(1, 1), 0.01 * r.mean(1, 1));
  FiveDofBearing next = b;
  next.phase = b.phase + 2 * 3.14159265358979323846 / b.balls;
  const Matrix5 K0 = solve_five_dof(b, F).at.stiffness, K1 = solve_five_dof(next, F).at.stiffness;
  EXPECT_LE((K1 - K0).cwiseAbs().maxCoeff(), 1e-9 * K0.cwiseAbs().maxCoeff());
  for (const auto& [i, j] : {std::pair{1, 1}, std::pair{0, 0}, std::pair{0, 1}}) {
    double variance = 0, nyquist = 0;
    for (int k = 0; k < N; ++k) {
      const double d = r.samples[k](i, j) - r.mean(i, j);
      variance += d * d / N;
      nyquist += (k % 2 ? -1 : 1) * r.samples[k](i, j) / N;
    }
    double sum = nyquist * nyquist;
    for (const Matrix5& h : r.harmonics) sum += 0.5 * h(i, j) * h(i, j);
    EXPECT_NEAR(sum, variance, 1e-9 * variance + 1e-30);
  }
  ASSERT_EQ(r.harmonics.size(), static_cast<std::size_t>(N / 2 - 1));
  for (int k = 0; k < N; ++k)  // N cage angles through exactly one pitch
    EXPECT_NEAR(r.cage_angles[k], b.phase + 2 * 3.14159265358979323846 / b.balls * k / N, 1e-15);
}

TEST(BallPassStiffness, NeedsFourSamples) {
  EXPECT_THROW(ball_pass_stiffness(of_preset("6308"), Vector5::Zero(), 3), InputError);
}

TEST(FiveDofStatic, ANonFiniteLoadIsAnInputError) {
  Vector5 F = Vector5::Zero();
  F(1) = std::nan("");
  EXPECT_THROW(solve_five_dof(of_preset("6308"), F), InputError);
}

TEST(FiveDofStatic, NoLoadIsTheCentredPosition) {
  const FiveDofSolution s = solve_five_dof(of_preset("6308"), Vector5::Zero());
  EXPECT_EQ(s.displacement, Vector5::Zero());
  for (double Q : s.at.ball_loads) EXPECT_EQ(Q, 0.0);
}

}  // namespace
}  // namespace bearing
