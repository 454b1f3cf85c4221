#pragma once
// A measured vibration record as the analysis takes it: one channel's samples in SI at a uniform
// rate, and where every number came from (the file or an option), so a report can say so.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "bearing/records/record_unit.h"

namespace bearing {

/// Where a record's rate or unit came from. `option`: RecordOptions gave it (the file, if it
/// states one too, agreed with it); `file`: only the file states it.
enum class RecordSource { file, option };

inline constexpr Named<RecordSource> kRecordSources[] = {
    {RecordSource::file, "file"},
    {RecordSource::option, "option"},
};

struct MeasuredRecord {
  /// The samples in SI: m/s^2 (acceleration), m/s (velocity) or m (displacement) by `quantity`;
  /// never empty, every value finite.
  std::vector<double> samples;
  MeasuredQuantity quantity = MeasuredQuantity::acceleration;
  /// Uniform sampling rate [Hz], finite and > 0.
  double rate = 0;
  /// The file as the user named it, and the channel read from it (a variable, column or
  /// dataset name; "0", "1", ... for unnamed channels).
  std::string file;
  std::string channel;
  /// The unit the stored values (times the scale) were in before the conversion to SI.
  RecordUnit unit = RecordUnit::m_per_s2;
  /// Stored value × scale = value in `unit` (RecordOptions::scale).
  double scale = 1.0;
  RecordSource rate_source = RecordSource::option;
  RecordSource unit_source = RecordSource::option;
  /// Where in the file the rate or unit was found when the file states it ("the WAV header",
  /// "time column t", "attribute rate of /acc", "the header of column DE"); empty otherwise.
  std::string rate_origin;
  std::string unit_origin;
  /// The shaft speed [rad/s] the file records, if any (a CWRU .mat's scalar XNNNRPM, stored in
  /// rpm, converted); finite and > 0 when set.
  std::optional<double> shaft_speed;
  /// Where it was found: "variable X130RPM (1796 rpm)"; empty without a shaft speed.
  std::string shaft_speed_origin;

  /// The record's length [s]: samples / rate.
  double duration() const { return static_cast<double>(samples.size()) / rate; }
};

}  // namespace bearing
