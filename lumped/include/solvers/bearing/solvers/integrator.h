#pragma once
// Time integration of a MechanicalSystem, one interface for every method (selected in [solver]).
// Output is recorded at prescribed times, independent of the internal step (exact step landing or
// dense output), so every method writes the same samples.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bearing/choice.h"
#include "bearing/contact_loop.h"
#include "bearing/solvers/mechanical_system.h"

namespace bearing {

/// The integration methods ([solver] method), each one file in src/solvers/.
enum class IntegratorMethod { rk4, rkf45, rk8pd, rk8pd_events, newmark, bdf };
inline constexpr Named<IntegratorMethod> kIntegratorMethods[] = {
    {IntegratorMethod::rk4, "rk4"},         {IntegratorMethod::rkf45, "rkf45"},
    {IntegratorMethod::rk8pd, "rk8pd"},     {IntegratorMethod::rk8pd_events, "rk8pd-events"},
    {IntegratorMethod::newmark, "newmark"}, {IntegratorMethod::bdf, "bdf"}};

/// The [solver] table: how a model is integrated and sampled. Defaults: RK4 at 5 µs (seeds 002/003)
/// for 1.2 s, the first 0.2 s discarded as transient, output at 20 kHz.
struct SolverSettings {
  IntegratorMethod method = IntegratorMethod::rk4;
  double dt = 5e-6;        ///< step (fixed-step methods) or first step [s]
  double duration = 1.2;   ///< simulated time [s]
  double transient = 0.2;  ///< discarded before statistics and spectra [s]
  /// Relative tolerance (adaptive, bdf, Newton) [-]; the absolute one on displacements is
  /// tolerance × max(|q0|, P_d/2, 1 um).
  double tolerance = 1e-6;
  double output_rate = 20000.0;    ///< samples per second written [Hz]
  double max_displacement = 1e-3;  ///< blow-up bound on the ring displacement [m]
  ContactLoop contact_loop = ContactLoop::simd;  ///< the models' per-ball loop (same bits)
};

struct IntegratorSettings {
  IntegratorMethod method = IntegratorMethod::rk4;
  double dt = 5e-6;     ///< fixed step (rk4, newmark) or initial step (adaptive) [s]
  double rtol = 1e-6;   ///< relative tolerance (adaptive, bdf; newmark's Newton) [-]
  double atol = 1e-12;  ///< absolute tolerance on displacements [m] (velocities scaled) [-]
  /// Blow-up bound on |q_i| [m]; exceeded → SolverError. Cyclic DOFs (MechanicalSystem::cyclic)
  /// are exempt: they must only stay finite.
  double max_displacement = 1e-3;
  /// The largest step the adaptive methods (rkf45, rk8pd, bdf) take [s]; 0: no limit. A run with
  /// local defects sets it so that no step jumps over one (the error control sees only the step's
  /// ends and nodes, and would not notice a defect crossed between them).
  double max_step = 0.0;
};

/// Called at each output time with the state there and the acceleration a = f/M.
using Observer = std::function<void(double t, const double* q, const double* v, const double* a)>;
/// Called now and then with the fraction of the run done, in [0, 1].
using Progress = std::function<void(double fraction)>;

struct IntegrationStats {
  long steps = 0;              ///< accepted steps
  long rejected_steps = 0;     ///< rejected steps (adaptive methods)
  long force_evaluations = 0;  ///< calls of MechanicalSystem::force (or force_with)
  long jacobian_evaluations = 0;
  long events = 0;  ///< steps ended on a switching event (rk8pd-events)
};

class Integrator {
 public:
  virtual ~Integrator() = default;

  /// Integrates from t0 with q(t0) = q0, v(t0) = v0 (n entries each) and calls `observe` at each
  /// of `output_times` (ascending, the first ≥ t0). Throws SolverError on blow-up (NaN/Inf, or
  /// |q_i| > max_displacement for a DOF that is not cyclic) naming the time, the step and what to
  /// change, before the observer sees any non-finite value.
  virtual IntegrationStats integrate(const MechanicalSystem& system, double t0,
                                     const std::vector<double>& q0, const std::vector<double>& v0,
                                     const std::vector<double>& output_times,
                                     const Observer& observe,
                                     const Progress& progress = {}) const = 0;

  /// The [solver] method name.
  virtual std::string name() const = 0;
};

/// The integrator for settings.method; throws InputError naming `solver.dt` / `solver.tolerance`
/// for invalid values.
std::unique_ptr<Integrator> make_integrator(const IntegratorSettings& settings);

/// The method names make_integrator accepts.
std::vector<std::string> integrator_names();

/// The largest fixed step for which RK4 is stable on the system linearised at (t, q, v).
struct StepLimit {
  double step = 0.0;  ///< h_max [s] (infinity when nothing limits it)
  double real = 0.0;  ///< the limiting eigenvalue λ of the first-order system, Re [1/s]
  double imag = 0.0;  ///< and |Im| [rad/s]: an oscillation, or (≈ 0) a relaxation rate −Re
};

/// Every eigenvalue λ of the first-order Jacobian [[0, I], [M⁻¹ ∂f/∂q, M⁻¹ ∂f/∂v]]
/// (force_jacobian) must satisfy |R(hλ)| ≤ 1, R(z) = 1 + z + z²/2 + z³/6 + z⁴/24 (RK4's stability
/// function): h ≤ 2√2/ω for an undamped oscillation ω, h ≤ 2.785/|λ| for a relaxation. Both the
/// oscillations of stiff contacts and the fast relaxations of stiff damping or traction limit it.
/// An eigenvalue with Re λ > 0 (a state that is unstable itself) is taken on the imaginary axis.
StepLimit rk4_step_limit(const MechanicalSystem& system, double t, const double* q,
                         const double* v);

}  // namespace bearing
