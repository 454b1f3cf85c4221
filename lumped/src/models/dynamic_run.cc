// A dynamic model (2dof, 3dof, balls) through the case's integrator.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/local_defect.h"
#include "bearing/models/bearing_model.h"
#include "bearing/models/model_registry.h"

namespace bearing {

namespace {

std::string g3(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// RK4 beyond its stability limit does not blow up here: the contacts' nonlinearity keeps the
// unstable mode bounded, and the run would end with plausible-looking nonsense (the ball-DOF
// model at seed 004's 10 µs: x acceleration 3000 times too large; at 5 µs with μ_m = 0.05, where
// the balls' spin relaxes onto its traction equilibrium at ~1e6 1/s: 80 times). So a fixed
// explicit step is checked against the linearised system at the start (the static state); a step
// that is stable there but not at a later, harder impact still shows up as a blow-up or in a dt
// convergence check.
void check_explicit_step(const SolverSettings& s, const BearingModel& model,
                         const std::vector<double>& q0, const std::vector<double>& v0) {
  if (s.method != IntegratorMethod::rk4) return;
  const StepLimit limit = rk4_step_limit(model, 0.0, q0.data(), v0.data());
  if (s.dt <= limit.step) return;
  const bool relaxation = limit.imag < 1e-3 * std::abs(limit.real);
  const std::string mode = relaxation ? "a relaxation at rate " + g3(-limit.real) +
                                            " 1/s (stiff damping or traction, e.g. a ball's spin)"
                                      : "an oscillation at " + g3(limit.imag) + " rad/s (" +
                                            g3(limit.imag / two_pi) + " Hz, a stiff contact)";
  throw InputError("solver.dt = " + g3(s.dt * 1e6) + " us: RK4 is unstable above dt = " +
                   g3(limit.step * 1e6) + " us for the fastest mode of this case at its static " +
                   "state, " + mode + "; use solver.dt <= " + g3(0.9 * limit.step * 1e6) +
                   " us, or solver.method = \"newmark\" (stable at any step)");
}

// The quickest crossing of a defect by a contact [s] and the defect's index (infinite: none).
std::pair<double, std::size_t> quickest_transit(const ModelInputs& in, double cage_speed,
                                                double contact_angle) {
  std::pair<double, std::size_t> out{std::numeric_limits<double>::infinity(), 0};
  for (std::size_t i = 0; i < in.defects.size(); ++i) {
    const double tau =
        defect_transit_time(in.defects[i], in.bearing, in.inner_speed, cage_speed, contact_angle);
    if (tau < out.first) out = {tau, i};
  }
  return out;
}

// A fixed step must not jump over a defect (the adaptive methods get it as their largest step).
void check_defect_step(const SolverSettings& s, const ModelInputs& in, double transit,
                       std::size_t index) {
  const bool fixed = s.method == IntegratorMethod::rk4 || s.method == IntegratorMethod::newmark;
  if (!fixed || s.dt <= transit / kStepsPerDefectCrossing) return;
  const LocalDefect& d = in.defects[index];
  throw InputError(
      "solver.dt = " + g3(s.dt * 1e6) + " us: a step must not jump over a defect: " + "defects[" +
      std::to_string(index) + "] (" + name_of(kDefectLocations, d.location) + ", " +
      g3(d.width * 1e3) + " mm wide) is crossed in " + g3(transit * 1e6) +
      " us at this speed, and " + "resolving its entry and exit takes " +
      g3(kStepsPerDefectCrossing) +
      " steps: use solver.dt <= " + g3(transit / kStepsPerDefectCrossing * 1e6) + " us");
}

class DynamicRun final : public ModelRun {
 public:
  DynamicRun(std::unique_ptr<BearingModel> model, const ModelInputs& in, const SolverSettings& s,
             double contact_angle, std::unique_ptr<Integrator> (*rk4)(const IntegratorSettings&))
      : model_(std::move(model)),
        q0_(model_->initial_displacement()),
        v0_(model_->initial_velocity()) {
    // One tolerance for the user: the absolute tolerance on displacements is solver.tolerance
    // times the displacement scale of the problem (the static deflection, the per-ball gap, at
    // least 1 µm), so tightening the tolerance is never capped by a fixed absolute floor.
    double scale = std::max(1e-6, in.bearing.ball_gap());
    for (int i = 0; i < model_->dofs(); ++i)
      if (!model_->cyclic(i)) scale = std::max(scale, std::fabs(q0_[static_cast<std::size_t>(i)]));
    IntegratorSettings settings;
    settings.method = s.method;
    settings.dt = s.dt;
    settings.rtol = s.tolerance;
    settings.atol = s.tolerance * scale;
    settings.max_displacement = s.max_displacement;
    const auto [transit, defect] = quickest_transit(in, model_->cage_speed(), contact_angle);
    if (std::isfinite(transit)) settings.max_step = transit / kStepsPerDefectCrossing;
    integrator_ =
        rk4 && s.method == IntegratorMethod::rk4 ? rk4(settings) : make_integrator(settings);
    check_defect_step(s, in, transit, defect);
    check_explicit_step(s, *model_, q0_, v0_);
  }

  const ModelOutputs& outputs() const override { return *model_; }

  RunStats run(const std::vector<double>& times, const Observer& observe,
               const Progress& progress) const override {
    RunStats stats;
    stats.integration = integrator_->integrate(*model_, 0.0, q0_, v0_, times, observe, progress);
    return stats;
  }

 private:
  std::unique_ptr<BearingModel> model_;
  std::vector<double> q0_, v0_;
  std::unique_ptr<Integrator> integrator_;
};

}  // namespace

std::unique_ptr<ModelRun> make_dynamic_run(
    std::unique_ptr<BearingModel> model, const ModelInputs& inputs, const SolverSettings& solver,
    double contact_angle, std::unique_ptr<Integrator> (*rk4)(const IntegratorSettings&)) {
  return std::make_unique<DynamicRun>(std::move(model), inputs, solver, contact_angle, rk4);
}

}  // namespace bearing
