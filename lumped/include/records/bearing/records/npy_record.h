#pragma once
// NumPy .npy records (numpy.lib.format versions 1.0, 2.0 and 3.0): a 1-D array of float32 or
// float64 (either byte order) is one channel "0"; a 2-D array (n, k) is k channels "0" ... "k-1",
// its columns (C or Fortran order); (n, 1) and (1, n) are one channel. A .npy states neither rate
// nor unit: RecordOptions give both.

#include <filesystem>
#include <string>
#include <string_view>

#include "bearing/records/raw_channel.h"
#include "bearing/records/record_options.h"

namespace bearing {

/// The channel `options` pick from the .npy bytes `bytes`; `file` names it in messages.
/// InputError naming the file for a bad magic or header, a dtype other than float32/float64, a
/// shape of another rank, or data shorter or longer than the shape says.
RawChannel parse_npy_record(std::string_view bytes, const std::string& file,
                            const RecordOptions& options);

/// parse_npy_record of the file's bytes (InputError when it cannot be read).
RawChannel read_npy_record(const std::filesystem::path& file, const RecordOptions& options);

}  // namespace bearing
