#pragma once
// A corrupt file can claim any size in its header; the libraries that read it allocate what it
// claims. Before asking for the data, the readers check the claim against what the file could
// hold: zlib (MAT 7, HDF5 deflate) expands at most 1032 to 1, so more than 1032 × the file's
// size (plus a little) is a corrupt header, refused before any allocation.

#include <cstddef>
#include <cstdint>
#include <string>

#include "bearing/records/raw_channel.h"

namespace bearing::records_detail {

/// InputError naming `file` and `channel` when `count` elements of `size` bytes cannot come from
/// a file of `file_size` bytes.
inline void check_claimed_size(std::size_t count, std::size_t size, std::uintmax_t file_size,
                               const std::string& file, const std::string& channel) {
  constexpr std::uintmax_t kMaxExpansion = 1032;  // zlib's largest ratio
  constexpr std::uintmax_t kSlack = 1 << 20;      // fill values, tiny files
  const std::uintmax_t limit = kMaxExpansion * file_size + kSlack;
  if (size != 0 && count > limit / size)
    throw record_error(file, channel,
                       "the header claims " + std::to_string(count) + " values of " +
                           std::to_string(size) + " bytes, more than a file of " +
                           std::to_string(file_size) + " bytes can hold (corrupt file?)");
}

}  // namespace bearing::records_detail
