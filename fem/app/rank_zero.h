#pragma once
// Output steps that rank 0 does alone (the output folder, its lock, temporary folders), and how
// the other ranks learn that one failed: without it they would wait for rank 0 forever inside the
// solver's next collective call.

#include <deal.II/base/mpi.h>

#include <exception>

#include <mpi.h>

#include "bearing/errors.h"

namespace bearing::fem {

/// What the ranks other than 0 throw when a step of rank 0 failed (rank 0 prints why): they end
/// with its exit status, silently.
struct FailedOnRankZero {
  int status;  ///< 2 bad input, 3 output error, 1 anything else
};

/// Runs `step` on rank 0 of `comm` alone and tells every rank how it went (collective): rank 0
/// rethrows what `step` threw, the others throw FailedOnRankZero with its exit status.
template <class Step>
void on_rank_zero(MPI_Comm comm, const Step& step) {
  int status = 0;
  std::exception_ptr error;
  if (dealii::Utilities::MPI::this_mpi_process(comm) == 0) {
    try {
      step();
    } catch (const InputError&) {
      error = std::current_exception(), status = 2;
    } catch (const OutputError&) {
      error = std::current_exception(), status = 3;
    } catch (...) {
      error = std::current_exception(), status = 1;
    }
  }
  MPI_Bcast(&status, 1, MPI_INT, 0, comm);
  if (error) std::rethrow_exception(error);
  if (status != 0) throw FailedOnRankZero{status};
}

}  // namespace bearing::fem
