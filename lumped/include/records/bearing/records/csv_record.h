#pragma once
// CSV records: one column per channel, named by a header line; a time column "t" or "time"
// (optionally "[s]") gives the rate, else RecordOptions::rate must. A header cell "DE [g]" states
// the column's unit. Without a header (a first line of numbers, as numpy.savetxt writes by
// default) the columns are "0", "1", ... and there is no time column.
//
// Details: the delimiter is the first of ',', ';', tab found in the first line, else runs of
// spaces; a UTF-8 byte-order mark, '\r' line ends, blank lines and lines starting with '#' are
// skipped, except that a '#' line right before the first data line is the header when no other
// line is and it has as many fields as the data (numpy.savetxt's "# t,DE"); fields may be quoted
// with '"'. Numbers as C writes them ("1.5e-3", no thousands separators); every row has the
// header's number of fields.

#include <filesystem>
#include <string>
#include <string_view>

#include "bearing/records/raw_channel.h"
#include "bearing/records/record_options.h"

namespace bearing {

/// The channel `options` pick from the CSV text `text` (the file's bytes); `file` names it in
/// messages. InputError naming the file, the channel, the line and the column for a field that is
/// not a finite number, a row of another length, a time column that is not uniform.
RawChannel parse_csv_record(std::string_view text, const std::string& file,
                            const RecordOptions& options);

/// parse_csv_record of the file's bytes (InputError when it cannot be read).
RawChannel read_csv_record(const std::filesystem::path& file, const RecordOptions& options);

}  // namespace bearing
