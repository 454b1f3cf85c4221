// Sliding and traction at the ball–race contacts (seed 004 §2); see traction.h.

#include "bearing/traction.h"

#include <algorithm>
#include <cmath>

#include "bearing/errors.h"
#include "bearing/limits.h"
#include "bearing/units.h"

namespace bearing {

namespace {

// g = D cos α / d_m and the ball's lever arm (D/2) cos α, of a validated bearing.
struct ContactGeometry {
  double g, rolling_radius;
};
ContactGeometry contact_geometry(const Bearing& b) {
  b.validate();
  const double c = std::cos(b.contact_angle);
  return {b.ball_diameter * c / b.pitch_diameter, 0.5 * b.ball_diameter * c};
}

void require_finite(double w, const char* what) {
  if (!std::isfinite(w))
    throw InputError(std::string(what) + " = " + format_number(w) + " rad/s: must be finite");
}

}  // namespace

TractionCurve make_traction_curve(double max_coefficient, double slide_speed) {
  limits::cage_friction.check(max_coefficient);
  limits::cage_slide_speed.check(slide_speed);
  return {max_coefficient, slide_speed};
}

SlidingSpeeds sliding_speeds(const Bearing& b, double inner_speed, double cage_speed,
                             double ball_spin) {
  const ContactGeometry c = contact_geometry(b);
  require_finite(inner_speed, "inner-ring speed");
  require_finite(cage_speed, "cage speed");
  require_finite(ball_spin, "ball spin");
  const double spin = ball_spin * c.rolling_radius;  // ½ ω_b D cos α
  return {0.5 * (inner_speed - cage_speed) * b.pitch_diameter * (1 - c.g) - spin,
          0.5 * cage_speed * b.pitch_diameter * (1 + c.g) - spin};
}

double rolling_ball_spin(const Bearing& b, double inner_speed) {
  const ContactGeometry c = contact_geometry(b);
  require_finite(inner_speed, "inner-ring speed");
  return 0.5 * inner_speed * b.pitch_diameter * (1 - c.g * c.g) / (2 * c.rolling_radius);
}

ContactTraction contact_traction(const TractionCurve& curve, const SlidingSpeeds& sliding,
                                 double inner_load, double outer_load) {
  if (!(inner_load >= 0 && outer_load >= 0 && std::isfinite(inner_load) &&
        std::isfinite(outer_load)))
    throw InputError("contact_traction: contact loads must be finite and non-negative (" +
                     format_number(inner_load) + ", " + format_number(outer_load) + " N)");
  const double mu_i = curve.coefficient(sliding.inner), mu_o = curve.coefficient(sliding.outer);
  ContactTraction t;
  t.on_ball_inner = mu_i * inner_load;
  t.on_ball_outer = -mu_o * outer_load;
  t.on_inner_race = -t.on_ball_inner;
  t.power = mu_i * inner_load * sliding.inner + mu_o * outer_load * sliding.outer;
  return t;
}

}  // namespace bearing
