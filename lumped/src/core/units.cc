#include "bearing/units.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <utility>

#include "bearing/constants.h"
#include "bearing/errors.h"

namespace bearing {

namespace {

struct UnitEntry {
  const char* name;  // normalised spelling (see normalise())
  double factor;     // SI value of one unit
};

// Normalised spellings: spaces, '*', '·' and '^' removed, micro sign written 'u'.
const std::vector<UnitEntry>& table(Dimension dim) {
  static const std::vector<UnitEntry> length{{"m", 1.0},   {"cm", 1e-2}, {"mm", 1e-3},
                                             {"um", 1e-6}, {"nm", 1e-9}, {"in", 0.0254}};
  static const std::vector<UnitEntry> angle{{"rad", 1.0},
                                            {"deg", pi / 180.0},
                                            {"degree", pi / 180.0},
                                            {"degrees", pi / 180.0},
                                            {"°", pi / 180.0}};
  static const std::vector<UnitEntry> speed{{"rpm", two_pi / 60.0},     {"r/min", two_pi / 60.0},
                                            {"rev/min", two_pi / 60.0}, {"rad/s", 1.0},
                                            {"rev/s", two_pi},          {"Hz", two_pi}};
  static const std::vector<UnitEntry> force{
      {"N", 1.0}, {"kN", 1e3}, {"mN", 1e-3}, {"lbf", 4.4482216152605}};
  static const std::vector<UnitEntry> pressure{{"Pa", 1.0},
                                               {"kPa", 1e3},
                                               {"MPa", 1e6},
                                               {"GPa", 1e9},
                                               {"N/mm2", 1e6},
                                               {"N/m2", 1.0},
                                               {"psi", 6894.757293168361}};
  static const std::vector<UnitEntry> mass{{"kg", 1.0}, {"g", 1e-3}};
  static const std::vector<UnitEntry> density{{"kg/m3", 1.0}, {"g/cm3", 1e3}};
  static const std::vector<UnitEntry> time{{"s", 1.0}, {"ms", 1e-3}, {"us", 1e-6}, {"ns", 1e-9}};
  static const std::vector<UnitEntry> frequency{{"Hz", 1.0}, {"kHz", 1e3}};
  static const std::vector<UnitEntry> damping{
      {"Ns/m", 1.0}, {"kNs/m", 1e3}, {"kg/s", 1.0}, {"Ns/mm", 1e3}};
  static const std::vector<UnitEntry> mass_length{
      {"kgm", 1.0}, {"gmm", 1e-6}, {"gcm", 1e-5}, {"gm", 1e-3}};
  static const std::vector<UnitEntry> velocity{{"m/s", 1.0}, {"mm/s", 1e-3}, {"km/h", 1.0 / 3.6}};
  static const std::vector<UnitEntry> inertia{{"kgm2", 1.0}, {"gmm2", 1e-9}, {"gcm2", 1e-7}};
  static const std::vector<UnitEntry> moment{{"Nm", 1.0},
                                             {"kNm", 1e3},
                                             {"Nmm", 1e-3},
                                             {"mNm", 1e-3},
                                             {"lbfin", 0.1129848290276167},
                                             {"lbfft", 1.3558179483314004}};
  static const std::vector<UnitEntry> viscosity{
      {"Pas", 1.0}, {"mPas", 1e-3}, {"cP", 1e-3}, {"P", 0.1}, {"Ns/m2", 1.0}};
  static const std::vector<UnitEntry> inverse_pressure{
      {"1/Pa", 1.0}, {"1/MPa", 1e-6}, {"1/GPa", 1e-9}, {"m2/N", 1.0}, {"mm2/N", 1e-6}};
  // degC's offset: unit_offset().
  static const std::vector<UnitEntry> temperature{{"K", 1.0}, {"degC", 1.0}, {"°C", 1.0}};
  static const std::vector<UnitEntry> inverse_temperature{{"1/K", 1.0}};
  static const std::vector<UnitEntry> none{};
  switch (dim) {
    case Dimension::length:
      return length;
    case Dimension::angle:
      return angle;
    case Dimension::angular_speed:
      return speed;
    case Dimension::force:
      return force;
    case Dimension::pressure:
      return pressure;
    case Dimension::mass:
      return mass;
    case Dimension::density:
      return density;
    case Dimension::time:
      return time;
    case Dimension::frequency:
      return frequency;
    case Dimension::damping:
      return damping;
    case Dimension::mass_length:
      return mass_length;
    case Dimension::velocity:
      return velocity;
    case Dimension::inertia:
      return inertia;
    case Dimension::moment:
      return moment;
    case Dimension::viscosity:
      return viscosity;
    case Dimension::inverse_pressure:
      return inverse_pressure;
    case Dimension::temperature:
      return temperature;
    case Dimension::inverse_temperature:
      return inverse_temperature;
    case Dimension::dimensionless:
      return none;
  }
  return none;
}

std::string normalise(std::string_view unit) {
  std::string out;
  for (std::size_t i = 0; i < unit.size(); ++i) {
    const char c = unit[i];
    if (c == ' ' || c == '\t' || c == '*' || c == '^') continue;
    // UTF-8 middle dot U+00B7 (C2 B7) and dot operator U+22C5 (E2 8B 85): multiplication.
    if (static_cast<unsigned char>(c) == 0xC2 && i + 1 < unit.size() &&
        static_cast<unsigned char>(unit[i + 1]) == 0xB7) {
      ++i;
      continue;
    }
    if (unit.substr(i, 3) == "\xE2\x8B\x85") {
      i += 2;
      continue;
    }
    // Micro: U+00B5 (C2 B5) and Greek mu U+03BC (CE BC) are both written 'u'.
    if (unit.substr(i, 2) == "\xC2\xB5" || unit.substr(i, 2) == "\xCE\xBC") {
      out += 'u';
      ++i;
      continue;
    }
    out += c;
  }
  return out;
}

std::string join(const std::vector<std::string>& items) {
  std::string s;
  for (std::size_t i = 0; i < items.size(); ++i) s += (i ? ", " : "") + items[i];
  return s;
}

// The dimension a unit belongs to, if any other than `dim` knows it (for a clearer message).
const char* other_dimension(const std::string& unit, Dimension dim) {
  for (Dimension d :
       {Dimension::length, Dimension::angle, Dimension::angular_speed, Dimension::force,
        Dimension::pressure, Dimension::mass, Dimension::density, Dimension::time,
        Dimension::frequency, Dimension::damping, Dimension::mass_length, Dimension::velocity,
        Dimension::inertia, Dimension::moment, Dimension::viscosity, Dimension::inverse_pressure,
        Dimension::temperature, Dimension::inverse_temperature}) {
    if (d == dim) continue;
    for (const auto& e : table(d))
      if (unit == e.name) return dimension_name(d).data();
  }
  return nullptr;
}

}  // namespace

std::string_view dimension_name(Dimension dim) {
  switch (dim) {
    case Dimension::length:
      return "length";
    case Dimension::angle:
      return "angle";
    case Dimension::angular_speed:
      return "angular speed";
    case Dimension::force:
      return "force";
    case Dimension::pressure:
      return "pressure";
    case Dimension::mass:
      return "mass";
    case Dimension::density:
      return "density";
    case Dimension::time:
      return "time";
    case Dimension::frequency:
      return "frequency";
    case Dimension::damping:
      return "damping";
    case Dimension::mass_length:
      return "unbalance (mass times eccentricity)";
    case Dimension::velocity:
      return "speed";
    case Dimension::inertia:
      return "moment of inertia";
    case Dimension::moment:
      return "moment (torque)";
    case Dimension::viscosity:
      return "dynamic viscosity";
    case Dimension::inverse_pressure:
      return "pressure-viscosity coefficient (1/pressure)";
    case Dimension::temperature:
      return "temperature";
    case Dimension::inverse_temperature:
      return "viscosity-temperature coefficient (1/temperature)";
    case Dimension::dimensionless:
      return "dimensionless number";
  }
  return "?";
}

std::string_view si_unit(Dimension dim) {
  switch (dim) {
    case Dimension::length:
      return "m";
    case Dimension::angle:
      return "rad";
    case Dimension::angular_speed:
      return "rad/s";
    case Dimension::force:
      return "N";
    case Dimension::pressure:
      return "Pa";
    case Dimension::mass:
      return "kg";
    case Dimension::density:
      return "kg/m^3";
    case Dimension::time:
      return "s";
    case Dimension::frequency:
      return "Hz";
    case Dimension::damping:
      return "N s/m";
    case Dimension::mass_length:
      return "kg m";
    case Dimension::velocity:
      return "m/s";
    case Dimension::inertia:
      return "kg m^2";
    case Dimension::moment:
      return "N m";
    case Dimension::viscosity:
      return "Pa s";
    case Dimension::inverse_pressure:
      return "1/Pa";
    case Dimension::temperature:
      return "K";
    case Dimension::inverse_temperature:
      return "1/K";
    case Dimension::dimensionless:
      return "";
  }
  return "";
}

std::vector<std::string> accepted_units(Dimension dim) {
  switch (dim) {
    case Dimension::length:
      return {"m", "cm", "mm", "um", "nm", "in"};
    case Dimension::angle:
      return {"rad", "deg"};
    case Dimension::angular_speed:
      return {"rpm", "rad/s", "rev/s", "Hz"};
    case Dimension::force:
      return {"N", "kN", "mN", "lbf"};
    case Dimension::pressure:
      return {"Pa", "kPa", "MPa", "GPa", "N/mm^2", "psi"};
    case Dimension::mass:
      return {"kg", "g"};
    case Dimension::density:
      return {"kg/m^3", "g/cm^3"};
    case Dimension::time:
      return {"s", "ms", "us", "ns"};
    case Dimension::frequency:
      return {"Hz", "kHz"};
    case Dimension::damping:
      return {"N s/m", "kN s/m", "N s/mm", "kg/s"};
    case Dimension::mass_length:
      return {"kg m", "g mm", "g cm", "g m"};
    case Dimension::velocity:
      return {"m/s", "mm/s", "km/h"};
    case Dimension::inertia:
      return {"kg m^2", "g mm^2", "g cm^2"};
    case Dimension::moment:
      return {"N m", "kN m", "N mm", "lbf in", "lbf ft"};
    case Dimension::viscosity:
      return {"Pa s", "mPa s", "cP", "P"};
    case Dimension::inverse_pressure:
      return {"1/Pa", "1/MPa", "1/GPa", "m^2/N", "mm^2/N"};
    case Dimension::temperature:
      return {"K", "degC"};
    case Dimension::inverse_temperature:
      return {"1/K"};
    case Dimension::dimensionless:
      return {};
  }
  return {};
}

bool bare_number_is_si(Dimension dim) {
  // A bare 80 is as likely meant in degC as in K.
  return dim != Dimension::angle && dim != Dimension::angular_speed &&
         dim != Dimension::temperature;
}

namespace {

// The SI value of a unit's zero: 273.15 K for degC, 0 for every other unit.
double unit_offset(std::string_view unit, Dimension dim) {
  if (dim != Dimension::temperature) return 0.0;
  const std::string u = normalise(unit);
  return u == "degC" || u == "°C" ? 273.15 : 0.0;
}

}  // namespace

double unit_factor(std::string_view unit, Dimension dim, const std::string& key) {
  const std::string u = normalise(unit);
  if (dim == Dimension::dimensionless)
    throw InputError(key + ": \"" + std::string(unit) +
                     "\" is a unit, but this field is a dimensionless number: give a plain number");
  for (const auto& e : table(dim))
    if (u == e.name) return e.factor;
  std::string msg =
      key + ": unknown " + std::string(dimension_name(dim)) + " unit \"" + std::string(unit) + "\"";
  if (const char* other = other_dimension(u, dim))
    msg = key + ": \"" + std::string(unit) + "\" is a unit of " + other + ", but this field is " +
          (dim == Dimension::angle || dim == Dimension::angular_speed ? "an " : "a ") +
          std::string(dimension_name(dim));
  throw InputError(msg + "; accepted units: " + join(accepted_units(dim)));
}

double to_si(double number, std::string_view unit, Dimension dim, const std::string& key) {
  const double factor = unit_factor(unit, dim, key);
  const double inverse = std::round(1.0 / factor);
  const bool exact_inverse = factor < 1.0 && std::fabs(inverse * factor - 1.0) < 1e-15 &&
                             inverse <= 1e22 && std::fmod(inverse, 10.0) == 0.0;
  return (exact_inverse ? number / inverse : number * factor) + unit_offset(unit, dim);
}

double parse_quantity(std::string_view text, Dimension dim, const std::string& key) {
  const std::string s(text);
  const char* begin = s.c_str();
  while (*begin == ' ' || *begin == '\t') ++begin;
  char* end = nullptr;
  errno = 0;
  const double number = std::strtod(begin, &end);
  const std::string quoted = "\"" + s + "\"";
  if (end == begin)
    throw InputError(key + " = " + quoted + ": expected a number followed by a unit, e.g. \"" +
                     (dim == Dimension::dimensionless
                          ? std::string("0.52")
                          : "1.5 " + (accepted_units(dim).empty() ? std::string("")
                                                                  : accepted_units(dim).front())) +
                     "\"");
  if (errno == ERANGE || !std::isfinite(number))
    throw InputError(key + " = " + quoted + ": the number is not finite or out of range");
  // strtod also reads "inf", "nan" and hex floats; only plain decimals are meant here.
  for (const char* p = begin; p < end; ++p) {
    const char c = *p;
    if (!((c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-'))
      throw InputError(key + " = " + quoted + ": not a decimal number");
  }
  std::string_view unit(end);
  while (!unit.empty() && (unit.front() == ' ' || unit.front() == '\t')) unit.remove_prefix(1);
  while (!unit.empty() && (unit.back() == ' ' || unit.back() == '\t')) unit.remove_suffix(1);
  if (unit.empty()) {
    if (dim == Dimension::dimensionless) return number;
    if (!bare_number_is_si(dim) && number != 0.0)
      throw InputError(key + " = " + quoted + ": missing unit; an " +
                       std::string(dimension_name(dim)) +
                       " needs one because a bare number is ambiguous (accepted units: " +
                       join(accepted_units(dim)) + ")");
    if (bare_number_is_si(dim))
      throw InputError(key + " = " + quoted +
                       ": missing unit inside the string; write a plain "
                       "number for SI (" +
                       std::string(si_unit(dim)) + ") or add a unit (" + join(accepted_units(dim)) +
                       ")");
    return number;
  }
  // A power-of-ten unit shifts the decimal exponent of the text, so strtod rounds once and
  // "15.081 mm" is exactly the double nearest 0.015081.
  const double factor = unit_factor(unit, dim, key + " = " + quoted);
  const int k = static_cast<int>(std::lround(std::log10(factor)));
  double si = number * factor;
  if (std::fabs(factor / std::pow(10.0, k) - 1.0) < 1e-15) {
    std::string digits(begin, static_cast<const char*>(end));
    const auto e = digits.find_first_of("eE");
    const long exponent =
        e == std::string::npos ? 0 : std::strtol(digits.c_str() + e + 1, nullptr, 10);
    if (e != std::string::npos) digits.resize(e);
    // A finite number with an exponent this far beyond a double's has a zero mantissa
    // ("0e99999999999999999999", strtol's LONG_MAX) or as many digits: the product above is
    // exact or as good, and exponent + k could overflow.
    if (exponent >= -100000 && exponent <= 100000)
      si = std::strtod((digits + "e" + std::to_string(exponent + k)).c_str(), nullptr);
  }
  si += unit_offset(unit, dim);
  if (!std::isfinite(si))
    throw InputError(key + " = " + quoted + ": the value overflows when converted to SI");
  return si;
}

namespace {

// Shortest "%g" text of `value` whose parse, times `factor`, is within 2 ulp of `target`; plain
// (not exponent) notation for magnitudes from 1e-4 to 1e15 so 2000 reads "2000", not "2e+03".
std::string shortest(double value, double factor, double target) {
  char buf[64];
  const double magnitude = value == 0.0 ? 0.0 : std::floor(std::log10(std::fabs(value))) + 1;
  for (int precision = 1; precision <= 17; ++precision) {
    const int p =
        magnitude >= 1 && magnitude <= 15 ? std::max(precision, int(magnitude)) : precision;
    std::snprintf(buf, sizeof buf, "%.*g", p, value);
    const double back = std::strtod(buf, nullptr) * factor;
    if (std::fabs(back - target) <= 4.5e-16 * std::fabs(target)) break;
  }
  return buf;
}

}  // namespace

std::string format_number(double value) {
  return shortest(value, 1.0, value);
}

std::string format_quantity(double value_si, std::string_view unit, Dimension dim) {
  const double factor = unit_factor(unit, dim, "format_quantity");
  const double offset = unit_offset(unit, dim);
  if (offset != 0.0) {  // degC: 2 ulp of the kelvin value, not of the Celsius one
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", value_si - offset);
    return std::string(buf) + " " + std::string(unit);
  }
  return shortest(value_si / factor, factor, value_si) + " " + std::string(unit);
}

}  // namespace bearing
