// Local defects ([[defects]], local_defect.h, models/defect_excitation.h) in the case file and in
// the dynamic models, each check against something computed independently: the ball-angle
// kinematics and the bearing frequencies (where each ball meets the defect), a ball-size error
// (what a drop does to a contact), finite differences (the rates), the 2-DOF model (the ball-DOF
// model's total approach), and step refinement (the impacts are resolved).

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bearing/case_file.h"
#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/info_report.h"
#include "bearing/kinematics.h"
#include "bearing/local_defect.h"
#include "bearing/models/ball_dofs.h"
#include "bearing/models/three_dof.h"
#include "bearing/models/two_dof.h"
#include "bearing/simulation.h"

namespace bearing {
namespace {

// The CWRU-like 6205 at 1797 rpm under 2 kN down, with `defects` as [[defects]] TOML.
Case cwru_6205(const std::string& defects, std::vector<std::string> sets = {}) {
  std::vector<Override> o;
  for (const auto& s : sets) o.push_back(parse_override(s));
  return parse_case(
      "[bearing]\npreset = \"6205\"\n[operation]\nspeed = \"1797 rpm\"\nload = [0, -2000]\n"
      "[solver]\nduration = \"0.1 s\"\ntransient = \"0.02 s\"\noutput_rate = \"48 kHz\"\n" +
          defects,
      "cwru_6205.toml", o);
}

const char* kOuterSpall =
    "[[defects]]\nlocation = \"outer\"\nposition = \"-90 deg\"\nwidth = \"0.53 mm\"\n"
    "depth = \"0.28 mm\"\n";

std::string error_of(const std::string& defects, std::vector<std::string> sets = {}) {
  try {
    cwru_6205(defects, sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(DefectCase, ReadsWritesAndRoundTrips) {
  const Case c =
      cwru_6205(std::string(kOuterSpall) +
                "[[defects]]\nlocation = \"ball\"\nball = 3\nwidth = \"1 mm\"\ndepth = \"50 um\"\n"
                "profile = \"smooth\"\n[[defects]]\nlocation = \"inner\"\nposition = \"10 deg\"\n"
                "width = \"0.3 mm\"\ndepth = \"0.1 mm\"\n");
  ASSERT_EQ(c.excitation.defects.size(), 3u);
  const LocalDefect& outer = c.excitation.defects[0];
  EXPECT_EQ(outer.location, DefectLocation::outer);
  EXPECT_DOUBLE_EQ(outer.position, -pi / 2);
  EXPECT_DOUBLE_EQ(outer.width, 0.53e-3);
  EXPECT_DOUBLE_EQ(outer.depth, 0.28e-3);
  EXPECT_EQ(outer.profile, DefectProfile::rectangular);
  const LocalDefect& ball = c.excitation.defects[1];
  EXPECT_EQ(ball.location, DefectLocation::ball);
  EXPECT_EQ(ball.ball, 3);
  EXPECT_DOUBLE_EQ(ball.position, pi / 2);  // the documented default
  EXPECT_EQ(ball.profile, DefectProfile::smooth);
  EXPECT_EQ(c.excitation.defects[2].location, DefectLocation::inner);

  const Case back = parse_case(case_to_toml(c), "back.toml");
  ASSERT_EQ(back.excitation.defects.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const LocalDefect &a = c.excitation.defects[i], &b = back.excitation.defects[i];
    EXPECT_EQ(a.location, b.location);
    EXPECT_EQ(a.position, b.position);
    EXPECT_EQ(a.ball, b.ball);
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.depth, b.depth);
    EXPECT_EQ(a.profile, b.profile);
  }
  const auto body = [](const Case& k) {  // without the header naming the source
    const std::string t = case_to_toml(k);
    return t.substr(t.find("\n\n"));
  };
  EXPECT_EQ(body(back), body(c));
  // An entry's value from the command line.
  const Case set = cwru_6205(kOuterSpall, {"defects.0.width=0.18 mm"});
  EXPECT_DOUBLE_EQ(set.excitation.defects[0].width, 0.18e-3);
  EXPECT_TRUE(cwru_6205("").excitation.defects.empty());
  EXPECT_EQ(case_to_toml(cwru_6205("")).find("defects"), std::string::npos);
}

TEST(DefectCase, BadEntriesAreErrorsNamingTheField) {
  const std::string loc = "[[defects]]\nlocation = ";
  EXPECT_NE(error_of(loc + "\"outr\"\nposition = 0\nwidth = \"1 mm\"\ndepth = \"1 um\"\n")
                .find("defects[0].location = \"outr\": unknown defect location; allowed: outer, "
                      "inner, ball (did you mean \"outer\"?)"),
            std::string::npos);
  EXPECT_NE(error_of(loc + "\"outer\"\nwidth = \"1 mm\"\ndepth = \"1 um\"\n")
                .find("defects[0].position is missing"),
            std::string::npos);
  EXPECT_NE(error_of(loc + "\"ball\"\nwidth = \"1 mm\"\ndepth = \"1 um\"\n")
                .find("defects[0].ball is missing"),
            std::string::npos);
  EXPECT_NE(
      error_of(loc + "\"inner\"\nball = 2\nposition = 0\nwidth = \"1 mm\"\ndepth = \"1 um\"\n")
          .find("defects[0].ball = 2: only a ball defect"),
      std::string::npos);
  EXPECT_NE(error_of(loc + "\"ball\"\nball = 9\nwidth = \"1 mm\"\ndepth = \"1 um\"\n")
                .find("defects[0].ball = 9: must lie in [0, 8]"),
            std::string::npos);
  EXPECT_NE(error_of(loc + "\"outer\"\nposition = 0\nwidth = \"1 cm\"\ndepth = \"1 um\"\n")
                .find("defects[0].width = 10 mm: must lie in (0, D = "),
            std::string::npos);
  EXPECT_NE(error_of(loc + "\"outer\"\nposition = 0\nwidth = \"1 mm\"\n")
                .find("each [[defects]] entry needs location"),
            std::string::npos);
  EXPECT_NE(
      error_of(loc + "\"outer\"\nposition = 0\nwidth = \"1 mm\"\ndepth = \"1 um\"\nsize = 1\n")
          .find("unknown key \"defects[0].size\""),
      std::string::npos)
      << error_of(loc + "\"outer\"\nposition = 0\nwidth = \"1 mm\"\ndepth = \"1 um\"\nsize = 1\n");
  EXPECT_NE(error_of(kOuterSpall, {"model.kind=quasistatic"})
                .find("[[defects]]: model.kind = \"quasistatic\" does not integrate in time"),
            std::string::npos);
  EXPECT_NE(error_of("[defects]\nlocation = \"outer\"\n").find("expected entries [[defects]]"),
            std::string::npos);
}

// `info` shows each defect's drop and crossing: the geometry's own numbers, and the crossing from
// the ball-pass frequency (a ball covers one spacing 2πρ/Z per pass).
TEST(DefectCase, InfoShowsTheDropAndTheStepItAsksFor) {
  const Case c = cwru_6205(std::string(kOuterSpall) +
                           "[[defects]]\nlocation = \"ball\"\nball = 1\nwidth = \"1 mm\"\n"
                           "depth = \"5 um\"\n");
  const InfoReport r = compute_info(c);
  ASSERT_EQ(r.defects.size(), 2u);
  const Bearing& b = c.bearing;
  const double ro = 0.5 * b.outer_raceway_diameter();
  EXPECT_EQ(r.defects[0].inner_drop, 0.0);
  EXPECT_DOUBLE_EQ(r.defects[0].outer_drop,
                   defect_max_drop(b.ball_diameter, Race::outer, ro, 0.53e-3, 0.28e-3));
  const double bpfo = bearing_frequencies(b, c.operation.speed).bpfo;
  EXPECT_NEAR(r.defects[0].crossing, 0.53e-3 / (two_pi * ro / b.balls * bpfo), 1e-15);
  EXPECT_DOUBLE_EQ(r.defects[0].max_step, r.defects[0].crossing / 10);
  EXPECT_EQ(r.defects[1].inner_drop, 5e-6);  // a 1 mm slot on the ball: floored at its depth
  EXPECT_EQ(r.defects[1].outer_drop, 5e-6);
  const nlohmann::json j = info_json(r);
  EXPECT_EQ(j["defects"][1]["location"], "ball");
  EXPECT_EQ(j["units"]["defects.crossing"], "s");
  EXPECT_NE(info_text(r).find("0: outer, 0.53 mm wide, 0.28 mm deep, rectangular: drop 7.3"),
            std::string::npos)
      << info_text(r);
}

// The change of each ball's approach that the defects make, at time t and ring position q.
std::vector<double> approach_change(const Case& with, double t, const std::vector<double>& q) {
  Case without = with;
  without.excitation.defects.clear();
  const auto a = make_model(with), b = make_model(without);
  std::vector<double> da(static_cast<std::size_t>(a->balls())), db(da.size());
  a->ball_approaches(t, q.data(), da.data());
  b->ball_approaches(t, q.data(), db.data());
  for (std::size_t j = 0; j < da.size(); ++j) da[j] -= db[j];
  return da;
}

// Where each ball meets a race defect, from the ball angles θ_j = φ₀ + 2πj/Z + ω_c t (docs/model.md
// §1) with ω_c from kinematics.h, and how much it drops there (the pivot geometry, tested on its
// own in test_local_defect.cc): at every instant of a few ball passes, every ball.
// The crowded variant (12 balls of 8 mm on a 33 mm pitch circle, a 7 mm defect) has a defect
// wider than half the balls' spacing on the inner race: two balls can be over it at once.
TEST(DefectModels, EachBallDropsWhereTheKinematicsPutItOverARaceDefect) {
  const std::vector<std::string> crowded{"bearing.balls=12", "bearing.ball_diameter=8 mm",
                                         "bearing.pitch_diameter=33 mm"};
  struct Variant {
    const char* where;
    const char* width;
    std::vector<std::string> sets;
  };
  for (const Variant& variant :
       {Variant{"outer", "0.8 mm", {}}, Variant{"inner", "0.8 mm", {}},
        Variant{"inner", "7 mm", crowded}, Variant{"outer", "7 mm", crowded}}) {
    const char* where = variant.where;
    const bool inner = std::string(where) == "inner";
    const Case c = cwru_6205(std::string("[[defects]]\nlocation = \"") + where +
                                 "\"\nposition = \"-80 deg\"\nwidth = \"" + variant.width +
                                 "\"\ndepth = \"20 um\"\n",
                             variant.sets);
    const Bearing& b = c.bearing;
    const double wi = c.operation.speed, wc = cage_speed(b, wi), Z = b.balls;
    const double rho = 0.5 * (inner ? b.inner_raceway_diameter() : b.outer_raceway_diameter());
    const LocalDefect& d = c.excitation.defects[0];
    const Race race = inner ? Race::inner : Race::outer;
    const std::vector<double> q{0, 0};
    int hits = 0, together = 0;
    for (int k = 0; k < 4000; ++k) {
      const double t = 0.05 * k / 4000;
      const std::vector<double> change = approach_change(c, t, q);
      for (int j = 0; j < b.balls; ++j) {
        const double theta = two_pi * j / Z + wc * t - (inner ? wi * t : 0.0);
        const double u = rho * std::remainder(theta - d.position, two_pi) + 0.5 * d.width;
        const double expected = defect_drop(b.ball_diameter, race, rho, d.width, d.depth, u);
        EXPECT_NEAR(change[static_cast<std::size_t>(j)], -expected, 1e-13) << where << " t " << t;
        hits += expected > 0;
      }
      together += std::count_if(change.begin(), change.end(), [](double x) { return x < 0; }) > 1;
    }
    EXPECT_EQ(together > 0, std::string(variant.width) == "7 mm" && inner) << where;
    // The time spent over the defect is the crossing time per pass times the passes, to the
    // sampling step per pass and the crossings the 50 ms window cuts at its ends.
    const BearingFrequencies f = bearing_frequencies(b, wi);
    const double passes = 0.05 * (inner ? f.bpfi : f.bpfo);
    const double transit = d.width / (two_pi * rho / Z * (inner ? f.bpfi : f.bpfo));
    EXPECT_NEAR(hits * (0.05 / 4000), passes * transit, 2 * transit + 0.05 / 4000 * (passes + 1))
        << where;
  }
}

// A ball defect strikes the outer race when the ball has turned ψ₀ + 2π BSF t ≡ 0 and the inner
// race at ≡ π (BSF from kinematics.h): twice per ball revolution, one contact at a time.
TEST(DefectModels, ABallDefectStrikesEachRaceOncePerBallRevolution) {
  const Case c = cwru_6205(
      "[[defects]]\nlocation = \"ball\"\nball = 2\nposition = \"30 deg\"\nwidth = \"1 mm\"\n"
      "depth = \"20 um\"\n");
  const Bearing& b = c.bearing;
  const double bsf = bearing_frequencies(b, c.operation.speed).bsf;
  const LocalDefect& d = c.excitation.defects[0];
  const double R = 0.5 * b.ball_diameter;
  const DefectPath inner(b, d, Race::inner), outer(b, d, Race::outer);
  const std::vector<double> q{0, 0};
  for (int k = 0; k < 3000; ++k) {
    const double t = 0.03 * k / 3000, psi = d.position + two_pi * bsf * t;
    const std::vector<double> change = approach_change(c, t, q);
    const double expected = outer.drop(R * std::remainder(psi, two_pi) + 0.5 * d.width) +
                            inner.drop(R * std::remainder(psi - pi, two_pi) + 0.5 * d.width);
    for (int j = 0; j < b.balls; ++j)
      EXPECT_NEAR(change[static_cast<std::size_t>(j)], j == 2 ? -expected : 0.0, 1e-13) << t;
  }
}

// A drop h over the whole contact (a defect wider than the contact's reach, floored at h) acts on
// the ball as a ball h smaller would: the model's forces agree with the defect-free model's with
// ΔD_0 = h, for the 2-DOF and the 3-DOF model, at several ring positions.
TEST(DefectModels, AFlooredDropActsAsASmallerBall) {
  for (const char* kind : {"2dof", "3dof"}) {
    Case c = cwru_6205(
        "[[defects]]\nlocation = \"outer\"\nposition = 0\nwidth = \"7 mm\"\ndepth = \"2 um\"\n",
        {std::string("model.kind=") + kind, "operation.speed=0",
         std::string("operation.axial_load=") + (std::string(kind) == "3dof" ? "300" : "0")});
    Case sized = c;
    sized.excitation.defects.clear();
    sized.excitation.ball_size_errors.assign(static_cast<std::size_t>(c.bearing.balls), 0.0);
    sized.excitation.ball_size_errors[0] = 2e-6;  // ΔD_0 = D − D_0
    const auto a = make_model(c), b = make_model(sized);
    const int n = a->dofs();
    for (const auto& q2 : std::vector<std::vector<double>>{{3e-6, -1e-6}, {8e-6, 2e-6}}) {
      std::vector<double> q = a->initial_displacement(), v(static_cast<std::size_t>(n), 0.0);
      q[0] += q2[0], q[1] += q2[1];
      std::vector<double> fa(q.size()), fb(q.size());
      a->force(0.0, q.data(), v.data(), fa.data());
      b->force(0.0, q.data(), v.data(), fb.data());
      for (int i = 0; i < n; ++i)
        EXPECT_NEAR(fa[static_cast<std::size_t>(i)], fb[static_cast<std::size_t>(i)],
                    1e-12 * std::max(1.0, std::abs(fb[static_cast<std::size_t>(i)])))
            << kind << " dof " << i;
    }
  }
}

// The ball-DOF model splits each ball's approach between its two contacts; their sum is the 2-DOF
// model's approach (ball_dofs.h), defects included, whatever the balls' own positions.
TEST(DefectModels, TheBallDofModelsTotalApproachIsTheTwoDofModels) {
  const std::string defects =
      std::string(kOuterSpall) +
      "[[defects]]\nlocation = \"ball\"\nball = 1\nposition = 0\nwidth = \"1 mm\"\n"
      "depth = \"20 um\"\n[[defects]]\nlocation = \"inner\"\nposition = \"-60 deg\"\n"
      "width = \"0.5 mm\"\ndepth = \"20 um\"\n";
  const auto two = make_model(cwru_6205(defects));
  const auto balls = make_model(cwru_6205(defects, {"model.kind=balls"}));
  std::vector<double> q = balls->initial_displacement();
  for (int j = 0; j < 9; ++j) q[static_cast<std::size_t>(2 + j)] += 1e-7 * j;
  std::vector<double> a(9), b(9);
  for (double t : {0.0, 0.0031, 0.0123, 0.0201, 0.0347}) {
    two->ball_approaches(t, q.data(), a.data());
    balls->ball_approaches(t, q.data(), b.data());
    for (int j = 0; j < 9; ++j) EXPECT_NEAR(a[j], b[j], 1e-17) << t << " ball " << j;
  }
}

// The ball-centre rate (ball_motion's vr) includes the defect's: at a fixed ring position and
// zero ring velocity it is the time derivative of r, checked by a centred difference while each
// kind of defect passes.
TEST(DefectModels, BallMotionRatesFollowTheDrop) {
  const std::string defects =
      std::string(kOuterSpall) +
      "[[defects]]\nlocation = \"ball\"\nball = 4\nposition = 0\nwidth = \"1 mm\"\n"
      "depth = \"20 um\"\n";
  for (const char* kind : {"2dof", "3dof"}) {
    const auto m =
        make_model(cwru_6205(defects, {std::string("model.kind=") + kind,
                                       std::string("operation.axial_load=") +
                                           (std::string(kind) == "3dof" ? "300" : "0")}));
    const std::vector<double> q = m->initial_displacement(),
                              v(static_cast<std::size_t>(m->dofs()), 0.0);
    std::vector<double> r0(9), r1(9), r(9), vr(9), scratch(9);
    const double h = 1e-9;
    double largest = 0;
    int moving = 0;
    for (int k = 1; k < 400; ++k) {
      const double t = 0.1 * k / 400 + 1.234e-5;
      m->ball_motion(t - h, q.data(), v.data(), r0.data(), scratch.data());
      m->ball_motion(t + h, q.data(), v.data(), r1.data(), scratch.data());
      m->ball_motion(t, q.data(), v.data(), r.data(), vr.data());
      for (int j = 0; j < 9; ++j) {
        const double fd = (r1[j] - r0[j]) / (2 * h);
        largest = std::max(largest, std::abs(vr[j]));
        if (std::abs(vr[j]) > 1e-3) ++moving;
        EXPECT_NEAR(vr[j], fd, 1e-6 * std::max(1e-3, std::abs(fd))) << kind << " t " << t;
      }
    }
    EXPECT_GT(moving, 0) << kind;  // some samples are on a defect's ramp
  }
}

TEST(DefectRuns, AStepThatJumpsOverADefectIsRefusedNamingSolverDt) {
  const Case c = cwru_6205(kOuterSpall, {"solver.dt=40 us"});
  try {
    simulate(c);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("solver.dt = 40 us: a step must not jump over a defect: defects[0] (outer, "
                     "0.53 mm wide) is crossed in 301 us"),
              std::string::npos)
        << m;
    EXPECT_NE(m.find("use solver.dt <= 30.1 us"), std::string::npos) << m;
  }
  EXPECT_NO_THROW(make_model(c));  // the model itself is fine: the step is what is refused
  EXPECT_THROW(simulate(cwru_6205(kOuterSpall, {"solver.dt=40 us", "solver.method=newmark"})),
               InputError);
}

double rms_after(const SimulationResult& r, const std::string& channel, double t0) {
  const auto& t = r.response.time;
  const auto& x = r.response.channel(channel);
  double mean = 0, sq = 0;
  int n = 0;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k] >= t0) mean += x[k], ++n;
  mean /= n;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k] >= t0) sq += (x[k] - mean) * (x[k] - mean);
  return std::sqrt(sq / n);
}

// The impacts are resolved: RK4 at the default 5 µs and at 2.5 µs, and the adaptive rk8pd (its
// steps capped at a tenth of the crossing), give the same vibration.
TEST(DefectRuns, TheImpactsConvergeWithTheStepAndAgreeAcrossIntegrators) {
  const Case c = cwru_6205(kOuterSpall, {"solver.duration=0.05", "solver.transient=0.01"});
  const double coarse = rms_after(simulate(c), "ay", 0.01);
  Case fine = c;
  fine.solver.dt = 2.5e-6;
  const double refined = rms_after(simulate(fine), "ay", 0.01);
  Case adaptive = c;
  adaptive.solver.method = IntegratorMethod::rk8pd;
  adaptive.solver.tolerance = 1e-8;
  const double rk8pd = rms_after(simulate(adaptive), "ay", 0.01);
  const double healthy = rms_after(
      simulate(cwru_6205("", {"solver.duration=0.05", "solver.transient=0.01"})), "ay", 0.01);
  EXPECT_GT(refined, 100 * healthy);  // the defect dominates
  EXPECT_NEAR(coarse, refined, 1e-3 * refined);
  EXPECT_NEAR(rk8pd, refined, 1e-3 * refined);
}

// At the largest step the check allows (a tenth of the crossing: 30.1 µs here) RK4 still resolves
// the impacts: the RMS of the response is within 0.5 % of a step twelve times finer.
TEST(DefectRuns, TheLargestAllowedStepResolvesTheImpacts) {
  const Case c = cwru_6205(kOuterSpall, {"solver.duration=0.1", "solver.transient=0.02"});
  Case coarse = c, fine = c;
  coarse.solver.dt = 30e-6;
  fine.solver.dt = 2.5e-6;
  for (const char* channel : {"y", "ay"})
    EXPECT_NEAR(rms_after(simulate(coarse), channel, 0.02),
                rms_after(simulate(fine), channel, 0.02),
                5e-3 * rms_after(simulate(fine), channel, 0.02))
        << channel;
  coarse.solver.dt = 30.2e-6;
  EXPECT_THROW(simulate(coarse), InputError);
}

}  // namespace
}  // namespace bearing
