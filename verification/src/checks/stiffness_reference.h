#pragma once
// The checks' own inner ring on Z Hertzian balls at rest (the stiffness family's reference),
// written from the groove geometry without five_dof_static.cc: the groove centres as points in
// space, the ring's small displacement moving the inner ones, each ball's approach the distance of
// its two centres in its radial plane (Harris's and ISO/TS 16281's projection of the ring's
// motion on each ball's plane) less A₀, the load Q = K δ^{3/2} along that line. The stiffness is
// the central difference of the load, never an analytic Hessian; the equilibrium is Newton's on
// those differences. Coordinates and units as five_dof_static.h: q = (δx, δy, δz, γx, γy) [m, m,
// m, rad, rad], F = (Fx, Fy, Fz, Mx, My) [N, N, N, N m, N m].

#include <array>

#include "bearing/bearing.h"
#include "bearing/five_dof_static.h"  // Vector5, Matrix5 only

namespace bearing::verify::reference {

struct RingOnBalls {
  int balls = 0;
  double K = 0;          ///< series constant of one ball [N/m^1.5]
  double A0 = 0;         ///< (f_i + f_o − 1) D [m]
  double inner_rho = 0;  ///< radius of the inner groove centres, ring centred [m]
  double outer_rho = 0;  ///< radius of the outer groove centres [m]
  double phase = 0;      ///< ball 0's angle from +x toward +y [rad]

  /// Ball j's approach δ_j at q [m] (negative: the gap left).
  double approach(int j, const Vector5& q) const;
  /// The load that holds the ring at q: Σ_j Q_j ∂δ_j/∂q [N, N m].
  Vector5 load(const Vector5& q) const;
  /// Central differences of load() at q with the step h [m] (tilts: h over inner_rho).
  Matrix5 stiffness(const Vector5& q, double h) const;
  /// The smallest |δ_j| over the balls at q [m]: the distance to the nearest kink of the load.
  double nearest_kink(const Vector5& q) const;
  /// The q with load(q) = F in the DOFs not held (held ones stay as in `start`), by Newton on
  /// the central-difference stiffness with step 1e-4 of nearest_kink, the step halved until the
  /// energy or the residual falls, to |residual| ≤ 1e-12 |F| (moments over inner_rho; the load's
  /// rounding, ε A₀/δ relative, keeps it from much less). The energy is convex,
  /// so the root is the same from any start. Throws std::runtime_error when it is not reached.
  Vector5 equilibrium(const Vector5& F, Vector5 start, const std::array<bool, 5>& held = {}) const;
};

/// `b` at rest with the constant K [N/m^1.5], ball 0 at `phase` [rad]: the groove centres from
/// d_m, D, f_i, f_o and P_d split evenly between the races, ρ_i = d_m/2 − D/2 − P_d/4 + f_i D and
/// ρ_o = d_m/2 + D/2 + P_d/4 − f_o D.
RingOnBalls ring_on_balls(const Bearing& b, double K, double phase);

}  // namespace bearing::verify::reference
