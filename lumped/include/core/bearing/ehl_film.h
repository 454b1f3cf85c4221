#pragma once
// The elastohydrodynamic (EHL) film of one ball–race contact (issue 43, docs/model.md §11): its
// thickness, its stiffness in series with Hertz, and its damping.
//
// Thickness: Hamrock & Dowson (1977, "Isothermal elastohydrodynamic lubrication of point
// contacts, Part III — fully flooded results", J. Lubr. Technol. 99, 264–276), the fully flooded,
// isothermal, Newtonian point contact:
//     h_c   / R_x = 2.69 U^0.67 G^0.53 W^−0.067 (1 − 0.61 e^{−0.73 k}),
//     h_min / R_x = 3.63 U^0.68 G^0.49 W^−0.073 (1 − e^{−0.68 k}),
//     U = η₀ u / (E' R_x),   G = α E',   W = Q / (E' R_x²),
// R_x = 1/(ρ_I1 + ρ_II1) and R_y = 1/(ρ_I2 + ρ_II2) the effective radii along and across the
// rolling direction (contact.h's curvatures), E' = 2/η_c (η_c the Hertz compliance,
// material.h), k = a/b the Hertz ellipticity of the case's Hertz method (Hamrock & Dowson used
// their fit k = 1.03 (R_y/R_x)^0.64; the two differ by a few per cent, h_c far
// less: its k factor is within 2e-3 of 1 for k ≥ 8), u the entrainment (mean surface)
// speed, η₀ the viscosity at the inlet and α the pressure–viscosity coefficient. Their 34 runs
// varied k from 1 to 8, U over nearly two orders of magnitude and W over one, with steel, bronze
// and silicon nitride and paraffinic and naphthenic mineral oils (their abstract; the runs' exact
// bounds are not available here, so only k's span is checked: within_fit). The film parameter is
// Λ = h_min / σ (σ the composite RMS roughness): Λ < 1 boundary, 1–3 mixed, > 3 full film.
//
// Entrainment: for a race turning at ω_r and a cage at ω_c, the race surface at the contact moves
// relative to the cage at u_r = |ω_r − ω_c| ρ_r, ρ_i = (d_m − D cos α)/2, ρ_o = (d_m + D cos α)/2;
// in rolling the ball's surface moves with it, so u_r is the mean surface speed. With the outer
// ring fixed and the cage at its pure-rolling speed, both are u = ω_i (d_m² − D² cos² α)/(4 d_m).
//
// Stiffness: the film thins as the load grows, h_c = C Q^−0.067 (C from the formula above), so the
// ball and race centres approach by −dh_c beyond Hertz's dδ_H: the film is a spring
//     k_f = |dQ/dh_c| = Q / (0.067 h_c)
// in series with the Hertz contact's k_H = n Q/δ_H. k_f/k_H grows as Q^0.73: a few per cent to
// over ten softer at light loads, far stiffer than Hertz under heavy ones (film_law.h: the law).
//
// Damping: the squeeze film between the ball and the race — Reynolds' equation for a rigid,
// isoviscous gap h(x, y) = h₀ + x²/(2R_x) + y²/(2R_y) closing at the speed −dh₀/dt,
//     ∇·(h³ ∇p) = 12 η₀ dh₀/dt,
// has the exact solution p = 6 η₀ (−dh₀/dt) / ((1/R_x + 1/R_y) h²) (∇·(h³∇h⁻²) = −2∇²h and
// ∇²h = 1/R_x + 1/R_y), which vanishes far away; its force, ∫p dA with x = √(2R_x) ξ,
// y = √(2R_y) ζ, is F = c (−dh₀/dt) with
//     c = 12 π η₀ (R_x R_y)^{3/2} / ((R_x + R_y) h₀),
// for a sphere (R_x = R_y = R) Reynolds' classical 6 π η₀ R² / h₀ (Reynolds 1886; Hamrock, Schmid
// & Jacobson, Fundamentals of Fluid Film Lubrication, 2nd ed., ch. 10). The gap is taken as the
// EHL central film, h₀ = h_c(Q). Range: it is the damping of the inlet's isoviscous squeeze; it
// leaves out the piezoviscous Hertz zone and the surfaces' elastic flattening, so it is the
// lower estimate of the published EHL damping (Wijnant 1998's numerical results, not available
// here, lie above it under heavy loads); it holds while h_c ≪ R_x and the approach speed is far
// below the entrainment speed.

#include "bearing/bearing.h"
#include "bearing/contact.h"
#include "bearing/lubricant.h"

namespace bearing {

/// The exponent of the load in Hamrock–Dowson's central film, h_c ∝ W^−0.067 [-].
inline constexpr double kCentralFilmLoadExponent = 0.067;

/// The EHL film of one ball–race contact under a normal load Q [N].
struct FilmContact {
  double rx = 0;                  ///< R_x, effective radius along the rolling direction [m]
  double ry = 0;                  ///< R_y, across it [m]
  double ellipticity = 1;         ///< k = a/b of the Hertz contact [-]
  double reduced_modulus = 0;     ///< E' = 2/η_c [Pa]
  double entrainment_speed = 0;   ///< u, mean surface speed [m/s]
  double viscosity = 0;           ///< η₀ at the operating temperature [Pa s]
  double pressure_viscosity = 0;  ///< α [1/Pa]
  double roughness = 0;           ///< σ [m]

  double speed_parameter() const;            ///< U = η₀ u / (E' R_x) [-]
  double material_parameter() const;         ///< G = α E' [-]
  double load_parameter(double load) const;  ///< W = Q / (E' R_x²) [-]
  /// C in h_c = C Q^−0.067 [m N^0.067]: the central film under 1 N.
  double central_coefficient() const;
  double central_thickness(double load) const;  ///< h_c [m]; Q > 0
  double minimum_thickness(double load) const;  ///< h_min [m]; Q > 0
  double lambda(double load) const;             ///< Λ = h_min / σ [-]
  /// The film's normal stiffness k_f = Q / (0.067 h_c) [N/m].
  double stiffness(double load) const;
  /// The squeeze-film damping c = 12 π η₀ (R_x R_y)^{3/2} / ((R_x + R_y) h_c) [N s/m]; 0 without
  /// entrainment (u = 0: no film, the contact is dry).
  double damping(double load) const;
  /// Whether k lies inside the span of Hamrock & Dowson's runs, 1 ≤ k ≤ 8 (above). Beyond 8 (a
  /// closely conforming groove) their k factors are within 0.5 % of 1, so the film formula
  /// extrapolates gently; U and W are not checked (their runs' bounds are not at hand).
  bool within_fit() const;
};

/// The mean surface speed of the contact of a ball on `race` [m/s]: |ω_r − ω_c| ρ_r, ω_i =
/// `inner_speed`, ω_o = 0, ω_c = `cage_speed` [rad/s], at the contact angle `contact_angle`
/// [rad].
double entrainment_speed(const Bearing& b, Race race, double inner_speed, double cage_speed,
                         double contact_angle);

/// The film of a ball on `race` of `b`: R_x, R_y from the curvatures at the free contact angle,
/// k of `contact` (the race's Hertz constants), the lubricant's operating viscosity, at the
/// entrainment speed `speed` [m/s]. Throws InputError for an invalid lubricant.
FilmContact film_contact(const Bearing& b, Race race, const RaceContact& contact,
                         const Lubricant& lubricant, double speed);

/// The films of one ball's two contacts.
struct BallFilms {
  FilmContact inner;
  FilmContact outer;
};

/// Both films of a ball of `b` with the contact constants `c`, at the inner ring's speed
/// `inner_speed` and the cage speed `cage_speed` [rad/s], at the free contact angle.
BallFilms ball_films(const Bearing& b, const ContactConstants& c, const Lubricant& lubricant,
                     double inner_speed, double cage_speed);

}  // namespace bearing
