// Line-to-floor statistics and the harmonic comb: the floor's exceedance probability against its
// closed forms and a simulation of independent exponential bins; the comb threshold against the
// exact single-line case and a simulated two-term case; the comb search finding planted lines at
// their common slip, ignoring excluded zones, and (almost) never firing on a line-free spectrum;
// the fundamental estimate of a harmonic series; bad input refused.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/signal/fundamental_estimate.h"
#include "bearing/signal/harmonic_comb.h"
#include "bearing/signal/line_floor.h"
#include "bearing/signal/spectrum.h"
#include "synthetic_signals.h"

namespace bearing {
namespace {

// A spectrum whose power bins are independent unit exponentials (a line-free background): the
// amplitude is the square root.
Spectrum exponential_spectrum(std::size_t bins, double resolution, std::uint64_t seed) {
  test::SplitMix64 g(seed);
  Spectrum s;
  s.resolution = resolution;
  for (std::size_t k = 0; k < bins; ++k) {
    s.frequency.push_back(k * resolution);
    s.amplitude.push_back(std::sqrt(-std::log(g.uniform())));
  }
  return s;
}

TEST(LineFloor, ExceedanceMatchesItsClosedForms) {
  // n = 1: P(E > R E') = 1/(1 + R) for two independent unit exponentials.
  for (double r : {0.0, 0.5, 3.0, 100.0}) EXPECT_NEAR(floor_exceedance(r, 1), 1 / (1 + r), 1e-12);
  // n = 3 (j = 2): (3/(3 + R)) (2/(2 + R)).
  for (double r : {0.7, 4.0, 50.0})
    EXPECT_NEAR(floor_exceedance(r, 3), 3 / (3 + r) * 2 / (2 + r), 1e-12 * 6 / ((3 + r) * (2 + r)));
  // n → ∞: the median is μ ln 2, so 2^(−R).
  EXPECT_NEAR(floor_exceedance(10, 200000) / std::pow(2.0, -10), 1.0, 1e-3);
  EXPECT_EQ(floor_exceedance(0, 40), 1.0);
  EXPECT_EQ(floor_exceedance(2, 0), 1.0);  // no floor: no information
}

TEST(LineFloor, ExceedanceMatchesASimulationOfExponentialBins) {
  // n = 9 floor samples, j = 5; 200 000 draws: the estimate's standard error is below 1e-3.
  const int n = 9;
  const double r = 3;
  test::SplitMix64 g(5);
  int exceed = 0;
  const int draws = 200000;
  std::vector<double> floor(n);
  for (int d = 0; d < draws; ++d) {
    for (double& v : floor) v = -std::log(g.uniform());
    std::nth_element(floor.begin(), floor.begin() + 4, floor.end());
    exceed += -std::log(g.uniform()) > r * floor[4];
  }
  const double p = floor_exceedance(r, n), estimate = static_cast<double>(exceed) / draws;
  EXPECT_NEAR(estimate, p, 4 * std::sqrt(p * (1 - p) / draws)) << p;
}

TEST(LineFloor, MedianOfEverySecondBinOfBothFlanks) {
  Spectrum s;
  s.resolution = 1;
  for (int k = 0; k < 400; ++k) {
    s.frequency.push_back(k);
    s.amplitude.push_back(2.0);  // power 4
  }
  for (int k = 195; k <= 205; ++k) s.amplitude[k] = 100;  // a line in the window: left out
  s.amplitude[150] = s.amplitude[252] = 50;               // two lines in the flanks: outvoted
  const LineFloor f = floor_around(s, 195, 205, 0, 399);
  EXPECT_EQ(f.power, 4.0);
  // Flanks as wide as the window but at least kFloorFlankBins = 20 bins: [175, 195) and
  // (205, 225], every second bin from the window outwards: 194, 192, …, 176 (10) and 206, …, 224
  // (10).
  EXPECT_EQ(f.samples, 20);
  // Clipped by the limits.
  EXPECT_EQ(floor_around(s, 195, 205, 180, 220).samples, 8 + 8);  // 194…180, 206…220
  EXPECT_THROW(floor_around(s, 205, 195, 0, 399), InputError);
}

// The same layout at 0.1 Hz bins: the flanks are counted in hertz, not in bins, and a window edge
// on a bin centre (197 × 0.1 Hz / 0.1 Hz = 197.00000000000003) is that bin, not the next.
TEST(LineFloor, FlanksScaleWithTheResolution) {
  const double r = 0.1;
  Spectrum s;
  s.resolution = r;
  for (int k = 0; k < 400; ++k) {
    s.frequency.push_back(k * r);
    s.amplitude.push_back(k >= 197 && k <= 207 ? 100.0 : 2.0);
  }
  const LineFloor f = floor_around(s, 197 * r, 207 * r, 0, 399 * r);
  EXPECT_EQ(f.power, 4.0);
  EXPECT_EQ(f.samples, 20);  // 196, 194, …, 178 and 208, …, 226
  EXPECT_EQ(floor_around(s, 197 * r, 207 * r, 182 * r, 222 * r).samples, 8 + 8);
}

TEST(CombThreshold, OneLineIsTheExactQuantile) {
  // One term, one line: trials · P(level ≥ t) = p, solved here by bisection on the closed form;
  // the grid rounds values up, so the threshold lies at most 0.1 dB above.
  for (int n : {50, 120})
    for (double trials : {1.0, 40.0, 300.0}) {
      const double p = 1e-3;
      double lo = 0, hi = 1e6;
      for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (trials * floor_exceedance(mid, n) > p ? lo : hi) = mid;
      }
      const double exact = 10 * std::log10(hi);
      const double t = comb_threshold({{n}}, trials, p);
      EXPECT_GE(t, exact - 1e-9) << n << " " << trials;
      EXPECT_LE(t, exact + 0.1 + 1e-9) << n << " " << trials;
    }
  EXPECT_EQ(comb_threshold({{}, {}}, 5, 1e-3), 0.0);  // nothing rated
}

TEST(CombThreshold, TwoTermsMatchASimulation) {
  // The mean of two terms, the first the larger of two lines (sidebands): simulated directly.
  const std::vector<std::vector<int>> samples = {{60, 60}, {80}};
  const double p = 0.02;
  const double t = comb_threshold(samples, 1, p);
  test::SplitMix64 g(9);
  const auto level = [&g](int n) {  // 10 log10 of an exponential over the median of n others
    std::vector<double> floor(n);
    for (double& v : floor) v = -std::log(g.uniform());
    std::nth_element(floor.begin(), floor.begin() + (n + 1) / 2 - 1, floor.end());
    return 10 * std::log10(-std::log(g.uniform()) / floor[(n + 1) / 2 - 1]);
  };
  const int draws = 40000;
  int above = 0, above_lower = 0;
  for (int d = 0; d < draws; ++d) {
    const double term1 = std::max({0.0, level(60), level(60)});
    const double term2 = std::max(0.0, level(80));
    const double mean = 0.5 * (term1 + term2);
    above += mean >= t;
    above_lower += mean >= t - 0.25;
  }
  const double se = std::sqrt(p * (1 - p) / draws);
  EXPECT_LE(static_cast<double>(above) / draws, p + 3 * se);        // at the threshold: ≤ p
  EXPECT_GT(static_cast<double>(above_lower) / draws, p - 3 * se);  // and not far above it
}

TEST(HarmonicComb, FindsPlantedLinesAtTheirCommonSlip) {
  Spectrum s = exponential_spectrum(6000, 0.1, 3);
  HarmonicComb comb;
  comb.carrier = 107.3;  // nominal [Hz]
  comb.harmonics = 3;
  comb.modulation = 29.95;  // sidebands k·c ± g
  comb.slip = 0.02;
  comb.rated = {0.3, 600};
  const double delta = 0.007;  // the lines sit 0.7 % above the nominal
  for (int k = 1; k <= 3; ++k)
    for (int m : {-1, 0, 1}) {
      const double f = k * comb.carrier * (1 + delta) + m * comb.modulation;
      const auto bin = static_cast<std::size_t>(std::lround(f / s.resolution));
      s.amplitude[bin] = m == 0 ? 10.0 : 4.0;  // 20 dB and 12 dB over a unit floor
    }
  const CombSearch r = search_comb(s, comb, 1e-3);
  EXPECT_TRUE(r.detected);
  EXPECT_EQ(r.rated_harmonics, 3);
  // The fastest line (3c + g) moves half a bin per step: δ within half a bin of 3c.
  EXPECT_NEAR(r.offset, delta, 0.5 * s.resolution / (3 * comb.carrier));
  // Every carrier line found at 20 dB over the median of its unit-exponential flanks (ln 2):
  // 10 log10(100 / ln 2) = 21.6 dB, up to the floor's scatter.
  for (const CombLine& l : r.lines)
    if (l.sideband == 0) EXPECT_NEAR(l.level, 10 * std::log10(100 / std::log(2.0)), 1.5);
  EXPECT_GT(r.evidence, 19);
  EXPECT_GT(r.threshold, 5);
  EXPECT_LT(r.threshold, 15);
}

TEST(HarmonicComb, EachLinesFloorIsTheFloorAroundItsSlipBand) {
  // A line may sit anywhere within ± slip of its nominal frequency: its floor is the one around
  // that whole band (line_floor.h), the same on both sides, whatever the line's rate.
  const Spectrum s = exponential_spectrum(6000, 0.1, 6);
  HarmonicComb comb;
  comb.carrier = 107.3;
  comb.harmonics = 3;
  comb.modulation = 29.95;
  comb.slip = 0.02;
  comb.rated = {0.3, 600};
  const CombSearch r = search_comb(s, comb, 1e-3);
  ASSERT_EQ(r.lines.size(), 9u);
  for (const CombLine& l : r.lines) {
    SCOPED_TRACE("harmonic " + std::to_string(l.harmonic) + ", sideband " +
                 std::to_string(l.sideband));
    ASSERT_TRUE(l.rated);
    const double rate = l.harmonic * comb.carrier;  // the sidebands' spacing does not slip
    const LineFloor f = floor_around(s, l.nominal - comb.slip * rate, l.nominal + comb.slip * rate,
                                     comb.rated.low, comb.rated.high);
    EXPECT_EQ(l.floor_samples, f.samples);
    EXPECT_EQ(l.floor, std::sqrt(f.power));
  }
}

TEST(HarmonicComb, LinesInAnExcludedZoneDoNotCount) {
  Spectrum s = exponential_spectrum(6000, 0.1, 4);
  HarmonicComb comb;
  comb.carrier = 100;
  comb.harmonics = 1;
  comb.slip = 0.02;
  comb.rated = {0.3, 600};
  s.amplitude[1005] = 100;  // 100.5 Hz: a strong line
  EXPECT_TRUE(search_comb(s, comb, 1e-3).detected);
  comb.excluded = {{100.3, 100.7}};  // where another source's line sits
  const CombSearch r = search_comb(s, comb, 1e-3);
  EXPECT_FALSE(r.detected);
  EXPECT_LT(r.evidence, r.threshold);
}

TEST(HarmonicComb, LinesBeyondTheRatedBandAreNotRated) {
  const Spectrum s = exponential_spectrum(6000, 0.1, 5);
  HarmonicComb comb;
  comb.carrier = 100;
  comb.harmonics = 3;
  comb.rated = {0.3, 250};  // 3 × 100 Hz and its flanks lie beyond
  const CombSearch r = search_comb(s, comb, 1e-3);
  EXPECT_EQ(r.rated_harmonics, 2);
  EXPECT_FALSE(r.lines[2].rated);
}

TEST(HarmonicComb, RarelyFiresOnALineFreeBackground) {
  // 300 spectra of independent exponential bins at a false-alarm probability of 0.05: the count
  // is at most binomial(300, 0.05) (the union bound makes it fewer); 27 is its 99.9 % quantile.
  HarmonicComb comb;
  comb.carrier = 162.2;
  comb.modulation = 29.95;
  comb.rated = {0.3, 700};
  int alarms = 0;
  for (std::uint64_t seed = 100; seed < 400; ++seed)
    alarms += search_comb(exponential_spectrum(8000, 0.1, seed), comb, 0.05).detected;
  EXPECT_LE(alarms, 27);
}

TEST(FundamentalEstimate, FindsTheShaftRateOfAHarmonicSeries) {
  // f_r = 29.73 Hz (between bins), nominal 31 Hz (4 % off); three harmonics in white noise.
  const double fs = 12000, fr = 29.73;
  const std::size_t n = 120000;  // 0.1 Hz bins
  test::SplitMix64 g(21);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = i / fs;
    x[i] = 0.4 * std::sin(two_pi * fr * t) + 0.3 * std::sin(two_pi * 2 * fr * t + 1) +
           0.2 * std::sin(two_pi * 3 * fr * t + 2) + g.normal();
  }
  const Spectrum s = amplitude_spectrum(x, fs, Window::hann);
  const FundamentalEstimate e = estimate_fundamental(s, 31, 0.1, 3, 1e-3);
  ASSERT_TRUE(e.found);
  // Each refined line is biased by at most 0.016 bin (Hann, peaks.h) plus the noise's share; the
  // least-squares fit f = Σ k f_k / Σ k² by no more: 0.02 bin.
  EXPECT_NEAR(e.frequency, fr, 0.02 * s.resolution);
  ASSERT_EQ(e.harmonics.size(), 3u);
  for (const HarmonicLine& h : e.harmonics) {
    EXPECT_TRUE(h.used) << h.order;
    EXPECT_NEAR(h.frequency, h.order * fr, 0.05 * s.resolution) << h.order;
  }
  // Noise alone: nothing found.
  std::vector<double> noise(n);
  for (double& v : noise) v = g.normal();
  EXPECT_FALSE(estimate_fundamental(amplitude_spectrum(noise, fs), 31, 0.1, 3, 1e-3).found);
}

TEST(HarmonicComb, RefusesBadSettings) {
  const Spectrum s = exponential_spectrum(1000, 1, 1);
  HarmonicComb comb;
  comb.carrier = 50;
  comb.rated = {0, 500};
  EXPECT_NO_THROW(search_comb(s, comb, 1e-3));
  for (double p : {0.0, 1.0, -1.0}) EXPECT_THROW(search_comb(s, comb, p), InputError);
  HarmonicComb bad = comb;
  bad.carrier = 0;
  EXPECT_THROW(search_comb(s, bad, 1e-3), InputError);
  bad = comb, bad.slip = 0.5;
  EXPECT_THROW(search_comb(s, bad, 1e-3), InputError);
  bad = comb, bad.harmonics = 0;
  EXPECT_THROW(search_comb(s, bad, 1e-3), InputError);
  bad = comb, bad.modulation = -1;
  EXPECT_THROW(search_comb(s, bad, 1e-3), InputError);
  EXPECT_THROW(floor_exceedance(-1, 5), InputError);
  EXPECT_THROW(comb_threshold({{10}}, 0.5, 1e-3), InputError);
}

}  // namespace
}  // namespace bearing
