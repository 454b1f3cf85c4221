#pragma once
// Private to the lumped models (not installed): the ball-DOF kind's input checks and the cage
// speed and contact angle of its kinematics (ball_dofs.cc), run before anything is built from the
// inputs.

#include <cmath>

#include "bearing/errors.h"
#include "bearing/kinematics.h"
#include "bearing/limits.h"
#include "bearing/models/model_inputs.h"
#include "bearing/models/three_dof.h"
#include "bearing/static_load.h"
#include "bearing/traction.h"
#include "bearing/units.h"
#include "model_input_checks.h"

namespace bearing::detail {

// Validates the inputs (before anything is built from them) and returns ω_ca = (1 − s_c) ω_c,
// ω_c at the loaded contact angle of the axial static state when there is an axial load.
inline double checked_ball_dof_cage_speed(const ModelInputs& in) {
  validate_common_inputs(in);
  limits::cage_slip.check(in.cage_slip);
  make_traction_curve(in.traction.max_coefficient, in.traction.slide_speed);
  // 0 stands for the default (default_ball_mass, default_ball_inertia).
  if (in.ball_mass != 0) limits::ball_mass.check(in.ball_mass);
  if (in.ball_inertia != 0) limits::ball_inertia.check(in.ball_inertia);
  limits::ball_damping.check(in.ball_damping);
  if (!(in.contact.inner.K > 0 && in.contact.outer.K > 0 && std::isfinite(in.contact.inner.K) &&
        std::isfinite(in.contact.outer.K) && in.contact.inner.exponent >= 1 &&
        in.contact.outer.exponent >= 1))
    throw InputError("model.contact: the ball-DOF model needs both races' constants, K_i = " +
                     format_number(in.contact.inner.K) +
                     ", K_o = " + format_number(in.contact.outer.K) +
                     " N/m^n (positive, finite) and exponents >= 1");
  const double wc =
      in.axial_load != 0.0 ? three_dof_cage_speed(in) : cage_speed(in.bearing, in.inner_speed);
  return (1.0 - in.cage_slip) * wc;
}

// The contact angle of the kinematics: the loaded one of the axial static state with an axial
// load, else the free one (the registry's angle for this kind).
inline double ball_dof_kinematic_angle(const ModelInputs& in) {
  validate_common_inputs(in);  // also when evaluated before checked_ball_dof_cage_speed
  return in.axial_load != 0.0 ? solve_axial_preload(in).contact_angle : in.bearing.contact_angle;
}

}  // namespace bearing::detail
