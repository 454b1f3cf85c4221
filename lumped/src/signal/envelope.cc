#include "bearing/signal/envelope.h"

#include <cmath>
#include <complex>
#include <string>

#include "bearing/errors.h"
#include "bearing/signal/fft.h"
#include "bearing/units.h"

namespace bearing {

namespace {

void check_input(const std::vector<double>& x, double rate, FrequencyBand band) {
  if (x.size() < 2)
    throw InputError("envelope: " + std::to_string(x.size()) + " samples; at least 2 needed");
  if (!(std::isfinite(rate) && rate > 0))
    throw InputError("envelope: sample rate = " + format_number(rate) +
                     " Hz: must be positive and finite");
  for (double v : x)
    if (!std::isfinite(v)) throw InputError("envelope: a sample is NaN or infinite");
  const double nyquist = 0.5 * rate;
  if (!(band.low >= 0 && band.low < band.high && band.high <= nyquist))
    throw InputError("envelope band = [" + format_number(band.low) + " Hz, " +
                     format_number(band.high) + " Hz]: allowed 0 <= low < high <= " +
                     format_number(nyquist) + " Hz (the Nyquist frequency)");
}

}  // namespace

std::vector<double> band_envelope(const std::vector<double>& x, double sample_rate,
                                  FrequencyBand band) {
  check_input(x, sample_rate, band);
  const std::size_t n = x.size();
  RealFft fft(n);
  std::vector<double> scratch = x;
  std::vector<std::complex<double>> spectrum = fft.forward(scratch);
  const double resolution = sample_rate / static_cast<double>(n);
  std::vector<std::complex<double>> hilbert(spectrum.size());
  for (std::size_t k = 0; k < spectrum.size(); ++k) {
    const double f = static_cast<double>(k) * resolution;
    // A relative slack of 1e-9 bin keeps band edges given on a bin inside the band.
    const bool inside = f >= band.low - 1e-9 * resolution && f <= band.high + 1e-9 * resolution;
    if (!inside) spectrum[k] = 0;
    // H: −i on positive frequencies; DC and Nyquist have no quadrature part.
    const bool edge = k == 0 || (n % 2 == 0 && k == n / 2);
    hilbert[k] = edge ? 0.0 : std::complex<double>(0, -1) * spectrum[k];
  }
  const std::vector<double> in_band = fft.inverse(spectrum);
  const std::vector<double> quadrature = fft.inverse(hilbert);
  std::vector<double> envelope(n);
  for (std::size_t i = 0; i < n; ++i) envelope[i] = std::hypot(in_band[i], quadrature[i]);
  return envelope;
}

Spectrum envelope_spectrum(const std::vector<double>& x, double sample_rate, FrequencyBand band,
                           Window window) {
  return amplitude_spectrum(band_envelope(x, sample_rate, band), sample_rate, window);
}

}  // namespace bearing
