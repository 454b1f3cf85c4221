#pragma once
// `bearing-sim sweep --save …`: every case's arrays in one HDF5 file, DIR/sweep.h5, written case by
// case as the sweep hands them over (nothing is held between cases) and renamed into place only by
// close(). Built as the library bearing_hdf5 when CMake finds HDF5 (Debian libhdf5-dev); the file
// is written with the HDF5 C API and read by h5py, MATLAB's h5read or any HDF5 reader.
//
// Layout (format "bearing-sim sweep", format_version 1):
//
//   /                       attrs: format, format_version (int), keys (the design's varied keys),
//                                  key_units (their SI units), saved (what was asked for), cases
//                                  (groups written), layout (this description, one line)
//   /cases/000123           one group per case, named by its global case index (at least 6 digits,
//                           zero-padded, so that names sort in case order); attrs: index (uint64),
//                           values (float64, the keys' values, SI), status ("ok" | "failed"),
//                           error (failed cases), case_toml (the resolved case, as case.toml)
//   /cases/000123/response  float64 table (samples, 1 + channels): `t` then every channel, as
//   /cases/000123/spectrum  response.npy / spectrum.npy / envelope.npy of `bearing-sim run` with
//   /cases/000123/envelope  output.format = "npy", bit for bit; attrs: columns and units (one per
//                           column, as columns.json). envelope only for cases with envelope spectra
//                           (output.envelope_band set).
//   /cases/000123/summary   float64 table (5, channels): rows mean, rms, ptp, kurtosis, crest of
//                           every channel; attrs: rows, columns (channel names), units (the
//                           channel's unit: that of mean, rms and ptp; kurtosis and crest are 1),
//                           summary_json (the text of the run's summary.json: peaks, frequencies…)
//
// Tables, not one dataset per channel: a column is `ds[:, list(ds.attrs["columns"]).index("ay")]`,
// and a table equals numpy.load of the run's .npy file. Datasets are chunked (≈256 KiB of whole
// rows per chunk) and compressed with the shuffle filter then deflate (gzip) level 4; strings are
// variable-length UTF-8, which h5py 3 returns as str.

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "bearing/case_file.h"
#include "bearing/simulation.h"
#include "bearing/sweep_tables.h"

namespace bearing {

/// One varied key of the design: its name and the SI unit of its values ("" if dimensionless).
struct SweepDatasetKey {
  std::string name;
  std::string unit;
};

/// The file DIR/sweep.h5, written under a temporary name (DIR/.sweep.h5.partial) until close().
/// Not thread-safe: call add_case from one thread (run_sweep's sink is serialised).
class SweepDataset {
 public:
  SweepDataset();
  /// Removes the temporary file unless close() succeeded.
  ~SweepDataset();
  SweepDataset(const SweepDataset&) = delete;
  SweepDataset& operator=(const SweepDataset&) = delete;

  /// Starts `path` (its folder must exist) with the root's attributes. `cases` (if known) widens
  /// the group names past 6 digits so that they sort. Throws InputError if HDF5 cannot create it.
  void open(const std::string& path, const std::vector<SweepDatasetKey>& keys,
            const std::vector<SweepSave>& what, std::size_t cases = 0);

  /// Case `index` with the design's `values` (SI): its group and the datasets `what` asked for.
  void add_case(std::size_t index, const std::vector<double>& values, const Case& c,
                const SimulationResult& r, const RunSummary& s);
  /// The same from the pieces: the resolved case text, the response, the analysis and, for
  /// `summary`, the summary.json text ("" leaves the attribute out).
  void add_case(std::size_t index, const std::vector<double>& values, const std::string& case_toml,
                const Response& response, const RunSummary& s, const std::string& summary_json);
  /// The same from the tables of sweep_case_tables (built where the case ran).
  void add_case(std::size_t index, const std::vector<double>& values, const SweepCaseTables& t);
  /// A case that failed: its group with status "failed", `error` and, if known, `case_toml`.
  void add_failed_case(std::size_t index, const std::vector<double>& values,
                       const std::string& error, const std::string& case_toml = "");

  /// Writes the root's `cases`, closes the file and renames it onto `path`. Throws InputError.
  void close();

  /// The group name of case `index` ("000123").
  std::string group_name(std::size_t index) const;

 private:
  struct File;
  std::unique_ptr<File> file_;
};

/// `bearing-sim merge`'s sweep.h5: the parts' files (one per --part, in part order, already
/// checked to belong to one design) into `out`, written under a temporary name and renamed: the
/// first part's file with every other part's case groups copied in, and the root's `cases` their
/// number, which is returned. Throws InputError if the parts saved different tables or share a
/// case.
std::size_t merge_datasets(const std::string& out, const std::vector<std::string>& parts);

}  // namespace bearing
