#pragma once
// The seat's rigid motion in a mode shape (fem/README.md, "Natural modes"): the least-squares fit
// of a translation at the seat's centre and a small rotation to the displacement field over the
// seat surface S,
//     minimise  ∫_S |u(x) − t − θ × (x − c)|² dA,
// with c the area centroid of S. Because ∫_S (x − c) dA = 0, the normal equations decouple:
//     t = (1/A) ∫_S u dA                        (the area mean of u),
//     J θ = ∫_S (x − c) × u dA,   J = ∫_S (|r|² I − r rᵀ) dA,  r = x − c,
// J being the seat's polar "inertia" tensor (positive definite unless S lies on a line). The
// misfit left is ∫|u|² − A|t|² − θᵀJθ (the fit is an orthogonal projection), reported relative:
//     residual = sqrt(misfit / ∫|u|²)   (0: the seat moves rigidly).
// The fit is the L² projection of u onto the rigid motions of S, so it does not depend on how the
// seat is meshed, and its translation is exactly what a unit force spread uniformly over the seat
// (traction e/A) does work against: t·e = φᵀF for a mode φ, which is why the modal model of
// modes.json and a direct FE solve under that load agree (verification, structure.frf.*).
//
// Everything is a sum of integrals, so a processor sums its own faces and the sums are added
// across processors before the fit. Plain C++ (no deal.II): the elastic solver evaluates the
// integrals with its quadrature.

#include <array>
#include <string>
#include <vector>

namespace bearing::fem {

using Vec3 = std::array<double, 3>;

/// The seat surface's area and first and second moments (summable over pieces of it).
struct SurfaceMoments {
  double area = 0;                         ///< A [m²]
  Vec3 first{};                            ///< ∫ x dA [m³]
  std::array<Vec3, 3> second{};            ///< ∫ x_i x_j dA [m⁴]
  void add(double weight, const Vec3& x);  ///< a quadrature point: weight [m²], position [m]
  Vec3 centre() const;                     ///< c = first / area [m]
};

/// A displacement field's moments over the seat (summable over pieces of it).
struct FieldMoments {
  Vec3 mean{};        ///< ∫ u dA
  Vec3 moment{};      ///< ∫ x × u dA (about the origin)
  double square = 0;  ///< ∫ |u|² dA
  void add(double weight, const Vec3& x, const Vec3& u);
};

/// The rigid motion that fits a field best, and how well it fits.
struct RigidFit {
  Vec3 translation{};   ///< t, at the seat's centre [unit of u]
  Vec3 rotation{};      ///< θ, small rotation about x, y, z [unit of u per m]
  double residual = 0;  ///< sqrt(misfit / ∫|u|²) [-]; 0 for a zero field
};

/// Throws InputError when the seat cannot determine a rotation (its points on a line, or no
/// area): J's smallest eigenvalue below 1e-9 of its largest.
void check_seat_geometry(const SurfaceMoments& s, const std::string& name);

/// The fit of `f` over the surface `s` (both summed over the whole seat).
RigidFit fit_rigid_motion(const SurfaceMoments& s, const FieldMoments& f);

/// The moments as a flat vector (for an MPI sum) and back: 13 numbers for a surface, 7 a field.
std::vector<double> packed(const SurfaceMoments& s);
std::vector<double> packed(const FieldMoments& f);
SurfaceMoments surface_moments_from(const double* p);
FieldMoments field_moments_from(const double* p);

}  // namespace bearing::fem
