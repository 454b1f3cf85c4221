// Fuzz target: the MAT-file record reader (read_mat_record, libmatio; MATLAB 5, 7 and 7.3). The
// library takes a path, so the input is written to a temporary file first (fuzz_record.h). Reads
// with the default channel and with variable "acc", then checks what finish_record promises.

#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "bearing/records/mat_record.h"
#include "fuzz_record.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = bearing::fuzz::input_file(data, size, ".mat");
  bearing::fuzz::read_both_ways("fuzz_record_mat", "acc", [&](const bearing::RecordOptions& o) {
    return bearing::read_mat_record(file, o);
  });
  std::filesystem::remove(file);
  return 0;
}
