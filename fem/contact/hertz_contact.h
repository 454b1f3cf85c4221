#pragma once
// Finite-element reference for one ball–race Hertz contact (docs/model.md §9, issue 4 phase 1).
//
// The Hertz-reduced problem. Two elastic bodies touching at a point, with principal radii of
// relative curvature R_x (rolling direction) and R_y (transverse), behave — in the small-strain,
// frictionless, half-space limit Hertz's theory assumes — like ONE elastic half-space of contact
// modulus E* (1/E* = η = (1−ν₁²)/E₁ + (1−ν₂²)/E₂) pressed by a RIGID surface
//     z = s(x, y) − δ,    s(x, y) = x²/(2 R_x) + y²/(2 R_y),
// where δ is the approach of the two bodies. We give the block Poisson ratio ν (0.3) and Young's
// modulus E = (1−ν²)/η, so that E/(1−ν²) = E*: the frictionless normal problem depends on the
// block's elasticity only through E*, so this reproduces the two-body problem exactly.
//
// The block occupies z ≤ 0 with its free surface at z = 0. A surface point (x, y, 0) moves to
// z = u_z(x, y, 0), and may not enter the rigid body:
//     u_z(x, y, 0) ≤ G(x, y) := s(x, y) − δ        (G < 0 inside the geometric overlap).
// With the contact pressure p = −σ_zz ≥ 0 this is the Signorini problem
//     u_z ≤ G,   p ≥ 0,   p (G − u_z) = 0,   no shear traction on z = 0 (frictionless).
// Hertz's solution: an elliptic contact patch with semi-axes a (along y, the major axis) and b
// (along x), an ellipsoidal pressure p = p₀ √(1 − x²/b² − y²/a²), p₀ = 3F/(2πab), and
// F = K δ^{3/2} with the K of lumped's RaceContact (exact method).
//
// Symmetry: the problem is even in x and in y, so we solve on the quarter x ≥ 0, y ≥ 0 with
// u_x = 0 on x = 0 and u_y = 0 on y = 0; the bottom z = −L_z is clamped, the other sides are free.
// The total force is 4× the quarter's.
//
// This header has no deal.II types in its interface, so the command line and the tests include it
// without pulling in deal.II's headers; the class lives in hertz_contact.cc.

#include <string>
#include <vector>

#include <mpi.h>

namespace bearing::fem {

/// The real groove geometry (issue 4, item 3): a segment of the ring with its true groove,
/// meshed coarsely by gmsh from meshes/raceway_segment.geo (frame and parameters there) and
/// refined by the solver on the exact surfaces, pressed by a RIGID SPHERE of the ball's radius.
///
/// The ball's compliance is accounted for by the equivalent-modulus method: the ring gets the
/// contact modulus E* of ball and ring (E = (1−ν²)E*), as in the Hertz-reduced problem. For two
/// half-spaces (Hertz's limit) this is exact: the frictionless normal problem sees only E*. Beyond
/// it, the ring's exact surface and finite size are modelled, the ball's own (a sphere, far larger
/// than the contact) is not, and the ring's structural compliance away from the contact is
/// overstated by η/η_ring (2 for steel on steel).
///
/// The gap is measured along z (the load direction): G = z_sphere(x, y) − z_ring(x, y) at each
/// node of the raceway, with z_sphere = R − δ − √(R² − x² − y²) the sphere's lower surface after
/// the approach δ. Frictionless; the constraint is on u_z (a fixed direction, the usual
/// small-displacement linearisation: the tangential displacement's share of the gap change is
/// the surface slope times u_t, second order).
struct RacewaySegment {
  std::string coarse_mesh;   ///< .msh (version 2.2) written by gmsh from raceway_segment.geo
  bool outer = false;        ///< the outer ring (else the inner ring)
  double ball_radius = 0;    ///< R = D/2, the rigid sphere [m]
  double groove_radius = 0;  ///< r_g = f D [m]
  double groove_bottom = 0;  ///< R_b, groove-bottom radius from the bearing axis: d_i/2, d_o/2 [m]
  double back_radius = 0;    ///< bore radius (inner) or outside radius (outer): clamped [m]
  double half_width = 0;     ///< B/2 [m]
  double land_depth = 0;     ///< h, groove bottom to land, as meshed [m]
  bool paraboloid_gap = false;  ///< Hertz's paraboloid instead of the sphere and the true groove
                                ///< surface: isolates the effect of the ring's finite size
};

/// Completes `r` for a groove depth h = groove_depth (groove bottom to land) [m] and writes its
/// coarse mesh to `msh` by running gmsh on meshes/raceway_segment.geo (on rank 0 of `comm`; the
/// others wait), the segment spanning `segment_angle` [rad] from the contact. Needs
/// r.{outer, ball_radius, groove_radius, groove_bottom, back_radius, half_width}; sets
/// r.land_depth (smaller than h where the groove reaches the ring's side) and r.coarse_mesh.
/// gmsh's output goes to `log`. Throws std::runtime_error if gmsh fails (on rank 0 with the last
/// lines of gmsh's output).
void mesh_raceway_segment(RacewaySegment& r, double groove_depth, double segment_angle,
                          const std::string& msh, const std::string& log, MPI_Comm comm);

/// Everything that defines one contact computation. Units SI.
struct HertzContactParameters {
  // --- physics --------------------------------------------------------------------------------
  double contact_modulus = 0;      ///< E* = 1/η [Pa]
  double poisson = 0.3;            ///< ν of the block [-]; E = (1−ν²) E*
  double radius_x = 0;             ///< R_x, rolling direction (minor axis b along x) [m]
  double radius_y = 0;             ///< R_y, transverse direction (major axis a along y) [m]
  std::vector<double> approaches;  ///< approach steps δ_k > 0, increasing [m]
  /// "hertz": the Hertz-reduced block and paraboloid above; "groove": `raceway` (radius_x and
  /// radius_y then only name the paraboloid of RacewaySegment::paraboloid_gap).
  std::string geometry = "hertz";
  RacewaySegment raceway;

  // --- mesh design: the ellipse the mesh is stretched and refined to ---------------------------
  double design_semi_minor = 0;  ///< b at the largest load (analytic Hertz, design only) [m]
  double design_semi_major = 0;  ///< a at the largest load [m]
  double finest_cell_fraction = 1.0 / 16;  ///< finest cell size in x over b: h_x = b / N_b [-]
  double stretch = 2;  ///< cell aspect h_y / h_x everywhere (the coarse box is stretched) [-]
  double grading = 6;  ///< a cell at (stretched) distance d from the patch has size ≥ d / m [-]
  double patch_margin = 0.3;  ///< the finest patch covers (1 + margin) × the design semi-axes [-]
  double domain_size = 256;   ///< target L_x = L_z ≈ domain_size × a; L_y = stretch × L_x [-]
                              ///< (hertz only: the groove's domain is the ring segment)

  // --- solver --------------------------------------------------------------------------------
  unsigned int max_active_set_iterations = 60;
  double solver_tolerance = 1e-11;  ///< CG: relative to the right-hand side's norm [-]

  // --- output --------------------------------------------------------------------------------
  std::string vtu_directory;  ///< VTU/PVTU of every approach step here (empty: none); the folder
                              ///< must exist
  bool verbose = false;       ///< progress on rank 0's stdout
};

/// The solution at one approach step.
struct ApproachStep {
  double approach = 0;            ///< δ [m]
  double force = 0;               ///< total contact force F (4 × quarter) [N]
  double semi_major = 0;          ///< a from the pressure's second moment along y [m]
  double semi_minor = 0;          ///< b from the pressure's second moment along x [m]
  double semi_major_edge = 0;     ///< a from the active set's extent along the y axis [m]
  double semi_minor_edge = 0;     ///< b from the active set's extent along the x axis [m]
  double edge_spacing_major = 0;  ///< node spacing there: the edge estimate's ±uncertainty [m]
  double edge_spacing_minor = 0;
  double peak_pressure =
      0;  ///< nodal contact pressure at the centre (reaction / tributary area) [Pa]
  unsigned long active_nodes = 0;          ///< contact nodes in the quarter
  unsigned int active_set_iterations = 0;  ///< primal–dual active-set iterations (linear solves)
  unsigned int linear_iterations = 0;      ///< CG iterations, summed over those solves
};

/// A whole force–approach computation on one mesh.
struct HertzContactResult {
  std::vector<ApproachStep> steps;
  unsigned long cells = 0;
  unsigned long dofs = 0;
  double finest_cell_x = 0;  ///< h_x [m]
  double finest_cell_y = 0;  ///< h_y [m]
  double domain_x = 0;       ///< L_x = L_z [m]
  double domain_y = 0;       ///< L_y [m]
  unsigned int mpi_processes = 1;
  double wall_time = 0;  ///< [s]
};

/// Builds the mesh, then solves every approach step by the primal–dual active-set method.
/// Collective over `comm`; every rank gets the same result. Throws OutputError (bearing/errors.h)
/// on every rank if a VTU file cannot be written.
HertzContactResult solve_hertz_contact(const HertzContactParameters& parameters, MPI_Comm comm);

/// Least-squares power law F = K δ^n through (δ_k, F_k): the fit of ln F on ln δ.
struct PowerLawFit {
  double K = 0;               ///< [N/m^n]
  double exponent = 0;        ///< n [-]
  double K_three_halves = 0;  ///< K of the one-parameter fit with n fixed at 3/2 [N/m^1.5]
  double residual = 0;  ///< RMS of ln F − ln(K δ^n) over the points (≈ relative RMS error) [-]
  double residual_three_halves = 0;  ///< the same for the n = 3/2 fit [-]
};
PowerLawFit fit_power_law(const std::vector<double>& approach, const std::vector<double>& force);

}  // namespace bearing::fem
