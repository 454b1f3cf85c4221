#pragma once
// What every format reader hands over: one channel's stored values and what the file itself says
// about them (rate, unit, shaft speed, each with where it was found). finish_record() applies the
// options (checking them against the file), converts to SI once and checks the samples, so the
// rules of rates, units and bad samples live in one place for every format.

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "bearing/errors.h"
#include "bearing/records/measured_record.h"
#include "bearing/records/record_options.h"

namespace bearing {

struct RawChannel {
  std::string channel;         ///< the name read (see RecordOptions::channel)
  std::vector<double> values;  ///< as stored, in file order
  std::optional<double> rate;  ///< [Hz] as the file states it
  std::string rate_origin;     ///< where: "the WAV header", "time column t", ...
  /// How far a given rate may lie from `rate` and still agree, relative (a WAV header's integer
  /// is exact; a CSV time column knows its rate only to its printed digits, time_column.h).
  double rate_tolerance = 1e-9;
  std::optional<std::string> unit;    ///< the unit text the file states for this channel
  std::string unit_origin;            ///< where: "the header of column DE", "attribute unit of /a"
  std::optional<double> shaft_speed;  ///< [rad/s]
  std::string shaft_speed_origin;
};

/// The record: `raw` with the options applied and checked against what the file states, the
/// values times options.scale times the unit's SI factor. InputError, one line naming the file
/// and the channel, when: there are no samples; a value is NaN or ±Inf (naming the sample, from
/// 0) or becomes so in SI; neither file nor options give the rate or the unit; the option's rate
/// or unit contradicts the file's; a rate or scale is not finite and > 0 (nonzero for scale); a
/// unit is unknown (listing the known ones).
MeasuredRecord finish_record(RawChannel raw, const RecordOptions& options, const std::string& file);

/// The InputError "FILE: channel CHANNEL: WHAT" ("FILE: WHAT" when `channel` is empty): every
/// reader's message has this form.
InputError record_error(const std::string& file, std::string_view channel, std::string_view what);

}  // namespace bearing
