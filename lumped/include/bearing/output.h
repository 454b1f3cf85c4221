#pragma once
// Result files of `bearing-sim run`: response.csv, spectrum.csv, summary.json and case.toml.

#include <string>

#include <nlohmann/json.hpp>

#include "bearing/simulation.h"

namespace bearing {

/// summary.json: `case` (with `case.calibration` for a calibrated law, see calibration_json),
/// `contact` (the law: `method`, `K` [N/m^n] and `exponent` n of the ball between both races and
/// of each race), `frequencies` [Hz], `channels.<name>.{mean,rms,ptp,kurtosis,crest}` (SI),
/// `peaks.<name>[]` with `frequency` [Hz], `amplitude` (SI) and `label`, `solver` (method, steps,
/// force evaluations) and `units`. Throws SolverError if any value is not finite.
nlohmann::json summary_json(const Case& c, const SimulationResult& r, const RunSummary& s);

/// A few readable lines: frequencies, each ring channel's RMS / PTP / kurtosis and its largest
/// peaks, with units.
std::string summary_text(const Case& c, const SimulationResult& r, const RunSummary& s);

/// Writes the four files into `dir` (created if missing), all or nothing: each is written under a
/// temporary name and the set is renamed into place only when every file is complete and every
/// value finite. Throws InputError (cannot write) or SolverError (non-finite value).
void write_run(const std::string& dir, const Case& c, const SimulationResult& r,
               const RunSummary& s);

}  // namespace bearing
