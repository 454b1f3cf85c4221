#pragma once
// Private to fem/modes/ (deal.II): the discrete elastic structure that the natural modes
// (elastic_modes.cc) and the harmonic responses (harmonic_response.cc) share — the mesh, the
// finite element, the stiffness and mass matrices, and the measurements on the seat and at the
// sensors. The mathematics is in elastic_problem.cc.

#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <mpi.h>

#include "modes/elastic_modes.h"
#include "modes/seat_fit.h"

namespace bearing::fem::modes {

using namespace dealii;
constexpr int dim = 3;

/// A deal.II point or tensor as seat_fit.h's Vec3.
inline Vec3 to_vec3(const Tensor<1, dim>& x) {
  return Vec3{{x[0], x[1], x[2]}};
}

/// The boundary point nearest a sensor, among the support points of the boundary faces, and the
/// process that owns its degrees of freedom.
struct SensorPoint {
  Point<dim> point;
  double distance = 0;
  std::array<types::global_dof_index, dim> dofs{};  ///< x, y, z (valid on `owner`)
  unsigned int owner = 0;
};

class ElasticProblem {
 public:
  ElasticProblem(const GmshMesh& mesh, const ElasticModesParameters& p, MPI_Comm comm);

  /// Builds the mesh, the finite element and the constraints; assembles K, M and the vectors
  /// below. Collective.
  void setup();

  // --- what setup() gives ------------------------------------------------------------------
  MPI_Comm comm;
  const ElasticModesParameters& prm;
  parallel::shared::Triangulation<dim> triangulation;
  std::unique_ptr<FESystem<dim>> fe;
  std::unique_ptr<Mapping<dim>> mapping;
  std::unique_ptr<Quadrature<dim>> cell_quadrature;
  std::unique_ptr<Quadrature<dim - 1>> face_quadrature;
  DoFHandler<dim> dof_handler;
  IndexSet owned, relevant;
  AffineConstraints<double> constraints;       ///< u = 0 on the fixed surfaces
  PETScWrappers::MPI::SparseMatrix stiffness;  ///< K; a constrained row: its diagonal alone
  PETScWrappers::MPI::SparseMatrix mass;       ///< M; a constrained row: all zero
  /// M r_d for the rigid translation r_d along x, y, z (all DoFs, no constraint): φᵀ(M r_d) is
  /// a mode's participation in a base motion along d [kg^1/2].
  std::array<PETScWrappers::MPI::Vector, dim> mass_translation;
  double volume = 0;             ///< [m³]
  double total_mass = 0;         ///< ∫ρ dV [kg]
  double diagonal = 0;           ///< the bounding box's diagonal L [m]
  Point<dim> centre;             ///< the bounding box's centre [m]
  SurfaceMoments seat;           ///< the seat's area and moments (whole seat, every process)
  unsigned long seat_nodes = 0;  ///< support points on the seat
  std::vector<SensorPoint> sensors;
  std::vector<types::boundary_id> seat_ids, fixed_ids;

  // --- measurements (collective) ------------------------------------------------------------
  /// A ghosted copy of an owned vector (for evaluation on the cells).
  PETScWrappers::MPI::Vector ghosted(const PETScWrappers::MPI::Vector& v) const;
  /// The seat's rigid fit of the displacement `u` (owned entries; seat_fit.h).
  RigidFit seat_fit(const PETScWrappers::MPI::Vector& u) const;
  /// The seat's rigid fits of several displacements at once (one sum across processes).
  std::vector<RigidFit> seat_fits(const std::vector<PETScWrappers::MPI::Vector>& u) const;
  /// The load vector of a unit force along `direction` spread uniformly over the seat (traction
  /// e_d / A), constrained entries zero: F_i = ∫_seat φ_i · e_d dA / A.
  PETScWrappers::MPI::Vector seat_load(unsigned int direction) const;
  /// Each sensor's displacement in each vector (every process gets them).
  std::vector<std::vector<Vec3>> sensor_values(
      const std::vector<PETScWrappers::MPI::Vector>& u) const;
  /// The rigid motions of the whole structure at the DoFs (translations x, y, z; rotations about
  /// x, y, z through the bounding box's centre [m per rad]).
  std::vector<PETScWrappers::MPI::Vector> rigid_motions() const;
  /// The field value(x, c) at the owned DoFs (x a DoF's support point, c its component).
  PETScWrappers::MPI::Vector dof_field(
      const std::function<double(const Point<dim>&, unsigned int)>& value) const;

 private:
  void make_grid();
  void setup_system();
  void assemble_system();
  void measure_seat();
  void find_sensors();

  const GmshMesh& mesh_;
};

}  // namespace bearing::fem::modes
