#pragma once
// Static load distribution of a radial ball bearing: the inner-ring displacement (x, y) that puts
// the ball set in equilibrium with a radial load, with clearance (docs/model.md §1 and §4).
//
// Ball j sits at θ_j = φ₀ + 2π j / Z (j = 0…Z−1), its approach is δ_j = x cos θ_j + y sin θ_j − γ,
// and its load Q_j = K [δ_j]_+^n. Equilibrium of the inner ring: Σ_j Q_j (cos θ_j, sin θ_j) = F.

#include <vector>

#include <Eigen/Dense>

namespace bearing {

struct StaticLoadOptions {
  double phase = 0.0;        ///< φ₀, angle of ball 0 from the +x axis [rad]
  double exponent = 1.5;     ///< load–deflection exponent n [-]
  double tolerance = 1e-12;  ///< relative force-balance tolerance |Σ Q e − F| / |F| [-]
  int max_iterations = 200;  ///< Newton iterations before giving up
};

struct StaticLoadResult {
  Eigen::Vector2d deflection = Eigen::Vector2d::Zero();  ///< inner-ring centre (x, y) [m]
  std::vector<double> ball_angles;                       ///< θ_j [rad]
  std::vector<double> ball_approach;                     ///< δ_j (negative: gap remains) [m]
  std::vector<double> ball_loads;                        ///< Q_j ≥ 0 [N]
  double q_max = 0.0;                                    ///< max_j Q_j [N]
  double residual = 0.0;  ///< |Σ Q e − F| / |F| at the solution [-] (0 for F = 0)
  int iterations = 0;     ///< Newton iterations used
};

/// Solves the static equilibrium for `balls` ≥ 3 balls with constant K [N/m^n] per ball (series,
/// both races), per-ball radial gap `gap` ≥ 0 [m] (half the diametral clearance) and radial load
/// `load` = (F_x, F_y) [N] on the inner ring. Needs no initial guess (it starts from the point
/// where the ring first touches the balls in the load direction) and converges for every valid
/// input; throws SolverError saying why if it does not. For F = 0 returns x = y = 0.
StaticLoadResult solve_static_load(int balls, double K, double gap, const Eigen::Vector2d& load,
                                   const StaticLoadOptions& options = {});

}  // namespace bearing
