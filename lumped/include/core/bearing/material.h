#pragma once
// Isotropic linear-elastic material of a ball or a ring.

#include <string>

namespace bearing {

struct Material {
  double young = 2.08e11;   ///< Young's modulus E [Pa] (Harris's bearing steel)
  double poisson = 0.3;     ///< Poisson ratio ν [-], in (−1, 0.5)
  double density = 7850.0;  ///< density [kg/m³]

  /// Throws InputError naming `where` (e.g. "material.ball") if a value is out of range.
  void validate(const std::string& where) const;
};

/// Hertz compliance η = (1−ν₁²)/E₁ + (1−ν₂²)/E₂ of two bodies in contact [1/Pa].
/// Johnson's contact modulus is E* = 1/η; Hamrock's reduced modulus is E' = 2/η.
double contact_compliance(const Material& a, const Material& b);

}  // namespace bearing
