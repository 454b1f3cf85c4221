// Fuzz target: the WAV record reader (read_wav_record, libsndfile). The library takes a path, so
// the input is written to a temporary file first (fuzz_record.h). Reads with the default channel
// and with channel "1", then checks what finish_record promises.

#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "bearing/records/wav_record.h"
#include "fuzz_record.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = bearing::fuzz::input_file(data, size, ".wav");
  bearing::fuzz::read_both_ways("fuzz_record_wav", "1", [&](const bearing::RecordOptions& o) {
    return bearing::read_wav_record(file, o);
  });
  std::filesystem::remove(file);
  return 0;
}
