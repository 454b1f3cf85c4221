// The quasi-static model (docs/model.md §4, seed 000); see quasi_static.h for the equations, the
// solver and the minimum load.

#include "bearing/models/quasi_static.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "ball_motion.h"
#include "ball_set.h"
#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/kinematics.h"
#include "bearing/numerics/newton.h"
#include "bearing/static_load.h"
#include "bearing/units.h"
#include "model_input_checks.h"

namespace bearing {

namespace {

constexpr double kTarget = 1e-12;   // |g|/|F| aimed at (rounding level)
constexpr double kRequired = 1e-9;  // |g|/|F| above which the solve fails
constexpr int kNewtonIterations = 30;

double sum_amplitudes(const Waviness& w) {
  double s = 0;
  for (const WavinessHarmonic& h : w.harmonics) s += h.amplitude;
  return s;
}

// The balance at one point: V, g = ∇V and J = ∇²V (quasi_static.h), and the loaded balls.
struct Balance : numerics::PotentialPoint<2> {
  int loaded = 0;
};

// Validates the inputs (before anything is built from them) and returns ω_c.
double checked_cage_speed(const ModelInputs& in) {
  detail::validate_common_inputs(in);
  return cage_speed(in.bearing, in.inner_speed);
}

class QuasiStatic final : public QuasiStaticModel {
 public:
  explicit QuasiStatic(const ModelInputs& in)
      : set_(in, checked_cage_speed(in), in.bearing.contact_angle),
        gap_(in.bearing.ball_gap()),
        inner_speed_(in.inner_speed),
        load_(in.radial_load()),
        unbalance_force_(in.unbalance * in.inner_speed * in.inner_speed),
        phase_(in.cage_phase),
        minimum_load_(quasi_static_minimum_load(in)),
        smooth_load_(quasi_static_smooth_load(in)) {
    const double least = load_.norm() - unbalance_force_;
    if (!(least > minimum_load_ && least > 0)) {
      std::string what = "operation.load = (" + format_number(in.load.x()) + ", " +
                         format_number(in.load.y()) + ") N";
      if (in.gravity || unbalance_force_ > 0)
        what += " (with gravity and unbalance, |F(t)| down to " + format_number(least) + " N)";
      throw InputError(
          what + ": the quasi-static model needs |F| > F_min = " + format_number(minimum_load_) +
          " N = K [gamma (1/cos(2 pi/Z) - 1)]^n for this bearing (below it the ring floats in "
          "the clearance: a single ball holds it each time the load line passes a ball, and the "
          "orbit jumps; see quasi_static.h); raise the load or use model.kind = \"2dof\"");
    }
    StaticLoadOptions o;
    o.phase = phase_;
    o.exponent = set_.exponent();
    const StaticLoadResult r = solve_static_load(set_.balls(), set_.K(), gap_, load_, o);
    static_ = r.deflection;
    // Stiffness scale for the damped Newton: the trace of J at the static solution.
    stiffness_scale_ = 0;
    for (double d : r.ball_approach)
      if (d > 0) stiffness_scale_ += set_.exponent() * set_.K() * std::pow(d, set_.exponent() - 1);
    stiffness_scale_ = std::max(stiffness_scale_, 1e-30);
  }

  int balls() const override { return set_.balls(); }
  double cage_speed() const override { return set_.cage_speed(); }
  bool has_cage_slip() const override { return set_.slip() != nullptr; }
  double cage_slip_angle(double t) const override {
    return set_.slip() ? set_.slip()->angle(t) : 0.0;
  }
  double minimum_load() const override { return minimum_load_; }
  double smooth_load() const override { return smooth_load_; }
  Eigen::Vector2d static_position() const override { return static_; }

  Eigen::Vector2d load(double t) const override {
    const double a = inner_speed_ * t;
    return load_ + unbalance_force_ * Eigen::Vector2d(std::cos(a), std::sin(a));
  }

  QuasiStaticPoint solve(double t, const Eigen::Vector2d& guess) const override {
    detail::BallFrame fr;
    set_.evaluate(t, fr);
    const Eigen::Vector2d F = load(t);
    const double scale = F.norm();
    QuasiStaticPoint pt;
    pt.t = t;
    Eigen::Vector2d p = guess;
    Balance b = balance(fr, F, p);
    const auto evaluate = [&](const Eigen::Vector2d& q) { return balance(fr, F, q); };
    // Newton, full steps while |g| falls; singular with < 2 non-collinear loaded balls.
    numerics::FullStepOptions newton;
    newton.tolerance = kTarget * scale;
    newton.good_enough = kRequired * scale * 1e-2;
    newton.max_iterations = kNewtonIterations;
    const numerics::FullStepResult fast = numerics::newton_full_steps(p, b, evaluate, newton);
    pt.iterations += fast.iterations;
    if (!fast.converged) {
      // Levenberg-damped Newton with an Armijo line search on V, then Newton polishing: V is
      // convex and coercive, so each damped step with a small enough length decreases it.
      pt.fallback = true;
      numerics::LevenbergOptions damped;
      damped.tolerance = kTarget * scale;
      damped.stiffness = stiffness_scale_;
      pt.iterations += numerics::levenberg_minimize(p, b, evaluate, damped);
    }
    pt.position = p;
    pt.residual = b.gradient.norm() / scale;
    pt.loaded_balls = b.loaded;
    if (!(pt.residual <= kRequired))
      throw SolverError("quasi-static balance at t = " + format_number(t) +
                        " s: residual |g|/|F| = " + format_number(pt.residual) +
                        " after damped Newton (needs <= 1e-9)");
    pt.velocity = velocity(t, fr, p, b.hessian);
    return pt;
  }

  // δ_j of the header at the ring position p.
  auto approach_at(const Eigen::Vector2d& p) const {
    return [this, p](int j, const detail::BallFrame& fr) {
      return p.x() * fr.cos_theta[j] + p.y() * fr.sin_theta[j] - gap_ + fr.excitation[j];
    };
  }

  void ball_loads(double t, const Eigen::Vector2d& position, double* loads) const override {
    set_.ball_loads(t, approach_at(position), loads);
  }

  void ball_approaches(double t, const Eigen::Vector2d& position, double* out) const override {
    set_.ball_approaches(t, approach_at(position), out);
  }

  void ball_motion(const QuasiStaticPoint& pt, double* r, double* vr) const override {
    detail::radial_ball_motion(set_, gap_, pt.t, pt.position.data(), pt.velocity.data(), r, vr);
  }

 private:
  Balance balance(const detail::BallFrame& fr, const Eigen::Vector2d& F,
                  const Eigen::Vector2d& p) const {
    Balance b;
    const double n = set_.exponent();
    double gx = 0, gy = 0, kxx = 0, kxy = 0, kyy = 0, energy = 0;
    for (int j = 0; j < set_.balls(); ++j) {
      const double c = fr.cos_theta[j], s = fr.sin_theta[j];
      const double delta = p.x() * c + p.y() * s - gap_ + fr.excitation[j];
      if (delta <= 0) continue;
      const double Q = detail::contact_load(fr.stiffness[j], n, delta);
      const double k = n * Q / delta;
      gx += Q * c;
      gy += Q * s;
      kxx += k * c * c;
      kxy += k * c * s;
      kyy += k * s * s;
      energy += Q * delta / (n + 1.0);
      ++b.loaded;
    }
    b.gradient = Eigen::Vector2d(gx, gy) - F;
    b.hessian << kxx, kxy, kxy, kyy;
    b.value = energy - F.dot(p);
    return b;
  }

  // dp/dt = −J⁻¹ ∂g/∂t (quasi_static.h).
  Eigen::Vector2d velocity(double t, const detail::BallFrame& fr, const Eigen::Vector2d& p,
                           const Eigen::Matrix2d& J) const {
    detail::BallRates br;
    set_.rates(t, br);
    const double n = set_.exponent(), wc = br.cage_rate;  // dθ/dt, with the slip
    Eigen::Vector2d dgdt = Eigen::Vector2d::Zero();
    for (int j = 0; j < set_.balls(); ++j) {
      const double c = fr.cos_theta[j], s = fr.sin_theta[j];
      const double delta = p.x() * c + p.y() * s - gap_ + fr.excitation[j];
      if (delta <= 0) continue;
      const double Q = detail::contact_load(fr.stiffness[j], n, delta);
      const double dQ = n * Q / delta * (wc * (p.y() * c - p.x() * s) + br.excitation_rate[j]) +
                        br.stiffness_rate[j] * std::pow(delta, n);
      dgdt += dQ * Eigen::Vector2d(c, s) + Q * wc * Eigen::Vector2d(-s, c);
    }
    const double a = inner_speed_ * t;
    dgdt -= unbalance_force_ * inner_speed_ * Eigen::Vector2d(-std::sin(a), std::cos(a));
    // J is positive definite above F_min; a least-squares solve keeps a degenerate instant finite.
    return -J.completeOrthogonalDecomposition().solve(dgdt);
  }

  detail::BallSet set_;
  double gap_;
  double inner_speed_;
  Eigen::Vector2d load_;    // constant load, gravity included [N]
  double unbalance_force_;  // F_u [N]
  double phase_;
  double minimum_load_;
  double smooth_load_;
  Eigen::Vector2d static_ = Eigen::Vector2d::Zero();
  double stiffness_scale_ = 1;
};

}  // namespace

double quasi_static_minimum_load(const ModelInputs& in) {
  const double cos_psi = std::cos(two_pi / in.bearing.balls);
  if (cos_psi <= 1e-12) return 0.0;
  const double gap = in.bearing.ball_gap();
  return in.contact.K * std::pow(gap * (1.0 / cos_psi - 1.0), in.contact.exponent);
}

double quasi_static_smooth_load(const ModelInputs& in) {
  const double cos_psi = std::cos(two_pi / in.bearing.balls);
  if (cos_psi <= 1e-12) return std::numeric_limits<double>::infinity();
  const double waviness = sum_amplitudes(in.inner_waviness) + sum_amplitudes(in.outer_waviness);
  double smaller = 0, larger = 0;  // max ΔD_j, max (−ΔD_j), both ≥ 0
  for (double e : in.ball_size_errors)
    smaller = std::max(smaller, e), larger = std::max(larger, -e);
  const double gap = in.bearing.ball_gap();
  const double d = (gap + waviness + smaller) / cos_psi - gap + waviness + larger;
  return in.contact.K * std::pow(d, in.contact.exponent);
}

std::unique_ptr<QuasiStaticModel> make_quasi_static_model(const ModelInputs& inputs) {
  return std::make_unique<QuasiStatic>(inputs);
}

QuasiStaticStats follow_equilibrium(const QuasiStaticModel& model, const std::vector<double>& times,
                                    const std::function<void(const QuasiStaticPoint&)>& observe,
                                    const std::function<void(double)>& progress) {
  QuasiStaticStats st;
  st.min_loaded_balls = model.balls();
  st.minimum_load = model.minimum_load();
  st.smooth_load = model.smooth_load();
  const int Z = model.balls();
  const double jump_floor = 0.01 * model.static_position().norm();
  std::vector<double> loads(Z), previous(Z);
  Eigen::Vector2d guess = model.static_position();
  QuasiStaticPoint last;
  for (std::size_t k = 0; k < times.size(); ++k) {
    const QuasiStaticPoint pt = model.solve(times[k], guess);
    ++st.steps;
    st.newton_iterations += pt.iterations;
    st.fallbacks += pt.fallback ? 1 : 0;
    st.max_relative_residual = std::max(st.max_relative_residual, pt.residual);
    st.min_loaded_balls = std::min(st.min_loaded_balls, pt.loaded_balls);
    model.ball_loads(pt.t, pt.position, loads.data());
    if (k > 0) {
      for (int j = 0; j < Z; ++j) st.contact_changes += (loads[j] > 0) != (previous[j] > 0);
      const Eigen::Vector2d step = pt.position - last.position;
      const Eigen::Vector2d predicted = 0.5 * (pt.t - last.t) * (pt.velocity + last.velocity);
      const double miss = (step - predicted).norm();
      if (miss > 0.5 * step.norm() && miss > jump_floor) {
        ++st.jumps;
        st.largest_jump = std::max(st.largest_jump, step.norm());
      }
    }
    previous = loads;
    observe(pt);
    // Continue from a first-order prediction of the next instant.
    guess = pt.position;
    if (k + 1 < times.size()) guess += (times[k + 1] - pt.t) * pt.velocity;
    last = pt;
    if (progress && (k % 1024 == 0 || k + 1 == times.size()))
      progress(static_cast<double>(k + 1) / times.size());
  }
  return st;
}

}  // namespace bearing
