// Cepstral pre-whitening: unit magnitude, phase kept, energy of the record.

#include "bearing/signal/prewhitening.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>

#include "bearing/errors.h"
#include "bearing/signal/fft.h"
#include "bearing/units.h"

namespace bearing {

namespace {

// Relative to the largest magnitude, a bin at or below this holds rounding only (the DFT of
// double data is exact to ~1e-16 of its largest bin, times a few log N).
constexpr double kRoundingBin = 1e-13;

}  // namespace

std::vector<double> cepstral_prewhiten(const std::vector<double>& x) {
  if (x.size() < 2)
    throw InputError("pre-whitening: " + std::to_string(x.size()) +
                     " samples given; at least 2 are needed");
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!std::isfinite(x[i]))
      throw InputError("pre-whitening: sample " + std::to_string(i) + " = " + format_number(x[i]) +
                       ": must be finite");
  const std::size_t n = x.size();
  RealFft fft(n);
  std::vector<double> scratch = x;
  std::vector<std::complex<double>> X = fft.forward(scratch);
  X[0] = 0;
  double largest = 0;
  for (const auto& v : X) largest = std::max(largest, std::abs(v));
  if (!(largest > 0)) return std::vector<double>(n, 0.0);
  // Bins 1 … ⌊N/2⌋ stand for the N − 1 bins but DC: the ones below N/2 twice (their mirror).
  double energy = 0, kept = 0;
  for (std::size_t k = 1; k < X.size(); ++k) {
    const double weight = (n % 2 == 0 && k == n / 2) ? 1 : 2;
    const double magnitude = std::abs(X[k]);
    energy += weight * magnitude * magnitude;
    if (magnitude > kRoundingBin * largest)
      kept += weight;
    else
      X[k] = 0;
  }
  const double a = std::sqrt(energy / kept);
  for (std::size_t k = 1; k < X.size(); ++k)
    if (X[k] != 0.0) X[k] *= a / std::abs(X[k]);
  return fft.inverse(X);
}

}  // namespace bearing
