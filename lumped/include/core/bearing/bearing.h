#pragma once
// Geometry and materials of one deep-groove (radial) ball bearing, in SI units.

#include <string>

#include "bearing/material.h"

namespace bearing {

struct Bearing {
  std::string designation;    ///< catalogue name, e.g. "6308" (informative only)
  double ball_diameter = 0;   ///< D [m]
  double pitch_diameter = 0;  ///< d_m [m], ball-set pitch diameter
  int balls = 0;              ///< Z, number of balls (≥ 3)
  double inner_conformity =
      0;  ///< f_i = r_i / D [-], inner groove radius over ball diameter (> 0.5)
  double outer_conformity = 0;  ///< f_o = r_o / D [-] (> 0.5)
  double clearance =
      0;  ///< P_d [m], ISO radial internal clearance (diametral); each ball's gap is P_d/2
  double contact_angle = 0;  ///< α [rad], free contact angle (0 for a radial deep-groove bearing)
  Material ball;             ///< ball material
  Material rings;            ///< inner and outer ring material

  /// Inner raceway (groove bottom) diameter d_i = d_m − D [m] (the value the curvature uses).
  double inner_raceway_diameter() const { return pitch_diameter - ball_diameter; }
  /// Outer raceway (groove bottom) diameter d_o = d_m + D [m].
  double outer_raceway_diameter() const { return pitch_diameter + ball_diameter; }
  /// Radial gap of one ball, γ = P_d / 2 [m].
  double ball_gap() const { return 0.5 * clearance; }

  /// Throws InputError naming the `bearing.*` key, the value and the allowed range for the first
  /// invalid field: sizes ≤ 0, fewer than 3 balls, d_m ≤ D, groove radius ≤ ball radius, negative
  /// clearance, contact angle outside [0, 90°), materials out of range.
  void validate() const;
};

}  // namespace bearing
