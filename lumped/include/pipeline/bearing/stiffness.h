#pragma once
// The bearing's stiffness at a case's operating point, for rotor models (issue 32): the case
// mapped to the 5-DOF static solution of the inner ring (five_dof_static.h) and solved. What
// `bearing-sim stiffness` writes per operating point, what `info` shows and `bearing.stiffness`
// returns.
//
// K is solved at the case's cage angle (ball 0 at the cage phase of its model inputs) and, with a
// ball pass, at N cage angles through one ball pitch; what a linear rotor model takes is their
// mean (rotor_coefficients.h), StiffnessPoint::rotor.
//
// Coordinates: q = (x, y, z, gx, gy) = (δx, δy, δz, γx, γy) [m, m, m, rad, rad], the inner ring's
// displacement from the centred position and its tilts about +x and +y; F = (Fx, Fy, Fz, Mx, My)
// [N, N, N, N m, N m] the load on it. K = ∂F/∂q, symmetric: N/m between forces and
// displacements, N/rad between forces and tilts (= N m/m, moments and displacements), N m/rad
// between moments and tilts. Assumed: rigid rings, the outer ring fixed; at operation.speed each
// ball carries its centrifugal load m_b ω_c² d_m/2 when ball.centrifugal is on (the default), so
// that its inner and outer contact angles differ (Jones; five_dof_static.h); the gyroscopic
// moment neglected. With [lubricant] (at a speed: the film needs entrainment) each contact has
// its EHL film in series with Hertz (K) and its squeeze-film damping C = ∂F/∂q̇ [N s/m, N s/rad,
// N s, N m s/rad]; without it, C = 0 and K is the dry contacts' (five_dof_static.h).

#include <array>
#include <optional>
#include <string>

#include "bearing/ball_pass_stiffness.h"
#include "bearing/case_file.h"
#include "bearing/five_dof_static.h"
#include "bearing/rotor_coefficients.h"

namespace bearing {

/// The DOF names (x, y, z, gx, gy), their units (m, rad) and the load components' (N, N*m).
constexpr std::array<const char*, 5> kStiffnessDofs = {"x", "y", "z", "gx", "gy"};
constexpr std::array<const char*, 5> kStiffnessDofUnits = {"m", "m", "m", "rad", "rad"};
constexpr std::array<const char*, 5> kStiffnessLoadUnits = {"N", "N", "N", "N*m", "N*m"};

/// The unit of K_ij = ∂F_i/∂q_j: "N/m", "N/rad", "N" or "N*m/rad".
std::string stiffness_unit(int i, int j);

/// The name of K_ij for i ≤ j: "k_" and both DOF names, joined by "_" when one is a tilt
/// ("k_xx", "k_yz", "k_x_gx", "k_gx_gy").
std::string stiffness_name(int i, int j);

/// The load vector of a case [N, N m]: (Fx, Fy) the constant radial load with the rotor weight
/// −m g on Fy when operation.gravity is on (ModelInputs::radial_load), Fz = operation.axial_load,
/// (Mx, My) = operation.moment.
Vector5 five_dof_load_of(const Case& c);

/// The case's bearing with its contact law (contact_constants(c): a Hertz method, or the
/// calibrated constants), ball 0 at the cage phase of its model inputs, and each ball's
/// centrifugal load at operation.speed when ball.centrifugal is on (ball_centrifugal_load), and
/// with [lubricant] each contact's film (add_films) at operation.speed, the cage at its
/// pure-rolling speed. Throws
/// InputError naming bearing.clearance when the clearance leaves no contact angle below 90°.
FiveDofBearing five_dof_bearing_of(const Case& c);

/// Cage angles a ball pitch of the ball-pass stiffness `bearing-sim stiffness` and
/// `bearing.ball_pass_stiffness` take by default, and the most they accept (each one a solve).
constexpr int kBallPassSamples = 32;
constexpr int kMaxBallPassSamples = 4096;

/// The 5-DOF static state at one operating point.
struct StiffnessPoint {
  Vector5 load = Vector5::Zero();  ///< F = (Fx, Fy, Fz, Mx, My) [N, N, N, N m, N m]
  /// The case's cage angle φ₀: ball 0's angle from +x toward +y, the cage phase a run starts at
  /// [rad]. `solution` is the equilibrium there.
  double cage_angle = 0;
  /// At the case's cage angle: q [m, rad], K [N/m, N/rad, N m/rad], the balls. K here depends on
  /// where the balls stand (one ball under the load: no sideways stiffness); a rotor model takes
  /// `rotor`, the ball-pass mean.
  FiveDofSolution solution;
  /// K over one ball pitch from the case's cage phase (ball_pass_stiffness.h), each cage angle
  /// its own equilibrium under `load`, the bearing the same (the centrifugal load at speed):
  /// its samples[0] is solution.at.stiffness. Empty when not asked for.
  std::optional<BallPassStiffness> ball_pass;
  /// With `ball_pass`: the coefficients a linear rotor model takes, K averaged over it, and the
  /// warnings when that mean is singular or near it (rotor_coefficients.h).
  std::optional<RotorCoefficients> rotor;
  /// The ball-pass frequency over the outer race at the case's speed, outer ring fixed, pure
  /// rolling at the free contact angle (kinematics.h) [Hz]: the period of K in time is 1/bpfo,
  /// its m-th harmonic at m × bpfo.
  double bpfo = 0;
  /// Peak Hertz pressure of the most loaded contact at the inner and outer race [Pa]; beyond
  /// kElasticPressureLimit (contact.h) the elastic contact law, and so K, does not hold.
  double inner_peak_pressure = 0, outer_peak_pressure = 0;
  bool elastic() const;
  /// The largest ball load [N] (0: no ball loaded, e.g. no load, K = 0).
  double q_max() const;
  /// The largest load of an outer contact [N]: q_max at rest, more at speed (each ball's
  /// centrifugal load presses it on the outer race).
  double outer_q_max() const;
  /// The balls that carry a load: Q_j > 0 and δ_j > 0 (with a film every ball carries a
  /// vanishing load; it counts where its Hertz deflection exceeds its film, five_dof_static.h).
  int loaded_balls() const;
};

/// Solves the case's operating point: five_dof_bearing_of(c) under five_dof_load_of(c), every
/// DOF free; with `ball_pass_samples` > 0 also its ball pass at that many cage angles (4 …
/// kMaxBallPassSamples; 0: the matrix at the case's cage angle alone) and its rotor coefficients.
/// Throws InputError (clearance, a sample count out of range) or SolverError (no equilibrium
/// reached, at any cage angle).
StiffnessPoint stiffness_point(const Case& c, int ball_pass_samples = kBallPassSamples);

}  // namespace bearing
