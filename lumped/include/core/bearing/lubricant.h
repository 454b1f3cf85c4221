#pragma once
// The lubricant between the balls and the races (issue 43): what the EHL film of every contact
// (ehl_film.h) is computed from. In a case, the [lubricant] table; absent, the contacts are dry.
//
// Viscosity and temperature. The film depends on the dynamic viscosity η₀ at the contact's inlet
// temperature. Give it directly (`viscosity`, at the operating temperature), or give it at a
// reference temperature with Reynolds' exponential law
//     η₀(T) = η_ref exp(−β (T − T_ref)),
// β the viscosity–temperature coefficient [1/K] (Reynolds 1886). The law is a local fit: it holds
// within some ±20 K of T_ref for mineral oils (over a wider span their viscosity falls less
// steeply than an exponential; ASTM D341's Walther law is the usual choice there), so a T further
// than kTemperatureLawSpan from T_ref is refused rather than extrapolated.

#include <cmath>
#include <limits>

namespace bearing {

/// How far the operating temperature may lie from the reference one under Reynolds' law [K].
inline constexpr double kTemperatureLawSpan = 40.0;

struct Lubricant {
  /// Dynamic viscosity η₀ [Pa s] at atmospheric pressure: at the operating temperature, or at
  /// reference_temperature when a temperature law is given (the three keys below).
  double viscosity = 0.0;
  /// Pressure–viscosity coefficient α of Barus' law η = η₀ exp(α p) [1/Pa] (mineral oils
  /// 1–3e-8 1/Pa).
  double pressure_viscosity = 0.0;
  /// Composite RMS roughness of ball and race, σ = sqrt(σ_ball² + σ_race²) [m], for the film
  /// parameter Λ = h_min / σ.
  double roughness = 0.0;

  /// Reynolds' viscosity–temperature law: on when `temperature` is finite.
  double temperature = std::numeric_limits<double>::quiet_NaN();  ///< operating T [K]
  double reference_temperature =
      std::numeric_limits<double>::quiet_NaN();  ///< T_ref where η₀ = viscosity [K]
  double viscosity_temperature = 0.0;            ///< β [1/K], ≥ 0

  bool has_temperature_law() const { return std::isfinite(temperature); }

  /// η₀ at the operating temperature [Pa s]: `viscosity`, or Reynolds' law at `temperature`.
  double operating_viscosity() const;

  /// Throws InputError naming the `lubricant.*` key, its value and the allowed range for the first
  /// invalid field (see the limits in lubricant.cc).
  void validate() const;
};

}  // namespace bearing
