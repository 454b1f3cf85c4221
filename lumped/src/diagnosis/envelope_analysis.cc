// The envelope analysis of a channel: band, spectral kurtosis, envelope spectrum, named peaks.

#include "bearing/envelope_analysis.h"

#include <algorithm>
#include <cstdio>

#include "bearing/errors.h"

namespace bearing {

std::string band_text(const FrequencyBand& band) {
  const bool khz = band.high >= 1000;
  const double unit = khz ? 1e3 : 1.0;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g–%.3g %s", band.low / unit, band.high / unit,
                khz ? "kHz" : "Hz");
  return buf;
}

std::optional<double> band_energy_fraction(const EnvelopeSummary& e) {
  std::optional<double> fraction;
  for (const KurtogramBand& b : e.kurtogram)
    if (b.band.low == e.band.low && b.band.high == e.band.high) fraction = b.energy_fraction;
  return fraction;
}

double envelope_min_bandwidth(const BearingFrequencies& f) {
  return 3 * std::max({f.bpfo, f.bpfi, 2 * f.bsf});
}

EnvelopeSummary analyse_envelope(const std::string& channel, const std::string& unit,
                                 const std::vector<double>& x, double sample_rate,
                                 const BearingFrequencies& f, const EnvelopeBandSetting& setting,
                                 Window window, int max_peaks, double min_bandwidth,
                                 std::vector<double>* envelope) {
  if (setting.source == EnvelopeBandSource::none)
    throw InputError("envelope analysis of " + channel + ": no band asked for (source none)");
  EnvelopeSummary e;
  e.channel = channel;
  e.unit = unit;
  e.source = setting.source;
  if (setting.source == EnvelopeBandSource::automatic) {
    const double narrowest = min_bandwidth > 0 ? min_bandwidth : envelope_min_bandwidth(f);
    Kurtogram k = fast_kurtogram(x, sample_rate, {narrowest, kEnvelopeNoiseFloor});
    e.band = k.best.band;
    e.spectral_kurtosis = k.best.spectral_kurtosis;
    e.kurtogram = std::move(k.map);
  } else {
    e.band = setting.band;
    e.spectral_kurtosis = spectral_kurtosis(x, sample_rate, e.band, kEnvelopeNoiseFloor);
  }
  std::vector<double> band = band_envelope(x, sample_rate, e.band);
  e.spectrum = amplitude_spectrum(band, sample_rate, window);  // envelope_spectrum()
  if (envelope) *envelope = std::move(band);
  const auto names =
      fault_frequency_names_up_to(0.5 * sample_rate, f.shaft, f.ftf, f.bpfo, f.bpfi, f.bsf);
  e.peaks = find_peaks(e.spectrum, names, max_peaks);
  return e;
}

}  // namespace bearing
