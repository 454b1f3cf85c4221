#pragma once
// The fundamental of a harmonic series in a spectrum, known only roughly beforehand: the shaft
// frequency of a machine from the shaft harmonics f_r, 2f_r, 3f_r, … its vibration carries
// (unbalance, misalignment, looseness), searched within a tolerance of the nominal speed.

#include <vector>

#include "bearing/signal/harmonic_comb.h"
#include "bearing/signal/spectrum.h"

namespace bearing {

/// A harmonic the estimate rests on.
struct HarmonicLine {
  int order = 1;         ///< k
  double frequency = 0;  ///< the line's refined frequency [Hz] (peak_vertex_offset())
  double amplitude = 0;  ///< its largest bin [unit of the spectrum]
  double level = 0;      ///< over its floor [dB] (CombLine::level)
  bool used = false;     ///< entered the refinement (estimate_fundamental())
};

/// What estimate_fundamental() found.
struct FundamentalEstimate {
  bool found = false;    ///< the comb of harmonics stands over its threshold
  double frequency = 0;  ///< the estimate [Hz] (found only; else the comb's best carrier)
  double nominal = 0;    ///< [Hz]
  double tolerance = 0;  ///< the search's relative half-width [-]
  CombSearch comb;       ///< the harmonic comb at its best offset
  std::vector<HarmonicLine> harmonics;  ///< every rated harmonic of the comb, by order
};

/// The fundamental f of the series f, 2f, …, K f (K = `harmonics`) in the amplitude spectrum
/// `spectrum`, within (1 ± tolerance)·nominal:
///  1. search_comb() of the harmonics (no sidebands, slip = tolerance, anchored: the fundamental
///     on a peak, rated over the whole spectrum from its third bin to its last), at the
///     false-alarm probability `false_alarm`: found if its evidence reaches the threshold;
///  2. refinement: each harmonic's line is located at the largest of the three bins around the
///     comb's and refined by peak_vertex_offset(); the fundamental f_1 is used, and each further
///     harmonic whose own level reaches the threshold and whose peak lies within 0.1 bin of
///     k f_1 (ten times the refinement's own bias: a peak further off is pulled by another
///     source's line beside it); f is the least-squares
///     fit of f_k = k f to those: f = Σ k f_k / Σ k² (the error of a refined line is about the
///     same in Hz for every k, so the higher harmonics pin f down more finely).
/// Within ±10 % only the true f lines the whole comb up with the series: another harmonic j ≠ k of
/// the series meets the comb's k-th line only at f'/f = j/k, outside [0.9, 1.1] for every k ≤ 9, so
/// it adds to one term at most.
/// Throws InputError as search_comb() (nominal as its carrier, tolerance as its slip).
FundamentalEstimate estimate_fundamental(const Spectrum& spectrum, double nominal, double tolerance,
                                         int harmonics, double false_alarm);

}  // namespace bearing
