// Random slip of the cage (random_slip.h): the speed's RMS and correlation, the angle as the
// speed's integral, the mean rate, the lines' attenuation with their harmonic number against the
// law derived in docs/model.md ("Random slip"), the same bits for the same seed and other bits for
// another, every model kind, and nothing changed when it is off. Every tolerance is a stated
// multiple of the estimator's standard deviation, derived for the Ornstein–Uhlenbeck process
// (false-alarm rate per comparison below 1e-6 at 5 standard deviations, the estimators being sums
// of many independent terms).

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../../lumped/src/models/ball_set.h"
#include "bearing/acoustics/microphones.h"
#include "bearing/case_file.h"
#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/info_report.h"
#include "bearing/kinematics.h"
#include "bearing/local_defect.h"
#include "bearing/models/random_slip.h"
#include "bearing/simulation.h"
#include "bearing/traction.h"

namespace bearing {
namespace {

constexpr double kSigmas = 5.0;  // the tolerance in standard deviations of the estimate

// u's RMS and its autocorrelation at three lags against σ and exp(−s/τ). At the grid's nodes u is
// the AR(1) process u_{k+1} = a u_k + σ sqrt(1 − a²) ξ_k, a = exp(−Δ/τ), exactly; for N samples
// of it (pooled over independent seeds) the large-N variances are (Bartlett):
//   sample variance with the mean known:  2 σ⁴ (1 + a²) / ((1 − a²) N),
//   sample autocorrelation at lag k:      [(1 + a²)(1 − a^2k)/(1 − a²) − 2k a^2k] / N,
//   sample mean:                          σ² (1 + a)/((1 − a) N).
TEST(RandomSlip, SpeedHasTheStatedRmsAndCorrelation) {
  const double sigma = 0.01, tau = 0.01, wc = 100.0, span = 20.0;
  const int seeds = 8;
  const std::vector<int> lags{32, 64, 128};  // τ/2, τ, 2τ
  double n = 0, sum = 0, sum2 = 0;
  std::vector<double> lagged(lags.size(), 0.0);
  double a = 0;
  for (int seed = 1; seed <= seeds; ++seed) {
    const SlipPath path(sigma, tau, seed, wc, span);
    a = std::exp(-path.step() / tau);
    const std::vector<double>& u = path.speed();
    for (std::size_t i = 0; i < u.size(); ++i) {
      n += 1, sum += u[i], sum2 += u[i] * u[i];
      for (std::size_t l = 0; l < lags.size(); ++l)
        if (i + lags[l] < u.size()) lagged[l] += u[i] * u[i + static_cast<std::size_t>(lags[l])];
    }
  }
  // u(0) itself is N(0, σ²) (the process stationary from the start): over 400 seeds the sample
  // variance has the relative standard deviation sqrt(2/400).
  double start = 0;
  for (int seed = 1; seed <= 400; ++seed)
    start += std::pow(SlipPath(sigma, tau, seed, wc, 0.0).speed()[0], 2) / 400;
  EXPECT_NEAR(start, sigma * sigma, kSigmas * std::sqrt(2.0 / 400) * sigma * sigma);
  const double variance = sum2 / n;
  const double sd_variance = std::sqrt(2 * std::pow(sigma, 4) * (1 + a * a) / ((1 - a * a) * n));
  EXPECT_NEAR(variance, sigma * sigma, kSigmas * sd_variance);
  EXPECT_NEAR(sum / n, 0.0, kSigmas * sigma * std::sqrt((1 + a) / ((1 - a) * n)));
  for (std::size_t l = 0; l < lags.size(); ++l) {
    const double k = lags[l], ak = std::pow(a, k);
    const double rho = lagged[l] / sum2;  // the few missing pairs at each path's end: O(k/N)
    const double sd = std::sqrt(((1 + a * a) * (1 - ak * ak) / (1 - a * a) - 2 * k * ak * ak) / n);
    EXPECT_NEAR(rho, std::exp(-k * (tau / SlipPath::kStepsPerCorrelationTime) / tau), kSigmas * sd)
        << "lag " << k << " steps";
  }
}

// φ is the integral of φ̇ = ω_c u, u linear between nodes: between two instants of one grid
// interval the angle grows by the trapezoid of the rates exactly, φ̇ at the nodes is ω_c u_k, φ(0)
// is 0; to rounding: 1e-12 of the largest angle, and of ω_c times the largest |u| (≤ 5σ = 0.1)
// at a node, which t = kΔ may reach through the interval before it (s = t − (k − 1)Δ carries
// k ε of rounding, k ≤ 2000).
TEST(RandomSlip, AngleIsTheIntegralOfTheRate) {
  const double wc = 75.0;
  const SlipPath path(0.02, 0.009, 3, wc, 2.0);
  const double h = path.step();
  EXPECT_EQ(path.angle(0.0), 0.0);
  double largest = 0;
  for (double t = 0; t < 2.0; t += 0.013) largest = std::max(largest, std::abs(path.angle(t)));
  ASSERT_GT(largest, 0.0);
  for (int k = 0; k < 2000; k += 37) {
    const double t0 = k * h;
    EXPECT_NEAR(path.rate(t0), wc * path.speed()[static_cast<std::size_t>(k)], 1e-12 * wc * 0.1);
    for (double f : {0.1, 0.5, 0.9, 1.0}) {
      const double t1 = t0 + f * h;
      const double trapezoid = (t1 - t0) * 0.5 * (path.rate(t0) + path.rate(t1));
      EXPECT_NEAR(path.angle(t1) - path.angle(t0), trapezoid, 1e-12 * largest) << k << " " << f;
      const SlipPath::AngleRate both = path.at(t1);
      EXPECT_EQ(both.angle, path.angle(t1));
      EXPECT_EQ(both.rate, path.rate(t1));
    }
  }
  EXPECT_THROW(path.angle(-1e-3), std::logic_error);
  EXPECT_THROW(path.angle(3.0), std::logic_error);
}

// The mean rate stays ω_c: φ(T)/(ω_c T) has mean 0 and the variance of the integrated
// Ornstein–Uhlenbeck process, Var φ(T) = 2 σ² ω_c² τ² (T/τ − 1 + e^(−T/τ)); each seed's within
// 5 of its standard deviations, and the mean of 16 seeds within 5 of its own.
TEST(RandomSlip, MeanRateIsTheCageSpeed) {
  const double sigma = 0.01, tau = 0.0093, wc = 74.9, T = 10.0;
  const double sd =
      std::sqrt(2 * sigma * sigma * tau * tau * (T / tau - 1 + std::exp(-T / tau))) / T;
  double mean = 0;
  const int seeds = 16;
  for (int seed = 1; seed <= seeds; ++seed) {
    const SlipPath path(sigma, tau, seed, wc, T);
    const double error = path.angle(T) / (wc * T);  // the relative error of the mean rate
    EXPECT_NEAR(error, 0.0, kSigmas * sd) << "seed " << seed;
    mean += error / seeds;
  }
  EXPECT_NEAR(mean, 0.0, kSigmas * sd / std::sqrt(seeds));
}

// The law (docs/model.md, "Random slip"): a line at m times the rate of a function of the cage
// angle, c_m e^(i m Z θ_c), seen over a record of length T, has the expected power
//     E|X_m|² = |c_m|² A_m,  A_m = (2/T) ∫₀ᵀ (1 − s/T) exp(−(mZ)² σ² ω_c² τ² (s/τ − 1 + e^(−s/τ)))
//     ds,
// from E[e^(i m Z (φ(t) − φ(t')))] = exp(−(mZ)² Var[φ(t) − φ(t')]/2) for the Gaussian φ. The
// squared envelope of a fault's impacts is such a function of the cage angle; so is the sum over
// the balls of an outer-race waviness of orders Z, 2Z, 3Z, 4Z (Σ_j A cos(mZ θ_j + ψ) = Z A
// cos(mZ θ_c + ψ), the other orders cancel over the balls), which is smooth, so its lines are
// read exactly by the DFT. The 6205 at 1796 rpm, σ = 1 %, τ = one ball pass, T = 1 s: A_m falls
// from 0.88 to 0.27 over m = 1…4. The estimate: the mean over K = 256 seeds of |X_m|²/|c_m|², each
// in [0, 1] (|X_m| ≤ |c_m|), so its variance is at most A_m (1 − A_m)/K (Bhatia–Davis); 5 of those
// standard deviations.
TEST(RandomSlip, LinesAttenuateWithTheHarmonicAsDerived) {
  Case c = default_case(
      {parse_override("bearing.preset=\"6205\""), parse_override("operation.speed=1796rpm")});
  ModelInputs in = model_inputs(c);
  const int Z = in.bearing.balls;
  const double wc = cage_speed(in.bearing, in.inner_speed), bpfo = Z * wc / two_pi;
  const double sigma = 0.01, tau = 1.0 / bpfo;
  const int periods = 107, per_period = 40;  // T ≈ 1 s, 40 samples a period (8 at 4 x BPFO)
  const double T = periods / bpfo;
  const int n = periods * per_period;
  for (int m = 1; m <= 4; ++m) in.outer_waviness.harmonics.push_back({m * Z, 1e-6, 0.3 * m});
  in.slip_span = T;
  const auto lines = [&](const detail::BallSet& set, std::vector<double>& power) {
    std::vector<std::complex<double>> x(4);
    detail::BallFrame fr;
    for (int i = 0; i < n; ++i) {
      const double t = i * T / n;
      set.evaluate(t, fr);
      double e = 0;
      for (int j = 0; j < Z; ++j) e += fr.excitation[j];
      for (int m = 1; m <= 4; ++m)
        x[m - 1] += e * std::exp(std::complex<double>(0, -m * Z * wc * t)) / static_cast<double>(n);
    }
    for (int m = 0; m < 4; ++m) power[m] = std::norm(x[m]);
  };
  std::vector<double> clean(4), power(4), mean(4, 0.0);
  lines(detail::BallSet(in, wc, 0.0), clean);
  for (int m = 0; m < 4; ++m)  // Z A/2: the line of an exactly periodic cosine
    ASSERT_NEAR(std::sqrt(clean[m]), 0.5 * Z * 1e-6, 1e-9 * Z * 1e-6);
  const int K = 256;
  for (int seed = 1; seed <= K; ++seed) {
    in.slip = {sigma, tau, seed};
    lines(detail::BallSet(in, wc, 0.0), power);
    for (int m = 0; m < 4; ++m) mean[m] += power[m] / clean[m] / K;
  }
  for (int m = 1; m <= 4; ++m) {
    const double b = std::pow(m * Z * sigma * wc * tau, 2);
    double A = 0;  // Simpson on 2000 intervals: the integrand is smooth, error < 1e-10
    const int steps = 2000;
    for (int i = 0; i <= steps; ++i) {
      const double s = T * i / steps;
      const double w = (i == 0 || i == steps) ? 1 : (i % 2 ? 4 : 2);
      A += w * (1 - s / T) * std::exp(-b * (s / tau - 1 + std::exp(-s / tau)));
    }
    A *= 2.0 / T * (T / steps) / 3.0;
    EXPECT_NEAR(mean[m - 1], A, kSigmas * std::sqrt(A * (1 - A) / K)) << "harmonic " << m;
    if (m == 1) EXPECT_GT(A, 0.8);
    if (m == 4) EXPECT_LT(A, 0.3);
  }
}

// The ball set under slip (ball_set.h, defect_excitation.h): a race defect is met where the cage
// angle ω_c t + φ(t) puts a ball, so the excitation with slip at t is the one without at
// t' = t + φ(t)/ω_c for an outer-race spall (housing-fixed), and a ball spall's spin follows the
// cage (ψ = ψ₀ + ω_s (t + φ/ω_c)) likewise; the angles computed ahead for several times are
// time_angles()'s own bits; and the rates of the excitation are its time derivative.
ModelInputs slip_inputs(const std::string& location, double duration) {
  Case c = default_case(
      {parse_override("bearing.preset=\"6205\""), parse_override("operation.speed=1796rpm")});
  ModelInputs in = model_inputs(c);
  LocalDefect d;
  d.location = location == "ball" ? DefectLocation::ball : DefectLocation::outer;
  d.position = -pi / 2;
  d.width = 1.0e-3;
  d.depth = 1e-4;  // deeper than the ball dips (~31 um): its drop is the ball's arc, smooth inside
  in.defects = {d};
  in.outer_waviness.harmonics = {{9, 2e-7, 0.1}, {4, 1e-7, 0.0}};
  in.slip = {0.02, 0.01, 5};
  in.slip_span = duration;
  return in;
}

TEST(RandomSlip, DefectsAndAnglesFollowTheSlippingCage) {
  for (const char* location : {"outer", "ball"}) {
    ModelInputs in = slip_inputs(location, 0.5);
    const double wc = cage_speed(in.bearing, in.inner_speed);
    const detail::BallSet slipping(in, wc, 0.0);
    in.outer_waviness.harmonics.clear();  // only the defect
    const detail::BallSet spall(in, wc, 0.0);
    ModelInputs plain_in = in;
    plain_in.slip = {};
    const detail::BallSet plain(plain_in, wc, 0.0);
    ASSERT_NE(spall.slip(), nullptr);
    int hits = 0;
    detail::BallFrame a, b;
    for (double t = 0.001; t < 0.5; t += 3.7e-6) {
      spall.evaluate(t, a);
      plain.evaluate(t + spall.slip()->angle(t) / wc, b);
      for (int j = 0; j < in.bearing.balls; ++j) {
        ASSERT_NEAR(a.excitation[j], b.excitation[j], 1e-12)
            << location << " t " << t << " j " << j;
        hits += a.excitation[j] < 0;
      }
    }
    EXPECT_GT(hits, 100) << location << ": the spall is met";
    // Ahead: the same bits as one at a time.
    std::vector<double> times, scratch;
    for (int i = 0; i < 13; ++i) times.push_back(0.01 + 1.3e-4 * i);
    std::vector<detail::BallSet::TimeAngles> ahead(times.size());
    slipping.time_angles(times.data(), static_cast<int>(times.size()), ahead.data(), scratch);
    for (std::size_t i = 0; i < times.size(); ++i) {
      const detail::BallSet::TimeAngles one = slipping.time_angles(times[i]);
      EXPECT_EQ(ahead[i].cage.c, one.cage.c);
      EXPECT_EQ(ahead[i].cage.s, one.cage.s);
      EXPECT_EQ(ahead[i].slip, one.slip);
      EXPECT_EQ(ahead[i].slip_rate, one.slip_rate);
      EXPECT_EQ(one.slip, slipping.slip()->angle(times[i]));
    }
    // Rates: de_j/dt against central differences of e_j at the midpoints of the slip path's
    // grid, where phi is a quadratic across [t - h, t + h] (h << the grid step / 2), so the
    // difference errs by h^2/6 times e's third derivative: the waviness's, sum A_s (N_s w)^3 ~
    // 70 m/s^3 at the cage's ~77 rad/s, i.e. 1.2e-11 m/s, and on the spall the ball's arc's,
    // 3 x v^3/R^3 ~ 2e5 m/s^3 at its edges (v = 1.9 m/s, R = D/2, x = w/2), i.e. 3e-8 m/s; twice
    // those for the slip's own terms. Instants where a ball crosses a kink of the spall's profile
    // (its one-sided differences disagree by 10 %) are left out.
    const double h = 1e-6, grid = slipping.slip()->step();
    int compared = 0, on_spall = 0;
    for (int k = 10; k < 2500; k += 7) {
      const double t = (k + 0.5) * grid;
      detail::BallFrame lo, hi, mid;
      slipping.evaluate(t - h, lo);
      slipping.evaluate(t + h, hi);
      slipping.evaluate(t, mid);
      detail::BallFrame drop_lo, drop_hi;  // the spall's drops alone
      spall.evaluate(t - h, drop_lo);
      spall.evaluate(t + h, drop_hi);
      detail::BallRates br;
      slipping.rates(t, br);
      EXPECT_NEAR(br.cage_rate, wc + slipping.slip()->rate(t), 1e-12 * wc);
      for (int j = 0; j < in.bearing.balls; ++j) {
        const double up = hi.excitation[j] - mid.excitation[j];
        const double down = mid.excitation[j] - lo.excitation[j];
        if (std::abs(up - down) > 0.1 * std::abs(up + down) + 1e-20) continue;  // a kink
        const double d = (up + down) / (2 * h);
        const bool on = drop_lo.excitation[j] != 0.0 || drop_hi.excitation[j] != 0.0;
        EXPECT_NEAR(br.excitation_rate[j], d, on ? 6e-8 : 2.5e-11) << location << " t " << t;
        ++compared;
        on_spall += on;
      }
    }
    EXPECT_GT(compared, 1000);
    EXPECT_GT(on_spall, 20) << location << ": rates compared on the spall";
  }
}

// The ball-DOF model's sliding speeds under slip: the cage turns at ω_ca + φ̇(t), so the outer
// contact's drive is A_o = ½ (ω_ca + φ̇) d_m (1 + g) (ball_dofs.h) and its friction force
// −μ(A_o − L ω_b) Q_o; the path rebuilt here from the same σ, τ, seed, ω_ca and span. μ on the
// traction curve's linear part, so an unslipped drive (φ̇ of 2 % of ω_ca moves A_o by 2 %) would
// be off by 2 % of the force; the comparison is to rounding (1e-12 relative).
TEST(RandomSlip, BallDofsSlideAtTheSlippingCageSpeed) {
  Case c = default_case(
      {parse_override("model.kind=\"balls\""), parse_override("operation.load=[0, -300]"),
       parse_override("cage.friction=0.05"), parse_override("cage.slip=0.01"),
       parse_override("cage.slide_speed=5"), parse_override("solver.duration=0.2"),
       parse_override("solver.transient=0.1"), parse_override("slip.rms=0.02"),
       parse_override("slip.seed=4")});
  const ModelInputs in = model_inputs(c);
  const auto model = make_model(c);
  const int Z = model->balls();
  const double wca = model->cage_speed(), D = in.bearing.ball_diameter;
  const double dm = in.bearing.pitch_diameter, g = D / dm, lever = 0.5 * D;
  const SlipPath path(0.02, two_pi / (Z * wca), 4, wca, 0.2);
  const TractionCurve curve = make_traction_curve(0.05, 5.0);
  std::vector<double> q = model->initial_displacement(), v = model->initial_velocity();
  std::vector<double> spin(Z), outer(Z), fi(Z), fo(Z);
  for (double t : {0.013, 0.071, 0.156}) {
    model->ball_dynamics(t, q.data(), v.data(), spin.data(), outer.data(), fi.data(), fo.data());
    int loaded = 0;
    for (int j = 0; j < Z; ++j) {
      const double drive = 0.5 * (wca + path.rate(t)) * dm * (1 + g);
      const double expected = -curve.coefficient(drive - lever * spin[j]) * outer[j];
      EXPECT_NEAR(fo[j], expected, 1e-12 * std::abs(expected) + 1e-15) << "t " << t << " j " << j;
      loaded += outer[j] > 0;
    }
    EXPECT_GT(loaded, 0);
  }
}

// Slip off: [slip] absent or rms = 0 writes no [slip] table and changes nothing (the frame's angles
// are those without slip, bit for bit); the same seed gives the same bits, another seed others,
// in every model kind; the kinds' responses all change with slip on.
TEST(RandomSlip, SameSeedSameBitsInEveryKind) {
  const auto response = [](std::vector<std::string> sets) {
    sets.push_back("solver.duration=0.05");
    sets.push_back("solver.transient=0.01");
    std::vector<Override> o;
    for (const auto& s : sets) o.push_back(parse_override(s));
    return simulate(default_case(o)).response;
  };
  for (const char* kind : {"2dof", "3dof", "balls", "quasistatic"}) {
    std::vector<std::string> base{std::string("model.kind=") + kind, "operation.load=[0, -300]"};
    if (std::string(kind) == "3dof") base.push_back("operation.axial_load=100");
    if (std::string(kind) == "quasistatic") base.push_back("operation.load=[0, -500]");
    const Response off = response(base);
    auto zero = base;
    zero.push_back("slip.rms=0");
    EXPECT_EQ(response(zero).values, off.values) << kind << ": rms = 0 is off";
    auto on = base;
    on.push_back("slip.rms=0.02");
    on.push_back("slip.seed=7");
    const Response a = response(on), b = response(on);
    EXPECT_EQ(a.values, b.values) << kind << ": the same seed";
    EXPECT_NE(a.values[1], off.values[1]) << kind << ": slip changes y";
    on.back() = "slip.seed=8";
    EXPECT_NE(response(on).values[1], a.values[1]) << kind << ": another seed";
  }
  std::vector<Override> none;
  EXPECT_EQ(case_to_toml(default_case(none)).find("[slip]"), std::string::npos);
}

// Where the balls were: a run records φ at its output times (for the acoustics' ball sources,
// whose orbits then turn with the slipping cage), the path rebuilt here from the case.
TEST(RandomSlip, RunRecordsTheCageAngleForTheBallSources) {
  const Case c = default_case({parse_override("slip.rms=0.015"), parse_override("slip.seed=9"),
                               parse_override("solver.duration=0.05"),
                               parse_override("solver.transient=0.01")});
  const Response r = simulate(c).response;
  ASSERT_EQ(r.cage_slip.size(), r.time.size());
  const ModelInputs in = model_inputs(c);
  const double wc = cage_speed(in.bearing, in.inner_speed);
  const SlipPath path(0.015, two_pi / (in.bearing.balls * wc), 9, wc, 0.05);
  for (std::size_t k = 0; k < r.time.size(); k += 97)
    EXPECT_EQ(r.cage_slip[k], path.angle(r.time[k]));
  EXPECT_TRUE(simulate(default_case({parse_override("solver.duration=0.05"),
                                     parse_override("solver.transient=0.01")}))
                  .response.cage_slip.empty());
  const std::vector<double> t{0.0, 0.01, 0.02}, slip{0.0, 0.1, -0.2};
  const BallOrbit o = ball_orbit(0.3, 50.0, t, slip);
  for (std::size_t n = 0; n < t.size(); ++n)
    EXPECT_EQ(o.cos[n], std::cos(0.3 + 50.0 * t[n] + slip[n]));
}

// Out of range: exit-2 messages naming the key, the value and the range.
TEST(RandomSlip, TableRulesNameTheKey) {
  const auto error = [](const std::string& set) {
    try {
      simulate(default_case({parse_override(set), parse_override("solver.duration=0.01"),
                             parse_override("solver.transient=0")}));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error("slip.rms=0.2").find("slip.rms = 0.2: must lie in [0, 0.1]"), std::string::npos);
  EXPECT_NE(error("slip.rms=-0.01").find("slip.rms = -0.01"), std::string::npos);
  EXPECT_NE(error("slip.correlation_time=-1ms").find("slip.correlation_time = -0.001 s"),
            std::string::npos);
  EXPECT_NE(error("slip.seed=-3").find("slip.seed = -3"), std::string::npos);
  EXPECT_NE(error("slip.seed=1.5").find("slip.seed"), std::string::npos);
}

// info --json reports the slip a run would use: the default correlation time resolved to one ball
// pass, 1/BPFO, a given one as given, nothing without [slip].
TEST(RandomSlip, InfoReportsTheSlipAsTheRunUsesIt) {
  const Case off = default_case({});
  EXPECT_FALSE(info_json(compute_info(off)).contains("slip"));
  const Case c = default_case({parse_override("slip.rms=0.015"), parse_override("slip.seed=7")});
  const InfoReport r = compute_info(c);
  const nlohmann::json j = info_json(r);
  ASSERT_TRUE(j.contains("slip"));
  EXPECT_EQ(j["slip"]["rms"].get<double>(), 0.015);
  EXPECT_EQ(j["slip"]["seed"].get<int>(), 7);
  EXPECT_EQ(j["slip"]["correlation_time_source"].get<std::string>(), "one ball pass");
  EXPECT_DOUBLE_EQ(j["slip"]["correlation_time"].get<double>(), 1.0 / r.frequencies.bpfo);
  EXPECT_EQ(j["units"]["slip.correlation_time"].get<std::string>(), "s");
  EXPECT_NE(info_text(r).find("Slip: the cage speed fluctuates by 1.5 % RMS"), std::string::npos);
  const Case given = default_case({parse_override("slip.rms=0.01"),
                                   parse_override("slip.correlation_time=2ms")});
  const nlohmann::json g = info_json(compute_info(given));
  EXPECT_EQ(g["slip"]["correlation_time_source"].get<std::string>(), "given");
  EXPECT_EQ(g["slip"]["correlation_time"].get<double>(), 0.002);
}

}  // namespace
}  // namespace bearing
