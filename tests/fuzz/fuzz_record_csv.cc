// Fuzz target: the CSV record reader (parse_csv_record: the file's bytes as text). Reads with the
// default channel and with "DE", then checks what finish_record promises (fuzz_record.h).

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "bearing/records/csv_record.h"
#include "fuzz_record.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  bearing::fuzz::read_both_ways("fuzz_record_csv", "DE", [&](const bearing::RecordOptions& o) {
    return bearing::parse_csv_record(text, "fuzz.csv", o);
  });
  return 0;
}
