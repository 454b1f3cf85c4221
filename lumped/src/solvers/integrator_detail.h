#pragma once
// What the integrators share (private to lumped/src/solvers): the per-method factories that
// make_integrator dispatches to, validation of an integrate() call, the blow-up check, the rule
// that lands a fixed step on an output time, and the progress throttle.

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <gsl/gsl_odeiv2.h>

#include "bearing/solvers/integrator.h"

namespace bearing {
namespace solvers_detail {

// Factories for the concrete methods; the settings are already validated by make_integrator.
std::unique_ptr<Integrator> make_rk4(const IntegratorSettings& settings);
/// method is "rkf45" or "rk8pd".
std::unique_ptr<Integrator> make_gsl_adaptive(const IntegratorSettings& settings);
std::unique_ptr<Integrator> make_newmark(const IntegratorSettings& settings);
std::unique_ptr<Integrator> make_bdf(const IntegratorSettings& settings);

/// What the GSL callbacks see through gsl_odeiv2_system::params: the model, 1/m, counters, work
/// arrays for force_jacobian, and an exception the model threw inside a callback (it is carried
/// across GSL's C frames and rethrown after gsl_odeiv2_evolve_apply returns).
struct GslContext {
  const MechanicalSystem* system = nullptr;
  int n = 0;
  const double* inv_mass = nullptr;  ///< 1/m_i [1/kg]
  double* dfdq = nullptr;            ///< n×n work array
  double* dfdv = nullptr;            ///< n×n work array
  long force_evaluations = 0;
  long jacobian_evaluations = 0;
  std::exception_ptr error;
  // A non-finite force ends the step with GSL_EBADFUNC; where it happened:
  double bad_time = 0.0;
  int bad_dof = -1;
  double bad_value = 0.0;
};

/// The Jacobian callback of gsl_odeiv2_system (params is a GslContext*), or nullptr.
using GslJacobian = int (*)(double t, const double y[], double* dfdy, double dfdt[], void* params);

/// integrate() for a GSL odeiv2 stepper with error control (gsl_adaptive.cc): rkf45, rk8pd, and
/// msbdf (bdf.cc, which passes the Jacobian callback). `method` names it in messages.
IntegrationStats integrate_gsl(const std::string& method, const gsl_odeiv2_step_type* type,
                               GslJacobian jacobian, const IntegratorSettings& settings,
                               const MechanicalSystem& system, double t0,
                               const std::vector<double>& q0, const std::vector<double>& v0,
                               const std::vector<double>& output_times, const Observer& observe,
                               const Progress& progress);

/// Checks one integrate() call and returns the inverse masses 1/m_i [1/kg]. Throws InputError when
/// q0 or v0 do not have dofs() entries or are not finite, when a mass is not positive and finite,
/// or when the output times are not finite, not ascending or start before t0.
std::vector<double> check_call(const std::string& method, const MechanicalSystem& system, double t0,
                               const std::vector<double>& q0, const std::vector<double>& v0,
                               const std::vector<double>& output_times);

/// The blow-up test after an accepted step: every q_i and v_i finite and |q_i| ≤ max_displacement.
/// Throws SolverError naming the method, the time t [s], the step number, the step dt [s], what
/// went wrong, and that solver.dt should be reduced. `step` 0 means the initial state. The test
/// is inline (it runs after every step); the message is built out of line.
[[noreturn]] void report_bad_state(const std::string& method, double t, long step, double dt,
                                   const double* q, const double* v, int n,
                                   double max_displacement);
inline void check_state(const std::string& method, double t, long step, double dt, const double* q,
                        const double* v, int n, double max_displacement) {
  bool good = true;
  // |q| ≤ bound is false for NaN; v − v is 0 for finite v and NaN otherwise.
  for (int i = 0; i < n; ++i) good &= (std::abs(q[i]) <= max_displacement) & (v[i] - v[i] == 0.0);
  if (!good) report_bad_state(method, t, step, dt, q, v, n, max_displacement);
}

/// A number for messages: 7 significant digits ("0.001956513", "5.651348e-05").
std::string format_brief(double value);

/// Throws the blow-up SolverError: "<method>: the solution blew up at t = … s (step N, dt = … s):
/// <what>; reduce solver.dt or check the load/clearance".
[[noreturn]] void throw_blow_up(const std::string& method, double t, long step, double dt,
                                const std::string& what);

/// The acceleration a = f/M handed to the observer must be finite; throws SolverError like
/// check_state otherwise.
void check_acceleration(const std::string& method, double t, long step, double dt, const double* a,
                        int n);

/// Fixed-step landing: a step of dt from t is shortened to end exactly at t_out when it would pass
/// it; when t_out is beyond t + dt by less than kLandingSlack·dt (a rounding remnant of the output
/// grid), the step is lengthened by that sliver instead of leaving a step of ~1e-6 dt behind.
constexpr double kLandingSlack = 1e-6;
inline bool final_step_to(double t, double dt, double t_out) {
  return t_out - t <= dt * (1.0 + kLandingSlack);
}

/// Calls a Progress at most 101 times per run: 0 at the start, once whenever another 1 % of
/// [t0, t_end] is done, and 1 at the end (finish()).
class ProgressThrottle {
 public:
  ProgressThrottle(const Progress& progress, double t0, double t_end)
      : progress_(progress), t0_(t0), span_(t_end - t0) {
    if (progress_) progress_(0.0);
    next_ = (progress_ && span_ > 0) ? threshold(1) : std::numeric_limits<double>::infinity();
  }
  /// Cheap enough for every step: one comparison unless a report is due.
  void update(double t) {
    if (t >= next_) report(t);
  }
  void finish() {
    if (progress_) progress_(1.0);
  }

 private:
  double threshold(int percent) const { return t0_ + span_ * percent / 100.0; }
  void report(double t) {
    while (percent_ <= 100 && threshold(percent_) <= t) ++percent_;
    if (t < t0_ + span_) progress_((t - t0_) / span_);  // 1 is reported once, by finish()
    next_ = percent_ <= 99 ? threshold(percent_) : std::numeric_limits<double>::infinity();
  }

  const Progress& progress_;
  double t0_;
  double span_;
  double next_;
  int percent_ = 1;  // the next whole percent to report
};

}  // namespace solvers_detail
}  // namespace bearing
