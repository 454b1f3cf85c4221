// Bearing defect frequencies from pure-rolling kinematics (docs/model.md §2).

#include "bearing/kinematics.h"

#include <cmath>
#include <sstream>
#include <string>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/limits.h"
#include "bearing/units.h"

namespace bearing {

namespace {

// g = D cos α / d_m of a valid bearing (Bearing::validate holds the rules).
double geometry_ratio(const Bearing& b) {
  b.validate();
  return b.ball_diameter * std::cos(b.contact_angle) / b.pitch_diameter;
}

void require_speed(double w, const char* what) {
  if (!std::isfinite(w))
    throw InputError(std::string(what) + " = " + format_number(w) + " rad/s: must be finite");
}

}  // namespace

double cage_speed(const Bearing& b, double inner_speed, double outer_speed) {
  require_speed(inner_speed, "inner-ring speed");
  require_speed(outer_speed, "outer-ring speed");
  const double g = geometry_ratio(b);
  // The ball centre moves at the mean of the two contact-point speeds (pure rolling).
  return 0.5 * inner_speed * (1.0 - g) + 0.5 * outer_speed * (1.0 + g);
}

BearingFrequencies bearing_frequencies(const Bearing& b, double inner_speed, double outer_speed,
                                       double cage_slip) {
  limits::cage_slip.check(cage_slip);
  const double g = geometry_ratio(b);
  const double cage = (1.0 - cage_slip) * cage_speed(b, inner_speed, outer_speed);  // ω_ca
  const double f_i = inner_speed / two_pi;
  const double f_o = outer_speed / two_pi;
  const double f_c = cage / two_pi;
  const double Z = b.balls;

  BearingFrequencies f;
  f.shaft = std::abs(f_i - f_o);
  f.ftf = std::abs(f_c);
  // A ball passes a point of a race at Z times the cage speed relative to that race.
  f.bpfo = Z * std::abs(f_c - f_o);
  f.bpfi = Z * std::abs(f_i - f_c);
  // Rolling on the outer race relative to the cage: ω_b (D/2) = (d_m/2)(1 + g)(ω_ca − ω_o),
  // which without slip is (d_m / 2D) f_i (1 − g²) (outer ring fixed).
  f.bsf = (b.pitch_diameter / b.ball_diameter) * (1.0 + g) * std::abs(f_c - f_o);
  return f;
}

}  // namespace bearing
