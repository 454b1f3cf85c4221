#pragma once
// WAV records through libsndfile (built when libsndfile1-dev is found): channels "0", "1", ...;
// the header's rate. Integer PCM is read as libsndfile normalises it, code / 2^(bits−1) (8-bit:
// (code − 128) / 128), so full scale is ±1 and RecordOptions::unit is the unit of full scale
// (RecordOptions::scale the full scale in it); float WAV values are read as stored.

#include <filesystem>

#include "bearing/records/raw_channel.h"
#include "bearing/records/record_options.h"

namespace bearing {

/// The channel `options` pick from the WAV file. InputError naming the file when libsndfile
/// cannot open it (its reason) or a read fails.
RawChannel read_wav_record(const std::filesystem::path& file, const RecordOptions& options);

}  // namespace bearing
