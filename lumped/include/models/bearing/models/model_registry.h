#pragma once
// The model kinds (model.kind), one descriptor each: what the kind is built from, whether an
// integrator runs it, which case tables only it reads, and the contact angle its kinematics use.
// Adding a model kind is one file with its make function and one row in model_registry.cc.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bearing/models/bearing_model.h"
#include "bearing/models/model_inputs.h"
#include "bearing/models/model_kind.h"
#include "bearing/models/model_outputs.h"
#include "bearing/models/quasi_static.h"
#include "bearing/solvers/integrator.h"

namespace bearing {

/// What a run did: the integrator's counts, or the quasi-static follower's.
struct RunStats {
  IntegrationStats integration;                  ///< dynamic models; quasi-static: steps only
  std::optional<QuasiStaticStats> quasi_static;  ///< quasi-static only
};

/// A model ready to run through the output times.
class ModelRun {
 public:
  virtual ~ModelRun() = default;
  /// What the outputs read from the model.
  virtual const ModelOutputs& outputs() const = 0;
  /// Calls `observe` at each of `times` (ascending) with the state and its acceleration [SI].
  /// Throws SolverError (blow-up, no convergence).
  virtual RunStats run(const std::vector<double>& times, const Observer& observe,
                       const Progress& progress) const = 0;
};

struct ModelDescriptor {
  ModelKind kind;
  const char* summary;  ///< one line
  /// The case tables only this kind reads (an error with any other kind).
  std::vector<std::string> tables;
  /// Has ball DOFs: the spin, outer-load and friction channels (output.ball_dynamics).
  bool ball_dofs;
  /// Carries operation.axial_load (an axial DOF, or the loaded contact angle). A kind without
  /// one has no equilibrium for an axial load: check_axial_load_supported refuses it.
  bool axial_load;
  /// The contact angle the model's kinematics use [rad]: the free one, or the loaded one of the
  /// axial static state.
  double (*contact_angle)(const ModelInputs&);
  /// A dynamic model (equations of motion): an integrator runs it, [solver] method, dt and
  /// tolerance apply. nullptr for a kind that runs otherwise (`run`).
  std::unique_ptr<BearingModel> (*dynamic)(const ModelInputs&) = nullptr;
  /// How a kind without equations of motion runs (nullptr for a dynamic one).
  std::unique_ptr<ModelRun> (*run)(const ModelInputs&, const SolverSettings&) = nullptr;
  /// RK4 with this kind's force statically dispatched (static_rk4.h: the same bits as
  /// make_integrator's RK4, which runs the kind when this is nullptr or the model is wrapped by
  /// [housing]); for a dynamic kind whose force is hot. It integrates only the kind's own model.
  std::unique_ptr<Integrator> (*rk4)(const IntegratorSettings&) = nullptr;
  /// Carries [housing]: the kind's model on the outer ring's support (housing.h) built from the
  /// inputs without the ring loads, the ring loads, the housing and the relative static start (as
  /// make_housing_model, with the kind's force statically dispatched). nullptr: the kind keeps its
  /// outer ring on the ground, and check_housing_supported refuses the table.
  std::unique_ptr<BearingModel> (*housed)(const ModelInputs& bearing_only, const RingLoad& load,
                                          const Housing& housing,
                                          std::vector<double> start) = nullptr;
  /// RK4 with the housed model's force statically dispatched (as `rk4`, for `housed`'s model).
  std::unique_ptr<Integrator> (*housed_rk4)(const IntegratorSettings&) = nullptr;

  /// Whether this kind carries [housing].
  bool housing() const { return housed != nullptr; }
  /// Whether this kind reads the case table `name`.
  bool owns(const std::string& name) const;
};

/// Every model kind, in the order of kModelKinds.
const std::vector<ModelDescriptor>& model_registry();

/// The descriptor of `kind`.
const ModelDescriptor& model_descriptor(ModelKind kind);

/// The model of `kind` built from `inputs`, ready to run with `solver`. Throws InputError naming
/// the case key for inputs the model cannot run.
std::unique_ptr<ModelRun> make_run(ModelKind kind, const ModelInputs& inputs,
                                   const SolverSettings& solver);

/// Local defects need a kind that integrates in time (a dynamic one): the impacts live between
/// the output instants a quasi-static run would sample. Throws InputError naming [[defects]] and
/// the kind otherwise.
void check_defects_supported(ModelKind kind, const std::vector<LocalDefect>& defects);

/// operation.axial_load `axial_load` [N] needs a kind that carries it (ModelDescriptor::
/// axial_load); `radial_load` [N] (the constant radial load's size, gravity included) only words
/// the error. Throws InputError naming operation.axial_load, its value and the kinds that carry
/// it.
void check_axial_load_supported(ModelKind kind, double axial_load, double radial_load);

/// [housing] (`housing.enabled`) needs a kind that carries it (ModelDescriptor::housed). Throws
/// InputError naming [housing], the kind, why it cannot, and the kinds that can.
void check_housing_supported(ModelKind kind, const Housing& housing);

/// The equations of motion of `kind` for `inputs`: the kind's own model, carried by the housing
/// (housing.h) when inputs.housing.enabled. Throws InputError for a kind without equations of
/// motion, one that cannot carry the housing, or inputs the model refuses.
std::unique_ptr<BearingModel> make_dynamic_model(ModelKind kind, const ModelInputs& inputs);

/// A dynamic model through the [solver] integrator (dynamic_run.cc); `contact_angle` [rad] the
/// kind's kinematic angle (ModelDescriptor::contact_angle), which the defects' transit times use.
/// Throws InputError naming solver.dt for a fixed step that would jump over a local defect, or
/// that RK4 cannot run stably.
/// `rk4`: the kind's statically dispatched RK4 (ModelDescriptor::rk4), used when solver.method is
/// rk4 (nullptr: make_integrator's).
std::unique_ptr<ModelRun> make_dynamic_run(
    std::unique_ptr<BearingModel> model, const ModelInputs& inputs, const SolverSettings& solver,
    double contact_angle, std::unique_ptr<Integrator> (*rk4)(const IntegratorSettings&) = nullptr);
/// The quasi-static model followed through the output times (quasi_static_run.cc).
std::unique_ptr<ModelRun> make_quasi_static_run(const ModelInputs& inputs,
                                                const SolverSettings& solver);

}  // namespace bearing
