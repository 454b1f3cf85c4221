#include "mat5_elements.h"

#include <fstream>
#include <vector>

#ifdef BEARING_RECORDS_WITH_ZLIB
#include <zlib.h>
#endif

#include "bearing/records/raw_channel.h"

namespace bearing::records_detail {

namespace {

constexpr std::uint32_t kMatrix = 14, kCompressed = 15;  // miMATRIX, miCOMPRESSED
constexpr std::size_t kHeaderBytes = 64 * 1024;  // of a matrix's start kept for its header check

std::uint32_t u32(const unsigned char* b, bool big) {
  const std::uint32_t v0 = b[0], v1 = b[1], v2 = b[2], v3 = b[3];
  return big ? (v0 << 24 | v1 << 16 | v2 << 8 | v3) : (v3 << 24 | v2 << 16 | v1 << 8 | v0);
}

// matio allocates what a matrix's first sub-elements claim before it reads anything else: it
// reads the array flags as a tag and 8 bytes, whatever their tag says, then the dimensions and
// the name, each a tag and the bytes it claims. So these must be as the format defines them:
// flags of 8 bytes; dimensions miINT32 (5), a multiple of 4 bytes, at least 2 of them; a name;
// a small element (its data in the tag) of at most 4 bytes; each inside the matrix's `bytes`.
// `content` holds the matrix's first `have` bytes after its tag. Returns what is wrong, or "".
std::string matrix_header_error(const unsigned char* content, std::size_t have, std::uint64_t bytes,
                                bool big) {
  constexpr std::uint32_t kInt32 = 5;
  if (bytes < 16) return "its header ends before its array flags";
  if (have < 16) return "";
  if ((u32(content, big) >> 16) == 0 && u32(content + 4, big) != 8)
    return "its array flags claim " + std::to_string(u32(content + 4, big)) + " bytes, not 8";
  std::uint64_t at = 16;
  for (const std::string what : {"dimensions", "name"}) {
    if (at + 8 > bytes) return "its header ends before its " + what;
    if (at + 8 > have) return "";
    const std::uint32_t tag = u32(content + at, big);
    const bool small = (tag >> 16) != 0;
    const std::uint32_t type = small ? tag & 0xffff : tag;
    const std::uint64_t n = small ? tag >> 16 : u32(content + at + 4, big);
    if (small && n > 4) return "its " + what + " claim " + std::to_string(n) + " bytes in a tag";
    if (n > bytes - at - 8)
      return "its " + what + " claim " + std::to_string(n) + " bytes of its " +
             std::to_string(bytes);
    if (what == "dimensions" && (type != kInt32 || n % 4 != 0 || n < 8))
      return "its dimensions are not 2 or more 32-bit integers (type " + std::to_string(type) +
             ", " + std::to_string(n) + " bytes)";
    at += small ? 8 : 8 + n + (8 - n % 8) % 8;
  }
  return "";
}

#ifdef BEARING_RECORDS_WITH_ZLIB
// Inflates `bytes` bytes at the stream's position, keeping the first kHeaderBytes of the result
// in `start` and counting all in `total`: zlib's message if the stream is corrupt or ends early,
// "" if it ends with a correct checksum.
std::string inflate_error(std::ifstream& in, std::uint32_t bytes, std::vector<unsigned char>& start,
                          std::uint64_t& total) {
  z_stream z{};
  if (inflateInit(&z) != Z_OK) return "zlib cannot start";
  std::vector<unsigned char> input(64 * 1024), output(256 * 1024);
  std::uint32_t left = bytes;
  int status = Z_OK;
  while (status == Z_OK) {
    if (z.avail_in == 0) {
      if (left == 0) break;
      const std::uint32_t chunk = std::min<std::uint32_t>(left, input.size());
      if (!in.read(reinterpret_cast<char*>(input.data()), chunk)) break;
      left -= chunk;
      z.next_in = input.data();
      z.avail_in = chunk;
    }
    z.next_out = output.data();
    z.avail_out = static_cast<uInt>(output.size());
    status = inflate(&z, Z_NO_FLUSH);
    if (status == Z_BUF_ERROR && z.avail_in == 0) status = Z_OK;  // needs more input
    const std::size_t produced = output.size() - z.avail_out;
    const std::size_t keep =
        std::min(produced, kHeaderBytes - std::min(kHeaderBytes, start.size()));
    start.insert(start.end(), output.begin(), output.begin() + static_cast<std::ptrdiff_t>(keep));
    total += produced;
  }
  std::string error;
  if (status != Z_STREAM_END)
    error = z.msg ? z.msg : status == Z_OK ? "the stream ends early" : "inflate failed";
  inflateEnd(&z);
  return error;
}
#endif

}  // namespace

void check_mat5_elements(const std::filesystem::path& path, std::uintmax_t file_size,
                         const std::string& file) {
  std::ifstream in(path, std::ios::binary);
  unsigned char header[128];
  if (!in.read(reinterpret_cast<char*>(header), sizeof header)) return;
  const bool big = header[126] == 'M' && header[127] == 'I';
  const unsigned version =
      big ? (header[124] << 8 | header[125]) : (header[125] << 8 | header[124]);
  if (version != 0x0100) return;
  std::uintmax_t at = 128;
  while (at + 8 <= file_size) {
    unsigned char tag[8];
    in.seekg(static_cast<std::streamoff>(at));
    if (!in.read(reinterpret_cast<char*>(tag), sizeof tag)) return;
    const std::uint32_t type = u32(tag, big), bytes = u32(tag + 4, big);
    if ((type >> 16) != 0) {  // a small data element: its bytes are inside the tag
      at += 8;
      continue;
    }
    if (type != kMatrix && type != kCompressed) return;  // not a variable: matio judges it
    const std::uintmax_t end = at + 8 + bytes + (type == kMatrix ? (8 - bytes % 8) % 8 : 0);
    if (end > file_size)
      throw record_error(file, "",
                         "truncated: the variable at byte " + std::to_string(at) + " claims " +
                             std::to_string(bytes) + " bytes, " + std::to_string(end - file_size) +
                             " more than the file has");
    const std::string where = "corrupt: the variable at byte " + std::to_string(at) + ": ";
    if (type == kMatrix) {
      std::vector<unsigned char> start(std::min<std::size_t>(bytes, kHeaderBytes));
      if (!in.read(reinterpret_cast<char*>(start.data()),
                   static_cast<std::streamsize>(start.size())))
        return;
      if (const std::string e = matrix_header_error(start.data(), start.size(), bytes, big);
          !e.empty())
        throw record_error(file, "", where + e);
    }
#ifdef BEARING_RECORDS_WITH_ZLIB
    if (type == kCompressed) {
      std::vector<unsigned char> start;
      std::uint64_t total = 0;
      if (const std::string error = inflate_error(in, bytes, start, total); !error.empty())
        throw record_error(file, "", where + "it does not inflate (zlib: " + error + ")");
      // Inside: one matrix element, whose header must fit as in an uncompressed file.
      if (start.size() >= 8 && u32(start.data(), big) == kMatrix) {
        const std::uint64_t inner = u32(start.data() + 4, big);
        const std::string e =
            inner > total - 8 ? "its matrix claims more than it inflates to"
                              : matrix_header_error(start.data() + 8, start.size() - 8, inner, big);
        if (!e.empty()) throw record_error(file, "", where + e);
      }
    }
#endif
    at = end;
  }
}

}  // namespace bearing::records_detail
