// Classic fixed-step fourth-order Runge–Kutta on the first-order form y = [q, v],
//     q' = v,   v' = a(t, q, v) = M⁻¹ f(t, q, v),
// the seeds' method (dt = 5 or 10 µs). One step of size h from (t, q, v):
//     a₁ = a(t, q, v)
//     a₂ = a(t + h/2, q + h/2 v,  v + h/2 a₁)        with v₂ = v + h/2 a₁
//     a₃ = a(t + h/2, q + h/2 v₂, v + h/2 a₂)        with v₃ = v + h/2 a₂
//     a₄ = a(t + h,   q + h v₃,   v + h a₃)          with v₄ = v + h a₃
//     q ← q + h/6 (v + 2v₂ + 2v₃ + v₄),   v ← v + h/6 (a₁ + 2a₂ + 2a₃ + a₄).
// Global error O(h⁴). Every step is dt except the one that would pass an output time, which is
// shortened to end on it exactly; the next step starts there with dt again.
//
// Cost: four force evaluations per step and O(n) arithmetic, on eight arrays of n doubles
// allocated once per integrate() (and the system's force workspace, MechanicalSystem::force_with).
// The loop is rk4_loop.h's, here with the force behind the MechanicalSystem interface; a model
// whose force is hot runs the same loop with its force inlined (models/static_rk4.h).
// At an output time the force is evaluated afresh for the observer's acceleration (counted in
// force_evaluations); that evaluation is at the state the next step starts from, so it doubles as
// that step's a₁ and costs nothing extra.

#include <memory>
#include <string>
#include <vector>

#include "bearing/solvers/integrator.h"
#include "bearing/solvers/rk4_loop.h"
#include "integrator_detail.h"

namespace bearing {
namespace solvers_detail {

namespace {

class Rk4 final : public Integrator {
 public:
  explicit Rk4(const IntegratorSettings& settings) : settings_(settings) {}

  IntegrationStats integrate(const MechanicalSystem& system, double t0,
                             const std::vector<double>& q0, const std::vector<double>& v0,
                             const std::vector<double>& output_times, const Observer& observe,
                             const Progress& progress) const override;

  std::string name() const override { return "rk4"; }

 private:
  IntegratorSettings settings_;
};

IntegrationStats Rk4::integrate(const MechanicalSystem& system, double t0,
                                const std::vector<double>& q0, const std::vector<double>& v0,
                                const std::vector<double>& output_times, const Observer& observe,
                                const Progress& progress) const {
  const std::unique_ptr<MechanicalSystem::Workspace> workspace = system.make_workspace();
  InterfaceForce force{system, workspace.get()};
  return rk4_loop<0>(name(), settings_.dt, settings_.max_displacement, system, t0, q0, v0,
                     output_times, observe, progress, force);
}

}  // namespace

std::unique_ptr<Integrator> make_rk4(const IntegratorSettings& settings) {
  return std::make_unique<Rk4>(settings);
}

}  // namespace solvers_detail
}  // namespace bearing
