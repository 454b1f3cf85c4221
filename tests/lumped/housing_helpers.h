#pragma once
// What the housing tests share (test_housing.cc, test_housing_modes.cc): a stand-in bearing with
// a prescribed force, a resonator's [housing], a plain integration observed at fixed times, and a
// least-squares sine fit.

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "bearing/models/bearing_model.h"
#include "bearing/models/housing.h"
#include "bearing/solvers/integrator.h"

namespace bearing {
namespace {

// A stand-in bearing on the ring's x, y, with no balls: what it exerts on the inner ring is
// prescribed, f_b = F sin(ω t) ŷ − k_b q_r − c_b v_r. With k_b = c_b = 0 the ring and the housing
// are uncoupled and the housing feels −F sin(ω t) ŷ alone.
class StubBearing final : public BearingModel {
 public:
  double ring_mass = 2.0;  // [kg]
  double amplitude = 0.0;  // F [N]: F sin ω t along y
  double omega = 0.0;      // ω [rad/s]
  double stiffness = 0.0;  // k_b [N/m]
  double damping = 0.0;    // c_b [N s/m]

  int dofs() const override { return 2; }
  void mass(double* m) const override { m[0] = m[1] = ring_mass; }
  void force(double t, const double* q, const double* v, double* f) const override {
    f[0] = -stiffness * q[0] - damping * v[0];
    f[1] = amplitude * std::sin(omega * t) - stiffness * q[1] - damping * v[1];
  }
  std::vector<std::string> dof_names() const override { return {"x", "y"}; }
  int balls() const override { return 0; }
  double cage_speed() const override { return 0.0; }
  void ball_loads(double, const double*, double*) const override {}
  void ball_approaches(double, const double*, double*) const override {}
  void ball_motion(double, const double*, const double*, double*, double*) const override {}
  double potential_energy(double, const double* q) const override {
    return 0.5 * stiffness * (q[0] * q[0] + q[1] * q[1]);
  }
  std::vector<double> initial_displacement() const override { return {0.0, 0.0}; }
};

Housing housing(double mass, double frequency, double zeta) {
  Housing h;
  h.enabled = true;
  h.mass = mass;
  h.frequency = frequency;
  h.damping_ratio = zeta;
  return h;
}

std::unique_ptr<BearingModel> on_housing(const StubBearing& stub, const Housing& h) {
  return make_housing_model(std::make_unique<StubBearing>(stub), RingLoad{}, h, {0.0, 0.0});
}

// The observed states of a run, every output instant.
struct Samples {
  std::vector<double> t;
  std::vector<std::vector<double>> q, v, a;
};

// Integrates `model` from (q0, v0) over [0, duration], observed every `every` s.
Samples integrate(const BearingModel& model, IntegratorMethod method, double dt, double rtol,
                  const std::vector<double>& q0, const std::vector<double>& v0, double duration,
                  double every) {
  IntegratorSettings s;
  s.method = method;
  s.dt = dt;
  s.rtol = rtol;
  s.atol = 1e-18;
  std::vector<double> times;
  const long n = std::lround(duration / every);
  for (long k = 0; k <= n; ++k) times.push_back(duration * static_cast<double>(k) / n);
  Samples out;
  const int dofs = model.dofs();
  make_integrator(s)->integrate(model, 0.0, q0, v0, times,
                                [&](double t, const double* q, const double* v, const double* a) {
                                  out.t.push_back(t);
                                  out.q.emplace_back(q, q + dofs);
                                  out.v.emplace_back(v, v + dofs);
                                  out.a.emplace_back(a, a + dofs);
                                });
  return out;
}

// Least-squares fit of u(t) ≈ s sin ω t + c cos ω t over the samples from `from` on.
Eigen::Vector2d fit_sine(const Samples& r, int dof, bool acceleration, double omega, double from) {
  Eigen::Matrix2d A = Eigen::Matrix2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  for (std::size_t k = 0; k < r.t.size(); ++k) {
    if (r.t[k] < from) continue;
    const Eigen::Vector2d basis(std::sin(omega * r.t[k]), std::cos(omega * r.t[k]));
    const double u = acceleration ? r.a[k][dof] : r.q[k][dof];
    A += basis * basis.transpose();
    b += basis * u;
  }
  return A.ldlt().solve(b);
}

}  // namespace
}  // namespace bearing
