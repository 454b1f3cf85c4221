#include "bearing/records/record_formats.h"

#include <algorithm>
#include <cctype>

#include "bearing/records/channel_choice.h"
#include "bearing/records/csv_record.h"
#include "bearing/records/npy_record.h"
#ifdef BEARING_RECORDS_WITH_SNDFILE
#include "bearing/records/wav_record.h"
#endif

namespace bearing {

namespace {

// What a program without bearing_records_hdf5's rows is told about .mat and .h5: whether this
// build has the library (the program did not merge its rows) or not (a package was missing).
#ifdef BEARING_RECORDS_HDF5_BUILT
#define BEARING_HDF5_MISSING(ext)                   \
  "this program does not read " ext                 \
  " (its reader is in bearing_records_hdf5: merge " \
  "hdf5_record_formats() into the formats)"
#else
#define BEARING_HDF5_MISSING(ext) \
  "this build cannot read " ext ": neither libmatio-dev nor libhdf5-dev was found at build time"
#endif

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::vector<RecordFormat> base_record_formats() {
  std::vector<RecordFormat> rows{
      {".csv", "CSV text: a header naming the columns, a time column [s] or --rate",
       read_csv_record, "", false},
      {".npy", "NumPy array: 1-D float32/float64, or 2-D with a channel per column",
       read_npy_record, "", false},
#ifdef BEARING_RECORDS_WITH_SNDFILE
      {".wav", "WAV (libsndfile): integer PCM as fractions of full scale, float as stored",
       read_wav_record, "", false},
#else
      {".wav", "WAV (libsndfile)", nullptr,
       "this build cannot read .wav: libsndfile1-dev was not found at build time", false},
#endif
      {".mat", "MATLAB 5, 7 and 7.3 (libmatio)", nullptr, BEARING_HDF5_MISSING(".mat"), false},
      {".h5", "HDF5 (--dataset)", nullptr, BEARING_HDF5_MISSING(".h5"), true},
      {".hdf5", "HDF5 (--dataset)", nullptr, BEARING_HDF5_MISSING(".hdf5"), true},
  };
  return rows;
}

std::vector<RecordFormat> with_formats(std::vector<RecordFormat> base,
                                       const std::vector<RecordFormat>& extra) {
  for (const RecordFormat& row : extra) {
    const auto same = std::find_if(base.begin(), base.end(), [&](const RecordFormat& b) {
      return b.extension == row.extension;
    });
    if (same != base.end())
      *same = row;
    else
      base.push_back(row);
  }
  return base;
}

MeasuredRecord read_record(const std::filesystem::path& file, const RecordOptions& options,
                           const std::vector<RecordFormat>& formats) {
  const std::string name = file.string();
  const std::string extension = lower(file.extension().string());
  const auto row = std::find_if(formats.begin(), formats.end(),
                                [&](const RecordFormat& f) { return f.extension == extension; });
  if (row == formats.end()) {
    std::vector<std::string> known;
    for (const RecordFormat& f : formats) known.emplace_back(f.extension);
    throw record_error(
        name, "", "unsupported extension \"" + extension + "\"; supported: " + join_names(known));
  }
  if (!row->read) throw record_error(name, "", row->unavailable);
  if (!options.dataset.empty() && !row->takes_dataset)
    throw record_error(
        name, "", "--dataset " + options.dataset + " applies to HDF5 files only, not " + extension);
  return finish_record(row->read(file, options), options, name);
}

}  // namespace bearing
