// The EHL film in the contacts of the dynamic kinds (film_contacts.h).

#include "film_contacts.h"

#include <cmath>
#include <string>

#include <Eigen/Dense>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/units.h"

namespace bearing::detail {

ContactFilm contact_film(const FilmContact& f, double exponent) {
  // c(Q) = 12 π η₀ (R_x R_y)^{3/2} / ((R_x + R_y) C Q^−e) = c(1 N) Q^e.
  return {f.central_coefficient(), exponent, f.damping(1.0)};
}

SeriesFilm series_film(const ModelInputs& in, double cage_speed) {
  SeriesFilm s;
  s.films = ball_films(in.bearing, in.contact, in.lubricant, in.inner_speed, cage_speed);
  const ContactFilm i = contact_film(s.films.inner, in.contact.exponent);
  const ContactFilm o = contact_film(s.films.outer, in.contact.exponent);
  s.ball.H = i.H + o.H;
  s.ball.exponent = in.contact.exponent;
  // Two dampers in series (film_law.h); either one 0 (no entrainment): none.
  s.ball.damper = i.damper > 0 && o.damper > 0 ? i.damper * o.damper / (i.damper + o.damper) : 0.0;
  // F_c = m_b ω_c² d_m/2 at the model's own cage speed (the 3-DOF one at its loaded angle).
  const double D = in.bearing.ball_diameter;
  const double ball_mass =
      in.ball_mass > 0 ? in.ball_mass : in.bearing.ball.density * pi * D * D * D / 6.0;
  s.press = ball_mass * cage_speed * cage_speed * 0.5 * in.bearing.pitch_diameter;
  return s;
}

RaceFilms race_films(const ModelInputs& in, double cage_speed) {
  RaceFilms r;
  r.films = ball_films(in.bearing, in.contact, in.lubricant, in.inner_speed, cage_speed);
  r.inner = contact_film(r.films.inner, in.contact.inner.exponent);
  r.outer = contact_film(r.films.outer, in.contact.outer.exponent);
  return r;
}

void series_film_thickness(const SeriesFilm& f, const double* loads, int Z, double* inner,
                           double* outer) {
  const FilmLaw li{1.0, f.ball.exponent, f.films.inner.central_coefficient()};
  const FilmLaw lo{1.0, f.ball.exponent, f.films.outer.central_coefficient()};
  for (int j = 0; j < Z; ++j) {
    inner[j] = li.film(loads[j]);
    outer[j] = lo.film(loads[j]);
  }
}

RingForce radial_film_force(const ContactFilm& film, const BallFrame& fr, int Z, double x, double y,
                            double vx, double vy, double gap) {
  RingForce f;
  for (int j = 0; j < Z; ++j) {
    const double c = fr.cos_theta[j], s = fr.sin_theta[j];
    const double delta = x * c + y * s - gap + fr.excitation[j];
    const double Q = film.load(fr.stiffness[j], delta);
    const double push = Q + film.damping(Q) * (vx * c + vy * s);
    f.x -= push * c;
    f.y -= push * s;
  }
  return f;
}

void radial_film_jacobian(const ContactFilm& film, const BallFrame& fr, int Z, double x, double y,
                          double gap, double* stiffness, double* damping) {
  double k[3] = {0, 0, 0}, d[3] = {0, 0, 0};  // xx, xy, yy
  for (int j = 0; j < Z; ++j) {
    const double c = fr.cos_theta[j], s = fr.sin_theta[j];
    const FilmLaw law = film.law(fr.stiffness[j]);
    const double Q = law.load(x * c + y * s - gap + fr.excitation[j]);
    const double kt = law.tangent(Q), cj = film.damping(Q);
    const double e[3] = {c * c, c * s, s * s};
    for (int i = 0; i < 3; ++i) {
      k[i] += kt * e[i];
      d[i] += cj * e[i];
    }
  }
  stiffness[0] = k[0], stiffness[1] = stiffness[2] = k[1], stiffness[3] = k[2];
  damping[0] = d[0], damping[1] = damping[2] = d[1], damping[3] = d[2];
}

namespace {

// Ball j's contact line in the 3-DOF geometry: δ_j, L_j and the normal n_j = ∇δ_j.
struct Line {
  double delta, L, n[3];
};
Line contact_line(const GrooveGeometry& g, const BallFrame& fr, int j, double x, double y,
                  double z) {
  const double c = fr.cos_theta[j], s = fr.sin_theta[j];
  const double r = x * c + y * s + fr.excitation[j];
  Line l;
  l.delta = approach(g, r, z, l.L);
  const double ca = (g.u0 + r) / l.L, sa = (g.w0 + z) / l.L;
  l.n[0] = ca * c, l.n[1] = ca * s, l.n[2] = sa;
  return l;
}

}  // namespace

RingForce axial_film_force(const ContactFilm& film, const GrooveGeometry& g, const BallFrame& fr,
                           int Z, double x, double y, double z, double vx, double vy, double vz) {
  RingForce f;
  for (int j = 0; j < Z; ++j) {
    const Line l = contact_line(g, fr, j, x, y, z);
    const double Q = film.load(fr.stiffness[j], l.delta);
    const double push = Q + film.damping(Q) * (l.n[0] * vx + l.n[1] * vy + l.n[2] * vz);
    f.x -= push * l.n[0];
    f.y -= push * l.n[1];
    f.z -= push * l.n[2];
  }
  return f;
}

void axial_film_jacobian(const ContactFilm& film, const GrooveGeometry& g, const BallFrame& fr,
                         int Z, const double* q, double* stiffness, double* damping) {
  for (int i = 0; i < 9; ++i) stiffness[i] = damping[i] = 0.0;
  for (int j = 0; j < Z; ++j) {
    const Line l = contact_line(g, fr, j, q[0], q[1], q[2]);
    const FilmLaw law = film.law(fr.stiffness[j]);
    const double Q = law.load(l.delta);
    const double kn = law.tangent(Q) - Q / l.L, QL = Q / l.L, cj = film.damping(Q);
    // three_dof.cc: (dQ/dδ − Q/L) n nᵀ + (Q/L)(e eᵀ + e_z e_zᵀ), e = (cos θ, sin θ, 0).
    const double e[3] = {fr.cos_theta[j], fr.sin_theta[j], 0.0}, ez[3] = {0.0, 0.0, 1.0};
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        stiffness[3 * a + b] += kn * l.n[a] * l.n[b] + QL * (e[a] * e[b] + ez[a] * ez[b]);
        damping[3 * a + b] += cj * l.n[a] * l.n[b];
      }
  }
}

void film_equilibrium(int n, double* q,
                      const std::function<void(const double* q, double* r, double* J)>& residual,
                      double scale) {
  using Mat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  Eigen::VectorXd x = Eigen::Map<Eigen::VectorXd>(q, n), r(n), r_try(n);
  Mat J(n, n), J_try(n, n);
  residual(x.data(), r.data(), J.data());
  const double tol = 1e-10 * std::max(scale, 1.0);
  for (int it = 0; it < 100 && !(r.norm() <= tol); ++it) {
    // J = −∂r/∂q is the contact stiffness, symmetric positive (semi)definite: a Newton step
    // q + J⁻¹ r, halved until the residual falls (the law's stiffness grows with the load).
    const Eigen::VectorXd step = J.completeOrthogonalDecomposition().solve(r);
    double a = 1.0;
    bool moved = false;
    for (int h = 0; h < 60 && step.allFinite(); ++h, a *= 0.5) {
      const Eigen::VectorXd xt = x + a * step;
      residual(xt.data(), r_try.data(), J_try.data());
      if (r_try.norm() < r.norm()) {
        x = xt, r = r_try, J = J_try;
        moved = true;
        break;
      }
    }
    if (!moved) break;
  }
  if (!(r.norm() <= tol))
    throw SolverError("film: no static equilibrium with the EHL film (force residual " +
                      format_number(r.norm()) + " N)");
  Eigen::Map<Eigen::VectorXd>(q, n) = x;
}

}  // namespace bearing::detail
