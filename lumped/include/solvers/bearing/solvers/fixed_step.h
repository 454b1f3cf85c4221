#pragma once
// What every fixed-step loop of an integrator shares (lumped/src/solvers, and the models'
// statically dispatched RK4, rk4_loop.h): validation of an integrate() call, the blow-up check
// after each step, the rule that lands a fixed step on an output time, and the progress throttle.
// Defined in integrator.cc.

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "bearing/solvers/integrator.h"
#include "bearing/solvers/mechanical_system.h"

namespace bearing {
namespace solvers_detail {

/// Checks one integrate() call and returns the inverse masses 1/m_i [1/kg]. Throws InputError when
/// q0 or v0 do not have dofs() entries or are not finite, when a mass is not positive and finite,
/// or when the output times are not finite, not ascending or start before t0.
std::vector<double> check_call(const std::string& method, const MechanicalSystem& system, double t0,
                               const std::vector<double>& q0, const std::vector<double>& v0,
                               const std::vector<double>& output_times);

/// The per-DOF blow-up bounds on |q_i| for check_state, built once per integrate() call:
/// max_displacement [m], or for a cyclic DOF (MechanicalSystem::cyclic) the largest finite double,
/// which any finite angle passes and ±Inf and NaN fail.
std::vector<double> displacement_bounds(const MechanicalSystem& system, double max_displacement);

/// The blow-up test after an accepted step: every q_i and v_i finite and |q_i| ≤ bound[i] (from
/// displacement_bounds). Throws SolverError naming the method, the time t [s], the step number,
/// the step dt [s], what went wrong, and that solver.dt should be reduced. `step` 0 means the
/// initial state. The test is inline (it runs after every step); the message is built out of line.
[[noreturn]] void report_bad_state(const std::string& method, double t, long step, double dt,
                                   const double* q, const double* v, int n, const double* bound);
inline void check_state(const std::string& method, double t, long step, double dt, const double* q,
                        const double* v, int n, const double* bound) {
  bool good = true;
  // |q| ≤ bound is false for NaN and ±Inf (the bound is finite); v − v is 0 for finite v and NaN
  // otherwise.
  for (int i = 0; i < n; ++i) good &= (std::abs(q[i]) <= bound[i]) & (v[i] - v[i] == 0.0);
  if (!good) report_bad_state(method, t, step, dt, q, v, n, bound);
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
