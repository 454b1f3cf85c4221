// The 2-DOF inner-ring model (docs/model.md §4, seeds 001–003); see two_dof.h for the equations.

#include "bearing/models/two_dof.h"

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "ball_motion.h"
#include "ball_set.h"
#include "bearing/constants.h"
#include "bearing/kinematics.h"
#include "bearing/static_load.h"
#include "film_contacts.h"
#include "frame_force.h"
#include "housed_model.h"
#include "inline_contacts.h"
#include "model_input_checks.h"
#include "static_rk4.h"

namespace bearing {

namespace {

// Validates the inputs (before anything is built from them) and returns ω_c.
double checked_cage_speed(const ModelInputs& in) {
  detail::validate_common_inputs(in);
  return cage_speed(in.bearing, in.inner_speed);
}

class TwoDofModel final : public detail::FrameForce<TwoDofModel, detail::BallFrame, BearingModel> {
 public:
  explicit TwoDofModel(const ModelInputs& in)
      : set_(in, checked_cage_speed(in), in.bearing.contact_angle),
        mass_(in.mass),
        damping_(in.damping),
        gap_(in.bearing.ball_gap()),
        load_x_(in.load.x()),
        load_y_(in.radial_load().y()),
        unbalance_force_(in.unbalance * in.inner_speed * in.inner_speed),
        phase_(in.cage_phase),
        film_on_(in.lubricated),
        film_(in.lubricated ? detail::series_film(in, set_.cage_speed()) : detail::SeriesFilm{}) {}

  int dofs() const override { return 2; }
  void mass(double* m) const override { m[0] = m[1] = mass_; }

  // Contact loop: δ_j from the rotated ball directions, Q_j = K_j δ_j^n, summed on the ring.
  void force_in(const detail::BallFrame& fr, const double* q, const double* v, double* f) const {
    contact_force<false>(fr, q, v, f);
  }
  // The same with the per-ball loop inline (frame_force.h, inline_contacts.h: the same bits).
  [[gnu::always_inline]] void force_in_inline(const detail::BallFrame& fr, const double* q,
                                              const double* v, double* f) const {
    contact_force<true>(fr, q, v, f);
  }

 private:
  // Always inline: the kind's own RK4 then keeps the state in registers (rk4_loop.h).
  template <bool kInline>
  [[gnu::always_inline]] void contact_force(const detail::BallFrame& fr, const double* q,
                                            const double* v, double* f) const {
    const double x = q[0], y = q[1], n = set_.exponent();
    double fx = load_x_ + unbalance_force_ * fr.cos_shaft - damping_ * v[0];
    double fy = load_y_ + unbalance_force_ * fr.sin_shaft - damping_ * v[1];
    const int Z = set_.balls();
    if (film_on_) {  // once per evaluation: the dry loops below stay as they were
      const detail::RingForce c =
          detail::radial_film_force(film_.ball, fr, Z, x, y, v[0], v[1], gap_);
      fx += c.x;
      fy += c.y;
    } else if (n == 1.5 && kInline) {
      detail::radial_contacts_inline(fr.cos_theta, fr.sin_theta, fr.excitation, fr.stiffness, Z, x,
                                     y, gap_, &fx, &fy);
    } else if (n == 1.5) {
      set_.kernels().radial(fr.cos_theta, fr.sin_theta, fr.excitation, fr.stiffness, Z, x, y, gap_,
                            &fx, &fy);
    } else {
      for (int j = 0; j < Z; ++j) {
        const double c = fr.cos_theta[j], s = fr.sin_theta[j];
        const double delta = x * c + y * s - gap_ + fr.excitation[j];
        if (delta <= 0) continue;
        const double Q = detail::contact_load(fr.stiffness[j], n, delta);
        fx -= Q * c;
        fy -= Q * s;
      }
    }
    f[0] = fx;
    f[1] = fy;
  }

 public:
  // ∂f/∂q = −Σ_j n K_j δ_j^{n−1} e_j e_jᵀ over the loaded balls (e_j = (cos θ_j, sin θ_j));
  // ∂f/∂v = −c I.
  void force_jacobian(double t, const double* q, const double* /*v*/, double* dfdq,
                      double* dfdv) const override {
    detail::BallFrame fr;
    set_.evaluate(t, fr);
    if (film_on_) {  // dQ/dδ the film law's tangent; −Σ c_j e_j e_jᵀ on v (∂c/∂q neglected)
      double k[4], d[4];
      detail::radial_film_jacobian(film_.ball, fr, set_.balls(), q[0], q[1], gap_, k, d);
      for (int i = 0; i < 4; ++i) dfdq[i] = -k[i], dfdv[i] = -d[i];
      dfdv[0] -= damping_;
      dfdv[3] -= damping_;
      return;
    }
    const double x = q[0], y = q[1], n = set_.exponent();
    double kxx = 0, kxy = 0, kyy = 0;
    const int Z = set_.balls();
    for (int j = 0; j < Z; ++j) {
      const double c = fr.cos_theta[j], s = fr.sin_theta[j];
      const double delta = x * c + y * s - gap_ + fr.excitation[j];
      if (delta <= 0) continue;
      const double k = n == 1.5 ? 1.5 * fr.stiffness[j] * std::sqrt(delta)
                                : n * fr.stiffness[j] * std::pow(delta, n - 1.0);
      kxx += k * c * c;
      kxy += k * c * s;
      kyy += k * s * s;
    }
    dfdq[0] = -kxx;
    dfdq[1] = -kxy;
    dfdq[2] = -kxy;
    dfdq[3] = -kyy;
    dfdv[0] = -damping_;
    dfdv[1] = 0.0;
    dfdv[2] = 0.0;
    dfdv[3] = -damping_;
  }

  std::vector<std::string> dof_names() const override { return {"x", "y"}; }
  int balls() const override { return set_.balls(); }
  double cage_speed() const override { return set_.cage_speed(); }

  void ball_loads(double t, const double* q, double* loads) const override {
    if (film_on_) return film_loads(t, q, loads);
    set_.ball_loads(
        t, [&](int j, const detail::BallFrame& fr) { return approach(q, fr, j); }, loads);
  }

  void ball_approaches(double t, const double* q, double* out) const override {
    set_.ball_approaches(
        t, [&](int j, const detail::BallFrame& fr) { return approach(q, fr, j); }, out);
  }

  // Contacts open and close where δ_j changes sign: the ball approaches are the switching
  // functions. With the film no contact opens (Q(δ) is smooth and positive): none.
  int switching_count() const override { return film_on_ ? 0 : set_.balls(); }
  void switching_functions(double t, const double* q, double* g) const override {
    ball_approaches(t, q, g);
  }

  void ball_motion(double t, const double* q, const double* v, double* r,
                   double* vr) const override {
    if (film_on_)  // the ball on the outer film (bearing_model.h)
      return detail::radial_film_ball_motion(set_, gap_, film_.ball.H,
                                             film_.films.outer.central_coefficient(), film_.press,
                                             t, q, v, r, vr);
    detail::radial_ball_motion(set_, gap_, t, q, v, r, vr);
  }

  double potential_energy(double t, const double* q) const override {
    if (film_on_) {  // Σ_j U(Q_j), film_law.h
      detail::BallFrame fr;
      set_.evaluate(t, fr);
      double e = 0.0;
      for (int j = 0; j < set_.balls(); ++j) {
        const FilmLaw law = film_.ball.law(fr.stiffness[j]);
        e += law.energy(law.load(approach(q, fr, j)));
      }
      return e;
    }
    return set_.potential_energy(
        t, [&](int j, const detail::BallFrame& fr) { return approach(q, fr, j); });
  }

  std::vector<double> initial_displacement() const override {
    StaticLoadOptions o;
    o.phase = phase_;
    o.exponent = set_.exponent();
    const StaticLoadResult r =
        solve_static_load(set_.balls(), set_.K(), gap_, Eigen::Vector2d(load_x_, load_y_), o);
    std::vector<double> q = {r.deflection.x(), r.deflection.y()};
    if (film_on_) film_static(q.data());
    return q;
  }

  void film_thickness(double t, const double* q, double* inner, double* outer) const override {
    if (!film_on_) return BearingModel::film_thickness(t, q, inner, outer);
    std::vector<double> loads(static_cast<std::size_t>(set_.balls()));
    film_loads(t, q, loads.data());
    detail::series_film_thickness(film_, loads.data(), set_.balls(), inner, outer);
  }

 private:
  void film_loads(double t, const double* q, double* loads) const {
    detail::BallFrame fr;
    set_.evaluate(t, fr);
    for (int j = 0; j < set_.balls(); ++j)
      loads[j] = film_.ball.load(fr.stiffness[j], approach(q, fr, j));
  }

  // The static state with the film, from the dry one: the ball set at t = 0 without excitation
  // (as solve_static_load), Newton on the film's force balance.
  void film_static(double* q) const {
    const int Z = set_.balls();
    const detail::BallFrame fr = set_.rest_frame(phase_);
    const auto residual = [&](const double* p, double* r, double* J) {
      const detail::RingForce c =
          detail::radial_film_force(film_.ball, fr, Z, p[0], p[1], 0, 0, gap_);
      r[0] = load_x_ + c.x;
      r[1] = load_y_ + c.y;
      double d[4];
      detail::radial_film_jacobian(film_.ball, fr, Z, p[0], p[1], gap_, J, d);
    };
    detail::film_equilibrium(2, q, residual, std::hypot(load_x_, load_y_));
  }

  // δ_j = x cos θ_j + y sin θ_j − γ + e_j (docs/model.md §1).
  double approach(const double* q, const detail::BallFrame& fr, int j) const {
    return q[0] * fr.cos_theta[j] + q[1] * fr.sin_theta[j] - gap_ + fr.excitation[j];
  }

  friend class detail::FrameForce<TwoDofModel, detail::BallFrame, BearingModel>;
  const detail::BallSet& ball_set() const { return set_; }

  detail::BallSet set_;
  double mass_;
  double damping_;
  double gap_;              // γ = P_d/2 [m]
  double load_x_, load_y_;  // constant load, gravity included [N]
  double unbalance_force_;  // F_u = m_u e ω_i² [N]
  double phase_;            // φ₀ [rad]
  bool film_on_;            // lubricated: the EHL film in every ball's contacts
  detail::SeriesFilm film_;
};

}  // namespace

std::unique_ptr<BearingModel> make_two_dof_model(const ModelInputs& inputs) {
  return std::make_unique<TwoDofModel>(inputs);
}

std::unique_ptr<Integrator> make_two_dof_rk4(const IntegratorSettings& settings) {
  return std::make_unique<detail::StaticRk4<TwoDofModel, 2>>(settings);
}

std::unique_ptr<BearingModel> make_two_dof_housed(const ModelInputs& bearing_only,
                                                  const RingLoad& load, const Housing& housing,
                                                  std::vector<double> start) {
  return detail::make_housed(TwoDofModel(bearing_only), load, housing, bearing_only.contact_loop,
                             std::move(start));
}

std::unique_ptr<Integrator> make_two_dof_housed_rk4(const IntegratorSettings& settings) {
  return std::make_unique<detail::StaticRk4<detail::HousedModel<TwoDofModel>, 0>>(settings);
}

}  // namespace bearing
