// The squared envelope spectrum against its closed form: an amplitude-modulated carrier
// (1 + m cos 2πf_m t) cos 2πf_c t has the squared envelope 1 + m²/2 + 2m cos 2πf_m t +
// (m²/2) cos 4πf_m t, so its SES holds lines of 2m at f_m and m²/2 at 2f_m and nothing else.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/signal/squared_envelope.h"

namespace bearing {
namespace {

constexpr double kFs = 20000;      // [Hz]
constexpr std::size_t kN = 20000;  // 1 Hz bins

std::vector<double> modulated(double m, double fm, double fc) {
  std::vector<double> x(kN);
  for (std::size_t i = 0; i < kN; ++i) {
    const double t = static_cast<double>(i) / kFs;
    x[i] = (1 + m * std::cos(two_pi * fm * t)) * std::cos(two_pi * fc * t);
  }
  return x;
}

TEST(SquaredEnvelope, AmplitudeModulatedCarrierIsOneSquaredPlusTheModulation) {
  const double m = 0.6, fm = 50, fc = 3000;
  const std::vector<double> e2 = squared_envelope(modulated(m, fm, fc), kFs, {2800, 3200});
  for (std::size_t i = 0; i < kN; i += 37) {
    const double a = 1 + m * std::cos(two_pi * fm * static_cast<double>(i) / kFs);
    ASSERT_NEAR(e2[i], a * a, 1e-12) << i;
  }
}

TEST(SquaredEnvelope, SpectrumHasLinesOf2mAtFmAndHalfMSquaredAt2Fm) {
  const double fm = 50, fc = 3000;
  for (double m : {0.1, 0.6, 1.0})
    for (Window w : {Window::hann, Window::flattop, Window::rectangular}) {
      const Spectrum s = squared_envelope_spectrum(modulated(m, fm, fc), kFs, {2900, 3100}, w);
      EXPECT_NEAR(s.amplitude[50], 2 * m, 1e-12) << m;
      EXPECT_NEAR(s.amplitude[100], m * m / 2, 1e-12) << m;
      // Elsewhere only the window's main lobes around the two lines (±4 bins flat-top).
      for (std::size_t k = 1; k < s.amplitude.size(); ++k) {
        const bool lobe = std::abs(static_cast<double>(k) - 50) <= 4 ||
                          std::abs(static_cast<double>(k) - 100) <= 4;
        if (!lobe) ASSERT_LT(s.amplitude[k], 1e-12) << "m " << m << " bin " << k;
      }
    }
}

TEST(SquaredEnvelope, UnitIsTheSquareOfTheRecords) {
  // Scaling the record by c scales the SES by c².
  const std::vector<double> x = modulated(0.5, 40, 2000);
  std::vector<double> y = x;
  for (double& v : y) v *= 7;
  const Spectrum a = squared_envelope_spectrum(x, kFs, {1900, 2100});
  const Spectrum b = squared_envelope_spectrum(y, kFs, {1900, 2100});
  EXPECT_NEAR(b.amplitude[40] / a.amplitude[40], 49.0, 1e-9);
}

TEST(SquaredEnvelope, RefusesABandOutsideTheSpectrum) {
  EXPECT_THROW(squared_envelope_spectrum(modulated(0.5, 40, 2000), kFs, {2000, 11000}), InputError);
  EXPECT_THROW(squared_envelope_spectrum({1.0}, kFs, {0, 100}), InputError);
}

}  // namespace
}  // namespace bearing
