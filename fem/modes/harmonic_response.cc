// The seat's harmonic response by a direct solve (harmonic_response.h): the reference the modal
// model of modes.json is verified against (bearing-verify, structure.frf.*).
//
// For a unit force along e_d spread uniformly over the seat (traction e_d/A), the load vector is
// F_d,i = ∫_seat φ_i · e_d dA / A, and the undamped steady response at ω solves
//     (K − ω² M) u = F_d.
// Its seat motion is the rigid fit of u (seat_fit.h). Expanded in the mass-normalised modes,
//     u = Σ_k φ_k (φ_kᵀ F_d) / (ω_k² − ω²),   φ_kᵀ F_d = t_k · e_d   (the fit's translation of
//     φ_k),
// so the seat's translation along e is Σ_k (t_k·e)(t_k·e_d)/(ω_k² − ω²): the modal model. The two
// agree when every mode is kept; the modes left out contribute what the static solve K u = F_d
// (ω = 0, a fixed structure only: a free one has no static response) has beyond the kept modes'
// static sum Σ_k (t_k·e)(t_k·e_d)/ω_k², the residual flexibility. Each solve factorises
// K − ω²M (symmetric, indefinite above the first mode) by MUMPS's LDLᵀ.

#include "modes/harmonic_response.h"

#include <petscksp.h>

#include <cmath>
#include <string>

#include "bearing/errors.h"
#include "modes/elastic_problem.h"

namespace bearing::fem::modes {

namespace {

#define BEARING_PETSC_CALL(call)                                             \
  do {                                                                       \
    const PetscErrorCode petsc_error_ = (call);                              \
    if (petsc_error_)                                                        \
      throw SolverError(std::string("PETSc: ") + #call + " failed (error " + \
                        std::to_string(petsc_error_) + ")");                 \
  } while (false)

// u_d = (K − ω²M)⁻¹ F_d for both loads, one MUMPS factorisation.
std::vector<PETScWrappers::MPI::Vector> solve(const ElasticProblem& e, double omega,
                                              const std::vector<PETScWrappers::MPI::Vector>& f) {
  Mat a;
  BEARING_PETSC_CALL(MatDuplicate(static_cast<Mat>(e.stiffness), MAT_COPY_VALUES, &a));
  KSP ksp = nullptr;
  std::vector<PETScWrappers::MPI::Vector> u;
  try {
    if (omega > 0)
      BEARING_PETSC_CALL(
          MatAXPY(a, -omega * omega, static_cast<Mat>(e.mass), SAME_NONZERO_PATTERN));
    BEARING_PETSC_CALL(KSPCreate(e.comm, &ksp));
    BEARING_PETSC_CALL(KSPSetOperators(ksp, a, a));
    BEARING_PETSC_CALL(KSPSetType(ksp, KSPPREONLY));
    PC pc;
    BEARING_PETSC_CALL(KSPGetPC(ksp, &pc));
    BEARING_PETSC_CALL(PCSetType(pc, PCCHOLESKY));
    BEARING_PETSC_CALL(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
    BEARING_PETSC_CALL(KSPSetUp(ksp));
    for (const auto& b : f) {
      u.emplace_back(e.owned, e.comm);
      BEARING_PETSC_CALL(
          KSPSolve(ksp, static_cast<const Vec&>(b), static_cast<const Vec&>(u.back())));
      KSPConvergedReason reason;
      BEARING_PETSC_CALL(KSPGetConvergedReason(ksp, &reason));
      if (reason < 0)
        throw SolverError("the direct harmonic solve at " + std::to_string(omega / (2 * M_PI)) +
                          " Hz failed (a frequency on a mode, K - w^2 M singular?)");
    }
  } catch (...) {
    if (ksp) KSPDestroy(&ksp);
    MatDestroy(&a);
    throw;
  }
  KSPDestroy(&ksp);
  MatDestroy(&a);
  return u;
}

}  // namespace

HarmonicResponse harmonic_response(const ElasticProblem& e, const std::vector<double>& frequencies,
                                   bool fixed) {
  HarmonicResponse h;
  h.frequencies = frequencies;
  const std::vector<PETScWrappers::MPI::Vector> f{e.seat_load(0), e.seat_load(1)};
  for (double hz : frequencies) {
    const auto fits = e.seat_fits(solve(e, 2 * M_PI * hz, f));
    for (int d = 0; d < 2; ++d) h.direct[d].push_back(fits[d]);
  }
  h.has_static = fixed;
  if (fixed) {
    const auto fits = e.seat_fits(solve(e, 0, f));
    h.static_response[0] = fits[0];
    h.static_response[1] = fits[1];
  }
  return h;
}

}  // namespace bearing::fem::modes
