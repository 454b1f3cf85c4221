#pragma once
// Spectral kurtosis of frequency bands and the fast kurtogram: the band where a signal is most
// impulsive, i.e. where the impacts of a local fault ring the structure, chosen for envelope
// analysis. After J. Antoni, "Fast computation of the kurtogram for the detection of transient
// faults", Mech. Syst. Signal Process. 21 (2007) 108–124, computed here in the frequency domain:
// one FFT of the record, then per band an inverse FFT of only that band's bins.

#include <vector>

#include "bearing/signal/envelope.h"

namespace bearing {

/// The spectral kurtosis of x (sampled at `sample_rate` [Hz], unit irrelevant) in `band` [Hz]:
///
///   SK = ⟨|c|⁴⟩ / ⟨|c|²⟩² − 2  [-],
///
/// c(t) the band's complex envelope (the analytic band-passed signal shifted to baseband). What it
/// is for three signals (the closed forms the tests check):
///  - a pure tone (any amplitude): |c| is constant, SK = −1;
///  - stationary Gaussian noise: c is circular complex Gaussian, ⟨|c|⁴⟩ = 2⟨|c|²⟩², SK = 0 (the
///    estimate scatters by about ±3/√M for a band of M bins);
///  - an impulse train: each impact at period T rings down as e^{−t/τ}, the tails adding as
///    phasors, so ⟨|c|⁴⟩/⟨|c|²⟩² = (T/τ) coth(T/τ) and SK ≈ T/τ − 2 for τ ≪ T, large; more
///    generally a transient signal scores high, the more so the rarer its bursts.
/// So SK ranks bands by how impulsive the signal is in them, independently of its level.
///
/// Noise floor: white Gaussian noise n independent of the signal s lowers SK to
/// SK_s · (P_s / (P_s + P_n))² (in expectation, exactly: circular noise adds 2P_n² + 4P_sP_n to
/// ⟨|c|⁴⟩, which the −2⟨|c|²⟩² takes out again), so a band holding a tiny share of the energy
/// shows its own impulsiveness only where nothing masks it, as in a noise-free simulation (the
/// faint ringing of each ball's contact onset). With
/// `noise_floor` ν > 0 the result is the SK the band would have over a white floor of ν times the
/// record's energy, spread evenly over 0 … fs/2: SK · (E_b / (E_b + ν E M/⌊N/2⌋))², E_b the band's
/// energy over its M bins, E the record's; ν = 0 leaves SK as it is.
///
/// How: the mean is removed and x is Hann-windowed (w = ½ − ½ cos 2πj/N: the periodic extension of
/// a record holding no whole number of periods would otherwise jump once per record, an impulse
/// every band would see), then transformed (RealFft). The band keeps the bins k·fs/N, k ≥ 1, in
/// [low, high] (inclusive, 1e-9 bin of slack, as band_envelope: DC never); their M values, zero
/// padded to a fast length L ≥ 2M − 1, are transformed back (ComplexFft), giving c on L points:
/// ⟨|c|²⟩ and ⟨|c|⁴⟩ (|c|⁴ holds frequencies up to 2(M − 1) < L bins) are then the exact time
/// averages of the band's envelope over the record, not those of a decimated copy. The window
/// multiplies c by w, so the ratio is divided by ⟨w⁴⟩/⟨w²⟩² = 35/18 (Hann): a tone's SK is then
/// −1 exactly (to rounding) when its three windowed bins lie inside the band, stationary noise's
/// 0; a band with less than 1e-20 of the record's energy (silent: rounding only) has SK = 0.
/// Throws InputError if N < 2, a sample is not finite, sample_rate is not positive and finite, the
/// band is not 0 ≤ low < high ≤ fs/2, or noise_floor is negative or not finite (each message names
/// the value and the allowed range). O(N log N).
double spectral_kurtosis(const std::vector<double>& x, double sample_rate, FrequencyBand band,
                         double noise_floor = 0);

/// One band of the kurtogram.
struct KurtogramBand {
  double level = 0;    ///< log2(bands): 0, 1, 1.585 (Antoni's "1.6"), 2, 2.585, 3, … [-]
  int bands = 1;       ///< bands the level splits [0, fs/2] into: 1, 2, 3, 4, 6, 8, 12, 16, …
  int index = 0;       ///< 0-based position of the band in its level, from low to high frequency
  FrequencyBand band;  ///< [index, index + 1] × fs / (2 · bands) [Hz]
  double spectral_kurtosis = 0;  ///< SK of x in `band` over the noise floor (spectral_kurtosis())
  double energy_fraction = 0;    ///< E_b / E: the band's share of the record's energy [-]
};

/// The fast kurtogram of a record: every band's SK, and the band of the largest.
struct Kurtogram {
  /// Level by level, coarse to fine (by `bands`), each from low to high frequency.
  std::vector<KurtogramBand> map;
  /// The largest SK of the map; a tie goes to the coarser level, then to the lower band.
  KurtogramBand best;
};

/// Fewest DFT bins a kurtogram band spans: Antoni's deepest level log2(N) − 7 (narrowest band
/// N/2^(L+1) ≥ 64 bins), so SK's scatter on noise stays within about ±0.37 (3/√64).
inline constexpr double kKurtogramMinBins = 64;

/// What the kurtogram's tree and its ranking take.
struct KurtogramSettings {
  /// narrowest band [Hz], e.g. a few times the fastest fault frequency, so that a band's envelope
  /// still holds the impact rate and its sidebands (at least kKurtogramMinBins bins anyway)
  double min_bandwidth = 0;
  double noise_floor = 0;  ///< ν of spectral_kurtosis() [-]: 0, none
};

/// The fast kurtogram of x (sampled at `sample_rate` [Hz]): the 1/3-binary tree of bands of
/// Antoni (2007) — level k splits [0, fs/2] into 2^k bands of width fs/2^(k+1); between levels k
/// and k + 1 (k ≥ 1) a level of 3·2^(k−1) bands of width fs/(3·2^k) — with each band's
/// spectral_kurtosis(x, fs, band, settings.noise_floor). Levels are taken in order of their band
/// count (1, 2, 3, 4, 6, 8, 12, …) as long as their bands are at least kKurtogramMinBins bins
/// (64 fs/N) and settings.min_bandwidth wide; level 0, the whole band, always. One FFT of the
/// record, then each level costs inverse FFTs of about 2 × N/2 points in all: O(N log N) a level
/// (about 6 ms for N = 20000 and 8 levels).
/// Throws InputError as spectral_kurtosis(), and for a min_bandwidth that is negative or not
/// finite.
Kurtogram fast_kurtogram(const std::vector<double>& x, double sample_rate,
                         const KurtogramSettings& settings = {});

}  // namespace bearing
