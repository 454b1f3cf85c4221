// gmsh on a .geo file (gmsh_run.h), as `bearing-fem contact --geometry groove` runs it on
// meshes/raceway_segment.geo (BEARING_GMSH is the gmsh CMake found).

#include "mesh/gmsh_run.h"

#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "bearing/errors.h"

namespace bearing::fem {

namespace {

std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// What gmsh said went wrong: its first two "Error" lines, or else its last three lines, joined
// by " | ".
std::string gmsh_complaint(const std::string& log) {
  std::ifstream in(log);
  std::vector<std::string> lines, errors;
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) continue;
    lines.push_back(line);
    if (line.find("Error") != std::string::npos && errors.size() < 2) errors.push_back(line);
  }
  const std::vector<std::string>& shown = errors.empty() ? lines : errors;
  std::string out;
  for (std::size_t k = shown.size() > 3 ? shown.size() - 3 : 0; k < shown.size(); ++k)
    out += (out.empty() ? "" : " | ") + shown[k];
  return out;
}

bool has_error(const std::string& log) {
  std::ifstream in(log);
  for (std::string line; std::getline(in, line);)
    if (line.compare(0, 9, "Error   :") == 0) return true;
  return false;
}

}  // namespace

void mesh_geo_file(const std::string& geo, const std::string& msh, const std::string& log,
                   MPI_Comm comm) {
  int rank = 0, status = 0;
  MPI_Comm_rank(comm, &rank);
  std::string why;
  if (rank == 0) {
    if (!std::ifstream(geo)) {
      status = 1;
      why = "cannot open it";
    } else {
      const std::string cmd = quoted(BEARING_GMSH) + " -3 -v 4 -format msh22 " + quoted(geo) +
                              " -o " + quoted(msh) + " > " + quoted(log) + " 2>&1";
      status = std::system(cmd.c_str());
      // gmsh 4.8 may exit with 0 after an error it printed ("Error   : ...").
      if (status == 0 && has_error(log)) status = 1;
      if (status != 0) why = "gmsh failed: " + gmsh_complaint(log);
    }
  }
  MPI_Bcast(&status, 1, MPI_INT, 0, comm);
  if (status != 0)
    throw InputError(geo + ": " + (rank == 0 ? why : std::string("gmsh failed (rank 0 says why)")));
}

}  // namespace bearing::fem
