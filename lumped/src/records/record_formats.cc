#include "bearing/records/record_formats.h"

#include <algorithm>
#include <cctype>

#include "bearing/records/channel_choice.h"
#include "bearing/records/csv_record.h"
#include "bearing/records/npy_record.h"

namespace bearing {

namespace {

// What a program without bearing_records_full's rows is told about .wav, .mat and .h5: that
// the library reads it (the program did not merge its rows; BEARING_RECORDS_FULL_<format>) or
// which package was missing at build time.
#define BEARING_IN_FULL(ext)                        \
  "this program does not read " ext                 \
  " (its reader is in bearing_records_full: merge " \
  "full_record_formats() into the formats)"
#ifdef BEARING_RECORDS_FULL_WAV
#define BEARING_WAV_MISSING BEARING_IN_FULL(".wav")
#else
#define BEARING_WAV_MISSING \
  "this build cannot read .wav: libsndfile1-dev was not found at build time"
#endif
#ifdef BEARING_RECORDS_FULL_MAT
#define BEARING_MAT_MISSING BEARING_IN_FULL(".mat")
#else
#define BEARING_MAT_MISSING "this build cannot read .mat: libmatio-dev was not found at build time"
#endif
#ifdef BEARING_RECORDS_FULL_H5
#define BEARING_H5_MISSING(ext) BEARING_IN_FULL(ext)
#else
#define BEARING_H5_MISSING(ext) \
  "this build cannot read " ext ": libhdf5-dev was not found at build time"
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
      {".wav", "WAV (libsndfile)", nullptr, BEARING_WAV_MISSING, false},
      {".mat", "MATLAB 5, 7 and 7.3 (libmatio)", nullptr, BEARING_MAT_MISSING, false},
      {".h5", "HDF5 (--dataset)", nullptr, BEARING_H5_MISSING(".h5"), true},
      {".hdf5", "HDF5 (--dataset)", nullptr, BEARING_H5_MISSING(".hdf5"), true},
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
