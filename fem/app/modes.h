#pragma once
// `bearing-fem modes`: the natural modes of an elastic structure from a gmsh mesh (modes.cc).

#include <string>
#include <vector>

#include <mpi.h>

namespace CLI {
class App;
}

namespace bearing::fem {

struct ModesOptions {
  std::string structure;  ///< the structure file (fem/modes/structure_file.h)
  std::string out_dir;
  unsigned int degree = 2;       ///< FE degree (P2: P1 tetrahedra lock in bending)
  unsigned int refinements = 0;  ///< global refinements of the gmsh mesh
  unsigned int count = 0;        ///< > 0: overrides [modes] count
  double max_frequency = 0;      ///< > 0: overrides [modes] max_frequency [Hz]
  double tolerance = 1e-10;      ///< SLEPc's relative tolerance
  std::vector<double> frf;       ///< frequencies of the direct harmonic solves [Hz]
  bool vtu = true;
  bool quiet = false;
};

/// Adds the `modes` subcommand to `app`, filling `o`.
CLI::App* add_modes_command(CLI::App& app, ModesOptions& o);

/// Runs `modes`: writes DIR/modes.json, DIR/modes.vtu (unless --no-vtu) and with --frf
/// DIR/frf.json, all or nothing (AtomicFileSet on rank 0, modes.json last). Throws InputError
/// for bad input (before any file is written), OutputError when a file cannot be written,
/// SolverError when the eigensolver fails; FailedOnRankZero on the other ranks.
int run_modes(const ModesOptions& o, MPI_Comm comm);

}  // namespace bearing::fem
