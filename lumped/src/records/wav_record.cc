#include "bearing/records/wav_record.h"

#include <sndfile.h>

#include <memory>
#include <vector>

#include "bearing/records/channel_choice.h"

namespace bearing {

namespace {

struct CloseSndfile {
  void operator()(SNDFILE* f) const { sf_close(f); }
};

}  // namespace

RawChannel read_wav_record(const std::filesystem::path& file, const RecordOptions& options) {
  const std::string name = file.string();
  SF_INFO info{};
  std::unique_ptr<SNDFILE, CloseSndfile> sf(sf_open(name.c_str(), SFM_READ, &info));
  if (!sf)
    throw record_error(name, "", std::string("libsndfile cannot read it: ") + sf_strerror(nullptr));
  if (info.channels < 1) throw record_error(name, "", "the header states no channel");

  std::vector<std::string> names;
  for (int k = 0; k < info.channels; ++k) names.push_back(std::to_string(k));
  const std::size_t column = choose_channel(names, options, name, "channel");

  // Integer PCM: libsndfile's normalisation (code / 2^(bits-1)), so full scale is ±1; float data
  // as stored. Both are libsndfile's defaults, set here so that they cannot change under us.
  sf_command(sf.get(), SFC_SET_NORM_DOUBLE, nullptr, SF_TRUE);
  sf_command(sf.get(), SFC_SET_SCALE_FLOAT_INT_READ, nullptr, SF_FALSE);

  RawChannel raw;
  raw.channel = names[column];
  raw.rate = static_cast<double>(info.samplerate);
  raw.rate_origin = "the WAV header";
  // Blocks until the end: the header's frame count is not trusted for the allocation.
  const std::size_t channels = static_cast<std::size_t>(info.channels);
  constexpr sf_count_t kFrames = 4096;
  std::vector<double> block(static_cast<std::size_t>(kFrames) * channels);
  while (true) {
    const sf_count_t got = sf_readf_double(sf.get(), block.data(), kFrames);
    if (got <= 0) break;
    for (sf_count_t f = 0; f < got; ++f)
      raw.values.push_back(block[static_cast<std::size_t>(f) * channels + column]);
  }
  if (sf_error(sf.get()) != SF_ERR_NO_ERROR)
    throw record_error(name, raw.channel, std::string("libsndfile: ") + sf_strerror(sf.get()));
  return raw;
}

}  // namespace bearing
