// The ball-DOF model with cage slip and traction (seed 004); see ball_dofs.h for the equations.
//
// One loop serves both geometries. Per ball it forms the two approaches, the loads, and the unit
// contact normal n_j along which the inner contact pushes the ring (ring components: (cos θ_j,
// sin θ_j) planar; (cos α_j cos θ_j, cos α_j sin θ_j, sin α_j) with an axial load), and 1/L_j,
// the curvature of the turning contact line (0 planar). Then, with the ring's friction direction
// τ_j = (sin θ_j, −cos θ_j, 0) (the force on the ring is μ(Δv_i) Q_i τ_j) and k = dQ/dδ,
//     ∂f_ring/∂q_ring = −k_i n nᵀ − (Q_i/L)(e eᵀ + e_z e_zᵀ − n nᵀ) + μ_i k_i τ nᵀ,
//     ∂f_ring/∂s_j   = k_i (n − μ_i τ),   ∂f_s/∂q_ring = k_i nᵀ,   ∂f_s/∂s_j = −k_i − k_o,
//     ∂f_w/∂q_ring = L_s μ_i k_i nᵀ,      ∂f_w/∂s_j = L_s (μ_o k_o − μ_i k_i),
// (e = (cos θ_j, sin θ_j, 0); the Q_i/L term is the 3-DOF model's geometric stiffness,
// three_dof.cc) and the velocity terms through the sliding speeds, ∂Δv_i/∂(ẋ, ẏ, ω_b) = (−sin θ,
// cos θ, −L_s), ∂Δv_o/∂ω_b = −L_s, times Q μ'(Δv).

#include "bearing/models/ball_dofs.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "ball_dof_film.h"
#include "ball_dof_inputs.h"
#include "ball_set.h"
#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/kinematics.h"
#include "bearing/limits.h"
#include "bearing/models/three_dof.h"
#include "bearing/models/two_dof.h"
#include "bearing/numerics/roots.h"
#include "bearing/static_load.h"
#include "bearing/units.h"
#include "frame_force.h"
#include "groove_geometry.h"
#include "model_input_checks.h"
#include "static_rk4.h"

namespace bearing {

namespace {

using detail::BallContacts;

class BallDofs final : public detail::FrameForce<BallDofs, detail::RaceFrame, BallDofModel> {
 public:
  explicit BallDofs(const ModelInputs& in)
      : set_(in, detail::checked_ball_dof_cage_speed(in), detail::ball_dof_kinematic_angle(in)),
        film_on_(in.lubricated),
        film_{in.lubricated ? detail::race_films(in, set_.cage_speed()) : detail::RaceFilms{}},
        axial_(in.axial_load != 0.0),
        ring_(axial_ ? 3 : 2),
        balls_(in.bearing.balls),
        mass_(in.mass),
        axial_mass_(in.axial_mass > 0 ? in.axial_mass : in.mass),
        damping_(in.damping),
        axial_damping_(in.axial_damping),
        gap_(in.bearing.ball_gap()),
        load_x_(in.load.x()),
        load_y_(in.radial_load().y()),
        load_z_(in.axial_load),
        unbalance_force_(in.unbalance * in.inner_speed * in.inner_speed),
        phase_(in.cage_phase),
        slip_(in.cage_slip),
        inner_exponent_(in.contact.inner.exponent),
        outer_exponent_(in.contact.outer.exponent),
        curve_(in.traction),
        friction_(in.traction.max_coefficient > 0),
        mu_max_(in.traction.max_coefficient),
        traction_gain_(in.traction.max_coefficient / in.traction.slide_speed),
        hertz_(in.contact.inner.exponent == 1.5 && in.contact.outer.exponent == 1.5) {
    const Bearing& b = in.bearing;
    const double D = b.ball_diameter, dm = b.pitch_diameter;
    double alpha = b.contact_angle;
    if (axial_) {
      geometry_ = detail::groove_geometry(b);
      alpha = std::abs(solve_axial_preload(in).contact_angle);
      ring_start_ = make_three_dof_model(in)->initial_displacement();
    } else if (film_on_) {  // the 2-DOF model's series law is the massless ball's (film_law.h)
      ring_start_ = make_two_dof_model(in)->initial_displacement();
    } else {
      StaticLoadOptions o;
      o.phase = phase_;
      o.exponent = in.contact.exponent;
      const StaticLoadResult st =
          solve_static_load(balls_, in.contact.K, gap_, Eigen::Vector2d(load_x_, load_y_), o);
      ring_start_ = {st.deflection.x(), st.deflection.y()};
    }
    const double g = D * std::cos(alpha) / dm;
    const double wc = set_.cage_speed();
    ball_mass_ = in.ball_mass > 0 ? in.ball_mass : default_ball_mass(b);
    ball_inertia_ = in.ball_inertia > 0 ? in.ball_inertia : default_ball_inertia(ball_mass_, D);
    ball_damping_ = in.ball_damping;
    lever_ = 0.5 * D * std::cos(alpha);
    drive_inner_ = 0.5 * (in.inner_speed - wc) * dm * (1.0 - g);
    drive_outer_ = 0.5 * wc * dm * (1.0 + g);
    inner_arm_ = 0.5 * dm * (1.0 - g);
    outer_arm_ = 0.5 * dm * (1.0 + g);
    // Centrifugal load along the ball's DOF: radial (planar), on the contact line at the static
    // contact angle (axial), so that it has the potential −F_c cos α s_j.
    centrifugal_ = in.centrifugal ? ball_mass_ * wc * wc * 0.5 * dm : 0.0;
    centrifugal_along_ = axial_ ? centrifugal_ * std::cos(alpha) : centrifugal_;
  }

  int dofs() const override { return ring_ + 2 * balls_; }
  void mass(double* m) const override {
    m[0] = m[1] = mass_;
    if (axial_) m[2] = axial_mass_;
    std::fill(m + ring_, m + ring_ + balls_, ball_mass_);
    std::fill(m + ring_ + balls_, m + ring_ + 2 * balls_, ball_inertia_);
  }
  bool cyclic(int i) const override { return i >= ring_ + balls_; }
  // RK4's stage loops one DOF at a time (rk4_loop.h): their vectorised form loads the force in
  // vectors that span the planar kernel's 4-lane stores, which cannot forward (issue 42).
  int wide_from() const { return dofs(); }

  // One instantiation per geometry and friction on/off: the hot loop has no per-ball branches
  // on them. The planar model with both exponents 3/2 (the usual case) runs the SIMD kernel.
  void force_in(const detail::RaceFrame& fr, const double* q, const double* v, double* f) const {
    if (film_on_)  // once per evaluation: the dry instantiations below stay as they were
      return axial_ ? (friction_ ? force_impl<true, true, true>(fr, q, v, f)
                                 : force_impl<true, false, true>(fr, q, v, f))
                    : (friction_ ? force_impl<false, true, true>(fr, q, v, f)
                                 : force_impl<false, false, true>(fr, q, v, f));
    if (axial_)
      friction_ ? force_impl<true, true>(fr, q, v, f) : force_impl<true, false>(fr, q, v, f);
    else if (hertz_)
      planar_hertz_force(fr, q, v, f);
    else
      friction_ ? force_impl<false, true>(fr, q, v, f) : force_impl<false, false>(fr, q, v, f);
  }

  // Row-major n×n (see the top of this file).
  void force_jacobian(double t, const double* q, const double* v, double* dfdq,
                      double* dfdv) const override {
    detail::RaceFrame fr;
    set_.evaluate(t, fr);
    const int Z = balls_, n = dofs(), nr = ring_;
    std::fill(dfdq, dfdq + n * n, 0.0);
    std::fill(dfdv, dfdv + n * n, 0.0);
    const auto at = [n](double* m, int i, int k) -> double& { return m[i * n + k]; };
    const double vx = v[0], vy = v[1];
    at(dfdv, 0, 0) = at(dfdv, 1, 1) = -damping_;
    if (axial_) at(dfdv, 2, 2) = -axial_damping_;
    for (int j = 0; j < Z; ++j) {
      const int S = nr + j, W = nr + Z + j;
      const double c = fr.cos_theta[j], s = fr.sin_theta[j];
      const BallContacts k = ball_contacts(fr, j, q, q[S]);
      double ki = k.delta_i > 0 ? inner_exponent_ * k.load_i / k.delta_i : 0.0;
      double ko = k.delta_o > 0 ? outer_exponent_ * k.load_o / k.delta_o : 0.0;
      if (film_on_) film_.tangents(fr, j, k, ki, ko);  // the film laws'
      double mi = 0, mo = 0, si = 0, so = 0;           // μ and dμ/dΔv at both contacts
      if (friction_) {
        const double dvi = inner_sliding(fr, v[W], vx, vy, c, s), dvo = outer_sliding(fr, v[W]);
        mi = curve_.coefficient(dvi), si = curve_.slope(dvi);
        mo = curve_.coefficient(dvo), so = curve_.slope(dvo);
      }
      const double nv[3] = {k.ca * c, k.ca * s, k.sa};  // contact normal, ring components
      const double ev[3] = {c, s, 0.0}, zv[3] = {0.0, 0.0, 1.0};
      const double tau[3] = {s, -c, 0.0};
      const double geo = k.load_i * k.inv_length;  // Q_i/L
      for (int a = 0; a < nr; ++a) {
        for (int b = 0; b < nr; ++b)
          at(dfdq, a, b) += -ki * nv[a] * nv[b] -
                            geo * (ev[a] * ev[b] + zv[a] * zv[b] - nv[a] * nv[b]) +
                            mi * ki * tau[a] * nv[b];
        at(dfdq, a, S) += ki * (nv[a] - mi * tau[a]);
        at(dfdq, S, a) += ki * nv[a];
        at(dfdq, W, a) += lever_ * mi * ki * nv[a];
      }
      at(dfdq, S, S) += -ki - ko;
      at(dfdq, W, S) += lever_ * (mo * ko - mi * ki);
      at(dfdv, S, S) = -ball_damping_;
      if (film_on_) film_.add_damping(k, nv, nr, S, n, dfdv);
      if (!friction_) continue;
      const double ai = k.load_i * si, ao = k.load_o * so;
      const double dvi[3] = {-s, c, -lever_};  // ∂Δv_i/∂(ẋ, ẏ, ω_b)
      const int vcols[3] = {0, 1, W};
      for (int m = 0; m < 3; ++m) {
        at(dfdv, 0, vcols[m]) += s * ai * dvi[m];
        at(dfdv, 1, vcols[m]) -= c * ai * dvi[m];
        at(dfdv, W, vcols[m]) += lever_ * ai * dvi[m];
      }
      at(dfdv, W, W) -= lever_ * ao * lever_;
    }
  }

  std::vector<std::string> dof_names() const override {
    return axial_ ? std::vector<std::string>{"x", "y", "z"} : std::vector<std::string>{"x", "y"};
  }
  int balls() const override { return balls_; }

  void ball_loads(double t, const double* q, double* loads) const override {
    detail::RaceFrame fr;
    set_.evaluate(t, fr);
    for (int j = 0; j < balls_; ++j) loads[j] = ball_contacts(fr, j, q, q[ring_ + j]).load_i;
  }

  // The ball's total approach δ_i + δ_o: the 2-DOF model's δ_j (planar), the 3-DOF model's
  // δ_j = L_j − A₀ (axial).
  void ball_approaches(double t, const double* q, double* out) const override {
    detail::RaceFrame fr;
    set_.evaluate(t, fr);
    for (int j = 0; j < balls_; ++j) {
      const BallContacts k = contacts(fr, j, q, q[ring_ + j]);
      out[j] = k.delta_i + k.delta_o;
    }
  }

  // Planar: the DOF itself. Axial: the 3-DOF model's r_j = δ_o cos α_j − Π_o + ΔD_j/2
  // (bearing_model.h) with δ_o = s_j, and its rate with d(cos α_j)/dt from the ring's motion
  // (three_dof.cc).
  void ball_motion(double t, const double* q, const double* v, double* r,
                   double* vr) const override {
    if (!axial_) {
      std::copy(q + 2, q + 2 + balls_, r);
      std::copy(v + 2, v + 2 + balls_, vr);
      return;
    }
    detail::RaceFrame fr;
    set_.evaluate(t, fr);
    detail::BallRates br;
    set_.rates(t, br);
    const double wc = br.cage_rate, w = geometry_.w0 + q[2];  // dθ/dt, with the slip
    for (int j = 0; j < balls_; ++j) {
      const double c = fr.cos_theta[j], s = fr.sin_theta[j];
      const BallContacts k = contacts(fr, j, q, q[3 + j]);
      const double rho_rate =
          v[0] * c + v[1] * s + wc * (q[1] * c - q[0] * s) + br.excitation_rate[j];
      const double L = 1.0 / k.inv_length;
      const double L_rate = (k.ca * L * rho_rate + w * v[2]) / L;
      const double ca_rate = (rho_rate - k.ca * L_rate) / L;
      r[j] = q[3 + j] * k.ca - br.outer_profile[j] + 0.5 * set_.size_error(j);
      vr[j] = v[3 + j] * k.ca + q[3 + j] * ca_rate - br.outer_profile_rate[j];
    }
  }

  bool has_ball_dofs() const override { return true; }

  // Each contact's own film, h_r = C_r Q_r^−0.067.
  void film_thickness(double t, const double* q, double* inner, double* outer) const override {
    if (!film_on_) return BearingModel::film_thickness(t, q, inner, outer);
    detail::RaceFrame fr;
    set_.evaluate(t, fr);
    for (int j = 0; j < balls_; ++j)
      film_.thickness(fr, j, ball_contacts(fr, j, q, q[ring_ + j]), inner[j], outer[j]);
  }

  void ball_dynamics(double t, const double* q, const double* v, double* spin, double* outer_load,
                     double* friction_inner, double* friction_outer) const override {
    detail::RaceFrame fr;
    set_.evaluate(t, fr);
    const int Z = balls_;
    for (int j = 0; j < Z; ++j) {
      const double c = fr.cos_theta[j], s = fr.sin_theta[j], w = v[ring_ + Z + j];
      const BallContacts k = ball_contacts(fr, j, q, q[ring_ + j]);
      spin[j] = w;
      outer_load[j] = k.load_o;
      friction_inner[j] = curve_.coefficient(inner_sliding(fr, w, v[0], v[1], c, s)) * k.load_i;
      friction_outer[j] = -curve_.coefficient(outer_sliding(fr, w)) * k.load_o;
    }
  }

  double potential_energy(double t, const double* q) const override {
    detail::RaceFrame fr;
    set_.evaluate(t, fr);
    double e = 0.0;
    const double ni = inner_exponent_, no = outer_exponent_;
    for (int j = 0; j < balls_; ++j) {
      const BallContacts k = ball_contacts(fr, j, q, q[ring_ + j]);
      if (film_on_) {  // U(Q) of each contact's film law (film_law.h)
        e += film_.energy(fr, j, k);
        continue;
      }
      if (k.delta_i > 0) e += k.load_i * k.delta_i / (ni + 1.0);
      if (k.delta_o > 0) e += k.load_o * k.delta_o / (no + 1.0);
    }
    return e;
  }

  // The ring at the static solution of the 2-DOF (planar) or 3-DOF (axial) model under the
  // constant loads; each ball where its contacts and the centrifugal load balance at t = 0,
  // Q_o = Q_i + F_c (cos α).
  std::vector<double> initial_displacement() const override {
    std::vector<double> q(static_cast<std::size_t>(dofs()), 0.0);
    std::copy(ring_start_.begin(), ring_start_.end(), q.begin());
    detail::RaceFrame fr;
    set_.evaluate(0.0, fr);
    for (int j = 0; j < balls_; ++j) q[ring_ + j] = ball_equilibrium(fr, j, q.data());
    return q;
  }

  // Each ball spinning where a ball with equal loads on both races has no spin torque in the
  // linear traction range (Δv_i = −Δv_o): ω_b = (A_i + A_o)/(2L), the pure-rolling spin when
  // s_c = 0 (seed 004 starts from the kinematic spin).
  std::vector<double> initial_velocity() const override {
    std::vector<double> v(static_cast<std::size_t>(dofs()), 0.0);
    std::fill(v.begin() + ring_ + balls_, v.end(), (drive_inner_ + drive_outer_) / (2.0 * lever_));
    return v;
  }

  double cage_speed() const override { return set_.cage_speed(); }
  double cage_slip() const override { return slip_; }
  double centrifugal_force() const override { return centrifugal_; }

  FrictionPower friction_power(double t, const double* q, const double* v) const override {
    detail::RaceFrame fr;
    set_.evaluate(t, fr);
    FrictionPower p;
    const int Z = balls_;
    for (int j = 0; j < Z; ++j) {
      const double c = fr.cos_theta[j], s = fr.sin_theta[j], w = v[ring_ + Z + j];
      const BallContacts k = ball_contacts(fr, j, q, q[ring_ + j]);
      const double dvi = inner_sliding(fr, w, v[0], v[1], c, s), dvo = outer_sliding(fr, w);
      const double pi = curve_.coefficient(dvi) * k.load_i, po = curve_.coefficient(dvo) * k.load_o;
      p.dissipated += pi * dvi + po * dvo;
      p.on_dofs += -pi * (-v[0] * s + v[1] * c) + lever_ * w * (pi + po);
      p.drives += -(pi * drives(fr).inner + po * drives(fr).outer);
    }
    return p;
  }

 private:
  // Q = K [δ]_+^n (both exponents 3/2 in the planar model go to the kernel instead).
  static double load(double K, double n, double delta) {
    return K * std::pow(std::max(delta, 0.0), n);
  }

  // force() of the planar model with both exponents 3/2: the per-ball kernel
  // (contact_kernels.h) of the case's contact loop.
  void planar_hertz_force(const detail::RaceFrame& fr, const double* q, const double* v,
                          double* f) const {
    detail::PlanarBalls in;
    in.cos_theta = fr.cos_theta;
    in.sin_theta = fr.sin_theta;
    in.inner_excitation = fr.inner_excitation;
    in.outer_excitation = fr.outer_excitation;
    in.inner_stiffness = fr.inner_stiffness;
    in.outer_stiffness = fr.outer_stiffness;
    in.position = q + ring_;
    in.speed = v + ring_;
    in.spin = v + ring_ + balls_;
    in.balls = balls_;
    in.vx = v[0], in.vy = v[1];
    in.gap = gap_;
    in.centrifugal = centrifugal_along_;
    in.ball_damping = ball_damping_;
    in.lever = lever_;
    const Drives a = drives(fr);
    in.drive_inner = a.inner, in.drive_outer = a.outer;
    in.traction_gain = traction_gain_, in.traction_cap = mu_max_;
    in.friction = friction_;
    in.fx = load_x_ + unbalance_force_ * fr.cos_shaft - damping_ * v[0];
    in.fy = load_y_ + unbalance_force_ * fr.sin_shaft - damping_ * v[1];
    set_.kernels().planar_balls(in, q[0], q[1], f, f + ring_, f + ring_ + balls_);
  }

  // force(): the equations of ball_dofs.h (the planar model with both exponents 3/2:
  // planar_hertz_force()).
  template <bool kAxial, bool kFriction, bool kFilm = false>
  void force_impl(const detail::RaceFrame& fr, const double* q, const double* v, double* f) const {
    const int Z = balls_;
    const double vx = v[0], vy = v[1];
    const double* s_dof = q + ring_;
    const double* vs = v + ring_;
    const double* spin = v + ring_ + Z;
    double fx = load_x_ + unbalance_force_ * fr.cos_shaft - damping_ * vx;
    double fy = load_y_ + unbalance_force_ * fr.sin_shaft - damping_ * vy;
    double fz = kAxial ? load_z_ - axial_damping_ * v[2] : 0.0;
    double* radial = f + ring_;
    double* torque = f + ring_ + Z;
    // Locals, not members: the stores to f could alias *this and would force reloads.
    const double x = q[0], y = q[1], gap = gap_, ni = inner_exponent_, no = outer_exponent_;
    const double fc = centrifugal_along_, cb = ball_damping_, lever = lever_;
    const Drives drive = drives(fr);
    const double ai = drive.inner, ao = drive.outer, gain = traction_gain_, cap = mu_max_;
    for (int j = 0; j < Z; ++j) {
      const double c = fr.cos_theta[j], s = fr.sin_theta[j];
      double load_i, load_o, ca = 1.0, sa = 0.0, delta_i, delta_o;
      if (kAxial) {
        const BallContacts k = contacts(fr, j, q, s_dof[j]);
        load_i = k.load_i, load_o = k.load_o, ca = k.ca, sa = k.sa;
        delta_i = k.delta_i, delta_o = k.delta_o;
      } else {
        delta_o = s_dof[j] + fr.outer_excitation[j];
        delta_i = x * c + y * s - s_dof[j] - gap + fr.inner_excitation[j];
        load_o = load(fr.outer_stiffness[j], no, delta_o);
        load_i = load(fr.inner_stiffness[j], ni, delta_i);
      }
      // The normal forces: the loads, and with the film its squeeze dampers on each contact's
      // approach rate, δ̇_i = n_j · v_ring − ṡ_j and δ̇_o = ṡ_j (film_contacts.h).
      double push_i = load_i, push_o = load_o;
      if constexpr (kFilm) {
        const double ring_rate = ca * (vx * c + vy * s) + (kAxial ? sa * v[2] : 0.0);
        film_.pushes(fr, j, delta_i, delta_o, ring_rate, vs[j], load_i, load_o, push_i, push_o);
      }
      fx -= push_i * ca * c;
      fy -= push_i * ca * s;
      if (kAxial) fz -= push_i * sa;
      radial[j] = push_i - push_o + fc - cb * vs[j];
      if (!kFriction) {
        torque[j] = 0.0;
        continue;
      }
      // μ(Δv) = clamp(μ_m/Δv_m · Δv, ±μ_m) (traction.h), without a division.
      const double dvi = ai - lever * spin[j] + (vy * c - vx * s);
      const double dvo = ao - lever * spin[j];
      const double pi = std::min(std::max(gain * dvi, -cap), cap) * load_i;
      const double po = std::min(std::max(gain * dvo, -cap), cap) * load_o;
      fx += pi * s;  // μ Q_i τ_j on the ring
      fy -= pi * c;
      torque[j] = lever * (pi + po);
    }
    f[0] = fx;
    f[1] = fy;
    if (kAxial) f[2] = fz;
  }

  // Ball j's contacts for the ring state q and the ball's DOF s (ball_dofs.h).
  BallContacts contacts(const detail::RaceFrame& fr, int j, const double* q, double s) const {
    BallContacts k;
    const double c = fr.cos_theta[j], sn = fr.sin_theta[j];
    if (axial_) {
      const double rho = q[0] * c + q[1] * sn + fr.inner_excitation[j] + fr.outer_excitation[j];
      double L;
      const double total = detail::approach(geometry_, rho, q[2], L);
      k.delta_o = s;
      k.delta_i = total - s;
      k.inv_length = 1.0 / L;
      k.ca = (geometry_.u0 + rho) * k.inv_length;
      k.sa = (geometry_.w0 + q[2]) * k.inv_length;
    } else {
      k.delta_o = s + fr.outer_excitation[j];
      k.delta_i = q[0] * c + q[1] * sn - s - gap_ + fr.inner_excitation[j];
    }
    k.load_o = k.delta_o > 0
                   ? detail::contact_load(fr.outer_stiffness[j], outer_exponent_, k.delta_o)
                   : 0.0;
    k.load_i = k.delta_i > 0
                   ? detail::contact_load(fr.inner_stiffness[j], inner_exponent_, k.delta_i)
                   : 0.0;
    return k;
  }

  // The drives A_i, A_o at the frame's instant [m/s]: with random slip the cage turns at
  // ω_ca + φ̇ (random_slip.h), so A_i − ½ φ̇ d_m (1 − g) and A_o + ½ φ̇ d_m (1 + g).
  struct Drives {
    double inner, outer;
  };
  Drives drives(const detail::RaceFrame& fr) const {
    if (fr.slip_rate == 0.0) return {drive_inner_, drive_outer_};
    return {drive_inner_ - fr.slip_rate * inner_arm_, drive_outer_ + fr.slip_rate * outer_arm_};
  }

  // Δv_i with the ring's translation along t_j, and Δv_o (ball_dofs.h) [m/s].
  double inner_sliding(const detail::RaceFrame& fr, double spin, double vx, double vy, double c,
                       double s) const {
    return drives(fr).inner - lever_ * spin + (-vx * s + vy * c);
  }
  double outer_sliding(const detail::RaceFrame& fr, double spin) const {
    return drives(fr).outer - lever_ * spin;
  }

  // The ball DOF with Q_o − Q_i = F_c (cos α) for the ring at q: Q_o − Q_i rises monotonically in
  // the DOF, so bisection between the root's bounds; a ball the ring does not reach rests on the
  // outer race.
  double ball_equilibrium(const detail::RaceFrame& fr, int j, const double* q) const {
    if (film_on_) {  // ball_dof_film.h
      const auto below = [&](double s) {
        const BallContacts k = ball_contacts(fr, j, q, s);
        return k.load_o - k.load_i - centrifugal_along_ < 0;
      };
      return detail::film_ball_equilibrium(below, -contacts(fr, j, q, 0.0).delta_o);
    }
    const auto excess = [&](double s) {
      const BallContacts k = contacts(fr, j, q, s);
      return k.load_o - k.load_i - centrifugal_along_;
    };
    // lo: the outer contact just closes (Q_o = 0 ≤ Q_i + F_c). hi: Q_o alone exceeds the largest
    // Q_i + F_c, that of the ball at lo.
    const BallContacts at_zero = contacts(fr, j, q, 0.0);
    double lo = -at_zero.delta_o;
    const BallContacts at_lo = contacts(fr, j, q, lo);
    const double qmax = at_lo.load_i + centrifugal_along_;
    double hi = lo + std::pow(qmax / fr.outer_stiffness[j], 1.0 / outer_exponent_) + 1e-12;
    if (excess(lo) >= 0) return lo;
    numerics::BisectionOptions o;
    o.abs_width = 1e-16;  // [m]
    const auto below = [&](double s) { return excess(s) < 0; };
    const numerics::Bracket b = numerics::bisect(lo, hi, below, o);
    return 0.5 * (b.lo + b.hi);
  }

  // contacts() with the film's loads when lubricated (not for the hot loop: a branch per ball).
  BallContacts ball_contacts(const detail::RaceFrame& fr, int j, const double* q, double s) const {
    BallContacts k = contacts(fr, j, q, s);
    if (film_on_) film_.set_loads(fr, j, k);
    return k;
  }

  friend class detail::FrameForce<BallDofs, detail::RaceFrame, BallDofModel>;
  const detail::BallSet& ball_set() const { return set_; }

  detail::BallSet set_;
  bool film_on_;              // lubricated: each contact with its own EHL film
  detail::BallDofFilm film_;  // the films at this model's cage speed (with cage slip)
  bool axial_;  // an axial load: the ring's z and the contact lines of the 3-DOF model
  int ring_;    // ring DOFs: 2, or 3 with z
  int balls_;
  double mass_, axial_mass_;
  double damping_, axial_damping_;
  double gap_;              // γ = P_d/2 [m], all on the inner side (planar)
  double load_x_, load_y_;  // constant radial load, gravity included [N]
  double load_z_;           // axial load [N]
  double unbalance_force_;  // F_u = m_u e ω_i² [N]
  double phase_;            // φ₀ [rad]
  double slip_;             // s_c [-]
  double inner_exponent_, outer_exponent_;
  TractionCurve curve_;
  bool friction_;                    // μ_m > 0
  double mu_max_;                    // μ_m [-]
  double traction_gain_;             // μ_m/Δv_m [s/m]
  bool hertz_;                       // both exponents 3/2
  detail::GrooveGeometry geometry_;  // axial only
  std::vector<double> ring_start_;   // the ring's static state
  double ball_mass_ = 0, ball_inertia_ = 0, ball_damping_ = 0;
  double lever_ = 0;              // L_s = (D/2) cos α [m]
  double drive_inner_ = 0;        // A_i = ½ (ω_i − ω_ca) d_m (1 − g) [m/s]
  double drive_outer_ = 0;        // A_o = ½ ω_ca d_m (1 + g) [m/s]
  double inner_arm_ = 0;          // ½ d_m (1 − g) [m]: A_i's change per unit cage speed
  double outer_arm_ = 0;          // ½ d_m (1 + g) [m]
  double centrifugal_ = 0;        // F_c [N]
  double centrifugal_along_ = 0;  // its component along the ball's DOF [N]
};

}  // namespace

double default_ball_mass(const Bearing& b) {
  const double D = b.ball_diameter;
  return b.ball.density * pi * D * D * D / 6.0;
}

double default_ball_inertia(double mass, double diameter) {
  return mass * diameter * diameter / 10.0;  // a solid sphere
}

std::unique_ptr<BallDofModel> make_ball_dof_model(const ModelInputs& inputs) {
  return std::make_unique<BallDofs>(inputs);
}

namespace {

// The ball model's RK4: for the usual planar ball counts (Z = 7, 8, 9) with the DOF count a
// compile-time constant, so that the stage loops are unrolled (issue 42); else the count known at
// run time. The same stage arithmetic either way: the same bits.
class BallDofRk4 final : public Integrator {
 public:
  explicit BallDofRk4(const IntegratorSettings& settings)
      : any_(settings), z7_(settings), z8_(settings), z9_(settings) {}

  IntegrationStats integrate(const MechanicalSystem& system, double t0,
                             const std::vector<double>& q0, const std::vector<double>& v0,
                             const std::vector<double>& output_times, const Observer& observe,
                             const Progress& progress) const override {
    const Integrator& rk4 = system.dofs() == 16   ? static_cast<const Integrator&>(z7_)
                            : system.dofs() == 18 ? static_cast<const Integrator&>(z8_)
                            : system.dofs() == 20 ? static_cast<const Integrator&>(z9_)
                                                  : static_cast<const Integrator&>(any_);
    return rk4.integrate(system, t0, q0, v0, output_times, observe, progress);
  }

  std::string name() const override { return "rk4"; }

 private:
  detail::StaticRk4<BallDofs, 0> any_;
  detail::StaticRk4<BallDofs, 16> z7_;
  detail::StaticRk4<BallDofs, 18> z8_;
  detail::StaticRk4<BallDofs, 20> z9_;
};

}  // namespace

std::unique_ptr<Integrator> make_ball_dof_rk4(const IntegratorSettings& settings) {
  return std::make_unique<BallDofRk4>(settings);
}

}  // namespace bearing
