#pragma once
// The record formats whose readers load large libraries (bearing_records_full, built when
// libsndfile1-dev, libmatio-dev or libhdf5-dev is found): .wav through libsndfile (which loads
// its FLAC, Vorbis, Opus, Ogg, MPEG and LAME codecs), .mat through libmatio (which reads MATLAB
// 7.3 files through HDF5) and .h5/.hdf5 through the HDF5 C API. Kept apart from bearing_records
// so that a program that reads no such file loads none of them (issue 31): merge these rows in
// with with_formats().

#include <vector>

#include "bearing/records/record_formats.h"

namespace bearing {

/// The rows .wav, .mat, .h5 and .hdf5; a row whose library was not found at build time has no
/// reader and says so ("this build cannot read .mat: libmatio-dev was not found at build time").
std::vector<RecordFormat> full_record_formats();

}  // namespace bearing
