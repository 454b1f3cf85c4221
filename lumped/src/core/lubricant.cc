// The lubricant (lubricant.h): its operating viscosity and its ranges.

#include "bearing/lubricant.h"

#include <cmath>

#include "bearing/errors.h"
#include "bearing/limits.h"
#include "bearing/units.h"

namespace bearing {

double Lubricant::operating_viscosity() const {
  if (!has_temperature_law()) return viscosity;
  return viscosity * std::exp(-viscosity_temperature * (temperature - reference_temperature));
}

void Lubricant::validate() const {
  limits::lubricant_viscosity.check(viscosity);
  limits::lubricant_pressure_viscosity.check(pressure_viscosity);
  limits::lubricant_roughness.check(roughness);
  if (!has_temperature_law()) {
    if (std::isfinite(reference_temperature) || viscosity_temperature != 0.0)
      throw InputError(
          "lubricant.temperature is missing: reference_temperature and viscosity_temperature "
          "give Reynolds' law eta(T) = viscosity exp(-beta (T - T_ref)), which needs the "
          "operating temperature (or remove them: viscosity is then at the operating "
          "temperature)");
    return;
  }
  limits::lubricant_temperature.check(temperature);
  if (!std::isfinite(reference_temperature))
    throw InputError(
        "lubricant.reference_temperature is missing: with lubricant.temperature, viscosity is "
        "taken at reference_temperature and carried to the operating temperature by Reynolds' "
        "law (give it, with viscosity_temperature; or remove temperature)");
  limits::lubricant_reference_temperature.check(reference_temperature);
  limits::lubricant_viscosity_temperature.check(viscosity_temperature);
  if (std::fabs(temperature - reference_temperature) > kTemperatureLawSpan)
    throw InputError("lubricant.temperature = " + format_number(temperature) +
                     " K: lies more than " + format_number(kTemperatureLawSpan) +
                     " K from reference_temperature = " + format_number(reference_temperature) +
                     " K, beyond where Reynolds' exponential law holds; give the viscosity at a "
                     "nearer reference temperature");
  const double eta = operating_viscosity();
  if (!limits::lubricant_viscosity.contains(eta))
    throw InputError("lubricant.temperature = " + format_number(temperature) +
                     " K: the viscosity there, " + format_number(eta) +
                     " Pa s, leaves lubricant.viscosity's range (" +
                     limits::lubricant_viscosity.allowed + ")");
}

}  // namespace bearing
