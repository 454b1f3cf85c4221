// "bdf": GSL's msbdf, variable-order (1–5) variable-step backward differentiation formulas in
// Nordsieck form with a modified Newton corrector, for stiff cases (a light stiff part beside a
// heavy slow one) where explicit methods are held to the fast mode's stability limit.
//
// The Newton matrix needs the Jacobian of the first-order system y = [q, v], y' = [v, M⁻¹ f]:
//     ∂y'/∂y = [ 0          I        ]
//              [ M⁻¹ ∂f/∂q  M⁻¹ ∂f/∂v ],
// built from MechanicalSystem::force_jacobian (analytic where the model provides it, central
// differences otherwise). msbdf re-evaluates it only on its own schedule (first step, every 50
// steps, after convergence failures). ∂y'/∂t is set to 0: msbdf takes it in the callback but does
// not use it, and a difference in t would cost two force evaluations for nothing.
//
// Error control, dense output and the blow-up check are those of the adaptive Runge–Kutta
// methods (gsl_adaptive.cc): |err_i| ≤ atol s_i + rtol |y_i|, s_i = 1 for displacements (a huge
// scale for a cyclic DOF's angle, whose error no force feels) and the DOF's own frequency ω_i for
// velocities; solver.dt is the first step, the steps go freely to the
// last output time, and the outputs inside a step are quintic Hermite interpolants of q (order 5,
// at least msbdf's order 1–5) from q, v, a at the step's ends, v their derivative. msbdf's
// dydt_out (the end state's y', from which a comes) is one force evaluation per attempted step.

#include <algorithm>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "bearing/solvers/integrator.h"
#include "integrator_detail.h"

namespace bearing {
namespace solvers_detail {

namespace {

// dfdy is 2n×2n row-major; params is a GslContext*.
int first_order_jacobian(double t, const double y[], double* dfdy, double dfdt[], void* params) {
  auto* c = static_cast<GslContext*>(params);
  const int n = c->n;
  const int m = 2 * n;
  try {
    c->system->force_jacobian(t, y, y + n, c->dfdq, c->dfdv);
  } catch (...) {
    c->error = std::current_exception();
    return GSL_EBADFUNC;
  }
  ++c->jacobian_evaluations;
  std::fill(dfdy, dfdy + m * m, 0.0);
  std::fill(dfdt, dfdt + m, 0.0);
  for (int i = 0; i < n; ++i) {
    dfdy[i * m + n + i] = 1.0;
    double* row = dfdy + (n + i) * m;
    const double w = c->inv_mass[i];
    for (int j = 0; j < n; ++j) {
      row[j] = w * c->dfdq[i * n + j];
      row[n + j] = w * c->dfdv[i * n + j];
    }
  }
  return GSL_SUCCESS;
}

class Bdf final : public Integrator {
 public:
  explicit Bdf(const IntegratorSettings& settings) : settings_(settings) {}

  IntegrationStats integrate(const MechanicalSystem& system, double t0,
                             const std::vector<double>& q0, const std::vector<double>& v0,
                             const std::vector<double>& output_times, const Observer& observe,
                             const Progress& progress) const override {
    return integrate_gsl(name(), gsl_odeiv2_step_msbdf, first_order_jacobian, settings_, system, t0,
                         q0, v0, output_times, observe, progress);
  }

  std::string name() const override { return "bdf"; }

 private:
  IntegratorSettings settings_;
};

}  // namespace

std::unique_ptr<Integrator> make_bdf(const IntegratorSettings& settings) {
  return std::make_unique<Bdf>(settings);
}

}  // namespace solvers_detail
}  // namespace bearing
