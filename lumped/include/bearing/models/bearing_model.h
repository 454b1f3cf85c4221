#pragma once
// A bearing model: a MechanicalSystem whose DOFs include the inner-ring centre, plus what the
// outputs need (DOF names, ball loads) and what the physics tests need (potential energy).

#include <string>
#include <vector>

#include "bearing/solvers/mechanical_system.h"

namespace bearing {

class BearingModel : public MechanicalSystem {
 public:
  /// Names of the DOFs, used as output channel stems: {"x", "y"} (2-DOF), {"x", "y", "z"} (3-DOF).
  virtual std::vector<std::string> dof_names() const = 0;

  /// Number of balls Z.
  virtual int balls() const = 0;

  /// Each ball's contact load Q_j ≥ 0 at (t, q) [N], Z entries (for the ball-DOF model, the
  /// inner-race load).
  virtual void ball_loads(double t, const double* q, double* loads) const = 0;

  /// Elastic potential energy stored in the contacts at (t, q) [J]: Σ_j K/(n+1) [δ_j]_+^{n+1}.
  virtual double potential_energy(double t, const double* q) const = 0;

  /// A starting state near equilibrium (the static solution under the mean load), n entries [m].
  virtual std::vector<double> initial_displacement() const = 0;
};

}  // namespace bearing
