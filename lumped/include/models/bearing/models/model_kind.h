#pragma once
// The lumped models a case can select (model.kind). What each kind is built from, and how it runs,
// is its entry in the model registry (bearing/model_registry.h).

#include "bearing/choice.h"

namespace bearing {

enum class ModelKind {
  two_dof,       ///< inner ring x, y (seeds 001–003)
  three_dof,     ///< x, y and the axial z under an axial load or preload (seed 001)
  balls,         ///< x, y and each ball's radial position and spin, cage slip, traction (seed 004)
  quasi_static,  ///< the force balance at each instant, no inertia (seed 000)
};
inline constexpr Named<ModelKind> kModelKinds[] = {{ModelKind::two_dof, "2dof"},
                                                   {ModelKind::three_dof, "3dof"},
                                                   {ModelKind::balls, "balls"},
                                                   {ModelKind::quasi_static, "quasistatic"}};

}  // namespace bearing
