#pragma once
// What matio does not check in a MATLAB 5 (and 7) file: matio reads a file cut short without a
// word, the missing data as zeros, and a compressed variable whose zlib stream is corrupt as
// whatever inflates (it ignores zlib's checksum). The file's top level is a 128-byte header and a
// sequence of data elements, each a tag (type, byte count: 4 + 4 bytes) and its bytes (a matrix,
// miMATRIX, padded to 8; a compressed one, miCOMPRESSED, a zlib stream). MATLAB 7.3 files are
// HDF5, which checks its own end and checksums.

#include <cstdint>
#include <filesystem>
#include <string>

namespace bearing::records_detail {

/// InputError naming `file` when a top-level variable of a MATLAB 5 file runs past its end, its
/// array flags, dimensions or name claim more bytes than the variable has (matio would allocate
/// what they claim), or a compressed one does not inflate to the end of its stream with a correct
/// checksum (built with zlib; without it compressed variables are only checked for their extent).
/// Other files (7.3, not a MAT-file) pass: matio judges them.
void check_mat5_elements(const std::filesystem::path& path, std::uintmax_t file_size,
                         const std::string& file);

}  // namespace bearing::records_detail
