#pragma once
// Spectral peaks and the bearing frequency each one is nearest to (MODEL.md §7), so a spectrum
// reads "BPFO 0.31 um, 2xBPFO 0.12 um, …".

#include <string>
#include <vector>

#include "bearing/signal/spectrum.h"

namespace bearing {

/// A frequency with a label such as "BPFO" or "2xBPFI" [Hz].
struct NamedFrequency {
  std::string label;
  double frequency = 0;  ///< [Hz]
};

/// The bearing frequencies and their harmonics 1 … max_harmonic, in this order: "fr", "2xfr", …,
/// "FTF", "2xFTF", …, "BPFO", …, "BPFI", …, "BSF", … (the fundamental has no "1x" prefix), then
/// the inner race's shaft-rate sidebands "BPFI-fr", "BPFI+fr", "2xBPFI-fr", … (k·BPFI ± f_r).
/// Arguments are the plain numbers (shaft rotation, cage, outer- and inner-race ball-pass and
/// ball-spin frequencies [Hz], e.g. from bearing_frequencies()), so this layer does not depend on
/// kinematics. A zero frequency (e.g. a stationary shaft) contributes no names.
/// Throws InputError for a negative or non-finite frequency or max_harmonic < 1.
std::vector<NamedFrequency> bearing_frequency_names(double shaft, double ftf, double bpfo,
                                                    double bpfi, double bsf, int max_harmonic = 5);

/// A spectral peak and the named frequency it was matched to.
struct Peak {
  double frequency = 0;  ///< refined peak frequency [Hz]
  double amplitude = 0;  ///< amplitude of the largest bin [unit of the spectrum]
  std::string label;     ///< nearest named frequency within tolerance, else "" (empty)
};

/// The largest local maxima of `spectrum`, largest first (equal amplitudes: lower frequency first),
/// at most max_peaks of them, each at least relative_threshold × the largest non-DC bin.
///
/// A local maximum is a bin k ≥ 1 (DC is never a peak) strictly above bin k−1 and not below bin
/// k+1 (the last bin has no right neighbour), so a flat top of two equal bins gives one peak, at
/// its lower bin. The frequency is refined by the vertex of the parabola through bins k−1, k, k+1
/// of the log amplitude (plain amplitude if a neighbour is 0): f = (k + δ)·resolution with
/// δ = ½(a₋ − a₊)/(a₋ − 2a₀ + a₊) ∈ [−½, ½]. Worst bias for a single tone: 0.016 bin hann,
/// 0.15 flattop, 0.17 rectangular; the last bin is not refined. The amplitude stays the largest
/// bin's: exact for a tone on a bin with any window, within 0.0039 dB between bins only with
/// Window::flattop (−1.42 dB hann, −3.9 dB rectangular).
///
/// Label: the named frequency nearest to the refined peak frequency f, if it is within
/// max(relative_tolerance × f, 1.5 × resolution) [Hz] (inclusive); names at the same distance go
/// to the earlier one in `names` (for bearing_frequency_names: fr before FTF, BPFO, BPFI, BSF).
/// Throws InputError if the spectrum's frequency and amplitude differ in length or its resolution
/// is not positive, max_peaks < 0, relative_threshold is outside [0, 1] or relative_tolerance < 0.
/// O(M log M) for M bins.
std::vector<Peak> find_peaks(const Spectrum& spectrum, const std::vector<NamedFrequency>& names,
                             int max_peaks = 10, double relative_threshold = 1e-3,
                             double relative_tolerance = 0.02);

}  // namespace bearing
