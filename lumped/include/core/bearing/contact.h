#pragma once
// Hertz load–deflection constants of a ball on each race and of the ball between both races.

#include <string>

#include "bearing/bearing.h"
#include "bearing/hertz.h"

namespace bearing {

enum class Race { inner, outer };
const char* to_string(Race race);

/// Principal curvatures of one ball–race contact [1/m] (Harris's sign convention: convex
/// positive, concave negative). Index 1 is the rolling direction, 2 the transverse (groove) one.
struct Curvatures {
  double ball_1 = 0;  ///< ρ_I1 = 2/D
  double ball_2 = 0;  ///< ρ_I2 = 2/D
  double race_1 = 0;  ///< ρ_II1: inner (2/D)·g/(1−g), outer −(2/D)·g/(1+g), g = D cos α / d_m
  double race_2 = 0;  ///< ρ_II2 = −1/(f D), the groove
  /// Curvature sum Σρ [1/m].
  double sum() const { return ball_1 + ball_2 + race_1 + race_2; }
  /// Curvature difference F(ρ) = [(ρ_I1 − ρ_I2) + (ρ_II1 − ρ_II2)] / Σρ [-].
  double difference() const { return ((ball_1 - ball_2) + (race_1 - race_2)) / sum(); }
};

/// Curvatures of the ball on the given race of `b` (docs/model.md §3).
Curvatures race_curvatures(const Bearing& b, Race race);

/// Contact constants of one ball on one race.
struct RaceContact {
  double sum_rho = 0;     ///< Σρ [1/m]
  double f_rho = 0;       ///< F(ρ) [-]
  double compliance = 0;  ///< η = (1−ν_b²)/E_b + (1−ν_r²)/E_r [1/Pa]
  HertzShape shape;       ///< κ, K(e), E(e), δ*, a*, b*
  double K = 0;           ///< load–deflection constant, Q = K δ^n [N/m^n] (N/m^1.5 for Hertz)
  double exponent = 1.5;  ///< load–deflection exponent n [-] (1.5 for Hertz; FE-calibrated: any)

  /// Elastic approach δ = (Q/K)^{1/n} under normal load Q ≥ 0 [m].
  double approach(double load) const;
  /// Major semi-axis a of the contact ellipse under load Q [m] (transverse to rolling). The
  /// semi-axes and the pressure are Hertz's, whatever K and n are (calibration.h).
  double semi_major(double load) const;
  /// Minor semi-axis b under load Q [m] (along the rolling direction).
  double semi_minor(double load) const;
  /// Peak Hertz pressure p_max = 3Q / (2π a b) [Pa].
  double peak_pressure(double load) const;
};

/// The peak Hertz pressure of ball bearings at their static load rating (ISO 76: 4200 MPa for
/// self-aligning ball bearings 4600, all other ball bearings 4200) [Pa]: beyond it the contact
/// deforms plastically, and the lumped model's elastic contact law no longer holds.
inline constexpr double kElasticPressureLimit = 4.2e9;

/// Hertz constants of one race contact of `b` by the given method.
RaceContact race_contact(const Bearing& b, Race race, const HertzSolution& method);

/// Series stiffness of a ball between two races, both Q = K δ^{3/2}:
/// K = (K_i^{−2/3} + K_o^{−2/3})^{−3/2} [N/m^1.5].
double series_stiffness(double k_inner, double k_outer);

/// Series stiffness of a ball between two races with the same exponent n, Q = K_r δ_r^n:
/// the approaches add, (Q/K)^{1/n} = (Q/K_i)^{1/n} + (Q/K_o)^{1/n}, so
/// K = (K_i^{−1/n} + K_o^{−1/n})^{−n} [N/m^n]. For n = 3/2 exactly the same number as
/// series_stiffness(k_inner, k_outer).
double series_stiffness(double k_inner, double k_outer, double exponent);

/// Contact constants of the whole bearing: both races and the ball between them.
/// The contact law a case selects (model.contact): a Hertz method, or the FE-calibrated constants
/// of calibration.h.
enum class ContactLaw { exact, hamrock_brewe, harris_table, calibrated };
inline constexpr Named<ContactLaw> kContactLaws[] = {{ContactLaw::exact, "exact"},
                                                     {ContactLaw::hamrock_brewe, "hamrock-brewe"},
                                                     {ContactLaw::harris_table, "harris-table"},
                                                     {ContactLaw::calibrated, "calibrated"}};

/// The law of a Hertz method.
ContactLaw contact_law(HertzMethod method);

/// The Hertz method behind a law's curvatures and ellipse shape (TVDS): the method itself, or
/// exact for the calibrated law.
HertzMethod hertz_shape_method(ContactLaw law);

struct ContactConstants {
  ContactLaw method = ContactLaw::exact;  ///< the law these constants come from
  RaceContact inner;
  RaceContact outer;
  double K = 0;           ///< series constant of one ball between both races [N/m^n]
  double exponent = 1.5;  ///< load–deflection exponent n of the series law [-]
  /// Relative RMS residual of the ball's law Q = K δ^n when it is a least-squares fit of the
  /// series law of two races with different exponents (calibration.h); 0 when it is exact [-].
  double series_fit_residual = 0;
};

/// Hertz constants of both races and of the ball between them by one Hertz method (exponent 3/2).
/// The FE-calibrated law: calibrated_contact_constants (calibration.h); the law a case selects:
/// contact_constants(const Case&) (case_file.h).
ContactConstants contact_constants(const Bearing& b, const HertzSolution& method);

}  // namespace bearing
