// Issue 41: the band-integrated cyclic spectral coherence and the diagnosis from it. The band SES
// against a direct computation; the line test's thresholds against their closed forms and its
// false-alarm rate measured on Gaussian noise; jittered impacts of each family named, with their
// physics (sidebands); a deterministic line and shaft modulation not named; two faults `several`;
// bad settings refused.

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

#include "bearing/coherence_diagnosis.h"
#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/presets.h"
#include "synthetic_signals.h"

namespace bearing {
namespace {

constexpr double kRate = 12000;  // [Hz]
const double kSpeed = 1797 * two_pi / 60;

BearingFrequencies cwru() {
  return bearing_frequencies(preset("6205"), kSpeed);
}

// Impacts at `rate` [Hz] ringing a `resonance`, jittered by 1 % of the period, their strength
// modulated at `modulation` (depth 0.8), in white noise `snr` dB below them; n samples.
std::vector<double> faulty(double rate, double modulation, std::size_t n, std::uint64_t seed,
                           double resonance = 3000, double snr = 0) {
  test::ImpactTrain p;
  p.rate = rate;
  p.resonance = resonance;
  p.damping_ratio = 0.03;
  p.modulation = modulation;
  p.depth = modulation > 0 ? 0.8 : 0;
  p.jitter = 0.01;
  p.seed = seed;
  return test::with_noise(test::impact_train(p, n, kRate), snr, seed + 1);
}

std::vector<double> gaussian(std::size_t n, std::uint64_t seed) {
  test::SplitMix64 g(seed);
  std::vector<double> x(n);
  for (double& v : x) v = g.normal();
  return x;
}

TEST(CoherenceBands, TheDyadicTreeAndItsShiftedBands) {
  const std::vector<CoherenceBand> b = coherence_bands(kRate, 3);
  ASSERT_EQ(b.size(), 25u);  // 1 + 2 + (4 + 3) + (8 + 7)
  EXPECT_EQ(b[0].band.low, 0);
  EXPECT_EQ(b[0].band.high, 6000);
  int shifted = 0;
  for (const CoherenceBand& c : b) {
    EXPECT_NEAR(c.band.high - c.band.low, 6000.0 / (1 << c.level), 1e-9);
    EXPECT_LE(c.band.high, 6000 + 1e-9);
    shifted += c.shifted;
    if (c.shifted) EXPECT_GE(c.level, 2);
  }
  EXPECT_EQ(shifted, 10);
  EXPECT_EQ(coherence_bands(kRate, 0).size(), 1u);
  EXPECT_THROW(coherence_bands(kRate, 7), InputError);
  EXPECT_THROW(coherence_bands(0, 3), InputError);
}

// The band SES against its definition computed another way: the whitened record's band bins put
// into a full-length spectrum (no shift to 0 Hz, no short transform), the analytic signal by a
// full-length inverse DFT, |a|², and its DFT summed directly at a few bins.
TEST(CoherenceBands, BandSesIsTheSquaredEnvelopeOfTheWhitenedBand) {
  const std::size_t n = 1500;  // 2² · 3 · 5³: a fast length for the direct check
  const double rate = 3000;
  std::vector<double> x = faulty(100, 0, n, 3, 700, 20);
  const std::vector<std::complex<double>> X = whitened_spectrum(x);
  ASSERT_EQ(X.size(), n / 2 + 1);
  for (std::size_t k = 1; k < X.size(); ++k) EXPECT_NEAR(std::abs(X[k]), 1.0, 1e-12);
  const FrequencyBand band{500, 900};
  const std::vector<double> ses = band_squared_envelope(X, n, rate, band);
  EXPECT_DOUBLE_EQ(ses[0], 1.0);
  const double df = rate / n;
  std::vector<std::complex<double>> full(n, 0.0);
  for (std::size_t k = 1; k < X.size(); ++k)
    if (k * df >= band.low - 1e-9 && k * df <= band.high + 1e-9) full[k] = X[k];
  std::vector<double> e(n);
  for (std::size_t t = 0; t < n; ++t) {
    std::complex<double> a = 0;
    for (std::size_t k = 0; k < n; ++k)
      a += full[k] * std::polar(1.0, two_pi * static_cast<double>(k * t % n) / n);
    e[t] = std::norm(a);
  }
  std::complex<double> dc = 0;
  for (double v : e) dc += v;
  ASSERT_EQ(ses.size(), 201u);  // bins up to the band's width, 400 Hz at 2 Hz
  for (std::size_t k : {1u, 49u, 50u, 100u, 150u, 200u}) {
    std::complex<double> s = 0;
    for (std::size_t t = 0; t < n; ++t)
      s += e[t] * std::polar(1.0, -two_pi * static_cast<double>(k * t % n) / n);
    EXPECT_NEAR(ses[k], std::abs(s) / std::abs(dc), 1e-9) << k;
  }
  EXPECT_THROW(band_squared_envelope(X, n, rate, {1000, 1600}), InputError);
  EXPECT_THROW(band_squared_envelope(X, n, rate, {500, 501}), InputError);
}

TEST(FamilyTest, ThresholdsAreTheirClosedForms) {
  for (int w : {1, 7, 200})
    for (double p : {1e-4, 1e-2, 0.2}) {
      const double t = exceedance_threshold(p, w);
      EXPECT_NEAR(1 - std::pow(1 - std::exp(-t), w), p, 1e-12 * std::max(1.0, 1 / p)) << w;
    }
  for (double rate : {1e-6, 1e-3, 0.05}) {
    const double p2 = harmonic_probability(rate, 2);
    EXPECT_NEAR(3 * p2 * p2 - 2 * p2 * p2 * p2, rate, 1e-12 * rate);
    EXPECT_NEAR(std::pow(harmonic_probability(rate, 3), 3), rate, 1e-12 * rate);
    EXPECT_NEAR(-std::expm1(3 * std::log1p(-harmonic_probability(rate, 1))), rate, 1e-12 * rate);
  }
}

// The harmonics test alone at a stated rate of 0.05 per family in one band of white noise: it
// passes in a fraction 3p² − 2p³ = 0.05 of the tries if its exponential model holds (the floor's
// median estimate adds a little). 450 tries (150 records × 3 families): binomial(450, 0.05) lies
// in [10, 37] with probability 0.999.
TEST(FamilyTest, GaussianNoisePassesAtTheStatedRate) {
  const BearingFrequencies f = cwru();
  const LineTestSettings s;
  int passes = 0;
  for (std::uint64_t seed = 1; seed <= 150; ++seed) {
    const std::vector<double> x = gaussian(24000, 500 + seed);
    const auto X = whitened_spectrum(x);
    std::vector<double> power = band_squared_envelope(X, x.size(), kRate, {0, 6000});
    for (double& v : power) v *= v;
    const SesView view{&power, kRate / x.size(), 6000, nullptr};
    for (double c : {f.bpfo, f.bpfi, 2 * f.bsf})
      passes +=
          test_harmonics(view, FaultFamily::outer, c, harmonic_probability(0.05, 2), 2, s).detected;
  }
  RecordProperty("passes_of_450", passes);
  EXPECT_GE(passes, 10);
  EXPECT_LE(passes, 37);
}

// The whole diagnosis on white noise at the default 1e-3 per family: 150 records × 3 families =
// 450 tries, 0.45 alarms expected at most; 4 or more has probability 0.0011.
TEST(CoherenceDiagnosis, GaussianNoiseFalseAlarmsStayWithinTheStatedRate) {
  const BearingFrequencies f = cwru();
  int alarms = 0, named = 0;
  for (std::uint64_t seed = 1; seed <= 150; ++seed) {
    const CoherenceDiagnosis d = diagnose_coherence(gaussian(24000, 900 + seed), kRate, f);
    for (const FamilyEvidence& e : d.families) alarms += e.test.detected && e.stage == 0;
    named += d.family != FaultFamily::none;
  }
  RecordProperty("alarms_of_450", alarms);
  EXPECT_LE(alarms, 3);
  EXPECT_LE(named, 3);
}

TEST(CoherenceDiagnosis, NamesJitteredImpactsOfEachFamilyWithTheirPhysics) {
  const BearingFrequencies f = cwru();
  struct Fault {
    FaultFamily family;
    double rate, modulation;
  };
  for (const Fault& fault :
       {Fault{FaultFamily::outer, f.bpfo, 0.0}, Fault{FaultFamily::inner, f.bpfi, f.shaft},
        Fault{FaultFamily::ball, 2 * f.bsf, f.ftf}}) {
    const CoherenceDiagnosis d =
        diagnose_coherence(faulty(fault.rate, fault.modulation, 48000, 5), kRate, f);
    EXPECT_EQ(d.family, fault.family) << d.reason;
    EXPECT_GT(d.margin, 0) << d.reason;
    const FamilyEvidence& e = d.families[static_cast<int>(fault.family) - 1];
    EXPECT_TRUE(e.named);
    // The band chosen holds the 3 kHz resonance the impacts ring.
    const FrequencyBand& b = d.bands[e.band].band;
    EXPECT_LE(b.low, 3000) << d.reason;
    EXPECT_GE(b.high, 3000) << d.reason;
    EXPECT_NEAR(e.test.harmonics[0].frequency, fault.rate, 0.5);
    if (fault.family != FaultFamily::outer) {
      ASSERT_FALSE(e.test.side_lines.empty());
      EXPECT_GT(e.test.side_lines.front().excess, 0) << e.test.side_lines.front().label;
    }
  }
  // Without the load zone's modulation an inner-race comb lacks its physics: its harmonics pass
  // in the band of the resonance, its f_r sidebands do not, and it is not named inner.
  for (double depth : {0.0, 0.8}) {
    const std::vector<double> x = faulty(f.bpfi, depth > 0 ? f.shaft : 0.0, 48000, 5);
    const auto X = whitened_spectrum(x);
    std::vector<double> power = band_squared_envelope(X, x.size(), kRate, {1500, 4500});
    for (double& v : power) v *= v;
    const SesView view{&power, kRate / x.size(), 3000, nullptr};
    const FamilyTest t =
        test_family(view, FaultFamily::inner, f.bpfi, f.shaft, f.ftf, 1e-3, 2, false, {});
    EXPECT_EQ(t.standing_out, 3) << depth;
    EXPECT_EQ(t.physics, depth > 0) << depth;
    EXPECT_EQ(t.detected, depth > 0) << depth;
    if (depth == 0) EXPECT_NE(diagnose_coherence(x, kRate, f).family, FaultFamily::inner);
  }
}

// A ball spall carried through a narrow load zone: impacts at 2·BSF whose strength
// e^(8 (cos 2π FTF t − 1)) is nearly zero half the cage turn, so the SES holds 2·BSF ± m·FTF far
// out in m — and 2·BSF − 3·FTF lies 1.9 % below the 6205's BPFO, inside the outer race's window.
// The outer comb's fundamental is a line of the ball's series, not the other way round: ball.
TEST(CoherenceDiagnosis, ACombBorrowedFromAnothersSeriesIsThatOnes) {
  const BearingFrequencies f = cwru();
  const std::size_t n = 120000;
  std::vector<double> x = gaussian(n, 31);
  for (double& v : x) v *= 0.05;
  test::SplitMix64 g(32);
  const double c = 2 * f.bsf, decay = 0.03 * two_pi * 3000;
  for (int j = 0; j / c < n / kRate; ++j) {
    const double tj = std::max(0.0, (j + 0.01 * g.normal()) / c);
    const double a = std::exp(8 * (std::cos(two_pi * f.ftf * tj) - 1));
    for (std::size_t i = static_cast<std::size_t>(std::ceil(tj * kRate)); i < n; ++i) {
      const double t = i / kRate - tj;
      if (decay * t > 20) break;
      x[i] += a * std::exp(-decay * t) * std::sin(two_pi * 3000 * t);
    }
  }
  const CoherenceDiagnosis d = diagnose_coherence(x, kRate, f);
  EXPECT_EQ(d.family, FaultFamily::ball) << d.reason;
  const FamilyTest& outer = d.families[0].test;
  RecordProperty("outer_standing_out", outer.standing_out);
  if (outer.detected) {  // it passed, and was explained by the ball's series
    EXPECT_NEAR(outer.harmonics[0].frequency, c - 3 * f.ftf, 0.5) << d.reason;
    EXPECT_EQ(d.families[0].explained_by, FaultFamily::ball);
  }
}

TEST(CoherenceDiagnosis, DeterministicLinesAreNotFaults) {
  const BearingFrequencies f = cwru();
  const std::size_t n = 48000;
  // A strong sinusoid at BPFO and its harmonics in the record itself (a line, not a modulation).
  std::vector<double> x = gaussian(n, 77);
  for (std::size_t i = 0; i < n; ++i)
    for (int h = 1; h <= 3; ++h) x[i] += 10 * std::sin(two_pi * h * f.bpfo * i / kRate);
  const CoherenceDiagnosis line = diagnose_coherence(x, kRate, f);
  EXPECT_EQ(line.family, FaultFamily::none) << line.reason;
  // Noise whose strength turns with the shaft (shaft harmonics in every band's SES).
  std::vector<double> y = gaussian(n, 78);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = i / kRate;
    y[i] *= 1 + 0.5 * std::cos(two_pi * f.shaft * t) + 0.3 * std::cos(2 * two_pi * f.shaft * t);
  }
  const CoherenceDiagnosis shaft = diagnose_coherence(y, kRate, f);
  EXPECT_EQ(shaft.family, FaultFamily::none) << shaft.reason;
}

TEST(CoherenceDiagnosis, TwoFaultsInTwoBandsAreSeveral) {
  const BearingFrequencies f = cwru();
  const std::size_t n = 48000;
  const std::vector<double> outer = faulty(f.bpfo, 0, n, 11, 2000, 10);
  const std::vector<double> inner = faulty(f.bpfi, f.shaft, n, 12, 4500, 10);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = outer[i] + inner[i];
  const CoherenceDiagnosis d = diagnose_coherence(x, kRate, f);
  EXPECT_EQ(d.family, FaultFamily::several) << d.reason;
  ASSERT_EQ(d.named.size(), 2u);
  EXPECT_GT(d.margin, 0);
  EXPECT_TRUE(d.families[0].named && d.families[1].named) << d.reason;
  // One alone is that one (its lines explained, the other race is not named).
  EXPECT_EQ(diagnose_coherence(outer, kRate, f).family, FaultFamily::outer);
}

TEST(CoherenceDiagnosis, BadSettingsAreRefused) {
  const BearingFrequencies f = cwru();
  const std::vector<double> x = gaussian(4800, 1);
  LineTestSettings s;
  s.slip = 0;
  EXPECT_THROW(diagnose_coherence(x, kRate, f, 3, s), InputError);
  s = {};
  s.false_alarm = 0.5;
  EXPECT_THROW(diagnose_coherence(x, kRate, f, 3, s), InputError);
  s = {};
  s.decoy_span = -1;
  EXPECT_THROW(diagnose_coherence(x, kRate, f, 3, s), InputError);
  BearingFrequencies still = f;
  still.shaft = 0;
  EXPECT_THROW(diagnose_coherence(x, kRate, still), InputError);
  std::vector<double> bad = x;
  bad[7] = std::nan("");
  try {
    diagnose_coherence(bad, kRate, f);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sample 7"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace bearing
