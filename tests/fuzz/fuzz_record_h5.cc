// Fuzz target: the HDF5 record reader (read_h5_record, the HDF5 C API). The library takes a path,
// so the input is written to a temporary file first (fuzz_record.h). Reads with the default channel
// and with column "ay", then checks what finish_record promises.

#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "bearing/records/h5_record.h"
#include "fuzz_record.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = bearing::fuzz::input_file(data, size, ".h5");
  bearing::fuzz::read_both_ways("fuzz_record_h5", "ay", [&](const bearing::RecordOptions& o) {
    return bearing::read_h5_record(file, o);
  });
  std::filesystem::remove(file);
  return 0;
}
