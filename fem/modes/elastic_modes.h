#pragma once
// Finite-element natural modes of an elastic structure (issue 40; fem/README.md, "Natural modes"):
// a housing or any body meshed by gmsh, 3-D small-strain isotropic elasticity,
//     find (ω, φ):  K φ = ω² M φ,
// with the mass-normalised shapes (φᵀMφ = 1), their seat participation (seat_fit.h), their
// values at named sensor points, and the harmonic response of the seat to a unit seat force by a
// direct solve. `bearing-fem modes` (app/modes.cc) calls it and writes modes.json.
//
// This header has no deal.II types in its interface, so the command line and the tests include it
// without deal.II's headers; the solver is elastic_modes.cc (and elastic_problem.cc,
// harmonic_response.cc).

#include <array>
#include <string>
#include <vector>

#include <mpi.h>

#include "mesh/gmsh_mesh.h"
#include "modes/seat_fit.h"

namespace bearing::fem {

/// Everything that defines one modal computation. Units SI.
struct ElasticModesParameters {
  double mesh_scale = 1;      ///< metres per mesh unit [m]
  double young = 0;           ///< E [Pa]
  double poisson = 0;         ///< ν [-], in [0, 0.5)
  double density = 0;         ///< ρ [kg/m³]
  std::vector<int> fixed;     ///< physical surfaces held (u = 0); empty: free-free
  int seat = 0;               ///< the physical surface of the bearing seat (its tag)
  std::string seat_name;      ///< its name (messages)
  std::vector<Vec3> sensors;  ///< sensor points [m]
  unsigned int count = 20;   ///< elastic modes wanted (at most); 0 with max_frequency: all below it
  double max_frequency = 0;  ///< [Hz]; > 0: no mode above it
  unsigned int degree = 2;   ///< polynomial degree of the finite element (1–3)
  unsigned int refinements = 0;  ///< global refinements of the mesh (each halves the cells' size)
  double tolerance = 1e-10;      ///< SLEPc's relative residual tolerance [-]
  std::vector<double> frf_frequencies;  ///< [Hz]: harmonic responses of the seat (none: empty)
  std::string vtu_file;                 ///< the shapes as VTU here (rank 0 writes it; empty: none)
  bool verbose = false;                 ///< progress on rank 0's stdout
};

/// The seat's harmonic response to a unit force along x and along y spread over the seat,
/// (K − ω²M) u = F, measured by the seat's rigid fit; undamped, so real.
struct HarmonicResponse {
  std::vector<double> frequencies;              ///< [Hz]
  std::array<std::vector<RigidFit>, 2> direct;  ///< load x, load y: one fit per frequency [m/N]
  bool has_static = false;                      ///< a fixed structure: K u = F solved too
  std::array<RigidFit, 2> static_response;      ///< ω = 0 [m/N]
};

/// The result; every process gets all of it.
struct ElasticModesResult {
  // --- the discretisation ------------------------------------------------------------------
  unsigned long cells = 0, vertices = 0, dofs = 0;
  unsigned int degree = 0;
  std::string cell_type;  ///< "tetrahedron" | "hexahedron"
  double volume = 0;      ///< [m³]
  double total_mass = 0;  ///< [kg]
  // --- the modes -----------------------------------------------------------------------------
  std::vector<double> frequencies;                    ///< [Hz], ascending, elastic modes only
  std::array<std::vector<double>, 3> effective_mass;  ///< (φᵀ M r_d)² for d = x, y, z [kg]
  std::vector<RigidFit> seat;                         ///< per mode [kg^-1/2], [rad kg^-1/2 m^-1]
  Vec3 seat_centre{};                                 ///< the seat's area centroid [m]
  double seat_area = 0;                               ///< [m²]
  unsigned long seat_nodes = 0;                       ///< support points on the seat
  struct Sensor {
    Vec3 point{};                    ///< the boundary support point used [m]
    double distance = 0;             ///< from the requested point [m]
    std::vector<Vec3> displacement;  ///< per mode [kg^-1/2]
  };
  std::vector<Sensor> sensors;
  unsigned int rigid_body_modes = 0;  ///< near-zero modes found and left out (6 free-free)
  double rigid_body_span = 0;  ///< free-free: the rigid motions' largest relative M-norm outside
                               ///< the span of the near-zero modes [-]
  std::string limited_by;      ///< "count" or "max_frequency"
  // --- the solver ----------------------------------------------------------------------------
  double orthogonality_mass = 0;       ///< max |ΦᵀMΦ − I| [-]
  double orthogonality_stiffness = 0;  ///< max |ΦᵀKΦ − diag(ω²)| / max ω² [-]
  double shift = 0;                    ///< σ of the shift-and-invert transformation [rad²/s²]
  double frequency_scale = 0;  ///< f_ref = √(E/ρ) / (2π L), L the bounding box's diagonal [Hz]
  double near_zero = 0;        ///< a mode below this is rigid: 1e-4 f_ref [Hz]
  double tolerance = 0;
  unsigned int eigensolves = 0;  ///< SLEPc solves (more than 1: max_frequency asked for more)
  HarmonicResponse frf;          ///< empty without frf_frequencies
  unsigned int mpi_processes = 1;
  double wall_time = 0;  ///< [s]
};

/// Solves the modes of `mesh` (scaled by p.mesh_scale) with the material and boundary of `p`.
/// Collective over `comm`. Throws InputError when the fixed surfaces leave rigid-body modes (or
/// a free-free structure has more than six), SolverError when SLEPc does not converge,
/// OutputError when the VTU cannot be written.
ElasticModesResult solve_elastic_modes(const GmshMesh& mesh, const ElasticModesParameters& p,
                                       MPI_Comm comm);

}  // namespace bearing::fem
