#pragma once
// A guard for a hang of HDF5 1.10 (Debian 12's 1.10.8), found by fuzzing: reading
// variable-length data (h5py's string attributes) loads the file's global heap collections, and
// the loader walks a collection's objects by their sizes; a free-space object (index 0) of size 0
// does not advance it, and it loops forever; an object whose size runs past its collection is
// later copied past it (a crash, also found). Before the reader reads such data, it walks each
// collection ("GCOL") of the file the same way and refuses one with such an object.

#include <cstdint>
#include <filesystem>
#include <string>

namespace bearing::records_detail {

/// InputError naming `file` when a global heap collection in it has an object that would stall
/// HDF5's loader (it does not advance the walk, or its size wraps the address space) or that runs
/// past the collection's end. Reads the
/// file once in blocks; a "GCOL" that is data, not a collection, is walked too, and passes
/// unless it has exactly that shape.
void check_global_heaps(const std::filesystem::path& path, std::uintmax_t file_size,
                        const std::string& file);

}  // namespace bearing::records_detail
