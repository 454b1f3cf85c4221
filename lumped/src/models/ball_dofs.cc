// The ball-DOF model with cage slip and traction (seed 004); see ball_dofs.h for the equations.

#include "bearing/models/ball_dofs.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "ball_set.h"
#include "bearing/errors.h"
#include "bearing/kinematics.h"
#include "bearing/static_load.h"
#include "bearing/units.h"

namespace bearing {

namespace {

// Validates the inputs (before anything is built from them) and returns ω_ca = (1 − s_c) ω_c.
double checked_cage_speed(const ModelInputs& in) {
  detail::validate_common_inputs(in);
  if (!(in.cage_slip >= 0 && in.cage_slip < 1))
    throw InputError("cage.slip = " + format_number(in.cage_slip) +
                     ": the cage slip s_c must be in [0, 1) (0: pure rolling; 0.02: 2 %)");
  make_traction_curve(in.traction.max_coefficient, in.traction.slide_speed);
  const auto non_negative = [](double v, const std::string& key, const char* unit) {
    if (!(std::isfinite(v) && v >= 0))
      throw InputError(key + " = " + format_number(v) + " " + unit +
                       ": must be finite and >= 0 (0: the default)");
  };
  non_negative(in.ball_mass, "ball.mass", "kg");
  non_negative(in.ball_inertia, "ball.inertia", "kg m^2");
  if (!(std::isfinite(in.ball_damping) && in.ball_damping >= 0))
    throw InputError("ball.damping = " + format_number(in.ball_damping) +
                     " N s/m: must be finite and >= 0");
  if (in.axial_load != 0.0)
    throw InputError("operation.axial_load = " + format_number(in.axial_load) +
                     " N: the ball-DOF model (model.kind = \"balls\") is planar, as seed 004's; an "
                     "axial load or preload needs model.kind = \"3dof\"");
  if (!(in.contact.inner.K > 0 && in.contact.outer.K > 0 && std::isfinite(in.contact.inner.K) &&
        std::isfinite(in.contact.outer.K) && in.contact.inner.exponent >= 1 &&
        in.contact.outer.exponent >= 1))
    throw InputError("model.contact: the ball-DOF model needs both races' constants, K_i = " +
                     format_number(in.contact.inner.K) +
                     ", K_o = " + format_number(in.contact.outer.K) +
                     " N/m^n (positive, finite) and exponents >= 1");
  return (1.0 - in.cage_slip) * cage_speed(in.bearing, in.inner_speed);
}

// One ball's two contacts.
struct BallContacts {
  double delta_i, delta_o;  // approaches [m], signed
  double load_i, load_o;    // Q_i, Q_o [N]
};

class BallDofs final : public BallDofModel {
 public:
  explicit BallDofs(const ModelInputs& in)
      : set_(in, checked_cage_speed(in)),
        balls_(in.bearing.balls),
        mass_(in.mass),
        damping_(in.damping),
        gap_(in.bearing.ball_gap()),
        load_x_(in.load.x()),
        load_y_(in.load.y() - (in.gravity ? in.mass * detail::kGravity : 0.0)),
        unbalance_force_(in.unbalance * in.inner_speed * in.inner_speed),
        phase_(in.cage_phase),
        slip_(in.cage_slip),
        inner_exponent_(in.contact.inner.exponent),
        outer_exponent_(in.contact.outer.exponent),
        curve_(in.traction),
        friction_(in.traction.max_coefficient > 0),
        series_K_(in.contact.K),
        series_exponent_(in.contact.exponent) {
    const Bearing& b = in.bearing;
    const double D = b.ball_diameter, dm = b.pitch_diameter;
    const double g = D * std::cos(b.contact_angle) / dm;
    const double wc = set_.cage_speed();
    ball_mass_ = in.ball_mass > 0 ? in.ball_mass : b.ball.density * M_PI * D * D * D / 6.0;
    ball_inertia_ = in.ball_inertia > 0 ? in.ball_inertia : ball_mass_ * D * D / 10.0;
    ball_damping_ = in.ball_damping;
    lever_ = 0.5 * D * std::cos(b.contact_angle);
    drive_inner_ = 0.5 * (in.inner_speed - wc) * dm * (1.0 - g);
    drive_outer_ = 0.5 * wc * dm * (1.0 + g);
    centrifugal_ = in.centrifugal ? ball_mass_ * wc * wc * 0.5 * dm : 0.0;
  }

  int dofs() const override { return 2 * balls_ + 2; }
  void mass(double* m) const override {
    m[0] = m[1] = mass_;
    std::fill(m + 2, m + 2 + balls_, ball_mass_);
    std::fill(m + 2 + balls_, m + 2 + 2 * balls_, ball_inertia_);
  }
  bool cyclic(int i) const override { return i >= 2 + balls_; }

  void force(double t, const double* q, const double* v, double* f) const override {
    const detail::RaceFrame& fr = set_.race_frame(t);
    const int Z = balls_;
    const double x = q[0], y = q[1], vx = v[0], vy = v[1];
    const double* r = q + 2;
    const double* vr = v + 2;
    const double* spin = v + 2 + Z;
    double fx = load_x_ + unbalance_force_ * fr.cos_shaft - damping_ * vx;
    double fy = load_y_ + unbalance_force_ * fr.sin_shaft - damping_ * vy;
    double* radial = f + 2;
    double* torque = f + 2 + Z;
    for (int j = 0; j < Z; ++j) {
      const double c = fr.cos_theta[j], s = fr.sin_theta[j];
      const BallContacts k = contacts(fr, j, x, y, r[j]);
      fx -= k.load_i * c;
      fy -= k.load_i * s;
      radial[j] = k.load_i - k.load_o + centrifugal_ - ball_damping_ * vr[j];
      torque[j] = 0.0;
      if (!friction_) continue;
      const double pi = curve_.coefficient(inner_sliding(spin[j], vx, vy, c, s)) * k.load_i;
      const double po = curve_.coefficient(outer_sliding(spin[j])) * k.load_o;
      fx += pi * s;  // −μ Q_i t_j on the ring
      fy -= pi * c;
      torque[j] = lever_ * (pi + po);
    }
    f[0] = fx;
    f[1] = fy;
  }

  // Row-major n×n; see the header comment of the .h for the forces differentiated here.
  void force_jacobian(double t, const double* q, const double* v, double* dfdq,
                      double* dfdv) const override {
    const detail::RaceFrame& fr = set_.race_frame(t);
    const int Z = balls_, n = dofs();
    std::fill(dfdq, dfdq + n * n, 0.0);
    std::fill(dfdv, dfdv + n * n, 0.0);
    const auto at = [n](double* m, int i, int k) -> double& { return m[i * n + k]; };
    const double x = q[0], y = q[1], vx = v[0], vy = v[1];
    at(dfdv, 0, 0) = at(dfdv, 1, 1) = -damping_;
    for (int j = 0; j < Z; ++j) {
      const int R = 2 + j, W = 2 + Z + j;
      const double c = fr.cos_theta[j], s = fr.sin_theta[j];
      const BallContacts k = contacts(fr, j, x, y, q[R]);
      // dQ_i/d(x, y, r_j) = k_i (c, s, −1), dQ_o/dr_j = k_o.
      const double ki = k.delta_i > 0 ? inner_exponent_ * k.load_i / k.delta_i : 0.0;
      const double ko = k.delta_o > 0 ? outer_exponent_ * k.load_o / k.delta_o : 0.0;
      double mi = 0, mo = 0, si = 0, so = 0;  // μ and dμ/dΔv at both contacts
      if (friction_) {
        const double dvi = inner_sliding(v[W], vx, vy, c, s), dvo = outer_sliding(v[W]);
        mi = curve_.coefficient(dvi), si = curve_.slope(dvi);
        mo = curve_.coefficient(dvo), so = curve_.slope(dvo);
      }
      const double gx = -c + mi * s, gy = -s - mi * c;  // ring force per unit Q_i
      const double dqi[3] = {ki * c, ki * s, -ki};
      const int cols[3] = {0, 1, R};
      for (int m = 0; m < 3; ++m) {
        at(dfdq, 0, cols[m]) += gx * dqi[m];
        at(dfdq, 1, cols[m]) += gy * dqi[m];
        at(dfdq, R, cols[m]) += dqi[m];
        at(dfdq, W, cols[m]) += lever_ * mi * dqi[m];
      }
      at(dfdq, R, R) -= ko;
      at(dfdq, W, R) += lever_ * mo * ko;
      at(dfdv, R, R) = -ball_damping_;
      if (!friction_) continue;
      // dΔv_i/d(ẋ, ẏ, ω_b) = (−s, c, −L), dΔv_o/dω_b = −L.
      const double ai = k.load_i * si, ao = k.load_o * so;
      const double dvi[3] = {-s, c, -lever_};
      const int vcols[3] = {0, 1, W};
      for (int m = 0; m < 3; ++m) {
        at(dfdv, 0, vcols[m]) += s * ai * dvi[m];
        at(dfdv, 1, vcols[m]) -= c * ai * dvi[m];
        at(dfdv, W, vcols[m]) += lever_ * ai * dvi[m];
      }
      at(dfdv, W, W) -= lever_ * ao * lever_;
    }
  }

  std::vector<std::string> dof_names() const override { return {"x", "y"}; }
  int balls() const override { return balls_; }

  void ball_loads(double t, const double* q, double* loads) const override {
    detail::RaceFrame fr;
    set_.evaluate_races(t, fr);
    for (int j = 0; j < balls_; ++j) loads[j] = contacts(fr, j, q[0], q[1], q[2 + j]).load_i;
  }

  // The ball's total approach δ_i + δ_o, the 2-DOF model's δ_j.
  void ball_approaches(double t, const double* q, double* out) const override {
    detail::RaceFrame fr;
    set_.evaluate_races(t, fr);
    for (int j = 0; j < balls_; ++j) {
      const BallContacts k = contacts(fr, j, q[0], q[1], q[2 + j]);
      out[j] = k.delta_i + k.delta_o;
    }
  }

  void ball_motion(double /*t*/, const double* q, const double* v, double* r,
                   double* vr) const override {
    std::copy(q + 2, q + 2 + balls_, r);
    std::copy(v + 2, v + 2 + balls_, vr);
  }

  bool has_ball_dofs() const override { return true; }

  void ball_dynamics(double t, const double* q, const double* v, double* spin, double* outer_load,
                     double* friction_inner, double* friction_outer) const override {
    detail::RaceFrame fr;
    set_.evaluate_races(t, fr);
    const int Z = balls_;
    for (int j = 0; j < Z; ++j) {
      const double c = fr.cos_theta[j], s = fr.sin_theta[j], w = v[2 + Z + j];
      const BallContacts k = contacts(fr, j, q[0], q[1], q[2 + j]);
      spin[j] = w;
      outer_load[j] = k.load_o;
      friction_inner[j] = curve_.coefficient(inner_sliding(w, v[0], v[1], c, s)) * k.load_i;
      friction_outer[j] = -curve_.coefficient(outer_sliding(w)) * k.load_o;
    }
  }

  double potential_energy(double t, const double* q) const override {
    detail::RaceFrame fr;
    set_.evaluate_races(t, fr);
    double e = 0.0;
    const double ni = inner_exponent_, no = outer_exponent_;
    for (int j = 0; j < balls_; ++j) {
      const BallContacts k = contacts(fr, j, q[0], q[1], q[2 + j]);
      if (k.delta_i > 0) e += k.load_i * k.delta_i / (ni + 1.0);
      if (k.delta_o > 0) e += k.load_o * k.delta_o / (no + 1.0);
    }
    return e;
  }

  // The ring at its static solution under the constant load (series law, as the 2-DOF model);
  // each ball where its two contacts and the centrifugal force balance, Q_o = Q_i + F_c, at t = 0.
  std::vector<double> initial_displacement() const override {
    StaticLoadOptions o;
    o.phase = phase_;
    o.exponent = series_exponent_;
    const StaticLoadResult st =
        solve_static_load(balls_, series_K_, gap_, Eigen::Vector2d(load_x_, load_y_), o);
    std::vector<double> q(static_cast<std::size_t>(dofs()), 0.0);
    q[0] = st.deflection.x();
    q[1] = st.deflection.y();
    detail::RaceFrame fr;
    set_.evaluate_races(0.0, fr);
    for (int j = 0; j < balls_; ++j) q[2 + j] = ball_equilibrium(fr, j, q[0], q[1]);
    return q;
  }

  // Each ball spinning where a ball with equal loads on both races has no spin torque in the
  // linear traction range (Δv_i = −Δv_o): ω_b = (A_i + A_o)/(2L), the pure-rolling spin when
  // s_c = 0 (seed 004 starts from the kinematic spin).
  std::vector<double> initial_velocity() const override {
    std::vector<double> v(static_cast<std::size_t>(dofs()), 0.0);
    std::fill(v.begin() + 2 + balls_, v.end(), (drive_inner_ + drive_outer_) / (2.0 * lever_));
    return v;
  }

  double cage_speed() const override { return set_.cage_speed(); }
  double cage_slip() const override { return slip_; }
  double centrifugal_force() const override { return centrifugal_; }

  FrictionPower friction_power(double t, const double* q, const double* v) const override {
    detail::RaceFrame fr;
    set_.evaluate_races(t, fr);
    FrictionPower p;
    const int Z = balls_;
    for (int j = 0; j < Z; ++j) {
      const double c = fr.cos_theta[j], s = fr.sin_theta[j], w = v[2 + Z + j];
      const BallContacts k = contacts(fr, j, q[0], q[1], q[2 + j]);
      const double dvi = inner_sliding(w, v[0], v[1], c, s), dvo = outer_sliding(w);
      const double pi = curve_.coefficient(dvi) * k.load_i, po = curve_.coefficient(dvo) * k.load_o;
      p.dissipated += pi * dvi + po * dvo;
      p.on_dofs += -pi * (-v[0] * s + v[1] * c) + lever_ * w * (pi + po);
      p.drives += -(pi * drive_inner_ + po * drive_outer_);
    }
    return p;
  }

 private:
  BallContacts contacts(const detail::RaceFrame& fr, int j, double x, double y, double r) const {
    BallContacts k;
    k.delta_o = r + fr.outer_excitation[j];
    k.delta_i = x * fr.cos_theta[j] + y * fr.sin_theta[j] - r - gap_ + fr.inner_excitation[j];
    k.load_o = k.delta_o > 0
                   ? detail::contact_load(fr.outer_stiffness[j], outer_exponent_, k.delta_o)
                   : 0.0;
    k.load_i = k.delta_i > 0
                   ? detail::contact_load(fr.inner_stiffness[j], inner_exponent_, k.delta_i)
                   : 0.0;
    return k;
  }

  // Δv_i with the ring's translation along t_j, and Δv_o (ball_dofs.h) [m/s].
  double inner_sliding(double spin, double vx, double vy, double c, double s) const {
    return drive_inner_ - lever_ * spin + (-vx * s + vy * c);
  }
  double outer_sliding(double spin) const { return drive_outer_ - lever_ * spin; }

  // r_j with Q_o(r) − Q_i(r) = F_c for the ring at (x, y): Q_o − Q_i rises monotonically in r,
  // so bisection between the root's bounds; a ball the ring does not reach rests on the outer race.
  double ball_equilibrium(const detail::RaceFrame& fr, int j, double x, double y) const {
    const auto excess = [&](double r) {
      const BallContacts k = contacts(fr, j, x, y, r);
      return k.load_o - k.load_i - centrifugal_;
    };
    // At r = −e_o the outer contact just closes (Q_o = 0 ≤ Q_i + F_c); above r_hi, Q_o alone
    // exceeds the largest Q_i + F_c.
    double lo = -fr.outer_excitation[j];
    const double total = x * fr.cos_theta[j] + y * fr.sin_theta[j] - gap_ + fr.inner_excitation[j] +
                         fr.outer_excitation[j];
    const double qmax =
        (total > 0 ? detail::contact_load(fr.inner_stiffness[j], inner_exponent_, total) : 0.0) +
        centrifugal_;
    double hi = lo + std::pow(qmax / fr.outer_stiffness[j], 1.0 / outer_exponent_) + 1e-12;
    if (excess(lo) >= 0) return lo;
    for (int it = 0; it < 200 && hi - lo > 1e-16; ++it) {
      const double mid = 0.5 * (lo + hi);
      (excess(mid) < 0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }

  detail::BallSet set_;
  int balls_;
  double mass_, damping_;
  double gap_;              // γ = P_d/2 [m], all on the inner side
  double load_x_, load_y_;  // constant load, gravity included [N]
  double unbalance_force_;  // F_u = m_u e ω_i² [N]
  double phase_;            // φ₀ [rad]
  double slip_;             // s_c [-]
  double inner_exponent_, outer_exponent_;
  TractionCurve curve_;
  bool friction_;  // μ_m > 0
  double series_K_, series_exponent_;
  double ball_mass_ = 0, ball_inertia_ = 0, ball_damping_ = 0;
  double lever_ = 0;        // L = (D/2) cos α [m]
  double drive_inner_ = 0;  // A_i = ½ (ω_i − ω_ca) d_m (1 − g) [m/s]
  double drive_outer_ = 0;  // A_o = ½ ω_ca d_m (1 + g) [m/s]
  double centrifugal_ = 0;  // F_c [N]
};

}  // namespace

std::unique_ptr<BallDofModel> make_ball_dof_model(const ModelInputs& inputs) {
  return std::make_unique<BallDofs>(inputs);
}

}  // namespace bearing
