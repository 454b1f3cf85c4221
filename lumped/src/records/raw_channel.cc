#include "bearing/records/raw_channel.h"

#include <cmath>
#include <cstdio>
#include <utility>

#include "bearing/units.h"

namespace bearing {

namespace {

// A message stays one line whatever bytes a file's names hold: control characters are shown as
// \xNN.
std::string one_line(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) {
      char esc[5];
      std::snprintf(esc, sizeof esc, "\\x%02x", u);
      out += esc;
    } else {
      out += c;
    }
  }
  return out;
}

std::string known_units() {
  return names_of(kRecordUnits);
}

RecordUnit parse_unit(const std::string& text, const std::string& file, const std::string& channel,
                      std::string_view where) {
  if (const auto unit = find_record_unit(text)) return *unit;
  throw record_error(
      file, channel,
      std::string(where) + ": unknown unit \"" + text + "\"; allowed " + known_units());
}

struct Settled {
  RecordUnit unit;
  RecordSource source;
  std::string origin;
};

Settled settle_unit(const RawChannel& raw, const RecordOptions& options, const std::string& file) {
  if (options.unit.empty()) {
    if (!raw.unit)
      throw record_error(
          file, raw.channel,
          "no unit: the file does not state one; give --unit (" + known_units() + ")");
    return {parse_unit(*raw.unit, file, raw.channel, raw.unit_origin), RecordSource::file,
            raw.unit_origin};
  }
  const RecordUnit given = parse_unit(options.unit, file, raw.channel, "--unit");
  if (raw.unit) {
    const RecordUnit stated = parse_unit(*raw.unit, file, raw.channel, raw.unit_origin);
    if (stated != given)
      throw record_error(file, raw.channel,
                         "--unit " + options.unit + " contradicts the file's unit " + *raw.unit +
                             " (" + raw.unit_origin + ")");
  }
  return {given, RecordSource::option, ""};
}

void check_rate(double rate, const std::string& file, const std::string& channel,
                std::string_view what) {
  if (!(std::isfinite(rate) && rate > 0))
    throw record_error(
        file, channel,
        std::string(what) + " " + format_number(rate) + " Hz: must be a finite rate > 0 Hz");
}

}  // namespace

InputError record_error(const std::string& file, std::string_view channel, std::string_view what) {
  std::string message = file + ": ";
  if (!channel.empty()) message += "channel " + std::string(channel) + ": ";
  return InputError(one_line(message + std::string(what)));
}

MeasuredRecord finish_record(RawChannel raw, const RecordOptions& options,
                             const std::string& file) {
  MeasuredRecord r;
  r.file = file;
  r.channel = raw.channel;
  if (raw.values.empty()) throw record_error(file, raw.channel, "no samples");
  if (!(std::isfinite(options.scale) && options.scale != 0))
    throw record_error(file, raw.channel,
                       "--scale " + format_number(options.scale) + ": must be finite and nonzero");

  // The rate: the option's, checked against the file's; else the file's.
  if (options.rate) check_rate(*options.rate, file, raw.channel, "--rate");
  if (raw.rate) check_rate(*raw.rate, file, raw.channel, "the rate of " + raw.rate_origin);
  if (options.rate && raw.rate &&
      !(std::abs(*options.rate - *raw.rate) <= raw.rate_tolerance * *raw.rate))
    throw record_error(file, raw.channel,
                       "--rate " + format_number(*options.rate) + " Hz contradicts the rate " +
                           format_number(*raw.rate) + " Hz of " + raw.rate_origin);
  if (options.rate) {
    r.rate = *options.rate;
    r.rate_source = RecordSource::option;
  } else if (raw.rate) {
    r.rate = *raw.rate;
    r.rate_source = RecordSource::file;
    r.rate_origin = raw.rate_origin;
  } else {
    throw record_error(file, raw.channel,
                       "no sampling rate: the file does not state one; give --rate in Hz");
  }

  const Settled unit = settle_unit(raw, options, file);
  r.unit = unit.unit;
  r.unit_source = unit.source;
  r.unit_origin = unit.origin;
  r.quantity = quantity_of(unit.unit);
  r.scale = options.scale;

  // To SI once: stored × scale × the unit's factor, each sample checked before and after.
  const double factor = si_factor(unit.unit);
  r.samples = std::move(raw.values);
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    const double stored = r.samples[i];
    if (!std::isfinite(stored))
      throw record_error(file, raw.channel,
                         "sample " + std::to_string(i) + " (from 0) is " +
                             (std::isnan(stored) ? "NaN"
                              : stored > 0       ? "+Inf"
                                                 : "-Inf"));
    r.samples[i] = stored * options.scale * factor;
    if (!std::isfinite(r.samples[i]))
      throw record_error(file, raw.channel,
                         "sample " + std::to_string(i) + " (from 0) = " + format_number(stored) +
                             " overflows in SI (" + std::string(si_unit_of(r.quantity)) + ")");
  }
  r.shaft_speed = raw.shaft_speed;
  r.shaft_speed_origin = raw.shaft_speed ? raw.shaft_speed_origin : "";
  return r;
}

}  // namespace bearing
