#pragma once
// The bearing's coefficients a linear rotor model takes (issue 43, item 6): each matrix averaged
// over one ball pass. K at one cage angle (StiffnessPoint::solution) depends on where the balls
// happen to stand: under a light radial load in the clearance one ball sits under the load and the
// ring has no sideways stiffness there at all, a quarter pitch later two balls share it. A linear
// rotor model (ROSS, a finite-element shaft) holds the bearing's coefficients constant in time, so
// it takes their mean over one ball pitch, where the cage angle has no say: the mean of the ball
// pass (ball_pass_stiffness.h) at its N cage angles, each its own equilibrium under the point's
// load. The time-varying part (the BPFO harmonics) is the parametric excitation, not a rotor
// coefficient.
//
// What `bearing-sim stiffness --format ross` writes (stiffness_ross.csv), stiffness.json's
// points[].rotor and `bearing.stiffness` / `bearing.damping` in Python. The damping matrix C of
// the contacts' squeeze films ([lubricant], five_dof_static.h; ROSS's cxx … cyy) is solved at the
// same cage angles and averaged the same way (ball_pass_mean); dry contacts have C = 0.
//
// Singular or near it. Each cage angle's K is positive semi-definite (the Hessian of a convex
// contact energy, five_dof_static.h), so their mean is singular along a direction only if every one
// of them is: the ring is then unsupported that way at every cage angle, and a rotor model on this
// bearing alone has a free rigid-body mode. rotor_stiffness_warnings() says so, per block of one
// unit: the translations (x, y, z) [N/m] and the tilts (gx, gy) [N m/rad]. A block is near
// singular when its smallest eigenvalue is below kNearSingularRatio times its largest (or its
// largest is not positive); the whole of K = 0 (no ball loaded at any cage angle: the load sits
// in the clearance) is one warning of its own. The radial 2×2 (x, y), ROSS's kxx … kyy, lies in
// the translations: its eigenvalues lie between theirs (Cauchy interlacing), so a near-singular
// radial block makes the translations near singular too, along a direction in the x–y plane.

#include <string>
#include <vector>

#include "bearing/ball_pass_stiffness.h"

namespace bearing {

/// Below this ratio of its smallest to its largest eigenvalue a block of K (the translations, or
/// the tilts) is near singular: far above round-off (~1e-16 of the largest), far below a weak but
/// real stiffness (the axial stiffness of a pure radial load in the clearance, from the turn of
/// the contact lines, is ~1e-3 of the radial one).
constexpr double kNearSingularRatio = 1e-9;

/// The linear coefficients of the bearing for a rotor model, at one operating point.
struct RotorCoefficients {
  int samples = 0;  ///< N: the cage angles through one ball pitch the matrices are averaged over
  /// K averaged over one ball pass [N/m, N/rad, N (= N m/m), N m/rad by block; rows F, columns q
  /// as stiffness.h]: the ball pass's mean.
  Matrix5 stiffness = Matrix5::Zero();
  /// C averaged over one ball pass [N s/m, N s/rad, N s, N m s/rad by block], the squeeze films'
  /// damping with [lubricant]; 0 for dry contacts.
  Matrix5 damping = Matrix5::Zero();
  /// Why `stiffness` is singular or near it (rotor_stiffness_warnings); empty when it is not.
  std::vector<std::string> warnings;
};

/// The entry-by-entry arithmetic mean of matrices sampled at the N cage angles of one ball pass
/// (as BallPassStiffness::mean: Σ_k M_k / N, summed in order). Throws std::logic_error when empty.
Matrix5 ball_pass_mean(const std::vector<Matrix5>& samples);

/// The rotor coefficients of a ball pass: its mean K and C and the warnings about K.
RotorCoefficients rotor_coefficients(const BallPassStiffness& pass);

/// Why a rotor model's K (a ball-pass mean) is singular or near it, one sentence a reason: no
/// stiffness at all (no ball loaded at any cage angle), or the block of the translations or of
/// the tilts near singular (kNearSingularRatio), naming its smallest eigenvalue, the direction
/// and the ratio. Empty when neither is.
std::vector<std::string> rotor_stiffness_warnings(const Matrix5& K);

}  // namespace bearing
