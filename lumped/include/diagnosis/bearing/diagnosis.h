#pragma once
// Which race or the balls a run's envelope spectra point at (issue 17): a local fault's impacts
// make the signal impulsive in some band, and their rate, seen in that band's envelope, names the
// faulty part — outer race k·BPFO, inner race k·BPFI and its shaft-rate sidebands, ball k·BSF and
// its cage-rate sidebands.
//
// Lines alone do not make a fault: a healthy bearing in this toolkit vibrates at BPFO harmonics
// (varying compliance: the ball set turns), and waviness adds deterministic lines, inner-race ones
// among them; "the family with the largest envelope lines" would call every healthy bearing an
// outer-race fault. So a family is named only where the band is impulsive (its spectral kurtosis,
// rated over the analysis's noise floor, reaches a threshold) and the family's lines dominate the
// fault lines of the envelope spectrum.

#include <string>
#include <vector>

#include "bearing/choice.h"
#include "bearing/envelope_analysis.h"
#include "bearing/kinematics.h"
#include "bearing/signal/peaks.h"

namespace bearing {

/// The part a fault family points at.
enum class FaultFamily {
  none,     ///< no fault lines, or not impulsive, or no family dominates
  outer,    ///< k·BPFO
  inner,    ///< k·BPFI and k·BPFI ± m·f_r
  ball,     ///< k·BSF (2k·BSF: a ball defect strikes both races each spin) and 2k·BSF ± m·FTF
  several,  ///< two families clearly present (a record's coherence diagnosis only)
};
/// As summary.json writes them.
inline constexpr Named<FaultFamily> kFaultFamilies[] = {{FaultFamily::none, "none"},
                                                        {FaultFamily::outer, "outer"},
                                                        {FaultFamily::inner, "inner"},
                                                        {FaultFamily::ball, "ball"},
                                                        {FaultFamily::several, "several"}};

/// "outer race", "inner race", "ball", "several families", "none": for the readable summary.
const char* fault_family_text(FaultFamily family);

/// The family a peak label of fault_frequency_names_up_to() belongs to: "BPFO", "3xBPFO" outer;
/// "BPFI", "2xBPFI-fr", "BPFI+2fr" inner; "BSF", "2xBSF", "4xBSF-FTF" ball; anything else
/// ("fr", "12xFTF", the raw spectra's subharmonics "5/2xBPFO", "", unknown spellings) none.
FaultFamily fault_family(const std::string& label);

/// The thresholds of diagnose().
struct DiagnosisSettings {
  /// Least spectral kurtosis (over kEnvelopeNoiseFloor) of the envelope's band to call it
  /// impulsive [-]. 5 is a train of ringing impacts each decaying within a seventh of the period
  /// (SK = (T/τ) coth(T/τ) − 2 = 5 at T/τ ≈ 7), far above stationary noise (0 ± 3/√M, M ≥ 64
  /// bins) and twice the healthy default 6308 (2.3: the light-load 2-DOF response's own rattle
  /// at BPFO, with or without 0.5 µm of outer-race waviness). Simulated 0.533 mm spalls on the
  /// CWRU-like 6205 reach 9.3 (outer), 27 (inner), 27 (ball): tests/lumped/test_fault_diagnosis.cc.
  /// Rings rattling over waviness under a light load pass it without a spall: the inner-race
  /// waviness of examples/seed002_tvds (SK 8.4) and seed003_measured (5.3), the ball-DOF
  /// seed004_6304 (5.3).
  double min_spectral_kurtosis = 5;
  /// Least share of the leading family in the amplitude of all fault-family lines among the
  /// envelope's listed peaks [-]: below it two families compete and none is named.
  double min_family_share = 0.6;
};

/// The verdict and what it rests on.
struct Diagnosis {
  FaultFamily family = FaultFamily::none;
  std::string channel;  ///< the envelope it rests on (the most impulsive one if none; "" if none)
  std::string unit;     ///< of the evidence amplitudes (the channel's)
  FrequencyBand band;   ///< that envelope's band [Hz]
  EnvelopeBandSource source = EnvelopeBandSource::none;  ///< given or automatic (kurtogram)
  double spectral_kurtosis = 0;                          ///< of that band [-]
  double family_share = 0;       ///< the leading family's share of the fault-line amplitude [-]
  std::vector<Peak> evidence;    ///< the named family's envelope lines, largest first (none: empty)
  std::string reason;            ///< one sentence: why this family, or why none
  DiagnosisSettings thresholds;  ///< the ones applied
};

/// The diagnosis from a run's envelope summaries: for each envelope, the fault family whose lines
/// (fault_family() of its peaks' labels) hold the largest summed amplitude leads; the envelope
/// counts if its spectral_kurtosis ≥ settings.min_spectral_kurtosis and that family holds at least
/// settings.min_family_share of the fault-family amplitude. Of the envelopes that count, the most
/// impulsive (largest SK; a tie: the earlier) names the family; if none counts, the family is none
/// and the reason names the most impulsive envelope and what it lacks. `frequencies` [Hz] (with
/// cage slip) only enter the reason. No envelopes: none, "no envelope analysis".
Diagnosis diagnose(const std::vector<EnvelopeSummary>& envelopes,
                   const BearingFrequencies& frequencies, const DiagnosisSettings& settings = {});

}  // namespace bearing
