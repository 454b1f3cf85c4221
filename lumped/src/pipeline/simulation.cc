// The run pipeline (simulation.h): one mapper from the case, then simulate, analyse, radiate.

#include "bearing/simulation.h"

#include "bearing/errors.h"
#include "bearing/excitation_families.h"
#include "bearing/models/three_dof.h"
#include "bearing/units.h"

namespace bearing {

ModelInputs model_inputs(const Case& c) {
  ModelInputs in;
  in.bearing = c.bearing;
  in.hertz_method = hertz_shape_method(c.model);
  in.contact_loop = c.solver.contact_loop;
  in.contact = contact_constants(c);
  in.inner_speed = c.operation.speed;
  in.load = c.operation.load;
  in.axial_load = c.operation.axial_load;
  in.unbalance = c.operation.unbalance;
  in.gravity = c.operation.gravity;
  in.mass = c.rotor.mass;
  in.damping = c.rotor.damping;
  in.axial_mass = c.rotor.axial_mass;
  in.axial_damping = c.rotor.axial_damping;
  in.housing = c.housing;
  in.slip = c.slip;
  in.slip_span = c.solver.duration;
  in.lubricated = c.lubricant.enabled;
  in.lubricant = c.lubricant;
  in.inner_waviness.harmonics = c.excitation.inner_waviness;
  in.outer_waviness.harmonics = c.excitation.outer_waviness;
  in.ball_size_errors = c.excitation.ball_size_errors;
  in.defects = c.excitation.defects;
  in.waviness_stiffness = c.model.waviness_stiffness;
  in.cage_slip = c.cage.slip;
  in.traction = make_traction_curve(c.cage.friction, c.cage.slide_speed);
  in.ball_mass = c.ball.mass;
  in.ball_inertia = c.ball.inertia;
  in.ball_damping = c.ball.damping;
  in.centrifugal = c.ball.centrifugal;
  return in;
}

namespace {

void check_loads(const Case& c) {
  const Eigen::Vector2d& m = c.operation.moment;
  if (!m.isZero(0.0))
    throw InputError(
        "operation.moment = [" + format_number(m.x()) + ", " + format_number(m.y()) +
        "] N m: model.kind = \"" + std::string(name_of(kModelKinds, c.model.kind)) +
        "\" has no tilt degree of freedom (no model kind of run or sweep has one: "
        "the inner ring only translates), so it cannot carry a moment; allowed: [0, 0] "
        "here; the moment is used by `bearing-sim stiffness` and `info` (the 5-DOF "
        "static solution)");
  ModelInputs loads;  // only for its radial_load(): the weight with gravity on
  loads.load = c.operation.load;
  loads.gravity = c.operation.gravity;
  loads.mass = c.rotor.mass;
  check_axial_load_supported(c.model.kind, c.operation.axial_load, loads.radial_load().norm());
}

}  // namespace

void check_run_loads(const Case& c) {
  try {
    check_loads(c);
  } catch (const InputError& e) {  // named by the case, as the case reader's errors are
    throw InputError(c.source.empty() ? std::string(e.what()) : c.source + ": " + e.what());
  }
}

RunSettings run_settings(const Case& c) {
  check_run_loads(c);
  RunSettings s;
  s.kind = c.model.kind;
  s.model = model_inputs(c);
  s.solver = c.solver;
  s.output.ball_loads = c.output.ball_loads;
  s.output.ball_approach = c.output.ball_approach;
  // The acoustics needs the balls' motion when the balls are sound sources.
  s.output.ball_motion =
      c.output.ball_motion || (c.acoustics.enabled && c.acoustics.ball_source != BallSource::none);
  s.output.ball_dynamics = c.output.ball_dynamics;
  s.output.ball_film = c.output.ball_film;
  s.analysis.window = c.output.window;
  s.analysis.peaks = c.output.peaks;
  s.analysis.envelope = c.output.envelope_band;
  s.analysis.lines = excitation_families(s.kind, s.model);
  s.acoustics = c.acoustics;
  return s;
}

std::unique_ptr<BearingModel> make_model(const Case& c) {
  check_run_loads(c);
  return make_dynamic_model(c.model.kind, model_inputs(c));
}

RunKinematics SimulationResult::kinematics() const {
  RunKinematics k;
  k.frequencies = frequencies;
  k.cage_speed = cage_speed;
  return k;
}

SimulationResult simulate(ModelKind kind, const ModelInputs& in, const SolverSettings& solver,
                          const OutputRequest& output, const Progress& progress) {
  const ModelDescriptor& d = model_descriptor(kind);
  SimulationResult r;
  r.contact = in.contact;
  Bearing turning = in.bearing;
  turning.contact_angle = d.contact_angle(in);
  r.frequencies = bearing_frequencies(turning, in.inner_speed, 0.0, in.cage_slip);
  const std::unique_ptr<ModelRun> model = make_run(kind, in, solver);
  r.cage_speed = model->outputs().cage_speed();
  r.response = lay_out_response(model->outputs(), output,
                                {solver.duration, solver.transient, solver.output_rate});
  ResponseRecorder record(model->outputs(), output, r.response);
  const RunStats stats = model->run(r.response.time, std::ref(record), progress);
  if (record.samples() != r.response.time.size())
    throw SolverError("the model delivered " + std::to_string(record.samples()) + " of " +
                      std::to_string(r.response.time.size()) + " output samples");
  r.stats = stats.integration;
  r.quasi_static = stats.quasi_static;
  return r;
}

SimulationResult simulate(const Case& c, const Progress& progress) {
  const RunSettings s = run_settings(c);
  return simulate(s.kind, s.model, s.solver, s.output, progress);
}

RunSummary summarize(const Case& c, const SimulationResult& result) {
  const RunSettings s = run_settings(c);
  RunSummary summary = analyse(result.response, result.frequencies, s.analysis);
  if (s.acoustics.enabled)
    summary.noise = radiate(result.response, s.acoustics, c.bearing, result.kinematics());
  return summary;
}

}  // namespace bearing
