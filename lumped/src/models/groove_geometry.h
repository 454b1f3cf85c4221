#pragma once
// Private to the lumped models: the groove-centre geometry of a ball between two races with an
// axial degree of freedom (three_dof.h has the derivation; the 3-DOF and the ball-DOF models use
// it).

#include <cmath>
#include <string>

#include "bearing/bearing.h"
#include "bearing/errors.h"
#include "bearing/units.h"

namespace bearing::detail {

// The fixed geometry of the groove centres (three_dof.h).
struct GrooveGeometry {
  double A0 = 0;  // distance of the groove curvature centres [m]
  double u0 = 0;  // A₀ cos α₀ [m]
  double w0 = 0;  // A₀ sin α₀ [m]
};

inline GrooveGeometry groove_geometry(const Bearing& b) {
  GrooveGeometry g;
  g.A0 = (b.inner_conformity + b.outer_conformity - 1.0) * b.ball_diameter;
  const double half = 0.5 * b.clearance;
  if (!(g.A0 > 0 && half < g.A0))
    throw InputError(
        "bearing.clearance = " + format_number(b.clearance) +
        " m: with an axial load the model needs P_d < 2 A0 = " + format_number(2 * g.A0) +
        " m (A0 = (f_i + f_o - 1) D), i.e. a free contact angle below 90 deg");
  g.u0 = g.A0 - half;
  g.w0 = std::sqrt(half * (2.0 * g.A0 - half));
  return g;
}

// δ for radial offset r and axial position z, and L = A₀ + δ.
inline double approach(const GrooveGeometry& g, double r, double z, double& L) {
  const double w = g.w0 + z, a = g.u0 + r;
  L = std::sqrt(w * w + a * a);
  return (z * (2.0 * g.w0 + z) + r * (2.0 * g.u0 + r)) / (L + g.A0);
}

}  // namespace bearing::detail
