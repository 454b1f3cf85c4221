#include "h5_global_heaps.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <vector>

#include "bearing/records/raw_channel.h"

namespace bearing::records_detail {

namespace {

std::uint64_t little_endian(const unsigned char* b, std::size_t bytes) {
  std::uint64_t v = 0;
  for (std::size_t k = 0; k < bytes; ++k) v |= std::uint64_t{b[k]} << (8 * k);
  return v;
}

// Walks the collection at `at` as H5HG__cache_heap_deserialize does (lengths of 8 bytes, the
// usual size of lengths): header "GCOL", version 1, 3 reserved, the collection's size; then
// objects of index (2), references (2), reserved (4), size (8), data padded to 8 (index 0, the
// free space, counts its header in its size). Returns the byte of an object that does not
// advance the walk or runs past the collection's end, or 0.
std::uintmax_t stalled_object(std::ifstream& in, std::uintmax_t at, std::uintmax_t file_size) {
  unsigned char header[16];
  in.clear();
  in.seekg(static_cast<std::streamoff>(at));
  if (!in.read(reinterpret_cast<char*>(header), sizeof header) || header[4] != 1) return 0;
  const std::uint64_t size = little_endian(header + 8, 8);
  const std::uintmax_t end = at + std::min<std::uint64_t>(size, file_size - at);
  std::uintmax_t p = at + 16;
  while (p + 16 <= end) {
    unsigned char object[16];
    in.seekg(static_cast<std::streamoff>(p));
    if (!in.read(reinterpret_cast<char*>(object), sizeof object)) return 0;
    const std::uint64_t index = little_endian(object, 2);
    const std::uint64_t bytes = little_endian(object + 8, 8);
    const std::uint64_t need = index > 0 ? 16 + ((bytes + 7) & ~std::uint64_t{7}) : bytes;
    // An object that does not advance the walk stalls it; one that runs past the collection's
    // end is read past it later (H5HG_read copies the object's size).
    if (need == 0 || (index > 0 && bytes > (std::uint64_t{1} << 62)) || need > end - p) return p;
    p += need;
  }
  return 0;
}

}  // namespace

void check_global_heaps(const std::filesystem::path& path, std::uintmax_t file_size,
                        const std::string& file) {
  std::ifstream in(path, std::ios::binary);
  std::ifstream walker(path, std::ios::binary);
  constexpr std::size_t kBlock = 1 << 20;
  std::vector<char> block(kBlock + 3);
  std::size_t kept = 0;       // bytes of the previous block's end, for a signature across blocks
  std::uintmax_t offset = 0;  // file offset of block[0]
  while (in) {
    in.read(block.data() + kept, static_cast<std::streamsize>(kBlock));
    const std::size_t have = kept + static_cast<std::size_t>(in.gcount());
    if (have < 4) break;
    for (std::size_t i = 0; i + 4 <= have; ++i) {
      if (std::memcmp(block.data() + i, "GCOL", 4) != 0) continue;
      if (const std::uintmax_t bad = stalled_object(walker, offset + i, file_size))
        throw record_error(file, "",
                           "corrupt: the global heap at byte " + std::to_string(offset + i) +
                               " has an object at byte " + std::to_string(bad) +
                               " that HDF5 would read forever or past the heap's end");
    }
    std::memmove(block.data(), block.data() + have - 3, 3);
    offset += have - 3;
    kept = 3;
  }
}

}  // namespace bearing::records_detail
