// Newmark-β, average acceleration (β = 1/4, γ = 1/2), with Newton–Raphson on the nonlinear force:
// the implicit method of seed 001 (Purohit & Purohit). One step of size h from (qₙ, vₙ, aₙ):
//     qₙ₊₁ = qₙ + h vₙ + h²/4 (aₙ + aₙ₊₁),   vₙ₊₁ = vₙ + h/2 (aₙ + aₙ₊₁),
//     M aₙ₊₁ = f(tₙ₊₁, qₙ₊₁, vₙ₊₁).
// With x = qₙ₊₁ as the unknown, aₙ₊₁ = 4/h² (x − qₙ) − 4/h vₙ − aₙ and vₙ₊₁ = 2/h (x − qₙ) − vₙ,
// so the step solves the n equations
//     R(x) = M aₙ₊₁(x) − f(tₙ₊₁, x, vₙ₊₁(x)) = 0,   ∂R/∂x = 4/h² M − ∂f/∂q − 2/h ∂f/∂v,
// by Newton from the predictor x⁰ = qₙ + h vₙ + h²/2 aₙ. The scheme is the trapezoidal rule on
// [q, v]: second order, unconditionally stable for linear systems, no numerical damping, and it
// conserves ½vᵀMv + ½qᵀKq of an undamped linear system exactly.
//
// Newton stops when every correction satisfies |Δxᵢ| ≤ atol + rtol |xᵢ| (solver.tolerance; the
// floor 8ε|xᵢ| keeps a tolerance below rounding reachable). The Jacobian (force_jacobian) and the
// LU factors of ∂R/∂x are kept from step to step (modified Newton) and rebuilt on the first step,
// when h changes by more than 0.1 % (a shortened landing step), and when an iteration contracts
// the correction by less than a factor 2. 4/h² M dominates ∂R/∂x for the step sizes that resolve
// the vibration, so a Jacobian a few steps old still converges in two or three iterations. Newton
// failure (no convergence in kMaxIterations, or a non-finite force) throws SolverError with the
// time, step and residual, suggesting a smaller solver.dt.
//
// For a cyclic DOF (MechanicalSystem::cyclic, a spin angle that grows without bound) rtol applies
// to its increment over the step instead: |Δxᵢ| ≤ atol + max(rtol, 8ε) |xᵢ − qₙ,ᵢ| + 8ε |xᵢ|. The
// step derives the velocity from the increment, vₙ₊₁ = 2/h (x − qₙ) − vₙ, so rtol |xᵢ| with an
// accumulated angle of hundreds of rad would accept a correction many times the increment's rtol
// and give a wrong spin speed. The rounding floor 8ε|xᵢ| stays: x is only resolved to its ulp
// (≤ ε|xᵢ|), and no smaller correction can be applied (at 1e7 rad with atol 1e-12, Newton stalled
// without it).
//
// Fixed step dt, shortened only to land on an output time. The observer's acceleration is a
// fresh force evaluation at the output point (counted), which agrees with the scheme's aₙ₊₁ to
// the Newton tolerance; the recursion carries the scheme's own aₙ₊₁.

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "bearing/errors.h"
#include "bearing/solvers/integrator.h"
#include "bearing/units.h"
#include "integrator_detail.h"

namespace bearing {
namespace solvers_detail {

namespace {

constexpr int kMaxIterations = 30;

class Newmark final : public Integrator {
 public:
  explicit Newmark(const IntegratorSettings& settings) : settings_(settings) {}

  IntegrationStats integrate(const MechanicalSystem& system, double t0,
                             const std::vector<double>& q0, const std::vector<double>& v0,
                             const std::vector<double>& output_times, const Observer& observe,
                             const Progress& progress) const override;

  std::string name() const override { return "newmark"; }

 private:
  IntegratorSettings settings_;
};

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

IntegrationStats Newmark::integrate(const MechanicalSystem& system, double t0,
                                    const std::vector<double>& q0, const std::vector<double>& v0,
                                    const std::vector<double>& output_times,
                                    const Observer& observe, const Progress& progress) const {
  const std::string method = name();
  const std::vector<double> inv_mass = check_call(method, system, t0, q0, v0, output_times);
  const int n = system.dofs();
  const double dt = settings_.dt;
  const double rtol = settings_.rtol;
  const double atol = settings_.atol;
  const std::vector<double> bounds = displacement_bounds(system, settings_.max_displacement);
  const double* const bound = bounds.data();
  constexpr double kRoundingFloor = 8.0 * 2.220446049250313e-16;
  IntegrationStats stats;

  // Everything the loop touches, allocated once.
  Eigen::VectorXd q = Eigen::Map<const Eigen::VectorXd>(q0.data(), n);
  Eigen::VectorXd v = Eigen::Map<const Eigen::VectorXd>(v0.data(), n);
  Eigen::VectorXd a(n), x(n), v_new(n), a_new(n), f(n), residual(n), dx(n), a_out(n);
  Eigen::VectorXd mass(n);
  for (int i = 0; i < n; ++i) mass[i] = 1.0 / inv_mass[i];
  RowMajor dfdq(n, n), dfdv(n, n);
  Eigen::MatrixXd jacobian(n, n);
  Eigen::PartialPivLU<Eigen::MatrixXd> lu(n);
  // Newton's tolerance for DOF i is atol + max(rtol, 8ε) |xᵢ − cᵢ qₙ,ᵢ| + cᵢ 8ε |xᵢ| with cᵢ = 1
  // for a cyclic DOF (rtol on its increment over the step) and 0 otherwise (see the top).
  Eigen::VectorXd cyclic(n);
  for (int i = 0; i < n; ++i) cyclic[i] = system.cyclic(i) ? 1.0 : 0.0;
  double h_factored = 0.0;  // step size the LU factors were built for; 0: none yet

  check_state(method, t0, 0, dt, q.data(), v.data(), n, bound);
  if (output_times.empty()) return stats;
  const std::unique_ptr<MechanicalSystem::Workspace> workspace = system.make_workspace();
  system.force_with(workspace.get(), t0, q.data(), v.data(), a.data());
  ++stats.force_evaluations;
  a = a.cwiseQuotient(mass);
  check_acceleration(method, t0, 0, dt, a.data(), n);

  ProgressThrottle report(progress, t0, output_times.back());
  double t = t0;
  for (const double t_out : output_times) {
    const double segment_start = t;
    long k = 0;
    while (t < t_out) {
      const bool last = final_step_to(t, dt, t_out);
      const double h = last ? t_out - t : dt;
      const double t_new = last ? t_out : segment_start + static_cast<double>(k + 1) * dt;
      const double c0 = 4.0 / (h * h);
      const double c2 = 2.0 / h;
      const long step = stats.steps + 1;

      x = q + h * v + (0.5 * h * h) * a;
      bool refresh = std::abs(h - h_factored) > 1e-3 * h;
      bool converged = false;
      double previous = 0.0;
      double norm = 0.0;
      int iteration = 0;
      for (; iteration < kMaxIterations && !converged; ++iteration) {
        v_new = c2 * (x - q) - v;
        a_new = c0 * (x - q) - (4.0 / h) * v - a;
        system.force_with(workspace.get(), t_new, x.data(), v_new.data(), f.data());
        ++stats.force_evaluations;
        residual = mass.cwiseProduct(a_new) - f;
        if (!residual.allFinite()) break;
        if (refresh) {
          system.force_jacobian(t_new, x.data(), v_new.data(), dfdq.data(), dfdv.data());
          ++stats.jacobian_evaluations;
          jacobian = -dfdq - c2 * dfdv;
          jacobian.diagonal() += c0 * mass;
          lu.compute(jacobian);
          h_factored = h;
          refresh = false;
        }
        dx.noalias() = lu.solve(residual);
        x -= dx;
        norm = 0.0;
        for (int i = 0; i < n; ++i) {
          const double scale = std::max(rtol, kRoundingFloor) * std::abs(x[i] - cyclic[i] * q[i]) +
                               cyclic[i] * kRoundingFloor * std::abs(x[i]);
          norm = std::max(norm, std::abs(dx[i]) / (atol + scale));
        }
        if (!std::isfinite(norm)) break;  // the Jacobian was not finite
        converged = norm <= 1.0;
        if (iteration > 0 && norm > 0.5 * previous) refresh = true;
        previous = norm;
      }
      if (!residual.allFinite() || !std::isfinite(norm))
        throw_blow_up(method, t_new, step, h,
                      "the force or its Jacobian at Newton iterate " +
                          std::to_string(iteration + 1) + " is not finite");
      if (!converged)
        throw SolverError(
            method + ": Newton iteration did not converge at t = " + format_brief(t_new) +
            " s (step " + std::to_string(step) + ", dt = " + format_brief(h) + " s) in " +
            std::to_string(kMaxIterations) + " iterations: force residual " +
            format_brief(residual.cwiseAbs().maxCoeff()) + " N, last correction " +
            format_brief(norm) +
            " times the tolerance; reduce solver.dt (or loosen solver.tolerance), "
            "or check the load/clearance");
      // vₙ₊₁ and aₙ₊₁ of the converged x (the loop's values belong to x before its last update).
      v_new = c2 * (x - q) - v;
      a_new = c0 * (x - q) - (4.0 / h) * v - a;
      q = x;
      v = v_new;
      a = a_new;
      ++k;
      t = t_new;
      ++stats.steps;
      check_state(method, t, stats.steps, h, q.data(), v.data(), n, bound);
      report.update(t);
    }
    system.force_with(workspace.get(), t, q.data(), v.data(), a_out.data());
    ++stats.force_evaluations;
    a_out = a_out.cwiseQuotient(mass);
    check_acceleration(method, t, stats.steps, dt, a_out.data(), n);
    if (observe) observe(t, q.data(), v.data(), a_out.data());
  }
  report.finish();
  return stats;
}

}  // namespace

std::unique_ptr<Integrator> make_newmark(const IntegratorSettings& settings) {
  return std::make_unique<Newmark>(settings);
}

}  // namespace solvers_detail
}  // namespace bearing
