#pragma once
// Private to the lumped models (not installed): the checks of the ModelInputs fields the lumped
// models use, each refusal an InputError that names the case-file key. Run before anything is
// built from the inputs.

#include <cmath>
#include <string>

#include "bearing/contact.h"
#include "bearing/errors.h"
#include "bearing/excitation.h"
#include "bearing/models/model_inputs.h"
#include "bearing/units.h"
#include "max_balls.h"

namespace bearing::detail {

inline void require_finite(double v, const std::string& key, const char* what) {
  if (!std::isfinite(v)) throw InputError(key + " = " + format_number(v) + ": " + what);
}

inline void validate_waviness(const Waviness& w, const std::string& key) {
  for (const WavinessHarmonic& h : w.harmonics) {
    if (h.order < 1)
      throw InputError(key + ": order = " + std::to_string(h.order) +
                       ": must be an integer >= 1 (waves per revolution)");
    if (!(std::isfinite(h.amplitude) && h.amplitude >= 0))
      throw InputError(key + ": amplitude = " + format_number(h.amplitude) + " m (order " +
                       std::to_string(h.order) + "): must be finite and >= 0");
    if (!std::isfinite(h.phase))
      throw InputError(key + ": phase = " + format_number(h.phase) + " rad (order " +
                       std::to_string(h.order) + "): must be finite");
  }
}

/// Checks of the ModelInputs fields every lumped model uses (InputError naming the case key).
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
  require_finite(in.inner_speed, "operation.speed", "rad/s: must be finite");
  require_finite(in.cage_phase, "cage phase", "rad: must be finite");
  if (!in.load.allFinite())
    throw InputError("operation.load = (" + format_number(in.load.x()) + ", " +
                     format_number(in.load.y()) + ") N: must be finite");
  if (!(std::isfinite(in.unbalance) && in.unbalance >= 0))
    throw InputError("operation.unbalance = " + format_number(in.unbalance) +
                     " kg m: must be finite and >= 0");
  if (!(std::isfinite(in.mass) && in.mass > 0))
    throw InputError("rotor.mass = " + format_number(in.mass) +
                     " kg: the inner ring and shaft need a positive mass");
  if (!(std::isfinite(in.damping) && in.damping >= 0))
    throw InputError("rotor.damping = " + format_number(in.damping) +
                     " N s/m: must be finite and >= 0");
  validate_waviness(in.inner_waviness, "waviness.inner");
  validate_waviness(in.outer_waviness, "waviness.outer");
  if (!in.ball_size_errors.empty()) {
    if (static_cast<int>(in.ball_size_errors.size()) != in.bearing.balls)
      throw InputError("ball_errors.values: " + std::to_string(in.ball_size_errors.size()) +
                       " values given for " + std::to_string(in.bearing.balls) +
                       " balls; give one per ball");
    for (double e : in.ball_size_errors)
      require_finite(e, "ball_errors.values", "m: each ball-size error must be finite");
  }
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
