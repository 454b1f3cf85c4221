#pragma once
// The columns of sweep.csv after the design's keys, `status` and `error`, and a row's fields in
// them. The CSV writer (sweep.h) and the Python rows (python/src/module.cc) both use these, so they
// give the same columns and values.

#include <cstddef>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "bearing/sweep_row.h"

namespace bearing {

/// What the columns of a sweep are made of: those of its first successful row (a row that lacks
/// one gets empty fields there).
struct SweepColumns {
  /// Ring channels: `<ch>.rms, <ch>.ptp, <ch>.kurtosis, <ch>.crest, <ch>.peak_frequency,
  /// <ch>.peak_label`.
  std::vector<std::string> channels;
  /// [acoustics] microphones i = 1…: `mic<i>.spl_total, mic<i>.spl_ring, mic<i>.spl_balls`.
  std::size_t microphones = 0;
  /// output.envelope_band: per ring acceleration `env_<ch>.band_low, env_<ch>.band_high,
  /// env_<ch>.spectral_kurtosis, env_<ch>.energy_fraction, env_<ch>.peak_frequency,
  /// env_<ch>.peak_amplitude, env_<ch>.peak_label`.
  std::vector<std::string> envelopes;
  /// With the envelopes: `diagnosis.family, diagnosis.channel, diagnosis.spectral_kurtosis,
  /// diagnosis.family_share, diagnosis.evidence_labels, diagnosis.evidence_frequencies,
  /// diagnosis.evidence_amplitudes, diagnosis.reason`.
  bool diagnosis = false;
};

/// The columns of a successful row.
SweepColumns sweep_columns(const SweepRow& first_ok);

/// The columns a sweep.csv header line (without its newline) names.
SweepColumns sweep_columns(std::string_view header);

/// The column names after `status,error`, in order: channels, microphones, envelopes, diagnosis.
std::vector<std::string> sweep_column_names(const SweepColumns& columns);

/// One field: empty (a failed row, a column the row lacks, a level or line that does not exist),
/// a number (SI) or a text.
using SweepCell = std::variant<std::monostate, double, std::string>;

/// `row`'s fields in the columns, one per name of sweep_column_names(). Numbers in SI: rms, ptp
/// and envelope amplitudes in the channel's unit, frequencies and bands in Hz, levels in dB re
/// 20 µPa, kurtosis, crest, spectral kurtosis, energy fraction and family share in 1. The
/// diagnosis evidence as three lists joined by ';' (labels; frequencies [Hz]; amplitudes [unit
/// of the channel], shortest round-trip decimals), empty for the family none.
std::vector<SweepCell> sweep_cells(const SweepColumns& columns, const SweepRow& row);

/// A number as sweep.csv writes it: the shortest decimal that reads back to the same double.
void append_number(std::string& out, double v);

}  // namespace bearing
