// The discrete elastic structure of `bearing-fem modes` (elastic_problem.h): mesh, finite
// element, K and M, the seat and the sensors. In the shape of a deal.II tutorial program (step-8
// for elasticity, step-17/step-40 for the distributed matrices, step-36 for the eigenproblem
// that elastic_modes.cc then solves).
//
// ---------------------------------------------------------------------------------------------
// Weak form. Small-strain isotropic elasticity of a body Ω with density ρ, displacement u in
// H¹(Ω)³, u = 0 on the fixed surfaces Γ_D, traction-free elsewhere. The free vibrations
// u(x, t) = φ(x) e^{iωt} satisfy, for every admissible v,
//     a(φ, v) = ω² m(φ, v),
//     a(φ, v) = ∫_Ω λ_L (∇·φ)(∇·v) + 2μ ε(φ):ε(v) dx,     m(φ, v) = ∫_Ω ρ φ·v dx,
// with the Lamé constants λ_L = Eν/((1+ν)(1−2ν)), μ = E/(2(1+ν)) and ε(v) = (∇v + ∇vᵀ)/2.
// Discretised with continuous Lagrange elements of degree p on the gmsh cells (FE_SimplexP on
// tetrahedra, FE_Q on hexahedra; p = 2 by default: P1 tetrahedra lock in bending, their
// frequencies converge slowly from above), a(·,·) gives the stiffness matrix K and m(·,·) the
// consistent mass matrix M, both symmetric, M positive definite, K positive semi-definite (its
// kernel: the six rigid motions when nothing is fixed). The geometry is the gmsh mesh's: straight
// edges and flat faces (an affine mapping on tetrahedra, trilinear on hexahedra), so a curved
// surface is the polyhedron gmsh inscribed in it.
//
// Fixed surfaces. u = 0 on Γ_D is imposed by AffineConstraints: a constrained DoF's row and
// column of K are zero but for its diagonal (deal.II puts there the mean of the cell matrix's
// diagonal, a stiffness of the order of the others), and its row and column of M are zero,
// diagonal too. Each constrained DoF then contributes the eigenvalue K_ii / 0 = ∞ to the pencil
// (K, M), which no shift-and-invert solver aimed at the low end of the spectrum ever returns
// (it maps to the eigenvalue 0 of (K − σM)⁻¹M), and the eigenvectors of the finite eigenvalues
// vanish on Γ_D. So no spurious mode lies inside the wanted range, whatever the mesh.
//
// Under MPI the mesh is a parallel::shared::Triangulation (every process holds all cells, METIS
// partitions them; in deal.II 9.4 this works for tetrahedra as well as hexahedra, and the mesh
// can be refined globally), and K and M are distributed PETSc matrices assembled by the owners of
// the cells.
// ---------------------------------------------------------------------------------------------

#include "modes/elastic_problem.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "bearing/errors.h"

namespace bearing::fem::modes {

ElasticProblem::ElasticProblem(const GmshMesh& mesh, const ElasticModesParameters& p,
                               MPI_Comm comm_)
    : comm(comm_),
      prm(p),
      triangulation(comm_, Triangulation<dim>::none, false,
                    parallel::shared::Triangulation<dim>::partition_metis),
      dof_handler(triangulation),
      mesh_(mesh) {}

void ElasticProblem::setup() {
  make_grid();
  setup_system();
  assemble_system();
  measure_seat();
  find_sensors();
}

// The gmsh cells become deal.II's CellData, the faces of physical surfaces its boundary
// SubCellData. A face's boundary id stands for the set of physical surfaces it lies in (a face may
// lie in several: one id per distinct set, 1, 2, …; 0 for a boundary face of no physical surface).
void ElasticProblem::make_grid() {
  std::vector<Point<dim>> vertices;
  for (const auto& x : mesh_.vertices)
    vertices.emplace_back(x[0] * prm.mesh_scale, x[1] * prm.mesh_scale, x[2] * prm.mesh_scale);
  std::vector<CellData<dim>> cells;
  for (const auto& c : mesh_.cells) {
    CellData<dim> cell(static_cast<unsigned int>(c.size()));
    cell.vertices = c;
    cells.push_back(cell);
  }
  SubCellData faces;
  std::map<std::vector<int>, types::boundary_id> id_of;
  for (const MeshFace& f : mesh_.faces) {
    const auto [it, added] =
        id_of.emplace(f.physicals, static_cast<types::boundary_id>(id_of.size() + 1));
    CellData<2> face(static_cast<unsigned int>(f.vertices.size()));
    face.vertices = f.vertices;
    face.boundary_id = it->second;
    faces.boundary_quads.push_back(face);
    (void)added;
  }
  for (const auto& [physicals, id] : id_of) {
    const auto has = [&](int tag) {
      return std::find(physicals.begin(), physicals.end(), tag) != physicals.end();
    };
    if (has(prm.seat)) seat_ids.push_back(id);
    for (int tag : prm.fixed)
      if (has(tag)) {
        fixed_ids.push_back(id);
        break;
      }
  }
  if (prm.refinements == 0) {
    triangulation.create_triangulation(vertices, cells, faces);
  } else {
    // Refined on one process's serial copy, then handed to the distributed mesh as its coarse
    // mesh (refining a parallel::shared mesh of tetrahedra under MPI does not finish in deal.II
    // 9.4): each child is a coarse cell, each boundary face keeps its id.
    Triangulation<dim> serial;
    serial.create_triangulation(vertices, cells, faces);
    serial.refine_global(prm.refinements);
    cells.clear();
    faces = SubCellData();
    for (const auto& cell : serial.active_cell_iterators()) {
      CellData<dim> c(cell->n_vertices());
      for (unsigned int v = 0; v < cell->n_vertices(); ++v) c.vertices[v] = cell->vertex_index(v);
      cells.push_back(c);
      for (const unsigned int f : cell->face_indices()) {
        const auto face = cell->face(f);
        if (!face->at_boundary() || face->boundary_id() == 0) continue;
        CellData<2> b(face->n_vertices());
        for (unsigned int v = 0; v < face->n_vertices(); ++v) b.vertices[v] = face->vertex_index(v);
        b.boundary_id = face->boundary_id();
        faces.boundary_quads.push_back(b);
      }
    }
    std::vector<Point<dim>> all = serial.get_vertices();
    GridTools::delete_unused_vertices(all, cells, faces);
    triangulation.create_triangulation(all, cells, faces);
  }

  // The bounding box: the structure's size L (the frequency scale) and its centre.
  const auto box = GridTools::compute_bounding_box(triangulation);
  diagonal = box.get_boundary_points().first.distance(box.get_boundary_points().second);
  centre = box.center();
}

void ElasticProblem::setup_system() {
  const unsigned int p = prm.degree;
  if (mesh_.cell_type == GmshMesh::CellType::tetrahedron) {
    fe = std::make_unique<FESystem<dim>>(FE_SimplexP<dim>(p), dim);
    mapping = std::make_unique<MappingFE<dim>>(FE_SimplexP<dim>(1));
    cell_quadrature = std::make_unique<QGaussSimplex<dim>>(p + 1);
    face_quadrature = std::make_unique<QGaussSimplex<dim - 1>>(p + 1);
  } else {
    fe = std::make_unique<FESystem<dim>>(FE_Q<dim>(p), dim);
    mapping = std::make_unique<MappingQ<dim>>(1);
    cell_quadrature = std::make_unique<QGauss<dim>>(p + 1);
    face_quadrature = std::make_unique<QGauss<dim - 1>>(p + 1);
  }
  dof_handler.distribute_dofs(*fe);
  owned = dof_handler.locally_owned_dofs();
  DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);

  constraints.clear();
  constraints.reinit(relevant);
  for (const types::boundary_id id : fixed_ids)
    VectorTools::interpolate_boundary_values(*mapping, dof_handler, id,
                                             Functions::ZeroFunction<dim>(dim), constraints);
  constraints.close();

  DynamicSparsityPattern dsp(relevant);
  DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
  SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
  stiffness.reinit(owned, owned, dsp, comm);
  mass.reinit(owned, owned, dsp, comm);
  for (auto& v : mass_translation) v.reinit(owned, comm);
}

// K and M cell by cell (step-8's bilinear form; the mass with the same quadrature of degree
// 2p + 1, exact for the affine tetrahedra), and M r_d: the mass of a rigid translation, for the
// effective masses.
void ElasticProblem::assemble_system() {
  const double E = prm.young, nu = prm.poisson, rho = prm.density;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double mu = E / (2 * (1 + nu));
  FEValues<dim> fev(*mapping, *fe, *cell_quadrature,
                    update_values | update_gradients | update_JxW_values);
  const FEValuesExtractors::Vector u(0);
  const unsigned int n = fe->n_dofs_per_cell(), nq = cell_quadrature->size();
  FullMatrix<double> ke(n, n), me(n, n);
  std::array<Vector<double>, dim> ge;
  for (auto& g : ge) g.reinit(n);
  std::vector<types::global_dof_index> dofs(n);
  std::vector<double> div(n);
  std::vector<SymmetricTensor<2, dim>> eps(n);
  std::vector<Tensor<1, dim>> phi(n);
  double local_volume = 0;
  for (const auto& cell : dof_handler.active_cell_iterators()) {
    if (!cell->is_locally_owned()) continue;
    fev.reinit(cell);
    ke = 0, me = 0;
    for (auto& g : ge) g = 0;
    for (unsigned int q = 0; q < nq; ++q) {
      const double dx = fev.JxW(q);
      local_volume += dx;
      for (unsigned int i = 0; i < n; ++i) {
        div[i] = fev[u].divergence(i, q);
        eps[i] = fev[u].symmetric_gradient(i, q);
        phi[i] = fev[u].value(i, q);
      }
      for (unsigned int i = 0; i < n; ++i) {
        for (unsigned int j = 0; j <= i; ++j) {
          ke(i, j) += (lambda * div[i] * div[j] + 2 * mu * (eps[i] * eps[j])) * dx;
          me(i, j) += rho * (phi[i] * phi[j]) * dx;
        }
        for (unsigned int d = 0; d < dim; ++d) ge[d](i) += rho * phi[i][d] * dx;
      }
    }
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i + 1; j < n; ++j) ke(i, j) = ke(j, i), me(i, j) = me(j, i);
    cell->get_dof_indices(dofs);
    constraints.distribute_local_to_global(ke, dofs, stiffness);
    constraints.distribute_local_to_global(me, dofs, mass);
    for (unsigned int d = 0; d < dim; ++d) mass_translation[d].add(dofs, ge[d]);
  }
  stiffness.compress(VectorOperation::add);
  mass.compress(VectorOperation::add);
  for (auto& v : mass_translation) v.compress(VectorOperation::add);
  // A constrained row of M: zero, so that its eigenvalue is infinite (the header comment).
  for (const auto i : owned)
    if (constraints.is_constrained(i)) mass.set(i, i, 0.0);
  mass.compress(VectorOperation::insert);
  volume = Utilities::MPI::sum(local_volume, comm);
  total_mass = rho * volume;
}

// The element-wise sum of `v` over the processes of `comm`.
std::vector<double> summed(std::vector<double> v, MPI_Comm comm) {
  MPI_Allreduce(MPI_IN_PLACE, v.data(), static_cast<int>(v.size()), MPI_DOUBLE, MPI_SUM, comm);
  return v;
}

PETScWrappers::MPI::Vector ElasticProblem::ghosted(const PETScWrappers::MPI::Vector& v) const {
  PETScWrappers::MPI::Vector g(owned, relevant, comm);
  g = v;
  return g;
}

// The seat's faces: each process its own cells' faces whose boundary id is one of the seat's.
template <class F>
void for_seat_faces(const ElasticProblem& e, FEFaceValues<dim>& fv, const F& f) {
  for (const auto& cell : e.dof_handler.active_cell_iterators()) {
    if (!cell->is_locally_owned() || !cell->at_boundary()) continue;
    for (const unsigned int face : cell->face_indices()) {
      if (!cell->face(face)->at_boundary()) continue;
      const auto id = cell->face(face)->boundary_id();
      if (std::find(e.seat_ids.begin(), e.seat_ids.end(), id) == e.seat_ids.end()) continue;
      fv.reinit(cell, face);
      f(cell, face);
    }
  }
}

void ElasticProblem::measure_seat() {
  FEFaceValues<dim> fv(*mapping, *fe, *face_quadrature,
                       update_quadrature_points | update_JxW_values);
  SurfaceMoments local;
  std::set<types::global_dof_index> nodes;
  std::vector<types::global_dof_index> face_dofs(fe->max_dofs_per_face());
  for_seat_faces(*this, fv, [&](const auto& cell, unsigned int face) {
    for (unsigned int q = 0; q < fv.n_quadrature_points; ++q) {
      const Point<dim>& x = fv.quadrature_point(q);
      local.add(fv.JxW(q), to_vec3(x));
    }
    face_dofs.resize(fe->n_dofs_per_face(face));
    cell->face(face)->get_dof_indices(face_dofs, cell->active_fe_index());
    for (unsigned int i = 0; i < face_dofs.size(); ++i)
      if (fe->face_system_to_component_index(i, face).first == 0 && owned.is_element(face_dofs[i]))
        nodes.insert(face_dofs[i]);
  });
  const std::vector<double> sum = summed(packed(local), comm);
  seat = surface_moments_from(sum.data());
  seat_nodes = Utilities::MPI::sum(static_cast<unsigned long>(nodes.size()), comm);
  check_seat_geometry(seat, prm.seat_name);
}

std::vector<RigidFit> ElasticProblem::seat_fits(
    const std::vector<PETScWrappers::MPI::Vector>& us) const {
  std::vector<PETScWrappers::MPI::Vector> g;
  for (const auto& u : us) g.push_back(ghosted(u));
  FEFaceValues<dim> fv(*mapping, *fe, *face_quadrature,
                       update_values | update_quadrature_points | update_JxW_values);
  const FEValuesExtractors::Vector disp(0);
  std::vector<FieldMoments> local(us.size());
  std::vector<Tensor<1, dim>> values(face_quadrature->size());
  for_seat_faces(*this, fv, [&](const auto&, unsigned int) {
    for (std::size_t k = 0; k < g.size(); ++k) {
      fv[disp].get_function_values(g[k], values);
      for (unsigned int q = 0; q < fv.n_quadrature_points; ++q) {
        const Point<dim>& x = fv.quadrature_point(q);
        local[k].add(fv.JxW(q), to_vec3(x), to_vec3(values[q]));
      }
    }
  });
  std::vector<double> flat;
  for (const auto& f : local) {
    const auto p = packed(f);
    flat.insert(flat.end(), p.begin(), p.end());
  }
  flat = summed(flat, comm);
  std::vector<RigidFit> fits;
  for (std::size_t k = 0; k < us.size(); ++k)
    fits.push_back(fit_rigid_motion(seat, field_moments_from(flat.data() + 7 * k)));
  return fits;
}

RigidFit ElasticProblem::seat_fit(const PETScWrappers::MPI::Vector& u) const {
  return seat_fits({u}).front();
}

PETScWrappers::MPI::Vector ElasticProblem::seat_load(unsigned int direction) const {
  PETScWrappers::MPI::Vector f(owned, comm);
  FEFaceValues<dim> fv(*mapping, *fe, *face_quadrature, update_values | update_JxW_values);
  const unsigned int n = fe->n_dofs_per_cell();
  Vector<double> fe_local(n);
  std::vector<types::global_dof_index> dofs(n);
  for_seat_faces(*this, fv, [&](const auto& cell, unsigned int) {
    fe_local = 0;
    for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
      for (unsigned int i = 0; i < n; ++i)
        if (fe->system_to_component_index(i).first == direction)
          fe_local(i) += fv.shape_value(i, q) * fv.JxW(q) / seat.area;
    cell->get_dof_indices(dofs);
    constraints.distribute_local_to_global(fe_local, dofs, f);
  });
  f.compress(VectorOperation::add);
  return f;
}

// Each sensor's point: the boundary support point nearest the requested one (its distance is
// reported). At a support point a Lagrange element's field is its nodal value, so the sensor
// reads the DoFs x, y, z there. Candidates are each process's owned boundary DoFs; the nearest
// over all processes wins, ties broken by the point's coordinates (never by a DoF number, which
// depends on the partition), so serial and MPI runs pick the same point.
void ElasticProblem::find_sensors() {
  std::map<types::global_dof_index, Point<dim>> support;
  DoFTools::map_dofs_to_support_points(*mapping, dof_handler, support);
  const std::size_t ns = prm.sensors.size();
  sensors.assign(ns, SensorPoint{});
  using Candidate = std::array<double, 4>;  // distance, x, y, z: compared in that order
  std::vector<Candidate> best(ns, Candidate{{std::numeric_limits<double>::max(), 0, 0, 0}});
  std::vector<types::global_dof_index> face_dofs;
  for (const auto& cell : dof_handler.active_cell_iterators()) {
    if (!cell->is_locally_owned() || !cell->at_boundary()) continue;
    for (const unsigned int face : cell->face_indices()) {
      if (!cell->face(face)->at_boundary()) continue;
      face_dofs.resize(fe->n_dofs_per_face(face));
      cell->face(face)->get_dof_indices(face_dofs, cell->active_fe_index());
      std::map<unsigned int, std::array<types::global_dof_index, dim>> at_point;
      for (unsigned int i = 0; i < face_dofs.size(); ++i) {
        const auto [component, base] = fe->face_system_to_component_index(i, face);
        at_point[base][component] = face_dofs[i];
      }
      for (const auto& [base, xyz] : at_point) {
        if (!owned.is_element(xyz[0])) continue;
        const Point<dim>& p = support.at(xyz[0]);
        for (std::size_t s = 0; s < ns; ++s) {
          const Point<dim> want(prm.sensors[s][0], prm.sensors[s][1], prm.sensors[s][2]);
          const Candidate candidate{{p.distance(want), p[0], p[1], p[2]}};
          if (candidate < best[s]) best[s] = candidate, sensors[s].dofs = xyz;
        }
      }
    }
  }
  const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
  for (std::size_t s = 0; s < ns; ++s) {
    const auto all = Utilities::MPI::all_gather(comm, best[s]);
    const auto winner = std::min_element(all.begin(), all.end()) - all.begin();
    const auto& [d, x, y, z] = all[winner];
    sensors[s].point = Point<dim>(x, y, z);
    sensors[s].distance = d;
    sensors[s].owner = static_cast<unsigned int>(winner);
    if (rank != sensors[s].owner) sensors[s].dofs = {};
  }
}

std::vector<std::vector<Vec3>> ElasticProblem::sensor_values(
    const std::vector<PETScWrappers::MPI::Vector>& us) const {
  const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
  std::vector<std::vector<Vec3>> out;
  for (const SensorPoint& s : sensors) {
    std::vector<double> v(3 * us.size());
    if (rank == s.owner)
      for (std::size_t k = 0; k < us.size(); ++k)
        for (unsigned int d = 0; d < dim; ++d) v[3 * k + d] = us[k](s.dofs[d]);
    MPI_Bcast(v.data(), static_cast<int>(v.size()), MPI_DOUBLE, static_cast<int>(s.owner), comm);
    std::vector<Vec3> values(us.size());
    for (std::size_t k = 0; k < us.size(); ++k)
      values[k] = Vec3{{v[3 * k], v[3 * k + 1], v[3 * k + 2]}};
    out.push_back(values);
  }
  return out;
}

// A field given point by point at the owned DoFs: value(x, c) at the support point x of a DoF
// of component c. Exact in the finite element space for linear fields (rigid motions).
PETScWrappers::MPI::Vector ElasticProblem::dof_field(
    const std::function<double(const Point<dim>&, unsigned int)>& value) const {
  std::map<types::global_dof_index, Point<dim>> support;
  DoFTools::map_dofs_to_support_points(*mapping, dof_handler, support);
  PETScWrappers::MPI::Vector r(owned, comm);
  std::vector<types::global_dof_index> dofs(fe->n_dofs_per_cell());
  std::vector<bool> done(owned.n_elements(), false);
  for (const auto& cell : dof_handler.active_cell_iterators()) {
    if (!cell->is_locally_owned()) continue;
    cell->get_dof_indices(dofs);
    for (unsigned int i = 0; i < dofs.size(); ++i) {
      if (!owned.is_element(dofs[i])) continue;
      const auto local = owned.index_within_set(dofs[i]);
      if (done[local]) continue;
      done[local] = true;
      r(dofs[i]) = value(support.at(dofs[i]), fe->system_to_component_index(i).first);
    }
  }
  r.compress(VectorOperation::insert);
  return r;
}

// The six rigid motions: a translation is 1 in its component; a rotation about axis a through
// the centre c is e_a × (x − c).
std::vector<PETScWrappers::MPI::Vector> ElasticProblem::rigid_motions() const {
  std::vector<PETScWrappers::MPI::Vector> r;
  for (unsigned int d = 0; d < dim; ++d)
    r.push_back(dof_field([d](const Point<dim>&, unsigned int c) { return c == d ? 1.0 : 0.0; }));
  for (unsigned int a = 0; a < dim; ++a)
    r.push_back(dof_field([&, a](const Point<dim>& x, unsigned int c) {
      Tensor<1, dim> e;
      e[a] = 1;
      return cross_product_3d(e, x - centre)[c];
    }));
  return r;
}

}  // namespace bearing::fem::modes
