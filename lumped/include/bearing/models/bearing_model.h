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

  /// Each ball's approach δ_j at (t, q) [m], Z entries, signed: positive, the elastic approach
  /// of the ball between both races that carries Q_j; negative, the gap left to contact. 2-DOF:
  /// δ_j = x cos θ_j + y sin θ_j − γ + Π_i + Π_o − ΔD_j; 3-DOF: along the loaded contact line.
  virtual void ball_approaches(double t, const double* q, double* approaches) const = 0;

  /// Each ball centre's radial motion at (t, q, v) (output.ball_motion; output instants only), Z
  /// entries each: r[j] [m], the ball centre's radial displacement from the pitch radius d_m/2,
  /// and vr[j] = dr_j/dt [m/s], analytic (chain rule through the contact law, not differences).
  ///
  /// Definition: the ball rides on the outer race (centrifugal force keeps an unloaded ball
  /// there). The ball is two springs in series carrying the same load Q_j, so its approach to the
  /// outer race is δ_o,j = (Q_j/K_o)^{1/n_o} (0 out of contact), and with the outer waviness
  /// Π_o(θ_j) (positive toward the ball: it pushes the ball inward) and the ball's own size error
  /// (a ball smaller by ΔD_j sits ΔD_j/2 further out on the same race)
  ///     r_j = δ_o,j − Π_o(θ_j) + ΔD_j/2.
  /// The toolkit's outer raceway diameter is d_m + D (the clearance is the per-ball gap γ on the
  /// inner side), so r_j = 0 is a nominal ball just touching the perfect outer race, at d_m/2.
  /// 3-DOF: δ_o,j acts along the loaded contact line, so r_j takes its radial part δ_o,j cos α_j.
  virtual void ball_motion(double t, const double* q, const double* v, double* r,
                           double* vr) const = 0;

  /// Elastic potential energy stored in the contacts at (t, q) [J]: Σ_j K/(n+1) [δ_j]_+^{n+1}.
  virtual double potential_energy(double t, const double* q) const = 0;

  /// A starting state near equilibrium (the static solution under the mean load), n entries [m].
  virtual std::vector<double> initial_displacement() const = 0;
};

}  // namespace bearing
