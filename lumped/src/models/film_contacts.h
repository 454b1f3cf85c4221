#pragma once
// Private to the lumped models (not installed): the EHL film in the contacts of the dynamic kinds
// (issue 43; ehl_film.h, film_law.h). Off without a [lubricant] table: the models then never call
// anything here, and their dry hot loops are the ones they had (one branch per evaluation, outside
// the per-ball loop, chooses this path).
//
// A contact with its film carries Q(δ) = FilmLaw{K, n, H}.load(δ), smooth and positive for every
// δ (no contact opens), and the squeeze film's damper c(Q) = d Q^0.067 (ehl_film.h: c ∝ 1/h_c and
// h_c = C Q^−0.067, so d = c at 1 N) on the contact's approach rate δ̇. The 2-DOF and 3-DOF kinds
// have one massless ball of two contacts in series: H = C_i + C_o and c = c_i c_o/(c_i + c_o)
// (film_law.h). The approach rate is the ring's (and the ball's) velocity along the contact
// normal, δ̇ = ∇δ · v: the rates of the turning geometry (ω_c (y cos θ − x sin θ), a ring off
// centre seen by the travelling ball) and of the excitation (waviness, defects) are left out, so
// the damper acts on the vibration, as a Rayleigh dissipation Σ ½ c δ̇², and the film's lag over
// the slow load cycle of a ball passing the load zone is not modelled. ∂c/∂q is neglected in the
// Jacobians (c varies as Q^0.067: a term 0.067 c δ̇/Q of the stiffness).

#include <cmath>
#include <functional>

#include "ball_set.h"
#include "bearing/ehl_film.h"
#include "bearing/film_law.h"
#include "bearing/models/model_inputs.h"
#include "groove_geometry.h"

namespace bearing::detail {

/// A contact's (or a ball's two contacts' in series) film.
struct ContactFilm {
  double H = 0;           ///< film coefficient, h_c = H Q^−0.067 [m N^0.067]
  double exponent = 1.5;  ///< n of the Hertz law it is in series with [-]
  double damper = 0;      ///< d in c(Q) = d Q^0.067 [N s/m N^−0.067]; 0: no entrainment

  FilmLaw law(double K) const { return {K, exponent, H}; }
  /// Q(δ) [N] for the Hertz constant K [N/m^n] and the approach δ [m].
  double load(double K, double delta) const { return law(K).load(delta); }
  /// The squeeze damper c(Q) [N s/m].
  double damping(double load) const {
    return load > 0 && damper > 0 ? damper * std::pow(load, kCentralFilmLoadExponent) : 0.0;
  }
};

/// The film of one contact in series with a Hertz law of exponent n.
ContactFilm contact_film(const FilmContact& f, double exponent);

/// The 2-DOF and 3-DOF kinds' films: each ball's two contacts (for the thickness outputs) and the
/// ball as their series (the force).
struct SeriesFilm {
  BallFilms films;
  ContactFilm ball;  ///< H = C_i + C_o, d = d_i d_o/(d_i + d_o), n of the series law
  /// F_c = m_b ω_c² d_m/2 [N] at the model's cage speed (m_b: ModelInputs::ball_mass, or ρ π D³/6),
  /// the centrifugal load that keeps a ball on the outer race (its film there: ball_motion.h)
  double press = 0;
};

/// The films of `in` (lubricated) with the model's cage speed ω_c [rad/s].
SeriesFilm series_film(const ModelInputs& in, double cage_speed);

/// The two contacts of the ball-DOF model, each with its own film.
struct RaceFilms {
  BallFilms films;
  ContactFilm inner, outer;
};
RaceFilms race_films(const ModelInputs& in, double cage_speed);

/// Each ball's central film thickness at its inner and outer contact for the ball loads Q_j [N]
/// of a ball of two contacts in series: h_r = C_r Q_j^−0.067 [m].
void series_film_thickness(const SeriesFilm& f, const double* loads, int Z, double* inner,
                           double* outer);

/// Generalised force of the contacts on the ring [N].
struct RingForce {
  double x = 0, y = 0, z = 0;
};

/// 2-DOF: −Σ_j (Q_j + c_j δ̇_j) e_j, δ_j = x cos θ_j + y sin θ_j − γ + e_j, δ̇_j = ẋ cos θ_j +
/// ẏ sin θ_j. (By value: no address of the state leaves the kind's RK4 loop.)
RingForce radial_film_force(const ContactFilm& film, const BallFrame& fr, int Z, double x, double y,
                            double vx, double vy, double gap);
/// Its −∂f/∂q (stiffness) and −∂f/∂v (damping), 2×2 row-major each.
void radial_film_jacobian(const ContactFilm& film, const BallFrame& fr, int Z, double x, double y,
                          double gap, double* stiffness, double* damping);

/// 3-DOF: −Σ_j (Q_j + c_j δ̇_j) n_j along the loaded contact line (three_dof.h), δ̇_j = n_j · v.
RingForce axial_film_force(const ContactFilm& film, const GrooveGeometry& g, const BallFrame& fr,
                           int Z, double x, double y, double z, double vx, double vy, double vz);
/// Its −∂f/∂q (with the geometric stiffness Q/L of the turning line) and −∂f/∂v, 3×3 row-major.
void axial_film_jacobian(const ContactFilm& film, const GrooveGeometry& g, const BallFrame& fr,
                         int Z, const double* q, double* stiffness, double* damping);

/// The static equilibrium of the ring's `n` DOFs (2 or 3) with the film: damped Newton on
/// residual(q, r, J) (r = the force at rest [N], J = its −∂/∂q) from the dry solution `q`,
/// halving the step until |r| falls. Throws SolverError if it does not converge.
/// `scale` [N]: the loads' size, for the tolerance 1e-10 scale.
void film_equilibrium(int n, double* q,
                      const std::function<void(const double* q, double* r, double* J)>& residual,
                      double scale);

}  // namespace bearing::detail
