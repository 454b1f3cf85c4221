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
#include <type_traits>
#include <utility>
#include <vector>

#include "bearing/solvers/integrator.h"
#include "bearing/solvers/rk4_loop.h"
#include "frame_workspace.h"

namespace bearing::detail {

/// Whether Model says where its DOFs split between one at a time and vectors (rk4_loop.h).
template <class M, class = void>
struct HasWideFrom : std::false_type {};
template <class M>
struct HasWideFrom<M, std::void_t<decltype(std::declval<const M&>().wide_from())>>
    : std::true_type {};

/// RK4 (IntegratorSettings::dt, max_displacement) on systems of type Model (a FrameForce model
/// with kDofs DOFs, or 0: a count known at run time) only: integrate() throws std::logic_error for
/// any other system (a wiring fault: such a system belongs to make_integrator's RK4), so a run
/// never falls back unseen.
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
    if (!model || (kDofs > 0 && model->dofs() != kDofs))
      throw std::logic_error(
          "a model kind's own RK4 was given a system of another kind (make_integrator's RK4 runs "
          "it)");
    AheadForce force{*model, {}, {}, {}, 0, {}};
    return solvers_detail::rk4_loop<kDofs>(name(), settings_.dt, settings_.max_displacement, system,
                                           t0, q0, v0, output_times, observe, progress, force);
  }

  std::string name() const override { return "rk4"; }

 private:
  // The model's force with the ball set's time_angles() of a segment's new times computed ahead,
  // together, before its steps (their phasors are independent chains of ~40 dependent
  // operations each, which then overlap; one at a time, inside each evaluation, they lay on its
  // critical path). The values are time_angles(t)'s own: the same bits.
  struct AheadForce {
    const Model& model;
    FrameWorkspace<typename Model::FrameType> workspace;
    std::vector<double> times;                // the new times of the segment, in call order
    std::vector<BallSet::TimeAngles> angles;  // time_angles() of each
    std::size_t next;                         // the first entry not yet used
    std::vector<double> scratch;              // BallSet::time_angles' work arrays

    void ahead(const std::vector<solvers_detail::Rk4Step>& plan, double t_out) {
      times.clear();
      auto add = [&](double t) {
        if (times.empty() || times.back() != t) times.push_back(t);
      };
      for (const solvers_detail::Rk4Step& s : plan) {
        add(s.t);
        add(s.mid);
        add(s.end);
      }
      add(t_out);
      angles.resize(times.size());
      model.time_angles(times.data(), static_cast<int>(times.size()), angles.data(), scratch);
      next = 0;
    }

    // The model's split of its DOFs (rk4_loop.h): Model::wide_from() where it has one, else
    // vectorised throughout from kRk4WideDofs DOFs on.
    int wide_from(int n) const {
      if constexpr (HasWideFrom<Model>::value)
        return model.wide_from();
      else
        return n >= solvers_detail::kRk4WideDofs ? 0 : n;
    }

    [[gnu::always_inline]] void operator()(double t, const double* q, const double* v, double* f) {
      // The calls come in the order of `times`, each new time after the last one used (a time
      // already in the workspace needs no angles).
      const BallSet::TimeAngles* found = nullptr;
      for (std::size_t i = next; i < times.size() && i < next + 3; ++i)
        if (times[i] == t) {
          found = &angles[i];
          next = i + 1;
          break;
        }
      model.force_at(workspace, t, q, v, f, found);
    }
  };

  IntegratorSettings settings_;
};

}  // namespace bearing::detail
