#pragma once
// The boundary of a plain bearing-sim (issue 31). bearing-sim links neither MPI, HDF5 nor
// libsndfile, so `run`, `info`, `presets`, a sweep on threads and the analysis of a CSV or NPY
// record start without loading them. What needs them — any command under mpirun (or srun),
// `sweep --save`, `sweep --resume` (its spool may hold a --save), merging parts that have
// sweep.h5, reading a .wav, .mat or .h5 record — is handed to bearing-sim-full, the same command
// line built with MPI, HDF5, matio and libsndfile beside it: exec, so the process (and under
// mpirun its rank) stays the same, with the same arguments. The user's command lines do not
// change.

#include <string>

namespace bearing_app {

/// The command line as main received it, for handing over to bearing-sim-full.
struct CommandLine {
  int argc = 0;
  char** argv = nullptr;
};

/// Whether this program hands work to bearing-sim-full (a plain bearing-sim of a build that has
/// MPI, HDF5, matio or libsndfile), or is the program that does everything itself.
bool hands_over();

/// Whether a parallel launcher (mpirun, srun) started this process: its variables are set.
bool launched_in_parallel();

/// Replaces this process by bearing-sim-full (beside this program) with the same arguments.
/// `why` says what needs it; when bearing-sim-full cannot be started, throws std::runtime_error
/// saying so (an installation fault: exit 1). Never returns otherwise.
[[noreturn]] void hand_over(const CommandLine& cl, const std::string& why);

}  // namespace bearing_app
