#pragma once
// Quantities with units in case files and on the command line: "15.081 mm", "2 um", "2000 rpm",
// "0.05 kN", "208 GPa", "30 deg". Everything inside the library is SI (m, rad, rad/s, N, Pa, kg,
// s).

#include <string>
#include <string_view>
#include <vector>

namespace bearing {

/// The physical dimension a field expects; it decides which units are accepted.
enum class Dimension {
  length,               ///< SI: m
  angle,                ///< SI: rad
  angular_speed,        ///< SI: rad/s
  force,                ///< SI: N
  pressure,             ///< SI: Pa (also elastic moduli)
  mass,                 ///< SI: kg
  density,              ///< SI: kg/m^3
  time,                 ///< SI: s
  frequency,            ///< SI: Hz
  damping,              ///< SI: N s/m
  mass_length,          ///< SI: kg m (unbalance: mass times eccentricity)
  velocity,             ///< SI: m/s (speed of sound)
  inertia,              ///< SI: kg m^2 (a ball's moment of inertia)
  moment,               ///< SI: N m (a moment of force, a torque: operation.moment)
  viscosity,            ///< SI: Pa s (a lubricant's dynamic viscosity)
  inverse_pressure,     ///< SI: 1/Pa (a pressure–viscosity coefficient)
  temperature,          ///< SI: K; "degC" too (an offset unit: 80 degC = 353.15 K)
  inverse_temperature,  ///< SI: 1/K (a viscosity–temperature coefficient)
  dimensionless,        ///< no unit
};

/// Name of the dimension for messages ("length", "angular speed", ...).
std::string_view dimension_name(Dimension dim);
/// The SI unit written in outputs ("m", "rad/s", ...; "" for dimensionless).
std::string_view si_unit(Dimension dim);
/// The units accepted for a dimension, in the spelling users should write.
std::vector<std::string> accepted_units(Dimension dim);
/// Whether a plain number (taken as SI) is accepted. Angles and speeds need a unit, because a bare
/// 30 or 2000 is as likely meant in degrees or rpm as in rad or rad/s; 0 is accepted for them.
bool bare_number_is_si(Dimension dim);

/// Factor that converts a value in `unit` to SI. Throws InputError naming `key` if the unit is
/// unknown or of another dimension, listing the accepted units.
double unit_factor(std::string_view unit, Dimension dim, const std::string& key);

/// `number` in `unit` converted to SI. Sub-multiples 10^-k are applied as a division by the exact
/// 10^k, so "10 um" is the double nearest 1e-5. Throws as unit_factor.
double to_si(double number, std::string_view unit, Dimension dim, const std::string& key);

/// Parses "<number> <unit>" (space optional) into SI. A string without a unit is accepted only for
/// dimensionless fields. Throws InputError naming `key`, the text and what is allowed.
double parse_quantity(std::string_view text, Dimension dim, const std::string& key);

/// Writes an SI value in the given unit with the fewest digits that parse back to within 2 ulp
/// (the unit factor itself may be inexact in binary, e.g. um, rpm, deg), e.g.
/// format_quantity(0.015081, "mm", Dimension::length) == "15.081 mm".
std::string format_quantity(double value_si, std::string_view unit, Dimension dim);

/// Shortest decimal text that parses back to `value` within 2 ulp ("0.015081", "2.08e+11").
std::string format_number(double value);

}  // namespace bearing
