#pragma once
// The result folder of an analysed record, in the files and keys of `bearing-sim run`
// (spectrum.csv, envelope.csv, summary.json; the readable summary) so that bearing-plot draws it,
// with what a record adds: where it came from (file, channel, rate), the speed and its source, the
// squared envelope spectrum and the fault lines.

#include <string>

#include <nlohmann/json.hpp>

#include "bearing/case_file.h"
#include "bearing/record_analysis.h"

namespace bearing {

/// Where an analysed record came from, as the caller knows it (the analysis works on samples).
struct RecordOrigin {
  std::string file;         ///< the record's file as the user named it ("" from memory)
  std::string case_source;  ///< the case file the bearing came from ("" for none)
  /// Where the speed was found when the record or an option gave it ("variable X130RPM", "--speed
  /// 1797rpm"); "" to say nothing.
  std::string speed_origin;
  /// How the file's values became SI samples, as the reader found them: the stored unit ("g")
  /// and scale (stored × scale = value in it), and where the rate and the unit came from
  /// ("--rate", "the WAV header"); all "" (scale 1) for samples from memory.
  std::string stored_unit;
  double scale = 1.0;
  std::string rate_origin;
  std::string unit_origin;
};

/// summary.json of an analysis: `record` {file, channel, rate [Hz], rate_origin, samples,
/// duration [s], unit (SI), stored_unit, scale, unit_origin, prewhitened}, `case` {source, bearing,
/// speed [rad/s]}, `speed` {value [rad/s], shaft [Hz], rpm, source "option" | "case" | "record" |
/// "estimate", origin, and for an estimate `estimate` {nominal [rad/s], tolerance, harmonics[]
/// (order, frequency [Hz], amplitude, level [dB], used), evidence and threshold [dB], false_alarm,
/// refinement}}, `frequencies` [Hz], `channels.<ch>` and `peaks.<ch>` (as `run`), `peak_families`,
/// with an envelope `envelope` (as `run`, plus `prewhitened`) and `fault_lines` {settings, and per
/// family outer, inner, ball: nominal, modulation, carrier [Hz], offset [-], evidence, threshold
/// [dB], trials, rated_harmonics, detected, excluding[] (families whose lines were left out of its
/// search), lines[] (label, harmonic, sideband, nominal, frequency [Hz], amplitude, floor [unit²],
/// floor_samples, level [dB], rated, excluded)}, `diagnosis` (the settings' rule: line_to_floor
/// {family, rule, channel, unit, band [Hz], band_source, spectral_kurtosis, evidence[] (label,
/// frequency, amplitude, level), evidence_level, threshold, margin [dB], reason, thresholds}, or
/// `run`'s block with rule "envelope_peaks"), and `units`. Throws SolverError if a value is not
/// finite.
nlohmann::json record_summary_json(const RecordAnalysis& a, const RecordOrigin& origin);

/// The readable summary: the record, speed, frequencies, statistics and largest peak, the envelope
/// band, each family's fault lines and the diagnosis, with units.
std::string record_summary_text(const RecordAnalysis& a, const RecordOrigin& origin);

/// Writes spectrum (frequency, <channel>), with an envelope envelope (frequency, env_<channel>:
/// the envelope spectrum; ses_<channel>: the squared envelope spectrum [unit²]) as CSV or .npy (+
/// columns.json), and summary.json into `dir`, all or nothing as write_run() does (files of an
/// earlier run or analysis there that this one does not write are removed). Throws InputError
/// (the folder cannot be created), OutputError (a file cannot be written) or SolverError (a value
/// is not finite).
void write_record_analysis(const std::string& dir, const RecordAnalysis& a,
                           const RecordOrigin& origin, OutputFormat format = OutputFormat::csv);

}  // namespace bearing
