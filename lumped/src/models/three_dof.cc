// The 3-DOF model with axial load / preload (docs/model.md §4, seed 001); see three_dof.h for the
// geometry, the equations and the reductions to the 2-DOF model.
//
// Numerics. δ_j = L_j − A₀ subtracts two lengths of order A₀ (≈ 0.6 mm for the 6308) to get a
// few micrometres. It is formed without that cancellation:
//     L² − A₀² = (w₀ + z)² + (u₀ + r)² − (w₀² + u₀²) = z (2w₀ + z) + r (2u₀ + r),
//     δ = (L² − A₀²)/(L + A₀),
// with u₀ = A₀ − P_d/2 and w₀ = sqrt((P_d/2)(2A₀ − P_d/2)) (no cos α₀ rounding).
//
// Jacobian. With e_j = (cos θ_j, sin θ_j, 0), e_z = (0, 0, 1) and the contact normal
// n_j = cos α_j e_j + sin α_j e_z = ∇δ_j, the Hessian of L_j is (e_j e_jᵀ + e_z e_zᵀ − n_j
// n_jᵀ)/L_j, so the contact force f = −Σ Q_j n_j has
//     ∂f/∂q = −Σ_j [ n K_j δ_j^{n−1} n_j n_jᵀ + (Q_j/L_j)(e_j e_jᵀ + e_z e_zᵀ − n_j n_jᵀ) ],
// the second term being the geometric stiffness of a load turning with the contact line.

#include "bearing/models/three_dof.h"

#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "ball_motion.h"
#include "ball_set.h"
#include "bearing/constants.h"
#include "bearing/kinematics.h"
#include "bearing/limits.h"
#include "bearing/numerics/newton.h"
#include "bearing/numerics/roots.h"
#include "bearing/static_load.h"
#include "film_contacts.h"
#include "frame_force.h"
#include "groove_geometry.h"
#include "housed_model.h"
#include "model_input_checks.h"
#include "static_rk4.h"

namespace bearing {

namespace {

using detail::approach;
using detail::groove_geometry;
using detail::GrooveGeometry;

void validate_axial(const ModelInputs& in) {
  if (!std::isfinite(in.axial_load))
    throw InputError("operation.axial_load = " + format_number(in.axial_load) +
                     " N: must be finite");
  if (in.axial_mass != 0) limits::rotor_axial_mass.check(in.axial_mass);  // 0: rotor.mass
  limits::rotor_axial_damping.check(in.axial_damping);
}

// The axial static state for load F (sign included): Z K δ^n sin α = F.
AxialPreload axial_state(const GrooveGeometry& g, int Z, double K, double n, double F) {
  AxialPreload p;
  if (F == 0) {
    p.z = -g.w0;  // centred: no ball loaded, α = 0
    return p;
  }
  const double load = std::abs(F);
  // h(δ) = Z K δ^n sin α(δ) − |F|, sin α = sqrt(L² − u₀²)/L, L = A₀ + δ: increasing in δ ≥ 0.
  // L² − u₀² = (A₀ − u₀ + δ)(A₀ + u₀ + δ) = (P_d/2 + δ)(2A₀ − P_d/2 + δ), without cancellation.
  const double half = g.A0 - g.u0;
  auto sin_alpha = [&](double d) {
    const double L = g.A0 + d;
    return std::sqrt((half + d) * (g.A0 + g.u0 + d)) / L;
  };
  const auto h = [&](double d) { return Z * K * std::pow(d, n) * sin_alpha(d) - load; };
  // Bracket: h(0) = −|F| < 0; grow from the estimate with sin α = 1 (at most 201 doublings, and
  // none past the largest double; an estimate that is infinite already fails the residual test).
  const double start = std::pow(load / (Z * K), 1.0 / n);
  const numerics::Bracket b = numerics::grow_bracket(
      0.0, start, [&](double d) { return h(d) < 0; }, 201);
  if (!b.found || (b.hi != start && !std::isfinite(b.hi)))
    throw SolverError("solve_axial_preload: could not bracket the ball approach for F_z = " +
                      format_number(F) + " N");
  // Regula falsi with the Illinois rule (bisection when the secant point leaves the bracket):
  // superlinear, and it cannot leave the bracket. Stops at an exact zero or a collapsed bracket.
  numerics::RegulaFalsiOptions rf;
  rf.max_iterations = 300;
  const double d =
      numerics::regula_falsi(
          h, b.lo, h(b.lo), b.hi, h(b.hi), [](double, double hd) { return hd == 0; }, rf)
          .x;
  const double s = sin_alpha(d);
  const double w = (g.A0 + d) * s;  // w₀ + z for F > 0
  p.z = F > 0 ? w - g.w0 : -w - g.w0;
  p.contact_angle = F > 0 ? std::asin(s) : -std::asin(s);
  p.ball_load = K * std::pow(d, n);
  const double residual = std::abs(Z * p.ball_load * s - load);
  if (!(residual <= 1e-10 * load))
    throw SolverError("solve_axial_preload: no axial equilibrium for F_z = " + format_number(F) +
                      " N (relative residual " + format_number(residual / load) + ")");
  return p;
}

double preload_cage_speed(const Bearing& b, double inner_speed, double contact_angle) {
  Bearing loaded = b;
  loaded.contact_angle = std::abs(contact_angle);
  return cage_speed(loaded, inner_speed);
}

class ThreeDofModel final
    : public detail::FrameForce<ThreeDofModel, detail::BallFrame, BearingModel> {
 public:
  explicit ThreeDofModel(const ModelInputs& in)
      : geometry_(checked_geometry(in)),
        preload_(axial_state(geometry_, in.bearing.balls, in.contact.K, in.contact.exponent,
                             in.axial_load)),
        set_(in, preload_cage_speed(in.bearing, in.inner_speed, preload_.contact_angle),
             preload_.contact_angle),
        mass_(in.mass),
        axial_mass_(in.axial_mass > 0 ? in.axial_mass : in.mass),
        damping_(in.damping),
        axial_damping_(in.axial_damping),
        load_x_(in.load.x()),
        load_y_(in.radial_load().y()),
        load_z_(in.axial_load),
        unbalance_force_(in.unbalance * in.inner_speed * in.inner_speed),
        phase_(in.cage_phase),
        film_on_(in.lubricated),
        film_(in.lubricated ? detail::series_film(in, set_.cage_speed()) : detail::SeriesFilm{}) {}

  int dofs() const override { return 3; }
  void mass(double* m) const override {
    m[0] = m[1] = mass_;
    m[2] = axial_mass_;
  }

  // Its per-ball loop is inline already: force_in_inline (frame_force.h) only has the frame's
  // balls rotated inline too.
  void force_in_inline(const detail::BallFrame& fr, const double* q, const double* v,
                       double* f) const {
    force_in(fr, q, v, f);
  }
  void force_in(const detail::BallFrame& fr, const double* q, const double* v, double* f) const {
    const double x = q[0], y = q[1], z = q[2], n = set_.exponent();
    const double w = geometry_.w0 + z;
    double fx = load_x_ + unbalance_force_ * fr.cos_shaft - damping_ * v[0];
    double fy = load_y_ + unbalance_force_ * fr.sin_shaft - damping_ * v[1];
    double fz = load_z_ - axial_damping_ * v[2];
    const int Z = set_.balls();
    if (film_on_) {  // once per evaluation: the dry loop below stays as it was
      const detail::RingForce c =
          detail::axial_film_force(film_.ball, geometry_, fr, Z, x, y, z, v[0], v[1], v[2]);
      f[0] = fx + c.x;
      f[1] = fy + c.y;
      f[2] = fz + c.z;
      return;
    }
    for (int j = 0; j < Z; ++j) {
      const double c = fr.cos_theta[j], s = fr.sin_theta[j];
      const double r = x * c + y * s + fr.excitation[j];
      double L;
      const double delta = approach(geometry_, r, z, L);
      if (delta <= 0) continue;
      const double QL = detail::contact_load(fr.stiffness[j], n, delta) / L;
      const double radial = QL * (geometry_.u0 + r);  // Q cos α_j
      fx -= radial * c;
      fy -= radial * s;
      fz -= QL * w;  // Q sin α_j
    }
    f[0] = fx;
    f[1] = fy;
    f[2] = fz;
  }

  void force_jacobian(double t, const double* q, const double* /*v*/, double* dfdq,
                      double* dfdv) const override {
    detail::BallFrame fr;
    set_.evaluate(t, fr);
    if (film_on_) {  // the film law's tangent; −Σ c_j n_j n_jᵀ on v (∂c/∂q neglected)
      detail::axial_film_jacobian(film_.ball, geometry_, fr, set_.balls(), q, dfdq, dfdv);
      for (int i = 0; i < 9; ++i) dfdq[i] = -dfdq[i], dfdv[i] = -dfdv[i];
      dfdv[0] -= damping_;
      dfdv[4] -= damping_;
      dfdv[8] -= axial_damping_;
      return;
    }
    contact_stiffness(fr, q, dfdq);
    for (int i = 0; i < 9; ++i) dfdq[i] = -dfdq[i];
    for (int i = 0; i < 9; ++i) dfdv[i] = 0.0;
    dfdv[0] = dfdv[4] = -damping_;
    dfdv[8] = -axial_damping_;
  }

  std::vector<std::string> dof_names() const override { return {"x", "y", "z"}; }
  int balls() const override { return set_.balls(); }
  double cage_speed() const override { return set_.cage_speed(); }

  void ball_loads(double t, const double* q, double* loads) const override {
    if (film_on_) return film_loads(t, q, loads);
    set_.ball_loads(
        t, [&](int j, const detail::BallFrame& fr) { return ball_approach(q, fr, j); }, loads);
  }

  void ball_approaches(double t, const double* q, double* out) const override {
    set_.ball_approaches(
        t, [&](int j, const detail::BallFrame& fr) { return ball_approach(q, fr, j); }, out);
  }

  // Contacts open and close where δ_j changes sign: the ball approaches are the switching
  // functions. With the film no contact opens (Q(δ) is smooth and positive): none.
  int switching_count() const override { return film_on_ ? 0 : set_.balls(); }
  void switching_functions(double t, const double* q, double* g) const override {
    ball_approaches(t, q, g);
  }

  // r_j = δ_o,j cos α_j − Π_o + ΔD_j/2 (bearing_model.h). With ρ_j = x cos θ_j + y sin θ_j + e_j,
  // L = sqrt((w₀ + z)² + (u₀ + ρ)²): dδ/dt = dL/dt = [(u₀ + ρ) dρ/dt + (w₀ + z) ż]/L and
  // d(cos α)/dt = [dρ/dt − cos α dL/dt]/L. An unloaded ball has no outer approach: r = −Π_o + ΔD/2.
  // With the film every ball is loaded and rides on the outer film (ball_motion.h).
  void ball_motion(double t, const double* q, const double* v, double* r,
                   double* vr) const override {
    detail::BallFrame fr;
    set_.evaluate(t, fr);
    detail::BallRates br;
    set_.rates(t, br);
    const double n = set_.exponent(), wc = br.cage_rate;  // dθ/dt, with the slip
    const double w = geometry_.w0 + q[2];
    for (int j = 0; j < set_.balls(); ++j) {
      const double c = fr.cos_theta[j], s = fr.sin_theta[j];
      const double rho = q[0] * c + q[1] * s + fr.excitation[j];
      double L;
      const double delta = approach(geometry_, rho, q[2], L);
      double Q = 0, Q_rate = 0, ca = 1, ca_rate = 0;
      if (delta > 0 || film_on_) {  // with the film every ball carries a load
        const double rho_rate =
            v[0] * c + v[1] * s + wc * (q[1] * c - q[0] * s) + br.excitation_rate[j];
        const double a = geometry_.u0 + rho;
        const double L_rate = (a * rho_rate + w * v[2]) / L;
        ca = a / L;
        ca_rate = (rho_rate - ca * L_rate) / L;
        if (film_on_) {
          const FilmLaw law = film_.ball.law(fr.stiffness[j]);
          Q = law.load(delta);
          Q_rate = detail::film_load_rate(law, Q, L_rate, br.stiffness_rate[j]);
        } else {
          Q = detail::contact_load(fr.stiffness[j], n, delta);
          Q_rate = n * Q / delta * L_rate + br.stiffness_rate[j] * std::pow(delta, n);
        }
      }
      double ro, vro;
      if (film_on_)  // the ball on the outer film (bearing_model.h)
        detail::outer_film_ball_motion(Q, Q_rate, br, j, set_.outer_exponent(),
                                       film_.films.outer.central_coefficient(), film_.press, 0.0,
                                       ro, vro);
      else
        detail::outer_ball_motion(Q, Q_rate, br, j, set_.outer_exponent(), 0.0, ro, vro);
      const double d_o = ro + br.outer_profile[j], d_o_rate = vro + br.outer_profile_rate[j];
      r[j] = d_o * ca - br.outer_profile[j] + 0.5 * set_.size_error(j);
      vr[j] = d_o_rate * ca + d_o * ca_rate - br.outer_profile_rate[j];
    }
  }

  double potential_energy(double t, const double* q) const override {
    if (film_on_) {  // Σ_j U(Q_j), film_law.h
      detail::BallFrame fr;
      set_.evaluate(t, fr);
      double e = 0.0;
      for (int j = 0; j < set_.balls(); ++j) {
        const FilmLaw law = film_.ball.law(fr.stiffness[j]);
        e += law.energy(law.load(ball_approach(q, fr, j)));
      }
      return e;
    }
    return set_.potential_energy(
        t, [&](int j, const detail::BallFrame& fr) { return ball_approach(q, fr, j); });
  }

  std::vector<double> initial_displacement() const override {
    std::vector<double> q = dry_static();
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
  std::vector<double> dry_static() const;

  void film_loads(double t, const double* q, double* loads) const {
    detail::BallFrame fr;
    set_.evaluate(t, fr);
    for (int j = 0; j < set_.balls(); ++j)
      loads[j] = film_.ball.load(fr.stiffness[j], ball_approach(q, fr, j));
  }

  // The ball set at t = 0 without excitation (the static solutions' frame).
  detail::BallFrame rest_frame() const { return set_.rest_frame(phase_); }

  // The static state with the film, from the dry one: Newton on the film's force balance.
  void film_static(double* q) const {
    const detail::BallFrame fr = rest_frame();
    const int Z = set_.balls();
    const auto residual = [&](const double* p, double* r, double* J) {
      const detail::RingForce c =
          detail::axial_film_force(film_.ball, geometry_, fr, Z, p[0], p[1], p[2], 0, 0, 0);
      r[0] = load_x_ + c.x;
      r[1] = load_y_ + c.y;
      r[2] = load_z_ + c.z;
      double d[9];
      detail::axial_film_jacobian(film_.ball, geometry_, fr, Z, p, J, d);
    };
    detail::film_equilibrium(3, q, residual, Eigen::Vector3d(load_x_, load_y_, load_z_).norm());
  }

  // δ_j of the 3-DOF geometry (docs/model.md §4), r_j = x cos θ_j + y sin θ_j + e_j.
  double ball_approach(const double* q, const detail::BallFrame& fr, int j) const {
    const double r = q[0] * fr.cos_theta[j] + q[1] * fr.sin_theta[j] + fr.excitation[j];
    double L;
    return approach(geometry_, r, q[2], L);
  }

  static GrooveGeometry checked_geometry(const ModelInputs& in) {
    detail::validate_common_inputs(in);
    validate_axial(in);
    return groove_geometry(in.bearing);
  }

  // Contact stiffness −∂f_contact/∂q (3×3 row-major, symmetric) for the balls of `fr` at q.
  void contact_stiffness(const detail::BallFrame& fr, const double* q, double* k) const {
    const double n = set_.exponent();
    const double w = geometry_.w0 + q[2];
    double kxx = 0, kxy = 0, kyy = 0, kxz = 0, kyz = 0, kzz = 0;
    for (int j = 0; j < set_.balls(); ++j) {
      const double c = fr.cos_theta[j], s = fr.sin_theta[j];
      const double r = q[0] * c + q[1] * s + fr.excitation[j];
      double L;
      const double delta = approach(geometry_, r, q[2], L);
      if (delta <= 0) continue;
      const double K = fr.stiffness[j];
      const double dQ = n == 1.5 ? 1.5 * K * std::sqrt(delta) : n * K * std::pow(delta, n - 1.0);
      const double QL = detail::contact_load(K, n, delta) / L;
      const double ca = (geometry_.u0 + r) / L, sa = w / L;  // cos α_j, sin α_j
      // n_j = (ca c, ca s, sa); K_j = (dQ − QL) n nᵀ + QL (e eᵀ + e_z e_zᵀ).
      const double kn = dQ - QL;
      kxx += kn * ca * ca * c * c + QL * c * c;
      kxy += kn * ca * ca * c * s + QL * c * s;
      kyy += kn * ca * ca * s * s + QL * s * s;
      kxz += kn * ca * sa * c;
      kyz += kn * ca * sa * s;
      kzz += kn * sa * sa + QL;
    }
    k[0] = kxx, k[1] = kxy, k[2] = kxz;
    k[3] = kxy, k[4] = kyy, k[5] = kyz;
    k[6] = kxz, k[7] = kyz, k[8] = kzz;
  }

  GrooveGeometry geometry_;
  AxialPreload preload_;
  friend class detail::FrameForce<ThreeDofModel, detail::BallFrame, BearingModel>;
  const detail::BallSet& ball_set() const { return set_; }

  detail::BallSet set_;
  double mass_, axial_mass_;
  double damping_, axial_damping_;
  double load_x_, load_y_, load_z_;  // constant loads, gravity included [N]
  double unbalance_force_;           // F_u = m_u e ω_i² [N]
  double phase_;                     // φ₀ [rad]
  bool film_on_;                     // lubricated: the EHL film in every ball's contacts
  detail::SeriesFilm film_;
};

// Static state under the constant loads, without waviness and size errors (three_dof.h).
// For F_z ≠ 0: minimise the convex potential Φ(q) = Σ_j K/(n+1) [δ_j]_+^{n+1} − F·q (each δ_j is
// a norm minus a constant, hence convex in q; [·]_+^{n+1} is convex and nondecreasing) by Newton
// steps (numerics::newton_minimize, μ = 1e-12 tr H) with an exact line search on the
// nondecreasing directional derivative: α = 1 unless it passes the minimum, else plain regula
// falsi on φ' in (0, 1) to |φ'| ≤ 0.1 |φ'(0)|. The start, the axial state, has every ball
// loaded, so the Hessian is positive definite there.
std::vector<double> ThreeDofModel::dry_static() const {
  const int Z = set_.balls();
  const Eigen::Vector3d F(load_x_, load_y_, load_z_);
  if (load_z_ == 0) {
    StaticLoadOptions o;
    o.phase = phase_;
    o.exponent = set_.exponent();
    // γ = A₀ − u₀ = P_d/2 (as the force sees it at the centred position).
    const StaticLoadResult r = solve_static_load(Z, set_.K(), geometry_.A0 - geometry_.u0,
                                                 Eigen::Vector2d(load_x_, load_y_), o);
    return {r.deflection.x(), r.deflection.y(), -geometry_.w0};
  }

  // The ball set at t = 0 without excitation.
  const detail::BallFrame fr = set_.rest_frame(phase_);
  const double n = set_.exponent();
  // ∇Φ = −(F − Σ Q_j n_j) and ∇²Φ = the contact stiffness; Φ itself is not needed.
  using State = numerics::PotentialPoint<3>;
  const auto evaluate = [&](const Eigen::Vector3d& q) {
    State st;
    Eigen::Vector3d& g = st.gradient;
    g = -F;
    const double w = geometry_.w0 + q.z();
    for (int j = 0; j < Z; ++j) {
      const double c = fr.cos_theta[j], s = fr.sin_theta[j];
      const double r = q.x() * c + q.y() * s;
      double L;
      const double delta = approach(geometry_, r, q.z(), L);
      if (delta <= 0) continue;
      const double QL = detail::contact_load(set_.K(), n, delta) / L;
      g += QL * Eigen::Vector3d((geometry_.u0 + r) * c, (geometry_.u0 + r) * s, w);
    }
    contact_stiffness(fr, q.data(), st.hessian.data());  // symmetric: storage order irrelevant
    return st;
  };

  Eigen::Vector3d q(0.0, 0.0, preload_.z);
  State at_q = evaluate(q);
  const double scale = F.norm();
  numerics::NewtonOptions o;
  o.tolerance = 1e-13 * scale;
  o.max_iterations = 100;
  o.line_search.unit_step = numerics::UnitStep::short_of_minimum;
  o.line_search.zoom.max_iterations = 100;
  o.line_search.zoom.margin = 0.01;
  o.line_search.zoom.illinois = false;
  o.line_search.zoom.stop_on_collapse = false;
  const numerics::NewtonResult r = numerics::newton_minimize(
      q, at_q, evaluate, [](const State&, const State&, const Eigen::Vector3d&) { return true; },
      o);
  const int it = r.iterations - (r.stalled ? 1 : 0);  // the one that could not move not counted
  const Eigen::Vector3d& g = at_q.gradient;
  if (!(g.norm() <= 1e-9 * scale)) {
    std::ostringstream msg;
    msg << "3-DOF model: no static equilibrium under the loads (" << format_number(F.x()) << ", "
        << format_number(F.y()) << ", " << format_number(F.z()) << ") N after " << it
        << " Newton iterations (relative force residual " << format_number(g.norm() / scale) << ")";
    throw SolverError(msg.str());
  }
  return {q.x(), q.y(), q.z()};
}

}  // namespace

AxialPreload solve_axial_preload(const ModelInputs& inputs) {
  detail::validate_common_inputs(inputs);
  validate_axial(inputs);
  const GrooveGeometry g = groove_geometry(inputs.bearing);
  return axial_state(g, inputs.bearing.balls, inputs.contact.K, inputs.contact.exponent,
                     inputs.axial_load);
}

double three_dof_cage_speed(const ModelInputs& inputs) {
  const AxialPreload p = solve_axial_preload(inputs);
  return preload_cage_speed(inputs.bearing, inputs.inner_speed, p.contact_angle);
}

std::unique_ptr<BearingModel> make_three_dof_model(const ModelInputs& inputs) {
  return std::make_unique<ThreeDofModel>(inputs);
}

std::unique_ptr<Integrator> make_three_dof_rk4(const IntegratorSettings& settings) {
  return std::make_unique<detail::StaticRk4<ThreeDofModel, 3>>(settings);
}

std::unique_ptr<BearingModel> make_three_dof_housed(const ModelInputs& bearing_only,
                                                    const RingLoad& load, const Housing& housing,
                                                    std::vector<double> start) {
  return detail::make_housed(ThreeDofModel(bearing_only), load, housing, bearing_only.contact_loop,
                             std::move(start));
}

std::unique_ptr<Integrator> make_three_dof_housed_rk4(const IntegratorSettings& settings) {
  return std::make_unique<detail::StaticRk4<detail::HousedModel<ThreeDofModel>, 0>>(settings);
}

}  // namespace bearing
