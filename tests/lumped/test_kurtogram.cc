// Spectral kurtosis against its closed forms (tone −1, Gaussian noise 0, a ringing impact train
// (T/τ) coth(T/τ) − 2), the fast kurtogram's tree, and the kurtogram finding the band of an
// impact train buried in noise, whose envelope then shows the impact rate.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <vector>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/signal/envelope.h"
#include "bearing/signal/fft.h"
#include "bearing/signal/kurtogram.h"
#include "bearing/signal/peaks.h"
#include "synthetic_signals.h"

namespace bearing {
namespace {

using test::ImpactTrain;

constexpr double kFs = 20000;      // [Hz]
constexpr std::size_t kN = 20000;  // 1 s: 1 Hz bins

std::vector<double> tone(double f, double amplitude, std::size_t n = kN, double fs = kFs) {
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = amplitude * std::sin(two_pi * f * i / fs + 0.4);
  return x;
}

TEST(SpectralKurtosis, PureToneIsMinusOne) {
  // On a bin, any amplitude, any band holding the tone's three windowed bins.
  for (double amplitude : {1e-9, 1.0, 3e6}) {
    const std::vector<double> x = tone(1234, amplitude);
    EXPECT_NEAR(spectral_kurtosis(x, kFs, {1000, 1500}), -1.0, 1e-12) << amplitude;
    EXPECT_NEAR(spectral_kurtosis(x, kFs, {1233, 1235}), -1.0, 1e-12) << amplitude;
    EXPECT_NEAR(spectral_kurtosis(x, kFs, {0, kFs / 2}), -1.0, 1e-12) << amplitude;
  }
  // A band the tone does not reach is silent: 0, not NaN.
  EXPECT_EQ(spectral_kurtosis(tone(1234, 1.0), kFs, {3000, 4000}), 0.0);
  EXPECT_EQ(spectral_kurtosis(std::vector<double>(100, 2.5), kFs, {0, kFs / 2}), 0.0);
}

TEST(SpectralKurtosis, StationaryGaussianNoiseIsZero) {
  // Mean of 40 records over a band of M = 1001 bins: each estimate scatters by about 3/√M, so the
  // mean of 40 lies within 0.1/√40·3 ≈ 0.015 of 0 (3 standard errors: 0.045).
  double sum = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    test::SplitMix64 g(seed);
    std::vector<double> x(kN);
    for (double& v : x) v = g.normal();
    const double sk = spectral_kurtosis(x, kFs, {4000, 5000});
    EXPECT_LT(std::abs(sk), 0.4) << seed;  // > 4 standard deviations: never with these seeds
    sum += sk;
  }
  EXPECT_NEAR(sum / 40, 0.0, 0.045);
}

TEST(SpectralKurtosis, RingingImpactTrainIsTOverTauCothMinusTwo) {
  // Impacts every T = 200 samples on a 5 kHz resonance with ζ = 0.02: the complex envelope decays
  // as e^{−t/τ}, τ = 1/(ζ ω_n) = 31.8 samples, each impact's tail adding to the next as a phasor,
  // so over one period |c|² ∝ e^{−2t/τ} and ⟨|c|⁴⟩/⟨|c|²⟩² = (T/τ) coth(T/τ): SK = 4.28. Over the
  // whole band the sampled damped sine's analytic signal differs from the complex exponential by
  // its negative-frequency part (1.1 %); a band of ±2.5 kHz cuts the ringing's onset (−4 %).
  ImpactTrain p;
  p.rate = 100;
  const std::vector<double> x = test::impact_train(p, kN, kFs);
  const double r = (kFs / p.rate) * (p.damping_ratio * two_pi * p.resonance / kFs);
  const double closed = r / std::tanh(r) - 2;
  EXPECT_NEAR(closed, 4.283, 1e-3);
  EXPECT_NEAR(spectral_kurtosis(x, kFs, {0, kFs / 2}), closed, 0.02 * closed);
  EXPECT_NEAR(spectral_kurtosis(x, kFs, {2500, 7500}), closed, 0.06 * closed);
  // Rarer impacts: more impulsive.
  p.rate = 25;
  EXPECT_GT(spectral_kurtosis(test::impact_train(p, kN, kFs), kFs, {0, kFs / 2}), 3 * closed);
}

// The noise floor ν is the SK the band would have with white noise of ν times the record's power
// added: the closed form SK·(E_b/(E_b + ν E M/⌊N/2⌋))² on the whole band, and the mean over noisy
// copies of the record within its standard error.
TEST(SpectralKurtosis, NoiseFloorIsTheSkUnderThatMuchWhiteNoise) {
  ImpactTrain p;
  p.rate = 100;
  const std::vector<double> x = test::impact_train(p, kN, kFs);
  const double clean = spectral_kurtosis(x, kFs, {0, kFs / 2});
  EXPECT_NEAR(spectral_kurtosis(x, kFs, {0, kFs / 2}, 0.25), clean / (1.25 * 1.25), 1e-12);
  EXPECT_EQ(spectral_kurtosis(x, kFs, {0, kFs / 2}, 0), clean);
  const FrequencyBand band{4000, 6000};  // M = 2001 of the 10000 bins
  const double nu = 0.5, floored = spectral_kurtosis(x, kFs, band, nu);
  EXPECT_LT(floored, 0.9 * spectral_kurtosis(x, kFs, band));
  double sum = 0;
  const int copies = 20;
  for (int seed = 1; seed <= copies; ++seed) {
    // ν times the record's power: the mean-square of x (its mean is about 0).
    const double snr_db = -10 * std::log10(nu);
    sum += spectral_kurtosis(test::with_noise(x, snr_db, seed), kFs, band);
  }
  // Each noisy estimate scatters by about 3/√M = 0.07 (noise) plus the signal's share: 0.03 for
  // the mean of 20, 3 standard errors 0.1.
  EXPECT_NEAR(sum / copies, floored, 0.1);
  EXPECT_THROW(spectral_kurtosis(x, kFs, band, -0.1), InputError);
  EXPECT_THROW(fast_kurtogram(x, kFs, {0, std::numeric_limits<double>::infinity()}), InputError);
}

TEST(Kurtogram, TreeHasTheOneThirdBinaryLevelsDownToTheNarrowestBand) {
  const Kurtogram k = fast_kurtogram(tone(1234, 1.0), kFs);
  // N = 20000: bands at least 64 bins (64 Hz) wide: 10 kHz / 128 = 78 Hz is the deepest level.
  const std::vector<int> counts = {1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128};
  std::vector<int> seen;
  for (const KurtogramBand& b : k.map)
    if (seen.empty() || seen.back() != b.bands) seen.push_back(b.bands);
  EXPECT_EQ(seen, counts);
  std::size_t i = 0;
  for (int bands : counts)
    for (int j = 0; j < bands; ++j, ++i) {
      const KurtogramBand& b = k.map.at(i);
      EXPECT_EQ(b.bands, bands);
      EXPECT_EQ(b.index, j);
      EXPECT_DOUBLE_EQ(b.level, std::log2(static_cast<double>(bands)));
      EXPECT_NEAR(b.band.low, j * 10000.0 / bands, 1e-9);
      EXPECT_NEAR(b.band.high, (j + 1) * 10000.0 / bands, 1e-9);
    }
  EXPECT_EQ(i, k.map.size());
  EXPECT_NEAR(k.map[3].level, 1.585, 1e-3);  // Antoni's "1.6"
  // A tone: every band holding it has SK −1, the others are silent (0): the best is a silent
  // band, the first (coarsest, lowest) of those: [0, 5 kHz] at level 1 holds the tone, so the
  // first silent band is [5, 10] kHz.
  EXPECT_EQ(k.best.bands, 2);
  EXPECT_EQ(k.best.index, 1);
  EXPECT_NEAR(k.map[0].spectral_kurtosis, -1.0, 1e-12);
  // A minimum band width stops the tree earlier.
  const Kurtogram wide = fast_kurtogram(tone(1234, 1.0), kFs, {500});
  EXPECT_EQ(wide.map.back().bands, 16);  // 625 Hz; 24 bands would be 417 Hz
  // Each band's SK is spectral_kurtosis() of its band (to rounding: the kurtogram pads a level's
  // bands to one transform length).
  test::SplitMix64 g(5);
  std::vector<double> noisy = tone(1234, 1.0);
  for (double& v : noisy) v += 0.3 * g.normal();
  const Kurtogram k2 = fast_kurtogram(noisy, kFs, {500, 0.01});
  for (std::size_t j = 0; j < k2.map.size(); j += 5)
    EXPECT_NEAR(k2.map[j].spectral_kurtosis, spectral_kurtosis(noisy, kFs, k2.map[j].band, 0.01),
                1e-12)
        << j;
}

// Issue 17's acceptance: a 5 kHz resonance (ζ = 0.02) struck at 97 Hz, buried in white noise at
// −6 dB (the noise's RMS twice the impacts'; the whole record is then almost Gaussian, SK 0.07):
// the kurtogram picks a band around the resonance — the third level's [3.33, 6.67] kHz, since
// 5 kHz is an edge of every binary band — more impulsive than anything the same noise alone
// reaches, and that band's envelope spectrum has its largest line at the impact rate.
TEST(Kurtogram, PicksTheBandOfAnImpactTrainBuriedInNoise) {
  ImpactTrain p;  // 97 Hz, 5 kHz, ζ = 0.02
  const std::vector<double> train = test::impact_train(p, kN, kFs);
  const std::vector<double> x = test::with_noise(train, -6.0, 17);
  const Kurtogram k = fast_kurtogram(x, kFs, {300});
  const FrequencyBand b = k.best.band;
  EXPECT_LT(b.low, 5000.0);
  EXPECT_GT(b.high, 5000.0);
  EXPECT_GE(k.best.bands, 2) << "the whole band is noise-dominated";
  EXPECT_LT(k.map[0].spectral_kurtosis, 0.25 * k.best.spectral_kurtosis);
  // The same noise alone (the train's RMS × 2, same seed).
  const double sigma = 2 * test::rms(train);
  test::SplitMix64 g(17);
  std::vector<double> noise(kN);
  for (double& v : noise) v = sigma * g.normal();
  EXPECT_GT(k.best.spectral_kurtosis,
            1.5 * fast_kurtogram(noise, kFs, {300}).best.spectral_kurtosis);
  const Spectrum s = envelope_spectrum(x, kFs, b, Window::hann);
  const std::vector<Peak> peaks = find_peaks(s, {{"rate", 97.0}}, 1);
  ASSERT_EQ(peaks.size(), 1u);
  EXPECT_EQ(peaks[0].label, "rate") << peaks[0].frequency;
  EXPECT_NEAR(peaks[0].frequency, 97.0, 0.1);
}

TEST(Kurtogram, RejectsShortRecordsNonFiniteSamplesAndBadBands) {
  const auto message = [](auto f) {
    try {
      f();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  std::vector<double> x = tone(1234, 1.0, 100);
  x[37] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(message([&] { fast_kurtogram(x, kFs); }).find("sample 37 = nan"), std::string::npos)
      << message([&] { fast_kurtogram(x, kFs); });
  EXPECT_NE(message([] { fast_kurtogram({1.0}, kFs); }).find("1 samples"), std::string::npos);
  EXPECT_NE(message([] { fast_kurtogram(tone(1, 1, 100), 0); }).find("sample rate = 0"),
            std::string::npos);
  EXPECT_NE(message([] { fast_kurtogram(tone(1, 1, 100), kFs, {-1}); }).find("-1 Hz"),
            std::string::npos);
  EXPECT_NE(message([] {
              spectral_kurtosis(tone(1, 1, 100), kFs, {200, 100});
            }).find("[200 Hz, 100 Hz]: allowed 0 <= low < high <= 10000 Hz"),
            std::string::npos);
  EXPECT_THROW(spectral_kurtosis(tone(1, 1, 100), kFs, {0, 10001}), InputError);
  EXPECT_NO_THROW(fast_kurtogram(tone(1, 1, 2), kFs));  // shortest record: level 0 only
  EXPECT_EQ(fast_kurtogram(tone(1, 1, 2), kFs).map.size(), 1u);
}

// The complex DFT both ways against the direct sums, on a length with factors 2, 3, 5 and 7.
TEST(ComplexFft, MatchesTheDirectDftBothWays) {
  const std::size_t n = 210;
  test::SplitMix64 g(3);
  std::vector<std::complex<double>> x(n);
  for (auto& v : x) v = {g.normal(), g.normal()};
  std::vector<std::complex<double>> X = x, back;
  ComplexFft fft(n);
  fft.forward(X);
  double worst = 0;
  for (std::size_t k = 0; k < n; ++k) {
    std::complex<double> direct = 0;
    for (std::size_t j = 0; j < n; ++j)
      direct += x[j] * std::polar(1.0, -two_pi * static_cast<double>((j * k) % n) / n);
    worst = std::max(worst, std::abs(X[k] - direct));
  }
  EXPECT_LT(worst, 1e-12);
  back = X;
  fft.inverse(back);  // unscaled: N x
  for (std::size_t j = 0; j < n; ++j) EXPECT_NEAR(std::abs(back[j] / double(n) - x[j]), 0, 1e-14);
  EXPECT_EQ(fast_fft_length(211), 216u);
  EXPECT_EQ(fast_fft_length(1), 1u);
  EXPECT_THROW(ComplexFft(0), InputError);
  EXPECT_THROW(ComplexFft(67), InputError);  // prime above 64
  EXPECT_THROW(fft.forward(x = std::vector<std::complex<double>>(3)), InputError);
}

}  // namespace
}  // namespace bearing
