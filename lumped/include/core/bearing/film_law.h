#pragma once
// A contact's load–approach law with its EHL film in series (issue 43, ehl_film.h): what the
// lumped kinds and the static solution use in place of Q = K δ^n when the case has a lubricant.
//
// The film keeps the surfaces h_c(Q) = H Q^−e apart (e = 0.067, Hamrock–Dowson), so the approach δ
// of the ball and race centres that a dry contact would turn into Hertz deflection alone (the
// geometric overlap, positive in contact) carries the load Q with
//     δ = δ_H(Q) − h_c(Q) = (Q/K)^{1/n} − H Q^−e.
// The right side rises monotonically from −∞ (Q → 0) to +∞, so every δ has exactly one Q > 0: the
// load falls smoothly towards 0 as the gap opens (a gap of 10 h_c leaves ~1e-15 of the load) and
// the contact never switches. Its tangent is the series of Hertz's and the film's springs,
//     dQ/dδ = 1 / (δ_H/(n Q) + e h_c/Q) = (1/k_H + 1/k_f)^−1,
// and its energy, U(Q) = ∫ Q dδ from the open gap, is
//     U = Q δ_H/(n + 1) + e/(1 − e) Q h_c.
// For a ball between two races (the 2-DOF and 3-DOF kinds, one series constant K) the two films
// add, H = C_i + C_o. With H = 0 (no viscosity) the law is Hertz's, Q = K [δ]_+^n.
//
// Damping of a ball between two races: its two squeeze films in series,
// c = c_i c_o / (c_i + c_o), acting on the rate of δ (the contacts' damping in parallel with
// their springs: exact when the two contacts' springs stand in the ratio of their dampers, and
// for the ball-DOF model, where each contact has its own δ, exact as it stands).

namespace bearing {

struct FilmLaw {
  double K = 0;           ///< Hertz constant of the contact (or of the ball in series) [N/m^n]
  double exponent = 1.5;  ///< n [-]
  double H = 0;           ///< film coefficient, h_c = H Q^−0.067 [m N^0.067]; 0: dry

  /// Q(δ) [N] for the approach δ [m]: the one root of δ = (Q/K)^{1/n} − H Q^−e; with H = 0,
  /// K [δ]_+^n.
  double load(double approach) const;
  /// dQ/dδ at the load Q [N/m].
  double tangent(double load) const;
  /// U(Q), the energy stored up to load Q [J].
  double energy(double load) const;
  /// The film's central thickness at load Q, H Q^−e [m] (0 for H = 0 or Q = 0).
  double film(double load) const;
};

}  // namespace bearing
