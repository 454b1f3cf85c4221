#pragma once
// The squared envelope spectrum (SES): the spectrum of the squared Hilbert envelope of a band of
// a record. Its lines are the rates at which the band's energy comes and goes — a local fault's
// impact rate and its modulations — and for a stationary Gaussian background its bins are
// exponentially distributed in power around a smooth floor, which makes a line's height over that
// floor a statistic with a known false-alarm rate (line_floor.h). The squared envelope rather
// than the envelope: its spectrum is the band's cyclic spectrum summed over the band (J. Antoni,
// "Cyclic spectral analysis of rolling-element bearing signals: facts and fictions", J. Sound Vib.
// 304, 2007), free of the square root's harmonics.

#include <vector>

#include "bearing/signal/envelope.h"
#include "bearing/signal/spectrum.h"

namespace bearing {

/// The squared envelope e²(t) = |x_b + i H(x_b)|² of x band-passed to `band` (band_envelope()
/// squared), sampled like x [unit of x, squared].
std::vector<double> squared_envelope(const std::vector<double>& x, double sample_rate,
                                     FrequencyBand band);

/// The amplitude spectrum (amplitude_spectrum(): mean removed, `window`, scaled so that a
/// sinusoid of amplitude A shows A) of squared_envelope(x, band) [unit of x, squared].
///
/// Closed form (the test): x = (1 + m cos 2πf_m t) cos 2πf_c t with the band holding f_c ± f_m has
/// the envelope 1 + m cos 2πf_m t, so e² = 1 + m²/2 + 2m cos 2πf_m t + (m²/2) cos 4πf_m t: lines
/// of amplitude 2m at f_m and m²/2 at 2 f_m (exactly, to rounding, when both lie on bins).
/// Throws InputError as band_envelope().
Spectrum squared_envelope_spectrum(const std::vector<double>& x, double sample_rate,
                                   FrequencyBand band, Window window = Window::hann);

}  // namespace bearing
