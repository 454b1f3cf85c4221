#pragma once
// `mpirun -np N bearing-sim sweep …`: the cases of a sweep dealt to MPI ranks (issue 20).
//
// Built only when CMake finds MPI (library bearing_sweep_mpi, BEARING_WITH_MPI defined for its
// users). MPI must be initialised (MPI_Init_thread with at least MPI_THREAD_FUNNELED: only the
// calling thread of each rank talks MPI; the others run cases).

#include <cstddef>
#include <functional>

#include "bearing/sweep.h"

namespace bearing {

/// run_sweep across the ranks of MPI_COMM_WORLD. Every rank calls it with the same arguments
/// (`threads` may differ per rank). Cases are dealt dynamically: rank 0 hands out case indices
/// one at a time to whichever rank asks (a rank keeps `threads` + 1 cases asked for or in hand,
/// so a thread that finishes finds the next case waiting), runs cases on its own `threads` workers
/// too, receives the other ranks' rows and hands every row to `sink(i, row)` in case order,
/// serialised, on rank 0 only; `progress` is called on rank 0 only. The rows are those of run_sweep
/// with one thread, bit for bit (the same code runs each case). Memory does not grow with `cases`:
/// no case is handed out more than 4 × (workers of all ranks) cases ahead of the oldest unfinished
/// one, so rank 0 holds at most that many finished rows. Other ranks return when there is no case
/// left for them. With one rank it is run_sweep. `threads` = 0: the cores of this node shared among
/// its ranks.
///
/// An exception from `sink` stops the dealing; rank 0 rethrows it once every rank has finished
/// its cases in hand. A failed case is reported in its row, as in run_sweep. Any other error
/// (MPI, decoding) throws on the rank that sees it; the caller should then MPI_Abort.
void run_sweep_mpi(const SweepLoader& load, std::size_t cases,
                   const std::function<SweepPoint(std::size_t)>& point, int threads,
                   const std::function<void(std::size_t, SweepRow&&)>& sink,
                   const SweepProgress& progress = {}, const std::vector<SweepSave>& save = {});

/// This process's rank in MPI_COMM_WORLD and the world's size (0 and 1 before MPI_Init).
int mpi_rank();
int mpi_size();

}  // namespace bearing
