// Cepstral pre-whitening against its closed forms: a sum of sinusoids plus an impulse comes out
// with a flat magnitude spectrum and its phases; an impulse comes out as itself (mean removed); a
// tone on a bin as itself; the energy about the mean is kept; bad input is refused.

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/signal/fft.h"
#include "bearing/signal/prewhitening.h"
#include "synthetic_signals.h"

namespace bearing {
namespace {

std::vector<std::complex<double>> dft(std::vector<double> x) {
  RealFft fft(x.size());
  return fft.forward(x);
}

double energy_about_mean(const std::vector<double>& x) {
  double mean = 0, e = 0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(x.size());
  for (double v : x) e += (v - mean) * (v - mean);
  return e;
}

// Three tones (one on a bin, two between bins) and an impulse: every bin of the DFT is non-zero.
std::vector<double> tones_and_impulse(std::size_t n) {
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(n);
    x[i] = 3 * std::sin(two_pi * 40 * t + 0.3) + 0.5 * std::cos(two_pi * 117.4 * t) +
           2e3 * std::sin(two_pi * 301.25 * t + 1.1) + 0.7;
  }
  x[n / 3] += 25;
  return x;
}

TEST(Prewhitening, SinusoidsPlusImpulseHaveAFlatMagnitudeAndTheirPhase) {
  // Even, odd (mixed radix) and prime (Bluestein) lengths.
  for (std::size_t n : {4096u, 3003u, 4099u}) {
    const std::vector<double> x = tones_and_impulse(n);
    const std::vector<double> y = cepstral_prewhiten(x);
    const auto X = dft(x), Y = dft(y);
    // a² (N − 1) = Σ_{k≠0} |X_k|² over all N bins: Parseval's N · energy about the mean.
    const double a = std::sqrt(static_cast<double>(n) * energy_about_mean(x) / (n - 1.0));
    EXPECT_LT(std::abs(Y[0]), 1e-9 * a) << n;
    for (std::size_t k = 1; k < Y.size(); ++k) {
      ASSERT_NEAR(std::abs(Y[k]) / a, 1.0, 1e-9) << "n " << n << " bin " << k;
      // The phase kept: Y_k / X_k real and positive.
      const std::complex<double> ratio = Y[k] / X[k];
      ASSERT_NEAR(std::arg(ratio), 0.0, 1e-9) << "n " << n << " bin " << k;
    }
  }
}

TEST(Prewhitening, AnImpulseGivesItselfWithoutItsMean) {
  for (std::size_t n : {1000u, 1001u, 997u}) {
    std::vector<double> x(n, 0.0);
    const std::size_t at = n / 4;
    const double amplitude = -3.5;
    x[at] = amplitude;
    const std::vector<double> y = cepstral_prewhiten(x);
    for (std::size_t i = 0; i < n; ++i) {
      const double expected = amplitude * ((i == at ? 1.0 : 0.0) - 1.0 / static_cast<double>(n));
      ASSERT_NEAR(y[i], expected, 1e-12 * std::abs(amplitude)) << "n " << n << " sample " << i;
    }
  }
}

TEST(Prewhitening, AToneOnABinStaysTheTone) {
  // One pair of bins holds everything, the others rounding only (Y_k = 0 there): y = x − mean.
  const std::size_t n = 2000;
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = 4 + 2.5 * std::cos(two_pi * 37.0 * i / n + 0.8);
  const std::vector<double> y = cepstral_prewhiten(x);
  for (std::size_t i = 0; i < n; ++i) ASSERT_NEAR(y[i], x[i] - 4, 1e-11) << i;
}

TEST(Prewhitening, KeepsTheEnergyAboutTheMean) {
  test::SplitMix64 g(11);
  for (std::size_t n : {512u, 777u, 1009u}) {
    std::vector<double> x(n);
    double previous = 0;
    for (double& v : x) v = previous = 0.9 * previous + g.normal() + 5;  // coloured, offset
    const std::vector<double> y = cepstral_prewhiten(x);
    EXPECT_NEAR(energy_about_mean(y) / energy_about_mean(x), 1.0, 1e-12) << n;
    double mean = 0;
    for (double v : y) mean += v;
    EXPECT_NEAR(mean / static_cast<double>(n), 0.0, 1e-12 * std::sqrt(energy_about_mean(x))) << n;
  }
  // A constant record has nothing but its mean: zeros.
  for (double v : cepstral_prewhiten(std::vector<double>(64, 3.0))) EXPECT_EQ(v, 0.0);
}

TEST(Prewhitening, RefusesBadInput) {
  EXPECT_THROW(cepstral_prewhiten({1.0}), InputError);
  std::vector<double> x(100, 1.0);
  x[42] = std::nan("");
  try {
    cepstral_prewhiten(x);
    FAIL() << "NaN accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sample 42"), std::string::npos) << e.what();
  }
  x[42] = INFINITY;
  EXPECT_THROW(cepstral_prewhiten(x), InputError);
}

}  // namespace
}  // namespace bearing
