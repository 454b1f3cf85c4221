// Adaptive embedded Runge–Kutta through GSL odeiv2: "rkf45" (Runge–Kutta–Fehlberg 4(5)) and
// "rk8pd" (Prince–Dormand 8(9)), and the stepping loop bdf.cc shares for msbdf.
//
// The state is y = [q, v] (2n entries), y' = [v, M⁻¹ f(t, q, v)]. gsl_odeiv2_evolve_apply takes
// one accepted step per call, from solver.dt at first, and is called towards the last output
// time t_end: the steps are the error control's alone (GSL clips only the step that would pass
// t_end, which lands on it exactly), so the output times neither cap nor shrink them, and the
// steps and their force evaluations do not depend on the output grid. After every accepted step
// the state passes the blow-up check, before any output from that step is recorded.
//
// Dense output. Every output time inside an accepted step [t_n, t_{n+1}] is filled by Hermite
// interpolation of q from q, v = q', a = q'' at the step's ends (HermiteStep in
// integrator_detail.h), and v by the derivative of the same polynomial:
//   - rkf45 and bdf: quintic Hermite on the step, interpolation order 5 (error O(h⁶) in q, O(h⁵)
//     in v), at least the method's order (rkf45 advances the 5th-order solution; msbdf 1–5).
//   - rk8pd: the quintic raised to degree 8 with the start of the previous step as a third node
//     (q, v, a there too; for the first step, the end of the second), interpolation order 8
//     (O(h⁹) in q, O(h⁸) in v). A quintic is not enough at rk8pd's long steps: on the 650 Hz test
//     oscillator it was 6–240 rtol·q0 off (rtol 1e-5 … 1e-10) against 0.04–0.2 rtol·q0 now.
// Outputs inside the first step of rk8pd wait until the second step is accepted. An output time
// equal to a step end gets that end's values exactly. At every output time a = M⁻¹ f is evaluated
// at the interpolated (t, q, v), one force evaluation per output, counted in force_evaluations.
//
// The accelerations at the step ends cost nothing extra: the three GSL steppers take y'(t_n)
// (dydt_in, which gsl_odeiv2_evolve_apply evaluates at the start of each call) and return
// y'(t_{n+1}) (dydt_out, which their apply functions evaluate at the accepted end state: the
// methods are not FSAL, so this is one evaluation beyond the stages). Both evaluations were made
// before dense output too and are counted (first_order_rhs): 7 per step for rkf45 and 14 for
// rk8pd, plus 6 and 13 per rejected attempt. (dydt_in repeats the previous step's dydt_out at the
// same state; avoiding that would take an own evolve loop around gsl_odeiv2_step_apply.)
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
// A cyclic DOF (MechanicalSystem::cyclic: a spin angle no force depends on) has s_i = 1e300 for
// its displacement: its error feeds back into nothing, and rtol |y_i| of an angle that grows
// without bound would tighten or loosen with the angle's history, so atol s_i (≥ 1e288 rad for
// atol ≥ 1e-12, finite for atol < 1e8) makes sure it never limits the step. Its velocity (the
// spin speed, which forces do depend on) keeps the ω_i or 1/solver.dt scale above.
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

// The absolute-tolerance scale of a cyclic displacement: large enough that its error never limits
// the step, finite so that GSL's error ratios stay numbers (see the top).
constexpr double kCyclicScale = 1e300;

}  // namespace

// y' = [v, M⁻¹ f]; params is a GslContext*. A model exception is parked, and a non-finite force
// recorded, and either is reported as a bad function, which makes GSL return at once: a
// non-finite force means the state has already run away (Hertz forces are finite for any finite
// approach), so no smaller step would help.
int first_order_rhs(double t, const double y[], double dydt[], void* params) {
  auto* c = static_cast<GslContext*>(params);
  const int n = c->n;
  try {
    c->system->force_with(c->workspace, t, y, y + n, dydt + n);
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

// Absolute-tolerance scales: 1 for displacements (kCyclicScale for a cyclic one), ω_i for
// velocities (see the top), from the Jacobian at the initial state (counted in `context`).
std::vector<double> tolerance_scales(const MechanicalSystem& system, double t0,
                                     const std::vector<double>& q0, const std::vector<double>& v0,
                                     const std::vector<double>& inv_mass, double dt,
                                     GslContext& context) {
  const int n = context.n;
  std::vector<double> scale(static_cast<std::size_t>(2 * n), 1.0);
  for (int i = 0; i < n; ++i)
    if (system.cyclic(i)) scale[static_cast<std::size_t>(i)] = kCyclicScale;
  system.force_jacobian(t0, q0.data(), v0.data(), context.dfdq, context.dfdv);
  ++context.jacobian_evaluations;
  for (int i = 0; i < n; ++i) {
    const double stiffness =
        std::abs(context.dfdq[static_cast<std::size_t>(i) * n + i]) * inv_mass[i];
    const double damping =
        std::abs(context.dfdv[static_cast<std::size_t>(i) * n + i]) * inv_mass[i];
    const double omega = std::max(std::sqrt(stiffness), damping);
    scale[static_cast<std::size_t>(n + i)] = std::isfinite(omega) && omega > 0 ? omega : 1.0 / dt;
  }
  return scale;
}

// The outcome of one gsl_odeiv2_evolve_apply: a model exception, a non-finite force (blow-up), or
// a step-size control that cannot meet the tolerance, each reported at step `step` (t, h).
void check_step(const std::string& method, int status, const GslContext& context, double t,
                long step, double h) {
  if (context.error) std::rethrow_exception(context.error);
  if (status == GSL_EBADFUNC && context.bad_dof >= 0)
    throw_blow_up(method, context.bad_time, step, h,
                  "the force on DOF " + std::to_string(context.bad_dof) + " is " +
                      format_brief(context.bad_value));
  if (status != GSL_SUCCESS)
    throw SolverError(method + ": the step-size control failed at t = " + format_brief(t) +
                      " s (step " + std::to_string(step) + ", dt = " + format_brief(h) +
                      " s): " + gsl_strerror(status) +
                      "; the tolerance cannot be met with a representable step: loosen "
                      "solver.tolerance or check the load/clearance");
}

namespace {

class GslAdaptive final : public Integrator {
 public:
  GslAdaptive(const IntegratorSettings& settings, const gsl_odeiv2_step_type* type)
      : settings_(settings), type_(type) {}

  IntegrationStats integrate(const MechanicalSystem& system, double t0,
                             const std::vector<double>& q0, const std::vector<double>& v0,
                             const std::vector<double>& output_times, const Observer& observe,
                             const Progress& progress) const override {
    return integrate_gsl(name(), type_, nullptr, settings_, system, t0, q0, v0, output_times,
                         observe, progress);
  }

  std::string name() const override { return name_of(kIntegratorMethods, settings_.method); }

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
  const std::vector<double> bounds = displacement_bounds(system, settings.max_displacement);
  const double* const bound = bounds.data();
  IntegrationStats stats;

  std::vector<double> y(dim), a(static_cast<std::size_t>(n));
  std::copy(q0.begin(), q0.end(), y.begin());
  std::copy(v0.begin(), v0.end(), y.begin() + n);
  check_state(method, t0, 0, settings.dt, y.data(), y.data() + n, n, bound);
  if (output_times.empty()) return stats;

  GslContextData data(system, inv_mass);
  GslContext& context = data.context;
  MechanicalSystem::Workspace* const workspace = data.workspace();

  const std::vector<double> scale =
      tolerance_scales(system, t0, q0, v0, inv_mass, settings.dt, context);

  gsl_odeiv2_system ode{first_order_rhs, jacobian, dim, &context};
  std::unique_ptr<gsl_odeiv2_driver, DriverFree> driver(gsl_odeiv2_driver_alloc_scaled_new(
      &ode, type, settings.dt, settings.atol, settings.rtol, 1.0, 0.0, scale.data()));
  if (!driver) throw SolverError(method + ": GSL could not allocate the ODE driver");

  // Dense output (see the top): the steps go towards the last output time, and the outputs
  // inside each accepted step are interpolated.
  const double t_end = output_times.back();
  ProgressThrottle report(progress, t0, t_end);
  std::size_t next = 0;  // the next output time to serve
  std::vector<double> qo(static_cast<std::size_t>(n)), vo(qo.size());
  // q, v at an output time are the initial values, a step's end values or interpolated inside
  // step number `step` of length dt; they pass the blow-up check too (an interpolant can overshoot
  // its ends slightly). a = M⁻¹ f there is evaluated afresh (counted) and must be finite.
  const auto emit = [&](double t_out, const double* q, const double* v, long step, double dt) {
    check_state(method, t_out, step, dt, q, v, n, bound);
    system.force_with(workspace, t_out, q, v, a.data());
    ++context.force_evaluations;
    for (int i = 0; i < n; ++i) a[static_cast<std::size_t>(i)] *= inv_mass[i];
    check_acceleration(method, t_out, step, dt, a.data(), n);
    if (observe) observe(t_out, q, v, a.data());
  };
  while (next < output_times.size() && output_times[next] <= t0)
    emit(output_times[next++], y.data(), y.data() + n, 0, settings.dt);

  // The accelerations at both ends of a step come with it (see the top): dydt_in and dydt_out of
  // the evolve object after gsl_odeiv2_evolve_apply returns. dydt_out is filled by every stepper
  // (gsl_odeiv2_step_apply's documented output), dydt_in only by those that take it.
  if (type->can_use_dydt_in == 0)
    throw SolverError(method + ": the GSL stepper takes no dydt_in, needed for dense output");
  const gsl_odeiv2_evolve* const evolve = driver->e;
  // Interpolation order at least the method's: quintic (order 5) for rkf45 and msbdf (orders 5
  // and 1–5), degree 8 with a third node for rk8pd (order 8).
  const bool third_node = gsl_odeiv2_step_order(driver->s) > 5;
  // This step [t_start, t] and the one before it, whose start is the interpolant's third node.
  std::vector<double> y_start(dim), a_start(static_cast<std::size_t>(n)), a_end(a_start.size());
  std::vector<double> y_before(dim), a_before(a_start.size());
  double t_start = t0, t_before = t0;
  bool first_pending = false;  // outputs inside the first step wait for the second step
  HermiteStep interpolant;
  const auto serve = [&](double t_last, long step, double dt) {
    for (; next < output_times.size() && output_times[next] <= t_last; ++next) {
      interpolant.at(output_times[next], qo.data(), vo.data());
      emit(output_times[next], qo.data(), vo.data(), step, dt);
      report.update(output_times[next]);
    }
  };
  double t = t0;
  double h = settings.dt;
  while (t < t_end) {
    if (settings.max_step > 0) h = std::min(h, settings.max_step);
    if (stats.steps > 0) {
      y_before.swap(y_start);
      a_before.swap(a_start);
      t_before = t_start;
    }
    t_start = t;
    std::copy(y.begin(), y.end(), y_start.begin());
    const int status =
        gsl_odeiv2_evolve_apply(driver->e, driver->c, driver->s, &ode, &t, t_end, &h, y.data());
    check_step(method, status, context, t, stats.steps + 1, h);
    ++stats.steps;
    const double dt = evolve->last_step;
    check_state(method, t, stats.steps, dt, y.data(), y.data() + n, n, bound);
    std::copy(evolve->dydt_in + n, evolve->dydt_in + 2 * n, a_start.begin());
    std::copy(evolve->dydt_out + n, evolve->dydt_out + 2 * n, a_end.begin());
    if (first_pending) {  // the first step, with this step's end as the third node
      interpolant.set(n, t_before, t_start, y_before.data(), y_before.data() + n, a_before.data(),
                      y_start.data(), y_start.data() + n, a_start.data());
      interpolant.add_node(t, y.data(), y.data() + n, a_end.data());
      serve(t_start, 1, t_start - t_before);
      first_pending = false;
    }
    if (next < output_times.size() && output_times[next] <= t) {
      if (third_node && stats.steps == 1 && t < t_end) {
        first_pending = true;
      } else {
        interpolant.set(n, t_start, t, y_start.data(), y_start.data() + n, a_start.data(), y.data(),
                        y.data() + n, a_end.data());
        if (third_node && stats.steps > 1)
          interpolant.add_node(t_before, y_before.data(), y_before.data() + n, a_before.data());
        serve(t, stats.steps, dt);
      }
    }
    report.update(t);
  }
  stats.rejected_steps = static_cast<long>(driver->e->failed_steps);
  stats.force_evaluations = context.force_evaluations;
  stats.jacobian_evaluations = context.jacobian_evaluations;
  report.finish();
  return stats;
}

std::unique_ptr<Integrator> make_gsl_adaptive(const IntegratorSettings& settings) {
  const gsl_odeiv2_step_type* type =
      settings.method == IntegratorMethod::rk8pd ? gsl_odeiv2_step_rk8pd : gsl_odeiv2_step_rkf45;
  return std::make_unique<GslAdaptive>(settings, type);
}

}  // namespace solvers_detail
}  // namespace bearing
