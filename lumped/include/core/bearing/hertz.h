#pragma once
// Dimensionless Hertz point-contact solution as a function of the curvature difference F(ρ).
//
// For two bodies with principal curvatures ρ_I1, ρ_I2 (body I) and ρ_II1, ρ_II2 (body II) the
// contact ellipse has ellipticity κ = a/b solving
//     F(ρ) = [(κ²+1) E(e) − 2 K(e)] / [(κ²−1) E(e)],   e² = 1 − 1/κ²,
// with K, E the complete elliptic integrals. The dimensionless approach and semi-axes (Harris) are
//     δ* = (2K/π) (π / (2κ² E))^{1/3},  a* = (2κ² E / π)^{1/3},  b* = (2E / (πκ))^{1/3},
// so that with η = (1−ν₁²)/E₁ + (1−ν₂²)/E₂ and a load Q:
//     δ = δ* (Σρ/2) (3Qη / (2Σρ))^{2/3},  a = a* (3Qη / (2Σρ))^{1/3},  b = b* (3Qη / (2Σρ))^{1/3}.
// Three methods give (κ, K, E, δ*): exact, Hamrock–Brewe, and the Harris δ* table (seed 001).

#include <memory>
#include <string>
#include <string_view>

#include "bearing/choice.h"

namespace bearing {

struct HertzShape {
  double ellipticity = 1;  ///< κ = a/b ≥ 1 [-]
  double elliptic_K = 0;   ///< complete elliptic integral of the first kind K(e) [-]
  double elliptic_E = 0;   ///< complete elliptic integral of the second kind E(e) [-]
  double delta_star = 1;   ///< dimensionless approach δ* [-]
  double a_star = 1;       ///< dimensionless major semi-axis a* [-]
  double b_star = 1;       ///< dimensionless minor semi-axis b* [-]
};

/// The ways of obtaining the Hertz solution, by their case-file names.
enum class HertzMethod { exact, hamrock_brewe, harris_table };
inline constexpr Named<HertzMethod> kHertzMethods[] = {
    {HertzMethod::exact, "exact"},
    {HertzMethod::hamrock_brewe, "hamrock-brewe"},
    {HertzMethod::harris_table, "harris-table"}};

/// One way of obtaining the dimensionless Hertz solution from F(ρ) ∈ [0, 1).
class HertzSolution {
 public:
  virtual ~HertzSolution() = default;
  /// The solution at curvature difference `f_rho` ∈ [0, 1). Throws InputError outside it.
  virtual HertzShape shape(double f_rho) const = 0;
  /// Which method this is.
  virtual HertzMethod method() const = 0;
  /// The case-file name of the method ("exact", "hamrock-brewe", "harris-table").
  std::string_view name() const { return name_of(kHertzMethods, method()); }
};

/// Exact: κ by bracketed root finding on the F(ρ) equation, K and E from GSL.
std::unique_ptr<HertzSolution> make_exact_hertz();
/// Hamrock & Brewe (1983) curve fits in R_y/R_x = (1+F)/(1−F):
/// κ ≈ 1.0339 (R_y/R_x)^0.6360, E ≈ 1.0003 + 0.5968 R_x/R_y, K ≈ 1.5277 + 0.6023 ln(R_y/R_x).
std::unique_ptr<HertzSolution> make_hamrock_brewe_hertz();
/// Harris's δ*(F(ρ)) table as printed in seed 001 Table 1, interpolated; κ, K, E, a*, b* of the
/// exact solution (the table gives δ* only).
std::unique_ptr<HertzSolution> make_harris_table_hertz();

/// The method itself.
std::unique_ptr<HertzSolution> make_hertz_solution(HertzMethod method);

/// The method by case-file name; throws InputError naming `key` and listing the allowed names.
std::unique_ptr<HertzSolution> make_hertz_solution(std::string_view name,
                                                   const std::string& key = "model.contact");

/// δ*, a*, b* from κ, K(e), E(e) by the formulas above (shared by all methods).
HertzShape hertz_shape_from(double ellipticity, double elliptic_K, double elliptic_E);

}  // namespace bearing
