#pragma once
// The closed forms the structure family (structure.cc) compares `bearing-fem modes` with, written
// here from the textbooks, independent of fem/:
//
// - the thin ring's in-plane flexural modes (inextensible, no shear, no rotary inertia; Hoppe 1871,
//   Love's Treatise §293): ω_n = √(EI/(ρA R⁴)) · n(n² − 1)/√(n² + 1), R the centroid radius;
// - the same ring as a Timoshenko curved beam (extension, shear with coefficient k, rotary
//   inertia): with u_r = U cos nθ, u_θ = V sin nθ and the section's rotation ψ = Ψ sin nθ, the
//   strains ε = (u_θ' + u_r)/R, γ = (u_r' − u_θ)/R − ψ, κ = ψ'/R give a 3 × 3 pencil per n,
//     K = EA/R² [1 n 0; n n² 0; 0 0 0] + EI n²/R² e₃e₃ᵀ + kGA g gᵀ,  g = (n/R, 1/R, 1),
//     M = ρ diag(A, A, I),
//   whose lowest eigenvalue is the flexural one (it tends to the thin ring's as h/R → 0);
// - Timoshenko's clamped-free beam: w'' and ψ from
//     EI ψ'' + kGA (w' − ψ) + ρI ω² ψ = 0,   kGA (w'' − ψ') + ρA ω² w = 0,
//   solutions e^{λx} with μ = λ² the roots of EI μ² + (EI q + ρIω²) μ + q (ρIω² − kGA) = 0,
//   q = ρAω²/(kGA): below the cut-off ω² < kGA/(ρI), one root μ₁ > 0 (cosh, sinh) and one
//   μ₂ < 0 (cos, sin). The four boundary conditions w = ψ = 0 at x = 0, ψ' = 0 and w' − ψ = 0 at
//   x = L make a 4 × 4 determinant whose zeros in ω are the frequencies, found by scanning and
//   bisection;
// - Cowper's shear coefficient of a rectangle, k = 10(1 + ν)/(12 + 11ν) (J. Appl. Mech. 1966).

#include <vector>

namespace bearing::verify::structure_reference {

/// A prismatic elastic beam or ring section: b × h, h in the plane of the motion [m]; E [Pa],
/// ν [-], ρ [kg/m³].
struct Section {
  double young, poisson, density, b, h;
  double area() const { return b * h; }
  double inertia() const { return b * h * h * h / 12; }
  double shear_modulus() const { return young / (2 * (1 + poisson)); }
};

/// Cowper's shear coefficient of a rectangle [-].
double cowper_rectangle(double poisson);

/// The thin ring's n-th in-plane flexural frequency, centroid radius R [m] [Hz].
double thin_ring_frequency(const Section& s, double radius, int n);

/// The Timoshenko ring's n-th in-plane flexural frequency, shear coefficient k [Hz].
double timoshenko_ring_frequency(const Section& s, double radius, int n, double k);

/// The first `count` frequencies of Timoshenko's clamped-free beam of length L [m], shear
/// coefficient k [Hz], ascending; bisected to 1e-13 relative.
std::vector<double> timoshenko_cantilever(const Section& s, double length, double k, int count);

/// The same of the Euler-Bernoulli beam (β L = 1.8751, 4.6941, …, from cos cosh = −1) [Hz].
std::vector<double> euler_bernoulli_cantilever(const Section& s, double length, int count);

}  // namespace bearing::verify::structure_reference
