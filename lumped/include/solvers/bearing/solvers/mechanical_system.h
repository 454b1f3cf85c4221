#pragma once
// A mechanical system  M q̈ = f(t, q, q̇)  with a diagonal mass matrix: the form every bearing model
// takes, and the only thing the integrators know about a model.

#include <memory>
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

  /// What one caller of force_with() lends the system between its calls; a system derives its
  /// own (the bearing models keep the ball set at the last t in it).
  class Workspace {
   public:
    virtual ~Workspace() = default;
  };

  /// A workspace for force_with(), made once per integration (it may allocate), or nullptr (the
  /// default) for a system that keeps nothing between calls.
  virtual std::unique_ptr<Workspace> make_workspace() const;

  /// force() for a caller that owns `workspace` (made by this object's make_workspace(), or
  /// nullptr): the same f to the bit, but what depends on t alone may be kept in the workspace
  /// and reused while t repeats (RK4 asks twice at t + h/2, and again at t + h when the next step
  /// starts). The integrators make one workspace per integrate() and pass it to every call. Must
  /// not allocate; calls with distinct workspaces may run concurrently on one object, and one
  /// workspace serves one thread at a time. The default calls force().
  virtual void force_with(Workspace* workspace, double t, const double* q, const double* v,
                          double* f) const;

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

  /// Number of switching functions (0, the default: none; see switching_functions()).
  virtual int switching_count() const { return 0; }

  /// The switching functions g_k(t, q), switching_count() entries: quantities whose sign change
  /// marks a point where f(t, q, v) is not smooth in time, e.g. a bearing model's signed ball
  /// approaches δ_j [m] (f has an unbounded second derivative where a contact opens or closes,
  /// δ_j = 0). An event-locating integrator (rk8pd-events) ends a step where one changes sign
  /// and restarts there, so no step straddles the kink. Sign convention: g_k > 0 is one side,
  /// g_k ≤ 0 the other (a contact is loaded for δ_j > 0). Must not allocate.
  virtual void switching_functions(double /*t*/, const double* /*q*/, double* /*g*/) const {}
};

}  // namespace bearing
