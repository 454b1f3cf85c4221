#pragma once
// The fault lines of a squared envelope spectrum (SES) and the diagnosis they make, for a record
// whose excitations are unknown (issue 29): for each fault family — outer race k·BPFO, inner race
// k·BPFI ± f_r, ball k·2BSF ± FTF — the comb of its first harmonics and sidebands is searched
// within a slip window (harmonic_comb.h), and its height over the SES's local floor in dB is the
// family's evidence. A family is detected where its evidence reaches the threshold a Gaussian
// background would reach only with a stated false-alarm probability; of the detected families the
// one furthest over its threshold is named.
//
// Why these choices:
//  - the slip window ±2 %: the lines of real bearings sit off the kinematic ones (the cage slips,
//    the contact angle and the effective diameters are not the catalogue's, the speed is read
//    within a fraction of a percent); the CWRU records' lines lie 0.3 % off, ball and cage lines
//    slip most, 1–2 % is the range the literature gives (Randall & Antoni, MSSP 25, 2011, §2.1);
//  - three harmonics: a local fault's impacts make a line series whose first harmonics stand out
//    in a band of a few times the fault rate; one line alone is as likely another source's;
//  - the sidebands: a defect on the turning inner race passes the load zone once a shaft turn
//    (k·BPFI ± f_r), a defective ball is carried through it by the cage (k·2BSF ± FTF);
//  - shaft harmonics are not fault lines: zones around n·f_r are left out of the search, so a
//    record whose band is modulated by the shaft (strong in many machines) does not feed a fault
//    comb whose higher harmonics happen to pass n·f_r (2·BPFI of the 6205 lies 1.6 % from 11 f_r).

#include <string>
#include <vector>

#include "bearing/diagnosis.h"
#include "bearing/kinematics.h"
#include "bearing/signal/harmonic_comb.h"
#include "bearing/signal/spectrum.h"

namespace bearing {

/// How the fault lines are searched and judged.
struct FaultLineSettings {
  double slip = 0.02;  ///< each family's rate searched within ±slip of its nominal [-]
  int harmonics = 3;   ///< k = 1 … harmonics of each family's rate
  /// The probability that a record holding no fault lines (a stationary Gaussian background)
  /// shows a family's comb over its threshold, per family and record [-].
  double false_alarm = 1e-3;
  /// Half-width of the zones around the shaft harmonics n·f_r left out of the search, relative to
  /// n·f_r (at least 2 bins): the speed is known to about 0.1–0.2 % [-].
  double shaft_exclusion = 0.002;
};

/// One family's comb in the SES.
struct FamilyLines {
  FaultFamily family = FaultFamily::none;
  double nominal = 0;     ///< its rate at the speed used: BPFO, BPFI or 2·BSF [Hz]
  double modulation = 0;  ///< its sideband spacing: f_r (inner), FTF (ball), 0 (outer) [Hz]
  CombSearch comb;        ///< the search (evidence, threshold, lines) [dB, Hz]
  /// The label of each comb line, as fault_frequency_names_up_to() spells them: "BPFO",
  /// "3xBPFO", "2xBPFI-fr", "2xBSF", "4xBSF+FTF" (one per comb.lines entry).
  std::vector<std::string> labels;
  /// Families whose lines were left out of this one's search (search_fault_lines(): each line
  /// to one source), in the order they were fixed.
  std::vector<FaultFamily> excluding;
};

/// The verdict of the fault lines.
struct LineDiagnosis {
  FaultFamily family = FaultFamily::none;  ///< the named family, or none
  std::vector<FamilyLines> families;       ///< outer, inner, ball
  /// The named family's evidence minus its threshold [dB] (none: the largest of the families').
  double margin = 0;
  std::string reason;  ///< one sentence: why this family, or why none
  FaultLineSettings settings;
};

/// The three families' combs in `ses` (the squared envelope spectrum of a band `band_width` [Hz]
/// wide: its floor falls to zero there, so lines are rated from its third bin up to band_width),
/// at the bearing frequencies `f` [Hz], zones around the shaft harmonics left out. Each line is
/// then given to one source: the detected family furthest over its threshold keeps its combs,
/// and every line of its series (n·c, n·c ± g and n·c ± 2g up to band_width, at the rate found,
/// ±(2 + n/2K) bins) is left out of the others', which are searched again; repeated while a family
/// not yet fixed is detected. Throws InputError for settings out of range (slip
/// outside [0, 0.5), harmonics < 1, false_alarm outside (0, 1), shaft_exclusion negative) or a
/// frequency that is not positive.
std::vector<FamilyLines> search_fault_lines(const Spectrum& ses, double band_width,
                                            const BearingFrequencies& f,
                                            const FaultLineSettings& settings);

/// The diagnosis from the families' combs: the detected family (evidence ≥ threshold) with the
/// largest margin over its threshold, or none. `where` names the spectrum in the reason ("ay,
/// 2–4 kHz (kurtogram), pre-whitened").
LineDiagnosis diagnose_lines(std::vector<FamilyLines> families, const FaultLineSettings& settings,
                             const std::string& where);

/// The lines of a family a report lists as its evidence: the rated ones, strongest first.
std::vector<std::size_t> evidence_lines(const FamilyLines& family);

}  // namespace bearing
