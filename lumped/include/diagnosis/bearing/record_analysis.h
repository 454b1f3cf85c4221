#pragma once
// The analysis of a measured record (issue 29): one channel's samples in SI at a uniform rate,
// analysed in memory as `run` analyses a simulated response — statistics, the spectrum with peaks
// named by every line family (a measured bearing's excitations are unknown), the envelope with a
// given band or the kurtogram's — plus what real data need: the shaft speed estimated from the
// record's own shaft harmonics, cepstral pre-whitening, the squared envelope spectrum, and the
// fault lines rated over its floor with a threshold from a stated false-alarm rate
// (fault_lines.h). Reading the file is not done here (the records layer reads it); writing the
// result folder is record_output.h.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "bearing/bearing.h"
#include "bearing/choice.h"
#include "bearing/coherence_diagnosis.h"
#include "bearing/fault_lines.h"
#include "bearing/kinematics.h"
#include "bearing/signal/fundamental_estimate.h"
#include "bearing/signal/squared_envelope.h"
#include "bearing/vibration_summary.h"

namespace bearing {

/// Where the shaft speed of an analysis comes from.
enum class SpeedSource {
  option,     ///< given on the command line (`--speed 1797rpm`)
  case_file,  ///< the case's operation.speed
  record,     ///< stored in the record (a CWRU file's XNNNRPM)
  estimate,   ///< found in the record's spectrum near a nominal speed (estimate_speed())
};
/// As summary.json writes them.
inline constexpr Named<SpeedSource> kSpeedSources[] = {{SpeedSource::option, "option"},
                                                       {SpeedSource::case_file, "case"},
                                                       {SpeedSource::record, "record"},
                                                       {SpeedSource::estimate, "estimate"}};

/// The speed asked for.
struct SpeedSetting {
  SpeedSource source = SpeedSource::case_file;
  /// The inner ring's speed [rad/s] (outer ring fixed); for `estimate` the nominal speed the search
  /// is centred on. Positive and finite.
  double speed = 0;
};

/// The speed an analysis used, and for an estimate its evidence.
struct RecordSpeed {
  SpeedSource source = SpeedSource::case_file;
  double speed = 0;  ///< inner-ring speed [rad/s]
  /// `estimate`, or a given speed refined: the nominal, the tolerance, the shaft-harmonic comb and
  /// the harmonics the refinement used (frequencies [Hz], levels over the floor [dB]).
  std::optional<FundamentalEstimate> estimate;
  /// A given speed that the record's own shaft harmonics refined (speed_refinement): the speed
  /// given [rad/s]; `speed` is then the record's.
  std::optional<double> given;
};

/// Which rule names the fault family.
enum class DiagnosisRule {
  coherence,       ///< each family in its band of the cyclic-coherence map (coherence_diagnosis.h)
  line_to_floor,   ///< the fault lines of the squared envelope spectrum (fault_lines.h)
  envelope_peaks,  ///< `run`'s: spectral kurtosis and the envelope peaks' shares (diagnosis.h)
};
inline constexpr Named<DiagnosisRule> kDiagnosisRules[] = {
    {DiagnosisRule::coherence, "coherence"},
    {DiagnosisRule::line_to_floor, "line_to_floor"},
    {DiagnosisRule::envelope_peaks, "envelope_peaks"}};

/// How a record is analysed. The defaults are those of a measured record; with
/// `prewhiten = false`, `min_bandwidth = envelope_min_bandwidth()` and the window, peaks, peak
/// families and band of a run, the statistics, spectrum, peaks, envelope and (rule
/// envelope_peaks) the diagnosis of a run's channel are the run's (analyse()).
struct RecordAnalysisSettings {
  /// Of the spectrum and the envelope spectrum. The squared envelope spectrum and the speed
  /// estimate's spectrum are always Hann: their floor statistics (line_floor.h) rest on its bins
  /// two apart being nearly independent.
  Window window = Window::hann;
  int peaks = 10;  ///< peaks listed in the spectrum and in the envelope spectrum
  /// The families naming the spectrum's peaks: all of them, a measured bearing's excitations
  /// being unknown (a run's own families to compare with a run).
  LineFamilies peak_families = LineFamilies::all();
  /// The envelope's band: the kurtogram's (default), a given one, or none (no envelope, no SES,
  /// no diagnosis).
  EnvelopeBandSetting envelope{EnvelopeBandSource::automatic, {}};
  /// The narrowest band the kurtogram may pick [Hz]; 0: (lines.harmonics + 1) times the fastest
  /// fault rate max(BPFO, BPFI, 2·BSF), so that the band's SES, which reaches the band's width,
  /// holds the last harmonic searched with its upper sideband and the floor beside it.
  double min_bandwidth = 0;
  /// Cepstral pre-whitening (prewhitening.h) of the record before the kurtogram and the envelope;
  /// the statistics and the spectrum stay those of the record as measured. On by default: a
  /// measured record's shaft, gear and electrical lines otherwise reach the squared envelope
  /// spectrum and raise false alarms (CWRU's healthy record 97 does without it).
  bool prewhiten = true;
  FaultLineSettings lines;  ///< the fault-line search and its false-alarm rate
  /// The coherence diagnosis's line test (its false-alarm rate per family and record).
  LineTestSettings coherence;
  int coherence_levels = 3;  ///< levels of the band map (coherence_bands())
  DiagnosisRule rule = DiagnosisRule::coherence;
  /// A given speed (option, case, record) is refined from the record's own shaft harmonics within
  /// ±this fraction, where they stand out (estimate_fundamental() with speed_harmonics, at the
  /// fault lines' false-alarm rate); 0: the given speed is used as is. A speed written down by
  /// hand is a reading: the CWRU fan-end record 279 (1 hp) stores 1732 rpm, its shaft lines say
  /// 1773 rpm (2.4 % faster), and its shaft harmonics then fall outside the zones left out. ±3 %
  /// lies inside the ±10 % within which a comb of shaft harmonics is unambiguous.
  double speed_refinement = 0.03;
  double speed_tolerance = 0.1;  ///< `estimate`: the search within ±10 % of the nominal speed [-]
  int speed_harmonics = 3;       ///< `estimate`: shaft harmonics f_r … 3 f_r in the comb
};

/// The analysis of one record.
struct RecordAnalysis {
  std::string channel;  ///< its name (a column of spectrum.csv, a key of summary.json)
  std::string unit;     ///< the SI unit of its samples ("m/s^2")
  double rate = 0;      ///< [Hz]
  std::size_t samples = 0;
  std::string bearing;  ///< the bearing's designation
  RecordSpeed speed;
  BearingFrequencies frequencies;  ///< at that speed, no cage slip [Hz]
  bool prewhitened = false;
  /// The run-shaped part: one channel (statistics, spectrum with peaks, all line families), its
  /// envelope (of the pre-whitened record if asked), and `diagnosis`, always `run`'s rule
  /// (diagnose() of that envelope).
  VibrationSummary summary;
  /// With an envelope: the squared envelope spectrum of its band [unit²] and the fault lines in it.
  std::optional<Spectrum> squared_envelope;
  std::optional<LineDiagnosis> lines;
  /// With an envelope: the diagnosis from the band-integrated cyclic spectral coherence.
  std::optional<CoherenceDiagnosis> coherence;
  RecordAnalysisSettings settings;  ///< as applied (min_bandwidth resolved)

  /// The family the settings' rule names (none without an envelope).
  FaultFamily family() const;
};

/// The shaft speed of a record from its own shaft harmonics: estimate_fundamental() of
/// `spectrum`, the record's amplitude spectrum with the Hann window, near nominal/2π [Hz] (nominal
/// [rad/s]), within ±tolerance, with `harmonics` harmonics, at the false-alarm probability
/// `false_alarm`. Returns the speed [rad/s] and the evidence. Throws InputError naming the
/// nominal speed, the best comb's level and its threshold when no shaft line stands out (then the
/// speed must be given).
RecordSpeed estimate_speed(const Spectrum& spectrum, double nominal, double tolerance,
                           int harmonics, double false_alarm);

/// Analyses `samples` (in `unit`, SI) taken at `rate` [Hz] from a bearing `bearing` turning at
/// `speed`: the speed (given, or estimate_speed()), the bearing frequencies, statistics, spectrum
/// and peaks (bearing_frequency_names_up_to(…, LineFamilies::all())), the envelope
/// (analyse_envelope() of the record or its pre-whitened copy), diagnose() of it, the squared
/// envelope spectrum of the envelope's band, search_fault_lines() and diagnose_lines() in it; with
/// rule line_to_floor, the envelope peaks then named at the rates the detected families were found
/// at (a measured line sits off the catalogue's by more than find_peaks()' one bin).
/// Throws InputError naming what is wrong: a NaN or infinite sample (its index), a rate that is
/// not positive and finite, a speed that is not, a record shorter than 20 shaft revolutions (the
/// fault lines' slip windows would span no bin and their floors reach 0 Hz), settings out of range,
/// or an estimate that finds no shaft line.
RecordAnalysis analyse_record(const std::vector<double>& samples, double rate,
                              const std::string& channel, const std::string& unit,
                              const Bearing& bearing, const SpeedSetting& speed,
                              const RecordAnalysisSettings& settings = {});

/// The fewest shaft revolutions a record must hold for analyse_record().
inline constexpr double kMinShaftRevolutions = 20;

}  // namespace bearing
