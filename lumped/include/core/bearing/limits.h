#pragma once
// The allowed range of each case key that more than one layer checks: written once here, checked
// by the case schema when a case is read and by the model, solver or kinematics that takes the
// value from code (ModelInputs, IntegratorSettings), so both enforce the same contract.

#include <limits>
#include <string>

#include "bearing/units.h"

namespace bearing {

struct Limit {
  const char* key;  ///< the case key, "rotor.mass"
  Dimension dim = Dimension::dimensionless;
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false, hi_open = false;
  const char* allowed = "";    ///< the rule in words, after "key = value: "
  const char* unit = nullptr;  ///< show the value in this unit ("rpm"); nullptr: SI

  /// Whether v lies in the range (never for NaN).
  bool contains(double v) const {
    return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
  /// Throws InputError "key = value unit: allowed" unless contains(v).
  void check(double v) const;
};

namespace limits {

constexpr double inf = std::numeric_limits<double>::infinity();
using D = Dimension;

inline constexpr Limit rotor_mass{
    "rotor.mass", D::mass, 0, inf, true, false, "must be positive (> 0 kg)"};
inline constexpr Limit rotor_damping{"rotor.damping", D::damping,    0, inf, false,
                                     false,           "must be >= 0"};
inline constexpr Limit rotor_axial_mass{"rotor.axial_mass",         D::mass, 0, inf, true, false,
                                        "must be positive (> 0 kg)"};
inline constexpr Limit rotor_axial_damping{"rotor.axial_damping", D::damping, 0, inf, false, false,
                                           "must be >= 0"};
inline constexpr Limit operation_speed{
    "operation.speed",
    D::angular_speed,
    0,
    inf,
    false,
    false,
    "must be >= 0 rpm (the inner ring turns counter-clockwise seen from +z)",
    "rpm"};
inline constexpr Limit operation_unbalance{
    "operation.unbalance", D::mass_length, 0, inf, false, false, "must be >= 0"};
inline constexpr Limit cage_slip{"cage.slip",
                                 D::dimensionless,
                                 0,
                                 1,
                                 false,
                                 true,
                                 "must lie in [0, 1) (0: pure rolling; 0.02: 2 %)"};
inline constexpr Limit cage_friction{
    "cage.friction", D::dimensionless, 0, 1, false, false, "must lie in [0, 1] (0: no friction)"};
inline constexpr Limit cage_slide_speed{"cage.slide_speed",        D::velocity, 0, 100, true, false,
                                        "must lie in (0, 100 m/s]"};
inline constexpr Limit ball_mass{"ball.mass", D::mass, 0, inf, true, false, "must be positive"};
inline constexpr Limit ball_inertia{"ball.inertia", D::inertia,        0, inf, true,
                                    false,          "must be positive"};
inline constexpr Limit ball_damping{"ball.damping", D::damping,    0, inf, false,
                                    false,          "must be >= 0"};
inline constexpr Limit solver_dt{"solver.dt",
                                 D::time,
                                 0,
                                 1e-3,
                                 true,
                                 false,
                                 "must lie in (0, 1 ms]; the Hertz contacts need a few us"};
inline constexpr Limit solver_tolerance{
    "solver.tolerance", D::dimensionless, 0, 0.1, true, false, "must lie in (0, 0.1]"};
inline constexpr Limit solver_max_displacement{
    "solver.max_displacement", D::length, 0, inf, true, false, "must be positive"};

inline constexpr Limit housing_mass{
    "housing.mass", D::mass, 0, inf, true, false, "must be positive (> 0 kg)"};
inline constexpr Limit housing_frequency{
    "housing.frequency", D::frequency, 0, inf, true, false, "must be positive (> 0 Hz)"};
inline constexpr Limit slip_rms{
    "slip.rms",
    D::dimensionless,
    0,
    0.1,
    false,
    false,
    "must lie in [0, 0.1] (the cage speed's RMS fluctuation as a fraction of its mean; 0: off, "
    "0.01: 1 %)"};
inline constexpr Limit slip_correlation_time{
    "slip.correlation_time",
    D::time,
    0,
    100,
    true,
    false,
    "must lie in (0, 100 s] (0 in the case file: one ball pass, the default)"};
inline constexpr Limit housing_damping_ratio{
    "housing.damping_ratio",
    D::dimensionless,
    0,
    1,
    false,
    true,
    "must lie in [0, 1) (an underdamped resonance; 0.05: 5 % of critical)"};

inline constexpr Limit lubricant_viscosity{
    "lubricant.viscosity",
    D::viscosity,
    1e-6,
    100,
    false,
    false,
    "must lie in [1e-6, 100] Pa s (water 1e-3, a mineral oil 0.005-0.5)"};
inline constexpr Limit lubricant_pressure_viscosity{
    "lubricant.pressure_viscosity",
    D::inverse_pressure,
    0,
    1e-7,
    true,
    false,
    "must lie in (0, 1e-7] 1/Pa (mineral oils 1e-8 to 3e-8 1/Pa)"};
inline constexpr Limit lubricant_roughness{
    "lubricant.roughness",
    D::length,
    0,
    1e-5,
    true,
    false,
    "must lie in (0, 10 um] (the composite RMS roughness of ball and race; ground races 0.05-0.2 "
    "um)"};
inline constexpr Limit lubricant_temperature{"lubricant.temperature",
                                             D::temperature,
                                             200,
                                             600,
                                             false,
                                             false,
                                             "must lie in [200, 600] K (-73 to 327 degC)"};
inline constexpr Limit lubricant_reference_temperature{
    "lubricant.reference_temperature",           D::temperature, 200, 600, false, false,
    "must lie in [200, 600] K (-73 to 327 degC)"};
inline constexpr Limit lubricant_viscosity_temperature{
    "lubricant.viscosity_temperature",
    D::inverse_temperature,
    0,
    0.2,
    false,
    false,
    "must lie in [0, 0.2] 1/K (mineral oils 0.02-0.06 1/K)"};

}  // namespace limits
}  // namespace bearing
