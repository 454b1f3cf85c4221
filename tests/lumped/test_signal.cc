// Signal layer against closed forms: sine, square and Gaussian moments; on-bin DFT of windowed
// tones; Parseval; the direct DFT; scalloping and sidelobe levels of the windows; peak naming.

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/signal/envelope.h"
#include "bearing/signal/peaks.h"
#include "bearing/signal/spectrum.h"
#include "bearing/signal/statistics.h"
#include "synthetic_signals.h"

namespace bearing {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

using test::SplitMix64;  // a fixed-seed generator of our own (synthetic_signals.h)

// A sin(2π (cycles / n) j + phase) + offset, j = 0 … n−1, with the phase reduced exactly in
// integers so large j loses no accuracy when cycles is an integer.
std::vector<double> sine(std::size_t n, double cycles, double amplitude, double phase = 0.3,
                         double offset = 0.0) {
  std::vector<double> x(n);
  const double whole = std::floor(cycles), part = cycles - whole;
  const auto k = static_cast<std::uint64_t>(whole);
  for (std::size_t j = 0; j < n; ++j) {
    const double turns = static_cast<double>((k * j) % n) / static_cast<double>(n) +
                         part * static_cast<double>(j) / static_cast<double>(n);
    x[j] = offset + amplitude * std::sin(two_pi * turns + phase);
  }
  return x;
}

std::size_t argmax_non_dc(const Spectrum& s) {
  std::size_t k = 1;
  for (std::size_t j = 1; j < s.amplitude.size(); ++j)
    if (s.amplitude[j] > s.amplitude[k]) k = j;
  return k;
}

// ----------------------------------------------------------------------------------------------
// Statistics

TEST(SignalStatistics, SampledSineMatchesClosedForms) {
  // 50 whole periods of 480 samples: Σ sin² = N/2 and Σ sin⁴ = 3N/8 hold exactly for the samples,
  // so mean, rms and kurtosis are exact to rounding. Max and min are sampled within half a sample
  // of the crest: |phase error| ≤ π/480, so they fall short by at most 1 − cos(π/480) = 2.2e-5.
  const double A = 3.0, offset = 5.0;
  const std::size_t n = 24000;
  const ChannelStatistics s = channel_statistics(sine(n, 50, A, 0.3, offset));
  const double sampling = 1.0 - std::cos(pi / 480);
  EXPECT_NEAR(s.mean, offset, 1e-12 * offset);
  EXPECT_NEAR(s.rms, A / std::sqrt(2.0), 1e-12 * A);
  EXPECT_NEAR(s.kurtosis, 1.5, 1e-11);
  EXPECT_LE(s.crest, std::sqrt(2.0) * (1 + 1e-12));
  EXPECT_GE(s.crest, std::sqrt(2.0) * (1 - sampling));
  EXPECT_LE(s.ptp, 2 * A * (1 + 1e-12));
  EXPECT_GE(s.ptp, 2 * A * (1 - sampling));
}

// The overflow guard divides by a power of two, which is exact: the mean is bit for bit the plain
// sum over n of the same values in the same order (any other scale would round each term).
TEST(SignalStatistics, OverflowScalingAddsNoRounding) {
  std::vector<double> x;
  for (int k = 0; k < 1000; ++k) x.push_back(0.1 * k + 1.0 / 3.0 + std::sin(0.37 * k));
  double sum = 0;
  for (double v : x) sum += v;
  const ChannelStatistics s = channel_statistics(x);
  EXPECT_EQ(s.mean, sum / 1000.0);
}

TEST(SignalStatistics, SquareWaveHasKurtosisAndCrestOne) {
  // ±A about an offset, equal halves: every deviation has magnitude A, so all ratios are exact
  // but for summation rounding, bounded by N·ε ≈ 1e-13 relative for N = 1000.
  const double A = 0.25, offset = -2.0;
  std::vector<double> x(1000);
  for (std::size_t j = 0; j < x.size(); ++j) x[j] = offset + ((j / 50) % 2 == 0 ? A : -A);
  const ChannelStatistics s = channel_statistics(x);
  EXPECT_NEAR(s.mean, offset, 1e-12);
  EXPECT_NEAR(s.rms, A, 1e-12);
  EXPECT_DOUBLE_EQ(s.ptp, 2 * A);
  EXPECT_NEAR(s.kurtosis, 1.0, 1e-12);
  EXPECT_NEAR(s.crest, 1.0, 1e-12);
}

TEST(SignalStatistics, GaussianKurtosisIsThreeWithinTwoStandardErrors) {
  // Sample kurtosis of N normal variates has standard error sqrt(24/N); the sample mean σ/√N and
  // the sample standard deviation σ/sqrt(2N). Kurtosis within two standard errors (as asked),
  // mean and rms within three, fixed seed.
  const std::size_t n = 1000000;
  const double sigma = 2e-6, mu = 1e-3;
  SplitMix64 rng(20240611);
  std::vector<double> x(n);
  for (double& v : x) v = mu + sigma * rng.normal();
  const ChannelStatistics s = channel_statistics(x);
  const double N = static_cast<double>(n);
  EXPECT_NEAR(s.kurtosis, 3.0, 2 * std::sqrt(24 / N));
  EXPECT_NEAR(s.mean, mu, 3 * sigma / std::sqrt(N));
  EXPECT_NEAR(s.rms, sigma, 3 * sigma / std::sqrt(2 * N));
}

TEST(SignalStatistics, ConstantSignalGivesZeroNotNaN) {
  for (const std::vector<double>& x :
       {std::vector<double>(1000, 0.1), std::vector<double>{7.5}, std::vector<double>(3, 0.0)}) {
    const ChannelStatistics s = channel_statistics(x);
    EXPECT_EQ(s.mean, x[0]);  // exact: no summation rounding for a constant
    EXPECT_EQ(s.rms, 0.0);
    EXPECT_EQ(s.ptp, 0.0);
    EXPECT_EQ(s.kurtosis, 0.0);
    EXPECT_EQ(s.crest, 0.0);
  }
}

TEST(SignalStatistics, TinyAndHugeSignalsKeepTheirShape) {
  // A 1e-90 sine has fourth moments of 1e-360 (below the smallest double) and a 1e300 sine sums
  // past the largest; the shape factors must still be the sine's.
  for (double A : {1e-90, 1e300}) {
    const ChannelStatistics s = channel_statistics(sine(4800, 10, A));
    EXPECT_NEAR(s.rms / A, 1 / std::sqrt(2.0), 1e-12) << A;
    EXPECT_NEAR(s.kurtosis, 1.5, 1e-11) << A;
    EXPECT_NEAR(s.crest, std::sqrt(2.0), 1e-4) << A;  // 480 samples a period, as above
  }
}

TEST(SignalStatistics, RejectsEmptyAndNonFiniteInput) {
  EXPECT_THROW(channel_statistics({}), InputError);
  EXPECT_THROW(channel_statistics({1.0, kNaN, 2.0}), InputError);
  EXPECT_THROW(channel_statistics({1.0, 2.0, kInf}), InputError);
  EXPECT_THROW(channel_statistics({-kInf}), InputError);
}

// ----------------------------------------------------------------------------------------------
// Spectrum

struct NamedWindow {
  Window window;
  std::size_t half_width;  // main-lobe half-width of the periodic window's DFT [bins]
};
constexpr NamedWindow kAllWindows[] = {
    {Window::rectangular, 0}, {Window::hann, 1}, {Window::flattop, 4}};

TEST(SignalSpectrum, OnBinSineIsExactForEveryWindowAndLength) {
  // A periodic cosine-sum window's DFT is non-zero only within its half-width h, so a tone on
  // bin k shows exactly A there and nothing beyond k ± h. Lengths: 24000 = 2⁶·3·5³, the primes
  // 4801 and 997 (Bluestein path), 3904 = 61·64 (GSL's generic radix-61 pass), 25728 = 67·384
  // (Bluestein, just above the radix limit), 210 = 2·3·5·7.
  const double fs = 2000.0, A = 0.7;
  for (std::size_t n : {24000u, 4801u, 997u, 3904u, 25728u, 210u}) {
    const std::size_t k = n / 5 + 1;
    const std::vector<double> x = sine(n, static_cast<double>(k), A, 1.1, 3.0);
    for (const NamedWindow& w : kAllWindows) {
      const Spectrum s = amplitude_spectrum(x, fs, w.window);
      ASSERT_EQ(s.amplitude.size(), n / 2 + 1);
      ASSERT_EQ(s.frequency.size(), n / 2 + 1);
      EXPECT_DOUBLE_EQ(s.resolution, fs / n);
      EXPECT_DOUBLE_EQ(s.frequency[k], k * fs / n);
      EXPECT_NEAR(s.amplitude[k], A, 1e-11 * A) << "N = " << n << ", window " << w.half_width;
      double leak = 0;
      for (std::size_t j = 0; j < s.amplitude.size(); ++j)
        if (j + w.half_width < k || j > k + w.half_width) leak = std::max(leak, s.amplitude[j]);
      EXPECT_LT(leak, 1e-11 * A) << "N = " << n << ", window " << w.half_width;
    }
  }
}

TEST(SignalSpectrum, FlattopIsAmplitudeCorrectBetweenBins) {
  // HFT90D is flat to 0.0039 dB (0.045 %) over ±½ bin; the test allows 0.1 %.
  const double A = 1.3;
  for (std::size_t n : {24000u, 4801u, 997u}) {
    for (double offset : {0.1, 0.25, 0.37, 0.5}) {
      const double cycles = std::floor(n / 4.0) + offset;
      const Spectrum s = amplitude_spectrum(sine(n, cycles, A), 1000.0, Window::flattop);
      EXPECT_NEAR(s.amplitude[argmax_non_dc(s)], A, 1e-3 * A)
          << "N = " << n << ", offset " << offset;
    }
  }
}

TEST(SignalSpectrum, SidelobesStayBelowThePublishedLevels) {
  // Peak sidelobe levels: Hann −31.5 dB (Harris 1978), HFT90D −90.2 dB (Heinzel et al. 2002),
  // beyond the main lobes (±2 and ±5 bins) of an off-bin tone. Bins within the main lobe of DC are
  // skipped: removing the sample mean of a non-whole number of periods (up to A/(π·cycles))
  // leaves a constant that the window spreads there. This pins the flat-top coefficients: a
  // 4 % change of the last one lifts the sidelobes to −73 dB while the flatness still passes.
  struct Case {
    Window window;
    double lobe, level_db;
  };
  for (const Case& c : {Case{Window::hann, 2.0, -31.4}, Case{Window::flattop, 5.0, -90.0}}) {
    for (std::size_t n : {24000u, 997u}) {
      for (double offset : {0.0, 0.2, 0.5}) {
        const double cycles = std::floor(n / 4.0) + offset;
        const Spectrum s = amplitude_spectrum(sine(n, cycles, 1.0), 1.0, c.window);
        double worst = 0;
        for (std::size_t k = 0; k < s.amplitude.size(); ++k)
          if (k > c.lobe && std::abs(k - cycles) > c.lobe) worst = std::max(worst, s.amplitude[k]);
        EXPECT_LT(20 * std::log10(worst), c.level_db) << "N = " << n << ", offset " << offset;
      }
    }
  }
}

TEST(SignalSpectrum, HannAndRectangularScallopAsTheirTransformsPredict) {
  // Half a bin off, the largest bin reads A·|W(½)|/W(0): for rectangular the Dirichlet kernel
  // sin(π/2) / (N sin(π/2N)), for Hann sinc(½)/(1 − ¼) = (2/π)/(3/4) in the large-N limit
  // (1/N² corrections, and the mirror tone leaks < 1e-4 at N/2 bins away). The check that the
  // windows are the right ones and the scaling is by the coherent gain.
  const std::size_t n = 24000;
  const double A = 2.0;
  const std::vector<double> x = sine(n, 6000.5, A);
  const Spectrum hann = amplitude_spectrum(x, 1.0, Window::hann);
  const Spectrum rect = amplitude_spectrum(x, 1.0, Window::rectangular);
  EXPECT_NEAR(hann.amplitude[6000] / A, (2 / pi) / 0.75, 1e-4);
  EXPECT_NEAR(hann.amplitude[6001], hann.amplitude[6000], 1e-9);
  EXPECT_NEAR(rect.amplitude[6000] / A, 1.0 / (n * std::sin(pi / (2.0 * n))), 1e-4);
}

TEST(SignalSpectrum, SeparatesTwoTones) {
  // On-bin tones three bins apart: Hann leaks only to ±1 bin, so both read exactly and the bins
  // between hold only the ½-amplitude skirts (A₁/2 at k₁+1, A₂/2 at k₂−1).
  const std::size_t n = 8000;
  const double fs = 8000.0;
  std::vector<double> x = sine(n, 1000, 1.0, 0.2);
  const std::vector<double> second = sine(n, 1003, 0.1, 2.0);
  for (std::size_t j = 0; j < n; ++j) x[j] += second[j];
  const Spectrum s = amplitude_spectrum(x, fs, Window::hann);
  EXPECT_NEAR(s.amplitude[1000], 1.0, 1e-12);
  EXPECT_NEAR(s.amplitude[1003], 0.1, 1e-12);
  EXPECT_NEAR(s.amplitude[1001], 0.5, 1e-12);
  EXPECT_NEAR(s.amplitude[1002], 0.05, 1e-12);

  const std::vector<Peak> peaks = find_peaks(s, {}, 10, 1e-3);
  ASSERT_EQ(peaks.size(), 2u);
  EXPECT_NEAR(peaks[0].frequency, 1000.0, 1e-9);
  EXPECT_NEAR(peaks[1].frequency, 1003.0, 1e-9);
  EXPECT_NEAR(peaks[1].amplitude, 0.1, 1e-12);
}

TEST(SignalSpectrum, RemovesTheMean) {
  // Whole periods, so the sampled mean is the offset: the DC bin holds only the rounding of the
  // mean of 4000 values near 1e3 (≲ 1e-11; allowed 1e-9 = 1e-12 of the offset), and an integer
  // constant, whose mean is exact, has an all-zero spectrum.
  const std::size_t n = 4000;
  const std::vector<double> x = sine(n, 37, 0.01, 0.0, 1e3);
  for (const NamedWindow& w : kAllWindows) {
    const Spectrum s = amplitude_spectrum(x, 100.0, w.window);
    EXPECT_LT(s.amplitude[0], 1e-9);
    EXPECT_NEAR(s.amplitude[37], 0.01, 1e-11);
    const Spectrum flat = amplitude_spectrum(std::vector<double>(n, 42.0), 100.0, w.window);
    for (double a : flat.amplitude) EXPECT_EQ(a, 0.0);
  }
}

TEST(SignalSpectrum, ScalesTinyAndHugeSignals) {
  // Amplitudes near the ends of the double range: the transform must neither overflow nor lose
  // the tone (both lengths, both FFT paths).
  for (std::size_t n : {4800u, 997u})
    for (double A : {1e-300, 1e300}) {
      const Spectrum s = amplitude_spectrum(sine(n, 101, A), 1.0, Window::flattop);
      EXPECT_NEAR(s.amplitude[101] / A, 1.0, 1e-11) << n << " " << A;
    }
}

TEST(SignalSpectrum, ParsevalHoldsForTheRectangularWindow) {
  // With w = 1: mean square of x − x̄ = a₀² + Σ_{0<k<N/2} a_k²/2 + a_{N/2}² (the last term only
  // for even N), since a one-sided bin of amplitude a carries power a²/2.
  for (std::size_t n : {4096u, 4801u, 3904u, 1001u}) {
    SplitMix64 rng(n);
    std::vector<double> x(n);
    for (double& v : x) v = rng.uniform() - 0.3;
    double mean = 0, power = 0;
    for (double v : x) mean += v;
    mean /= n;
    for (double v : x) power += (v - mean) * (v - mean);
    power /= n;
    const Spectrum s = amplitude_spectrum(x, 1.0, Window::rectangular);
    double sum = s.amplitude[0] * s.amplitude[0];
    for (std::size_t k = 1; k < s.amplitude.size(); ++k)
      sum += (2 * k == n ? 1.0 : 0.5) * s.amplitude[k] * s.amplitude[k];
    EXPECT_NEAR(sum, power, 1e-12 * power) << "N = " << n;
  }
}

TEST(SignalSpectrum, MatchesTheDirectDft) {
  // The definition X_k = Σ w_j (x_j − x̄) e^{−2πijk/N}, summed directly in long double, checks the
  // half-complex unpacking and the Bluestein path bin by bin (not just at a tone).
  for (std::size_t n : {210u, 211u, 536u, 997u}) {  // 211, 997 prime; 536 = 67·8
    SplitMix64 rng(7 * n);
    std::vector<double> x(n);
    for (double& v : x) v = rng.normal();
    const Spectrum s = amplitude_spectrum(x, 1.0, Window::hann);
    long double mean = 0, wsum = 0;
    for (double v : x) mean += v;
    mean /= n;
    std::vector<long double> wx(n);
    for (std::size_t j = 0; j < n; ++j) {
      const long double w = 0.5L - 0.5L * std::cos(2 * static_cast<long double>(pi) * j / n);
      wx[j] = w * (x[j] - mean);
      wsum += w;
    }
    for (std::size_t k = 0; k <= n / 2; ++k) {
      std::complex<long double> X = 0;
      for (std::size_t j = 0; j < n; ++j)
        X += wx[j] * std::polar(1.0L, -2 * static_cast<long double>(pi) * ((j * k) % n) / n);
      const long double expected = (k == 0 || 2 * k == n ? 1 : 2) * std::abs(X) / wsum;
      ASSERT_NEAR(s.amplitude[k], static_cast<double>(expected), 1e-13)
          << "N = " << n << " k " << k;
    }
  }
}

TEST(SignalSpectrum, RejectsBadInput) {
  EXPECT_THROW(amplitude_spectrum({}, 1.0), InputError);
  EXPECT_THROW(amplitude_spectrum({1.0}, 1.0), InputError);
  EXPECT_THROW(amplitude_spectrum({1.0, kNaN, 3.0}, 1.0), InputError);
  EXPECT_THROW(amplitude_spectrum({1.0, kInf, 3.0}, 1.0), InputError);
  for (double fs : {0.0, -100.0, kNaN, kInf})
    EXPECT_THROW(amplitude_spectrum({1.0, 2.0, 3.0}, fs), InputError) << fs;
}

// One plan, several signals: bin for bin what amplitude_spectrum() gives for each alone, on both
// DFT paths (N = 2^5 5^3: mixed radix; N = 1009, prime: Bluestein), every window; the plan keeps
// no state from one signal to the next.
TEST(SignalSpectrum, PlanMatchesOneShotSpectraOnBothPaths) {
  SplitMix64 rng(99);
  for (std::size_t n : {std::size_t{4000}, std::size_t{1009}}) {
    for (Window w : {Window::hann, Window::flattop, Window::rectangular}) {
      SpectrumPlan plan(n, 250.0, w);
      for (int signal = 0; signal < 3; ++signal) {
        std::vector<double> x(n);
        for (double& v : x) v = (signal + 1) * rng.normal() + signal;
        const Spectrum a = plan(x), b = amplitude_spectrum(x, 250.0, w);
        ASSERT_EQ(a.amplitude.size(), b.amplitude.size());
        EXPECT_EQ(a.resolution, b.resolution);
        for (std::size_t k = 0; k < a.amplitude.size(); ++k) {
          EXPECT_EQ(a.frequency[k], b.frequency[k]);
          EXPECT_EQ(a.amplitude[k], b.amplitude[k]) << "N " << n << " bin " << k;
        }
      }
    }
  }
  SpectrumPlan plan(8, 1.0, Window::hann);
  EXPECT_THROW(plan(std::vector<double>(7, 1.0)), InputError);
  EXPECT_THROW(plan({1, 2, 3, kNaN, 5, 6, 7, 8}), InputError);
  EXPECT_THROW(SpectrumPlan(1, 1.0, Window::hann), InputError);
  EXPECT_THROW(SpectrumPlan(8, kNaN, Window::hann), InputError);
}

TEST(SignalSpectrum, ParsesWindowNames) {
  EXPECT_EQ(parse_window("hann", "output.window"), Window::hann);
  EXPECT_EQ(parse_window("flattop", "output.window"), Window::flattop);
  EXPECT_EQ(parse_window("rectangular", "output.window"), Window::rectangular);
  for (const NamedWindow& w : kAllWindows)
    EXPECT_EQ(parse_window(window_name(w.window), "k"), w.window);
  for (const char* bad : {"hanning", "Hann", "", "flat-top", "boxcar"})
    EXPECT_THROW(parse_window(bad, "output.window"), InputError) << bad;
  try {
    parse_window("han", "output.window");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("output.window"), std::string::npos) << msg;
    EXPECT_NE(msg.find("did you mean \"hann\""), std::string::npos) << msg;
  }
}

// ----------------------------------------------------------------------------------------------
// Peaks

// A spectrum with resolution 1 Hz, bins 0 … m−1, and a symmetric three-bin peak (½, 1, ½)·a at
// each given bin, so the refined frequency is exactly the bin's.
Spectrum synthetic(std::size_t m, const std::vector<std::pair<std::size_t, double>>& lines) {
  Spectrum s;
  s.resolution = 1.0;
  s.frequency.resize(m);
  s.amplitude.assign(m, 0.0);
  for (std::size_t k = 0; k < m; ++k) s.frequency[k] = static_cast<double>(k);
  for (const auto& [k, a] : lines) {
    s.amplitude[k] += a;
    s.amplitude[k - 1] += 0.5 * a;
    s.amplitude[k + 1] += 0.5 * a;
  }
  return s;
}

TEST(SignalPeaks, NamesEveryHarmonicInOrder) {
  const std::vector<NamedFrequency> names = bearing_frequency_names(25, 10, 89.5, 135.5, 59, 3);
  const std::vector<std::string> labels = {"fr",     "2xfr",   "3xfr",   "FTF",    "2xFTF",
                                           "3xFTF",  "BPFO",   "2xBPFO", "3xBPFO", "BPFI",
                                           "2xBPFI", "3xBPFI", "BSF",    "2xBSF",  "3xBSF"};
  const std::vector<double> base = {25, 10, 89.5, 135.5, 59};
  // The plain harmonics first, then the inner race's shaft sidebands k·BPFI ± f_r.
  ASSERT_EQ(names.size(), labels.size() + 6);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    EXPECT_EQ(names[i].label, labels[i]);
    EXPECT_DOUBLE_EQ(names[i].frequency, base[i / 3] * static_cast<double>(i % 3 + 1));
  }
  const std::vector<std::string> sidebands = {"BPFI-fr",   "BPFI+fr",   "2xBPFI-fr",
                                              "2xBPFI+fr", "3xBPFI-fr", "3xBPFI+fr"};
  for (std::size_t i = 0; i < sidebands.size(); ++i) {
    EXPECT_EQ(names[labels.size() + i].label, sidebands[i]);
    const double k = static_cast<double>(i / 2 + 1);
    EXPECT_DOUBLE_EQ(names[labels.size() + i].frequency, k * 135.5 + (i % 2 ? 25.0 : -25.0));
  }
  EXPECT_EQ(bearing_frequency_names(25, 10, 89.5, 135.5, 59).size(), 35u);  // default 5
  // No inner-race sidebands without a BPFI (nothing to modulate).
  for (const auto& n : bearing_frequency_names(25, 10, 89.5, 0, 59))
    EXPECT_EQ(n.label.find("BPFI"), std::string::npos) << n.label;
}

TEST(SignalPeaks, SkipsZeroFrequenciesAndRejectsBadOnes) {
  const std::vector<NamedFrequency> names = bearing_frequency_names(0, 0, 80, 0, 0, 2);
  ASSERT_EQ(names.size(), 2u);
  EXPECT_EQ(names[0].label, "BPFO");
  EXPECT_EQ(names[1].label, "2xBPFO");
  EXPECT_TRUE(bearing_frequency_names(0, 0, 0, 0, 0).empty());
  EXPECT_THROW(bearing_frequency_names(-1, 10, 80, 120, 50), InputError);
  EXPECT_THROW(bearing_frequency_names(25, kNaN, 80, 120, 50), InputError);
  EXPECT_THROW(bearing_frequency_names(25, 10, kInf, 120, 50), InputError);
  EXPECT_THROW(bearing_frequency_names(25, 10, 80, 120, 50, 0), InputError);
}

TEST(SignalPeaks, LabelsBearingTonesInASimulatedSpectrum) {
  // A 6205-like bearing at 25 Hz (FTF 9.95, BPFO 89.54, BPFI 135.46, BSF 59.01 Hz) with tones at
  // 2×BPFO, BPFI, fr and 3×BSF, mostly between the 0.25 Hz bins. 3×BSF = 177.03 Hz lies within
  // the tolerance of 2×BPFO = 179.08 Hz too, so the nearest must win. The 330 Hz tone is 28 Hz
  // from the nearest name (4×BPFO 358.2 Hz), far beyond its 6.6 Hz tolerance: label "".
  const double fr = 25, ftf = 9.95, bpfo = 89.54, bpfi = 135.46, bsf = 59.01;
  const double fs = 2048, duration = 4;  // resolution 0.25 Hz
  const auto n = static_cast<std::size_t>(fs * duration);
  struct Tone {
    double frequency, amplitude;
    const char* label;
  };
  const Tone tones[] = {{2 * bpfo, 1.0, "2xBPFO"},
                        {bpfi, 0.6, "BPFI"},
                        {fr, 0.35, "fr"},
                        {3 * bsf, 0.2, "3xBSF"},
                        {330.0, 0.1, ""}};
  std::vector<double> x(n, 0.0);
  for (const Tone& t : tones) {
    const std::vector<double> s = sine(n, t.frequency * duration, t.amplitude, 0.7);
    for (std::size_t j = 0; j < n; ++j) x[j] += s[j];
  }
  const Spectrum s = amplitude_spectrum(x, fs, Window::flattop);
  const std::vector<Peak> peaks =
      find_peaks(s, bearing_frequency_names(fr, ftf, bpfo, bpfi, bsf), 5, 1e-3);
  ASSERT_EQ(peaks.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(peaks[i].label, tones[i].label) << i;
    // Flat-top: amplitude within 0.1 % (0.045 % flatness, −90 dB sidelobes from the others);
    // frequency within 0.2 bin (three-point interpolation across the 10-bin-wide flat-top lobe
    // is biased by up to 0.15 bin).
    EXPECT_NEAR(peaks[i].amplitude, tones[i].amplitude, 1e-3 * tones[i].amplitude) << i;
    EXPECT_NEAR(peaks[i].frequency, tones[i].frequency, 0.2 * s.resolution) << i;
  }
}

TEST(SignalPeaks, HannRefinementIsWithinItsBias) {
  // Log-parabolic interpolation of a Hann main lobe is biased by at most 0.016 bin.
  const std::size_t n = 4800;
  for (double offset : {0.0, 0.1, 0.2, 0.3, 0.4, 0.5}) {
    const Spectrum s = amplitude_spectrum(sine(n, 700 + offset, 1.0), 4800.0, Window::hann);
    const std::vector<Peak> p = find_peaks(s, {}, 1);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_NEAR(p[0].frequency, 700 + offset, 0.017) << offset;
  }
}

TEST(SignalPeaks, LabelToleranceIsOneBinInclusiveAndTheErrorIsReported) {
  // Resolution 1 Hz, a line on bin 512: names within one bin (inclusive) label it, farther ones
  // do not; label_error = peak − name.
  const Spectrum s = synthetic(1024, {{512, 1.0}});
  const auto peak = [&s](double named, double bins = 1.0) {
    return find_peaks(s, {{"X", named}}, 10, 1e-3, bins).at(0);
  };
  EXPECT_EQ(peak(513.0).label, "X");
  EXPECT_EQ(peak(511.0).label, "X");
  EXPECT_DOUBLE_EQ(peak(511.0).label_error, 1.0);
  EXPECT_DOUBLE_EQ(peak(512.25).label_error, -0.25);
  EXPECT_EQ(peak(513.0 + 1e-9).label, "");
  EXPECT_EQ(peak(511.0 - 1e-9).label, "");
  EXPECT_EQ(peak(513.0 + 1e-9).label_error, 0.0);
  EXPECT_EQ(peak(514.0, 2.0).label, "X");
  EXPECT_THROW(find_peaks(s, {}, 10, 1e-3, -1.0), InputError);
}

TEST(SignalPeaks, NearestNameWinsAndTiesGoToTheLowerHarmonicThenTheEarlierName) {
  const Spectrum s = synthetic(1024, {{500, 1.0}});
  const auto label = [&s](const std::vector<NamedFrequency>& names) {
    return find_peaks(s, names).at(0).label;
  };
  EXPECT_EQ(label({{"far", 500.8}, {"near", 499.5}}), "near");
  EXPECT_EQ(label({{"A", 499.5}, {"B", 500.5}}), "A");
  EXPECT_EQ(label({{"B", 500.5}, {"A", 499.5}}), "B");
  // The same line named twice (8×FTF = BPFO of a bearing with Z = 8 and no slip): the lower
  // harmonic wins wherever it is listed.
  EXPECT_EQ(label({{"8xFTF", 500.0, 8}, {"BPFO", 500.0 * (1 + 1e-15), 1}}), "BPFO");
  EXPECT_EQ(label({{"BPFO", 500.0, 1}, {"8xFTF", 500.0, 8}}), "BPFO");
  // From bearing_frequency_names: 2×FTF = fr at 10 Hz resolves to "fr".
  const Spectrum low = synthetic(64, {{10, 1.0}});
  EXPECT_EQ(find_peaks(low, bearing_frequency_names(10, 5, 0, 0, 0)).at(0).label, "fr");
  EXPECT_EQ(label({}), "");
}

TEST(SignalPeaks, NamesUpToTheBandCoverEveryHarmonicBelowIt) {
  // One family at a time (together, shaft and outer add the sidebands k·BPFO ± f_r).
  const auto up_to_1000 = [](bool LineFamilies::*family) {
    LineFamilies one;
    one.*family = true;
    return bearing_frequency_names_up_to(1000, 50, 0, 153.6, 0, 0, one);
  };
  const auto fr = up_to_1000(&LineFamilies::shaft), bpfo = up_to_1000(&LineFamilies::outer);
  for (const auto& list : {fr, bpfo})
    for (const auto& n : list) EXPECT_LE(n.frequency, 1000.0) << n.label;
  EXPECT_EQ(fr.size(), 20u);   // 50 … 1000 Hz
  EXPECT_EQ(bpfo.size(), 6u);  // 153.6 … 921.6 Hz
  EXPECT_EQ(fr.back().label, "20xfr");
  EXPECT_EQ(bpfo.back().label, "6xBPFO");
  EXPECT_EQ(bpfo.back().harmonic, 6);
  EXPECT_THROW(bearing_frequency_names_up_to(0, 50, 0, 153.6, 0, 0, LineFamilies::all()),
               InputError);
}

TEST(SignalPeaks, OrdersBySizeBreaksTiesByFrequencyAndThresholds) {
  const Spectrum s =
      synthetic(1000, {{100, 0.01}, {200, 1.0}, {300, 0.5}, {400, 0.5}, {500, 0.0005}, {600, 0.1}});
  std::vector<Peak> p = find_peaks(s, {}, 10, 1e-3);
  ASSERT_EQ(p.size(), 5u);  // 0.0005 is below 1e-3 × 1
  const double order[] = {200, 300, 400, 600, 100};
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_DOUBLE_EQ(p[i].frequency, order[i]) << i;
  EXPECT_EQ(find_peaks(s, {}, 10, 0.0).size(), 6u);
  EXPECT_EQ(find_peaks(s, {}, 10, 0.2).size(), 3u);
  p = find_peaks(s, {}, 2);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_DOUBLE_EQ(p[1].frequency, 300);
  EXPECT_TRUE(find_peaks(s, {}, 0).empty());
}

TEST(SignalPeaks, FlatTopOfTwoBinsIsOnePeakHalfwayBetween) {
  // Bins 0.5, 1, 1, 0.5: one peak (the lower bin), and the parabola's vertex is exactly ½ bin up.
  Spectrum s = synthetic(100, {});
  s.amplitude[39] = 0.5, s.amplitude[40] = 1.0, s.amplitude[41] = 1.0, s.amplitude[42] = 0.5;
  const std::vector<Peak> p = find_peaks(s, {});
  ASSERT_EQ(p.size(), 1u);
  EXPECT_DOUBLE_EQ(p[0].frequency, 40.5);
  EXPECT_DOUBLE_EQ(p[0].amplitude, 1.0);
}

TEST(SignalPeaks, SkipsDcAndKeepsTheLastBin) {
  Spectrum s = synthetic(100, {{50, 0.3}});
  s.amplitude[0] = 10.0;  // a large DC bin is never a peak
  s.amplitude[98] = 0.1;
  s.amplitude[99] = 0.2;  // rising into the last bin: a peak, not refined
  const std::vector<Peak> p = find_peaks(s, {});
  ASSERT_EQ(p.size(), 2u);
  EXPECT_DOUBLE_EQ(p[0].frequency, 50.0);
  EXPECT_DOUBLE_EQ(p[1].frequency, 99.0);
  EXPECT_TRUE(find_peaks(synthetic(100, {}), {}).empty());  // all zero: no maxima
}

TEST(SignalPeaks, RejectsBadArguments) {
  const Spectrum good = synthetic(100, {{50, 1.0}});
  Spectrum mismatched = good;
  mismatched.frequency.pop_back();
  EXPECT_THROW(find_peaks(mismatched, {}), InputError);
  Spectrum no_resolution = good;
  no_resolution.resolution = 0;
  EXPECT_THROW(find_peaks(no_resolution, {}), InputError);
  EXPECT_THROW(find_peaks(good, {}, -1), InputError);
  EXPECT_THROW(find_peaks(good, {}, 10, -0.1), InputError);
  EXPECT_THROW(find_peaks(good, {}, 10, 1.5), InputError);
  EXPECT_THROW(find_peaks(good, {}, 10, kNaN), InputError);
  EXPECT_THROW(find_peaks(good, {}, 10, 1e-3, -0.01), InputError);
}

}  // namespace
}  // namespace bearing

// The inner race turns with the shaft: its lines carry shaft-rate sidebands k·BPFI ± f_r. The
// 6308 at 2000 rpm has BPFI − f_r = 130.94 Hz, 2.4 Hz from 4·f_r = 133.33 Hz: the sideband is the
// nearer name and wins; a tone exactly on 4·f_r stays "4xfr".
TEST(SignalPeaks, LabelsInnerRaceShaftSidebands) {
  const double fr = 2000.0 / 60.0, bpfi = 164.269, ftf = 12.8, bpfo = 102.4, bsf = 67.967;
  const auto names = bearing::bearing_frequency_names(fr, ftf, bpfo, bpfi, bsf);
  const auto label_of = [&](double f) {
    const double rate = 8192.0, n = 8192.0 * 4;  // 0.25 Hz bins
    std::vector<double> x(static_cast<std::size_t>(n));
    for (std::size_t j = 0; j < x.size(); ++j) x[j] = std::sin(bearing::two_pi * f * j / rate);
    const auto s = bearing::amplitude_spectrum(x, rate, bearing::Window::hann);
    return bearing::find_peaks(s, names, 1).at(0).label;
  };
  EXPECT_EQ(label_of(bpfi - fr), "BPFI-fr");
  EXPECT_EQ(label_of(2 * bpfi + fr), "2xBPFI+fr");
  EXPECT_EQ(label_of(4 * fr), "4xfr");
  for (const auto& n : names) EXPECT_GT(n.frequency, 0.0) << n.label;
}

namespace bearing {
namespace {

// Envelope analysis: an amplitude-modulated carrier (1 + m cos ω_m t) cos ω_c t, both on bins,
// band [f_c − 2 f_m, f_c + 2 f_m]: the envelope is 1 + m cos ω_m t exactly, its spectrum a line
// of amplitude m at f_m; a tone outside the band leaves no trace.
TEST(SignalEnvelope, AmplitudeModulatedCarrierGivesItsModulation) {
  const double fs = 20000, n = 20000;  // 1 Hz bins
  const double fc = 3000, fm = 105, m = 0.4;
  std::vector<double> x(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double t = static_cast<double>(i) / fs;
    x[i] = (1 + m * std::cos(two_pi * fm * t)) * std::cos(two_pi * fc * t) +
           0.7 * std::sin(two_pi * 500 * t);  // out of band
  }
  const FrequencyBand band{fc - 2 * fm, fc + 2 * fm};
  const std::vector<double> e = band_envelope(x, fs, band);
  ASSERT_EQ(e.size(), x.size());
  double worst = 0;
  for (std::size_t i = 0; i < e.size(); ++i) {
    const double t = static_cast<double>(i) / fs;
    worst = std::max(worst, std::abs(e[i] - (1 + m * std::cos(two_pi * fm * t))));
  }
  EXPECT_LT(worst, 1e-11);
  const Spectrum s = envelope_spectrum(x, fs, band, Window::hann);
  const std::vector<Peak> p = find_peaks(s, {{"fm", fm}}, 1);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].label, "fm");
  EXPECT_NEAR(p[0].amplitude, m, 1e-9);
}

TEST(SignalEnvelope, RejectsABandOutsideZeroToNyquist) {
  const std::vector<double> x(100, 1.0);
  EXPECT_THROW(band_envelope(x, 1000, {200, 100}), InputError);
  EXPECT_THROW(band_envelope(x, 1000, {-1, 100}), InputError);
  EXPECT_THROW(band_envelope(x, 1000, {100, 600}), InputError);
  EXPECT_THROW(band_envelope({1.0}, 1000, {100, 200}), InputError);
  EXPECT_THROW(band_envelope(x, 0, {100, 200}), InputError);
  EXPECT_NO_THROW(band_envelope(x, 1000, {0, 500}));
}

}  // namespace
}  // namespace bearing
