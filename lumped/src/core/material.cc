#include "bearing/material.h"

#include <cmath>

#include "bearing/errors.h"
#include "bearing/units.h"

namespace bearing {

void Material::validate(const std::string& where) const {
  if (!std::isfinite(young) || young <= 0)
    throw InputError(where + ".young = " + format_number(young) +
                     " Pa: must be a positive modulus (> 0 Pa)");
  if (!std::isfinite(poisson) || poisson <= -1.0 || poisson >= 0.5)
    throw InputError(where + ".poisson = " + format_number(poisson) +
                     ": Poisson ratio must lie in the open interval (-1, 0.5)");
  if (!std::isfinite(density) || density <= 0)
    throw InputError(where + ".density = " + format_number(density) +
                     " kg/m^3: must be positive (> 0)");
}

double contact_compliance(const Material& a, const Material& b) {
  return (1.0 - a.poisson * a.poisson) / a.young + (1.0 - b.poisson * b.poisson) / b.young;
}

}  // namespace bearing
