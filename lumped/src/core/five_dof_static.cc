// The 5-DOF static solution and stiffness (five_dof_static.h has the equations).

#include "bearing/five_dof_static.h"

#include <cmath>
#include <string>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/film_law.h"
#include "bearing/kinematics.h"
#include "bearing/numerics/newton.h"
#include "bearing/units.h"

namespace bearing {

namespace {

// The solver's coordinates: the tilts times ℜ_i, so that every coordinate is a length [m] and
// every component of the gradient a force [N] (one tolerance for all).
Vector5 scales(const FiveDofBearing& b) {
  Vector5 s;
  s << 1, 1, 1, 1 / b.groove_radius, 1 / b.groove_radius;
  return s;
}

// One contact's load Q = K δ^n and its 2×2 Hessian n K δ^{n−1} e eᵀ + (Q/L) t tᵀ along the
// line of length L and direction e (five_dof_static.h); nothing where δ ≤ 0. With a film
// (film_H > 0) FilmLaw's Q(δ), its tangent in place of n K δ^{n−1} and its energy.
struct Contact {
  double delta = 0, Q = 0, energy = 0;
  Eigen::Vector2d e = Eigen::Vector2d::Zero();
  Eigen::Matrix2d H = Eigen::Matrix2d::Zero();
};
Contact contact(const Eigen::Vector2d& line, double offset, double K, double n, double film_H = 0) {
  Contact c;
  const double L = line.norm();
  c.delta = L - offset;
  c.e = line / L;
  double tangent = 0;
  if (film_H == 0) {
    if (c.delta <= 0) return c;
    c.Q = K * std::pow(c.delta, n);
    c.energy = c.Q * c.delta / (n + 1);
    tangent = n * c.Q / c.delta;
  } else {
    const FilmLaw law{K, n, film_H};
    c.Q = law.load(c.delta);
    if (!(c.Q > 0)) return c;
    c.energy = law.energy(c.Q);
    tangent = law.tangent(c.Q);
  }
  const Eigen::Vector2d t(-c.e(1), c.e(0));
  c.H = tangent * c.e * c.e.transpose() + (c.Q / L) * t * t.transpose();
  return c;
}

// The squeeze film's damping c = S / h_c(Q) = S Q^e / C of one contact [N s/m] (0 when dry).
double squeeze_damping(double S, double film_C, double Q) {
  if (film_C == 0 || S == 0 || !(Q > 0)) return 0.0;
  return S * std::pow(Q, kCentralFilmLoadExponent) / film_C;
}

// One ball between the races at speed, its inner groove centre at `a` from the outer one (radial,
// axial): the ball centre p where its contacts and F_c balance, and what the ring feels.
struct BallAtSpeed {
  Contact inner, outer;
  double energy = 0;
  Eigen::Matrix2d ring_hessian = Eigen::Matrix2d::Zero();  // H_i − H_i (H_o + H_i)⁻¹ H_i
  Eigen::Matrix2d ring_damping = Eigen::Matrix2d::Zero();  // (I−P)ᵀ D_i (I−P) + Pᵀ D_o P
};
BallAtSpeed ball_at_speed(const FiveDofBearing& b, const Eigen::Vector2d& a) {
  const double ni = b.inner_exponent, no = b.outer_exponent, Fc = b.centrifugal;
  const Eigen::Vector2d radial(1, 0);
  BallAtSpeed ball;
  const double squeeze = a.norm() - b.inner_offset - b.outer_offset;
  if (Fc == 0 && squeeze <= 0) return ball;  // a free ball between open contacts
  // Start on the line of centres, the squeeze shared as two contacts in series, or resting on
  // the outer race under F_c alone.
  Eigen::Vector2d p = (b.outer_offset + std::pow(Fc / b.outer_K, 1 / no)) * radial;
  if (squeeze > 0)
    p = a.normalized() * (b.outer_offset + squeeze / (1 + std::pow(b.outer_K / b.inner_K, 1 / no)));
  const auto evaluate = [&](const Eigen::Vector2d& at) {
    const Contact o = contact(at, b.outer_offset, b.outer_K, no, b.outer_film_H);
    const Contact i = contact(a - at, b.inner_offset, b.inner_K, ni, b.inner_film_H);
    numerics::PotentialPoint<2> pt;
    pt.value = o.energy + i.energy - Fc * at(0);
    pt.gradient = o.Q * o.e - i.Q * i.e - Fc * radial;
    pt.hessian = o.H + i.H;
    return pt;
  };
  numerics::PotentialPoint<2> at = evaluate(p);
  numerics::LevenbergOptions opt;
  const double scale = std::max(Fc, b.inner_K * std::pow(std::max(squeeze, 0.0), ni));
  opt.tolerance = 1e-13 * scale;
  opt.stiffness = std::max(at.hessian.trace(), 1e-300);
  opt.max_iterations = 200;  // a convex 2-D problem: a few Newton steps from the start above
  const int iterations = numerics::levenberg_minimize<2>(p, at, evaluate, opt);
  if (!(at.gradient.norm() <= 1e-9 * scale))
    throw SolverError(
        "5-DOF static solution at speed: a ball between the races did not settle (its "
        "force balance " +
        format_number(at.gradient.norm()) + " N against F_c = " + format_number(Fc) + " N after " +
        std::to_string(iterations) + " iterations)");
  ball.outer = contact(p, b.outer_offset, b.outer_K, no, b.outer_film_H);
  ball.inner = contact(a - p, b.inner_offset, b.inner_K, ni, b.inner_film_H);
  ball.energy = at.value;  // min over p of E: its gradient in a is the inner contact force
  if (!(ball.inner.Q > 0)) return ball;
  ball.ring_hessian =
      ball.inner.H - ball.inner.H * (ball.outer.H + ball.inner.H).ldlt().solve(ball.inner.H);
  const double ci = squeeze_damping(b.inner_squeeze, b.inner_film_H, ball.inner.Q);
  const double co = squeeze_damping(b.outer_squeeze, b.outer_film_H, ball.outer.Q);
  if (ci > 0 || co > 0) {
    // The ball follows the ring as its springs place it (ṗ = P ȧ); each damper dissipates along
    // its own line (five_dof_static.h).
    const Eigen::Matrix2d P = (ball.outer.H + ball.inner.H).ldlt().solve(ball.inner.H);
    const Eigen::Matrix2d I_P = Eigen::Matrix2d::Identity() - P;
    const Eigen::Vector2d ri = I_P.transpose() * ball.inner.e, ro = P.transpose() * ball.outer.e;
    ball.ring_damping = ci * ri * ri.transpose() + co * ro * ro.transpose();
  }
  return ball;
}

}  // namespace

double ball_centrifugal_load(const Bearing& b, double inner_speed) {
  const double mass = b.ball.density * pi * std::pow(b.ball_diameter, 3) / 6;
  const double wc = cage_speed(b, inner_speed);
  return mass * wc * wc * 0.5 * b.pitch_diameter;
}

FiveDofBearing five_dof_bearing(const Bearing& b, const ContactConstants& c, double phase,
                                double centrifugal) {
  FiveDofBearing f;
  f.balls = b.balls;
  f.K = c.K;
  f.exponent = c.exponent;
  f.A0 = (b.inner_conformity + b.outer_conformity - 1.0) * b.ball_diameter;
  f.clearance = b.clearance;
  if (!(f.A0 > 0 && 0.5 * b.clearance < f.A0))
    throw InputError("bearing.clearance = " + format_number(b.clearance) +
                     " m: the 5-DOF solution needs P_d < 2 A0 = " + format_number(2 * f.A0) +
                     " m (A0 = (f_i + f_o - 1) D), i.e. a free contact angle below 90 deg");
  f.groove_radius =
      0.5 * b.pitch_diameter + (b.inner_conformity - 0.5) * b.ball_diameter - 0.25 * b.clearance;
  f.phase = phase;
  f.centrifugal = centrifugal;
  f.races_apart = centrifugal > 0;
  f.inner_K = c.inner.K;
  f.outer_K = c.outer.K;
  f.inner_exponent = c.inner.exponent;
  f.outer_exponent = c.outer.exponent;
  f.inner_offset = (b.inner_conformity - 0.5) * b.ball_diameter;
  f.outer_offset = (b.outer_conformity - 0.5) * b.ball_diameter;
  if (!(centrifugal >= 0 && std::isfinite(centrifugal)))
    throw InputError("centrifugal load = " + format_number(centrifugal) +
                     " N: allowed a finite load >= 0");
  return f;
}

void add_films(FiveDofBearing& b, const BallFilms& films) {
  // S = c h_c, the same at every load (ehl_film.h); no entrainment: no film, a dry contact.
  const auto set = [](const FilmContact& f, double& C, double& S) {
    C = f.entrainment_speed > 0 ? f.central_coefficient() : 0.0;
    S = C > 0 ? f.damping(1.0) * f.central_thickness(1.0) : 0.0;
  };
  set(films.inner, b.inner_film_H, b.inner_squeeze);
  set(films.outer, b.outer_film_H, b.outer_squeeze);
  b.film_H = b.inner_film_H + b.outer_film_H;
}

namespace {

// Ball j at speed (ball_at_speed) into p: its force Bᵀ Q_i e_i on the ring and its condensed
// stiffness Bᵀ H B (lower triangle; five_dof_point mirrors it).
void add_ball_at_speed(const FiveDofBearing& b, const Eigen::Vector2d& a, double c, double s, int j,
                       FiveDofPoint& p) {
  const BallAtSpeed ball = ball_at_speed(b, a);
  const double R = b.groove_radius;
  Eigen::Matrix<double, 2, 5> B;
  B << c, s, 0, 0, 0, 0, 0, 1, R * s, -R * c;
  p.approaches[j] = ball.inner.delta;
  p.ball_loads[j] = ball.inner.Q;
  p.outer_loads[j] = ball.outer.Q;
  p.contact_angles[j] = std::atan2(ball.inner.e(1), ball.inner.e(0));
  p.outer_contact_angles[j] = std::atan2(ball.outer.e(1), ball.outer.e(0));
  p.energy += ball.energy;
  if (ball.inner.Q <= 0) return;
  p.force += ball.inner.Q * B.transpose() * ball.inner.e;
  p.stiffness.triangularView<Eigen::Lower>() += B.transpose() * ball.ring_hessian * B;
  if (b.film_H > 0) p.damping += B.transpose() * ball.ring_damping * B;
}

}  // namespace

FiveDofPoint five_dof_point(const FiveDofBearing& b, const Vector5& q) {
  FiveDofPoint p;
  const int Z = b.balls;
  const double half = 0.5 * b.clearance;
  const double u = b.A0 - half;                           // radial offset of the centres, centred
  const double w0 = std::sqrt(half * (2 * b.A0 - half));  // axial offset where a ball touches
  const double n = b.exponent, R = b.groove_radius;
  p.ball_angles.resize(Z);
  p.approaches.resize(Z);
  p.ball_loads.resize(Z);
  p.contact_angles.resize(Z);
  p.outer_loads.resize(Z);
  p.outer_contact_angles.resize(Z);
  for (int j = 0; j < Z; ++j) {
    const double psi = b.phase + two_pi * j / Z, c = std::cos(psi), s = std::sin(psi);
    const double r = q(0) * c + q(1) * s;
    const double ax = q(2) + R * (q(3) * s - q(4) * c);
    const double L = std::hypot(u + r, ax);
    // δ = L − A₀ without the cancellation: L² − A₀² = (s − w₀)(s + w₀) + r (2u + r).
    const double delta = ((ax - w0) * (ax + w0) + r * (2 * u + r)) / (L + b.A0);
    const double ca = (u + r) / L, sa = ax / L;
    p.ball_angles[j] = psi;
    p.approaches[j] = delta;
    p.contact_angles[j] = std::atan2(ax, u + r);
    p.outer_contact_angles[j] = p.contact_angles[j];
    if (b.races_apart) {
      add_ball_at_speed(b, Eigen::Vector2d(u + r, ax), c, s, j, p);
      continue;
    }
    double Q = 0, tangent = 0;  // the load and dQ/dδ: Hertz's, or with the film in series
    if (b.film_H == 0) {
      if (delta <= 0) continue;
      Q = b.K * std::pow(delta, n);
      p.energy += Q * delta / (n + 1);
      tangent = n * Q / delta;
    } else {
      const FilmLaw law{b.K, n, b.film_H};
      Q = law.load(delta);
      if (!(Q > 0)) continue;
      p.energy += law.energy(Q);
      tangent = law.tangent(Q);
    }
    p.ball_loads[j] = Q;
    p.outer_loads[j] = Q;
    Vector5 g, h;  // Bᵀ e and Bᵀ t
    g << ca * c, ca * s, sa, sa * R * s, -sa * R * c;
    h << -sa * c, -sa * s, ca, ca * R * s, -ca * R * c;
    p.force += Q * g;
    // The lower triangle only, mirrored below: K is symmetric to the bit, as theory says.
    p.stiffness.selfadjointView<Eigen::Lower>().rankUpdate(g, tangent);
    p.stiffness.selfadjointView<Eigen::Lower>().rankUpdate(h, Q / L);
    if (b.film_H > 0) {
      // The two squeeze films in series on the ball's approach (film_law.h).
      const double ci = squeeze_damping(b.inner_squeeze, b.inner_film_H, Q);
      const double co = squeeze_damping(b.outer_squeeze, b.outer_film_H, Q);
      if (ci > 0 && co > 0)
        p.damping.selfadjointView<Eigen::Lower>().rankUpdate(g, ci * co / (ci + co));
    }
  }
  p.stiffness = p.stiffness.selfadjointView<Eigen::Lower>();
  p.damping = p.damping.selfadjointView<Eigen::Lower>();
  if (b.film_H > 0) {
    const FilmLaw inner{b.inner_K, b.inner_exponent, b.inner_film_H};
    const FilmLaw outer{b.outer_K, b.outer_exponent, b.outer_film_H};
    p.inner_films.resize(Z);
    p.outer_films.resize(Z);
    for (int j = 0; j < Z; ++j) {
      p.inner_films[j] = inner.film(p.ball_loads[j]);
      p.outer_films[j] = outer.film(p.outer_loads[j]);
    }
  }
  return p;
}

FiveDofSolution solve_five_dof(const FiveDofBearing& b, const Vector5& load, const HeldDofs& held) {
  FiveDofSolution sol;
  const Vector5 S = scales(b);  // q = S q', F' = S F (moments over ℜ_i)
  Vector5 free;                 // 1 for a free DOF, 0 for a held one
  for (int i = 0; i < 5; ++i) free(i) = held[i] ? 0.0 : 1.0;
  if (!load.allFinite())
    throw InputError("5-DOF static solution: the load (" + format_number(load(0)) + ", " +
                     format_number(load(1)) + ", " + format_number(load(2)) + " N; " +
                     format_number(load(3)) + ", " + format_number(load(4)) +
                     " N m) is not finite; allowed: finite forces and moments");
  const Vector5 Fs = S.cwiseProduct(load).cwiseProduct(free);
  const double Fn = Fs.norm();
  if (Fn == 0) {
    sol.at = five_dof_point(b, sol.displacement);
    return sol;
  }
  // The scale of the Hessian at the solution: Z balls at the deflection that carries |F|.
  const double n = b.exponent;
  const double delta = std::pow(Fn / (b.balls * b.K), 1 / n);
  numerics::LevenbergOptions o;
  o.tolerance = 1e-12 * Fn;
  o.stiffness = n * b.balls * b.K * std::pow(delta, n - 1);
  // A held DOF: no gradient and a unit row of the Hessian (times its scale), so no step moves it.
  const auto evaluate = [&](const Vector5& qs) {
    const FiveDofPoint p = five_dof_point(b, S.cwiseProduct(qs));
    numerics::PotentialPoint<5> pt;
    pt.value = p.energy - Fs.dot(qs);
    pt.gradient = (S.cwiseProduct(p.force) - Fs).cwiseProduct(free);
    pt.hessian =
        free.asDiagonal() * (S.asDiagonal() * p.stiffness * S.asDiagonal()) * free.asDiagonal();
    for (int i = 0; i < 5; ++i)
      if (held[i]) pt.hessian(i, i) = o.stiffness;
    return pt;
  };
  Vector5 qs = Vector5::Zero();
  numerics::PotentialPoint<5> at = evaluate(qs);
  sol.iterations = numerics::levenberg_minimize<5>(qs, at, evaluate, o);
  sol.displacement = S.cwiseProduct(qs);
  sol.at = five_dof_point(b, sol.displacement);
  sol.residual = at.gradient.norm() / Fn;
  // A NaN anywhere in q or K fails here too: no non-finite number leaves the solution.
  if (!(sol.residual <= 1e-10) || !sol.displacement.allFinite() || !sol.at.stiffness.allFinite() ||
      !sol.at.damping.allFinite())
    throw SolverError("5-DOF static solution: the load (" + format_number(load(0)) + ", " +
                      format_number(load(1)) + ", " + format_number(load(2)) + " N; " +
                      format_number(load(3)) + ", " + format_number(load(4)) +
                      " N m) is balanced only to " + format_number(sol.residual) +
                      " of its size after " + std::to_string(sol.iterations) + " iterations");
  return sol;
}

}  // namespace bearing
