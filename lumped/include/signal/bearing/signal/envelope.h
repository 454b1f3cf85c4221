#pragma once
// The envelope of a band of a signal (envelope analysis, the diagnostic tool for local bearing
// faults): band-pass in the frequency domain, Hilbert envelope, and the spectrum of the envelope.
// An impact train excites the structure's resonances; the envelope of a band around them carries
// the impact rate (BPFO, BPFI, 2×BSF) that the raw spectrum buries among the resonance's lines.

#include <vector>

#include "bearing/choice.h"
#include "bearing/signal/spectrum.h"

namespace bearing {

/// A frequency band [low, high] [Hz].
struct FrequencyBand {
  double low = 0;   ///< [Hz], ≥ 0
  double high = 0;  ///< [Hz], > low and ≤ the Nyquist frequency
};

/// Where the band of an envelope analysis comes from (the case key output.envelope_band).
enum class EnvelopeBandSource {
  none,       ///< no envelope analysis
  given,      ///< a band the user gave
  automatic,  ///< the band of largest spectral kurtosis (fast_kurtogram(), kurtogram.h)
};

/// As the case file and summary.json write them: "none", "given" (summary.json only: a case file
/// gives the band itself), "auto".
inline constexpr Named<EnvelopeBandSource> kEnvelopeBandSources[] = {
    {EnvelopeBandSource::none, "none"},
    {EnvelopeBandSource::given, "given"},
    {EnvelopeBandSource::automatic, "auto"}};

/// The envelope analysis asked for: none, a given band, or the kurtogram's.
struct EnvelopeBandSetting {
  EnvelopeBandSource source = EnvelopeBandSource::none;
  FrequencyBand band;  ///< [Hz], when source is given
};

/// The Hilbert envelope |x_b + i H(x_b)| of x band-passed to `band`, sampled like x [unit of x].
///
/// x_b keeps the DFT bins k·fs/N inside the band (inclusive) and zeroes the others — an ideal,
/// zero-phase band-pass of the periodic extension of x; its Hilbert transform H multiplies bin k
/// by −i (the e^{iωt} convention of fft.h). For x = (1 + m cos ω_m t) cos ω_c t with both
/// frequencies on bins and the band holding ω_c ± ω_m, the envelope is 1 + m cos ω_m t exactly
/// (m ≤ 1), to rounding. O(N log N).
/// Throws InputError if N < 2, a sample is not finite, sample_rate is not positive and finite, or
/// the band is not 0 ≤ low < high ≤ fs/2 (each message names the value and the allowed range).
std::vector<double> band_envelope(const std::vector<double>& x, double sample_rate,
                                  FrequencyBand band);

/// The amplitude spectrum (amplitude_spectrum(), mean removed) of band_envelope(x, band).
Spectrum envelope_spectrum(const std::vector<double>& x, double sample_rate, FrequencyBand band,
                           Window window = Window::hann);

}  // namespace bearing
