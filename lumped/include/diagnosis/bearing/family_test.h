#pragma once
// The line test of one fault family in one squared envelope spectrum (issue 41), and the two
// guards a real machine needs beyond a Gaussian background.
//
// 1. Harmonics over the floor. For each of the family's first three harmonics h·c (c = BPFO,
//    BPFI or 2·BSF), the SES's largest power bin within ±slip of h·c, bins in excluded zones left
//    out (the shaft harmonics; the lines of a family already named), against the mean of the
//    floor around it, median / ln 2 of the power bins within ±c/2. Under the null — a whitened
//    Gaussian record — an SES power bin is exponential, so the largest of W exceeds t times the
//    mean with probability p = 1 − (1 − e^(−t))^W (exceedance_threshold()). A harmonic stands
//    out when it exceeds the t of p; the family passes when 2 of its 3 harmonics do (3 of 3 for a
//    second family, a stricter rate), which a Gaussian record does with 3p² − 2p³ (p³). p comes
//    from the stated false-alarm rate per family and record, divided among the bands searched.
// 2. Decoys: the record's own lines. A real machine's SES holds deterministic lines (shaft
//    harmonics and their products with everything else, the supply, a fault's sidebands) that a
//    Gaussian threshold does not know. The same test is run at decoy rates c·(1 + s), s from
//    −span to +span in steps of 2·slip, away (by 2·slip·c) from the family's own series c + m·g,
//    |m| ≤ 3; the family's score (the summed excess of its standing-out harmonics over their
//    thresholds, dB) must beat every rated decoy's. If the family's lines are exchangeable with
//    the decoys' (no fault: any rate is as likely to meet the machine's lines as another), it
//    beats D decoys with probability 1/(D + 1) at most — a false-alarm rate that holds for the
//    record's own line density, whatever it is; with the Gaussian test both must pass.
// 3. The physics of each family, once its harmonics pass: an inner race defect passes the load
//    zone once a shaft turn, so one of the f_r sidebands of the first two harmonics stands out; a
//    ball defect is carried through it by the cage, so one of the first two harmonics' FTF
//    sidebands, or the BSF line, or the FTF line stands out; an outer race defect in a stationary
//    load zone needs no modulation. Each side line is tested as a harmonic is, within ±1.5 bins,
//    against the floor of the 20 bins (at least 10 Hz) beside it, at p / (number of lines).

#include <array>
#include <vector>

#include "bearing/diagnosis.h"
#include "bearing/signal/envelope.h"

namespace bearing {

/// How a family is tested.
struct LineTestSettings {
  double slip = 0.02;         ///< each harmonic searched within ±slip of h·c [-], in [0.002, 0.1]
  double false_alarm = 1e-3;  ///< per family and record, over all bands [-], in (0, 0.1]
  double decoy_span = 0.45;   ///< decoy rates c·(1 ± s), s ≤ span [-], in [0, 0.9]
  int explained_sidebands = 3;  ///< a named family's series n·c + m·g, |m| ≤ this, excluded [-]
  /// Half-width of the zones around the shaft harmonics n·f_r left out, relative to n·f_r (at
  /// least 2 bins) [-].
  double shaft_exclusion = 0.002;
};

/// One harmonic's test.
struct HarmonicTest {
  int harmonic = 1;
  double nominal = 0;    ///< h·c [Hz]
  double frequency = 0;  ///< the largest bin's [Hz]
  double ratio = 0;      ///< its power over the floor's mean [-]
  double threshold = 0;  ///< t of p for its window [-]
  double excess = 0;     ///< 10 log10(ratio / threshold) [dB]
  int window = 0;        ///< bins searched
};

/// A side line (sideband, BSF, FTF) of the physics test.
struct SideLine {
  const char* label = "";  ///< "BPFI-fr", "2xBPFI+fr", "2xBSF-FTF", "BSF", "FTF"
  double frequency = 0;    ///< [Hz]
  double excess = 0;       ///< over its threshold [dB]
};

/// A family's test in one SES.
struct FamilyTest {
  FaultFamily family = FaultFamily::none;
  bool rated = false;  ///< all three harmonics' windows and floors lie inside the band
  std::array<HarmonicTest, 3> harmonics{};
  int standing_out = 0;         ///< harmonics over their threshold
  int needed = 2;               ///< harmonics that must stand out (2 first, 3 for a second family)
  double score = 0;             ///< Σ max(0, excess) [dB]
  bool decoys_applied = false;  ///< the decoy test was asked for (and is then needed)
  int decoys = 0;               ///< decoys rated
  double decoy_score = 0;       ///< the largest rated decoy's score [dB]
  bool physics = true;          ///< the family's side lines as its physics asks (outer: always)
  std::vector<SideLine> side_lines;  ///< those tested, strongest first
  bool detected = false;             ///< harmonics, physics and (if applied) decoys all pass
  /// How far the test is from flipping [dB]: detected, the least of the needed-th largest excess
  /// and (decoys applied) score − decoy score, > 0; not detected, the largest failing such term,
  /// ≤ 0 (physics missing: the best side line's excess); −100 when the side lines or the
  /// decoys it needs could not be rated (too near the band's edge).
  double margin = 0;
};

/// An SES as the tests read it: power bins |SES_k|² at k·df, rated up to `width` [Hz], and the
/// bins to leave out (1: excluded).
struct SesView {
  const std::vector<double>* power = nullptr;
  double df = 0;     ///< [Hz]
  double width = 0;  ///< [Hz]
  const std::vector<char>* excluded = nullptr;
};

/// t such that the largest of `window` exponential bins exceeds t times their mean with
/// probability p: −ln(1 − (1 − p)^(1/W)).
double exceedance_threshold(double p, int window);
/// The per-harmonic probability p for which at least `needed` of three independent harmonics
/// exceed with probability `rate`: 3p² − 2p³ = rate (needed 2), p³ = rate (needed 3), else
/// 1 − (1 − p)³ = rate.
double harmonic_probability(double rate, int needed);

/// The harmonics of rate `carrier` [Hz] in `ses` at per-harmonic probability p (no decoys, no
/// physics); rated false if a window or floor leaves the band.
FamilyTest test_harmonics(const SesView& ses, FaultFamily family, double carrier, double p,
                          int needed, const LineTestSettings& s);

/// The full test: test_harmonics() at p = harmonic_probability(p_family, 2) (`needed` 3 then asks
/// all three at that p: a rate p³); if it passes, the physics lines (`shaft` f_r, `ftf` [Hz],
/// both at the speed used; the ball's FTF scaled by the offset found) at p_side = p_family / n;
/// then, if `with_decoys`, the decoys (their modulation g = f_r for the races, FTF for the ball).
/// `p_family` is the family's false-alarm rate in this SES (the record's divided among bands).
FamilyTest test_family(const SesView& ses, FaultFamily family, double carrier, double shaft,
                       double ftf, double p_family, int needed, bool with_decoys,
                       const LineTestSettings& s);

}  // namespace bearing
