#pragma once
// `bearing-sim run` as pipeline stages, each with its own inputs and outputs:
//
//   Case ──run_settings──▶ RunSettings
//   simulate(kind, ModelInputs, SolverSettings, OutputRequest) ──▶ SimulationResult (Response)
//   analyse(Response, frequencies, AnalysisSettings)           ──▶ RunSummary
//   radiate(Response, AcousticsOptions, Bearing, RunKinematics) ──▶ BearingNoise
//
// summarize() is analyse() plus radiate() for a case.

#include <optional>

#include "bearing/analysis.h"
#include "bearing/case_file.h"
#include "bearing/contact.h"
#include "bearing/kinematics.h"
#include "bearing/models/model_inputs.h"
#include "bearing/models/model_registry.h"
#include "bearing/noise.h"
#include "bearing/response.h"
#include "bearing/solvers/integrator.h"

namespace bearing {

/// Everything one run is made of, mapped from a case once.
struct RunSettings {
  ModelKind kind = ModelKind::two_dof;
  ModelInputs model;  ///< excitations resolved, contact constants computed
  SolverSettings solver;
  OutputRequest output;
  AnalysisSettings analysis;
  AcousticsOptions acoustics;  ///< enabled only with an [acoustics] table
};

/// The loads of `c` its model kind must carry to run: operation.axial_load needs a kind with an
/// axial DOF (check_axial_load_supported), and operation.moment must be [0, 0] (no kind has a tilt
/// DOF). Throws InputError naming the key, its value and why. run_settings() and make_model() call
/// it; the static analyses (info, the 5-DOF stiffness) carry every load and do not.
void check_run_loads(const Case& c);

/// The one Case → settings mapper (check_run_loads first).
RunSettings run_settings(const Case& c);

/// The model inputs a case describes (run_settings(c).model).
ModelInputs model_inputs(const Case& c);

/// The dynamic model of `c.model.kind` (InputError for a kind without equations of motion, or
/// loads it cannot carry: check_run_loads).
std::unique_ptr<BearingModel> make_model(const Case& c);

struct SimulationResult {
  Response response;
  IntegrationStats stats;                        ///< dynamic models; quasistatic: steps only
  std::optional<QuasiStaticStats> quasi_static;  ///< quasistatic only
  ContactConstants contact;
  BearingFrequencies frequencies;  ///< at the model's contact angle, with cage slip
  double cage_speed = 0;           ///< ω_ca of the model's balls [rad/s]
  /// The frequencies and the model's cage speed and contact angle together.
  RunKinematics kinematics() const;
};

/// Runs a model kind (model_registry.h) through the output times. Throws InputError (bad
/// settings) or SolverError (blow-up, no convergence).
SimulationResult simulate(ModelKind kind, const ModelInputs& inputs, const SolverSettings& solver,
                          const OutputRequest& output, const Progress& progress = {});

/// simulate() with a case's settings.
SimulationResult simulate(const Case& c, const Progress& progress = {});

/// analyse() with the case's window and peak count, and, with an [acoustics] table, radiate().
RunSummary summarize(const Case& c, const SimulationResult& result);

}  // namespace bearing
