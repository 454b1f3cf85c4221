#pragma once
// The record formats that need HDF5 (bearing_records_hdf5, built when libmatio-dev or
// libhdf5-dev is found): .mat through libmatio (which reads MATLAB 7.3 files through HDF5) and
// .h5/.hdf5 through the HDF5 C API. Kept apart from bearing_records so that a program that reads
// no such file does not load HDF5 (issue 31): merge these rows in with with_formats().

#include <vector>

#include "bearing/records/record_formats.h"

namespace bearing {

/// The rows .mat, .h5 and .hdf5; a row whose library was not found at build time has no reader
/// and says so ("this build cannot read .mat: libmatio-dev was not found at build time").
std::vector<RecordFormat> hdf5_record_formats();

}  // namespace bearing
