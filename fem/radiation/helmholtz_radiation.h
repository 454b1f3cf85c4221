#pragma once
// Finite-element reference for sound radiation (docs/model.md §9, issue 6): the exterior Helmholtz
// problem around rigid bodies whose surfaces vibrate, truncated by a perfectly matched layer.
//
// Time dependence e^{iωt}, k = ω/c₀ (the convention of lumped's acoustics/sources.h). The sound
// pressure p solves, in the fluid outside the bodies,
//     Δp + k² p = 0,
// with the momentum equation iωρ₀ v = −∇p on each body's surface: a surface whose outward normal
// velocity is u·Θ (Θ = 1 breathing, Θ = n·d for a rigid body translating along d) gives
//     ∂p/∂n_body = −iωρ₀ u Θ,
// and p radiates outward (∝ e^{−ikr} far away). Planar problems (an infinite cylinder, or the
// 2-D section of a bearing: every body is a cylinder) live in the (x, y) plane; axisymmetric ones
// (a sphere on the axis, translating along it) in the meridian half-plane (x = distance from the
// axis ≥ 0, y = along the axis), with the weight x in every integral.
//
// This header has no deal.II types, so the command line and the tests include it without deal.II's
// headers; the solver (HelmholtzRadiation) and the mathematics of the layer are in
// helmholtz_radiation.cc.

#include <array>
#include <complex>
#include <string>
#include <vector>

#include <mpi.h>

#include "bearing/acoustics/sources.h"

namespace bearing::fem {

/// Planar (cylinders) or axisymmetric (bodies on the axis; the axis is the FE y-axis).
enum class RadiationGeometry { planar, axisymmetric };

/// A rigid circular body in the FE plane: a cylinder (planar) or a sphere (axisymmetric, centred
/// on the axis x = 0).
struct RadiatingBody {
  double x = 0, y = 0;     ///< centre [m]
  double radius = 0;       ///< a [m]
  bool breathing = false;  ///< surface velocity u everywhere (monopole); else a rigid translation
  /// Direction of the translation [rad] from +x towards +y (planar); axisymmetric bodies translate
  /// along +y (the axis) and this is ignored.
  double direction = 0;
};

/// One right-hand side: body `body` moves with unit velocity amplitude (1 m/s) as `breathing` or
/// translating along `direction`; every other body is rigid and still (a sound-hard scatterer).
struct SurfaceMotion {
  std::size_t body = 0;
  bool breathing = false;
  double direction = 0;  ///< [rad] from +x (planar; axisymmetric: along +y)
  std::string name;      ///< label in outputs ("ring-x", "ball3", …)
};

/// Everything the solver needs. Lengths in metres, frequencies in hertz.
struct HelmholtzParameters {
  RadiationGeometry geometry = RadiationGeometry::planar;
  std::vector<RadiatingBody> bodies;  ///< one: meshed as a polar grid; more: by gmsh
  std::vector<SurfaceMotion> motions;
  /// FE-plane points [m] in the fluid: inside the mesh, or beyond it (continued by outgoing modes).
  std::vector<std::array<double, 2>> microphones;
  std::vector<double> frequencies;  ///< [Hz], > 0
  Air air;
  unsigned int degree = 4;            ///< polynomial degree of the FE_Q elements (and the mapping)
  double cells_per_wavelength = 1.5;  ///< coarse cell size ≤ λ_min / this, λ_min = c₀/f_max
  double cells_per_radius = 4;        ///< coarse cells per body radius along its surface (≥ 4)
  unsigned int refinements = 0;       ///< global refinements of the coarse mesh
  /// R₀, radius of the meshed physical zone about the origin [m]; 0: max(1.25 × the bodies'
  /// extent, 1.1 × the farthest microphone within 3 × the extent), 1.5 × the extent if farther.
  double physical_radius = 0;
  double pml_thickness = 0;  ///< L [m]; 0: auto (min(λ_min/2, R₀/2))
  /// Coarse cells across the layer; 0: auto, the largest of 4, nγ at f_min (n = 1 planar, 2
  /// axisymmetric: one e-fold of the near field per cell) and L / (λ_min / cells_per_wavelength).
  unsigned int pml_layers = 0;
  double pml_attenuation = 12;  ///< σ₀: an outgoing wave decays by e^{−σ₀} across the layer
  std::string work_dir;         ///< gmsh's mesh file goes here (multi-body only)
  std::string vtu_dir;          ///< write one VTU per frequency here (empty: none)
  bool verbose = false;
};

/// The pressure at each microphone for each motion, per frequency.
struct HelmholtzResult {
  std::vector<double> frequencies;  ///< [Hz]
  /// pressure[f][m][i]: frequency f, motion m, microphone i [Pa per m/s of surface velocity].
  std::vector<std::vector<std::vector<std::complex<double>>>> pressure;
  unsigned int n_dofs = 0;                        ///< unknowns (real and imaginary parts)
  unsigned int n_cells = 0;                       ///< active cells
  double physical_radius = 0, pml_thickness = 0;  ///< R₀, L as used [m]
  unsigned int pml_layers = 0;                    ///< coarse cells across the layer, as used
  double largest_cell = 0;  ///< diameter of the largest cell in the physical zone [m]
  double wall_time = 0;     ///< [s]
  unsigned int mpi_processes = 1;
  std::vector<std::string> vtu_files;  ///< written by this process
};

/// Solves for every frequency and motion. Under MPI the frequencies are shared round-robin among
/// the processes, each solving its own on the whole (small, 2-D) mesh with a direct solver; the
/// results are then summed across processes, so every process returns the full result and it is
/// the serial one exactly. Throws InputError (bad parameters, a microphone inside a body, a
/// physical zone too small) or std::runtime_error (gmsh, solver).
HelmholtzResult solve_helmholtz(const HelmholtzParameters& p, MPI_Comm comm);

}  // namespace bearing::fem
