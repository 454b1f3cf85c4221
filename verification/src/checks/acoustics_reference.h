#pragma once
// The acoustics checks' references (docs/model.md §8), written independently of
// lumped/src/acoustics: the cylinders' Hankel functions from Bessel's and Schläfli's integrals (GSL
// quadrature, not GSL's Bessel routines the toolkit calls), their derivatives by the recurrence
// H_n' = (H_{n−1} − H_{n+1})/2 (the toolkit uses H₁' = H₀ − H₁/x), the spheres' fields from the
// elementary spherical Hankel functions, and seed 000's forms as printed in the check. Time
// dependence e^{iωt}; every field is per unit surface velocity [Pa/(m/s)].

#include <complex>

namespace bearing::verify::acoustic_reference {

using cd = std::complex<double>;

/// Air at 20 °C, 1 atm: the reference medium (the toolkit's comes through Context::air()).
constexpr double kDensity = 1.204;     ///< ρ₀ [kg/m^3]
constexpr double kSoundSpeed = 343.2;  ///< c₀ [m/s]
constexpr double kImpedance = kDensity * kSoundSpeed;

/// Requested accuracy of the Hankel quadratures: absolute on [0, π] (integrands ≤ 2), relative on
/// Schläfli's tail.
constexpr double kQuadratureTolerance = 1e-12;

/// Outgoing (second-kind) Hankel function H_n⁽²⁾(x) = J_n(x) − i Y_n(x), x > 0, n ≥ 0, from
///   J_n(x) = (1/π)∫₀^π cos(nτ − x sin τ) dτ,
///   Y_n(x) = (1/π)∫₀^π sin(x sin τ − nτ) dτ − (1/π)∫₀^∞ (e^{nt} + (−1)ⁿ e^{−nt}) e^{−x sinh t} dt.
cd hankel(int n, double x);
/// dH_n⁽²⁾/dx: −H₁ for n = 0, (H_{n−1} − H_{n+1})/2 otherwise.
cd hankel_derivative(int n, double x);

/// Spherical h_n⁽²⁾ for n = 0, 1 in closed form: h₀ = i e^{−ix}/x, h₁ = e^{−ix}(i − x)/x².
cd spherical_hankel(int n, double x);
/// Their derivatives, differentiated by hand: h₀' = e^{−ix}(1/x − i/x²),
/// h₁' = e^{−ix}(i/x + 2/x² − 2i/x³).
cd spherical_hankel_derivative(int n, double x);

/// A body of radius a with surface velocity uΘ radiates p = −iρ₀c₀ Θ h(kr)/h'(ka): order n = 0
/// breathing (Θ = 1), n = 1 translating (Θ = cos ψ). Arguments ka, kr (r ≥ a) and cos ψ.
cd cylinder_field(int order, double ka, double kr, double cos_angle);
cd sphere_field(int order, double ka, double kr, double cos_angle);

/// Low-ka limits (sources.h): cylinder dipole (π/2) ρ₀c₀ (ka)² cos ψ H₁(kr);
/// sphere dipole −(ρ₀c₀ (ka)² (a/r)/2) cos ψ (1 − i/(kr)) e^{−ikr}.
cd cylinder_dipole_low_ka(double ka, double kr, double cos_angle);
cd sphere_dipole_low_ka(double ka, double kr, double r_over_a, double cos_angle);

/// Seed 000 eq. (19) as derived (docs/model.md §8): the cylinder dipole with H₁(x) ≈ x/2 + 2i/(πx)
/// and H₁'(x) ≈ 1/2 − 2i/(πx²) for both ka and kr.
cd paper_cylinder_dipole(double ka, double kr, double cos_angle);
/// Seed 000 eq. (23): p = ρ₀c₀ k a² /(r √(1 + (ka)²)) e^{iθ}, θ = arctan(1/(ka)).
cd paper_pulsating_sphere(double ka, double r_over_a);

/// Truncation bounds at x ≤ 0.1, from the next terms of the series J₁ = x/2 − x³/16 + …,
/// Y₁ = −2/(πx) + (x/π)(ln(x/2) + γ − 1/2) + O(x³ ln x) (Abramowitz & Stegun 9.1.11):
/// - seed 000's small-argument H₁ and H₁' (they keep x/2 and 1/2) are each relatively wrong by
///   (x²/2)|ln(x/2) + γ ∓ 1/2| + O(x⁴) ≤ (x²/2)(|ln(x/2)| + 1);
/// - the leading term −2i/(πx²) alone of H₁' by |iπx²/4 + (x²/2)(ln(x/2) + γ + 1/2)| + O(x⁴ ln x)
///   ≤ (x²/2)(|ln(x/2)| + 2).
double small_argument_bound(double x);
double leading_order_bound(double x);

}  // namespace bearing::verify::acoustic_reference
