#pragma once
// Sliding and traction at the ball–race contacts when the cage slips (seed 004 §2; docs/model.md
// §4, "Ball DOFs, cage slip and friction"). The ball-DOF model (issue 7) is built on this.
//
// Kinematics, outer ring fixed, inner ring turning at ω_i, cage at ω_ca (seed 004 eq. 3:
// ω_ca = (1 − s_c) ω_c with ω_c the pure-rolling cage speed), each ball spinning at ω_b relative
// to the cage about an axis parallel to the bearing axis (so its lever arm to a contact is
// (D/2) cos α; kinematics.h's BSF takes the axis normal to the contact line, lever arm D/2, and
// the two agree for α = 0), g = D cos α / d_m. Surface speeds at the contact points, positive
// in the direction of rotation (seed 004 eqs. 4–6):
//     inner race at the inner contact   v_ii = ½ ω_i d_m (1 − g)
//     ball at the inner contact         v_ib = ½ ω_ca d_m (1 − g) + ½ ω_b D cos α
//     ball at the outer contact         v_ob = ½ ω_ca d_m (1 + g) − ½ ω_b D cos α
// and the sliding speeds, race surface minus ball surface at the inner contact, ball surface
// minus (fixed) race surface at the outer one (eqs. 7–8):
//     Δv_i = v_ii − v_ib = ½ (ω_i − ω_ca) d_m (1 − g) − ½ ω_b D cos α,
//     Δv_o = v_ob        = ½ ω_ca d_m (1 + g) − ½ ω_b D cos α.
// Both vanish at pure rolling: ω_ca = ω_c and ω_b D cos α = ½ ω_i d_m (1 − g²) (2π·BSF / cos α).
// With that spin and a slip s_c: Δv_i = ½ s_c ω_c d_m (1 − g) > 0 and Δv_o = −½ s_c ω_c d_m (1 + g)
// < 0 — the inner race drives the ball forward and the outer race holds it back, which is what lets
// a slipping cage keep its balls turning.
//
// Traction (seed 004 Fig. 3): μ(Δv) = μ_m · sign(Δv) · min(|Δv|/Δv_m, 1). Directions, derived here
// because seed 004's eqs. 9–10 and 20–23 do not agree on whose force their sign is: friction
// opposes the relative sliding of the two surfaces, so the slower surface is pulled along the
// faster one. Tangential forces, positive in the direction of rotation:
//     on the ball at the inner contact    F_bi = +μ(Δv_i) Q_i,  on the inner race −F_bi;
//     on the ball at the outer contact    F_bo = −μ(Δv_o) Q_o,  on the outer race −F_bo.
// The power they dissipate is P = μ(Δv_i) Q_i Δv_i + μ(Δv_o) Q_o Δv_o ≥ 0.

#include <algorithm>
#include <cmath>
#include <string>

#include "bearing/bearing.h"

namespace bearing {

/// Seed 004's traction curve: μ rises linearly with the sliding speed up to Δv_m, then stays μ_m.
struct TractionCurve {
  double max_coefficient = 0.0;  ///< μ_m [-], ≥ 0
  double slide_speed = 1.0;      ///< Δv_m [m/s], > 0

  /// μ(Δv) [-], odd in Δv [m/s]. Inline: the ball-DOF model calls it twice per ball and force.
  double coefficient(double sliding_speed) const {
    return max_coefficient * std::clamp(sliding_speed / slide_speed, -1.0, 1.0);
  }
  /// dμ/dΔv [s/m]: μ_m/Δv_m on the linear part |Δv| < Δv_m, 0 beyond (one-sided at the kink).
  double slope(double sliding_speed) const {
    return std::abs(sliding_speed) < slide_speed ? max_coefficient / slide_speed : 0.0;
  }
};

/// A checked TractionCurve: InputError naming cage.friction or cage.slide_speed outside their
/// limits (limits.h).
TractionCurve make_traction_curve(double max_coefficient, double slide_speed);

/// Sliding speeds at the two contacts of a ball [m/s].
struct SlidingSpeeds {
  double inner = 0.0;  ///< Δv_i: inner race surface minus ball surface
  double outer = 0.0;  ///< Δv_o: ball surface minus outer race surface (the outer ring is fixed)
};

/// Δv_i, Δv_o (seed 004 eqs. 7–8) for inner-ring speed ω_i, cage speed ω_ca and the ball's spin
/// ω_b relative to the cage [rad/s]. InputError for an invalid bearing (Bearing::validate) or
/// non-finite speeds.
SlidingSpeeds sliding_speeds(const Bearing& b, double inner_speed, double cage_speed,
                             double ball_spin);

/// The ball spin relative to the cage [rad/s] at which a pure-rolling cage (ω_ca = ω_c) has no
/// sliding at either contact: ω_b = ω_i d_m (1 − g²) / (2 D cos α).
double rolling_ball_spin(const Bearing& b, double inner_speed);

/// The tangential forces of one ball's two contacts [N] (positive in the direction of rotation)
/// and the power they dissipate [W].
struct ContactTraction {
  double on_ball_inner = 0.0;  ///< F_bi, on the ball at the inner contact
  double on_ball_outer = 0.0;  ///< F_bo, on the ball at the outer contact
  double on_inner_race = 0.0;  ///< −F_bi, on the inner race
  double power = 0.0;          ///< dissipated, ≥ 0
};

/// Traction of a ball loaded by Q_i, Q_o ≥ 0 [N] at its inner and outer contacts.
ContactTraction contact_traction(const TractionCurve& curve, const SlidingSpeeds& sliding,
                                 double inner_load, double outer_load);

}  // namespace bearing
