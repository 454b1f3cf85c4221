#pragma once
// The diagnosis of a measured record from its band-integrated cyclic spectral coherence (issue
// 41): each fault family's line test (family_test.h) in each band of the map (coherence_bands.h),
// the family named by its best band, its lines then explained away, and the others looked for
// again — so that a verdict says which part, with which lines, in which band, and by how much.
//
// The procedure, and why:
//  1. The record is pre-whitened (its discrete lines and its resonances' shape removed) and the
//     SES of each band formed. Every family is tested in every band at the record's
//     false-alarm rate divided by the number of bands (a union bound over the bands searched).
//  2. Zones around the shaft harmonics n·f_r are left out of every search: shaft modulation is in
//     every real record, and 2·BSF of the 6203 lies 0.3 % from 4 f_r.
//  3. Of the families that pass, one whose fundamental is a line of another's series (n·c + m·g,
//     |m| ≤ 3), while the other's is not of its own, is the other's: a comb is anchored on its
//     fundamental (the 6205's 2·BSF − 3·FTF lies 1.9 % below BPFO: a ball spall strongly
//     modulated by the cage lends the outer race a comb; the 6203's BPFO + f_r lies 1.6 % above
//     2·BSF, its BPFI − f_r 1.0 % below). Of those left, a race family goes first: where neither
//     explains the other the ball's comb is the likelier borrower, so the ball is named only
//     where no race family passes. Of the races, the larger score over its decoys.
//  4. The named family's series n·c + m·g (|m| ≤ 3, g = f_r for the races, FTF for the ball) is
//     excluded from every band, and the remaining race family is tested again, now with 3 of 3
//     harmonics and its decoys: where it still passes, both are clearly present and the verdict
//     is `several`.
//  5. Decoys guard the weakest evidence: a first family passing with 2 of 3 harmonics must beat
//     its decoys; a first family with 3 of 3 need not (a Gaussian record reaches 3 of 3 with p³,
//     and a coincidence of three harmonics with the machine's lines is rarer than of two). The
//     development records informed this choice (docs/diagnosis.md).
// The false-alarm rate per family and record is then at most the stated one on a Gaussian
// background, and for 2-of-3 and second families also at most 1/(D + 1) on the record's own lines.

#include <string>
#include <vector>

#include "bearing/coherence_bands.h"
#include "bearing/family_test.h"
#include "bearing/kinematics.h"

namespace bearing {

/// One family's best evidence, and where.
struct FamilyEvidence {
  FaultFamily family = FaultFamily::none;
  double nominal = 0;    ///< its rate at the speed used: BPFO, BPFI or 2·BSF [Hz]
  std::size_t band = 0;  ///< index into CoherenceDiagnosis::bands of its best band
  FamilyTest test;       ///< there
  bool named = false;    ///< part of the verdict
  int stage = 0;         ///< 0: tested as a first family; 1: again, after another was named
  /// Bands in which its harmonics alone passed (2 of 3) at the first stage: the Gaussian test
  /// before physics and decoys, whose rate over all bands is at most the stated one on noise.
  int harmonic_bands = 0;
  /// Passed, but its fundamental is a line of this named family's series (step 3); none if not.
  FaultFamily explained_by = FaultFamily::none;
};

/// The verdict.
struct CoherenceDiagnosis {
  /// none, outer, inner, ball, or several (then `named` lists them, the first the stronger).
  FaultFamily family = FaultFamily::none;
  std::vector<FaultFamily> named;
  /// The verdict's margin [dB]: named, the least of the named families' margins (> 0); none, the
  /// largest of the families' (≤ 0).
  double margin = 0;
  std::vector<CoherenceBand> bands;
  std::vector<FamilyEvidence> families;  ///< outer, inner, ball: each family's best band
  /// The map: each family's margin in each band at the first stage [dB], by family (outer,
  /// inner, ball), then band; −100 where the family cannot be rated in that band.
  std::vector<std::vector<double>> map;
  double false_alarm = 0;   ///< per family and record [-]
  bool prewhitened = true;  ///< the bands are those of the pre-whitened record
  std::string reason;       ///< one sentence
  LineTestSettings settings;
};

/// The diagnosis of `x` (any unit, `rate` [Hz], not yet whitened) at the bearing frequencies `f`
/// [Hz], with the bands of coherence_bands(rate, levels); `prewhiten` false leaves the record's
/// spectrum as it is (whitened_spectrum()). Throws InputError for settings out of
/// range, a frequency that is not positive and finite, or a record as whitened_spectrum()
/// refuses it.
CoherenceDiagnosis diagnose_coherence(const std::vector<double>& x, double rate,
                                      const BearingFrequencies& f, int levels = 3,
                                      const LineTestSettings& settings = {}, bool prewhiten = true);

}  // namespace bearing
