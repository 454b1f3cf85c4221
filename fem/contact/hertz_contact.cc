// The Hertz-reduced contact problem (see hertz_contact.h for the physics and the reduction).
//
// The solver is the same for every geometry (contact_geometry.h): the Hertz-reduced block and
// paraboloid below (HertzBlock, in this file), or the ring segment with its true groove pressed by
// a rigid sphere (raceway_segment.cc). The geometry supplies the coarse mesh with its boundary ids
// and manifolds, the depth below the contact surface (for the refinement) and the gap G; the
// rest — refinement toward the patch, assembly, the active set, the measurements — is shared.
// What the comments below say about "the block" and "the top surface z = 0" holds for the ring
// segment with "the groove surface" and the depth below it.
//
// Shape of a deal.II tutorial program: one class, HertzContactProblem, with make_grid /
// refine_grid / setup_system / assemble_system / solve / update_active_set / measure_contact /
// output_results / run. The numbers a user may change come in through HertzContactParameters
// (the command line fills it), not a ParameterHandler.
//
// ---------------------------------------------------------------------------------------------
// Weak form. Small-strain isotropic elasticity, no body force, displacement u in H¹ with
// u_x = 0 on x = 0, u_y = 0 on y = 0, u = 0 on the bottom z = −L_z:
//     a(u, v) = ∫ λ_L (∇·u)(∇·v) + 2μ ε(u):ε(v) dx = ∫_{z=0} −p v_z dA,
// with the Lamé constants λ_L = Eν/((1+ν)(1−2ν)), μ = E/(2(1+ν)). Discretised with trilinear Q1
// elements, the contact condition is imposed node by node on the top-surface vertical DoFs
// U_i = u_z(x_i, y_i, 0):
//     U_i ≤ G_i,   Λ_i ≥ 0,   Λ_i (G_i − U_i) = 0,        Λ := −(A U)_i  (the nodal reaction,
// the force the rigid surface exerts on node i, pointing down; A the stiffness matrix with the
// hanging-node constraints condensed).
//
// Primal–dual active set (Hintermüller, Ito & Kunisch 2002; step-41 of deal.II). Given a guess
// of the contact set 𝒜, solve the LINEAR problem with U_i = G_i on 𝒜 (inhomogeneous Dirichlet
// constraints) and Λ_i = 0 elsewhere, then update
//     𝒜 ← { i : Λ_i / m_i + c (U_i − G_i) > 0 },
// where m_i = ∫_{z=0} φ_i dA turns the nodal force into a pressure and c > 0 (a stiffness per
// area: E*/h) weighs penetration against pressure. Stop when 𝒜 no longer changes: the solution
// is then the exact solution of the discrete Signorini problem (no penalty parameter, no
// regularisation, no tolerance on the contact condition). PDAS is a semismooth Newton method for
// the complementarity function Λ − max(0, Λ + c(U − G)), so it converges superlinearly and, in
// practice, in a handful of iterations from the previous step's contact set. This is why we use
// it rather than a penalty (force error ∝ 1/penalty) or Nitsche (a stabilisation parameter to
// tune): the force it returns is exactly the discrete reaction.
//
// Each linear solve is SPD: CG with Trilinos ML algebraic multigrid, the three rigid translations
// given as near-null space. Under MPI the mesh is a p4est forest, the contact set of a node is
// decided by the process that owns the node and sent to the others as ghost values, so every
// process imposes the same constraints.
//
// Mesh. Hertz's ellipse has ellipticity κ = a/b ≈ 7–12 for these bearings. The coarse mesh is a
// box whose cells have aspect h_y/h_x = `stretch`, so every refinement of it keeps cells stretched
// along the major axis. The stretch is a compromise: the contact zone wants cells of aspect κ, the
// far field (a Boussinesq field, isotropic) wants cubes, and AMG-CG slows down as the aspect grows.
// Measured (README.md): stretch 2 beats κ/2 ≈ 4.8 both in error and in time. Cells are refined
// isotropically (p4est cannot refine
// anisotropically) while, in the stretched metric (x, y/stretch, z), their distance from the
// contact patch [0, (1+margin) b] × [0, (1+margin) a] is below `grading` × their size, and until
// h_x = b/N_b: a uniformly fine patch over the contact ellipse of the largest load, then cells
// growing geometrically with distance. That makes a domain of ~100 a cost a few thousand cells
// more than one of 10 a, so the block's finite size is pushed far away (its effect on the force is
// ∝ a/L; the study in README.md measures it).
// ---------------------------------------------------------------------------------------------

#include "hertz_contact.h"

#include "bearing/atomic_file_set.h"
#include "bearing/errors.h"
#include "contact_geometry.h"

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace bearing::fem {

using namespace dealii;

namespace {

constexpr int dim = 3;

// One vertical DoF on the contact surface that may come into contact (not a hanging node).
struct ContactNode {
  types::global_dof_index dof;
  Point<dim> p;  // undeformed position
  bool owned;
};

class HertzContactProblem {
 public:
  HertzContactProblem(const HertzContactParameters& parameters, MPI_Comm comm);
  HertzContactResult run();

 private:
  void make_grid();
  void refine_grid();
  void setup_system();
  void assemble_cell_matrices();
  void assemble_stiffness();
  void assemble_system();
  unsigned int solve();
  unsigned long update_active_set(double approach);
  ApproachStep measure_contact(double approach) const;
  void output_results(unsigned int step) const;

  double gap(const ContactNode& node, double approach) const {
    return geometry->gap(node.p, approach);
  }
  const FullMatrix<double>& cell_matrix(
      const typename DoFHandler<dim>::active_cell_iterator& cell) const {
    return geometry->cells_are_level_boxes() ? cell_matrix_of_level.at(cell->level())
                                             : cell_matrix_of_cell.at(cell->active_cell_index());
  }

  HertzContactParameters prm;
  std::unique_ptr<ContactGeometry> geometry;
  MPI_Comm comm;
  ConditionalOStream pcout;
  mutable TimerOutput timer;

  parallel::distributed::Triangulation<dim> triangulation;
  FESystem<dim> fe;
  DoFHandler<dim> dof_handler;
  IndexSet locally_owned_dofs;
  IndexSet locally_relevant_dofs;

  // Hanging nodes only / hanging nodes + symmetry + clamped bottom / those + the contact set.
  AffineConstraints<double> constraints_hanging;
  AffineConstraints<double> constraints_fixed;
  AffineConstraints<double> constraints_all;

  TrilinosWrappers::SparseMatrix stiffness;      // A with hanging nodes condensed: reactions
  TrilinosWrappers::SparseMatrix system_matrix;  // A with every constraint: the linear solve
  TrilinosWrappers::SparseMatrix fixed_matrix;   // A without the contact constraints: for the AMG
  TrilinosWrappers::PreconditionAMG amg;
  TrilinosWrappers::MPI::Vector system_rhs;
  TrilinosWrappers::MPI::Vector solution;      // locally owned, satisfies all constraints
  TrilinosWrappers::MPI::Vector reaction;      // −A U on locally owned DoFs (Λ at contact DoFs)
  TrilinosWrappers::MPI::Vector surface_mass;  // m_i = ∫_{z=0} φ_i dA (ghosted)

  std::vector<ContactNode> contact_nodes;  // locally relevant
  std::vector<char> active;                // per contact node, same on every process sharing it

  // Geometry of the mesh: domain, target and actual finest cell sizes near the contact.
  DomainSize domain;
  double target_hx = 0;
  double finest_hx = 0, finest_hy = 0;
  unsigned int refinement_levels = 0;
  std::map<unsigned int, FullMatrix<double>> cell_matrix_of_level;  // level boxes
  std::map<unsigned int, FullMatrix<double>> cell_matrix_of_cell;   // by active cell index
};

HertzContactProblem::HertzContactProblem(const HertzContactParameters& parameters, MPI_Comm comm_)
    : prm(parameters),
      comm(comm_),
      pcout(std::cout, parameters.verbose && Utilities::MPI::this_mpi_process(comm_) == 0),
      timer(comm_, pcout, parameters.verbose ? TimerOutput::summary : TimerOutput::never,
            TimerOutput::wall_times),
      triangulation(comm_),
      fe(FE_Q<dim>(1), dim),
      dof_handler(triangulation) {
  if (!(prm.contact_modulus > 0 && prm.radius_x > 0 && prm.radius_y > 0 &&
        prm.design_semi_minor > 0 && prm.design_semi_major > 0 && !prm.approaches.empty()))
    throw std::invalid_argument(
        "HertzContactParameters: moduli, radii, design semi-axes and "
        "approach steps must be positive");
  if (!(prm.poisson > -1 && prm.poisson < 0.5))
    throw std::invalid_argument("HertzContactParameters: poisson must lie in (-1, 0.5)");
  if (!(prm.finest_cell_fraction > 0 && prm.stretch >= 1 && prm.grading >= 1 &&
        prm.domain_size > 2))
    throw std::invalid_argument("HertzContactParameters: mesh parameters out of range");
  if (prm.geometry == "hertz")
    geometry = make_hertz_block(prm);
  else if (prm.geometry == "groove")
    geometry = make_raceway_segment(prm);
  else
    throw std::invalid_argument("HertzContactParameters: geometry \"" + prm.geometry +
                                "\" (allowed: hertz, groove)");
}

// ---------------------------------------------------------------------------------------------
// The Hertz-reduced block. Coarse mesh: 2 × 2 × 2 cells of size H × (stretch·H) × H covering
// [0, L_x] × [0, L_y] × [−L_z, 0], with L_x = L_z = 2H and L_y = stretch·L_x. H is the finest
// cell size h_x = b/N_b times 2^R, R chosen so that L_x ≥ domain_size · a.
class HertzBlock final : public ContactGeometry {
 public:
  explicit HertzBlock(const HertzContactParameters& p) : prm(p) {
    const double finest = prm.finest_cell_fraction * prm.design_semi_minor;
    const double target = prm.domain_size * prm.design_semi_major;
    levels = static_cast<unsigned int>(std::max(0.0, std::ceil(std::log2(target / (2 * finest)))));
    hx = finest * std::ldexp(1.0, static_cast<int>(levels));
  }
  DomainSize make_coarse_grid(parallel::distributed::Triangulation<dim>& tria) const override {
    const DomainSize d{2 * hx, 2 * prm.stretch * hx, 2 * hx};
    GridGenerator::subdivided_hyper_rectangle(tria, {2u, 2u, 2u}, Point<dim>(0, 0, -d.z),
                                              Point<dim>(d.x, d.y, 0), /*colorize=*/true);
    // Colorized ids: 0/1 x min/max, 2/3 y min/max, 4 z min (the bottom: clamped), 5 z max (the
    // surface: contact) — the ids of namespace boundary.
    return d;
  }
  unsigned int levels_to(double) const override { return levels; }
  bool cells_are_level_boxes() const override { return true; }
  double gap(const Point<dim>& p, double approach) const override {
    return p[0] * p[0] / (2 * prm.radius_x) + p[1] * p[1] / (2 * prm.radius_y) - approach;
  }
  std::string describe() const override {
    return "Hertz-reduced: quarter block with E = (1-nu^2) E*, rigid paraboloid "
           "z = x^2/2R_x + y^2/2R_y - delta";
  }

 private:
  HertzContactParameters prm;
  unsigned int levels = 0;
  double hx = 0;  // coarse cell size in x (and z)
};

void HertzContactProblem::make_grid() {
  target_hx = prm.finest_cell_fraction * prm.design_semi_minor;
  domain = geometry->make_coarse_grid(triangulation);
  refinement_levels = geometry->levels_to(target_hx);
}

// Refinement toward the contact patch: repeat "refine every cell closer (in the stretched metric)
// than `grading` × its own size to the patch, unless it is already as fine as h_x" until no cell
// is flagged. Distances are measured from the cell's box, so the whole patch becomes fine.
void HertzContactProblem::refine_grid() {
  TimerOutput::Scope t(timer, "make and refine grid");
  const double patch_x = (1 + prm.patch_margin) * prm.design_semi_minor;
  const double patch_y = (1 + prm.patch_margin) * prm.design_semi_major;
  for (unsigned int sweep = 0; sweep <= refinement_levels + 2; ++sweep) {
    unsigned int flagged = 0;
    for (const auto& cell : triangulation.active_cell_iterators()) {
      if (!cell->is_locally_owned()) continue;
      const BoundingBox<dim> box = cell->bounding_box();
      const Point<dim> lo = box.get_boundary_points().first, hi = box.get_boundary_points().second;
      const double hx = hi[0] - lo[0];
      if (hx < 1.5 * target_hx) continue;
      const double dx = std::max(0.0, lo[0] - patch_x);
      const double dy = std::max(0.0, lo[1] - patch_y) / prm.stretch;
      double depth = std::numeric_limits<double>::max();
      for (const unsigned int v : cell->vertex_indices())
        depth = std::min(depth, geometry->depth(cell->vertex(v)));
      const double dz = std::max(0.0, depth);
      if (std::sqrt(dx * dx + dy * dy + dz * dz) < prm.grading * hx) {
        cell->set_refine_flag();
        ++flagged;
      }
    }
    if (Utilities::MPI::sum(flagged, comm) == 0) break;
    triangulation.execute_coarsening_and_refinement();
  }
  // The finest cells (at the contact patch): their sizes enter the semi-axis correction.
  double hx = std::numeric_limits<double>::max(), hy = hx;
  for (const auto& cell : triangulation.active_cell_iterators()) {
    if (!cell->is_locally_owned()) continue;
    const BoundingBox<dim> box = cell->bounding_box();
    const auto [lo, hi] = box.get_boundary_points();
    hx = std::min(hx, hi[0] - lo[0]);
    hy = std::min(hy, hi[1] - lo[1]);
  }
  finest_hx = Utilities::MPI::min(hx, comm);
  finest_hy = Utilities::MPI::min(hy, comm);
}

// ---------------------------------------------------------------------------------------------
// DoFs, the fixed constraints (hanging nodes; u_x = 0 on x = 0, u_y = 0 on y = 0; u = 0 at the
// bottom), the matrices' sparsity pattern, the list of contact candidates on z = 0, and the
// surface "mass" m_i = ∫_{z=0} φ_i dA that converts a nodal reaction into a pressure.
void HertzContactProblem::setup_system() {
  TimerOutput::Scope t(timer, "setup system");
  dof_handler.distribute_dofs(fe);
  locally_owned_dofs = dof_handler.locally_owned_dofs();
  locally_relevant_dofs = DoFTools::extract_locally_relevant_dofs(dof_handler);

  constraints_hanging.clear();
  constraints_hanging.reinit(locally_relevant_dofs);
  DoFTools::make_hanging_node_constraints(dof_handler, constraints_hanging);
  constraints_hanging.close();

  constraints_fixed.clear();
  constraints_fixed.reinit(locally_relevant_dofs);
  constraints_fixed.merge(constraints_hanging);
  const FEValuesExtractors::Scalar ux(0), uy(1);
  VectorTools::interpolate_boundary_values(dof_handler, boundary::symmetry_x,
                                           Functions::ZeroFunction<dim>(dim), constraints_fixed,
                                           fe.component_mask(ux));
  VectorTools::interpolate_boundary_values(dof_handler, boundary::symmetry_y,
                                           Functions::ZeroFunction<dim>(dim), constraints_fixed,
                                           fe.component_mask(uy));
  VectorTools::interpolate_boundary_values(dof_handler, boundary::clamped,
                                           Functions::ZeroFunction<dim>(dim), constraints_fixed);
  constraints_fixed.close();

  // One pattern for both matrices: the hanging-node-condensed pattern keeps every entry the
  // Dirichlet-type constraints could need (they only remove couplings).
  DynamicSparsityPattern dsp(locally_relevant_dofs);
  DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints_hanging, /*keep_constrained=*/true);
  SparsityTools::distribute_sparsity_pattern(dsp, locally_owned_dofs, comm, locally_relevant_dofs);
  stiffness.reinit(locally_owned_dofs, locally_owned_dofs, dsp, comm);
  system_matrix.reinit(locally_owned_dofs, locally_owned_dofs, dsp, comm);
  fixed_matrix.reinit(locally_owned_dofs, locally_owned_dofs, dsp, comm);
  system_rhs.reinit(locally_owned_dofs, comm);
  solution.reinit(locally_owned_dofs, comm);
  reaction.reinit(locally_owned_dofs, comm);

  // Contact candidates: vertical DoFs of the vertices of top faces of owned and ghost cells.
  std::map<types::global_dof_index, ContactNode> nodes;
  for (const auto& cell : dof_handler.active_cell_iterators()) {
    if (cell->is_artificial()) continue;
    for (const auto& face : cell->face_iterators()) {
      if (!face->at_boundary() || face->boundary_id() != boundary::contact) continue;
      for (unsigned int v = 0; v < face->n_vertices(); ++v) {
        const auto dof = face->vertex_dof_index(v, 2);
        if (constraints_hanging.is_constrained(dof)) continue;
        const Point<dim> p = face->vertex(v);
        nodes.emplace(dof, ContactNode{dof, p, locally_owned_dofs.is_element(dof)});
      }
    }
  }
  contact_nodes.clear();
  for (const auto& [dof, node] : nodes) contact_nodes.push_back(node);
  active.assign(contact_nodes.size(), 0);

  // m_i by 2×2 Gauss quadrature on the top faces of owned cells, condensed like the matrix.
  TrilinosWrappers::MPI::Vector mass(locally_owned_dofs, comm);
  const QGauss<dim - 1> face_quadrature(2);
  FEFaceValues<dim> fe_face(fe, face_quadrature, update_values | update_JxW_values);
  Vector<double> cell_mass(fe.n_dofs_per_cell());
  std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
  for (const auto& cell : dof_handler.active_cell_iterators()) {
    if (!cell->is_locally_owned()) continue;
    for (const auto f : cell->face_indices()) {
      if (!cell->face(f)->at_boundary() || cell->face(f)->boundary_id() != boundary::contact)
        continue;
      fe_face.reinit(cell, f);
      cell_mass = 0;
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i) {
        if (fe.system_to_component_index(i).first != 2) continue;
        for (unsigned int q = 0; q < face_quadrature.size(); ++q)
          cell_mass(i) += fe_face.shape_value(i, q) * fe_face.JxW(q);
      }
      cell->get_dof_indices(dofs);
      constraints_hanging.distribute_local_to_global(cell_mass, dofs, mass);
    }
  }
  mass.compress(VectorOperation::add);
  surface_mass.reinit(locally_owned_dofs, locally_relevant_dofs, comm);
  surface_mass = mass;
}

// ---------------------------------------------------------------------------------------------
// Every cell is an axis-parallel box, a coarse cell divided by 2^level in each direction, so the
// element stiffness matrix depends on the level only. We compute it once per level on a reference
// box of exactly that size (the same numbers on every process, whatever cells it owns):
//     A^K_ij = ∫_K λ_L (∇·φ_i)(∇·φ_j) + 2μ ε(φ_i):ε(φ_j) dx,   2×2×2 Gauss points (exact for Q1).
void HertzContactProblem::assemble_cell_matrices() {
  TimerOutput::Scope t(timer, "element matrices");
  const double E = (1 - prm.poisson * prm.poisson) * prm.contact_modulus;
  const double nu = prm.poisson;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double mu = E / (2 * (1 + nu));
  const QGauss<dim> quadrature(2);
  const FEValuesExtractors::Vector u(0);
  const unsigned int n = fe.n_dofs_per_cell();
  const auto element_matrix = [&](FEValues<dim>& fe_values) {
    FullMatrix<double> A(n, n);
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      for (unsigned int i = 0; i < n; ++i) {
        const auto eps_i = fe_values[u].symmetric_gradient(i, q);
        const double div_i = fe_values[u].divergence(i, q);
        for (unsigned int j = 0; j < n; ++j) {
          const auto eps_j = fe_values[u].symmetric_gradient(j, q);
          const double div_j = fe_values[u].divergence(j, q);
          A(i, j) +=
              (lambda * div_i * div_j + 2 * mu * scalar_product(eps_i, eps_j)) * fe_values.JxW(q);
        }
      }
    return A;
  };
  if (!geometry->cells_are_level_boxes()) {  // curved or distorted cells: one matrix per cell
    FEValues<dim> fe_values(fe, quadrature, update_gradients | update_JxW_values);
    for (const auto& cell : dof_handler.active_cell_iterators()) {
      if (!cell->is_locally_owned()) continue;
      fe_values.reinit(cell);
      cell_matrix_of_cell.emplace(cell->active_cell_index(), element_matrix(fe_values));
    }
    return;
  }
  // Boxes: the 2 × 2 × 2 coarse cells of the block divided by 2^level.
  std::set<unsigned int> levels;
  for (const auto& cell : triangulation.active_cell_iterators())
    if (cell->is_locally_owned()) levels.insert(cell->level());
  for (const unsigned int level : levels) {
    if (cell_matrix_of_level.count(level)) continue;
    const double scale = std::ldexp(1.0, -static_cast<int>(level));
    Triangulation<dim> box;
    GridGenerator::hyper_rectangle(
        box, Point<dim>(0, 0, 0),
        Point<dim>(domain.x / 2 * scale, domain.y / 2 * scale, domain.z / 2 * scale));
    DoFHandler<dim> box_dofs(box);
    box_dofs.distribute_dofs(fe);
    // A fresh FEValues per box: it must not compare this cell with one of a destroyed mesh.
    FEValues<dim> fe_values(fe, quadrature, update_gradients | update_JxW_values);
    fe_values.reinit(box_dofs.begin_active());
    cell_matrix_of_level.emplace(level, element_matrix(fe_values));
  }
}

// The stiffness with only the hanging nodes condensed. With it, A U at a contact DoF is the
// reaction −Λ_i of the converged solution (rows of constrained DoFs are not used).
// Also the stiffness with the fixed constraints (no contact set) and its algebraic multigrid:
// the matrices of the active-set iterations differ from it only in the rows and columns of the
// contact nodes (replaced by a diagonal), a modification of rank ≤ the number of contact nodes,
// so one AMG hierarchy per mesh preconditions all of them (CG needs a few more iterations than
// with a fresh hierarchy, but the setup, which costs as much as a solve, is paid once).
void HertzContactProblem::assemble_stiffness() {
  TimerOutput::Scope t(timer, "assemble stiffness + AMG setup");
  stiffness = 0;
  fixed_matrix = 0;
  std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
  for (const auto& cell : dof_handler.active_cell_iterators()) {
    if (!cell->is_locally_owned()) continue;
    cell->get_dof_indices(dofs);
    const auto& A = cell_matrix(cell);
    constraints_hanging.distribute_local_to_global(A, dofs, stiffness);
    constraints_fixed.distribute_local_to_global(A, dofs, fixed_matrix);
  }
  stiffness.compress(VectorOperation::add);
  fixed_matrix.compress(VectorOperation::add);

  // Trilinos ML, smoothed aggregation, the rigid translations as near-null space (deal.II 9.4
  // cannot pass the rotations to ML), two Chebyshev sweeps.
  std::vector<std::vector<bool>> constant_modes;
  DoFTools::extract_constant_modes(dof_handler, ComponentMask(), constant_modes);
  TrilinosWrappers::PreconditionAMG::AdditionalData data;
  data.constant_modes = constant_modes;
  data.elliptic = true;
  data.higher_order_elements = false;
  data.smoother_sweeps = 2;
  data.aggregation_threshold = 0.02;
  amg.initialize(fixed_matrix, data);
}

// The linear system of one active-set iteration: every constraint (hanging nodes, symmetry,
// clamped bottom, and U_i = G_i on the contact set) eliminated while assembling, so the
// inhomogeneities G_i appear on the right-hand side.
void HertzContactProblem::assemble_system() {
  TimerOutput::Scope t(timer, "assemble system");
  system_matrix = 0;
  system_rhs = 0;
  const unsigned int n = fe.n_dofs_per_cell();
  Vector<double> cell_rhs(n);
  std::vector<types::global_dof_index> dofs(n);
  for (const auto& cell : dof_handler.active_cell_iterators()) {
    if (!cell->is_locally_owned()) continue;
    cell->get_dof_indices(dofs);
    constraints_all.distribute_local_to_global(cell_matrix(cell), cell_rhs, dofs, system_matrix,
                                               system_rhs);
  }
  system_matrix.compress(VectorOperation::add);
  system_rhs.compress(VectorOperation::add);
}

// CG preconditioned by the mesh's AMG, started from the previous solution. The tolerance is
// tight (1e-11 of ‖b‖ by default) because the serial and the parallel runs must agree on K to
// 1e-8. Returns the number of CG iterations.
unsigned int HertzContactProblem::solve() {
  TimerOutput::Scope t(timer, "solve (CG)");
  SolverControl control(5000, prm.solver_tolerance * system_rhs.l2_norm());
  SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
  constraints_all.set_zero(solution);
  cg.solve(system_matrix, solution, system_rhs, amg);
  constraints_all.distribute(solution);
  return control.last_step();
}

// One primal–dual active-set update for approach δ: reactions Λ = −A U, then the new contact set
// from Λ_i/m_i + c (U_i − G_i) > 0, decided by the owner of each node and exchanged as ghost
// values. Rebuilds constraints_all. Returns the number of nodes whose status changed (all
// processes). On the first call of a step, pass through with the current set (see run()).
unsigned long HertzContactProblem::update_active_set(double approach) {
  TimerOutput::Scope t(timer, "active-set update");
  stiffness.vmult(reaction, solution);
  reaction *= -1.0;
  const double c = prm.contact_modulus / finest_hx;

  TrilinosWrappers::MPI::Vector flags(locally_owned_dofs, comm);
  unsigned long changed = 0;
  for (std::size_t k = 0; k < contact_nodes.size(); ++k) {
    const ContactNode& node = contact_nodes[k];
    if (!node.owned) continue;
    const double pressure = reaction(node.dof) / surface_mass(node.dof);
    const bool now = pressure + c * (solution(node.dof) - gap(node, approach)) > 0;
    if (now != static_cast<bool>(active[k])) ++changed;
    flags(node.dof) = now ? 1.0 : 0.0;
  }
  flags.compress(VectorOperation::insert);
  TrilinosWrappers::MPI::Vector ghosted(locally_owned_dofs, locally_relevant_dofs, comm);
  ghosted = flags;
  for (std::size_t k = 0; k < contact_nodes.size(); ++k)
    active[k] = ghosted(contact_nodes[k].dof) > 0.5;
  return Utilities::MPI::sum(changed, comm);
}

// ---------------------------------------------------------------------------------------------
// What we measure at a converged step (Λ_i = reaction at the active nodes):
//   force      F = 4 Σ Λ_i (the quarter's reaction, times 4);
//   semi-axes  from the second moments of the pressure. For Hertz's ellipsoidal pressure
//              ∫ p x² dA / ∫ p dA = b²/5 and ∫ p y² dA / ∫ p dA = a²/5. With nodal forces,
//              Σ Λ_i x_i² = ∫ p I_h(x²) dA, and the Q1 interpolant of x² exceeds x² by h_x²/6 on
//              average over a cell of the uniform patch, so b² = 5 (Σ Λ x² / Σ Λ − h_x²/6)
//              (likewise a with y, h_y). This uses every contact node, not just the edge, and is
//              accurate to a fraction of a cell;
//   edge       the active set's extent along the axes: midway between the last active and the
//              first free node on y = 0 (for b) and on x = 0 (for a), ± half the node spacing;
//   p₀         Λ/m at the node at the centre (the pressure there, to O(h²)).
ApproachStep HertzContactProblem::measure_contact(double approach) const {
  double sum = 0, sum_x2 = 0, sum_y2 = 0, centre_pressure = 0;
  double last_active_x = 0, last_active_y = 0;
  unsigned long n_active = 0;
  const double on_axis = 1e-6 * finest_hx;
  for (std::size_t k = 0; k < contact_nodes.size(); ++k) {
    const ContactNode& node = contact_nodes[k];
    if (!node.owned || !active[k]) continue;
    const double f = reaction(node.dof);
    sum += f;
    sum_x2 += f * node.p[0] * node.p[0];
    sum_y2 += f * node.p[1] * node.p[1];
    ++n_active;
    if (std::abs(node.p[0]) < on_axis && std::abs(node.p[1]) < on_axis)
      centre_pressure = f / surface_mass(node.dof);
    if (std::abs(node.p[1]) < on_axis) last_active_x = std::max(last_active_x, node.p[0]);
    if (std::abs(node.p[0]) < on_axis) last_active_y = std::max(last_active_y, node.p[1]);
  }
  sum = Utilities::MPI::sum(sum, comm);
  sum_x2 = Utilities::MPI::sum(sum_x2, comm);
  sum_y2 = Utilities::MPI::sum(sum_y2, comm);
  centre_pressure = Utilities::MPI::sum(centre_pressure, comm);
  n_active = Utilities::MPI::sum(n_active, comm);
  last_active_x = Utilities::MPI::max(last_active_x, comm);
  last_active_y = Utilities::MPI::max(last_active_y, comm);

  double first_free_x = std::numeric_limits<double>::max();
  double first_free_y = std::numeric_limits<double>::max();
  for (std::size_t k = 0; k < contact_nodes.size(); ++k) {
    const ContactNode& node = contact_nodes[k];
    if (!node.owned || active[k]) continue;
    if (std::abs(node.p[1]) < on_axis && node.p[0] > last_active_x)
      first_free_x = std::min(first_free_x, node.p[0]);
    if (std::abs(node.p[0]) < on_axis && node.p[1] > last_active_y)
      first_free_y = std::min(first_free_y, node.p[1]);
  }
  first_free_x = Utilities::MPI::min(first_free_x, comm);
  first_free_y = Utilities::MPI::min(first_free_y, comm);

  ApproachStep s;
  s.approach = approach;
  s.force = 4 * sum;
  if (sum > 0) {
    s.semi_minor = std::sqrt(std::max(0.0, 5 * (sum_x2 / sum - finest_hx * finest_hx / 6)));
    s.semi_major = std::sqrt(std::max(0.0, 5 * (sum_y2 / sum - finest_hy * finest_hy / 6)));
  }
  s.semi_minor_edge = 0.5 * (last_active_x + first_free_x);
  s.semi_major_edge = 0.5 * (last_active_y + first_free_y);
  s.edge_spacing_minor = first_free_x - last_active_x;
  s.edge_spacing_major = first_free_y - last_active_y;
  s.peak_pressure = centre_pressure;
  s.active_nodes = n_active;
  return s;
}

// VTU + PVTU per step: displacement, contact pressure (Λ/m on the contact set, as the z component
// of a vector so ParaView can warp by it), contact set, and the MPI partition.
void HertzContactProblem::output_results(unsigned int step) const {
  TimerOutput::Scope t(timer, "output");
  TrilinosWrappers::MPI::Vector pressure(locally_owned_dofs, comm);
  for (std::size_t k = 0; k < contact_nodes.size(); ++k)
    if (contact_nodes[k].owned && active[k])
      pressure(contact_nodes[k].dof) =
          reaction(contact_nodes[k].dof) / surface_mass(contact_nodes[k].dof);
  pressure.compress(VectorOperation::insert);
  TrilinosWrappers::MPI::Vector u_ghosted(locally_owned_dofs, locally_relevant_dofs, comm);
  TrilinosWrappers::MPI::Vector p_ghosted(locally_owned_dofs, locally_relevant_dofs, comm);
  u_ghosted = solution;
  p_ghosted = pressure;

  DataOut<dim> data_out;
  data_out.attach_dof_handler(dof_handler);
  const std::vector<DataComponentInterpretation::DataComponentInterpretation> vector(
      dim, DataComponentInterpretation::component_is_part_of_vector);
  data_out.add_data_vector(u_ghosted, std::vector<std::string>(dim, "displacement"),
                           DataOut<dim>::type_dof_data, vector);
  data_out.add_data_vector(p_ghosted, std::vector<std::string>(dim, "contact_pressure"),
                           DataOut<dim>::type_dof_data, vector);
  Vector<float> subdomain(triangulation.n_active_cells());
  for (auto& s : subdomain) s = static_cast<float>(triangulation.locally_owned_subdomain());
  data_out.add_data_vector(subdomain, "subdomain");
  data_out.build_patches();
  // Each rank's piece and rank 0's record, named as write_vtu_with_pvtu_record names them, but
  // written by write_file: a full disk is an OutputError, never a silently shorter file, and on
  // every rank (one rank throwing alone would leave the others waiting in the next solve).
  const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
  const unsigned int ranks = Utilities::MPI::n_mpi_processes(comm);
  const std::string stem = "contact_" + Utilities::int_to_string(step, 3);
  const auto piece = [&](unsigned int r) {
    return stem + "." + Utilities::int_to_string(r, Utilities::needed_digits(ranks - 1)) + ".vtu";
  };
  std::string error;
  try {
    std::ostringstream vtu;
    data_out.write_vtu(vtu);
    write_file(prm.vtu_directory + "/" + piece(rank), vtu.str());
    if (rank == 0) {
      std::vector<std::string> pieces;
      for (unsigned int r = 0; r < ranks; ++r) pieces.push_back(piece(r));
      std::ostringstream record;
      data_out.write_pvtu_record(record, pieces);
      write_file(prm.vtu_directory + "/" + stem + ".pvtu", record.str());
    }
  } catch (const OutputError& e) {
    error = e.what();
  }
  if (Utilities::MPI::max(error.empty() ? 0 : 1, comm) != 0)
    throw OutputError(error.empty() ? "the VTU files could not be written (another rank says why)"
                                    : error);
}

// ---------------------------------------------------------------------------------------------
// The approach steps, each solved by PDAS. The first step starts from the geometric overlap
// {G_i < 0}; every later step from the previous contact set and displacement (the sets grow with
// δ, so a few iterations suffice).
HertzContactResult HertzContactProblem::run() {
  const auto t0 = std::chrono::steady_clock::now();
  make_grid();
  refine_grid();
  setup_system();
  assemble_cell_matrices();
  assemble_stiffness();

  HertzContactResult result;
  result.cells = triangulation.n_global_active_cells();
  result.dofs = dof_handler.n_dofs();
  result.finest_cell_x = finest_hx;
  result.finest_cell_y = finest_hy;
  result.domain_x = domain.x;
  result.domain_y = domain.y;
  result.mpi_processes = Utilities::MPI::n_mpi_processes(comm);
  pcout << "  mesh: " << result.cells << " cells, " << result.dofs << " DoFs, h_x = b/"
        << prm.design_semi_minor / finest_hx << ", L_x = " << domain.x / prm.design_semi_major
        << " a, " << result.mpi_processes << " process(es); " << geometry->describe() << "\n";

  for (std::size_t k = 0; k < contact_nodes.size(); ++k)
    active[k] = gap(contact_nodes[k], prm.approaches.front()) < 0;

  for (unsigned int step = 0; step < prm.approaches.size(); ++step) {
    const double delta = prm.approaches[step];
    ApproachStep s;
    // Start from the previous step by self-similarity: Hertz's patch grows as √δ and the
    // displacement near it as δ, so scale the previous solution by δ/δ_prev and take as contact
    // set the previous ellipse (its moment semi-axes) scaled by √(δ/δ_prev). PDAS then needs
    // only the corrections of the discrete set.
    if (step > 0) {
      const ApproachStep& prev = result.steps.back();
      const double ratio = delta / prev.approach;
      solution *= ratio;
      const double a = prev.semi_major * std::sqrt(ratio), b = prev.semi_minor * std::sqrt(ratio);
      for (std::size_t k = 0; k < contact_nodes.size(); ++k) {
        const double x = contact_nodes[k].p[0] / b, y = contact_nodes[k].p[1] / a;
        active[k] = x * x + y * y < 1;
      }
    }
    for (unsigned int it = 1;; ++it) {
      constraints_all.clear();
      constraints_all.reinit(locally_relevant_dofs);
      for (std::size_t k = 0; k < contact_nodes.size(); ++k)
        if (active[k]) {
          constraints_all.add_line(contact_nodes[k].dof);
          constraints_all.set_inhomogeneity(contact_nodes[k].dof, gap(contact_nodes[k], delta));
        }
      constraints_all.merge(constraints_fixed);
      constraints_all.close();
      assemble_system();
      s.linear_iterations += solve();
      const unsigned long changed = update_active_set(delta);
      s.active_set_iterations = it;
      if (changed == 0) break;
      if (it == prm.max_active_set_iterations)
        throw std::runtime_error("active set did not settle in " + std::to_string(it) +
                                 " iterations at approach step " + std::to_string(step));
    }
    const unsigned int iterations = s.active_set_iterations, cg = s.linear_iterations;
    s = measure_contact(delta);
    s.active_set_iterations = iterations;
    s.linear_iterations = cg;
    pcout << "  step " << step << ": delta = " << delta << " m, F = " << s.force
          << " N, a = " << s.semi_major << " m, b = " << s.semi_minor << " m, " << s.active_nodes
          << " contact nodes, " << iterations << " active-set iterations, " << cg
          << " CG iterations\n";
    result.steps.push_back(s);
    if (!prm.vtu_directory.empty()) output_results(step);
  }
  result.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace

std::unique_ptr<ContactGeometry> make_hertz_block(const HertzContactParameters& p) {
  return std::make_unique<HertzBlock>(p);
}

HertzContactResult solve_hertz_contact(const HertzContactParameters& parameters, MPI_Comm comm) {
  // An OutputError comes on every rank at once (output_results) and leaves once the problem is
  // gone: its timers then close normally, not with deal.II's "uncaught exception" notice.
  std::optional<OutputError> failed;
  {
    HertzContactProblem problem(parameters, comm);
    try {
      return problem.run();
    } catch (const OutputError& e) {
      failed.emplace(e);
    }
  }
  throw *failed;
}

// ln F = ln K + n ln δ by least squares (two parameters), and ln K at n = 3/2 (one parameter:
// the mean of ln F − 1.5 ln δ). Residuals are RMS over the points, in ln F.
PowerLawFit fit_power_law(const std::vector<double>& approach, const std::vector<double>& force) {
  if (approach.size() != force.size() || approach.size() < 2)
    throw std::invalid_argument("fit_power_law: need at least two (approach, force) points");
  const std::size_t m = approach.size();
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < m; ++i) {
    if (!(approach[i] > 0 && force[i] > 0))
      throw std::invalid_argument("fit_power_law: approach and force must be positive");
    mx += std::log(approach[i]);
    my += std::log(force[i]);
  }
  mx /= m;
  my /= m;
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < m; ++i) {
    const double dx = std::log(approach[i]) - mx, dy = std::log(force[i]) - my;
    sxx += dx * dx;
    sxy += dx * dy;
  }
  PowerLawFit fit;
  fit.exponent = sxx > 0 ? sxy / sxx : 1.5;
  const double ln_k = my - fit.exponent * mx;
  const double ln_k15 = my - 1.5 * mx;
  fit.K = std::exp(ln_k);
  fit.K_three_halves = std::exp(ln_k15);
  double r = 0, r15 = 0;
  for (std::size_t i = 0; i < m; ++i) {
    const double x = std::log(approach[i]), y = std::log(force[i]);
    r += std::pow(y - ln_k - fit.exponent * x, 2);
    r15 += std::pow(y - ln_k15 - 1.5 * x, 2);
  }
  fit.residual = std::sqrt(r / m);
  fit.residual_three_halves = std::sqrt(r15 / m);
  return fit;
}

}  // namespace bearing::fem
