// The housing carrying the outer ring (housing.h): the bearing model evaluated at the rings'
// relative position, its force on the inner ring plus the ring loads, its reaction on the housing.
//
// Jacobian. With f_b(q_r, v_r), q_r = q − P q_h (P puts x_h, y_h on the ring's x, y) and B = the
// x, y rows of the bearing's ∂f_b/∂q_r (n columns), B_xy its x, y columns:
//     ring:    ∂f/∂q = ∂f_b/∂q_r,         ∂f/∂q_h = −(∂f_b/∂q_r) P
//     housing: ∂f_h/∂q = −B,              ∂f_h/∂q_h = B_xy − k_h I
// and the same for v with c_h.

#include "bearing/models/housing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Dense>

#include "bearing/constants.h"
#include "bearing/limits.h"
#include "phasor.h"

namespace bearing {

double Housing::stiffness() const {
  const double w = two_pi * frequency;
  return mass * w * w;
}

double Housing::damping() const {
  return 2.0 * damping_ratio * mass * two_pi * frequency;
}

namespace {

constexpr int kMaxRingDofs = 8;  // the bearing's DOFs (2 or 3); the work arrays live on the stack

class HousingModel final : public BearingModel {
 public:
  HousingModel(std::unique_ptr<BearingModel> bearing, const RingLoad& load, const Housing& h,
               std::vector<double> start)
      : bearing_(std::move(bearing)),
        n_(bearing_->dofs()),
        load_(load),
        mass_(h.mass),
        stiffness_(h.stiffness()),
        damping_(h.damping()),
        start_(std::move(start)) {
    if (n_ < 2 || n_ > kMaxRingDofs || bearing_->dof_names().size() != static_cast<std::size_t>(n_))
      throw std::logic_error("housing: the bearing model must have the ring's DOFs only (2 to " +
                             std::to_string(kMaxRingDofs) + ", x and y first)");
    if (start_.size() != static_cast<std::size_t>(n_))
      throw std::logic_error("housing: the static start has the wrong number of entries");
  }

  int dofs() const override { return n_ + 2; }
  void mass(double* m) const override {
    bearing_->mass(m);
    m[n_] = m[n_ + 1] = mass_;
  }

  // The bearing keeps its frame in the workspace; the housing keeps nothing.
  std::unique_ptr<Workspace> make_workspace() const override { return bearing_->make_workspace(); }
  void force(double t, const double* q, const double* v, double* f) const override {
    force_with(nullptr, t, q, v, f);
  }
  void force_with(Workspace* workspace, double t, const double* q, const double* v,
                  double* f) const override {
    std::array<double, kMaxRingDofs> qr{}, vr{};
    relative(q, qr.data());
    relative(v, vr.data());
    bearing_->force_with(workspace, t, qr.data(), vr.data(), f);  // f_b on the ring
    const double bx = f[0], by = f[1];
    f[0] += load_.constant.x();
    f[1] += load_.constant.y();
    if (load_.unbalance_force != 0.0) {
      const detail::Phasor shaft = detail::phasor(load_.shaft_speed * t);
      f[0] += load_.unbalance_force * shaft.c;
      f[1] += load_.unbalance_force * shaft.s;
    }
    f[n_] = -bx - stiffness_ * q[n_] - damping_ * v[n_];
    f[n_ + 1] = -by - stiffness_ * q[n_ + 1] - damping_ * v[n_ + 1];
  }

  void force_jacobian(double t, const double* q, const double* v, double* dfdq,
                      double* dfdv) const override {
    std::array<double, kMaxRingDofs> qr{}, vr{};
    relative(q, qr.data());
    relative(v, vr.data());
    std::array<double, kMaxRingDofs * kMaxRingDofs> bq{}, bv{};
    bearing_->force_jacobian(t, qr.data(), vr.data(), bq.data(), bv.data());
    couple(bq.data(), stiffness_, dfdq);
    couple(bv.data(), damping_, dfdv);
  }

  bool cyclic(int i) const override { return i < n_ && bearing_->cyclic(i); }
  int switching_count() const override { return bearing_->switching_count(); }
  void switching_functions(double t, const double* q, double* g) const override {
    std::array<double, kMaxRingDofs> qr{};
    relative(q, qr.data());
    bearing_->switching_functions(t, qr.data(), g);
  }

  std::vector<std::string> dof_names() const override {
    std::vector<std::string> names = bearing_->dof_names();
    names.emplace_back("x_housing");
    names.emplace_back("y_housing");
    return names;
  }
  int balls() const override { return bearing_->balls(); }
  double cage_speed() const override { return bearing_->cage_speed(); }
  bool has_ball_dofs() const override { return bearing_->has_ball_dofs(); }

  void ball_loads(double t, const double* q, double* loads) const override {
    std::array<double, kMaxRingDofs> qr{};
    relative(q, qr.data());
    bearing_->ball_loads(t, qr.data(), loads);
  }
  void ball_approaches(double t, const double* q, double* approaches) const override {
    std::array<double, kMaxRingDofs> qr{};
    relative(q, qr.data());
    bearing_->ball_approaches(t, qr.data(), approaches);
  }
  void ball_motion(double t, const double* q, const double* v, double* r,
                   double* vr) const override {
    std::array<double, kMaxRingDofs> qr{}, vrel{};
    relative(q, qr.data());
    relative(v, vrel.data());
    bearing_->ball_motion(t, qr.data(), vrel.data(), r, vr);
  }
  void ball_dynamics(double t, const double* q, const double* v, double* spin, double* outer_load,
                     double* friction_inner, double* friction_outer) const override {
    std::array<double, kMaxRingDofs> qr{}, vr{};
    relative(q, qr.data());
    relative(v, vr.data());
    bearing_->ball_dynamics(t, qr.data(), vr.data(), spin, outer_load, friction_inner,
                            friction_outer);
  }

  // The contacts' energy at the relative position and the housing's spring.
  double potential_energy(double t, const double* q) const override {
    std::array<double, kMaxRingDofs> qr{};
    relative(q, qr.data());
    const double xh = q[n_], yh = q[n_ + 1];
    return bearing_->potential_energy(t, qr.data()) + 0.5 * stiffness_ * (xh * xh + yh * yh);
  }

  // The relative static position, shifted by the housing's deflection k_h q_h = F.
  std::vector<double> initial_displacement() const override {
    const Eigen::Vector2d qh = load_.constant / stiffness_;
    std::vector<double> q = start_;
    q[0] += qh.x();
    q[1] += qh.y();
    q.push_back(qh.x());
    q.push_back(qh.y());
    return q;
  }
  std::vector<double> initial_velocity() const override {
    std::vector<double> v = bearing_->initial_velocity();
    v.push_back(0.0);
    v.push_back(0.0);
    return v;
  }

 private:
  // The ring's entries of a full state relative to the housing's (n entries).
  void relative(const double* full, double* ring) const {
    for (int i = 0; i < n_; ++i) ring[i] = full[i];
    ring[0] -= full[n_];
    ring[1] -= full[n_ + 1];
  }

  // The (n + 2)² Jacobian block from the bearing's n² one `b` and the housing's own coefficient
  // (k_h for ∂/∂q, c_h for ∂/∂v); see the file comment.
  void couple(const double* b, double own, double* out) const {
    const int N = n_ + 2;
    for (int i = 0; i < n_; ++i) {
      for (int j = 0; j < n_; ++j) out[i * N + j] = b[i * n_ + j];
      out[i * N + n_] = -b[i * n_ + 0];
      out[i * N + n_ + 1] = -b[i * n_ + 1];
    }
    for (int a = 0; a < 2; ++a) {
      double* row = out + (n_ + a) * N;
      for (int j = 0; j < n_; ++j) row[j] = -b[a * n_ + j];
      row[n_] = b[a * n_ + 0] - (a == 0 ? own : 0.0);
      row[n_ + 1] = b[a * n_ + 1] - (a == 1 ? own : 0.0);
    }
  }

  std::unique_ptr<BearingModel> bearing_;
  int n_;  // the bearing's DOFs
  RingLoad load_;
  double mass_, stiffness_, damping_;  // m_h [kg], k_h [N/m], c_h [N s/m]
  std::vector<double> start_;          // the relative static position q_r [m]
};

}  // namespace

std::vector<HousingMode> housing_modes(const BearingModel& model) {
  const int n = model.dofs();
  const std::vector<double> q = model.initial_displacement();
  const std::vector<double> v(static_cast<std::size_t>(n), 0.0);
  std::vector<double> dfdq(static_cast<std::size_t>(n * n)), dfdv(dfdq.size()), m(q.size());
  model.force_jacobian(0.0, q.data(), v.data(), dfdq.data(), dfdv.data());
  model.mass(m.data());
  Eigen::MatrixXd K(n, n), M = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    M(i, i) = m[static_cast<std::size_t>(i)];
    for (int j = 0; j < n; ++j)
      K(i, j) = -0.5 * (dfdq[static_cast<std::size_t>(i * n + j)] +
                        dfdq[static_cast<std::size_t>(j * n + i)]);
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(K, M);
  std::vector<HousingMode> modes;
  for (int k = 0; k < n; ++k) {
    const Eigen::VectorXd phi = eig.eigenvectors().col(k);  // φᵀ M φ = 1
    HousingMode mode;
    mode.frequency = std::sqrt(std::max(eig.eigenvalues()(k), 0.0)) / two_pi;
    for (int i = n - 2; i < n; ++i) mode.housing_share += M(i, i) * phi(i) * phi(i);
    modes.push_back(mode);
  }
  return modes;
}

std::unique_ptr<BearingModel> make_housing_model(std::unique_ptr<BearingModel> bearing,
                                                 const RingLoad& load, const Housing& housing,
                                                 std::vector<double> start) {
  limits::housing_mass.check(housing.mass);
  limits::housing_frequency.check(housing.frequency);
  limits::housing_damping_ratio.check(housing.damping_ratio);
  return std::make_unique<HousingModel>(std::move(bearing), load, housing, std::move(start));
}

}  // namespace bearing
