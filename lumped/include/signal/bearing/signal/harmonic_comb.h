#pragma once
// A comb of spectral lines — the harmonics k·c of a rate c and their sidebands k·c ± g — searched
// in a spectrum where c is known only within a relative slip, and rated against the spectrum's
// floor. It serves the fault lines of a squared envelope spectrum (c a fault rate, g the shaft or
// cage rate) and the shaft harmonics of a raw spectrum (the speed estimate).
//
// The comb moves as one: all its lines follow the same relative offset δ of the carrier, as slip
// and speed errors move every line of one source in proportion. So a line of another source that
// happens to fall into one harmonic's window (3·BPFO lies 0.7 % from 2·BPFI) adds to one term of
// the comb, not to all of them.

#include <vector>

#include "bearing/signal/envelope.h"
#include "bearing/signal/spectrum.h"

namespace bearing {

/// The comb to search.
struct HarmonicComb {
  double carrier = 0;  ///< nominal rate c [Hz], > 0: the harmonics k·c, k = 1 … harmonics
  int harmonics = 3;   ///< K ≥ 1
  /// Sideband spacing g [Hz]: with g > 0 each harmonic has the lines k·c − g, k·c, k·c + g; 0: the
  /// harmonics alone.
  double modulation = 0;
  /// g moves with the carrier (a cage-rate modulation: both are the cage's) or stays (the shaft
  /// rate, known apart from the slip).
  bool modulation_slips = false;
  /// The carrier is searched within (1 ± slip)·c [-], 0 ≤ slip < 0.5.
  double slip = 0.02;
  /// A line is rated only if its window (the range it spans as δ goes over ± slip) and its floor
  /// flanks (floor_around()) lie inside this band [Hz]: a squared envelope spectrum's floor falls
  /// to zero at the demodulated band's width, a raw spectrum ends at the Nyquist frequency.
  FrequencyBand rated;
  /// Only offsets at which the first harmonic's bin is a peak (above its left neighbour, not
  /// below its right one) count: a harmonic series is anchored on its fundamental, so that a comb
  /// whose higher harmonics merely meet other sources' lines, its fundamental on no line, loses.
  /// Restricting the offsets can only lower the false-alarm rate.
  bool anchored = false;
  /// Zones where lines of another source sit (e.g. shaft harmonics in a squared envelope
  /// spectrum) [Hz]: a comb line whose bin falls into one counts as absent at that offset.
  std::vector<FrequencyBand> excluded;
};

/// One line of the comb at the offset found.
struct CombLine {
  int harmonic = 1;      ///< k
  int sideband = 0;      ///< −1, 0, +1: the line k·c + sideband·g
  double nominal = 0;    ///< its frequency at the nominal carrier [Hz]
  double frequency = 0;  ///< the frequency of its bin at the offset found [Hz]
  double amplitude = 0;  ///< the spectrum there [unit of the spectrum]
  double floor = 0;      ///< √ of the floor power around its window (floor_around()) [unit]
  int floor_samples = 0;
  /// 10 log10(amplitude² / floor²) [dB]; 0 when not rated or excluded at this offset.
  double level = 0;
  bool rated = false;     ///< window and flanks inside the rated band, and a floor estimated
  bool excluded = false;  ///< its bin lies in an excluded zone at this offset
};

/// What the search found.
struct CombSearch {
  double offset = 0;   ///< δ of the best comb: the carrier at (1 + δ)·nominal [-]
  double carrier = 0;  ///< (1 + δ)·nominal [Hz]
  /// The comb's evidence: the mean over the rated harmonics of each harmonic's strongest rated
  /// line level, levels below 0 dB counted as 0 [dB]. Its largest value over the offsets.
  double evidence = 0;
  /// The evidence a line-free Gaussian background reaches with probability `false_alarm`
  /// somewhere in the search (comb_threshold()) [dB]; 0 if nothing is rated.
  double threshold = 0;
  double false_alarm = 0;       ///< the false-alarm probability asked for [-]
  double trials = 0;            ///< offsets counted as independent tries (comb_threshold()) [-]
  int rated_harmonics = 0;      ///< harmonics with at least one rated line
  bool detected = false;        ///< rated_harmonics > 0 and evidence ≥ threshold
  std::vector<CombLine> lines;  ///< every line at the offset found, by harmonic, then sideband
};

/// Searches `comb` in `spectrum` (an amplitude spectrum: Spectrum's amplitude, any unit): for
/// each offset δ ∈ [−slip, slip] in steps that move the fastest line by half a bin, every rated
/// line is read at its nearest bin, its level taken over its floor (floor_around() of the line's
/// whole window, within comb.rated, estimated once), and the comb's evidence formed (CombSearch);
/// the best offset wins (a tie: the smaller |δ|; anchored: only offsets whose first harmonic sits
/// on a peak; none such: evidence 0, offset 0). The threshold is comb_threshold() of the rated
/// lines' floors with trials = the bins the fastest rated line crosses.
/// Throws InputError for a carrier that is not positive and finite, harmonics < 1, a modulation
/// that is negative or not finite, a slip outside [0, 0.5), a false_alarm outside (0, 1), or a
/// spectrum as floor_around() refuses it.
CombSearch search_comb(const Spectrum& spectrum, const HarmonicComb& comb, double false_alarm);

/// The threshold on a comb's evidence (mean over K terms [dB]) that a line-free background
/// exceeds with probability at most `false_alarm` in `trials` tries. Term k is
/// max(0, max over its lines m of 10 log10 r_m), each ratio r_m of an exponential bin over a floor
/// of `floor_samples[k][m]` samples, independent (floor_exceedance(): P(r_m > R) exactly), so
/// P(term_k ≤ d) = Π_m (1 − floor_exceedance(10^(d/10), n_m)); the terms are independent (their
/// bins lie apart) and their sum's law is their convolution, done on a 0.1 dB grid with every
/// value rounded up (so the threshold errs high). A term with no line is left
/// out (K counts the others). The threshold t satisfies trials · P(Σ terms ≥ K t) ≤ false_alarm
/// and lies less than 0.1 dB above the least such t (the grid's rounding): a union bound over the
/// tries, which are correlated (neighbouring offsets share most bins), so the true false-alarm
/// rate is lower. [dB]; 0 when no term has a line.
/// Throws InputError for false_alarm outside (0, 1), trials < 1 or not finite, or a negative n.
double comb_threshold(const std::vector<std::vector<int>>& floor_samples, double trials,
                      double false_alarm);

}  // namespace bearing
