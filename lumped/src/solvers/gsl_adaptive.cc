// Adaptive embedded Runge–Kutta through GSL odeiv2: "rkf45" (Runge–Kutta–Fehlberg 4(5)) and
// "rk8pd" (Prince–Dormand 8(9)), and the stepping loop bdf.cc shares for msbdf.
//
// The state is y = [q, v] (2n entries), y' = [v, M⁻¹ f(t, q, v)]. gsl_odeiv2_evolve_apply takes
// one accepted step per call and is called towards the next output time: it clips the step that
// would pass it and returns with t equal to it exactly, keeping the unclipped step size for the
// next call, so the output grid neither drives nor shrinks the step size. After every accepted
// step the state passes the blow-up check.
//
// Error control (gsl_odeiv2_control_scaled_new, a_y = 1, a_dydt = 0): a step is accepted when
// every component's local error estimate satisfies
//     |err_i| ≤ atol s_i + rtol |y_i|,
// with s_i = 1 for a displacement, so atol is in metres, and s_i = ω_i for the velocity of DOF i,
// where ω_i = max(√(|∂f_i/∂q_i| / m_i), |∂f_i/∂v_i| / m_i) is the DOF's own natural frequency
// (or damping rate) at the initial state, from force_jacobian. A displacement amplitude A comes
// with a velocity amplitude ω A, so atol ω_i asks of the velocity what atol asks of the
// displacement; one atol for both would be far too tight for the velocities (ω ~ 1e4 rad/s in a
// bearing) or far too loose for the displacements. Where ω_i is 0 (a DOF that is free or whose
// contacts are open at t0) or not finite, s_i = 1/solver.dt, the frequency the user resolves.
// The per-DOF scale also keeps a slow heavy DOF from inheriting the tolerance of a fast one.
//
// GSL's default error handler aborts; the integrators check every return code instead, and the
// application should call gsl_set_error_handler_off() once at start-up (a process-wide setting
// this library does not change on its own).

#include <algorithm>
#include <cmath>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "bearing/errors.h"
#include "bearing/solvers/integrator.h"
#include "bearing/units.h"
#include "integrator_detail.h"

namespace bearing {
namespace solvers_detail {

namespace {

// y' = [v, M⁻¹ f]; params is a GslContext*. A model exception is parked, and a non-finite force
// recorded, and either is reported as a bad function, which makes GSL return at once: a
// non-finite force means the state has already run away (Hertz forces are finite for any finite
// approach), so no smaller step would help.
int first_order_rhs(double t, const double y[], double dydt[], void* params) {
  auto* c = static_cast<GslContext*>(params);
  const int n = c->n;
  try {
    c->system->force(t, y, y + n, dydt + n);
  } catch (...) {
    c->error = std::current_exception();
    return GSL_EBADFUNC;
  }
  ++c->force_evaluations;
  bool finite = true;
  for (int i = 0; i < n; ++i) {
    dydt[i] = y[n + i];
    dydt[n + i] *= c->inv_mass[i];
    finite = finite && std::isfinite(dydt[n + i]);
  }
  if (finite) return GSL_SUCCESS;
  for (int i = 0; i < n; ++i) {
    if (std::isfinite(dydt[n + i])) continue;
    c->bad_time = t;
    c->bad_dof = i;
    c->bad_value = dydt[n + i];
    break;
  }
  return GSL_EBADFUNC;
}

struct DriverFree {
  void operator()(gsl_odeiv2_driver* d) const { gsl_odeiv2_driver_free(d); }
};

class GslAdaptive final : public Integrator {
 public:
  GslAdaptive(const IntegratorSettings& settings, const gsl_odeiv2_step_type* type)
      : settings_(settings), type_(type) {}

  IntegrationStats integrate(const MechanicalSystem& system, double t0,
                             const std::vector<double>& q0, const std::vector<double>& v0,
                             const std::vector<double>& output_times, const Observer& observe,
                             const Progress& progress) const override {
    return integrate_gsl(settings_.method, type_, nullptr, settings_, system, t0, q0, v0,
                         output_times, observe, progress);
  }

  std::string name() const override { return settings_.method; }

 private:
  IntegratorSettings settings_;
  const gsl_odeiv2_step_type* type_;
};

}  // namespace

IntegrationStats integrate_gsl(const std::string& method, const gsl_odeiv2_step_type* type,
                               GslJacobian jacobian, const IntegratorSettings& settings,
                               const MechanicalSystem& system, double t0,
                               const std::vector<double>& q0, const std::vector<double>& v0,
                               const std::vector<double>& output_times, const Observer& observe,
                               const Progress& progress) {
  const std::vector<double> inv_mass = check_call(method, system, t0, q0, v0, output_times);
  const int n = system.dofs();
  const auto dim = static_cast<std::size_t>(2 * n);
  const double bound = settings.max_displacement;
  IntegrationStats stats;

  std::vector<double> y(dim), a(static_cast<std::size_t>(n));
  std::copy(q0.begin(), q0.end(), y.begin());
  std::copy(v0.begin(), v0.end(), y.begin() + n);
  check_state(method, t0, 0, settings.dt, y.data(), y.data() + n, n, bound);
  if (output_times.empty()) return stats;

  std::vector<double> dfdq(static_cast<std::size_t>(n) * n), dfdv(dfdq.size());
  GslContext context;
  context.system = &system;
  context.n = n;
  context.inv_mass = inv_mass.data();
  context.dfdq = dfdq.data();
  context.dfdv = dfdv.data();

  // Absolute-tolerance scales: 1 for displacements, ω_i for velocities (see the top).
  std::vector<double> scale(dim, 1.0);
  system.force_jacobian(t0, q0.data(), v0.data(), dfdq.data(), dfdv.data());
  ++context.jacobian_evaluations;
  for (int i = 0; i < n; ++i) {
    const double stiffness = std::abs(dfdq[static_cast<std::size_t>(i) * n + i]) * inv_mass[i];
    const double damping = std::abs(dfdv[static_cast<std::size_t>(i) * n + i]) * inv_mass[i];
    const double omega = std::max(std::sqrt(stiffness), damping);
    scale[static_cast<std::size_t>(n + i)] =
        std::isfinite(omega) && omega > 0 ? omega : 1.0 / settings.dt;
  }

  gsl_odeiv2_system ode{first_order_rhs, jacobian, dim, &context};
  std::unique_ptr<gsl_odeiv2_driver, DriverFree> driver(gsl_odeiv2_driver_alloc_scaled_new(
      &ode, type, settings.dt, settings.atol, settings.rtol, 1.0, 0.0, scale.data()));
  if (!driver) throw SolverError(method + ": GSL could not allocate the ODE driver");

  ProgressThrottle report(progress, t0, output_times.back());
  double t = t0;
  double h = settings.dt;
  for (const double t_out : output_times) {
    while (t < t_out) {
      const int status =
          gsl_odeiv2_evolve_apply(driver->e, driver->c, driver->s, &ode, &t, t_out, &h, y.data());
      if (context.error) std::rethrow_exception(context.error);
      if (status == GSL_EBADFUNC && context.bad_dof >= 0)
        throw_blow_up(method, context.bad_time, stats.steps + 1, h,
                      "the force on DOF " + std::to_string(context.bad_dof) + " is " +
                          format_brief(context.bad_value));
      if (status != GSL_SUCCESS)
        throw SolverError(method + ": the step-size control failed at t = " + format_brief(t) +
                          " s (step " + std::to_string(stats.steps + 1) +
                          ", dt = " + format_brief(h) + " s): " + gsl_strerror(status) +
                          "; the tolerance cannot be met with a representable step: loosen "
                          "solver.tolerance or check the load/clearance");
      ++stats.steps;
      check_state(method, t, stats.steps, driver->e->last_step, y.data(), y.data() + n, n, bound);
      report.update(t);
    }
    system.force(t, y.data(), y.data() + n, a.data());
    ++context.force_evaluations;
    for (int i = 0; i < n; ++i) a[static_cast<std::size_t>(i)] *= inv_mass[i];
    check_acceleration(method, t, stats.steps, driver->e->last_step, a.data(), n);
    if (observe) observe(t, y.data(), y.data() + n, a.data());
  }
  stats.rejected_steps = static_cast<long>(driver->e->failed_steps);
  stats.force_evaluations = context.force_evaluations;
  stats.jacobian_evaluations = context.jacobian_evaluations;
  report.finish();
  return stats;
}

std::unique_ptr<Integrator> make_gsl_adaptive(const IntegratorSettings& settings) {
  const gsl_odeiv2_step_type* type =
      settings.method == "rk8pd" ? gsl_odeiv2_step_rk8pd : gsl_odeiv2_step_rkf45;
  return std::make_unique<GslAdaptive>(settings, type);
}

}  // namespace solvers_detail
}  // namespace bearing
