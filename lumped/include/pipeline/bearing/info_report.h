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
/// contact.calibration (calibration_json, json_helpers.h). Throws SolverError if any value is not
/// finite.
nlohmann::json info_json(const InfoReport& report);

/// Human-readable report with units.
std::string info_text(const InfoReport& report);

}  // namespace bearing
