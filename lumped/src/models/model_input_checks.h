#pragma once
// Private to the lumped models (not installed): the checks of the ModelInputs fields the lumped
// models use, each refusal an InputError that names the case-file key. Run before anything is
// built from the inputs.

#include <cmath>
#include <string>

#include "bearing/contact.h"
#include "bearing/errors.h"
#include "bearing/excitation.h"
#include "bearing/limits.h"
#include "bearing/local_defect.h"
#include "bearing/models/model_inputs.h"
#include "bearing/units.h"
#include "max_balls.h"

namespace bearing::detail {

inline void require_finite(double v, const std::string& key, const char* what) {
  if (!std::isfinite(v)) throw InputError(key + " = " + format_number(v) + ": " + what);
}

/// Checks of the ModelInputs fields every lumped model uses (InputError naming the case key): the
/// same rules the case reader applies (Bearing::validate, limits.h, check_waviness,
/// check_ball_size_errors), for inputs built in code; plus what only the models need.
inline void validate_common_inputs(const ModelInputs& in) {
  in.bearing.validate();
  if (in.bearing.balls > kMaxBalls)
    throw InputError("bearing.balls = " + std::to_string(in.bearing.balls) +
                     ": the lumped models support at most " + std::to_string(kMaxBalls) + " balls");
  if (!(std::isfinite(in.contact.K) && in.contact.K > 0))
    throw InputError("model.contact: load-deflection constant K = " + format_number(in.contact.K) +
                     " N/m^n must be positive and finite");
  if (!(std::isfinite(in.contact.exponent) && in.contact.exponent >= 1))
    throw InputError("model.contact: load-deflection exponent " +
                     format_number(in.contact.exponent) + " must be finite and >= 1");
  limits::operation_speed.check(in.inner_speed);
  require_finite(in.cage_phase, "cage phase", "rad: must be finite");
  if (!in.load.allFinite())
    throw InputError("operation.load = (" + format_number(in.load.x()) + ", " +
                     format_number(in.load.y()) + ") N: must be finite");
  limits::operation_unbalance.check(in.unbalance);
  limits::rotor_mass.check(in.mass);
  limits::rotor_damping.check(in.damping);
  check_waviness(in.inner_waviness.harmonics, in.bearing, "waviness.inner");
  check_waviness(in.outer_waviness.harmonics, in.bearing, "waviness.outer");
  check_ball_size_errors(in.ball_size_errors, in.bearing);
  check_defects(in.defects, in.bearing);
}

/// Checks of the contact law that TVDS (model.waviness_stiffness) needs: the Hertz exponent 3/2
/// and positive per-race constants K_i, K_o. Run by BallSet when TVDS has waviness to act on.
inline void validate_tvds_contact(const ModelInputs& in) {
  const bool hertz_exponents = in.contact.exponent == 1.5 && in.contact.inner.exponent == 1.5 &&
                               in.contact.outer.exponent == 1.5;
  if (!hertz_exponents && in.contact.method == ContactLaw::calibrated)
    throw InputError(
        "model.waviness_stiffness = true (TVDS) needs the Hertz exponent 3/2 on both races, but "
        "the calibrated contact law (model.calibration) has n = " +
        format_number(in.contact.inner.exponent) + " (inner), " +
        format_number(in.contact.outer.exponent) +
        " (outer): use waviness_stiffness = false (TVD) with this calibration, or a calibration "
        "fitted with the exponent fixed at 1.5");
  if (!hertz_exponents)
    throw InputError(
        "model.waviness_stiffness: TVDS needs the Hertz exponent 3/2 (the contact "
        "law has " +
        format_number(in.contact.exponent) + ")");
  if (!(in.contact.inner.K > 0 && in.contact.outer.K > 0 && std::isfinite(in.contact.inner.K) &&
        std::isfinite(in.contact.outer.K)))
    throw InputError("model.waviness_stiffness: TVDS needs the per-race constants K_i = " +
                     format_number(in.contact.inner.K) +
                     ", K_o = " + format_number(in.contact.outer.K) + " N/m^1.5 (positive)");
}

}  // namespace bearing::detail
