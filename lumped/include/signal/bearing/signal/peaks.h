#pragma once
// Spectral peaks and the bearing frequency each one is nearest to (docs/model.md §7), so a spectrum
// reads "BPFO 0.31 um, 2xBPFO 0.12 um, …". The names: line_names.h.

#include <string>
#include <vector>

#include "bearing/signal/line_names.h"
#include "bearing/signal/spectrum.h"

namespace bearing {

/// A spectral peak and the named frequency it was matched to.
struct Peak {
  double frequency = 0;    ///< refined peak frequency [Hz]
  double amplitude = 0;    ///< amplitude of the largest bin [unit of the spectrum]
  std::string label;       ///< nearest named frequency within tolerance, else "" (empty)
  double label_error = 0;  ///< frequency − the named frequency [Hz] (0 when unlabelled)
};

/// Offset δ ∈ [−½, ½] [bins] of the vertex of the parabola through (−1, a), (0, b), (1, c) for a
/// local maximum b (b > a, b ≥ c): through the logarithms when all three are positive, else
/// through the amplitudes; 0 where the three are not curved downwards. A peak at bin k lies at
/// (k + δ)·resolution.
double peak_vertex_offset(double a, double b, double c);

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
/// tolerance_bins × resolution [Hz] (inclusive; default one bin: the refined frequency of a line
/// is within 0.2 bin of it for every window, so a line's own name is always nearer than that),
/// else none — a peak near no name stays unlabelled rather than taking a distant one. Names at
/// the same distance (to 1e-9 bin: 8×FTF and BPFO of the same bearing) go to the lower order
/// harmonic/subharmonic (BPFO before 8xFTF, 1/2xBPFO before 4xFTF), then to the earlier one in
/// `names` (for bearing_frequency_names: fr before FTF, BPFO, BPFI, BSF). label_error = f − the
/// name's frequency.
/// Throws InputError if the spectrum's frequency and amplitude differ in length or its resolution
/// is not positive, max_peaks < 0, relative_threshold is outside [0, 1] or tolerance_bins < 0.
/// O(M log M + P·N) for M bins, P peaks and N names.
std::vector<Peak> find_peaks(const Spectrum& spectrum, const std::vector<NamedFrequency>& names,
                             int max_peaks = 10, double relative_threshold = 1e-3,
                             double tolerance_bins = 1.0);

}  // namespace bearing
