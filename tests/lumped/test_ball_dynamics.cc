// The ball-DOF model with cage slip and traction (model.kind = "balls", seed 004) through `run`:
// its massless-ball limit against the 2-DOF model, the outer-race passing frequency under cage
// slip (seed 004 eq. 26), the energy balance with and without friction, the trends of the
// friction force (seed 004 §4.2), every integrator on the same case, and the per-ball outputs.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bearing/case_file.h"
#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/models/ball_dofs.h"
#include "bearing/output.h"
#include "bearing/simulation.h"
#include "bearing/solvers/integrator.h"

namespace bearing {
namespace {

// Seed 004's SKF 6304 (examples/seed004_6304.toml without its comments): 2000 rpm, 2000 N along +x.
constexpr const char* kSeed004 = R"(
[bearing]
preset = "6304"
clearance = "30 um"
[rotor]
mass = "0.4 kg"
damping = "350 N s/m"
[operation]
speed = "2000 rpm"
load = ["2000 N", "0 N"]
[model]
kind = "balls"
[cage]
friction = 0.01
[ball]
inertia = "3.18e-8 kg m^2"
centrifugal = false
[solver]
duration = "0.5 s"
transient = "0.2 s"
)";

Case seed004(const std::vector<std::string>& sets = {}) {
  std::vector<Override> o;
  for (const auto& s : sets) o.push_back(parse_override(s));
  return parse_case(kSeed004, "seed 004 test case", o);
}

double rms(const std::vector<double>& x) {
  double s = 0;
  for (double v : x) s += v * v;
  return std::sqrt(s / static_cast<double>(x.size()));
}

double steady_rms(const SimulationResult& r, const std::string& channel) {
  return rms(r.response.steady(channel));
}

// μ = 0, a ball 3500 times lighter than steel (1 mg), no centrifugal load: the balls follow their
// contacts, and the ring moves as on the 2-DOF (3-DOF, with an axial preload) model's massless
// balls. The small ball damping
// (2 N s/m against the ring's 350) keeps the near-free balls in the unloaded zone from rattling;
// its share of the ring's damping is below 1 %. Newmark (implicit) for the stiff 1 mg balls; the
// waviness and ball-size errors go through both models too.
TEST(BallDynamics, MasslessFrictionlessBallsGiveTheRingModelsResponse) {
  const std::string excitation = R"(
[[waviness.outer]]
order = 9
amplitude = "0.3 um"
[ball_errors]
values = ["0.4 um", "0 um", "-0.3 um", "0 um", "0 um", "0.2 um", "0 um"]
)";
  // Radial load only against the 2-DOF model; with a 300 N axial preload against the 3-DOF one.
  for (const std::string& ring : {std::string("2dof"), std::string("3dof")}) {
    SCOPED_TRACE(ring);
    std::vector<std::string> sets = {"solver.method=newmark", "solver.dt=5us"};
    if (ring == "3dof") sets.push_back("operation.axial_load=300N");
    std::vector<Override> ob, o2;
    for (const auto& s : sets) ob.push_back(parse_override(s)), o2.push_back(parse_override(s));
    for (const char* s : {"cage.friction=0", "ball.mass=1e-6kg", "ball.damping=2"})
      ob.push_back(parse_override(s));
    o2.push_back(parse_override("model.kind=" + ring));
    const std::string text = std::string(kSeed004) + excitation;
    const std::string rings_only =  // the same case without [cage] and [ball]
        text.substr(0, text.find("[cage]")) + text.substr(text.find("[solver]"));
    const SimulationResult rb = simulate(parse_case(text, "balls", ob));
    const SimulationResult r2 = simulate(parse_case(rings_only, ring, o2));
    std::vector<std::string> channels = {"ax", "ay"};
    if (ring == "3dof") channels.push_back("az");
    for (const auto& ch : channels) {
      const double a = steady_rms(rb, ch), b = steady_rms(r2, ch);
      EXPECT_NEAR(a / b, 1.0, 0.01) << ch << ": balls " << a << ", " << ring << " " << b;
    }
  }
}

// Seed 004 eq. (26): the outer-race passing frequency is (1 − s_c) BPFO. The perfect bearing's
// largest peak in x near BPFO sits there within one bin (1 Hz over 1 s), for s_c = 0, 2 %, 5 %.
TEST(BallDynamics, OuterRacePassingPeakFollowsTheCageSlip) {
  double pure = 0;
  for (double slip : {0.0, 0.02, 0.05}) {
    SCOPED_TRACE(slip);
    const Case c = seed004({"cage.slip=" + std::to_string(slip), "solver.duration=1.2s"});
    const SimulationResult r = simulate(c);
    if (slip == 0.0) pure = r.frequencies.bpfo;
    EXPECT_NEAR(r.frequencies.bpfo, (1 - slip) * pure, 1e-9 * pure);
    const RunSummary s = summarize(c, r);
    const Spectrum* sx = nullptr;
    for (std::size_t i = 0; i < s.spectrum_channels.size(); ++i)
      if (s.spectrum_channels[i] == "x") sx = &s.spectra[i];
    ASSERT_NE(sx, nullptr);
    double best = 0, at = 0;
    for (std::size_t k = 0; k < sx->frequency.size(); ++k)
      if (sx->frequency[k] > 0.6 * pure && sx->frequency[k] < 1.3 * pure && sx->amplitude[k] > best)
        best = sx->amplitude[k], at = sx->frequency[k];
    const double bin = sx->resolution;
    EXPECT_NEAR(at, (1 - slip) * pure, bin) << "peak at " << at << " Hz";
  }
  EXPECT_NEAR(pure, 85.8, 0.05);  // seed 004 §4.3: 85.5 Hz by ref. [33]'s kinematics
}

// --- Energy -------------------------------------------------------------------------------

struct Trajectory {
  std::vector<double> t;
  std::vector<std::vector<double>> q, v;
};

Trajectory integrate(const BallDofModel& m, std::vector<double> q0, std::vector<double> v0,
                     double duration, int samples) {
  IntegratorSettings set;
  set.method = IntegratorMethod::rk8pd;
  set.dt = 1e-7;
  set.rtol = 1e-11;
  set.atol = 1e-17;
  Trajectory run;
  std::vector<double> times;
  for (int k = 0; k <= samples; ++k) times.push_back(duration * k / samples);
  const int n = m.dofs();
  make_integrator(set)->integrate(m, 0.0, q0, v0, times,
                                  [&](double t, const double* q, const double* v, const double*) {
                                    run.t.push_back(t);
                                    run.q.emplace_back(q, q + n);
                                    run.v.emplace_back(v, v + n);
                                  });
  return run;
}

// The DOFs' energy: ½ vᵀMv + contact potential − the constant load's work (ball_dofs.h).
double energy(const BallDofModel& m, const ModelInputs& in, const std::vector<double>& q,
              const std::vector<double>& v) {
  std::vector<double> mass(static_cast<std::size_t>(m.dofs()));
  m.mass(mass.data());
  double e = m.potential_energy(0.0, q.data()) - in.load.x() * q[0] - in.load.y() * q[1];
  for (std::size_t i = 0; i < mass.size(); ++i) e += 0.5 * mass[i] * v[i] * v[i];
  return e;
}

ModelInputs at_rest(std::vector<std::string> sets) {
  sets.insert(sets.end(), {"operation.speed=0rpm", "rotor.damping=0", "ball.damping=0"});
  return model_inputs(seed004(sets));
}

// Speed, damping and friction zero: a conservative system of 2Z + 2 DOFs. Released off
// equilibrium, the ring and the balls exchange kinetic and contact energy (balls lose and regain
// contact), and the total is conserved to the integrator's tolerance.
TEST(BallDynamics, EnergyIsConservedWithoutDampingAndSpeed) {
  const ModelInputs in = at_rest({"cage.friction=0"});
  const auto m = make_ball_dof_model(in);
  std::vector<double> q0 = m->initial_displacement(), v0(q0.size(), 0.0);
  q0[0] += 3e-6;
  q0[1] += 2e-6;
  for (int j = 0; j < 7; ++j) q0[2 + j] += 0.3e-6 * std::cos(j);
  const Trajectory run = integrate(*m, q0, v0, 0.01, 400);
  const double e0 = energy(*m, in, run.q[0], run.v[0]);
  double swing = 0, drift = 0;
  for (std::size_t k = 0; k < run.t.size(); ++k) {
    const double e = energy(*m, in, run.q[k], run.v[k]);
    swing = std::max(swing, e0 - m->potential_energy(0, run.q[k].data()) +
                                in.load.x() * run.q[k][0] + in.load.y() * run.q[k][1]);
    drift = std::max(drift, std::fabs(e - e0));
  }
  EXPECT_GT(swing, 0.0);
  EXPECT_LT(drift / swing, 1e-7) << "drift " << drift << " J of " << swing << " J exchanged";
}

// With friction: at zero speed the contact geometry stands still, so the DOFs' energy falls by
// exactly what the contacts dissipate, Σ μ Q Δv. The balls start spinning (the only sliding
// besides the ring's own motion) and the ring off equilibrium; E(t) + ∫ P_diss dt (Simpson on the
// output samples) stays at E(0), to the integrator's tolerance.
TEST(BallDynamics, FrictionDissipatesExactlyTheContactPower) {
  const ModelInputs in = at_rest({"cage.friction=0.05", "cage.slide_speed=0.1"});
  const auto m = make_ball_dof_model(in);
  std::vector<double> q0 = m->initial_displacement(), v0(q0.size(), 0.0);
  q0[0] += 2e-6;
  q0[1] += 1e-6;
  for (int j = 0; j < 7; ++j) v0[2 + 7 + j] = 20.0 * (1 + 0.3 * j);  // |Δv| ≤ 0.09 m/s: linear μ
  const int samples = 64000;
  const Trajectory run = integrate(*m, q0, v0, 0.004, samples);
  std::vector<double> p(run.t.size());
  for (std::size_t k = 0; k < run.t.size(); ++k) {
    const FrictionPower fp = m->friction_power(run.t[k], run.q[k].data(), run.v[k].data());
    p[k] = fp.dissipated;
    EXPECT_NEAR(fp.drives, 0.0, 1e-12 * (1 + fp.dissipated));  // nothing turns at zero speed
  }
  const double e0 = energy(*m, in, run.q[0], run.v[0]);
  const double h = run.t[1] - run.t[0];
  double dissipated = 0, worst = 0;
  for (int k = 2; k <= samples; k += 2) {
    dissipated += h / 3 * (p[k - 2] + 4 * p[k - 1] + p[k]);
    const double e = energy(*m, in, run.q[k], run.v[k]);
    worst = std::max(worst, std::fabs(e + dissipated - e0));
  }
  EXPECT_GT(dissipated, 0.1 * (e0 - energy(*m, in, run.q.back(), run.v.back())));
  EXPECT_LT(worst / dissipated, 1e-6)
      << "energy balance off by " << worst << " J of " << dissipated << " J dissipated";
}

// --- Friction force on a ball (seed 004 §4.2) ---------------------------------------------

// The peak over a run of the friction force on ball 1 at its inner contact, and its value
// wherever the ball carries no load [N].
struct FrictionPeak {
  double peak = 0;
  double unloaded = 0;
};

FrictionPeak friction_on_ball_one(std::vector<std::string> sets) {
  sets.insert(sets.end(), {"output.ball_dynamics=true", "output.ball_loads=true",
                           "solver.duration=0.3s", "solver.transient=0.1s", "solver.dt=2us"});
  const Case c = seed004(sets);
  const SimulationResult r = simulate(c);
  const auto fi = r.response.steady("Fi1"), fo = r.response.steady("Fo1");
  const auto qi = r.response.steady("Q1"), qo = r.response.steady("Qo1");
  FrictionPeak out;
  for (std::size_t k = 0; k < fi.size(); ++k) {
    out.peak = std::max(out.peak, std::fabs(fi[k]));
    if (qi[k] == 0 && qo[k] == 0)
      out.unloaded = std::max({out.unloaded, std::fabs(fi[k]), std::fabs(fo[k])});
  }
  return out;
}

TEST(BallDynamics, FrictionOnABallGrowsWithSlipFrictionLoadAndSpeed) {
  const std::vector<std::string> base = {"cage.slip=0.02", "cage.friction=0.01"};
  const FrictionPeak b = friction_on_ball_one(base);
  EXPECT_GT(b.peak, 0.0);
  EXPECT_EQ(b.unloaded, 0.0);  // only in the load zone (no centrifugal load here)
  const auto with = [&](const std::string& set) {
    std::vector<std::string> s = base;
    s.push_back(set);
    return friction_on_ball_one(s).peak;
  };
  EXPECT_GT(with("cage.slip=0.05"), b.peak);
  EXPECT_GT(with("cage.friction=0.03"), b.peak);
  EXPECT_GT(with("operation.load=[3000, 0]"), b.peak);
  EXPECT_GT(with("operation.speed=4000rpm"), b.peak);
}

// --- Integrators --------------------------------------------------------------------------

// Every method runs the ball model; over 20 ms their x(t) agree with a fine RK4 reference to a
// small fraction of its peak-to-peak (the ball contacts are stiff: ω ≈ 2e5 rad/s).
TEST(BallDynamics, EveryIntegratorAgreesOnTheResponse) {
  const std::vector<std::string> common = {"cage.slip=0.02", "solver.duration=0.02s",
                                           "solver.transient=0", "solver.output_rate=50kHz"};
  auto sets = common;
  sets.push_back("solver.dt=0.5us");
  const SimulationResult ref = simulate(seed004(sets));
  const auto& xr = ref.response.channel("x");
  const double ptp =
      *std::max_element(xr.begin(), xr.end()) - *std::min_element(xr.begin(), xr.end());
  for (const std::string method : {"rk4", "rkf45", "rk8pd", "newmark", "bdf"}) {
    auto s = common;
    s.push_back("solver.method=" + method);
    if (method == "newmark") s.push_back("solver.dt=1us");
    const SimulationResult r = simulate(seed004(s));
    const auto& x = r.response.channel("x");
    double worst = 0;
    for (std::size_t k = 0; k < x.size(); ++k) worst = std::max(worst, std::fabs(x[k] - xr[k]));
    EXPECT_LT(worst / ptp, 0.01) << method;
  }
}

// The message of the InputError a run of the seed 004 case with `sets` throws ("" if none).
std::string run_error(const std::vector<std::string>& sets) {
  try {
    simulate(seed004(sets));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Seed 004 integrates with RK4 at 10 µs; with steel balls (3.55 g) on their Hertz contacts the
// radial contact mode (≈ 3e5 rad/s at 2000 N) makes that unstable, and the run would end with a
// bounded but meaningless response. The run refuses it, naming solver.dt and the limit; likewise
// a step the balls' spin relaxation makes unstable.
TEST(BallDynamics, Rk4AboveItsStabilityLimitIsRefused) {
  const std::string contact = run_error({"solver.dt=10us"});
  EXPECT_NE(contact.find("solver.dt = 10 us"), std::string::npos) << contact;
  EXPECT_NE(contact.find("newmark"), std::string::npos) << contact;
  EXPECT_EQ(run_error({"solver.dt=10us", "solver.method=newmark", "solver.duration=0.01s",
                       "solver.transient=0"}),
            "");
  // The spin's relaxation onto its traction equilibrium, rate L² μ_m/Δv_m (Q_i + Q_o)/J ≈ 1e6 1/s
  // at μ_m = 0.05 (0.1 m/s, 2000 N), limits RK4 to about 2.6 µs.
  const std::string spin = run_error({"cage.friction=0.05"});
  EXPECT_NE(spin.find("solver.dt = 5 us"), std::string::npos) << spin;
  EXPECT_NE(spin.find("relaxation"), std::string::npos) << spin;
}

// --- Outputs and input errors -------------------------------------------------------------

TEST(BallDynamics, WritesPerBallChannelsAndTheCageUsed) {
  const Case c = seed004({"cage.slip=0.03", "output.ball_dynamics=true", "output.ball_motion=true",
                          "solver.duration=0.02s", "solver.transient=0"});
  const SimulationResult r = simulate(c);
  for (const char* stem : {"r", "vr", "wb", "Qo", "Fi", "Fo"})
    for (int j = 1; j <= 7; ++j) {
      const std::string name = stem + std::to_string(j);
      EXPECT_NO_THROW(r.response.channel(name)) << name;
      const Channel& ch = r.response.channels[r.response.index(name)];
      EXPECT_EQ(ch.group, ChannelGroup::ball) << name;
      EXPECT_EQ(ch.index, j - 1) << name;
    }
  EXPECT_EQ(r.response.channels[r.response.index("vx")].group, ChannelGroup::ring);
  EXPECT_THROW(r.response.index("Qo"), std::out_of_range);
  const RunSummary s = summarize(c, r);
  const auto j = summary_json(c, r, s);
  EXPECT_EQ(j["cage"]["slip"].get<double>(), 0.03);
  EXPECT_NEAR(j["cage"]["speed"].get<double>(), two_pi * r.frequencies.ftf, 1e-12);
  // The spin channel: seed 004's kinematic spin, 2π BSF relative to the cage (α = 0), slowed by
  // the slip to where the traction balances.
  const auto& wb = r.response.channel("wb1");
  EXPECT_GT(wb.back(), 0.9 * 2 * pi * r.frequencies.bsf);
}

TEST(BallDynamics, CaseErrorsNameTheKey) {
  const auto error_of = [](const std::string& text, const std::vector<std::string>& sets) {
    std::vector<Override> o;
    for (const auto& s : sets) o.push_back(parse_override(s));
    try {
      parse_case(text, "t", o);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error_of(kSeed004, {"cage.slip=1"}).find("cage.slip"), std::string::npos);
  EXPECT_NE(error_of(kSeed004, {"cage.friction=-0.1"}).find("cage.friction"), std::string::npos);
  EXPECT_NE(error_of(kSeed004, {"cage.slide_speed=0"}).find("cage.slide_speed"), std::string::npos);
  EXPECT_NE(error_of(kSeed004, {"ball.mass=-1g"}).find("ball.mass"), std::string::npos);
  EXPECT_NE(error_of(kSeed004, {"model.kind=2dof"}).find("[cage]"), std::string::npos);
  EXPECT_NE(error_of("[bearing]\npreset = \"6304\"\n[output]\nball_dynamics = true\n", {})
                .find("output.ball_dynamics"),
            std::string::npos);
}

}  // namespace
}  // namespace bearing
