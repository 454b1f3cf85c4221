// Fuzz target: the .npy record reader (parse_npy_record: the file's bytes). Reads with the
// default channel and with column "1", then checks what finish_record promises (fuzz_record.h).

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "bearing/records/npy_record.h"
#include "fuzz_record.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  bearing::fuzz::read_both_ways("fuzz_record_npy", "1", [&](const bearing::RecordOptions& o) {
    return bearing::parse_npy_record(bytes, "fuzz.npy", o);
  });
  return 0;
}
