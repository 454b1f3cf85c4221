#pragma once
// Private to the lumped models (not installed): RK4 with a model's force statically dispatched,
// for the model kinds whose force is hot (a registry row's `rk4`, model_registry.h).
//
// Why: make_integrator's RK4 calls MechanicalSystem::force_with through a virtual call four
// times a step, so the compiler can neither inline the force (the frame lookup, the contact loop's
// set-up) nor keep the state of a 2-DOF model in registers across the stages. Here the same loop
// (rk4_loop.h) is instantiated with Model::force_at and the DOF count as compile-time constants:
// the same steps, the same operations in the same order, so the same bits as make_integrator's
// RK4, which stays the path of every other system (and of this model when wrapped by the
// housing: make_run passes the kind's row only for an unwrapped model).

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "bearing/solvers/integrator.h"
#include "bearing/solvers/rk4_loop.h"
#include "frame_workspace.h"

namespace bearing::detail {

/// RK4 (IntegratorSettings::dt, max_displacement) on systems of type Model (a FrameForce model
/// with kDofs DOFs) only: integrate() throws std::logic_error for any other system (a wiring
/// fault: such a system belongs to make_integrator's RK4), so a run never falls back unseen.
template <class Model, int kDofs>
class StaticRk4 final : public Integrator {
 public:
  /// `settings` with method rk4, validated as make_integrator does (InputError as there).
  explicit StaticRk4(const IntegratorSettings& settings) : settings_(settings) {
    make_integrator(settings);
  }

  IntegrationStats integrate(const MechanicalSystem& system, double t0,
                             const std::vector<double>& q0, const std::vector<double>& v0,
                             const std::vector<double>& output_times, const Observer& observe,
                             const Progress& progress) const override {
    const auto* model = dynamic_cast<const Model*>(&system);
    if (!model || model->dofs() != kDofs)
      throw std::logic_error(
          "a model kind's own RK4 was given a system of another kind (make_integrator's RK4 runs "
          "it)");
    FrameWorkspace<typename Model::FrameType> workspace;
    return solvers_detail::rk4_loop<kDofs>(
        name(), settings_.dt, settings_.max_displacement, system, t0, q0, v0, output_times, observe,
        progress, [&](double t, const double* q, const double* v, double* f) {
          model->force_at(workspace, t, q, v, f);
        });
  }

  std::string name() const override { return "rk4"; }

 private:
  IntegratorSettings settings_;
};

}  // namespace bearing::detail
