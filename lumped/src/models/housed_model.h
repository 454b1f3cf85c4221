#pragma once
// Private to the lumped models (not installed): a bearing model carried by the housing
// (housing.h), one class for the resonator and for the structure's modes, whose equations the
// opening of housing.cc writes out.
//
// Why a template: the support's arithmetic is added to every force evaluation, so for the kinds
// whose force is hot (2-DOF, 3-DOF) the wrapped model is held by value and its force_at() is
// called statically, and the whole model runs through its own StaticRk4 (static_rk4.h: the
// bearing's phasors computed ahead, nothing behind a virtual call); Bearing = BearingModel holds
// any model behind the interface (make_housing_model, the tests' stubs). Both evaluate the same
// operations in the same order: the same bits.

#include <algorithm>
#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "ball_set.h"
#include "bearing/contact_loop.h"
#include "bearing/models/bearing_model.h"
#include "bearing/models/housing.h"
#include "frame_workspace.h"
#include "phasor.h"

namespace bearing::detail {

/// The partial sums of the seat's motion (SupportKernels::seat_sums).
inline constexpr std::size_t kSupportLanes = 8;

/// The support's arithmetic (support_kernels.cc): Highway's best instruction set or the scalar
/// reference, the same bits.
struct SupportKernels {
  /// The seat's motion from the support's displacements p and velocities pv (`dofs` entries):
  /// out = {Σ sx_k p_k, Σ sy_k p_k, Σ sx_k pv_k, Σ sy_k pv_k}, each summed in 8 partial sums
  /// (lane k mod 8) joined pairwise; sx and sy hold whole blocks of 8 (zeros past `dofs`).
  void (*seat_sums)(const double* sx, const double* sy, const double* p, const double* pv, int dofs,
                    double* out);
  /// Each support DOF's force f_k = (sx_k (−b_x) + sy_k (−b_y)) − k_k p_k − c_k pv_k from the
  /// bearing's force (b_x, b_y) on the inner ring.
  void (*forces)(const double* sx, const double* sy, const double* k, const double* c, double bx,
                 double by, const double* p, const double* pv, int dofs, double* f);
};

/// The kernels of `loop` (simd: the best instruction set of this CPU).
SupportKernels support_kernels(ContactLoop loop);
/// The kernels of every instruction set this build holds that this CPU runs, named, for the
/// tests that check each against the scalar reference (switches Highway's dispatch while it runs:
/// not while other threads run models).
std::vector<std::pair<std::string, SupportKernels>> support_kernels_per_target();

/// The support's DOFs (housing.cc's opening): M uncoupled DOFs p_k of mass m_k, stiffness k_k
/// and damping c_k that move the seat by (sx_k, sy_k) p_k. Arrays of M entries.
struct Support {
  int dofs = 0;
  std::vector<double> mass;        ///< m_k [kg] (the resonator) or 1 (mass-normalised modes)
  std::vector<double> stiffness;   ///< k_k [N/m] or ω_k² [1/s²]
  std::vector<double> damping;     ///< c_k [N s/m] or 2 ζ_k ω_k [1/s]
  std::vector<double> sx, sy;      ///< the seat's x, y per unit p_k [-] or [kg^-½], and zeros
                                   ///< to a whole number of 8 (seat_sums reads whole blocks)
  std::vector<std::string> names;  ///< written DOF names: the resonator's x_housing, y_housing
  std::vector<SensorRow> sensors;  ///< written sensor rows (the modes'), indices into p
  SupportKernels kernels{};
};

/// The support of `housing`, checked (check_housing): the resonator or the modes (housing.cc),
/// with the kernels of `loop`.
Support make_support(const Housing& housing, ContactLoop loop);

/// The seat's motion (SupportKernels::seat_sums), with the resonator's two DOFs inline: there the
/// 8 partial sums are the two products and zeros, whose pairwise join is the products' sum (a
/// zero changes no bit but the sign of a zero sum, which no difference it enters sees).
inline void seat_motion(const Support& s, const double* p, const double* pv, double* out) {
  const double *sx = s.sx.data(), *sy = s.sy.data();
  if (s.dofs != 2) return s.kernels.seat_sums(sx, sy, p, pv, s.dofs, out);
  out[0] = sx[0] * p[0] + sx[1] * p[1];
  out[1] = sy[0] * p[0] + sy[1] * p[1];
  out[2] = sx[0] * pv[0] + sx[1] * pv[1];
  out[3] = sy[0] * pv[0] + sy[1] * pv[1];
}

/// The support's forces (SupportKernels::forces).
inline void support_forces(const Support& s, double bx, double by, const double* p,
                           const double* pv, double* f) {
  s.kernels.forces(s.sx.data(), s.sy.data(), s.stiffness.data(), s.damping.data(), bx, by, p, pv,
                   s.dofs, f);
}

/// The frame type of a FrameForce model, void for the interface.
template <class B, class = void>
struct FrameOf {
  using type = void;
};
template <class B>
struct FrameOf<B, std::void_t<typename B::FrameType>> {
  using type = typename B::FrameType;
};

/// `Bearing` (a FrameForce model held by value, or BearingModel behind a unique_ptr) on its
/// support; DOFs: the bearing's n, then the support's M (housing.h).
template <class Bearing>
class HousedModel final : public BearingModel {
 public:
  static constexpr bool kStatic = !std::is_same_v<Bearing, BearingModel>;
  static constexpr int kMaxRingDofs = 8;  // the work arrays live on the stack
  using FrameType = typename FrameOf<Bearing>::type;
  using Held = std::conditional_t<kStatic, Bearing, std::unique_ptr<BearingModel>>;

  HousedModel(Held bearing, const RingLoad& load, Support support, std::vector<double> start)
      : bearing_(std::move(bearing)),
        n_(model().dofs()),
        load_(load),
        support_(std::move(support)),
        start_(std::move(start)) {
    if (n_ < 2 || n_ > kMaxRingDofs || model().dof_names().size() != static_cast<std::size_t>(n_))
      throw std::logic_error("housing: the bearing model must have the ring's DOFs only (2 to " +
                             std::to_string(kMaxRingDofs) + ", x and y first)");
    if (start_.size() != static_cast<std::size_t>(n_))
      throw std::logic_error("housing: the static start has the wrong number of entries");
    for (SensorRow& row : support_.sensors)
      for (auto& term : row.terms) term.first += n_;  // the support's DOFs follow the ring's
  }

  const BearingModel& model() const {
    if constexpr (kStatic)
      return bearing_;
    else
      return *bearing_;
  }

  int dofs() const override { return n_ + support_.dofs; }
  void mass(double* m) const override {
    model().mass(m);
    std::copy(support_.mass.begin(), support_.mass.end(), m + n_);
  }

  // The bearing keeps its frame in the workspace; the housing keeps nothing.
  std::unique_ptr<Workspace> make_workspace() const override { return model().make_workspace(); }
  void force(double t, const double* q, const double* v, double* f) const override {
    if constexpr (kStatic) {
      FrameWorkspace<FrameType> fresh;  // on the stack, evaluated at t
      force_at(fresh, t, q, v, f);
    } else {
      force_with(nullptr, t, q, v, f);
    }
  }
  void force_with(Workspace* workspace, double t, const double* q, const double* v,
                  double* f) const override {
    if constexpr (kStatic) {
      if (!workspace) return force(t, q, v, f);
      force_at(static_cast<FrameWorkspace<FrameType>&>(*workspace), t, q, v, f);
    } else {
      evaluate(t, q, v, f, [&](const double* qr, const double* vr, double* fb) {
        bearing_->force_with(workspace, t, qr, vr, fb);
      });
    }
  }

  /// force_with() for StaticRk4 (static_rk4.h): the bearing's force_at inlined, its time
  /// angles computed ahead (`ahead`, or nullptr).
  template <class Workspace>
  void force_at(Workspace& workspace, double t, const double* q, const double* v, double* f,
                const BallSet::TimeAngles* ahead = nullptr) const {
    evaluate(t, q, v, f, [&](const double* qr, const double* vr, double* fb) {
      bearing_.force_at(workspace, t, qr, vr, fb, ahead);
    });
  }
  /// Where RK4's stage loops turn to vectors (rk4_loop.h): at the support's DOFs, which the
  /// support's kernels load and store a vector at a time; the ring's one at a time, as the
  /// bearing's force stores them.
  int wide_from() const { return n_; }
  /// The bearing's time angles of n times at once (static_rk4.h).
  void time_angles(const double* t, int n, BallSet::TimeAngles* out,
                   std::vector<double>& scratch) const {
    bearing_.time_angles(t, n, out, scratch);
  }

  void force_jacobian(double t, const double* q, const double* v, double* dfdq,
                      double* dfdv) const override {
    std::array<double, kMaxRingDofs> qr{}, vr{};
    relative(q, v, qr.data(), vr.data());
    std::array<double, kMaxRingDofs * kMaxRingDofs> bq{}, bv{};
    model().force_jacobian(t, qr.data(), vr.data(), bq.data(), bv.data());
    couple(bq.data(), support_.stiffness, dfdq);
    couple(bv.data(), support_.damping, dfdv);
  }

  bool cyclic(int i) const override { return i < n_ && model().cyclic(i); }
  int switching_count() const override { return model().switching_count(); }
  void switching_functions(double t, const double* q, double* g) const override {
    std::array<double, kMaxRingDofs> qr{};
    relative(q, qr.data());
    model().switching_functions(t, qr.data(), g);
  }

  std::vector<std::string> dof_names() const override {
    std::vector<std::string> names = model().dof_names();
    names.insert(names.end(), support_.names.begin(), support_.names.end());
    return names;
  }
  std::vector<SensorRow> sensor_rows() const override { return support_.sensors; }
  int balls() const override { return model().balls(); }
  double cage_speed() const override { return model().cage_speed(); }
  bool has_cage_slip() const override { return model().has_cage_slip(); }
  double cage_slip_angle(double t) const override { return model().cage_slip_angle(t); }
  bool has_ball_dofs() const override { return model().has_ball_dofs(); }

  void ball_loads(double t, const double* q, double* loads) const override {
    std::array<double, kMaxRingDofs> qr{};
    relative(q, qr.data());
    model().ball_loads(t, qr.data(), loads);
  }
  void ball_approaches(double t, const double* q, double* approaches) const override {
    std::array<double, kMaxRingDofs> qr{};
    relative(q, qr.data());
    model().ball_approaches(t, qr.data(), approaches);
  }
  void ball_motion(double t, const double* q, const double* v, double* r,
                   double* vr) const override {
    std::array<double, kMaxRingDofs> qr{}, vrel{};
    relative(q, v, qr.data(), vrel.data());
    model().ball_motion(t, qr.data(), vrel.data(), r, vr);
  }
  void ball_dynamics(double t, const double* q, const double* v, double* spin, double* outer_load,
                     double* friction_inner, double* friction_outer) const override {
    std::array<double, kMaxRingDofs> qr{}, vr{};
    relative(q, v, qr.data(), vr.data());
    model().ball_dynamics(t, qr.data(), vr.data(), spin, outer_load, friction_inner,
                          friction_outer);
  }

  void film_thickness(double t, const double* q, double* inner, double* outer) const override {
    std::array<double, kMaxRingDofs> qr{};
    relative(q, qr.data());
    model().film_thickness(t, qr.data(), inner, outer);
  }

  // The contacts' energy at the relative position and the support's springs.
  double potential_energy(double t, const double* q) const override {
    std::array<double, kMaxRingDofs> qr{};
    relative(q, qr.data());
    double springs = 0.0;
    for (int k = 0; k < support_.dofs; ++k)
      springs += support_.stiffness[k] * q[n_ + k] * q[n_ + k];
    return model().potential_energy(t, qr.data()) + 0.5 * springs;
  }

  // The relative static position, shifted by the seat's static deflection: each support DOF
  // k_k p_k = s_k · F (the resonator: k_h q_h = F).
  std::vector<double> initial_displacement() const override {
    std::vector<double> q = start_;
    const Eigen::Vector2d F = load_.constant;
    for (int k = 0; k < support_.dofs; ++k)
      q.push_back((support_.sx[k] * F.x() + support_.sy[k] * F.y()) / support_.stiffness[k]);
    std::array<double, 4> seat{};
    seat_motion(support_, q.data() + n_, q.data() + n_, seat.data());
    q[0] += seat[0];
    q[1] += seat[1];
    return q;
  }
  std::vector<double> initial_velocity() const override {
    std::vector<double> v = model().initial_velocity();
    v.resize(static_cast<std::size_t>(dofs()), 0.0);
    return v;
  }

 private:
  // f at (t, q, v): the bearing's force f_b at the relative state (bearing_force(qr, vr, f)),
  // the ring loads added on the ring, the reaction on the support.
  template <class BearingForce>
  void evaluate(double t, const double* q, const double* v, double* f,
                const BearingForce& bearing_force) const {
    std::array<double, kMaxRingDofs> qr{}, vr{};
    relative(q, v, qr.data(), vr.data());
    bearing_force(qr.data(), vr.data(), f);  // f_b on the ring
    const double bx = f[0], by = f[1];
    f[0] += load_.constant.x();
    f[1] += load_.constant.y();
    if (load_.unbalance_force != 0.0) {
      const Phasor shaft = phasor(load_.shaft_speed * t);
      f[0] += load_.unbalance_force * shaft.c;
      f[1] += load_.unbalance_force * shaft.s;
    }
    support_forces(support_, bx, by, q + n_, v + n_, f + n_);
  }

  // The ring's entries of a full state relative to the seat's (n entries), for q and v at once.
  void relative(const double* q, const double* v, double* qr, double* vr) const {
    std::array<double, 4> seat{};
    seat_motion(support_, q + n_, v + n_, seat.data());
    std::copy(q, q + n_, qr);
    std::copy(v, v + n_, vr);
    qr[0] -= seat[0];
    qr[1] -= seat[1];
    vr[0] -= seat[2];
    vr[1] -= seat[3];
  }
  // The same for q alone.
  void relative(const double* q, double* qr) const {
    std::array<double, 4> seat{};
    seat_motion(support_, q + n_, q + n_, seat.data());
    std::copy(q, q + n_, qr);
    qr[0] -= seat[0];
    qr[1] -= seat[1];
  }

  // The (n + M)² Jacobian from the bearing's n² one `b` and the support's own coefficients
  // (k for ∂/∂q, c for ∂/∂v); housing.cc's opening.
  void couple(const double* b, const std::vector<double>& own, double* out) const {
    const int M = support_.dofs, N = n_ + M;
    const std::vector<double>&sx = support_.sx, &sy = support_.sy;
    for (int i = 0; i < n_; ++i) {
      for (int j = 0; j < n_; ++j) out[i * N + j] = b[i * n_ + j];
      for (int k = 0; k < M; ++k)
        out[i * N + n_ + k] = -(b[i * n_ + 0] * sx[k] + b[i * n_ + 1] * sy[k]);
    }
    for (int k = 0; k < M; ++k) {
      double* row = out + (n_ + k) * N;
      for (int j = 0; j < n_; ++j) row[j] = -(sx[k] * b[0 * n_ + j] + sy[k] * b[1 * n_ + j]);
      for (int l = 0; l < M; ++l) {
        const double bs_x = b[0 * n_ + 0] * sx[l] + b[0 * n_ + 1] * sy[l];  // (B_xy S)_x,l
        const double bs_y = b[1 * n_ + 0] * sx[l] + b[1 * n_ + 1] * sy[l];
        row[n_ + l] = sx[k] * bs_x + sy[k] * bs_y - (k == l ? own[k] : 0.0);
      }
    }
  }

  Held bearing_;
  int n_;  // the bearing's DOFs
  RingLoad load_;
  Support support_;
  std::vector<double> start_;  // the relative static position q_r [m]
};

/// The kind's model (held by value) on the housing; `start` as make_housing_model's.
template <class Bearing>
std::unique_ptr<BearingModel> make_housed(Bearing bearing, const RingLoad& load,
                                          const Housing& housing, ContactLoop loop,
                                          std::vector<double> start) {
  return std::make_unique<HousedModel<Bearing>>(std::move(bearing), load,
                                                make_support(housing, loop), std::move(start));
}

}  // namespace bearing::detail
