// The quasi-static model (seed 000) through the output times: the equilibrium followed from
// instant to instant, fed to the same observer as the integrators.

#include <Eigen/Dense>

#include "bearing/models/model_registry.h"
#include "bearing/models/quasi_static.h"

namespace bearing {

namespace {

// The quasi-static model's ball outputs at (t, q = position, v = velocity).
class QuasiStaticOutputs final : public ModelOutputs {
 public:
  explicit QuasiStaticOutputs(std::unique_ptr<QuasiStaticModel> model) : model_(std::move(model)) {}
  const QuasiStaticModel& model() const { return *model_; }

  std::vector<std::string> dof_names() const override { return {"x", "y"}; }
  int balls() const override { return model_->balls(); }
  double cage_speed() const override { return model_->cage_speed(); }
  bool has_cage_slip() const override { return model_->has_cage_slip(); }
  double cage_slip_angle(double t) const override { return model_->cage_slip_angle(t); }
  void ball_state(double t, const double* q, const double* v, BallFields fields,
                  BallState& s) const override {
    const Eigen::Vector2d position(q[0], q[1]);
    if (has(fields, BallField::load)) model_->ball_loads(t, position, s[BallField::load].data());
    if (has(fields, BallField::approach))
      model_->ball_approaches(t, position, s[BallField::approach].data());
    if (has(fields, BallField::radial) || has(fields, BallField::radial_velocity)) {
      QuasiStaticPoint point;
      point.t = t;
      point.position = position;
      point.velocity = Eigen::Vector2d(v[0], v[1]);
      model_->ball_motion(point, s[BallField::radial].data(), s[BallField::radial_velocity].data());
    }
  }

 private:
  std::unique_ptr<QuasiStaticModel> model_;
};

class QuasiStaticRun final : public ModelRun {
 public:
  explicit QuasiStaticRun(const ModelInputs& in) : outputs_(make_quasi_static_model(in)) {}

  const ModelOutputs& outputs() const override { return outputs_; }

  // The model has no acceleration of its own (no inertia); the one observed is the centred
  // difference of the analytic velocities, (v_{k+1} − v_{k−1}) / (2Δt), the mean acceleration
  // over [t_{k−1}, t_{k+1}] (one-sided at the ends), so spectra of a* work as for the dynamic
  // models. Hence the whole orbit first, then the observer.
  RunStats run(const std::vector<double>& times, const Observer& observe,
               const Progress& progress) const override {
    std::vector<Eigen::Vector2d> p, v;
    p.reserve(times.size());
    v.reserve(times.size());
    const auto keep = [&](const QuasiStaticPoint& pt) {
      p.push_back(pt.position);
      v.push_back(pt.velocity);
    };
    RunStats stats;
    stats.quasi_static = follow_equilibrium(outputs_.model(), times, keep, progress);
    stats.integration.steps = stats.quasi_static->steps;
    const std::size_t m = times.size();
    for (std::size_t s = 0; s < m; ++s) {
      const std::size_t lo = s == 0 ? 0 : s - 1, hi = s + 1 == m ? s : s + 1;
      Eigen::Vector2d a = Eigen::Vector2d::Zero();
      for (int i = 0; i < 2; ++i)
        a[i] = hi > lo ? (v[hi][i] - v[lo][i]) / (times[hi] - times[lo]) : 0.0;
      observe(times[s], p[s].data(), v[s].data(), a.data());
    }
    return stats;
  }

 private:
  QuasiStaticOutputs outputs_;
};

}  // namespace

std::unique_ptr<ModelRun> make_quasi_static_run(const ModelInputs& inputs, const SolverSettings&) {
  return std::make_unique<QuasiStaticRun>(inputs);
}

}  // namespace bearing
