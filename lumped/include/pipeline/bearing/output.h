#pragma once
// Result files of `bearing-sim run`: response.csv, spectrum.csv, summary.json and case.toml, and
// pressure.csv with an [acoustics] table.

#include <string>

#include <nlohmann/json.hpp>

#include "bearing/simulation.h"

namespace bearing {

/// summary.json: `case` (with `case.calibration` for a calibrated law, see calibration_json),
/// `contact` (the law: `method`, `K` [N/m^n] and `exponent` n of the ball between both races and
/// of each race), `frequencies` [Hz], `channels.<name>.{mean,rms,ptp,kurtosis,crest}` (SI),
/// `peaks.<name>[]` with `frequency` [Hz], `amplitude` (SI) and `label`, `solver` (method, steps,
/// force evaluations), `units`, and with an [acoustics] table `acoustics` (sources and their
/// models, summation, radii [m], air, band [Hz], and per microphone `position` [m], `radius`
/// [m], `angle` [rad], `p_rms*` [Pa], `spl_total`, `spl_ring`, `spl_balls` [dB re 20 µPa; null
/// where the source is "none" or silent] and `nearest_ball_surface` [m]). Throws SolverError if
/// any value is not finite.
nlohmann::json summary_json(const Case& c, const SimulationResult& r, const RunSummary& s);

/// A few readable lines: frequencies, each ring channel's RMS / PTP / kurtosis and its largest
/// peaks, with units.
std::string summary_text(const Case& c, const SimulationResult& r, const RunSummary& s);

/// Writes the four files (five with acoustics: pressure.csv, `t` then p1…pM [Pa] over the
/// analysis window) into `dir` (created if missing), all or nothing: each is written under a
/// temporary name and the set is renamed into place only when every file is complete and every
/// value finite; each file then replaces its predecessor by one rename. Runs into one folder commit
/// one at a time (an flock on `dir`/.run.lock). Throws InputError (the folder cannot be created),
/// OutputError (a file cannot be written: disk full, ...) or SolverError (non-finite value).
void write_run(const std::string& dir, const Case& c, const SimulationResult& r,
               const RunSummary& s);

}  // namespace bearing
