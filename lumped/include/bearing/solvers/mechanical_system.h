#pragma once
// A mechanical system  M q̈ = f(t, q, q̇)  with a diagonal mass matrix: the form every bearing model
// takes, and the only thing the integrators know about a model.

#include <vector>

namespace bearing {

class MechanicalSystem {
 public:
  virtual ~MechanicalSystem() = default;

  /// Number of degrees of freedom n.
  virtual int dofs() const = 0;

  /// Diagonal of the mass matrix, n entries [kg, or kg m² for a rotation].
  virtual void mass(double* m) const = 0;

  /// Total generalised force on each DOF, f(t, q, v), n entries [N or N m]: external loads,
  /// contact forces, damping and friction. Must not allocate (it runs in the integrators' hot loop)
  /// and must be safe to call concurrently on one object from several threads.
  virtual void force(double t, const double* q, const double* v, double* f) const = 0;

  /// ∂f/∂q and ∂f/∂v, each n×n row-major (entry [i*n + j] = ∂f_i/∂q_j). The default uses central
  /// differences of force(); models override it with the analytic form where an implicit method
  /// needs it to be fast.
  virtual void force_jacobian(double t, const double* q, const double* v, double* dfdq,
                              double* dfdv) const;

  /// Whether DOF i (0 ≤ i < n) is cyclic: an angle [rad] no force depends on (a ball's spin
  /// angle), unbounded as it turns; only its velocity [rad/s] enters f. The integrators exempt a
  /// cyclic q_i from the blow-up bound (it must only stay finite), leave its error out of the
  /// adaptive methods' step-size control (its velocity is still controlled), and apply Newmark's
  /// relative Newton tolerance to its increment over a step rather than its accumulated value.
  virtual bool cyclic(int /*i*/) const { return false; }
};

}  // namespace bearing
