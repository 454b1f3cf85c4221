#pragma once
// The quasi-static model of seed 000 (docs/model.md §4): no inertia and no damping; at each instant
// the inner-ring centre p = (x, y) is where the ball set balances the load,
//
//   g(p, t) = Σ_j Q_j(p, t) (cos θ_j, sin θ_j) − F(t) = 0,   Q_j = K_j [δ_j]_+^n,
//   δ_j = x cos θ_j + y sin θ_j − γ + Π_i(θ_j − ω_i t) + Π_o(θ_j) − ΔD_j,
//   F(t) = (F_x, F_y − m g) + F_u (cos ω_i t, sin ω_i t)   (−m g only with gravity),
//
// with the 2-DOF model's ball angles, excitations, contact law (TVDS and calibrated exponents
// included) and cage speed. g = ∇V of the convex potential V(p) = Σ_j K_j/(n+1) [δ_j]_+^{n+1} −
// F·p, so the balance is a minimisation; V is strictly convex wherever two non-collinear balls are
// loaded, and coercive for Z ≥ 3 evenly spaced balls (every direction pushes some ball in).
//
// Solution: Newton on the two unknowns, continued from the previous instant, full steps accepted
// while |g| falls; otherwise (singular Jacobian, no decrease) a Levenberg-damped Newton with an
// Armijo line search on V, which converges for a convex coercive V from any start. Every instant
// is solved to |g| ≤ 1e-12 |F| (rounding level; solver.tolerance is not used: a looser balance
// would make the implicit-function velocity inconsistent with the orbit). Above 1e-9 |F| the
// solve fails with a SolverError naming the time.
//
// Velocity by the implicit function theorem: dp/dt = −J⁻¹ ∂g/∂t, J = ∂g/∂p =
// Σ n K_j δ_j^{n−1} e_j e_jᵀ over the loaded balls (e_j = (cos θ_j, sin θ_j)), and
//   ∂g/∂t = Σ_j [∂Q_j/∂t e_j + Q_j ω_c (−sin θ_j, cos θ_j)] − dF/dt,
//   ∂Q_j/∂t = n K_j δ_j^{n−1} [ω_c (−x sin θ_j + y cos θ_j) + de_j/dt] + dK_j/dt δ_j^n,
//   dF/dt = F_u ω_i (−sin ω_i t, cos ω_i t),
// with de_j/dt through the race-fixed angles (outer θ_j, inner θ_j − ω_i t).
//
// Minimum load. With F = 0 and clearance the ring floats anywhere in the clearance (no unique
// equilibrium). With F ≠ 0 force balance needs two loaded balls unless F points exactly at one
// ball; at that instant, if that ball's neighbours (at ψ = 2π/Z) are out of contact, a single ball
// holds the ring, J is singular (nothing resists a tangential motion) and the orbit jumps across
// the clearance from "ball j+1 just touching" to "ball j−1 just touching": the quasi-static orbit
// is not a motion any more. For the nominal bearing the neighbours are loaded at that instant iff
// the displacement d along the load line exceeds γ/cos ψ, where the load-line ball carries
// K (d − γ)^n, so (exact, necessary and sufficient for a continuous nominal orbit)
//   F_min = K [γ (1/cos ψ − 1)]^n,  required: min_t |F(t)| > F_min,  and always |F| > 0,
// with min_t |F(t)| = |(F_x, F_y − m g)| − F_u. The 608 at γ = 2.5 µm: F_min ≈ 12 N.
// Excitations can still unload a neighbour at such an instant. A sufficient load for a smooth
// orbit under every excitation: with E₋ the most they can reduce an approach (Σ A_i + Σ A_o +
// max_j ΔD_j) and E₊ the most they can add (Σ A_i + Σ A_o + max_j (−ΔD_j)), the neighbours are
// loaded once d > d* = (γ + E₋)/cos ψ, and below d* the load-line ball alone carries at most
// K (d* − γ + E₊)^n, so
//   F_smooth = K [(γ + E₋)/cos ψ − γ + E₊]^n.
// It is conservative (the worst excitations rarely meet on neighbouring balls), so it is not
// enforced: between F_min and F_smooth the run goes on and counts the jumps it meets
// (QuasiStaticStats). For Z ≤ 4 (cos ψ ≤ 0) no load keeps the neighbours loaded: F_min = 0
// (only |F| > 0 is required) and F_smooth = ∞. K is the nominal constant (TVDS changes it by a
// small fraction).

#include <functional>
#include <memory>

#include <Eigen/Dense>

#include "bearing/models/model_inputs.h"

namespace bearing {

/// The equilibrium of the inner ring at one instant.
struct QuasiStaticPoint {
  double t = 0;                                        ///< time [s]
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  ///< (x, y) [m]
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();  ///< dp/dt (implicit function) [m/s]
  double residual = 0;                                 ///< |g| / |F(t)| at the solution [-]
  int loaded_balls = 0;                                ///< balls with δ_j > 0
  int iterations = 0;                                  ///< Newton iterations (damped ones included)
  bool fallback = false;                               ///< the damped Newton on V was needed
};

/// Statistics of a followed orbit (summary.json "solver").
struct QuasiStaticStats {
  long steps = 0;                    ///< instants solved
  long newton_iterations = 0;        ///< total Newton iterations
  long fallbacks = 0;                ///< instants that needed the damped Newton on V
  double max_relative_residual = 0;  ///< max over instants of |g|/|F| [-]
  int min_loaded_balls = 0;          ///< fewest loaded balls at any instant
  long contact_changes = 0;          ///< balls entering or leaving contact between samples
  /// Samples where the orbit jumps: the step |Δp| disagrees with the trapezoid of the analytic
  /// velocities, |Δp − Δt (v_k + v_{k+1})/2| > |Δp|/2, by more than 1 % of the static
  /// deflection (a ball leaving contact with J nearly singular).
  long jumps = 0;
  double largest_jump = 0;  ///< largest |Δp| of a jump [m]
  double minimum_load = 0;  ///< F_min [N]
  double smooth_load = 0;   ///< F_smooth [N]
};

class QuasiStaticModel {
 public:
  virtual ~QuasiStaticModel() = default;

  /// Number of balls Z.
  virtual int balls() const = 0;
  /// The cage speed ω_c the balls turn at [rad/s].
  virtual double cage_speed() const = 0;
  /// Whether the cage slips randomly, and its angle error φ(t) [rad] (random_slip.h).
  virtual bool has_cage_slip() const { return false; }
  virtual double cage_slip_angle(double /*t*/) const { return 0.0; }
  /// F_min of the header [N].
  virtual double minimum_load() const = 0;
  /// F_smooth of the header [N].
  virtual double smooth_load() const = 0;
  /// The static solution (solve_static_load) under the constant load, no excitation [m].
  virtual Eigen::Vector2d static_position() const = 0;
  /// The load on the ring at time t, F(t) [N].
  virtual Eigen::Vector2d load(double t) const = 0;
  /// The equilibrium at time t from the starting point `guess` [m]. Throws SolverError if the
  /// balance cannot be brought below 1e-9 |F|.
  virtual QuasiStaticPoint solve(double t, const Eigen::Vector2d& guess) const = 0;
  /// Each ball's load Q_j at (t, position) [N], Z entries.
  virtual void ball_loads(double t, const Eigen::Vector2d& position, double* loads) const = 0;
  /// Each ball's signed approach δ_j at (t, position) [m], Z entries (bearing_model.h).
  virtual void ball_approaches(double t, const Eigen::Vector2d& position,
                               double* approaches) const = 0;
  /// Each ball centre's radial displacement r_j [m] and velocity vr_j [m/s] (bearing_model.h),
  /// Z entries each, at an equilibrium with its velocity.
  virtual void ball_motion(const QuasiStaticPoint& point, double* r, double* vr) const = 0;
};

/// F_min of the header for these inputs [N].
double quasi_static_minimum_load(const ModelInputs& inputs);

/// F_smooth of the header for these inputs [N] (infinite for Z ≤ 4).
double quasi_static_smooth_load(const ModelInputs& inputs);

/// Builds the model. Throws InputError naming the case key for invalid inputs (as
/// make_two_dof_model; rotor.mass only matters with gravity, rotor.damping not at all), and for
/// min_t |F(t)| ≤ F_min naming operation.load, its value and the minimum.
std::unique_ptr<QuasiStaticModel> make_quasi_static_model(const ModelInputs& inputs);

/// Solves the equilibrium at each of `times` (ascending), each continued from the previous one
/// (the first from the static solution), and passes each point to `observe`, in order.
/// `progress` (optional) gets the fraction done now and then.
QuasiStaticStats follow_equilibrium(const QuasiStaticModel& model, const std::vector<double>& times,
                                    const std::function<void(const QuasiStaticPoint&)>& observe,
                                    const std::function<void(double)>& progress = {});

}  // namespace bearing
