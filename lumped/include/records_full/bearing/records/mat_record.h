#pragma once
// MATLAB .mat records through libmatio (versions 5, 7 and 7.3; 7.3 is HDF5 underneath). Channels
// are the numeric real vectors (n×1 or 1×n, n ≥ 2; double, single or integer); scalars, matrices,
// text, cells and structs are not. A scalar whose name ends in "RPM" (a CWRU file's XNNNRPM) is
// the shaft speed in rpm: the only such scalar, or the one whose name before "RPM" begins the
// channel's name (X130RPM for X130_DE_time); one that is not finite and > 0 is ignored.
// A .mat states neither rate nor unit: RecordOptions give both.

#include <filesystem>

#include "bearing/records/raw_channel.h"
#include "bearing/records/record_options.h"

namespace bearing {

/// The variable `options` pick from the MAT-file. InputError naming the file when matio cannot
/// open it, the variable is not a channel (saying what it is), its data cannot be read, or it
/// claims more data than the file could hold.
RawChannel read_mat_record(const std::filesystem::path& file, const RecordOptions& options);

}  // namespace bearing
