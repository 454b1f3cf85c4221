#pragma once
// gmsh run on a .geo file (a structure file may name its geometry instead of a mesh): rank 0 runs
// `gmsh -3 -format msh22`, the other processes wait. No deal.II.

#include <string>

#include <mpi.h>

namespace bearing::fem {

/// Meshes `geo` into `msh` (MSH 2.2, 3-D) with gmsh's output in `log`, on rank 0 of `comm`
/// (collective). Throws InputError on every process if gmsh fails (rank 0's message ends with
/// the last lines of gmsh's output: a .geo file is the user's input).
void mesh_geo_file(const std::string& geo, const std::string& msh, const std::string& log,
                   MPI_Comm comm);

}  // namespace bearing::fem
