#pragma once
// What the integrators share (private to lumped/src/solvers): the per-method factories that
// make_integrator dispatches to, validation of an integrate() call, the blow-up check, the
// adaptive methods' dense-output interpolant (hermite_step.h), the rule that lands a fixed step on
// an output time, and the progress throttle.

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <gsl/gsl_odeiv2.h>

#include "bearing/solvers/fixed_step.h"
#include "bearing/solvers/integrator.h"
#include "hermite_step.h"

namespace bearing {
namespace solvers_detail {

// Factories for the concrete methods; the settings are already validated by make_integrator.
std::unique_ptr<Integrator> make_rk4(const IntegratorSettings& settings);
/// method is "rkf45" or "rk8pd".
std::unique_ptr<Integrator> make_gsl_adaptive(const IntegratorSettings& settings);
std::unique_ptr<Integrator> make_newmark(const IntegratorSettings& settings);
std::unique_ptr<Integrator> make_bdf(const IntegratorSettings& settings);
/// rk8pd with contact events located (event_adaptive.cc).
std::unique_ptr<Integrator> make_event_adaptive(const IntegratorSettings& settings);

/// What the GSL callbacks see through gsl_odeiv2_system::params: the model and its force
/// workspace, 1/m, counters, work arrays for force_jacobian, and an exception the model threw
/// inside a callback (it is carried across GSL's C frames and rethrown after
/// gsl_odeiv2_evolve_apply returns).
struct GslContext {
  const MechanicalSystem* system = nullptr;
  MechanicalSystem::Workspace* workspace = nullptr;  ///< the system's, for force_with()
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

/// A GslContext with what it points to, for one integrate() call: the system's force workspace and
/// the n×n Jacobian work arrays. Not copyable: the context points into it.
class GslContextData {
 public:
  GslContextData(const MechanicalSystem& system, const std::vector<double>& inv_mass)
      : workspace_(system.make_workspace()),
        dfdq_(static_cast<std::size_t>(system.dofs()) * static_cast<std::size_t>(system.dofs())),
        dfdv_(dfdq_.size()) {
    context.system = &system;
    context.workspace = workspace_.get();
    context.n = system.dofs();
    context.inv_mass = inv_mass.data();
    context.dfdq = dfdq_.data();
    context.dfdv = dfdv_.data();
  }
  GslContextData(const GslContextData&) = delete;
  GslContextData& operator=(const GslContextData&) = delete;

  MechanicalSystem::Workspace* workspace() const { return workspace_.get(); }
  GslContext context;

 private:
  std::unique_ptr<MechanicalSystem::Workspace> workspace_;
  std::vector<double> dfdq_, dfdv_;
};

/// The Jacobian callback of gsl_odeiv2_system (params is a GslContext*), or nullptr.
using GslJacobian = int (*)(double t, const double y[], double* dfdy, double dfdt[], void* params);

/// y' = [v, M⁻¹ f] for GSL (gsl_adaptive.cc; params is a GslContext*): counts the evaluation,
/// parks a model exception in the context and records a non-finite force there, either returned
/// as GSL_EBADFUNC.
int first_order_rhs(double t, const double y[], double dydt[], void* params);

/// The adaptive methods' absolute-tolerance scales s_i of y = [q, v] (gsl_adaptive.cc: 1 for a
/// displacement, 1e300 for a cyclic one, ω_i for a velocity), from force_jacobian at t0.
std::vector<double> tolerance_scales(const MechanicalSystem& system, double t0,
                                     const std::vector<double>& q0, const std::vector<double>& v0,
                                     const std::vector<double>& inv_mass, double dt,
                                     GslContext& context);

/// Throws for a failed GSL step (status ≠ GSL_SUCCESS): the model's exception, a blow-up (a
/// non-finite force), or a step-size control that cannot meet the tolerance.
void check_step(const std::string& method, int status, const GslContext& context, double t,
                long step, double h);

struct DriverFree {
  void operator()(gsl_odeiv2_driver* d) const { gsl_odeiv2_driver_free(d); }
};

/// integrate() for a GSL odeiv2 stepper with error control (gsl_adaptive.cc): rkf45, rk8pd, and
/// msbdf (bdf.cc, which passes the Jacobian callback). `method` names it in messages.
IntegrationStats integrate_gsl(const std::string& method, const gsl_odeiv2_step_type* type,
                               GslJacobian jacobian, const IntegratorSettings& settings,
                               const MechanicalSystem& system, double t0,
                               const std::vector<double>& q0, const std::vector<double>& v0,
                               const std::vector<double>& output_times, const Observer& observe,
                               const Progress& progress);

}  // namespace solvers_detail
}  // namespace bearing
