// The integrator factory and what every method shares: validation of settings and of an
// integrate() call, and the blow-up check after each accepted step (docs/model.md §6).
//
// Conventions every method follows:
// - Output: the observer is called at each requested time exactly (fixed steps are shortened to
//   land on it, GSL's evolve clips its step to it), with an acceleration a = M⁻¹ f computed by a
//   fresh force evaluation at that point.
// - IntegrationStats::force_evaluations counts the integrator's own calls of force(), the output
//   evaluations included. A force_jacobian() call counts once in jacobian_evaluations whatever it
//   costs; the default central differences call force() 4n times inside it, not counted above.
// - Blow-up: after every accepted step all q_i, v_i must be finite and |q_i| ≤ max_displacement,
//   checked before the observer can see the state; otherwise SolverError names the time, the step
//   and dt and suggests a smaller solver.dt. A cyclic DOF (MechanicalSystem::cyclic, a spin
//   angle that grows without bound) is exempt from the bound and must only stay finite.

#include "bearing/solvers/integrator.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "bearing/errors.h"
#include "bearing/limits.h"
#include "bearing/numerics/roots.h"
#include "bearing/units.h"
#include "integrator_detail.h"

namespace bearing {

namespace {

// The settings come from [solver] (limits.h holds the keys' ranges) except atol, which the run
// derives from solver.tolerance.
void validate(const IntegratorSettings& s) {
  limits::solver_dt.check(s.dt);
  limits::solver_tolerance.check(s.rtol);
  if (!(std::isfinite(s.atol) && s.atol > 0))
    throw InputError("solver.tolerance: absolute tolerance " + format_number(s.atol) +
                     " m must be positive and finite");
  limits::solver_max_displacement.check(s.max_displacement);
}

}  // namespace

StepLimit rk4_step_limit(const MechanicalSystem& system, double t, const double* q,
                         const double* v) {
  const int n = system.dofs();
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  RowMajor dfdq(n, n), dfdv(n, n);
  system.force_jacobian(t, q, v, dfdq.data(), dfdv.data());
  std::vector<double> mass(static_cast<std::size_t>(n));
  system.mass(mass.data());
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  a.topRightCorner(n, n).setIdentity();
  for (int i = 0; i < n; ++i) {
    a.block(n + i, 0, 1, n) = dfdq.row(i) / mass[static_cast<std::size_t>(i)];
    a.block(n + i, n, 1, n) = dfdv.row(i) / mass[static_cast<std::size_t>(i)];
  }
  StepLimit limit;
  limit.step = std::numeric_limits<double>::infinity();
  const Eigen::EigenSolver<Eigen::MatrixXd> eig(a, /*computeEigenvectors=*/false);
  if (eig.info() != Eigen::Success) return limit;
  const auto stable = [](std::complex<double> z) {
    const std::complex<double> r = 1.0 + z * (1.0 + z * (0.5 + z * (1.0 / 6 + z / 24.0)));
    return std::abs(r) <= 1.0 + 1e-12;
  };
  for (int k = 0; k < 2 * n; ++k) {
    std::complex<double> lambda = eig.eigenvalues()[k];
    if (lambda.real() > 0) lambda = {0.0, std::abs(lambda)};
    const double size = std::abs(lambda);
    if (!(size > 0)) continue;
    // The boundary along the ray hλ, h > 0: the first s = h|λ| where |R| exceeds 1 (the region
    // reaches |z| ≈ 2.79–2.83 along every ray of the left half-plane), then bisection.
    const std::complex<double> dir = lambda / size;
    double lo = 0.0, hi = 0.0;
    for (double s = 0.05; s <= 4.0; s += 0.05) {
      if (!stable(s * dir)) {
        hi = s;
        break;
      }
      lo = s;
    }
    if (hi == 0.0) continue;
    numerics::BisectionOptions o;
    o.max_iterations = 60;
    const auto stable_at = [&](double s) { return stable(s * dir); };
    lo = numerics::bisect(lo, hi, stable_at, o).lo;
    const double h = lo / size;
    if (h < limit.step) limit = {h, lambda.real(), std::abs(lambda.imag())};
  }
  return limit;
}

std::vector<std::string> integrator_names() {
  std::vector<std::string> out;
  for (const auto& entry : kIntegratorMethods) out.emplace_back(entry.name);
  return out;
}

std::unique_ptr<Integrator> make_integrator(const IntegratorSettings& settings) {
  validate(settings);
  switch (settings.method) {
    case IntegratorMethod::rk4:
      return solvers_detail::make_rk4(settings);
    case IntegratorMethod::newmark:
      return solvers_detail::make_newmark(settings);
    case IntegratorMethod::bdf:
      return solvers_detail::make_bdf(settings);
    case IntegratorMethod::rk8pd_events:
      return solvers_detail::make_event_adaptive(settings);
    case IntegratorMethod::rkf45:
    case IntegratorMethod::rk8pd:
      break;
  }
  return solvers_detail::make_gsl_adaptive(settings);
}

namespace solvers_detail {

std::vector<double> check_call(const std::string& method, const MechanicalSystem& system, double t0,
                               const std::vector<double>& q0, const std::vector<double>& v0,
                               const std::vector<double>& output_times) {
  const std::string where = method + " integrate: ";
  const int n = system.dofs();
  if (n < 1) throw InputError(where + "the system has " + std::to_string(n) + " DOFs");
  const auto size = static_cast<std::size_t>(n);
  if (q0.size() != size || v0.size() != size)
    throw InputError(where + "initial state has " + std::to_string(q0.size()) +
                     " displacements and " + std::to_string(v0.size()) +
                     " velocities, the system has " + std::to_string(n) + " DOFs");
  for (std::size_t i = 0; i < size; ++i)
    if (!(std::isfinite(q0[i]) && std::isfinite(v0[i])))
      throw InputError(where + "initial state of DOF " + std::to_string(i) + " (q = " +
                       format_number(q0[i]) + ", v = " + format_number(v0[i]) + ") is not finite");
  if (!std::isfinite(t0)) throw InputError(where + "start time " + format_number(t0) + " s");
  for (std::size_t k = 0; k < output_times.size(); ++k) {
    const double t = output_times[k];
    const double before = k == 0 ? t0 : output_times[k - 1];
    if (!(std::isfinite(t) && t >= before))
      throw InputError(where + "output time [" + std::to_string(k) + "] = " + format_number(t) +
                       " s must be finite and not before " +
                       (k == 0 ? "the start time " : "the previous output time ") +
                       format_number(before) + " s");
  }
  std::vector<double> inv_mass(size);
  system.mass(inv_mass.data());
  for (std::size_t i = 0; i < size; ++i) {
    if (!(std::isfinite(inv_mass[i]) && inv_mass[i] > 0))
      throw InputError(where + "mass of DOF " + std::to_string(i) + " = " +
                       format_number(inv_mass[i]) + " kg must be positive and finite");
    inv_mass[i] = 1.0 / inv_mass[i];
  }
  return inv_mass;
}

std::string format_brief(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.7g", value);
  return text;
}

void throw_blow_up(const std::string& method, double t, long step, double dt,
                   const std::string& what) {
  const std::string at = step == 0
                             ? "in the initial state at t = " + format_brief(t) + " s"
                             : "at t = " + format_brief(t) + " s (step " + std::to_string(step) +
                                   ", dt = " + format_brief(dt) + " s)";
  throw SolverError(method + ": the solution blew up " + at + ": " + what +
                    "; reduce solver.dt or check the load/clearance");
}

std::vector<double> displacement_bounds(const MechanicalSystem& system, double max_displacement) {
  const int n = system.dofs();
  std::vector<double> bound(static_cast<std::size_t>(std::max(n, 0)), max_displacement);
  for (int i = 0; i < n; ++i)
    if (system.cyclic(i)) bound[static_cast<std::size_t>(i)] = std::numeric_limits<double>::max();
  return bound;
}

void report_bad_state(const std::string& method, double t, long step, double dt, const double* q,
                      const double* v, int n, const double* bound) {
  for (int i = 0; i < n; ++i) {
    const std::string dof = "[" + std::to_string(i) + "]";
    if (!std::isfinite(q[i]))
      throw_blow_up(method, t, step, dt, "q" + dof + " = " + format_brief(q[i]));
    if (!std::isfinite(v[i]))
      throw_blow_up(method, t, step, dt, "v" + dof + " = " + format_brief(v[i]));
    if (std::abs(q[i]) > bound[i])
      throw_blow_up(method, t, step, dt,
                    "|q" + dof + "| = " + format_brief(std::abs(q[i])) +
                        " m exceeds the blow-up bound " + format_brief(bound[i]) + " m");
  }
  throw_blow_up(method, t, step, dt, "the state is not valid");  // not reached
}

void check_acceleration(const std::string& method, double t, long step, double dt, const double* a,
                        int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(a[i]))
      throw_blow_up(method, t, step, dt,
                    "the force on DOF " + std::to_string(i) + " is " + format_brief(a[i]));
}

}  // namespace solvers_detail

}  // namespace bearing
