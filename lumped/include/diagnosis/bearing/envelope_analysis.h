#pragma once
// The envelope analysis of one vibration channel (issue 17): the band (given, or the fast
// kurtogram's), the spectral kurtosis there, the envelope spectrum and its peaks named after the
// bearing's fault frequencies. A run's analysis applies it to each ring acceleration
// (analyse_envelopes(), pipeline's analysis.h), a record's to the record (record_analysis.h).

#include <optional>
#include <string>
#include <vector>

#include "bearing/kinematics.h"
#include "bearing/signal/envelope.h"
#include "bearing/signal/kurtogram.h"
#include "bearing/signal/peaks.h"
#include "bearing/signal/spectrum.h"

namespace bearing {

/// The envelope analysis of one channel.
struct EnvelopeSummary {
  std::string channel;  ///< "ax", "ay", …
  std::string unit;     ///< the channel's SI unit ("m/s^2"): that of the envelope and its peaks
  FrequencyBand band;   ///< the band demodulated [Hz]
  EnvelopeBandSource source = EnvelopeBandSource::given;  ///< given, or automatic (kurtogram)
  double spectral_kurtosis = 0;  ///< SK of the channel in `band` (spectral_kurtosis()) [-]
  /// automatic: the kurtogram's every band, coarse to fine (empty for a given band)
  std::vector<KurtogramBand> kurtogram;
  Spectrum spectrum;        ///< amplitude spectrum of the envelope [unit]
  std::vector<Peak> peaks;  ///< its largest peaks, largest first, fault_frequency_names_up_to()
};

/// The share of the record's energy in the envelope's band, from its kurtogram (a band the
/// kurtogram chose; none for a given band) [-]: summary.json `envelope.<ch>.energy_fraction`.
std::optional<double> band_energy_fraction(const EnvelopeSummary& envelope);

/// "1.67–2.5 kHz" (≥ 1 kHz at the top) or "625–833 Hz": a band for the readable summary.
std::string band_text(const FrequencyBand& band);

/// The noise floor the analysis rates spectral kurtosis against (spectral_kurtosis()): ν = 1e-2,
/// a white background 20 dB below the record's vibration, as any measurement has one. A noise-free
/// simulation otherwise shows its faintest bands' own impulsiveness: the healthy default 6308's
/// accelerations have SK 25 in 5–10 kHz, a band holding 1e-5 of their energy (the ringing of each
/// ball's contact onset); over the floor that band's SK is below 0.001, and the kurtogram picks the
/// 1.7–2.5 kHz band (0.5 % of the energy, SK 2.3). [-]
inline constexpr double kEnvelopeNoiseFloor = 1e-2;

/// The narrowest band the kurtogram may pick for a bearing [Hz]: three times its fastest impact
/// rate max(BPFO, BPFI, 2·BSF), so that the band's envelope (whose spectrum reaches the band
/// width) holds the fault line, its second harmonic and their shaft or cage sidebands.
double envelope_min_bandwidth(const BearingFrequencies& frequencies);

/// The envelope analysis of x (sampled at `sample_rate` [Hz]; `channel` and `unit` only name it):
/// the band (setting.band, or fast_kurtogram(x, rate, min_bandwidth).best with min_bandwidth > 0,
/// else envelope_min_bandwidth(f) [Hz]: a run's choice), its
/// spectral kurtosis, envelope_spectrum(x, rate, band, window) and its `max_peaks` largest peaks
/// labelled with fault_frequency_names_up_to(rate/2, …) (f with cage slip, as the run turns).
/// With `envelope`, the band's Hilbert envelope (band_envelope()) is left there.
/// Throws InputError for setting.source = none, and as the functions it calls (a band outside
/// 0 … rate/2, a non-finite sample, fewer than 2 samples).
EnvelopeSummary analyse_envelope(const std::string& channel, const std::string& unit,
                                 const std::vector<double>& x, double sample_rate,
                                 const BearingFrequencies& frequencies,
                                 const EnvelopeBandSetting& setting, Window window, int max_peaks,
                                 double min_bandwidth = 0, std::vector<double>* envelope = nullptr);

}  // namespace bearing
