#pragma once
// The structure file of `bearing-fem modes` (fem/README.md, "Natural modes"): a TOML file naming
// a gmsh mesh of an elastic structure (a housing, an end shield), its material, the physical
// surfaces held fixed and the one the bearing sits in, named sensor points and how many modes to
// compute. Units as in case files ("210 GPa", "7850 kg/m^3", "20 kHz"; a bare number is SI).
//
//   mesh = "housing.msh"     # gmsh .msh 2.2 or 4.1, or a .geo gmsh meshes (-3) at run time;
//                            # relative to this file
//   mesh_unit = "mm"         # m (default) or mm: the mesh's and the sensors' coordinates
//   [material]
//   young = "210 GPa"        # (0, 1e13] Pa
//   poisson = 0.3            # [0, 0.5)
//   density = "7850 kg/m^3"  # (0, 1e5] kg/m^3
//   [boundary]
//   fixed = ["bolts"]        # physical surfaces held (u = 0); [] or absent: free-free
//   seat = "seat"            # the physical surface the bearing's outer ring sits in (required)
//   [sensors]                # name = [x, y, z] in mesh units; names [A-Za-z0-9_]+
//   top = [0, 60, 0]
//   [modes]
//   count = 20               # 1-500; and/or
//   max_frequency = "20 kHz" # (0, 1e7] Hz; neither given: count = 20
//
// Plain C++ (toml++ and the lumped core's units, no deal.II): it reads a user's file, so it is
// fuzzed (tests/fuzz/fuzz_structure_file.cc) in the sanitizer builds, which have no deal.II. Bad
// input throws bearing::InputError with one line naming the file, the key, the value and what is
// allowed.

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace bearing::fem {

struct GmshMesh;

/// The ranges the reader enforces (the options' ranges of `bearing-fem modes` are its own).
struct StructureLimits {
  static constexpr double max_young = 1e13;         ///< [Pa]
  static constexpr double max_density = 1e5;        ///< [kg/m^3]
  static constexpr unsigned int max_count = 500;    ///< modes
  static constexpr double max_frequency = 1e7;      ///< [Hz]
  static constexpr unsigned int max_sensors = 100;  ///< sensors
  static constexpr unsigned int max_fixed = 64;     ///< fixed surfaces
  static constexpr double max_coordinate = 1e9;     ///< |sensor coordinate| in mesh units
};

/// A named point where the displacement of every mode is reported.
struct StructureSensor {
  std::string name;                 ///< [A-Za-z0-9_]+, unique
  std::array<double, 3> point{};    ///< [m]
  std::array<double, 3> written{};  ///< as written, in mesh units
};

struct StructureFile {
  std::string source;              ///< the file as given (messages, modes.json's "structure")
  std::string mesh;                ///< the mesh file as written
  std::string mesh_path;           ///< the mesh file, relative to the structure file's folder
  std::string mesh_unit = "m";     ///< "m" or "mm"
  double mesh_scale = 1;           ///< metres per mesh unit [m]
  double young = 0;                ///< Young's modulus E [Pa]
  double poisson = 0;              ///< Poisson's ratio nu [-]
  double density = 0;              ///< rho [kg/m^3]
  std::vector<std::string> fixed;  ///< physical surfaces held; empty: free-free
  std::string seat;                ///< the physical surface of the bearing seat
  std::vector<StructureSensor> sensors;
  unsigned int count = 0;    ///< modes wanted; 0: not given (max_frequency is)
  double max_frequency = 0;  ///< [Hz]; 0: not given
};

/// Parses the text of a structure file; `source` is its path (messages; the mesh is relative to
/// its folder). Throws InputError.
StructureFile parse_structure(std::string_view text, const std::string& source);

/// Reads and parses the structure file at `path`. Throws InputError.
StructureFile read_structure_file(const std::string& path);

/// Checks the file's surfaces against the mesh: each fixed one and the seat a physical surface
/// of it (the message lists the mesh's physical surfaces), the seat not held. Throws InputError.
void check_structure_against_mesh(const StructureFile& s, const GmshMesh& mesh);

}  // namespace bearing::fem
