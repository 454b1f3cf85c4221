// The natural modes (elastic_modes.h): the generalized eigenproblem K φ = ω² M φ of
// elastic_problem.cc solved by SLEPc, the shapes mass-normalised, the rigid-body modes counted and
// left out, and what modes.json reports measured on them.
//
// ---------------------------------------------------------------------------------------------
// Eigensolver. The lowest eigenpairs of the symmetric-definite pencil (K, M) are found by
// Krylov–Schur on the shift-and-invert transformation
//     (K − σM)⁻¹ M φ = θ φ,   θ = 1/(λ − σ),   λ = ω²,
// which turns the eigenvalues nearest σ into the largest |θ|, well separated, where Krylov
// methods converge fastest (step-36 does the same). K − σM is factorised once per solve by MUMPS
// (PETSc KSP "preonly", PC Cholesky: LDLᵀ, distributed under MPI). SLEPc is called through its C
// API on deal.II's PETSc matrices, to give its spectral transformation that factorisation
// explicitly; the problem type is GHEP (Hermitian, B = M semi-definite: M's constrained rows are
// zero, elastic_problem.cc, which SLEPc's B-inner product with purification handles).
//
// Shift. σ = −(2π · 0.01 f_ref)², slightly below 0, with f_ref = √(E/ρ) / (2π L), L the bounding
// box's diagonal: the order of the structure's lowest longitudinal frequency. K − σM is then
// positive definite even for a free-free structure (K singular), and the eigenvalues nearest σ are
// the lowest ones, rigid-body modes first.
//
// Rigid-body modes. A mode below 1e-4 f_ref ("near zero") is a rigid-body mode: a free-free
// structure has exactly six (found: they are counted, checked to span the six rigid motions to
// 1e-6 in the M-norm, and left out); an elastic mode of a real structure lies orders of magnitude
// above that threshold (a slender beam of length L and thickness h: f₁ ≈ 0.16 (h/L) f_ref, so
// only a body thinner than 1/1000 of its size comes near it). With fixed surfaces any near-zero
// mode means they leave the body (or a part of it) free to move: bad input, not a mode.
//
// Normalisation. φᵀMφ = 1 (M in kg, so a shape is in kg^-1/2); the sign makes Σ_i w_i φ_i > 0
// for a fixed smooth, non-symmetric weight w(x, c) of each DoF's support point and component,
// which does not depend on how the DoFs are numbered or shared among processes.
// ---------------------------------------------------------------------------------------------

#include "modes/elastic_modes.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/utilities.h>
#include <deal.II/numerics/data_out.h>
#include <slepceps.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <numeric>

#include "bearing/errors.h"
#include "modes/elastic_problem.h"
#include "modes/harmonic_response.h"

namespace bearing::fem {

namespace modes {

#define BEARING_PETSC_CHECK(call)                                                  \
  do {                                                                             \
    const PetscErrorCode petsc_error_ = (call);                                    \
    if (petsc_error_)                                                              \
      throw SolverError(std::string("SLEPc/PETSc: ") + #call + " failed (error " + \
                        std::to_string(petsc_error_) + ")");                       \
  } while (false)

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Eigenpairs {
  std::vector<double> lambda;                      ///< ω², ascending [rad²/s²]
  std::vector<PETScWrappers::MPI::Vector> shapes;  ///< M-normalised as SLEPc returns them
};

// The `wanted` eigenpairs of (K, M) nearest σ (all SLEPc converged, at least `wanted`),
// ascending.
Eigenpairs eigensolve(const ElasticProblem& e, unsigned int wanted, double sigma,
                      double tolerance) {
  EPS eps;
  BEARING_PETSC_CHECK(EPSCreate(e.comm, &eps));
  Eigenpairs out;
  try {
    BEARING_PETSC_CHECK(
        EPSSetOperators(eps, static_cast<Mat>(e.stiffness), static_cast<Mat>(e.mass)));
    BEARING_PETSC_CHECK(EPSSetProblemType(eps, EPS_GHEP));
    BEARING_PETSC_CHECK(EPSSetType(eps, EPSKRYLOVSCHUR));
    BEARING_PETSC_CHECK(EPSSetTarget(eps, sigma));
    BEARING_PETSC_CHECK(EPSSetWhichEigenpairs(eps, EPS_TARGET_MAGNITUDE));
    ST st;
    KSP ksp;
    PC pc;
    BEARING_PETSC_CHECK(EPSGetST(eps, &st));
    BEARING_PETSC_CHECK(STSetType(st, STSINVERT));
    BEARING_PETSC_CHECK(STGetKSP(st, &ksp));
    BEARING_PETSC_CHECK(KSPSetType(ksp, KSPPREONLY));
    BEARING_PETSC_CHECK(KSPGetPC(ksp, &pc));
    BEARING_PETSC_CHECK(PCSetType(pc, PCCHOLESKY));
    BEARING_PETSC_CHECK(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
    BEARING_PETSC_CHECK(EPSSetDimensions(eps, wanted, PETSC_DEFAULT, PETSC_DEFAULT));
    BEARING_PETSC_CHECK(EPSSetTolerances(eps, tolerance, 1000));
    BEARING_PETSC_CHECK(EPSSolve(eps));
    PetscInt converged = 0;
    BEARING_PETSC_CHECK(EPSGetConverged(eps, &converged));
    if (converged < static_cast<PetscInt>(wanted))
      throw SolverError("SLEPc found " + std::to_string(converged) + " of the " +
                        std::to_string(wanted) + " eigenpairs asked for (tolerance " +
                        std::to_string(tolerance) + "): loosen --tolerance or ask fewer modes");
    std::vector<std::pair<double, PetscInt>> order;
    for (PetscInt i = 0; i < converged; ++i) {
      PetscScalar kr, ki;
      BEARING_PETSC_CHECK(EPSGetEigenvalue(eps, i, &kr, &ki));
      order.emplace_back(PetscRealPart(kr), i);
    }
    std::sort(order.begin(), order.end());
    for (const auto& [lambda, i] : order) {
      PETScWrappers::MPI::Vector v(e.owned, e.comm);
      PetscScalar kr, ki;
      BEARING_PETSC_CHECK(EPSGetEigenpair(eps, i, &kr, &ki, static_cast<const Vec&>(v), nullptr));
      out.lambda.push_back(lambda);
      out.shapes.push_back(std::move(v));
    }
  } catch (...) {
    EPSDestroy(&eps);
    throw;
  }
  BEARING_PETSC_CHECK(EPSDestroy(&eps));
  return out;
}

// φ ← ±φ / √(φᵀMφ), the sign making wᵀφ > 0.
void normalise(const ElasticProblem& e, const PETScWrappers::MPI::Vector& w,
               PETScWrappers::MPI::Vector& phi) {
  PETScWrappers::MPI::Vector m(e.owned, e.comm);
  e.mass.vmult(m, phi);
  const double norm = std::sqrt(phi * m);
  phi *= ((w * phi) < 0 ? -1.0 : 1.0) / norm;
}

// max |ΦᵀMΦ − I| and max |ΦᵀKΦ − diag(λ)| / max λ over the returned modes.
std::pair<double, double> orthogonality(const ElasticProblem& e,
                                        const std::vector<PETScWrappers::MPI::Vector>& phi,
                                        const std::vector<double>& lambda) {
  double mass = 0, stiffness = 0;
  const double scale = lambda.empty() ? 1.0 : *std::max_element(lambda.begin(), lambda.end());
  PETScWrappers::MPI::Vector m(e.owned, e.comm), k(e.owned, e.comm);
  for (std::size_t j = 0; j < phi.size(); ++j) {
    e.mass.vmult(m, phi[j]);
    e.stiffness.vmult(k, phi[j]);
    for (std::size_t i = 0; i <= j; ++i) {
      mass = std::max(mass, std::fabs((phi[i] * m) - (i == j ? 1.0 : 0.0)));
      stiffness = std::max(stiffness, std::fabs((phi[i] * k) - (i == j ? lambda[j] : 0.0)) / scale);
    }
  }
  return {mass, stiffness};
}

// The largest share of a rigid motion's M-norm outside the span of the (M-orthonormal) modes.
double rigid_span(const ElasticProblem& e, const std::vector<PETScWrappers::MPI::Vector>& modes) {
  double worst = 0;
  PETScWrappers::MPI::Vector m(e.owned, e.comm);
  for (const auto& r : e.rigid_motions()) {
    e.mass.vmult(m, r);
    const double norm = r * m;
    double inside = 0;
    for (const auto& phi : modes) inside += std::pow(phi * m, 2);
    worst = std::max(worst, std::max(0.0, 1 - inside / norm));
  }
  return worst;
}

void write_vtu(const ElasticProblem& e, const std::vector<PETScWrappers::MPI::Vector>& phi,
               const std::vector<double>& frequencies, const std::string& file) {
  DataOut<dim> out;
  out.attach_dof_handler(e.dof_handler);
  // Every cell (parallel::shared: each process has them all).
  out.set_cell_selection(
      [](const Triangulation<dim>& t) {
        return Triangulation<dim>::cell_iterator(t.begin_active());
      },
      [](const Triangulation<dim>&, const Triangulation<dim>::cell_iterator& c) {
        Triangulation<dim>::active_cell_iterator a(c);
        return Triangulation<dim>::cell_iterator(++a);
      });
  const std::vector<DataComponentInterpretation::DataComponentInterpretation> vector(
      dim, DataComponentInterpretation::component_is_part_of_vector);
  // Every process gathers the shapes and builds the patches (build_patches is collective on a
  // distributed mesh); rank 0 alone writes.
  std::vector<Vector<double>> full;
  for (const auto& p : phi) full.emplace_back(p);
  for (std::size_t k = 0; k < full.size(); ++k) {
    char name[64];
    std::snprintf(name, sizeof name, "mode_%02zu_%.6gHz", k + 1, frequencies[k]);
    out.add_data_vector(full[k], std::vector<std::string>(dim, name), DataOut<dim>::type_dof_data,
                        vector);
  }
  // The shapes at the cells' vertices, on linear cells (a tenth of a degree-2 file's size; the
  // modal data in modes.json are the finite element's own values).
  out.build_patches(*e.mapping, 1);
  int ok = 1;
  if (Utilities::MPI::this_mpi_process(e.comm) == 0) {
    std::ofstream f(file);
    if (f) out.write_vtu(f);
    ok = f.good() ? 1 : 0;
  }
  MPI_Bcast(&ok, 1, MPI_INT, 0, e.comm);
  if (!ok) throw OutputError(file + ": cannot write the mode shapes (VTU)");
}

}  // namespace

}  // namespace modes

ElasticModesResult solve_elastic_modes(const GmshMesh& mesh, const ElasticModesParameters& p,
                                       MPI_Comm comm) {
  using namespace modes;
  const auto start = std::chrono::steady_clock::now();
  ConditionalOStream pcout(std::cout, p.verbose && Utilities::MPI::this_mpi_process(comm) == 0);
  ElasticProblem e(mesh, p, comm);
  e.setup();
  ElasticModesResult r;
  r.cells = e.triangulation.n_global_active_cells();
  r.vertices = e.triangulation.n_vertices();
  r.dofs = e.dof_handler.n_dofs();
  r.degree = p.degree;
  r.cell_type = mesh.cell_type_name();
  r.volume = e.volume;
  r.total_mass = e.total_mass;
  r.mpi_processes = Utilities::MPI::n_mpi_processes(comm);
  pcout << "bearing-fem modes: " << r.cells << " cells (" << r.cell_type << "), " << r.dofs
        << " DoFs, degree " << p.degree << ", mass " << r.total_mass << " kg" << std::endl;

  const bool free = p.fixed.empty();
  r.frequency_scale = std::sqrt(p.young / p.density) / (2 * kPi * e.diagonal);
  r.near_zero = 1e-4 * r.frequency_scale;
  r.shift = -std::pow(2 * kPi * 1e-2 * r.frequency_scale, 2);
  r.tolerance = p.tolerance;
  const double zero_lambda = std::pow(2 * kPi * r.near_zero, 2);
  const unsigned int cap = 500, rigid = free ? 6 : 0;
  unsigned int want = p.count > 0 ? p.count : 20;
  Eigenpairs pairs;
  unsigned int n_zero = 0;
  for (;;) {
    const unsigned int ask =
        std::min<unsigned int>(want + rigid, static_cast<unsigned int>(r.dofs) - 1);
    pairs = eigensolve(e, ask, r.shift, p.tolerance);
    ++r.eigensolves;
    n_zero = 0;
    for (double l : pairs.lambda) n_zero += std::fabs(l) < zero_lambda ? 1 : 0;
    const double top = std::sqrt(std::max(0.0, pairs.lambda.back())) / (2 * kPi);
    pcout << "  " << pairs.lambda.size() << " eigenpairs, up to " << top << " Hz" << std::endl;
    if (p.count > 0 || p.max_frequency <= 0 || top > p.max_frequency || want >= cap ||
        ask + 1 >= r.dofs)
      break;
    want = std::min(2 * want, cap);
  }
  if (free && n_zero > 6)
    throw InputError("the free-free structure has " + std::to_string(n_zero) +
                     " rigid-body modes (six expected): parts of the mesh move independently");
  if (free && n_zero < 6)
    throw SolverError("found " + std::to_string(n_zero) +
                      " of the six rigid-body modes of the free-free structure");
  if (!free && n_zero > 0)
    throw InputError("the fixed set leaves " + std::to_string(n_zero) +
                     " rigid-body modes (frequencies below " + std::to_string(r.near_zero) +
                     " Hz): hold more surfaces");
  r.rigid_body_modes = n_zero;

  const PETScWrappers::MPI::Vector w = e.dof_field([&](const Point<dim>& x, unsigned int c) {
    const Tensor<1, dim> y = (x - e.centre) / e.diagonal;
    return std::cos(1.3 + 2.1 * y[0] + 3.7 * y[1] + 5.3 * y[2] + 0.7 * c);
  });
  std::vector<PETScWrappers::MPI::Vector> zero, phi;
  std::vector<double> lambda;
  for (std::size_t k = 0; k < pairs.lambda.size(); ++k) {
    normalise(e, w, pairs.shapes[k]);
    if (k < n_zero) {
      zero.push_back(std::move(pairs.shapes[k]));
      continue;
    }
    const double f = std::sqrt(pairs.lambda[k]) / (2 * kPi);
    const unsigned int limit = p.count > 0 ? p.count : cap;
    if ((p.max_frequency > 0 && f > p.max_frequency) || phi.size() >= limit) continue;
    lambda.push_back(pairs.lambda[k]);
    phi.push_back(std::move(pairs.shapes[k]));
    r.frequencies.push_back(f);
  }
  if (phi.empty())
    throw InputError(
        "no elastic mode at or below max_frequency = " + std::to_string(p.max_frequency) + " Hz");
  const bool cut =
      p.max_frequency > 0 && std::sqrt(pairs.lambda.back()) / (2 * kPi) > p.max_frequency;
  r.limited_by = cut ? "max_frequency" : "count";
  if (free) r.rigid_body_span = rigid_span(e, zero);
  if (free && r.rigid_body_span > 1e-6)
    throw SolverError("the six near-zero modes do not span the rigid motions (a share of " +
                      std::to_string(r.rigid_body_span) + " outside)");
  std::tie(r.orthogonality_mass, r.orthogonality_stiffness) = orthogonality(e, phi, lambda);

  for (unsigned int d = 0; d < dim; ++d)
    for (const auto& v : phi) r.effective_mass[d].push_back(std::pow(v * e.mass_translation[d], 2));
  r.seat = e.seat_fits(phi);
  r.seat_centre = e.seat.centre();
  r.seat_area = e.seat.area;
  r.seat_nodes = e.seat_nodes;
  const auto values = e.sensor_values(phi);
  for (std::size_t s = 0; s < e.sensors.size(); ++s) {
    const Point<dim>& x = e.sensors[s].point;
    ElasticModesResult::Sensor sensor;
    sensor.point = to_vec3(x);
    sensor.distance = e.sensors[s].distance;
    sensor.displacement = values[s];
    r.sensors.push_back(sensor);
  }
  if (!p.frf_frequencies.empty()) r.frf = harmonic_response(e, p.frf_frequencies, !free);
  if (!p.vtu_file.empty()) write_vtu(e, phi, r.frequencies, p.vtu_file);
  r.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  pcout << "  " << r.frequencies.size() << " modes, " << r.frequencies.front() << " to "
        << r.frequencies.back() << " Hz, " << r.wall_time << " s" << std::endl;
  return r;
}

}  // namespace bearing::fem
