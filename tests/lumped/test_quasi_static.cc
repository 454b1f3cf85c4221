// The quasi-static model (seed 000) and the ball-centre motion channels (output.ball_motion):
// each check compares with something computed independently — the force balance recomputed from
// the ball loads, the ball-pass period, finite differences, the 2-DOF model in its slow limit,
// solve_static_load.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bearing/case_file.h"
#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/kinematics.h"
#include "bearing/models/quasi_static.h"
#include "bearing/models/two_dof.h"
#include "bearing/simulation.h"
#include "bearing/static_load.h"

namespace bearing {
namespace {

// The seed 000 608 at 720 rpm, 50 N down, quasistatic, with overrides.
Case case_608(std::vector<std::string> sets = {}) {
  std::vector<Override> o;
  for (const auto& s : sets) o.push_back(parse_override(s));
  return read_case_file(std::string(BEARING_SOURCE_DIR) + "/examples/seed000_608_quasistatic.toml",
                        o);
}

// The same bearing and operating point without waviness or ball errors.
Case perfect_608(std::vector<std::string> sets = {}) {
  std::vector<Override> o;
  for (const auto& s : sets) o.push_back(parse_override(s));
  return parse_case(
      "[bearing]\npreset = \"608\"\n[operation]\nspeed = \"720 rpm\"\nload = [0, -50]\n"
      "[model]\nkind = \"quasistatic\"\n",
      "perfect_608.toml", o);
}

// Independent force balance: Σ Q_j (cos θ_j, sin θ_j) − F with θ_j from the kinematics and F the
// load plus the unbalance's m_u e ω² turning with the shaft (ω t from t = 0).
double relative_residual(const Case& c, const QuasiStaticModel& m, const QuasiStaticPoint& p) {
  const int Z = c.bearing.balls;
  std::vector<double> Q(Z);
  m.ball_loads(p.t, p.position, Q.data());
  const double wc = cage_speed(c.bearing, c.operation.speed);
  const double w = c.operation.speed;
  Eigen::Vector2d g = -c.operation.load - c.operation.unbalance * w * w *
                                              Eigen::Vector2d(std::cos(w * p.t), std::sin(w * p.t));
  for (int j = 0; j < Z; ++j) {
    const double th = two_pi * j / Z + wc * p.t;
    g += Q[j] * Eigen::Vector2d(std::cos(th), std::sin(th));
  }
  return g.norm() / c.operation.load.norm();
}

TEST(QuasiStatic, ForceBalanceBelow1e9AtEveryInstantWithWavinessAndBallErrors) {
  const Case c = case_608({"ball_errors.band=3um", "operation.load=[5,-30]"});
  const auto m = make_quasi_static_model(model_inputs(c));
  std::vector<double> times;
  for (int k = 0; k <= 4000; ++k) times.push_back(k * 1e-4);
  double worst = 0, worst_reported = 0;
  const QuasiStaticStats st = follow_equilibrium(*m, times, [&](const QuasiStaticPoint& p) {
    worst = std::max(worst, relative_residual(c, *m, p));
    worst_reported = std::max(worst_reported, p.residual);
  });
  EXPECT_LT(worst, 1e-9);
  EXPECT_LT(worst_reported, 1e-9);
  EXPECT_DOUBLE_EQ(st.max_relative_residual, worst_reported);
  EXPECT_EQ(st.steps, 4001);
  EXPECT_GE(st.min_loaded_balls, 2);
}

// The unbalance's rotating force is part of the balance: 10 N turning at the shaft speed on 50 N.
TEST(QuasiStatic, ForceBalanceIncludesTheRotatingUnbalance) {
  const Case c0 = case_608();
  const double w = c0.operation.speed;
  const Case c = case_608({"operation.unbalance=" + std::to_string(10.0 / (w * w)) + " kg*m"});
  ASSERT_NEAR(c.operation.unbalance * w * w, 10.0, 1e-3);  // to_string keeps 6 decimals
  const auto m = make_quasi_static_model(model_inputs(c));
  std::vector<double> times;
  for (int k = 0; k <= 800; ++k) times.push_back(k * 1e-4);
  double worst = 0;
  follow_equilibrium(*m, times, [&](const QuasiStaticPoint& p) {
    worst = std::max(worst, relative_residual(c, *m, p));
  });
  EXPECT_LT(worst, 1e-9);
}

// The run's statistics from what it observed: contact changes counted from the balls' loads at
// consecutive instants, and the progress reaching 1 at the last instant.
TEST(QuasiStatic, StatisticsCountWhatTheRunObserved) {
  const Case c = case_608();
  const auto m = make_quasi_static_model(model_inputs(c));
  std::vector<double> times;
  for (int k = 0; k <= 3000; ++k) times.push_back(k * 1e-4);
  const int Z = c.bearing.balls;
  std::vector<double> loads(Z), previous(Z);
  long changes = 0, points = 0;
  std::vector<double> fractions;
  const QuasiStaticStats st = follow_equilibrium(
      *m, times,
      [&](const QuasiStaticPoint& p) {
        m->ball_loads(p.t, p.position, loads.data());
        if (points++ > 0)
          for (int j = 0; j < Z; ++j) changes += (loads[j] > 0) != (previous[j] > 0);
        previous = loads;
      },
      [&](double f) { fractions.push_back(f); });
  EXPECT_GT(changes, 10);  // balls enter and leave the load zone
  EXPECT_EQ(st.contact_changes, changes);
  ASSERT_FALSE(fractions.empty());
  EXPECT_EQ(fractions.back(), 1.0);
  EXPECT_EQ(fractions.size(), 4u);  // k = 0, 1024, 2048 and the last
}

// Without excitations the ball set repeats itself every ball pass: x(t + 1/BPFO) = x(t).
TEST(QuasiStatic, PerfectBearingOrbitIsPeriodicAtTheBallPassPeriod) {
  const Case c = perfect_608();
  const auto m = make_quasi_static_model(model_inputs(c));
  const double T = 1.0 / bearing_frequencies(c.bearing, c.operation.speed).bpfo;
  const double scale = m->static_position().norm();
  for (double t : {0.0, 0.0123, 0.031, 0.07}) {
    const QuasiStaticPoint a = m->solve(t, m->static_position());
    const QuasiStaticPoint b = m->solve(t + T, m->static_position());
    EXPECT_LT((a.position - b.position).norm(), 1e-9 * scale) << "t = " << t;
  }
}

// The implicit-function velocity against a centred difference of two solved positions.
TEST(QuasiStatic, VelocityAgreesWithCentredDifferenceOfSolvedPositions) {
  const Case c = case_608();
  const auto m = make_quasi_static_model(model_inputs(c));
  const double h = 1e-7;  // s; the orbit changes on ~1/(7 BPFI) ≈ 3 ms
  for (double t : {0.0101, 0.0237, 0.05, 0.0913}) {
    const QuasiStaticPoint p = m->solve(t, m->static_position());
    const QuasiStaticPoint lo = m->solve(t - h, p.position);
    const QuasiStaticPoint hi = m->solve(t + h, p.position);
    const Eigen::Vector2d fd = (hi.position - lo.position) / (2 * h);
    EXPECT_LT((fd - p.velocity).norm(), 1e-5 * p.velocity.norm() + 1e-9) << "t = " << t;
  }
}

// Slow excitation, heavy damping: the 2-DOF response follows the equilibrium (inertia and damping
// forces ~ c v ≈ 1e-3 N against 50 N), so both orbits agree to 1e-3 of the deflection.
TEST(QuasiStatic, EqualsTheTwoDofSteadyResponseInTheSlowLimit) {
  const std::vector<std::string> common = {"operation.speed=6rpm",    "rotor.damping=5000",
                                           "solver.duration=0.6",     "solver.transient=0.1",
                                           "solver.output_rate=1000", "output.ball_motion=false",
                                           "output.ball_loads=false"};
  std::vector<std::string> q = common, d = common;
  q.push_back("model.kind=quasistatic");
  d.push_back("model.kind=2dof");
  d.push_back("solver.method=rkf45");
  d.push_back("solver.tolerance=1e-9");
  const Case cq = case_608(q), cd = case_608(d);
  const SimulationResult rq = simulate(cq), rd = simulate(cd);
  const double scale = std::hypot(rq.response.channel("x")[0], rq.response.channel("y")[0]);
  double worst = 0;
  for (std::size_t k = rq.response.first_steady; k < rq.response.time.size(); ++k)
    worst = std::max(worst, std::hypot(rq.response.channel("x")[k] - rd.response.channel("x")[k],
                                       rq.response.channel("y")[k] - rd.response.channel("y")[k]));
  EXPECT_LT(worst, 1e-3 * scale);
}

// No excitation, no speed: the equilibrium, found from the bearing centre (a start where no ball
// is loaded, so the damped Newton must run), is solve_static_load's.
TEST(QuasiStatic, StaticSolutionEqualsSolveStaticLoad) {
  const Case c = perfect_608({"operation.speed=0", "operation.load=[12,-37]"});
  const auto m = make_quasi_static_model(model_inputs(c));
  const QuasiStaticPoint p = m->solve(0.0, Eigen::Vector2d::Zero());
  const ContactConstants k = contact_constants(c);
  const StaticLoadResult s =
      solve_static_load(c.bearing.balls, k.K, c.bearing.ball_gap(), c.operation.load);
  EXPECT_TRUE(p.fallback);
  EXPECT_LT((p.position - s.deflection).norm(), 1e-9 * s.deflection.norm());
  EXPECT_LT(p.velocity.norm(), 1e-12);
}

TEST(QuasiStatic, RejectsLoadsBelowTheMinimumNamingTheKey) {
  const ModelInputs in = model_inputs(case_608());
  const double fmin = quasi_static_minimum_load(in);
  EXPECT_NEAR(fmin, 12.34, 0.01);  // 608: K = 6.652e9 N/m^1.5, γ = 2.5 µm, Z = 7
  for (double load : {0.0, 5.0, 12.0}) {
    ModelInputs bad = in;
    bad.load = Eigen::Vector2d(0, -load);
    try {
      make_quasi_static_model(bad);
      ADD_FAILURE() << "accepted " << load << " N";
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("operation.load"), std::string::npos) << m;
      EXPECT_NE(m.find("F_min = 12.3"), std::string::npos) << m;
    }
  }
  ModelInputs ok = in;
  ok.load = Eigen::Vector2d(0, -12.5);
  EXPECT_NO_THROW(make_quasi_static_model(ok));
  // A rotating unbalance lowers the least load: 50 N with F_u = 45 N leaves 5 N.
  ModelInputs spin = in;
  spin.unbalance = 45.0 / (in.inner_speed * in.inner_speed);
  EXPECT_THROW(make_quasi_static_model(spin), InputError);
}

// vr_j against a centred difference of r_j on a finely sampled run, for the 2-DOF model and the
// quasi-static one. Samples within 50 µs of any ball entering or leaving contact are skipped: there
// the quasi-static orbit's acceleration has an integrable singularity (J ~ sqrt δ of the new ball),
// which a centred difference cannot follow.
void expect_ball_velocity_matches_difference(const std::string& kind, bool tvds = false) {
  const Case c = case_608({"model.kind=" + kind, "solver.duration=0.06", "solver.transient=0",
                           "solver.output_rate=400000", "solver.method=rkf45",
                           "solver.tolerance=1e-10", "rotor.damping=2000",
                           std::string("model.waviness_stiffness=") + (tvds ? "true" : "false")});
  const SimulationResult r = simulate(c);
  const auto& t = r.response.time;
  const double dt = t[1] - t[0];
  std::vector<bool> near_change(t.size(), false);
  const std::size_t window = static_cast<std::size_t>(50e-6 / dt);
  for (int j = 1; j <= c.bearing.balls; ++j) {
    const auto& Q = r.response.channel("Q" + std::to_string(j));
    for (std::size_t k = 1; k < t.size(); ++k)
      if ((Q[k - 1] > 0) != (Q[k] > 0))
        for (std::size_t i = k > window ? k - window : 0; i < std::min(t.size(), k + window); ++i)
          near_change[i] = true;
  }
  for (int j = 1; j <= c.bearing.balls; ++j) {
    const auto& rr = r.response.channel("r" + std::to_string(j));
    const auto& vr = r.response.channel("vr" + std::to_string(j));
    double peak = 0, worst = 0;
    for (double v : vr) peak = std::max(peak, std::fabs(v));
    // the 2-DOF start is the static solution: skip its first 10 ms of transient
    for (std::size_t k = t.size() / 6; k + 1 < t.size(); ++k) {
      if (near_change[k]) continue;
      worst = std::max(worst, std::fabs((rr[k + 1] - rr[k - 1]) / (2 * dt) - vr[k]));
    }
    EXPECT_LT(worst, 1e-3 * peak) << kind << " ball " << j;
  }
}

TEST(BallMotion, VelocityAgreesWithCentredDifferenceTwoDof) {
  expect_ball_velocity_matches_difference("2dof");
}

TEST(BallMotion, VelocityAgreesWithCentredDifferenceQuasiStatic) {
  expect_ball_velocity_matches_difference("quasistatic");
}

// With TVDS the races' stiffness varies along the waviness: the rates' dK/dt terms (the TVDS
// table's slope, the outer race's dK_o/dt) enter vr_j and must agree with r_j's difference too.
TEST(BallMotion, VelocityAgreesWithCentredDifferenceTvds) {
  expect_ball_velocity_matches_difference("2dof", true);
  expect_ball_velocity_matches_difference("quasistatic", true);
}

// A ball rides on the outer race: out of the load zone r_j = −Π_o(θ_j) + ΔD_j/2 and vr_j its
// rate; in it, at its outer contact's approach, r_j = (Q_j/K_o)^{1/n} − Π_o(θ_j) + ΔD_j/2, with
// Q_j the run's own ball-load channel and K_o the outer race's Hertz constant (no TVDS).
TEST(BallMotion, BallFollowsItsOuterContact) {
  for (const char* kind : {"quasistatic", "2dof", "3dof"}) {
    const Case c =
        case_608({std::string("model.kind=") + kind, "solver.duration=0.05", "solver.transient=0"});
    const SimulationResult r = simulate(c);
    const ContactConstants k = contact_constants(c);
    const double wc = cage_speed(c.bearing, c.operation.speed);
    Waviness outer;
    outer.harmonics = c.excitation.outer_waviness;
    int unloaded = 0, loaded = 0;
    for (int j = 0; j < c.bearing.balls; ++j) {
      const auto& Q = r.response.channel("Q" + std::to_string(j + 1));
      const auto& rr = r.response.channel("r" + std::to_string(j + 1));
      const auto& vr = r.response.channel("vr" + std::to_string(j + 1));
      for (std::size_t i = 0; i < Q.size(); i += 37) {
        const double th = two_pi * j / c.bearing.balls + wc * r.response.time[i];
        const double ride = -outer.profile(th) + 0.5 * c.excitation.ball_size_errors[j];
        if (Q[i] > 0) {
          const double d_o = std::pow(Q[i] / k.outer.K, 1.0 / k.outer.exponent);
          EXPECT_NEAR(rr[i], d_o + ride, 1e-9 * d_o) << kind << " ball " << j + 1;
          ++loaded;
        } else {
          EXPECT_NEAR(rr[i], ride, 1e-15) << kind;
          EXPECT_NEAR(vr[i], -outer.slope(th) * wc, 1e-12) << kind;
          ++unloaded;
        }
      }
    }
    EXPECT_GT(unloaded, 20) << kind;
    EXPECT_GT(loaded, 20) << kind;
  }
}

TEST(BallMotion, BallChannelsHaveStatisticsButNoSpectrum) {
  const Case c = case_608({"solver.duration=0.1", "solver.transient=0"});
  const SimulationResult r = simulate(c);
  const RunSummary s = summarize(c, r);
  EXPECT_EQ(s.spectrum_channels, (std::vector<std::string>{"x", "y", "vx", "vy", "ax", "ay"}));
  EXPECT_EQ(s.channels.size(), 6u + 3u * 7u);
  // Each channel says whose it is: the ring's six, then per ball Q, r, vr with its ball index.
  const auto& ch = r.response.channels;
  for (std::size_t i = 0; i < ch.size(); ++i) {
    EXPECT_EQ(ch[i].group, i < 6 ? ChannelGroup::ring : ChannelGroup::ball) << ch[i].name;
    EXPECT_EQ(s.channels[i].group, ch[i].group) << ch[i].name;
    if (i >= 6) EXPECT_EQ(ch[i].index, static_cast<int>((i - 6) % 7)) << ch[i].name;
  }
  EXPECT_EQ(ch[6].name, "Q1");
  EXPECT_EQ(ch[6].field, BallField::load);
  EXPECT_EQ(ch[20 + 6].name, "vr7");
  EXPECT_EQ(ch[20 + 6].field, BallField::radial_velocity);
  EXPECT_EQ(ch[2].name, "vx");
  EXPECT_EQ(ch[2].derivative, 1);
}

// output.ball_approach: d_j is the approach the contact law turns into the load, Q_j = K [d_j]_+^n
// with the run's constants, for every model kind; balls out of the load zone show their gap (d <
// 0).
TEST(BallApproach, LoadIsTheContactLawOfTheApproach) {
  for (const char* kind : {"quasistatic", "2dof", "3dof"}) {
    // An axial load where the kind carries one (the 3-DOF contact line), none where it does not.
    const std::string axial = std::string(kind) == "3dof" ? "10" : "0";
    const Case c =
        case_608({std::string("model.kind=") + kind, "solver.duration=0.2", "solver.transient=0.1",
                  "output.ball_approach=true", "operation.axial_load=" + axial});
    const SimulationResult r = simulate(c);
    const Response& resp = r.response;
    const double K = r.contact.K, n = r.contact.exponent;
    double most = 0, least = 0;
    for (int j = 1; j <= c.bearing.balls; ++j) {
      const auto& Q = resp.channel("Q" + std::to_string(j));
      const auto& d = resp.channel("d" + std::to_string(j));
      for (std::size_t k = 0; k < Q.size(); k += 7) {
        const double law = d[k] > 0 ? K * std::pow(d[k], n) : 0.0;
        EXPECT_NEAR(Q[k], law, 1e-9 * std::max(1.0, law)) << kind << " ball " << j;
        most = std::max(most, d[k]), least = std::min(least, d[k]);
      }
    }
    EXPECT_GT(most, 0) << kind;
    EXPECT_LT(least, 0) << kind;  // the top of the bearing is out of contact
    EXPECT_EQ(r.response.channels[r.response.index("d3")].group, ChannelGroup::ball);
  }
}

}  // namespace
}  // namespace bearing
