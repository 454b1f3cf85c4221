#include "bearing/bearing.h"

#include <cmath>
#include <string>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/units.h"

namespace bearing {

namespace {

// "bearing.ball_diameter = 15.081 mm" — the value as the user would write it.
std::string shown(const char* key, double si, const char* unit, Dimension dim) {
  return std::string("bearing.") + key + " = " +
         (std::isfinite(si) ? format_quantity(si, unit, dim) : std::string("non-finite"));
}

void require_positive(const char* key, double si) {
  if (!std::isfinite(si) || si <= 0)
    throw InputError(shown(key, si, "mm", Dimension::length) + ": must be positive (> 0 mm)");
}

}  // namespace

void Bearing::validate() const {
  require_positive("ball_diameter", ball_diameter);
  require_positive("pitch_diameter", pitch_diameter);
  if (balls < 3)
    throw InputError("bearing.balls = " + std::to_string(balls) +
                     ": a radial ball bearing needs at least 3 balls (allowed: integer >= 3)");
  if (pitch_diameter <= ball_diameter)
    throw InputError(shown("pitch_diameter", pitch_diameter, "mm", Dimension::length) +
                     ": must be larger than the ball diameter (" +
                     format_quantity(ball_diameter, "mm", Dimension::length) + ")");
  // Balls must fit around the pitch circle: Z D < π d_m is necessary (adjacent balls not
  // overlapping needs d_m sin(π/Z) > D).
  if (pitch_diameter * std::sin(pi / balls) <= ball_diameter)
    throw InputError("bearing.balls = " + std::to_string(balls) + ": " + std::to_string(balls) +
                     " balls of " + format_quantity(ball_diameter, "mm", Dimension::length) +
                     " do not fit on a pitch circle of " +
                     format_quantity(pitch_diameter, "mm", Dimension::length) +
                     " (need pitch_diameter * sin(pi/balls) > ball_diameter)");
  const auto check_conformity = [](const char* key, double f) {
    if (!std::isfinite(f) || f <= 0.5)
      throw InputError(std::string("bearing.") + key + " = " +
                       (std::isfinite(f) ? format_number(f) : std::string("non-finite")) +
                       ": the groove radius must be larger than the ball radius (conformity = "
                       "groove radius / ball diameter > 0.5; typical 0.515-0.53)");
  };
  check_conformity("inner_conformity", inner_conformity);
  check_conformity("outer_conformity", outer_conformity);
  if (!std::isfinite(clearance) || clearance < 0)
    throw InputError(shown("clearance", clearance, "um", Dimension::length) +
                     ": the radial internal clearance must be >= 0 (use preload, not negative "
                     "clearance)");
  // Real clearances are well below 1 % of D; a tenth of D means a unit slip, not a bearing.
  if (clearance >= 0.1 * ball_diameter)
    throw InputError(shown("clearance", clearance, "um", Dimension::length) +
                     ": more than 10 % of the ball diameter (" +
                     format_quantity(ball_diameter, "mm", Dimension::length) +
                     "); did you mean um rather than mm?");
  if (!std::isfinite(contact_angle) || contact_angle < 0 || contact_angle >= pi / 2)
    throw InputError(shown("contact_angle", contact_angle, "deg", Dimension::angle) +
                     ": must lie in [0 deg, 90 deg)");
  ball.validate("material.ball");
  rings.validate("material.rings");
}

}  // namespace bearing
