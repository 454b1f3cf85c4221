#pragma once
// What `bearing-sim sweep --save …` keeps of each case: its arrays as float64 tables (the layout
// of `run`'s .npy outputs, with column names and SI units), its resolved case and its summary.json
// text. Built where the case runs (a sweep thread, or an MPI rank), so that only these tables
// travel to the writer of sweep.h5 (sweep_dataset.h).

#include <cstddef>
#include <string>
#include <vector>

#include "bearing/case_file.h"
#include "bearing/simulation.h"

namespace bearing {

/// What `--save` may name.
enum class SweepSave { response, spectrum, envelope, summary };

/// Parses `--save` values: each a name or a comma list ("response,summary"), repeats allowed.
/// Throws InputError naming `--save`, the text and the names allowed. Empty input: empty result.
std::vector<SweepSave> parse_sweep_save(const std::vector<std::string>& texts);

/// The name of a SweepSave ("response", …).
const char* sweep_save_name(SweepSave what);

/// A table: row-major float64 values with one name and SI unit per column.
struct SweepTable {
  std::string name;  ///< "response", "spectrum", "envelope", "summary"
  std::size_t rows = 0;
  std::vector<std::string> columns;    ///< as the CSV header / columns.json
  std::vector<std::string> units;      ///< one per column
  std::vector<std::string> row_names;  ///< summary: mean, rms, ptp, kurtosis, crest; else empty
  std::vector<double> values;          ///< rows × columns
};

/// One case's part of sweep.h5.
struct SweepCaseTables {
  std::string case_toml;           ///< the resolved case, as case.toml
  std::string summary_json;        ///< summary.json's text ("" unless `summary` was asked for)
  std::vector<SweepTable> tables;  ///< in the order `what` asked for them
};

/// The tables of a run that `what` asks for: response (t and every channel), spectrum (frequency
/// and every spectrum channel), envelope (only with envelope spectra), summary (5 × channels).
SweepCaseTables sweep_case_tables(const Case& c, const SimulationResult& r, const RunSummary& s,
                                  const std::vector<SweepSave>& what);
/// The same from the pieces: the case's text, its response, its analysis and summary.json's text
/// (kept only when `summary` is asked for).
SweepCaseTables sweep_case_tables(std::string case_toml, const Response& response,
                                  const RunSummary& s, std::string summary_json,
                                  const std::vector<SweepSave>& what);

}  // namespace bearing
