#pragma once
// A bearing model: a MechanicalSystem whose DOFs include the inner-ring centre, plus what the
// outputs need (DOF names, ball loads) and what the physics tests need (potential energy).

#include <stdexcept>
#include <string>
#include <vector>

#include "bearing/models/model_outputs.h"
#include "bearing/solvers/mechanical_system.h"

namespace bearing {

/// A model's further DOFs beyond dof_names() (the ball-DOF model's radial positions and spins)
/// reach the output through the per-ball fields.
class BearingModel : public MechanicalSystem, public ModelOutputs {
 public:
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
  /// With the EHL film ([lubricant], film_law.h) the ball rides on the outer contact's film: its
  /// load Q_j is the film law's (never 0), and the film under it is the one that carries the load
  /// pressing the ball on the outer race, Q_j + F_c (F_c = m_b ω_c² d_m/2, the centrifugal load
  /// that keeps an unloaded ball there):
  ///     δ_o,j = (Q_j/K_o)^{1/n_o} − h_o,   h_o = C_o (Q_j + F_c)^−0.067 [m],
  /// so r_j falls by h_o (a few tenths of a micron) from the dry law's at the same load, and an
  /// unloaded ball sits on its outer film. (The output.ball_film channel ho_j is the film under
  /// Q_j alone, the contact's: for an unloaded ball its open gap.)
  /// The ball-DOF kind: r_j is its DOF, and its outer contact's film law carries Q_o,j at that
  /// same δ_o,j (ball_dofs.h).
  virtual void ball_motion(double t, const double* q, const double* v, double* r,
                           double* vr) const = 0;

  /// Elastic potential energy stored in the contacts at (t, q) [J]: Σ_j K/(n+1) [δ_j]_+^{n+1}.
  virtual double potential_energy(double t, const double* q) const = 0;

  /// A starting state near equilibrium (the static solution under the mean load), n entries [m].
  virtual std::vector<double> initial_displacement() const = 0;

  /// The starting velocities, n entries [m/s, rad/s]: at rest, unless the model has DOFs that
  /// turn (the ball-DOF model's spins start at their kinematic speed).
  virtual std::vector<double> initial_velocity() const {
    return std::vector<double>(static_cast<std::size_t>(dofs()), 0.0);
  }

  /// The ball-DOF model's per-ball channels at (t, q, v), Z entries each: the spin ω_b,j relative
  /// to the cage [rad/s], the outer-race load Q_o,j [N] (ball_loads gives the inner one), and the
  /// tangential friction forces on the ball at its inner and outer contact [N], positive in the
  /// direction of rotation. Throws std::logic_error for a model without ball DOFs.
  virtual void ball_dynamics(double /*t*/, const double* /*q*/, const double* /*v*/,
                             double* /*spin*/, double* /*outer_load*/, double* /*friction_inner*/,
                             double* /*friction_outer*/) const {
    throw std::logic_error("ball_dynamics: this model has no ball DOFs");
  }

  /// Each ball's central EHL film thickness h_c at its inner and outer contact at (t, q) [m], Z
  /// entries each (output.ball_film). Throws std::logic_error for a dry model.
  virtual void film_thickness(double /*t*/, const double* /*q*/, double* /*inner*/,
                              double* /*outer*/) const {
    throw std::logic_error("film_thickness: the model is dry (no [lubricant])");
  }

  /// The per-ball fields from the calls above.
  void ball_state(double t, const double* q, const double* v, BallFields fields,
                  BallState& s) const override {
    if (has(fields, BallField::load)) ball_loads(t, q, s[BallField::load].data());
    if (has(fields, BallField::approach)) ball_approaches(t, q, s[BallField::approach].data());
    if (has(fields, BallField::radial) || has(fields, BallField::radial_velocity))
      ball_motion(t, q, v, s[BallField::radial].data(), s[BallField::radial_velocity].data());
    if (has(fields, BallField::spin) || has(fields, BallField::outer_load) ||
        has(fields, BallField::friction_inner) || has(fields, BallField::friction_outer))
      ball_dynamics(t, q, v, s[BallField::spin].data(), s[BallField::outer_load].data(),
                    s[BallField::friction_inner].data(), s[BallField::friction_outer].data());
    if (has(fields, BallField::film_inner) || has(fields, BallField::film_outer))
      film_thickness(t, q, s[BallField::film_inner].data(), s[BallField::film_outer].data());
  }
};

}  // namespace bearing
