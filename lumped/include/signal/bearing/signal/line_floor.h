#pragma once
// How far a spectral line stands above the spectrum's floor, and how often a line-free background
// stands that high by chance. For a stationary Gaussian background the power |A_k|² of a bin of a
// (squared envelope or raw) spectrum is exponentially distributed about a floor that varies
// slowly with frequency; the floor is estimated by the median of the bins beside the line, and
// the chance that a bin exceeds R times that median is known exactly (floor_exceedance()). A
// detection threshold then follows from a stated false-alarm rate instead of from the data.

#include "bearing/signal/spectrum.h"

namespace bearing {

/// Fewest bins a floor flank spans (floor_around()): 20 bins, of which every second one is a
/// floor sample, give at least 10 samples per flank. The median of n exponential samples scatters
/// by about 1.44/√n of itself (32 % for n = 20), which floor_exceedance() takes into account:
/// few samples only raise the threshold. Wider flanks would reach 0 Hz below the first lines of a
/// short record (a 1 s record has 1 Hz bins).
inline constexpr int kFloorFlankBins = 20;

/// A floor estimate: the power (amplitude squared) of the background and how many samples it rests
/// on.
struct LineFloor {
  double power = 0;  ///< [unit of the spectrum, squared]; 0 with no samples
  int samples = 0;   ///< n, the floor samples used
};

/// The floor around the search window [low, high] [Hz] of `spectrum`: the lower median (the
/// ⌈n/2⌉-th smallest) of the power of every second bin in the two flanks [low − w, low) and
/// (high, high + w], w = max(high − low, kFloorFlankBins · resolution), kept within
/// [lowest, highest] [Hz]. The window itself is left out, so a line inside it does not raise its
/// own floor; a few other lines in the flanks move the median little. Every second bin: adjacent
/// bins of a Hann-windowed spectrum are correlated (power correlation 0.44), bins two apart hardly
/// (0.028), so the samples are close to independent, as floor_exceedance() assumes. For a floor
/// that varies linearly across the flanks the median of the two flanks is its value at the
/// window's centre. No sample: {0, 0}.
/// Throws InputError if the spectrum's frequencies and amplitudes differ in length, its
/// resolution is not positive, or low > high.
LineFloor floor_around(const Spectrum& spectrum, double low, double high, double lowest,
                       double highest);

/// The probability that a bin whose power P is exponential with mean μ exceeds `ratio` times a
/// floor that is the j-th smallest (j = ⌈n/2⌉) of n independent samples of the same law:
///
///   P(P > R · P_(j)) = Π_{i=1}^{j} (n − i + 1) / (n − i + 1 + R)   (n ≥ 1, R ≥ 0),
///
/// exact: by Rényi's representation P_(j) = μ Σ_{i=1}^{j} Z_i / (n − i + 1) with Z_i independent
/// unit exponentials, and E[e^{−R Z/m}] = m / (m + R). It tends to 2^(−R) as n → ∞ (the median
/// of an exponential is μ ln 2); for finite n it is larger: the floor's own scatter. n = 0: 1.
/// Throws InputError for a negative or NaN ratio or a negative n.
double floor_exceedance(double ratio, int samples);

}  // namespace bearing
