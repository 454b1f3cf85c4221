#pragma once
// The names of a bearing's spectral lines (docs/model.md §7): the families of frequencies its
// excitations make — shaft rate, cage, outer- and inner-race ball pass, ball spin — with their
// harmonics, the inner race's shaft-rate sidebands and the subharmonics of the ball pass, and the
// sidebands of local faults for envelope spectra. find_peaks() (peaks.h) names a peak after the
// nearest of them.

#include <string>
#include <vector>

namespace bearing {

/// A frequency with a label such as "BPFO", "2xBPFI" or "5/2xBPFO" [Hz].
struct NamedFrequency {
  std::string label;
  double frequency = 0;  ///< [Hz]
  /// k of k·f, or of (k/m)·f (sidebands: their carrier's k). A tie between names goes to the lower
  /// order k/m.
  int harmonic = 1;
  int subharmonic = 1;  ///< m of (k/m)·f: 1 for a harmonic or a sideband
};

/// Which families of lines name a raw spectrum's peaks: those the signal's excitations make.
/// A simulated run knows its case's excitations (excitation_families(), pipeline layer); a signal
/// whose excitations are unknown takes all().
struct LineFamilies {
  /// k·f_r "fr", "2xfr", …, and with `outer` the ball pass's shaft-rate sidebands k·BPFO ± f_r
  /// "BPFO-fr", "2xBPFO+fr", … (a load turning with the shaft meets the compliance varying at the
  /// ball pass): unbalance, inner-race waviness or defects
  bool shaft = false;
  bool cage = false;   ///< k·FTF "FTF", "2xFTF", …: balls that differ (size errors, a defect)
  bool outer = false;  ///< k·BPFO "BPFO", "2xBPFO", …: the ball set turns (varying compliance)
  /// (k/m)·BPFO, m = 2, 3, 4, k/m in lowest terms and not whole: "1/2xBPFO", "5/2xBPFO",
  /// "4/3xBPFO", "7/4xBPFO": a response that repeats only every 2, 3 or 4 ball passes (period
  /// doubling and period 3 in a bearing whose balls lose contact)
  bool outer_subharmonics = false;
  /// k·BPFI "BPFI", … and its shaft-rate sidebands k·BPFI ± f_r, ± 2f_r "BPFI-fr", "2xBPFI+fr",
  /// "BPFI-2fr", …: features on the turning inner race (waviness, a defect) under the fixed load
  /// zone
  bool inner = false;
  bool spin = false;  ///< k·BSF "BSF", "2xBSF", …: a ball defect

  /// Every family: for a signal whose excitations are not known (a measured record).
  static LineFamilies all() { return {true, true, true, true, true, true}; }
};

/// The families' short names as summary.json lists them, in this order: "fr", "FTF", "BPFO",
/// "BPFO/m" (the subharmonics), "BPFI" (with its shaft sidebands), "BSF".
std::vector<std::string> line_family_names(const LineFamilies& families);

/// The bearing frequencies and their harmonics 1 … max_harmonic, in this order: "fr", "2xfr", …,
/// "FTF", "2xFTF", …, "BPFO", …, "BPFI", …, "BSF", … (the fundamental has no "1x" prefix), then
/// the inner race's shaft-rate sidebands "BPFI-fr", "BPFI+fr", "2xBPFI-fr", … (k·BPFI ± f_r): the
/// plain list of every family, without the ball pass's sidebands and subharmonics.
/// Arguments are the plain numbers (shaft rotation, cage, outer- and inner-race ball-pass and
/// ball-spin frequencies [Hz], e.g. from bearing_frequencies()), so this layer does not depend on
/// kinematics. A zero frequency (e.g. a stationary shaft) contributes no names.
/// Throws InputError for a negative or non-finite frequency or max_harmonic < 1.
std::vector<NamedFrequency> bearing_frequency_names(double shaft, double ftf, double bpfo,
                                                    double bpfi, double bsf, int max_harmonic = 5);

/// The names of `families` for a raw spectrum, with every harmonic up to `max_frequency` [Hz] (the
/// analysis band, e.g. the spectrum's Nyquist frequency), at most 4096 per family, so that a line
/// like 8×BPFO is named as such instead of being left to a lower-order name nearby. Order as
/// bearing_frequency_names(), the families left out skipped, then the inner race's second shaft
/// sidebands "BPFI-2fr", "BPFI+2fr", "2xBPFI-2fr", … (inner), the ball pass's shaft sidebands
/// "BPFO-fr", "BPFO+fr", "2xBPFO-fr", … (shaft and outer), then its subharmonics by m, then k:
/// "1/2xBPFO", "3/2xBPFO", …, "1/3xBPFO", "2/3xBPFO", …, "1/4xBPFO", "3/4xBPFO", … (at most 4096
/// per m). Throws as bearing_frequency_names(), and for a max_frequency that is not positive and
/// finite; the five frequencies are checked whether or not their family is asked for.
std::vector<NamedFrequency> bearing_frequency_names_up_to(double max_frequency, double shaft,
                                                          double ftf, double bpfo, double bpfi,
                                                          double bsf, const LineFamilies& families);

/// For labelling envelope spectra (a diagnosis that does not know the excitations): the plain list
/// of every family (bearing_frequency_names()'s: a local fault strikes at whole multiples of its
/// rate, so no ball-pass sidebands or subharmonics) with every harmonic up to `max_frequency`
/// [Hz], then the other lines of local faults: the inner race's second shaft sidebands "BPFI-2fr",
/// "BPFI+2fr", "2xBPFI-2fr", … (k·BPFI ± 2f_r: a defect on the turning race passes through the
/// load zone once a shaft turn), then the ball's cage sidebands "2xBSF-FTF", "2xBSF+FTF",
/// "4xBSF-FTF", …, "2xBSF-2FTF", … (2k·BSF ± m·FTF, m = 1, 2: a ball defect strikes both races
/// once a spin each and is carried through the load zone by the cage). Same order rule (the
/// simpler names first: a tie goes to them) and harmonic numbers (a sideband has its carrier's
/// k); k·BSF itself is among the plain harmonics. Harmonics k·f ≤ max_frequency, at most 4096 per
/// family; the frequencies are those of bearing_frequency_names (cage slip included if they
/// include it). Throws as bearing_frequency_names_up_to().
std::vector<NamedFrequency> fault_frequency_names_up_to(double max_frequency, double shaft,
                                                        double ftf, double bpfo, double bpfi,
                                                        double bsf);

}  // namespace bearing
