#pragma once
// HDF5 records through the HDF5 C API. RecordOptions::dataset names the dataset (default: the
// file's only numeric dataset of rank 1 or 2). A rank-1 dataset, or a rank-2 one of one column,
// is one channel named by its path; a rank-2 dataset (n, k) is k channels, its columns, named by
// a string-array attribute "columns" if it has one (as bearing-sim's sweep.h5 writes) or "0",
// "1", .... A column named "t" or "time" is the time column (time_column.h).
//
// Attributes of the dataset read: the rate [Hz] from the first of "rate", "sample_rate",
// "sampling_rate", "fs" (a finite number > 0); the unit from "unit" (a string; one channel) or
// "units" (a string array, one per column).

#include <filesystem>

#include "bearing/records/raw_channel.h"
#include "bearing/records/record_options.h"

namespace bearing {

/// The channel `options` pick from the HDF5 file. InputError naming the file when HDF5 cannot
/// open it, the dataset is missing or not numeric, an attribute is unreadable or out of range,
/// or the dataset claims more data than the file could hold.
RawChannel read_h5_record(const std::filesystem::path& file, const RecordOptions& options);

}  // namespace bearing
