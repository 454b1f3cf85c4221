#pragma once
// JSON pieces shared by the result writers (`bearing-sim info --json` and run's summary.json):
// the check that nothing non-finite is written, and a calibrated law's provenance and the housing
// as both show them.

#include <string>

#include <nlohmann/json.hpp>

#include "bearing/calibration.h"
#include "bearing/contact.h"
#include "bearing/models/housing.h"
#include "bearing/models/random_slip.h"

namespace bearing {

/// The calibration behind a calibrated law: {file, designation, geometry, method, mesh, date,
/// load_range [N] (null if the file has none), fit_residual.{inner,outer} (the FE fit's; null if
/// not given), series_fit_residual (the ball's law, 0 if exact)}.
nlohmann::json calibration_json(const ContactCalibration& cal, const ContactConstants& cc);

/// The housing as it ran: the resonator {mass, frequency, damping_ratio, stiffness, damping}, or
/// the structure's modes {structure (the modes file), frequencies [Hz], damping_ratios, sensors}.
nlohmann::json housing_json(const Housing& housing);
/// Their units, into a summary's or info's `units` (keys "housing.<key>").
void add_housing_units(const Housing& housing, nlohmann::json& units);

/// The cage's random slip as a run uses it (random_slip.h): {rms, correlation_time [s] resolved
/// (the default, one ball pass, is 1/bpfo [Hz]), correlation_time_source, seed}.
nlohmann::json slip_json(const RandomSlip& slip, double bpfo);
/// Their units, into a summary's or info's `units` (keys "slip.<key>").
void add_slip_units(nlohmann::json& units);
/// The one line `info` and `run` print for it ("Slip: ...\n").
std::string slip_line(const RandomSlip& slip, double bpfo);

/// Throws SolverError naming the JSON path of the first NaN or infinity in `j`.
void require_finite(const nlohmann::json& j, const std::string& path = "");

}  // namespace bearing
