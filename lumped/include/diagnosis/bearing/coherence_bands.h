#pragma once
// The cyclic content of a record band by band (issue 41): the squared envelope spectra (SES) of
// the pre-whitened record in a fixed set of bands — the whole band, its halves, quarters and
// eighths, and from the quarters on the same bands shifted by half a width — over which each fault
// family is looked for in the band where its lines stand out most.
//
// Why this is the cyclic spectral coherence. The SES of a record filtered to a band [f1, f2] is,
// at a cyclic frequency α well below the band's width, the integral over f ∈ [f1, f2] of the
// cyclic spectral correlation S_x(f, α); divided by the band's mean power it is the integral of
// the cyclic spectral coherence γ_x(f, α) = S_x(f, α) / √(S_x(f) S_x(f − α)) wherever the PSD
// S_x is flat — and pre-whitening makes it flat. So the band SES of the whitened record, its DC
// set to one, is the band-integrated spectral coherence: the improved envelope spectrum of
// Mauricio et al. ("Improved envelope spectrum via feature optimisation-gram (IESFOgram)", MSSP
// 144, 2020) up to taking magnitudes before integrating; and the map of a family's evidence over
// the bands is their IESFOgram (band selection by the fault lines, not by the kurtosis), computed
// at the cost of one FFT of the record and two short ones a band (J. Antoni, G. Xin, N. Hamzaoui,
// "Fast computation of the spectral correlation", MSSP 92, 2017, use the same short-time
// shortcut). Why these bands: the kurtogram's dyadic tree (Antoni, MSSP 21, 2007) with its
// 1/2-shifted bands, so that a resonance straddling a dyadic edge lies inside one band; no
// narrower than an eighth of the Nyquist band, so that the SES of a band holds three harmonics
// of the fastest fault rate of a bearing turning at up to the rate / 100 (750 Hz at 12 kHz).

#include <complex>
#include <cstddef>
#include <vector>

#include "bearing/signal/envelope.h"

namespace bearing {

/// One band of the map.
struct CoherenceBand {
  FrequencyBand band;    ///< [Hz]
  int level = 0;         ///< 0 the whole band, l: a width of rate / 2^(l+1)
  bool shifted = false;  ///< moved up by half its width from the dyadic grid
};

/// The bands for a record sampled at `rate` [Hz]: level 0 (0 … rate/2), levels 1 … `levels`
/// (2^l bands each) and, for l ≥ 2, the 2^l − 1 bands shifted by half a width; 25 bands for
/// levels = 3. Throws InputError for a rate that is not positive and finite or levels outside
/// [0, 6].
std::vector<CoherenceBand> coherence_bands(double rate, int levels);

/// The spectrum of a record pre-whitened (prewhitening.h: every bin's magnitude set to one, its
/// phase kept; bins of rounding only, |X_k| ≤ 1e-13 max|X|, and DC set to zero), bins
/// k = 0 … ⌊N/2⌋ of a record of N samples; with `whiten` false the record's own spectrum, DC set
/// to zero (a simulated response, whose exactly periodic impacts whitening would flatten: the
/// band SES is then the band's squared envelope spectrum, not its coherence). Throws InputError
/// for N < 64 or a non-finite sample.
std::vector<std::complex<double>> whitened_spectrum(const std::vector<double>& x,
                                                    bool whiten = true);

/// The squared envelope spectrum of the whitened record (its spectrum `whitened`, N samples at
/// `rate` [Hz]) in `band`: the analytic signal of the band's bins, shifted to 0 Hz, |a(t)|², its
/// DFT magnitude divided by its DC (so bin 0 is 1: the band-integrated spectral coherence). Bin
/// k lies at k · rate / N, as the record's spectrum; bins up to the band's width (then the SES's
/// floor falls to zero). Throws InputError for a band outside 0 … rate/2 or narrower than 4 bins.
std::vector<double> band_squared_envelope(const std::vector<std::complex<double>>& whitened,
                                          std::size_t samples, double rate, FrequencyBand band);

}  // namespace bearing
