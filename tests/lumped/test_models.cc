// The 2-DOF, 3-DOF and ball-DOF models (models/two_dof.h, three_dof.h, ball_dofs.h) against
// physics: static equilibrium, energy, Jacobians, the excitation conventions of docs/model.md
// §1/§5, TVDS, and the reductions of the 3-DOF model to the 2-DOF one.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "bearing/constants.h"
#include "bearing/contact.h"
#include "bearing/errors.h"
#include "bearing/excitation.h"
#include "bearing/hertz.h"
#include "bearing/kinematics.h"
#include "bearing/models/ball_dofs.h"
#include "bearing/models/three_dof.h"
#include "bearing/models/two_dof.h"
#include "bearing/presets.h"
#include "bearing/static_load.h"
#include "bearing/traction.h"

namespace bearing {
namespace {

// The 6308 of seeds 002/003 at 2000 rpm under 20 N down, m = 0.6 kg, c = 200 N s/m.
ModelInputs inputs_6308() {
  ModelInputs in;
  in.bearing = preset("6308");
  in.contact = contact_constants(in.bearing, *make_exact_hertz());
  in.hertz_method = HertzMethod::exact;
  in.inner_speed = 2000 * two_pi / 60;
  in.load = Eigen::Vector2d(0, -20);
  in.mass = 0.6;
  in.damping = 200;
  return in;
}

ModelInputs at_rest(ModelInputs in) {
  in.inner_speed = 0;
  in.damping = 0;
  in.axial_damping = 0;
  return in;
}

Waviness random_waviness(int max_order, double amplitude, unsigned seed) {
  Waviness w;
  unsigned s = seed;
  auto next = [&] {
    s = s * 1664525u + 1013904223u;
    return (s >> 8) / double(1 << 24);
  };
  for (int n = 1; n <= max_order; ++n)
    if (next() < 0.5) w.harmonics.push_back({n, amplitude * next(), two_pi * next()});
  return w;
}

Waviness seed003_table() {
  Waviness w;
  w.harmonics = read_waviness_table(
      std::string(BEARING_SOURCE_DIR) + "/examples/seed003_inner_waviness.csv", "table");
  for (std::size_t i = 0; i < w.harmonics.size(); ++i) w.harmonics[i].phase = 0.37 * i * i;
  return w;
}

std::vector<double> eval_force(const BearingModel& m, double t, const std::vector<double>& q,
                               const std::vector<double>& v) {
  std::vector<double> f(m.dofs());
  m.force(t, q.data(), v.data(), f.data());
  return f;
}

std::vector<double> loads_of(const BearingModel& m, double t, const std::vector<double>& q) {
  std::vector<double> l(m.balls());
  m.ball_loads(t, q.data(), l.data());
  return l;
}

double norm(const std::vector<double>& a) {
  double s = 0;
  for (double x : a) s += x * x;
  return std::sqrt(s);
}

// Approach of a loaded ball from its load, δ = (Q/K)^{2/3}.
double approach_from_load(double Q, double K) {
  return std::cbrt((Q / K) * (Q / K));
}

// ∂f/∂q and ∂f/∂v by central differences against the analytic force_jacobian.
void expect_jacobian_matches(const BearingModel& m, double t, const std::vector<double>& q,
                             const std::vector<double>& v, double rel_tol) {
  const int n = m.dofs();
  std::vector<double> dfdq(n * n), dfdv(n * n);
  m.force_jacobian(t, q.data(), v.data(), dfdq.data(), dfdv.data());
  double scale = 0;
  for (double x : dfdq) scale = std::max(scale, std::abs(x));
  ASSERT_GT(scale, 0.0);
  const double h = 1e-10, hv = 1e-4;
  for (int j = 0; j < n; ++j) {
    auto qp = q, qm = q, vp = v, vm = v;
    qp[j] += h;
    qm[j] -= h;
    vp[j] += hv;
    vm[j] -= hv;
    const auto fp = eval_force(m, t, qp, v), fm = eval_force(m, t, qm, v);
    const auto gp = eval_force(m, t, q, vp), gm = eval_force(m, t, q, vm);
    for (int i = 0; i < n; ++i) {
      EXPECT_NEAR(dfdq[i * n + j], (fp[i] - fm[i]) / (2 * h), rel_tol * scale)
          << "df" << i << "/dq" << j;
      EXPECT_NEAR(dfdv[i * n + j], (gp[i] - gm[i]) / (2 * hv),
                  1e-9 * (1 + std::abs(dfdv[i * n + j])))
          << "df" << i << "/dv" << j;
    }
  }
}

// −∇V by central differences equals the contact force (the force with no load, no damping).
void expect_energy_gradient_is_force(const BearingModel& m, double t,
                                     const std::vector<double>& q) {
  const int n = m.dofs();
  const std::vector<double> zero(n, 0.0);
  const auto f = eval_force(m, t, q, zero);
  const double h = 1e-10;
  for (int j = 0; j < n; ++j) {
    auto qp = q, qm = q;
    qp[j] += h;
    qm[j] -= h;
    const double grad =
        (m.potential_energy(t, qp.data()) - m.potential_energy(t, qm.data())) / (2 * h);
    EXPECT_NEAR(-grad, f[j], 1e-6 * norm(f)) << "dof " << j;
  }
}

// Contact forces only: no external load, no unbalance, no damping.
ModelInputs contact_only(ModelInputs in) {
  in.load.setZero();
  in.axial_load = 0;
  in.unbalance = 0;
  in.gravity = false;
  return in;
}

// --- 2-DOF -----------------------------------------------------------------------------------

TEST(TwoDof, InterfaceBasics) {
  const auto m = make_two_dof_model(inputs_6308());
  EXPECT_EQ(m->dofs(), 2);
  EXPECT_EQ(m->balls(), 8);
  EXPECT_EQ(m->dof_names(), (std::vector<std::string>{"x", "y"}));
  double mass[2];
  m->mass(mass);
  EXPECT_EQ(mass[0], 0.6);
  EXPECT_EQ(mass[1], 0.6);
}

// At the static load solution the force (at rest, no damping) vanishes; initial_displacement()
// is that solution.
TEST(TwoDof, StaticEquilibrium) {
  for (double clearance : {0.0, 14e-6, 40e-6}) {
    for (const Eigen::Vector2d& F :
         {Eigen::Vector2d(0, -20), Eigen::Vector2d(300, -500), Eigen::Vector2d(-5000, 10)}) {
      for (double phase : {0.0, 0.3}) {
        ModelInputs in = at_rest(inputs_6308());
        in.bearing.clearance = clearance;
        in.load = F;
        in.cage_phase = phase;
        const auto m = make_two_dof_model(in);
        StaticLoadOptions o;
        o.phase = phase;
        const auto s = solve_static_load(8, in.contact.K, clearance / 2, F, o);
        const std::vector<double> q{s.deflection.x(), s.deflection.y()};
        for (double t : {0.0, 0.7}) {
          const auto f = eval_force(*m, t, q, {0, 0});
          EXPECT_LT(norm(f), 1e-9 * F.norm()) << clearance << " " << F.transpose();
        }
        const auto q0 = m->initial_displacement();
        EXPECT_NEAR(q0[0], q[0], 1e-15);
        EXPECT_NEAR(q0[1], q[1], 1e-15);
        const auto loads = loads_of(*m, 0.0, q);
        for (int j = 0; j < 8; ++j) EXPECT_NEAR(loads[j], s.ball_loads[j], 1e-9 * F.norm());
      }
    }
  }
}

TEST(TwoDof, PotentialGradientIsContactForce) {
  ModelInputs in = contact_only(inputs_6308());
  in.inner_waviness = random_waviness(30, 0.3e-6, 1);
  in.outer_waviness = random_waviness(12, 0.5e-6, 2);
  in.ball_size_errors = ball_size_errors_from_band(8, 1e-6, 3);
  for (bool tvds : {false, true}) {
    in.waviness_stiffness = tvds;
    const auto m = make_two_dof_model(in);
    for (double t : {0.0, 0.0123, 0.31}) expect_energy_gradient_is_force(*m, t, {3e-6, -14e-6});
  }
}

TEST(TwoDof, JacobianMatchesFiniteDifferences) {
  ModelInputs in = inputs_6308();
  in.unbalance = 1e-4;
  in.inner_waviness = random_waviness(40, 0.2e-6, 4);
  in.outer_waviness = random_waviness(9, 0.5e-6, 5);
  for (bool tvds : {false, true}) {
    in.waviness_stiffness = tvds;
    const auto m = make_two_dof_model(in);
    for (double t : {0.0, 0.004, 0.2})
      expect_jacobian_matches(*m, t, {2e-6, -15e-6}, {0.01, -0.02}, 1e-6);
  }
  in.contact.exponent = 10.0 / 9.0;  // the general-exponent path (line contact law)
  in.waviness_stiffness = false;
  expect_jacobian_matches(*make_two_dof_model(in), 0.01, {2e-6, -15e-6}, {0, 0}, 1e-6);
}

// Setup for reading approaches off the loads: no clearance, q = 0, every ball 5 µm oversize
// (ΔD_j = −5 µm), so δ_j = 5 µm + Π_i,j + Π_o,j and every ball is loaded.
ModelInputs oversize_balls(ModelInputs in) {
  in.bearing.clearance = 0;
  in.ball_size_errors.assign(in.bearing.balls, -5e-6);
  return contact_only(in);
}

double theta(const ModelInputs& in, int j, double t) {
  return in.cage_phase + two_pi * j / in.bearing.balls + cage_speed(in.bearing, in.inner_speed) * t;
}

TEST(TwoDof, WavinessIncreasesApproachAndLoad) {
  for (bool inner : {true, false}) {
    ModelInputs in = oversize_balls(inputs_6308());
    in.cage_phase = 0.2;
    const double t = 0.0037;
    Waviness w;
    w.harmonics = {{6, 1e-6, 0.0}};
    // Phase so that ball 0 sits on a crest: N φ_0 + ψ = π/2.
    const double phi0 = theta(in, 0, t) - (inner ? in.inner_speed * t : 0.0);
    w.harmonics[0].phase = pi / 2 - 6 * phi0;
    (inner ? in.inner_waviness : in.outer_waviness) = w;
    const auto plain = make_two_dof_model(oversize_balls(inputs_6308()));
    ModelInputs ref = oversize_balls(inputs_6308());
    ref.cage_phase = 0.2;
    const auto smooth = loads_of(*make_two_dof_model(ref), t, {0, 0});
    const auto wavy = loads_of(*make_two_dof_model(in), t, {0, 0});
    EXPECT_GT(wavy[0], smooth[0]) << (inner ? "inner" : "outer");
    EXPECT_NEAR(approach_from_load(wavy[0], in.contact.K), 6e-6, 1e-15);
    EXPECT_NEAR(approach_from_load(smooth[0], in.contact.K), 5e-6, 1e-15);
  }
}

// Inner waviness is fixed to the rotating inner race, so ball j meets it at θ_j − ω_i t: a single
// order N makes δ_j periodic at N (f_i − f_c); outer waviness at θ_j: periodic at N f_c.
TEST(TwoDof, InnerWavinessIsSeenInTheRotatingFrame) {
  const int N = 7;
  const double A = 0.4e-6, psi = 0.9;
  for (bool inner : {true, false}) {
    ModelInputs in = oversize_balls(inputs_6308());
    in.cage_phase = 0.1;
    Waviness w;
    w.harmonics = {{N, A, psi}};
    (inner ? in.inner_waviness : in.outer_waviness) = w;
    const auto m = make_two_dof_model(in);
    const double wc = cage_speed(in.bearing, in.inner_speed);
    const double fi = in.inner_speed / two_pi, fc = wc / two_pi;
    const double f_expected = inner ? N * (fi - fc) : N * fc;
    for (double t : {0.0, 0.00123, 0.0271, 0.5}) {
      const auto l = loads_of(*m, t, {0, 0});
      for (int j = 0; j < 8; ++j) {
        const double phi = theta(in, j, t) - (inner ? in.inner_speed * t : 0.0);
        EXPECT_NEAR(approach_from_load(l[j], in.contact.K), 5e-6 + A * std::sin(N * phi + psi),
                    1e-16)
            << (inner ? "inner" : "outer") << " t " << t << " ball " << j;
      }
      // Periodic at f_expected, and not at the other race's frequency.
      const auto l1 = loads_of(*m, t + 1 / f_expected, {0, 0});
      for (int j = 0; j < 8; ++j) EXPECT_NEAR(l1[j], l[j], 1e-9 * l[j]);
      const double f_other = inner ? N * fc : N * (fi - fc);
      const auto l2 = loads_of(*m, t + 1 / f_other, {0, 0});
      double diff = 0;
      for (int j = 0; j < 8; ++j) diff = std::max(diff, std::abs(l2[j] - l[j]) / l[j]);
      EXPECT_GT(diff, 1e-3);
    }
  }
}

// The hot loop folds orders by N mod Z and uses the Chebyshev recurrence; it must agree with
// the direct sum Waviness::profile for every ball, including the full seed 003 table.
TEST(TwoDof, FoldedWavinessMatchesDirectSum) {
  for (int Z : {3, 8, 13}) {
    for (double phase : {-0.4, 0.0, pi / 4, pi / 2}) {
      ModelInputs in = inputs_6308();
      in.bearing.balls = Z;
      in = oversize_balls(in);
      in.inner_waviness = seed003_table();
      in.outer_waviness = random_waviness(150, 0.02e-6, 9);
      in.cage_phase = phase;
      const auto m = make_two_dof_model(in);
      for (double t : {0.0, 1e-5, 0.0137, 0.29, 3.7}) {
        const auto l = loads_of(*m, t, {0, 0});
        for (int j = 0; j < Z; ++j) {
          const double th = theta(in, j, t);
          const double expected = 5e-6 + in.inner_waviness.profile(th - in.inner_speed * t) +
                                  in.outer_waviness.profile(th);
          EXPECT_NEAR(approach_from_load(l[j], in.contact.K), expected, 2e-17)
              << "Z " << Z << " phase " << phase << " t " << t << " ball " << j;
        }
      }
    }
  }
  // A single high order far above Z (orders fold by N mod Z).
  ModelInputs in = oversize_balls(inputs_6308());
  in.outer_waviness.harmonics = {{997, 0.1e-6, 0.3}};
  const auto l = loads_of(*make_two_dof_model(in), 0.0123, {0, 0});
  for (int j = 0; j < 8; ++j)
    EXPECT_NEAR(approach_from_load(l[j], in.contact.K),
                5e-6 + in.outer_waviness.profile(theta(in, j, 0.0123)), 1e-17);
}

TEST(TwoDof, BallSizeErrorReducesApproach) {
  ModelInputs in = oversize_balls(inputs_6308());
  const auto base = loads_of(*make_two_dof_model(in), 0.01, {0, 0});
  const std::vector<double> dD = {1e-6, -0.5e-6, 0, 2e-6, 0.25e-6, -1e-6, 3e-6, 4.5e-6};
  for (int j = 0; j < 8; ++j) in.ball_size_errors[j] += dD[j];
  const auto l = loads_of(*make_two_dof_model(in), 0.01, {0, 0});
  for (int j = 0; j < 8; ++j) {
    EXPECT_NEAR(approach_from_load(l[j], in.contact.K),
                approach_from_load(base[j], in.contact.K) - dD[j], 1e-17);
    if (dD[j] > 0) EXPECT_LT(l[j], base[j]);
  }
}

TEST(TwoDof, UnbalanceForceRotatesWithTheShaft) {
  ModelInputs in = inputs_6308();  // 14 µm clearance: q = 0 touches no ball
  in.load.setZero();
  in.unbalance = 2e-5;  // 20 g mm
  const double w = in.inner_speed;
  const auto m = make_two_dof_model(in);
  for (double t : {0.0, 0.001, 0.0113}) {
    const auto f = eval_force(*m, t, {0, 0}, {0, 0});
    EXPECT_NEAR(std::hypot(f[0], f[1]), 2e-5 * w * w, 1e-12);
    EXPECT_NEAR(f[0], 2e-5 * w * w * std::cos(w * t), 1e-12);
    EXPECT_NEAR(f[1], 2e-5 * w * w * std::sin(w * t), 1e-12);
  }
}

TEST(TwoDof, DampingAndGravity) {
  ModelInputs in = inputs_6308();
  in.gravity = true;
  const auto m = make_two_dof_model(in);
  const auto f = eval_force(*m, 0.0, {0, 0}, {0.01, -0.02});
  EXPECT_NEAR(f[0], -200 * 0.01, 1e-12);
  EXPECT_NEAR(f[1], -20 - 0.6 * standard_gravity + 200 * 0.02, 1e-12);
  // The static state carries the weight too.
  const auto q0 = m->initial_displacement();
  const auto s =
      solve_static_load(8, in.contact.K, 7e-6, Eigen::Vector2d(0, -20 - 0.6 * standard_gravity));
  EXPECT_NEAR(q0[1], s.deflection.y(), 1e-15);
  EXPECT_LT(norm(eval_force(*make_two_dof_model(at_rest(in)), 0, q0, {0, 0})), 1e-9 * 26);
}

// The ball set advances one pitch in 2π/(Z ω_c): the loads repeat, shifted by one ball.
TEST(TwoDof, BallsAdvanceAtTheCageSpeed) {
  ModelInputs in = inputs_6308();
  in.load = Eigen::Vector2d(0, -500);
  const auto m = make_two_dof_model(in);
  const double pitch_time = two_pi / (8 * cage_speed(in.bearing, in.inner_speed));
  const std::vector<double> q = m->initial_displacement();
  const auto a = loads_of(*m, 0.002, q), b = loads_of(*m, 0.002 + pitch_time, q);
  for (int j = 0; j < 8; ++j) EXPECT_NEAR(b[j], a[(j + 1) % 8], 1e-9 * 500);
}

TEST(TwoDof, TvdsWithZeroAmplitudeIsTvd) {
  ModelInputs in = inputs_6308();
  in.inner_waviness.harmonics = {{8, 0.0, 0.3}, {16, 0.0, 1.0}};
  in.outer_waviness.harmonics = {{5, 0.0, 0.0}};
  const auto tvd = make_two_dof_model(in);
  in.waviness_stiffness = true;
  const auto tvds = make_two_dof_model(in);
  for (double t : {0.0, 0.01, 0.3}) {
    const std::vector<double> q{1e-6, -12e-6};
    const auto a = eval_force(*tvd, t, q, {0, 0}), b = eval_force(*tvds, t, q, {0, 0});
    for (int i = 0; i < 2; ++i) EXPECT_NEAR(a[i], b[i], 1e-12 * norm(a));
  }
}

// The first-order curvature of r(φ) = R + A sin Nφ, 1/R + A (N²−1) sin(Nφ)/R² (docs/model.md §3),
// against the curvature of the polar curve itself: the circle through three nearby points
// (step h: truncation O((N h)²), rounding O(ε R / (R h²)) relative to 1/R).
double polar_curvature(const std::function<double(double)>& r, double phi, double h) {
  auto point = [&](double p) { return Eigen::Vector2d(r(p) * std::cos(p), r(p) * std::sin(p)); };
  const Eigen::Vector2d b = point(phi);
  const Eigen::Vector2d a = point(phi - h) - b, c = point(phi + h) - b;
  const double cross = a.x() * c.y() - a.y() * c.x();  // > 0 for a curve convex about the origin
  return -2 * cross / (a.norm() * c.norm() * (a - c).norm());
}

TEST(TwoDof, TvdsCurvatureFormulaMatchesPolarCurve) {
  const double R = 0.025;
  for (int N : {5, 20, 60}) {
    for (double A : {0.1e-6, 1e-6}) {
      for (double phi : {0.1, 0.77, 2.0}) {
        auto r = [&](double p) { return R + A * std::sin(N * p); };
        const double exact = polar_curvature(r, phi, 2e-3 / N);
        const double first_order = 1 / R + A * (N * N - 1.0) * std::sin(N * phi) / (R * R);
        const double effect = A * (N * N - 1.0) / (R * R);
        // The neglected terms are O(A/R) relative to the effect; the three-point circle adds
        // O((N h)²) truncation and O(ε/h²) rounding, both below 1e-4 of the effect here.
        EXPECT_NEAR(exact, first_order, 2e-4 * effect) << N << " " << A << " " << phi;
      }
    }
  }
}

// K_j under TVDS against a reference built from the exact curvature of the wavy raceway: inner
// race r = R_i + Π (convex, ρ_II1 = +κ), outer race r = R_o − Π (concave, ρ_II1 = −κ).
TEST(TwoDof, TvdsStiffnessFollowsTheRacewayCurvature) {
  const auto exact = make_exact_hertz();
  for (bool inner : {true, false}) {
    ModelInputs in = oversize_balls(inputs_6308());
    in.waviness_stiffness = true;
    Waviness w;
    w.harmonics = {{30, 1e-6, 0.4}};
    (inner ? in.inner_waviness : in.outer_waviness) = w;
    const auto m = make_two_dof_model(in);
    const Bearing& b = in.bearing;
    const double D = b.ball_diameter;
    const double R = 0.5 * (inner ? b.inner_raceway_diameter() : b.outer_raceway_diameter());
    const Curvatures cv = race_curvatures(b, inner ? Race::inner : Race::outer);
    const RaceContact& rc = inner ? in.contact.inner : in.contact.outer;
    const RaceContact& other = inner ? in.contact.outer : in.contact.inner;
    double max_effect = 0;
    for (double t : {0.0, 0.0011, 0.0042, 0.013}) {
      const auto l = loads_of(*m, t, {0, 0});
      for (int j = 0; j < 8; ++j) {
        const double phi = theta(in, j, t) - (inner ? in.inner_speed * t : 0.0);
        const double delta = 5e-6 + w.profile(phi);
        const double K_model = l[j] / std::pow(delta, 1.5);
        auto radius = [&](double p) { return inner ? R + w.profile(p) : R - w.profile(p); };
        const double kappa = polar_curvature(radius, phi, 2e-3 / 30);
        const double rho1 = inner ? kappa : -kappa;
        const double sum = 4 / D + rho1 + cv.race_2;
        const double F = (rho1 - cv.race_2) / sum;
        const double ds = exact->shape(F).delta_star;
        const double K_race =
            std::pow(2.0, 2.5) / (3 * rc.compliance * std::pow(ds, 1.5) * std::sqrt(sum));
        const double K_ref = series_stiffness(K_race, other.K);
        const double effect = K_ref - in.contact.K;
        max_effect = std::max(max_effect, std::abs(effect) / in.contact.K);
        // With the first-order curvature itself the model's tabulated K is exact to rounding.
        const double rho1_lin = cv.race_1 - (w.profile(phi) + w.second_derivative(phi)) / (R * R);
        const double sum_lin = 4 / D + rho1_lin + cv.race_2;
        const double ds_lin = exact->shape((rho1_lin - cv.race_2) / sum_lin).delta_star;
        const double K_lin = series_stiffness(
            std::pow(2.0, 2.5) / (3 * rc.compliance * std::pow(ds_lin, 1.5) * std::sqrt(sum_lin)),
            other.K);
        EXPECT_NEAR(K_model, K_lin, 1e-10 * K_lin);
        EXPECT_NEAR(K_model - in.contact.K, effect, 0.01 * std::abs(effect) + 1e-12 * K_ref)
            << (inner ? "inner" : "outer") << " t " << t << " ball " << j;
      }
    }
    EXPECT_GT(max_effect, 1e-4);  // the test resolves the effect
  }
}

TEST(TwoDof, ForceIsThreadSafe) {
  ModelInputs in = inputs_6308();
  in.inner_waviness = seed003_table();
  in.waviness_stiffness = true;
  const auto m = make_two_dof_model(in);
  const std::vector<double> q{1e-6, -10e-6}, v{0, 0};
  std::vector<std::vector<double>> serial;
  for (int k = 0; k < 200; ++k) serial.push_back(eval_force(*m, 1e-4 * k, q, v));
  std::vector<int> mismatches(4, 0);
  std::vector<std::thread> threads;
  for (int th = 0; th < 4; ++th)
    threads.emplace_back([&, th] {
      for (int rep = 0; rep < 20; ++rep)
        for (int k = 0; k < 200; ++k)
          if (eval_force(*m, 1e-4 * k, q, v) != serial[k]) ++mismatches[th];
    });
  for (auto& t : threads) t.join();
  for (int c : mismatches) EXPECT_EQ(c, 0);
}

std::string input_error(const ModelInputs& in, bool three = false) {
  try {
    if (three)
      make_three_dof_model(in);
    else
      make_two_dof_model(in);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

TEST(TwoDof, InputErrorsNameTheKey) {
  auto with = [](auto change) {
    ModelInputs in = inputs_6308();
    change(in);
    return in;
  };
  EXPECT_NE(input_error(with([](ModelInputs& in) { in.mass = 0; })).find("rotor.mass"),
            std::string::npos);
  EXPECT_NE(input_error(with([](ModelInputs& in) { in.damping = -1; })).find("rotor.damping"),
            std::string::npos);
  EXPECT_NE(input_error(with([](ModelInputs& in) {
              in.ball_size_errors = {1e-6, 2e-6};
            })).find("ball_errors.values"),
            std::string::npos);
  EXPECT_NE(input_error(with([](ModelInputs& in) {
              in.inner_waviness.harmonics = {{0, 1e-6, 0}};
            })).find("waviness.inner"),
            std::string::npos);
  EXPECT_NE(input_error(with([](ModelInputs& in) {
              in.outer_waviness.harmonics = {{3, -1e-6, 0}};
            })).find("waviness.outer"),
            std::string::npos);
  EXPECT_NE(input_error(with([](ModelInputs& in) { in.bearing.balls = 2; })).find("bearing.balls"),
            std::string::npos);
  EXPECT_NE(input_error(with([](ModelInputs& in) { in.load.x() = NAN; })).find("operation.load"),
            std::string::npos);
}

// --- 3-DOF -----------------------------------------------------------------------------------

// Groove geometry of the inputs: A₀, u₀ = A₀ cos α₀, w₀ = A₀ sin α₀.
struct Groove {
  double A0, u0, w0;
};
Groove groove(const ModelInputs& in) {
  const Bearing& b = in.bearing;
  const double A0 = (b.inner_conformity + b.outer_conformity - 1) * b.ball_diameter;
  const double ca = 1 - b.clearance / (2 * A0);
  return {A0, A0 * ca, A0 * std::sqrt(1 - ca * ca)};
}

TEST(ThreeDof, InterfaceBasics) {
  ModelInputs in = inputs_6308();
  in.axial_damping = 50;
  const auto m = make_three_dof_model(in);
  EXPECT_EQ(m->dofs(), 3);
  EXPECT_EQ(m->dof_names(), (std::vector<std::string>{"x", "y", "z"}));
  double mass[3];
  m->mass(mass);
  EXPECT_EQ(mass[2], 0.6);  // axial_mass 0 → mass
  in.axial_mass = 1.5;
  make_three_dof_model(in)->mass(mass);
  EXPECT_EQ(mass[2], 1.5);
  const auto f = eval_force(*m, 0, {0, 0, -groove(in).w0}, {0, 0, 0.1});
  EXPECT_NEAR(f[2], -5.0, 1e-12);
}

// (a) P_d = 0 and z = 0: exactly the zero-clearance 2-DOF model; no axial contact force.
TEST(ThreeDof, WithoutClearanceReducesToTwoDof) {
  ModelInputs in = inputs_6308();
  in.bearing.clearance = 0;
  in.inner_waviness = random_waviness(25, 0.3e-6, 11);
  in.outer_waviness = random_waviness(10, 0.3e-6, 12);
  in.ball_size_errors = ball_size_errors_from_band(8, 1e-6, 13);
  in.axial_load = 0;
  const auto two = make_two_dof_model(in);
  const auto three = make_three_dof_model(in);
  for (double t : {0.0, 0.003, 0.2}) {
    for (const auto& xy : {std::vector<double>{0, -5e-6}, std::vector<double>{3e-6, 2e-6}}) {
      const auto f2 = eval_force(*two, t, xy, {0.01, 0.02});
      const auto f3 = eval_force(*three, t, {xy[0], xy[1], 0}, {0.01, 0.02, 0});
      EXPECT_NEAR(f3[0], f2[0], 1e-12 * norm(f2));
      EXPECT_NEAR(f3[1], f2[1], 1e-12 * norm(f2));
      EXPECT_EQ(f3[2], 0.0);
    }
  }
}

// (b) With clearance, at the axially centred position z = −A₀ sin α₀: exactly the 2-DOF model
// with γ = P_d/2, forces and radial stiffness; no axial contact force.
TEST(ThreeDof, CentredPositionIsTwoDofWithClearance) {
  for (double clearance : {14e-6, 60e-6}) {
    ModelInputs in = inputs_6308();
    in.bearing.clearance = clearance;
    in.inner_waviness = random_waviness(25, 0.3e-6, 21);
    in.ball_size_errors = ball_size_errors_from_band(8, 1e-6, 22);
    in.waviness_stiffness = clearance > 20e-6;  // TVDS reduces alike
    const auto two = make_two_dof_model(in);
    const auto three = make_three_dof_model(in);
    const double zc = -groove(in).w0;
    for (double t : {0.0, 0.0077}) {
      const std::vector<double> xy{2e-6, -clearance / 2 - 6e-6};
      const auto f2 = eval_force(*two, t, xy, {0, 0});
      const auto f3 = eval_force(*three, t, {xy[0], xy[1], zc}, {0, 0, 0});
      EXPECT_NEAR(f3[0], f2[0], 1e-9 * norm(f2));
      EXPECT_NEAR(f3[1], f2[1], 1e-9 * norm(f2));
      EXPECT_NEAR(f3[2], 0.0, 1e-9 * norm(f2));
      std::vector<double> j2(4), d2(4), j3(9), d3(9);
      two->force_jacobian(t, xy.data(), xy.data(), j2.data(), d2.data());
      const std::vector<double> q3{xy[0], xy[1], zc};
      three->force_jacobian(t, q3.data(), q3.data(), j3.data(), d3.data());
      EXPECT_NEAR(j3[0], j2[0], 1e-9 * std::abs(j2[3]));
      EXPECT_NEAR(j3[1], j2[1], 1e-9 * std::abs(j2[3]));
      EXPECT_NEAR(j3[4], j2[3], 1e-9 * std::abs(j2[3]));
      EXPECT_NEAR(j3[2], 0.0, 1e-9 * std::abs(j2[3]));  // no radial–axial coupling at α = 0
    }
  }
}

// (c) Near the centred position the difference is second order in ζ = z + w₀, and the axial
// force is the geometric stiffness −ζ Σ Q_j/(A₀ + δ_j).
TEST(ThreeDof, NearCentredDifferenceIsSecondOrder) {
  ModelInputs in = contact_only(inputs_6308());
  const auto two = make_two_dof_model(in);
  const auto three = make_three_dof_model(in);
  const Groove g = groove(in);
  const std::vector<double> xy{1e-6, -15e-6};
  const auto f2 = eval_force(*two, 0.01, xy, {0, 0});
  const auto loads = loads_of(*two, 0.01, xy);
  double geometric = 0;
  for (int j = 0; j < 8; ++j)
    if (loads[j] > 0) geometric += loads[j] / (g.A0 + approach_from_load(loads[j], in.contact.K));
  double previous = 0;
  for (double zeta : {4e-6, 2e-6, 1e-6}) {
    const auto f3 = eval_force(*three, 0.01, {xy[0], xy[1], -g.w0 + zeta}, {0, 0, 0});
    const double diff = std::hypot(f3[0] - f2[0], f3[1] - f2[1]);
    if (previous > 0) EXPECT_NEAR(previous / diff, 4.0, 0.05);
    previous = diff;
    // Next term: Q_j changes by (3/2) ζ²/(2 L_j δ_j) relative (≈ 1.6e-4 per µm² here).
    EXPECT_NEAR(f3[2], -zeta * geometric,
                2.5e-4 * (zeta / 1e-6) * (zeta / 1e-6) * zeta * geometric);
  }
}

// (d) At z = 0 with clearance the balls touch at α₀; to first order in r/A₀ the radial force is
// the zero-clearance 2-DOF one with K cos^{5/2} α₀.
TEST(ThreeDof, FreeContactAngleScalesTheRadialForce) {
  ModelInputs in = contact_only(inputs_6308());
  in.bearing.clearance = 30e-6;
  const Groove g = groove(in);
  const double ca = g.u0 / g.A0;
  const auto three = make_three_dof_model(in);
  ModelInputs flat = in;
  flat.bearing.clearance = 0;
  flat.contact.K = in.contact.K * std::pow(ca, 2.5);
  const auto two = make_two_dof_model(flat);
  const std::vector<double> xy{0.5e-6, -4e-6};
  const auto f2 = eval_force(*two, 0, xy, {0, 0});
  const auto f3 = eval_force(*three, 0, {xy[0], xy[1], 0}, {0, 0, 0});
  const double r_over_A = 4e-6 / g.A0;
  EXPECT_NEAR(f3[0], f2[0], 5 * r_over_A * norm(f2));
  EXPECT_NEAR(f3[1], f2[1], 5 * r_over_A * norm(f2));
  EXPECT_LT(f3[2], 0.0);  // the loaded balls push the ring back axially
}

TEST(ThreeDof, AxialPreloadMatchesHarrisClosedForm) {
  for (double clearance : {0.0, 14e-6, 40e-6}) {
    for (double Fz : {1.0, 50.0, 1000.0, 20000.0}) {
      ModelInputs in = at_rest(inputs_6308());
      in.bearing.clearance = clearance;
      in.load.setZero();
      in.axial_load = Fz;
      const AxialPreload p = solve_axial_preload(in);
      const Groove g = groove(in);
      const double ca0 = g.u0 / g.A0;
      const double a = p.contact_angle;
      ASSERT_GT(a, 0.0);
      // Harris: F_z = Z K [A₀ (cos α₀/cos α − 1)]^{3/2} sin α.
      const double harris =
          8 * in.contact.K * std::pow(g.A0 * (ca0 / std::cos(a) - 1), 1.5) * std::sin(a);
      EXPECT_NEAR(harris, Fz, 1e-7 * Fz) << clearance << " " << Fz;
      EXPECT_NEAR(8 * p.ball_load * std::sin(a), Fz, 1e-10 * Fz);
      // The model is in equilibrium there, every ball carrying p.ball_load.
      const auto m = make_three_dof_model(in);
      const auto f = eval_force(*m, 0.3, {0, 0, p.z}, {0, 0, 0});
      EXPECT_LT(norm(f), 1e-9 * Fz);
      for (double Q : loads_of(*m, 0.3, {0, 0, p.z})) EXPECT_NEAR(Q, p.ball_load, 1e-9 * Q);
      const auto q0 = m->initial_displacement();
      EXPECT_NEAR(q0[2], p.z, 1e-12 * std::abs(p.z) + 1e-18);
      // Symmetric about the centred position for a negative load.
      in.axial_load = -Fz;
      const AxialPreload n = solve_axial_preload(in);
      EXPECT_NEAR(n.z, -2 * g.w0 - p.z, 1e-12 * (g.w0 + std::abs(p.z)));
      EXPECT_NEAR(n.contact_angle, -a, 1e-12);
      EXPECT_NEAR(n.ball_load, p.ball_load, 1e-10 * p.ball_load);
    }
  }
  // Seed 001 eq. (2.21) is the α₀ = 0 case: P = Z K [A₀ (1/cos α − 1)]^{3/2} sin α.
  ModelInputs in = inputs_6308();
  in.bearing.clearance = 0;
  in.axial_load = 30;
  const AxialPreload p = solve_axial_preload(in);
  const double A0 = groove(in).A0;
  EXPECT_NEAR(8 * in.contact.K * std::pow(A0 * (1 / std::cos(p.contact_angle) - 1), 1.5) *
                  std::sin(p.contact_angle),
              30.0, 1e-6);
}

TEST(ThreeDof, NoAxialLoadStartsCentred) {
  ModelInputs in = at_rest(inputs_6308());
  const AxialPreload p = solve_axial_preload(in);
  EXPECT_NEAR(p.z, -groove(in).w0, 1e-18);
  EXPECT_EQ(p.contact_angle, 0.0);
  EXPECT_EQ(p.ball_load, 0.0);
  const auto m = make_three_dof_model(in);
  const auto q0 = m->initial_displacement();
  const auto s = solve_static_load(8, in.contact.K, 7e-6, in.load);
  EXPECT_NEAR(q0[0], s.deflection.x(), 1e-15);
  EXPECT_NEAR(q0[1], s.deflection.y(), 1e-15);
  EXPECT_NEAR(q0[2], -groove(in).w0, 1e-18);
  EXPECT_LT(norm(eval_force(*m, 0, q0, {0, 0, 0})), 1e-9 * 20);
  // With a radial load the centred state is stable axially: positive axial stiffness.
  std::vector<double> J(9), Jv(9);
  m->force_jacobian(0, q0.data(), q0.data(), J.data(), Jv.data());
  EXPECT_LT(J[8], 0.0);
  EXPECT_EQ(three_dof_cage_speed(in), cage_speed(in.bearing, in.inner_speed));
}

TEST(ThreeDof, InitialDisplacementIsEquilibriumUnderCombinedLoads) {
  for (double clearance : {0.0, 14e-6}) {
    for (const Eigen::Vector3d& F : {Eigen::Vector3d(0, -20, 50), Eigen::Vector3d(0, -2000, 100),
                                     Eigen::Vector3d(300, 100, -400)}) {
      ModelInputs in = at_rest(inputs_6308());
      in.bearing.clearance = clearance;
      in.load = F.head<2>();
      in.axial_load = F.z();
      in.gravity = true;
      const auto m = make_three_dof_model(in);
      const auto q0 = m->initial_displacement();
      const auto f = eval_force(*m, 0, q0, {0, 0, 0});
      EXPECT_LT(norm(f), 1e-9 * F.norm()) << clearance << " " << F.transpose();
    }
  }
}

// Radial stiffness (linearised at the static state) grows with the axial preload.
TEST(ThreeDof, AxialPreloadRaisesRadialStiffness) {
  double previous = 0;
  for (double Fz : {0.0, 20.0, 100.0, 500.0, 2000.0}) {
    ModelInputs in = at_rest(inputs_6308());
    in.axial_load = Fz;
    const auto m = make_three_dof_model(in);
    const auto q0 = m->initial_displacement();
    std::vector<double> J(9), Jv(9);
    m->force_jacobian(0, q0.data(), q0.data(), J.data(), Jv.data());
    const double kyy = -J[4];
    EXPECT_GT(kyy, previous) << Fz;
    previous = kyy;
  }
}

// The cage speed follows the loaded contact angle (BPF changes with preload), and the model's
// balls advance at that speed.
TEST(ThreeDof, AxialPreloadChangesTheCageSpeed) {
  ModelInputs in = inputs_6308();
  const double w2 = cage_speed(in.bearing, in.inner_speed);
  double previous = w2;
  for (double Fz : {10.0, 100.0, 1000.0}) {
    in.axial_load = Fz;
    const AxialPreload p = solve_axial_preload(in);
    const double wc = three_dof_cage_speed(in);
    const double g =
        in.bearing.ball_diameter * std::cos(p.contact_angle) / in.bearing.pitch_diameter;
    EXPECT_NEAR(wc, 0.5 * in.inner_speed * (1 - g), 1e-12 * wc);
    EXPECT_GT(wc, previous);
    previous = wc;
  }
  in.axial_load = 300;
  in.load = Eigen::Vector2d(0, -500);
  const auto m = make_three_dof_model(in);
  const auto q0 = m->initial_displacement();
  const double pitch_time = two_pi / (8 * three_dof_cage_speed(in));
  const auto a = loads_of(*m, 0.003, q0), b = loads_of(*m, 0.003 + pitch_time, q0);
  for (int j = 0; j < 8; ++j) EXPECT_NEAR(b[j], a[(j + 1) % 8], 1e-9 * a[(j + 1) % 8]);
  // ... and not at the 2-DOF cage speed.
  const auto c = loads_of(*m, 0.003 + two_pi / (8 * w2), q0);
  double diff = 0;
  for (int j = 0; j < 8; ++j) diff = std::max(diff, std::abs(c[j] - a[(j + 1) % 8]));
  EXPECT_GT(diff, 1e-6);
}

TEST(ThreeDof, PotentialGradientAndJacobian) {
  ModelInputs in = inputs_6308();
  in.inner_waviness = random_waviness(30, 0.2e-6, 31);
  in.outer_waviness = random_waviness(8, 0.4e-6, 32);
  in.ball_size_errors = ball_size_errors_from_band(8, 1e-6, 33);
  in.axial_damping = 70;
  in.unbalance = 1e-4;
  for (bool tvds : {false, true}) {
    in.waviness_stiffness = tvds;
    for (double z : {-groove(in).w0 + 3e-6, 5e-6}) {
      const auto m = make_three_dof_model(in);
      const std::vector<double> q{2e-6, -10e-6, z};
      for (double t : {0.0, 0.0051}) {
        expect_jacobian_matches(*m, t, q, {0.01, 0.02, -0.03}, 1e-6);
        expect_energy_gradient_is_force(*make_three_dof_model(contact_only(in)), t, q);
      }
    }
  }
}

TEST(ThreeDof, InputErrors) {
  ModelInputs in = inputs_6308();
  in.bearing.clearance = 2.5 * groove(in).A0;
  EXPECT_NE(input_error(in, true).find("bearing.clearance"), std::string::npos);
  in = inputs_6308();
  in.axial_mass = -1;
  EXPECT_NE(input_error(in, true).find("rotor.axial_mass"), std::string::npos);
  in = inputs_6308();
  in.axial_damping = NAN;
  EXPECT_NE(input_error(in, true).find("rotor.axial_damping"), std::string::npos);
  in = inputs_6308();
  in.axial_load = INFINITY;
  EXPECT_NE(input_error(in, true).find("operation.axial_load"), std::string::npos);
}

// The axial root search doubles its bracket at most 201 times (numerics::grow_bracket), then
// reports it as a solver error: a load 600 decades below the contact constant.
TEST(ThreeDof, AxialLoadOutOfReachIsASolverError) {
  ModelInputs in = inputs_6308();
  in.contact.K = 1e300;
  in.axial_load = 1e-300;
  try {
    solve_axial_preload(in);
    ADD_FAILURE() << "no error";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("could not bracket the ball approach"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace bearing

// The cage angle's (cos, sin) come from a table rotated by a Taylor series (phasor.h), not libm:
// within a few ulp of libm over the angles a run reaches, including large ones and negatives.
#include "../../lumped/src/models/phasor.h"
TEST(TwoDofPhasor, MatchesLibmToAFewUlp) {
  double worst = 0;
  for (int i = -200000; i <= 200000; ++i) {
    const double theta = i * 0.0123456789 + 1e-3 * std::sin(i);  // ±2470 rad, irregular
    const auto p = bearing::detail::phasor(theta);
    worst = std::max({worst, std::fabs(p.c - std::cos(theta)), std::fabs(p.s - std::sin(theta))});
  }
  EXPECT_LT(worst, 4e-16);
  for (double theta : {0.0, 1e-300, -1e-12, bearing::pi, 1e5, -7.5e5}) {
    const auto p = bearing::detail::phasor(theta);
    EXPECT_NEAR(p.c, std::cos(theta), 2e-15 + 1e-16 * std::fabs(theta)) << theta;
    EXPECT_NEAR(p.s, std::sin(theta), 2e-15 + 1e-16 * std::fabs(theta)) << theta;
    EXPECT_NEAR(p.c * p.c + p.s * p.s, 1.0, 4e-16) << theta;
  }
}

// --- Ball DOFs, cage slip and traction (models/ball_dofs.h) ---------------------------------

namespace bearing {
namespace {
namespace balls {

// Seed 004's SKF 6304 (Table 1): 2000 rpm, 2000 N along +x, m = 0.4 kg, c = 350 N s/m, its
// P_d = 15 µm as the per-ball gap (clearance 30 µm), μ_m = 0.05 at Δv_m = 0.1 m/s.
ModelInputs inputs_6304(double slip = 0.0, double friction = 0.05) {
  ModelInputs in;
  in.bearing = preset("6304");
  in.bearing.clearance = 30e-6;
  in.contact = contact_constants(in.bearing, *make_exact_hertz());
  in.inner_speed = 2000 * two_pi / 60;
  in.load = Eigen::Vector2d(2000, 0);
  in.mass = 0.4;
  in.damping = 350;
  in.cage_slip = slip;
  in.traction = make_traction_curve(friction, 0.1);
  in.ball_damping = 350;
  in.centrifugal = true;
  return in;
}

// A state away from equilibrium with every kind of contact: loaded balls, open ones, spins off
// their rolling value (sliding inside the linear traction range) and a moving ring.
void perturbed_state(const BallDofModel& m, std::vector<double>& q, std::vector<double>& v) {
  q = m.initial_displacement();
  v = m.initial_velocity();
  const int Z = m.balls();
  q[0] += 1.3e-6;
  q[1] -= 0.7e-6;
  v[0] = 0.012;
  v[1] = -0.008;
  for (int j = 0; j < Z; ++j) {
    q[2 + j] += 0.2e-6 * std::sin(1.7 * j + 0.5);
    v[2 + j] = 0.003 * std::cos(0.9 * j);
    v[2 + Z + j] *= 1.0 + 0.004 * std::sin(2.3 * j + 0.4);
  }
}

TEST(BallDofs, InterfaceAndMassesFromTheDensity) {
  const auto m = make_ball_dof_model(inputs_6304());
  const int Z = 7;
  EXPECT_EQ(m->dofs(), 2 * Z + 2);
  EXPECT_EQ(m->balls(), Z);
  EXPECT_EQ(m->dof_names(), (std::vector<std::string>{"x", "y"}));
  std::vector<double> mass(m->dofs());
  m->mass(mass.data());
  const double D = 9.525e-3, mb = 7850 * pi * D * D * D / 6;
  EXPECT_EQ(mass[0], 0.4);
  EXPECT_NEAR(mass[2], mb, 1e-15);
  EXPECT_NEAR(mass[2 + Z], mb * D * D / 10, 1e-20);  // solid sphere, 2/5 m (D/2)²
  for (int i = 0; i < m->dofs(); ++i) EXPECT_EQ(m->cyclic(i), i >= 2 + Z) << i;
  // Centrifugal load m_b ω_ca² d_m/2 at the pure-rolling cage speed.
  const double wc = cage_speed(preset("6304"), 2000 * two_pi / 60);
  EXPECT_NEAR(m->centrifugal_force(), mb * wc * wc * 0.018, 1e-12);
  EXPECT_NEAR(m->cage_speed(), wc, 1e-12);
  EXPECT_NEAR(make_ball_dof_model(inputs_6304(0.05))->cage_speed(), 0.95 * wc, 1e-12);
}

// The ball's two contacts carry the 2-DOF model's approach between them: at the initial state
// (each ball in equilibrium, no centrifugal load) the ring force equals the 2-DOF model's, and
// each loaded ball's two loads are equal.
TEST(BallDofs, MasslessBallEquilibriumIsTheTwoDofContact) {
  for (bool tvds : {false, true}) {
    SCOPED_TRACE(tvds ? "TVDS" : "TVD");
    ModelInputs in = inputs_6304(0.0, 0.0);
    in.centrifugal = false;
    in.hertz_method = HertzMethod::exact;
    in.waviness_stiffness = tvds;
    in.outer_waviness.harmonics = {{9, 0.4e-6, 0.3}, {16, 0.2e-6, 1.1}};
    in.inner_waviness.harmonics = {{5, 0.3e-6, 2.0}};
    in.ball_size_errors = {0.5e-6, -0.3e-6, 0, 0.2e-6, 0, -0.6e-6, 0.1e-6};
    const auto balls = make_ball_dof_model(in);
    const auto two = make_two_dof_model(in);
    const auto q = balls->initial_displacement();
    const auto v0 = std::vector<double>(balls->dofs(), 0.0);
    std::vector<double> f(balls->dofs()), f2(2);
    balls->force(0.0, q.data(), v0.data(), f.data());
    const double qr[2] = {q[0], q[1]}, vr[2] = {0, 0};
    two->force(0.0, qr, vr, f2.data());
    EXPECT_NEAR(f[0], f2[0], 1e-9 * 2000);
    EXPECT_NEAR(f[1], f2[1], 1e-9 * 2000);
    for (int j = 0; j < 7; ++j) EXPECT_NEAR(f[2 + j], 0.0, 1e-9 * 2000) << "ball " << j;
    std::vector<double> a1(7), a2(7);
    balls->ball_approaches(0.0, q.data(), a1.data());
    two->ball_approaches(0.0, qr, a2.data());
    for (int j = 0; j < 7; ++j) EXPECT_NEAR(a1[j], a2[j], 1e-15) << "ball " << j;
  }
}

TEST(BallDofs, AnalyticJacobianMatchesDifferences) {
  for (double slip : {0.0, 0.03}) {
    ModelInputs in = inputs_6304(slip);
    in.outer_waviness.harmonics = {{9, 0.4e-6, 0.3}};
    in.inner_waviness.harmonics = {{5, 0.3e-6, 2.0}};
    const auto m = make_ball_dof_model(in);
    std::vector<double> q, v;
    perturbed_state(*m, q, v);
    // (Every contact is clear of its kink at δ = 0 by much more than the difference step.)
    for (double t : {0.0, 3.1e-3}) expect_jacobian_matches(*m, t, q, v, 1e-6);
  }
}

// −∇V is the contact force on every DOF (no load, damping, friction or centrifugal load).
TEST(BallDofs, PotentialGradientIsTheContactForce) {
  ModelInputs in = contact_only(inputs_6304(0.0, 0.0));
  in.damping = 0;
  in.ball_damping = 0;
  in.centrifugal = false;
  in.outer_waviness.harmonics = {{9, 0.4e-6, 0.3}};
  const auto m = make_ball_dof_model(in);
  std::vector<double> q, v;
  perturbed_state(*m, q, v);
  q[0] += 10e-6;  // load the balls on the +x side
  expect_energy_gradient_is_force(*m, 2e-3, q);
}

// The friction powers: what the DOFs and the drives receive adds up to minus what the contacts
// dissipate (an identity of the derived force directions), and the dissipation is Σ μ Q Δv
// computed here from traction.h's own sliding speeds and forces.
TEST(BallDofs, FrictionPowersAddUpToTheDissipation) {
  const auto m = make_ball_dof_model(inputs_6304(0.03));
  std::vector<double> q, v;
  perturbed_state(*m, q, v);
  const int Z = 7;
  const double t = 1.7e-3;
  const FrictionPower p = m->friction_power(t, q.data(), v.data());
  EXPECT_GT(p.dissipated, 0.0);
  EXPECT_NEAR(p.on_dofs + p.drives, -p.dissipated, 1e-12 * p.dissipated);
  // Independently: traction.h's contact_traction with the ring's translation left out of Δv_i
  // (traction.h has no ring velocity), so compare with the ring at rest.
  std::vector<double> v_rest = v;
  v_rest[0] = v_rest[1] = 0;
  const Bearing b = preset("6304");
  const TractionCurve curve = make_traction_curve(0.05, 0.1);
  std::vector<double> qi(Z), qo(Z), spin(Z), fi(Z), fo(Z);
  m->ball_loads(t, q.data(), qi.data());
  m->ball_dynamics(t, q.data(), v_rest.data(), spin.data(), qo.data(), fi.data(), fo.data());
  double expected = 0;
  for (int j = 0; j < Z; ++j) {
    const SlidingSpeeds s = sliding_speeds(b, 2000 * two_pi / 60, m->cage_speed(), spin[j]);
    const ContactTraction tr = contact_traction(curve, s, qi[j], qo[j]);
    expected += tr.power;
    EXPECT_NEAR(fi[j], tr.on_ball_inner, 1e-12 * 2000);
    EXPECT_NEAR(fo[j], tr.on_ball_outer, 1e-12 * 2000);
  }
  EXPECT_NEAR(m->friction_power(t, q.data(), v_rest.data()).dissipated, expected, 1e-12 * expected);
}

// Seed 004's starting spin: no spin torque on a ball with equal loads, and the pure-rolling
// spin when the cage does not slip.
TEST(BallDofs, InitialSpinIsKinematic) {
  const Bearing b = preset("6304");
  const double wi = 2000 * two_pi / 60;
  const auto m0 = make_ball_dof_model(inputs_6304(0.0));
  EXPECT_NEAR(m0->initial_velocity()[2 + 7], rolling_ball_spin(b, wi), 1e-9 * wi);
  const auto m = make_ball_dof_model(inputs_6304(0.05));
  const double w = m->initial_velocity()[2 + 7];
  const SlidingSpeeds s = sliding_speeds(b, wi, m->cage_speed(), w);
  EXPECT_NEAR(s.inner, -s.outer, 1e-12);
  EXPECT_GT(s.inner, 0.0);  // the inner race drives, the outer brakes
}

TEST(BallDofs, RejectsBadInputsNamingTheKey) {
  const auto fails_with = [](ModelInputs in, const std::string& key) {
    try {
      make_ball_dof_model(in);
      ADD_FAILURE() << "no error for " << key;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  ModelInputs in = inputs_6304();
  in.cage_slip = 1.0;
  fails_with(in, "cage.slip");
  in = inputs_6304();
  in.cage_slip = -0.01;
  fails_with(in, "cage.slip");
  in = inputs_6304();
  in.ball_mass = -1;
  fails_with(in, "ball.mass");
  in = inputs_6304();
  in.ball_damping = std::nan("");
  fails_with(in, "ball.damping");
  in = inputs_6304();
  in.traction.max_coefficient = -0.1;
  fails_with(in, "cage.friction");
  in = inputs_6304();
  in.axial_load = 100;
  in.axial_damping = -1;
  fails_with(in, "rotor.axial_damping");
}

// With an axial load the ball sits on the 3-DOF model's contact line: massless balls in
// equilibrium (no centrifugal load, no friction) give the ring exactly the 3-DOF model's force,
// z included, and the balls' total approaches are its δ_j.
TEST(BallDofs, AxialLoadGivesTheThreeDofContactWithMasslessBalls) {
  ModelInputs in = inputs_6304(0.0, 0.0);
  in.centrifugal = false;
  in.axial_load = 500;
  in.axial_mass = 0.4;
  in.outer_waviness.harmonics = {{9, 0.4e-6, 0.3}};
  in.inner_waviness.harmonics = {{5, 0.3e-6, 2.0}};
  in.ball_size_errors = {0.5e-6, -0.3e-6, 0, 0.2e-6, 0, -0.6e-6, 0.1e-6};
  const auto balls = make_ball_dof_model(in);
  const auto three = make_three_dof_model(in);
  EXPECT_EQ(balls->dofs(), 2 * 7 + 3);
  EXPECT_EQ(balls->dof_names(), (std::vector<std::string>{"x", "y", "z"}));
  EXPECT_NEAR(balls->cage_speed(), three_dof_cage_speed(in), 1e-12);
  const auto q = balls->initial_displacement();
  const auto q3 = three->initial_displacement();
  for (int i = 0; i < 3; ++i) EXPECT_EQ(q[i], q3[i]) << i;
  const std::vector<double> v(balls->dofs(), 0.0), v3(3, 0.0);
  const auto f = eval_force(*balls, 0.0, q, v);
  const auto f3 = eval_force(*three, 0.0, {q[0], q[1], q[2]}, v3);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(f[i], f3[i], 1e-9 * 2000) << "ring " << i;
  for (int j = 0; j < 7; ++j) EXPECT_NEAR(f[3 + j], 0.0, 1e-9 * 2000) << "ball " << j;
  std::vector<double> a(7), a3(7);
  balls->ball_approaches(0.0, q.data(), a.data());
  three->ball_approaches(0.0, q3.data(), a3.data());
  for (int j = 0; j < 7; ++j) EXPECT_NEAR(a[j], a3[j], 1e-15) << "ball " << j;
}

TEST(BallDofs, AxialJacobianAndPotentialGradient) {
  ModelInputs in = inputs_6304(0.03);
  in.axial_load = 500;
  in.outer_waviness.harmonics = {{9, 0.4e-6, 0.3}};
  const auto m = make_ball_dof_model(in);
  std::vector<double> q = m->initial_displacement(), v = m->initial_velocity();
  q[0] += 1.1e-6;
  q[2] -= 0.6e-6;
  v[0] = 0.01, v[1] = -0.007, v[2] = 0.004;
  for (int j = 0; j < 7; ++j) q[3 + j] += 0.15e-6 * std::sin(1.3 * j + 0.2);
  expect_jacobian_matches(*m, 1e-3, q, v, 1e-6);
  ModelInputs free = contact_only(in);
  free.damping = free.axial_damping = free.ball_damping = 0;
  free.centrifugal = false;
  free.traction = make_traction_curve(0.0, 0.1);
  free.axial_load = 500;  // the axial geometry needs the load; it is taken off f[2] below
  const auto mf = make_ball_dof_model(free);
  // −∇V is the contact force on the ring's and the balls' DOFs (the spins have no potential).
  std::vector<double> f(mf->dofs());
  const std::vector<double> zero(mf->dofs(), 0.0);
  mf->force(1e-3, q.data(), zero.data(), f.data());
  f[2] -= 500;
  const double h = 1e-10;
  double scale = 0;
  for (double x : f) scale = std::max(scale, std::abs(x));
  for (int i = 0; i < mf->dofs() - 7; ++i) {
    auto qp = q, qm = q;
    qp[i] += h;
    qm[i] -= h;
    const double grad =
        (mf->potential_energy(1e-3, qp.data()) - mf->potential_energy(1e-3, qm.data())) / (2 * h);
    EXPECT_NEAR(-grad, f[i], 1e-6 * scale) << "dof " << i;
  }
}

}  // namespace balls
}  // namespace
}  // namespace bearing
