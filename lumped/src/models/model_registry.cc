// One row per model kind (model_registry.h).

#include "bearing/models/model_registry.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "bearing/errors.h"
#include "bearing/units.h"

#include "bearing/models/ball_dofs.h"
#include "bearing/models/three_dof.h"
#include "bearing/models/two_dof.h"

namespace bearing {

namespace {

double free_angle(const ModelInputs& in) {
  return in.bearing.contact_angle;
}
double loaded_angle(const ModelInputs& in) {
  return solve_axial_preload(in).contact_angle;
}
// The ball-DOF model turns at the 3-DOF model's loaded angle when it carries an axial load.
double ball_angle(const ModelInputs& in) {
  return in.axial_load != 0 ? loaded_angle(in) : free_angle(in);
}

}  // namespace

const std::vector<ModelDescriptor>& model_registry() {
  static const std::vector<ModelDescriptor> registry{
      {ModelKind::two_dof,
       "inner ring x, y (seeds 001-003)",
       {},
       false,
       false,
       free_angle,
       make_two_dof_model,
       nullptr,
       make_two_dof_rk4,
       make_two_dof_housed,
       make_two_dof_housed_rk4},
      {ModelKind::three_dof,
       "x, y and the axial z under an axial load or preload (seed 001)",
       {},
       false,
       true,
       loaded_angle,
       make_three_dof_model,
       nullptr,
       make_three_dof_rk4,
       make_three_dof_housed,
       make_three_dof_housed_rk4},
      {ModelKind::balls,
       "ball DOFs, cage slip and traction (seed 004)",
       {"cage", "ball"},
       true,
       true,
       ball_angle,
       [](const ModelInputs& in) -> std::unique_ptr<BearingModel> {
         return make_ball_dof_model(in);
       },
       nullptr,
       make_ball_dof_rk4},
      {ModelKind::quasi_static,
       "equilibrium per output instant, no inertia (seed 000)",
       {},
       false,
       false,
       free_angle,
       nullptr,
       make_quasi_static_run},
  };
  return registry;
}

bool ModelDescriptor::owns(const std::string& name) const {
  return std::find(tables.begin(), tables.end(), name) != tables.end();
}

void check_defects_supported(ModelKind kind, const std::vector<LocalDefect>& defects) {
  if (defects.empty() || model_descriptor(kind).dynamic) return;
  std::string dynamic;
  for (const ModelDescriptor& d : model_registry())
    if (d.dynamic)
      dynamic += std::string(dynamic.empty() ? "" : ", ") + name_of(kModelKinds, d.kind);
  throw InputError("[[defects]]: model.kind = \"" + std::string(name_of(kModelKinds, kind)) +
                   "\" does not integrate in time, and a spall's impacts last a fraction of a "
                   "millisecond between its output instants; use a model that does (" +
                   dynamic + ")");
}

void check_axial_load_supported(ModelKind kind, double axial_load, double radial_load) {
  if (axial_load == 0 || model_descriptor(kind).axial_load) return;
  std::string carriers;
  for (const ModelDescriptor& d : model_registry())
    if (d.axial_load)
      carriers +=
          std::string(carriers.empty() ? "" : " or ") + "\"" + name_of(kModelKinds, d.kind) + "\"";
  const std::string kind_name = name_of(kModelKinds, kind);
  const std::string why =
      radial_load == 0
          ? "with no radial load no ball is in its load zone, so nothing carries the axial load "
            "and the static solution does not exist"
          : "its contacts are radial and would ignore it";
  throw InputError("operation.axial_load = " + format_number(axial_load) + " N: model.kind = \"" +
                   kind_name + "\" has no axial degree of freedom (" + why +
                   "); allowed: 0 with this kind, or model.kind = " + carriers);
}

void check_housing_supported(ModelKind kind, const Housing& housing) {
  if (!housing.enabled || model_descriptor(kind).housing()) return;
  std::string carriers;
  for (const ModelDescriptor& d : model_registry())
    if (d.housing())
      carriers +=
          std::string(carriers.empty() ? "" : " or ") + "\"" + name_of(kModelKinds, d.kind) + "\"";
  const std::string why =
      model_descriptor(kind).dynamic
          ? "its balls' inertia would have to follow the moving outer ring, which it does not model"
          : "it has no inertia, and the housing is a resonance";
  throw InputError("[housing]: model.kind = \"" + std::string(name_of(kModelKinds, kind)) +
                   "\" keeps the outer ring fixed to the ground (" + why +
                   "); the housing needs model.kind = " + carriers + ", or remove [housing]");
}

std::unique_ptr<BearingModel> make_dynamic_model(ModelKind kind, const ModelInputs& inputs) {
  const ModelDescriptor& d = model_descriptor(kind);
  if (!d.dynamic)
    throw InputError("model.kind = \"" + std::string(name_of(kModelKinds, kind)) +
                     "\" has no equations of motion (no integrator runs it)");
  if (!inputs.housing.enabled) return d.dynamic(inputs);
  check_housing_supported(kind, inputs.housing);
  // The bearing's force without the ring loads is what it exerts on the inner ring (housing.h);
  // the static start comes from the model with them.
  ModelInputs bearing_only = inputs;
  bearing_only.load = Eigen::Vector2d::Zero();
  bearing_only.unbalance = 0.0;
  bearing_only.gravity = false;
  RingLoad load;
  load.constant = inputs.radial_load();
  load.unbalance_force = inputs.unbalance * inputs.inner_speed * inputs.inner_speed;
  load.shaft_speed = inputs.inner_speed;
  return d.housed(bearing_only, load, inputs.housing, d.dynamic(inputs)->initial_displacement());
}

std::unique_ptr<ModelRun> make_run(ModelKind kind, const ModelInputs& inputs,
                                   const SolverSettings& solver) {
  const ModelDescriptor& d = model_descriptor(kind);
  check_defects_supported(kind, inputs.defects);
  check_axial_load_supported(kind, inputs.axial_load, inputs.radial_load().norm());
  check_housing_supported(kind, inputs.housing);
  if (d.dynamic)
    return make_dynamic_run(make_dynamic_model(kind, inputs), inputs, solver,
                            d.contact_angle(inputs), inputs.housing.enabled ? d.housed_rk4 : d.rk4);
  return d.run(inputs, solver);
}

const ModelDescriptor& model_descriptor(ModelKind kind) {
  for (const ModelDescriptor& d : model_registry())
    if (d.kind == kind) return d;
  throw std::logic_error("model registry: no row for model kind " +
                         std::string(name_of(kModelKinds, kind)));
}

}  // namespace bearing
