// The EHL film in the ball-DOF kind (ball_dof_film.h).

#include "ball_dof_film.h"

#include "bearing/numerics/roots.h"

namespace bearing::detail {

void BallDofFilm::tangents(const RaceFrame& fr, int j, const BallContacts& k, double& ki,
                           double& ko) const {
  ki = races.inner.law(fr.inner_stiffness[j]).tangent(k.load_i);
  ko = races.outer.law(fr.outer_stiffness[j]).tangent(k.load_o);
}

double BallDofFilm::energy(const RaceFrame& fr, int j, const BallContacts& k) const {
  return races.inner.law(fr.inner_stiffness[j]).energy(k.load_i) +
         races.outer.law(fr.outer_stiffness[j]).energy(k.load_o);
}

void BallDofFilm::thickness(const RaceFrame& fr, int j, const BallContacts& k, double& inner,
                            double& outer) const {
  inner = races.inner.law(fr.inner_stiffness[j]).film(k.load_i);
  outer = races.outer.law(fr.outer_stiffness[j]).film(k.load_o);
}

void BallDofFilm::add_damping(const BallContacts& k, const double* nv, int ring, int S, int n,
                              double* dfdv) const {
  const auto at = [n](double* m, int i, int c) -> double& { return m[i * n + c]; };
  const double ci = races.inner.damping(k.load_i), co = races.outer.damping(k.load_o);
  for (int a = 0; a < ring; ++a) {
    for (int b = 0; b < ring; ++b) at(dfdv, a, b) -= ci * nv[a] * nv[b];
    at(dfdv, a, S) += ci * nv[a];
    at(dfdv, S, a) += ci * nv[a];
  }
  at(dfdv, S, S) -= ci + co;
}

double film_ball_equilibrium(const std::function<bool(double)>& below, double s0) {
  double lo = s0, hi = s0, step = 1e-7;  // [m]
  for (int i = 0; i < 60 && !below(lo); ++i, step *= 2) lo -= step;
  step = 1e-7;
  for (int i = 0; i < 60 && below(hi); ++i, step *= 2) hi += step;
  numerics::BisectionOptions o;
  o.abs_width = 1e-16;  // [m]
  const numerics::Bracket b = numerics::bisect(lo, hi, below, o);
  return 0.5 * (b.lo + b.hi);
}

}  // namespace bearing::detail
