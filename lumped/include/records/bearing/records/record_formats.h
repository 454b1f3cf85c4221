#pragma once
// The formats a measured record is read from: one row per file extension, with its reader. The
// readers that load large libraries (libsndfile and its codecs, matio, HDF5) live in the optional
// library bearing_records_full (full_record_formats.h), so a program that reads no such file loads
// none of them; this library's rows for .wav, .mat and .h5 say how to get them. read_record()
// picks the row by extension, runs its reader and finish_record().
//
// A program that reads records:
//   std::vector<RecordFormat> formats = base_record_formats();
//   formats = with_formats(formats, full_record_formats());   // if it links bearing_records_full
//   MeasuredRecord r = read_record("130.mat", options, formats);

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "bearing/records/measured_record.h"
#include "bearing/records/raw_channel.h"
#include "bearing/records/record_options.h"

namespace bearing {

/// Reads the channel `options` pick from `file` (InputError naming the file when it cannot).
using RecordReader = RawChannel (*)(const std::filesystem::path& file,
                                    const RecordOptions& options);

struct RecordFormat {
  std::string_view extension;    ///< with the dot, lower case: ".csv" (matched in any case)
  std::string_view description;  ///< "CSV text (a time column [s] or --rate)", for --help
  RecordReader read = nullptr;   ///< nullptr: this build cannot read the format
  std::string_view unavailable;  ///< why not, when `read` is nullptr (a whole sentence)
  bool takes_dataset = false;    ///< RecordOptions::dataset applies (.h5)
};

/// The rows of this library: .csv and .npy with their readers, and .wav, .mat, .h5, .hdf5 as rows
/// without a reader, saying which library reads them or which package was missing at build time.
std::vector<RecordFormat> base_record_formats();

/// `base` with each row of `extra` in place of the row of the same extension (or appended).
std::vector<RecordFormat> with_formats(std::vector<RecordFormat> base,
                                       const std::vector<RecordFormat>& extra);

/// The record in `file`, read by the row of its extension. InputError naming the file when the
/// extension has no row (listing the supported ones), the row has no reader in this build (its
/// `unavailable`), options.dataset is given for a format without datasets, or the reader or
/// finish_record() refuses.
MeasuredRecord read_record(const std::filesystem::path& file, const RecordOptions& options,
                           const std::vector<RecordFormat>& formats);

}  // namespace bearing
