#pragma once
// `bearing-sim info`: the numbers that follow from a case's geometry and load alone — contact
// constants, bearing frequencies and the static load distribution — as text and as JSON.

#include <string>

#include <nlohmann/json.hpp>

#include "bearing/case_file.h"
#include "bearing/contact.h"
#include "bearing/kinematics.h"
#include "bearing/static_load.h"

namespace bearing {

struct InfoReport {
  Case input;
  ContactConstants contact;
  BearingFrequencies frequencies;
  StaticLoadResult static_load;
};

/// Computes everything `info` shows. Throws InputError / SolverError.
InfoReport compute_info(const Case& c);

/// JSON with the keys of DESIGN.md: kinematics.{shaft,ftf,bpfo,bpfi,bsf} [Hz],
/// contact.{inner,outer}.{sum_rho [1/m], f_rho, ellipticity, delta_star, K [N/m^n], exponent n},
/// contact.K, contact.exponent, static.{deflection [m, m], ball_loads [N], q_max [N]}; plus
/// contact.method, static.ball_angles [rad] and a `units` object; for a calibrated law
/// contact.calibration (calibration_json). Throws SolverError if any value is not finite.
nlohmann::json info_json(const InfoReport& report);

/// The calibration behind a calibrated law: {file, designation, geometry, method, mesh, date,
/// load_range [N] (null if the file has none), fit_residual.{inner,outer} (the FE fit's; null if
/// not given), series_fit_residual (the ball's law, 0 if exact)}.
nlohmann::json calibration_json(const ContactCalibration& cal, const ContactConstants& cc);

/// Human-readable report with units.
std::string info_text(const InfoReport& report);

/// Throws SolverError naming the JSON path of the first NaN or infinity in `j`.
void require_finite(const nlohmann::json& j, const std::string& path = "");

}  // namespace bearing
