#pragma once
// What the fuzz targets of the measured-record readers share (lumped/include/records/): the
// readers of files (WAV, MAT, HDF5: their libraries take a path) get the input through a
// temporary file; every target then checks what finish_record promises of whatever the reader
// accepted.

#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "bearing/records/raw_channel.h"
#include "fuzz_harness.h"

namespace bearing::fuzz {

/// The input as a file of this process (one per process and extension, rewritten for each input,
/// in TMPDIR or /tmp), so that libraries that open a path see exactly the bytes.
inline std::filesystem::path input_file(const std::uint8_t* data, std::size_t size,
                                        const char* extension) {
  const char* dir = std::getenv("TMPDIR");
  const std::filesystem::path path = std::filesystem::path(dir && *dir ? dir : "/tmp") /
                                     ("bearing-fuzz-" + std::to_string(::getpid()) + extension);
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f || (size > 0 && std::fwrite(data, 1, size, f) != size) || std::fclose(f) != 0) {
    std::perror(path.c_str());
    std::abort();  // the harness cannot work, which is no finding of the reader
  }
  return path;
}

/// finish_record on what a reader accepted, with the options the file lacks given: either an
/// InputError (no samples, NaN, a rate or unit the file states that is out of range or unknown)
/// or a record as documented: samples as many as the values, all finite; rate finite > 0.
inline void check_finished(const char* target, const RawChannel& raw) {
  RecordOptions o;
  if (!raw.rate) o.rate = 1000;
  if (!raw.unit) o.unit = "g";
  expect_only_input_errors(target, [&] {
    const MeasuredRecord r = finish_record(raw, o, "fuzz");
    if (r.samples.size() != raw.values.size() || r.samples.empty())
      property_failed(target, "finish_record changed the number of samples or kept none");
    for (const double v : r.samples)
      if (!std::isfinite(v)) property_failed(target, "a record with a non-finite sample");
    if (!(std::isfinite(r.rate) && r.rate > 0))
      property_failed(target, "a record whose rate is not finite and > 0");
    if (r.shaft_speed && !(std::isfinite(*r.shaft_speed) && *r.shaft_speed > 0))
      property_failed(target, "a shaft speed that is not finite and > 0");
  });
}

/// Reads with the channel chosen by default and by `channel` (one the seeds use), checking each
/// result: `read(options)` returns the RawChannel.
template <class Read>
void read_both_ways(const char* target, const char* channel, Read&& read) {
  for (const char* c : {"", channel}) {
    RecordOptions o;
    o.channel = c;
    expect_only_input_errors(target, [&] { check_finished(target, read(o)); });
  }
}

}  // namespace bearing::fuzz
