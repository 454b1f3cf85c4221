#pragma once
// The time-varying stiffness over one ball pass (issue 32): the parametric excitation the dynamic
// models feel. As the cage turns, the balls pass the load zone and the 5-DOF stiffness
// (five_dof_static.h) of the ring under a constant load varies with the cage angle φ; the ball
// set repeats after one pitch 2π/Z, so K(φ) is periodic in it, and in time its harmonics are those
// of the ball-pass frequency over the outer race (BPFO, m = 1, 2, …).
//
// K is sampled at N cage angles φ₀ + k (2π/Z)/N, k = 0 … N−1, each at its own equilibrium under
// the same load (the ring moves a little as the balls pass), and each entry's samples give
//     mean, min, max,   and   c_m = (2/N) |Σ_k K_k e^{−2πi m k/N}|   (m = 1 … N/2 − 1),
// the amplitude of its m-th BPFO harmonic (a real periodic signal sampled N times a period).

#include <vector>

#include "bearing/five_dof_static.h"

namespace bearing {

struct BallPassStiffness {
  std::vector<double> cage_angles;  ///< φ_k [rad]
  std::vector<Matrix5> samples;     ///< K at each φ_k
  Matrix5 mean = Matrix5::Zero();   ///< over one pitch
  Matrix5 min = Matrix5::Zero();    ///< entry by entry
  Matrix5 max = Matrix5::Zero();
  /// harmonics[m − 1]: each entry's amplitude at m × BPFO, m = 1 … N/2 − 1 (units of K).
  std::vector<Matrix5> harmonics;
  /// The squeeze films' damping C at each φ_k and its mean over one pitch [N s/m, N s/rad, N s,
  /// N m s/rad] (five_dof_static.h; 0 for dry contacts).
  std::vector<Matrix5> damping_samples;
  Matrix5 damping_mean = Matrix5::Zero();
};

/// K over one ball pass of `b` (its phase the first cage angle) under `load` (as solve_five_dof,
/// with `held`), at `samples` ≥ 4 cage angles. Throws InputError for fewer samples, SolverError
/// as solve_five_dof.
BallPassStiffness ball_pass_stiffness(const FiveDofBearing& b, const Vector5& load,
                                      int samples = 32, const HeldDofs& held = {});

}  // namespace bearing
