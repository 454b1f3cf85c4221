// The bands of the cyclic-coherence map and the squared envelope spectrum of each.

#include "bearing/coherence_bands.h"

#include <algorithm>
#include <cmath>

#include "bearing/errors.h"
#include "bearing/signal/fft.h"
#include "bearing/units.h"

namespace bearing {

std::vector<CoherenceBand> coherence_bands(double rate, int levels) {
  if (!(std::isfinite(rate) && rate > 0))
    throw InputError("coherence bands: sample rate = " + format_number(rate) +
                     " Hz: must be positive and finite");
  if (levels < 0 || levels > 6)
    throw InputError("coherence bands: levels = " + std::to_string(levels) +
                     ": allowed 0 … 6 (3: bands down to an eighth of the Nyquist band)");
  const double nyquist = 0.5 * rate;
  std::vector<CoherenceBand> out = {{{0, nyquist}, 0, false}};
  for (int l = 1; l <= levels; ++l) {
    const int count = 1 << l;
    const double width = nyquist / count;
    for (int i = 0; i < count; ++i) out.push_back({{i * width, (i + 1) * width}, l, false});
    if (l >= 2)
      for (int i = 0; i + 1 < count; ++i)
        out.push_back({{(i + 0.5) * width, (i + 1.5) * width}, l, true});
  }
  return out;
}

std::vector<std::complex<double>> whitened_spectrum(const std::vector<double>& x, bool whiten) {
  if (x.size() < 64)
    throw InputError("coherence bands: " + std::to_string(x.size()) +
                     " samples; at least 64 are needed");
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!std::isfinite(x[i]))
      throw InputError("coherence bands: sample " + std::to_string(i) + " = " +
                       format_number(x[i]) + ": every sample must be finite");
  std::vector<double> copy = x;
  RealFft fft(copy.size());
  std::vector<std::complex<double>> X = fft.forward(copy);
  double largest = 0;
  for (const auto& v : X) largest = std::max(largest, std::abs(v));
  X[0] = 0;
  if (!whiten) return X;
  for (std::size_t k = 1; k < X.size(); ++k) {
    const double m = std::abs(X[k]);
    X[k] = m > 1e-13 * largest ? X[k] / m : std::complex<double>(0);
  }
  return X;
}

std::vector<double> band_squared_envelope(const std::vector<std::complex<double>>& X, std::size_t n,
                                          double rate, FrequencyBand band) {
  const double df = rate / static_cast<double>(n);
  if (!(band.low >= 0 && band.high > band.low && band.high <= 0.5 * rate * (1 + 1e-12)))
    throw InputError("coherence bands: band " + format_number(band.low) + " … " +
                     format_number(band.high) + " Hz: must lie within 0 … " +
                     format_number(0.5 * rate) + " Hz");
  const std::size_t lo =
      std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(band.low / df)));
  const std::size_t hi =
      std::min(X.size() - 1, static_cast<std::size_t>(std::floor(band.high / df + 1e-9)));
  if (hi < lo + 3)
    throw InputError("coherence bands: band " + format_number(band.low) + " … " +
                     format_number(band.high) + " Hz spans fewer than 4 bins");
  const std::size_t K = hi - lo + 1;
  // The band's analytic signal at 0 Hz, sampled fast enough that |a|², of bandwidth 2K bins,
  // does not alias: M ≥ 2K + 2 samples over the record's duration.
  const std::size_t M = fast_fft_length(2 * K + 2);
  std::vector<std::complex<double>> a(M, 0.0);
  std::copy(X.begin() + static_cast<std::ptrdiff_t>(lo),
            X.begin() + static_cast<std::ptrdiff_t>(hi + 1), a.begin());
  ComplexFft fft(M);
  fft.inverse(a);
  for (auto& v : a) v = std::norm(v);
  fft.forward(a);
  const double dc = std::abs(a[0]);
  std::vector<double> ses(std::min(K, M / 2));  // |a|² spans lags up to K − 1 bins
  for (std::size_t k = 0; k < ses.size(); ++k) ses[k] = dc > 0 ? std::abs(a[k]) / dc : 0.0;
  return ses;
}

}  // namespace bearing
