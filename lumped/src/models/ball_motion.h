#pragma once
// Private to the lumped models (not installed): each ball centre's radial motion at an output
// instant (BearingModel::ball_motion, bearing_model.h), from its load and the ball set's rates.

#include <cmath>

#include "ball_set.h"
#include "bearing/ehl_film.h"
#include "bearing/film_law.h"

namespace bearing::detail {

/// The ball centre's radial displacement from the pitch radius, r = δ_o − Π_o + ΔD/2 [m], and
/// its rate [m/s], from the ball's load Q = K δ^n and its rate (see bearing_model.h for the
/// definition): δ_o = (Q/K_o)^{1/n_o}, dδ_o/dt = δ_o/n_o · (dQ/dt / Q − dK_o/dt / K_o).
inline void outer_ball_motion(double load, double load_rate, const BallRates& br, int j,
                              double outer_exponent, double size_error, double& r, double& vr) {
  double d_o = 0, d_o_rate = 0;
  if (load > 0) {
    const double Ko = br.outer_stiffness[j];
    d_o = std::pow(load / Ko, 1.0 / outer_exponent);
    d_o_rate = d_o / outer_exponent * (load_rate / load - br.outer_stiffness_rate[j] / Ko);
  }
  r = d_o - br.outer_profile[j] + 0.5 * size_error;
  vr = d_o_rate - br.outer_profile_rate[j];
}

/// outer_ball_motion() with the EHL film (film_law.h): the ball rides on the outer contact's film
/// under the load that presses it there, h_o = C_o (Q + F_c)^−e (e = 0.067, C_o [m N^e], F_c
/// `press` [N] the ball's centrifugal load, which keeps an unloaded ball on the outer race as in
/// the dry definition; the contact laws leave F_c's sub-micron Hertz deflection out, as the dry
/// ones do), so δ_o = (Q/K_o)^{1/n_o} − h_o and
/// dδ_o/dt = δ_H,o/n_o (dQ/dt / Q − dK_o/dt / K_o) + e h_o dQ/dt / (Q + F_c).
inline void outer_film_ball_motion(double load, double load_rate, const BallRates& br, int j,
                                   double outer_exponent, double outer_film, double press,
                                   double size_error, double& r, double& vr) {
  double d_o = 0, d_o_rate = 0;
  if (load > 0) {
    const double Ko = br.outer_stiffness[j];
    const double hertz = std::pow(load / Ko, 1.0 / outer_exponent);
    d_o = hertz;
    d_o_rate = hertz / outer_exponent * (load_rate / load - br.outer_stiffness_rate[j] / Ko);
  }
  if (outer_film > 0 && load + press > 0) {  // no entrainment (C_o = 0): no film
    const double film = outer_film * std::pow(load + press, -kCentralFilmLoadExponent);
    d_o -= film;
    d_o_rate += kCentralFilmLoadExponent * film * load_rate / (load + press);
  }
  r = d_o - br.outer_profile[j] + 0.5 * size_error;
  vr = d_o_rate - br.outer_profile_rate[j];
}

/// The rate of a film law's load Q(δ; K) [N/s] (film_law.h) for the approach's rate dδ/dt [m/s]
/// and the Hertz constant's dK/dt [N/(m^n s)]: at fixed δ only the Hertz part
/// δ_H = (Q/K)^{1/n} moves with K (∂δ_H/∂K = −δ_H/(n K)), so
/// dQ/dt = dQ/dδ · (dδ/dt + δ_H/(n K) · dK/dt); without the film, n Q/δ dδ/dt + dK/dt δ^n.
inline double film_load_rate(const FilmLaw& law, double load, double approach_rate,
                             double stiffness_rate) {
  if (!(load > 0)) return 0.0;
  const double hertz = std::pow(load / law.K, 1.0 / law.exponent);
  return law.tangent(load) * (approach_rate + hertz / (law.exponent * law.K) * stiffness_rate);
}

/// The radial ball motion (bearing_model.h) of the 2-DOF geometry, δ_j = x cos θ_j + y sin θ_j −
/// γ + e_j, at (t, q = (x, y), v = (ẋ, ẏ)): dδ_j/dt = v·(cos θ_j, sin θ_j) + ω_c (−x sin θ_j +
/// y cos θ_j) + de_j/dt, dQ_j/dt = n K_j δ_j^{n−1} dδ_j/dt + dK_j/dt δ_j^n.
inline void radial_ball_motion(const BallSet& set, double gap, double t, const double* q,
                               const double* v, double* r, double* vr) {
  BallFrame fr;
  set.evaluate(t, fr);
  BallRates br;
  set.rates(t, br);
  const double n = set.exponent(), wc = br.cage_rate;  // dθ/dt, with the slip
  for (int j = 0; j < set.balls(); ++j) {
    const double c = fr.cos_theta[j], s = fr.sin_theta[j];
    const double delta = q[0] * c + q[1] * s - gap + fr.excitation[j];
    double Q = 0, Q_rate = 0;
    if (delta > 0) {
      const double rate = v[0] * c + v[1] * s + wc * (q[1] * c - q[0] * s) + br.excitation_rate[j];
      Q = contact_load(fr.stiffness[j], n, delta);
      Q_rate = n * Q / delta * rate + br.stiffness_rate[j] * std::pow(delta, n);
    }
    outer_ball_motion(Q, Q_rate, br, j, set.outer_exponent(), set.size_error(j), r[j], vr[j]);
  }
}

/// radial_ball_motion() with the EHL film: Q_j = FilmLaw{K_j, n, H}.load(δ_j) of the ball's
/// series law (H = C_i + C_o, smooth and positive for every δ_j), its rate by film_load_rate(),
/// and the ball on the outer film C_o [m N^0.067] under Q_j + F_c (`press` [N],
/// outer_film_ball_motion()).
inline void radial_film_ball_motion(const BallSet& set, double gap, double H, double outer_film,
                                    double press, double t, const double* q, const double* v,
                                    double* r, double* vr) {
  BallFrame fr;
  set.evaluate(t, fr);
  BallRates br;
  set.rates(t, br);
  const double n = set.exponent(), wc = br.cage_rate;  // dθ/dt, with the slip
  for (int j = 0; j < set.balls(); ++j) {
    const double c = fr.cos_theta[j], s = fr.sin_theta[j];
    const double delta = q[0] * c + q[1] * s - gap + fr.excitation[j];
    const double rate = v[0] * c + v[1] * s + wc * (q[1] * c - q[0] * s) + br.excitation_rate[j];
    const FilmLaw law{fr.stiffness[j], n, H};
    const double Q = law.load(delta);
    const double Q_rate = film_load_rate(law, Q, rate, br.stiffness_rate[j]);
    outer_film_ball_motion(Q, Q_rate, br, j, set.outer_exponent(), outer_film, press,
                           set.size_error(j), r[j], vr[j]);
  }
}

}  // namespace bearing::detail
