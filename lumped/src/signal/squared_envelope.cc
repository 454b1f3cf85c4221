// The squared envelope of a band and its spectrum.

#include "bearing/signal/squared_envelope.h"

namespace bearing {

std::vector<double> squared_envelope(const std::vector<double>& x, double sample_rate,
                                     FrequencyBand band) {
  std::vector<double> e = band_envelope(x, sample_rate, band);
  for (double& v : e) v *= v;
  return e;
}

Spectrum squared_envelope_spectrum(const std::vector<double>& x, double sample_rate,
                                   FrequencyBand band, Window window) {
  return amplitude_spectrum(squared_envelope(x, sample_rate, band), sample_rate, window);
}

}  // namespace bearing
