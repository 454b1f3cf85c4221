#pragma once
// A gmsh mesh file (.msh, ASCII, versions 2.2 and 4.1) as the FE solvers take it: the vertices,
// the volume cells (4-node tetrahedra or 8-node hexahedra, in deal.II's vertex order and with a
// positive volume), the boundary faces that belong to a physical surface, and the physical names.
//
// Plain C++ (no deal.II): it is a reader of outside files, so it is built with or without deal.II
// and fuzzed (tests/fuzz/fuzz_gmsh_mesh.cc) in the sanitizer builds, which have no deal.II. Bad
// input of any kind throws bearing::InputError naming the file, the line and what is wrong.
//
// What is read, and what is refused:
// - $MeshFormat 2.2 or 4.1 with file-type 0 (ASCII). Binary files, other versions and partitioned
//   4.1 files ($PartitionedEntities) are refused.
// - $PhysicalNames (optional): dimension, tag, "name".
// - $Entities (4.1): the physical tags of each surface and volume entity.
// - $Nodes: coordinates as written (the caller scales them: mesh_unit). Tags may be sparse.
// - $Elements: 3-D elements must all be 4-node tetrahedra (type 4) or all 8-node hexahedra (type
//   5); anything else in the volume (prisms, pyramids, second-order elements, a mix of the two) is
//   refused. 2-D elements (3-node triangles, 4-node quadrilaterals) are kept when they belong to
//   a physical surface and must be a face of a volume cell. Points and lines are skipped. A
//   second-order element anywhere is refused (the FE degree is the solver's option, not the
//   mesh's).
// - Other sections ($NodeData, $Periodic, ...) are skipped.
// Then: at least one volume cell; every node an element names exists; every cell has a non-zero
// volume (a tetrahedron or hexahedron written with a negative one is turned over: two vertices
// of a tetrahedron swapped, the two end faces of a hexahedron exchanged); every face of a
// physical surface is a face of a cell (a face may lie in several physical surfaces). An element
// written twice (MSH 2.2 repeats an element once per physical group) is kept once. Only the
// vertices of volume cells are kept, renumbered from 0 in the order the file lists them.

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace bearing::fem {

/// One name of $PhysicalNames.
struct PhysicalName {
  int dimension = 0;  ///< 2 a physical surface, 3 a physical volume, ...
  int tag = 0;        ///< the physical tag (> 0)
  std::string name;
};

/// A face of one or more physical surfaces: a triangle (3 vertices) or a quadrilateral (4), its
/// vertices in the order of the face of the cell it belongs to (deal.II's lexicographic order for
/// a quadrilateral).
struct MeshFace {
  std::vector<unsigned int> vertices;  ///< indices into GmshMesh::vertices
  std::vector<int> physicals;          ///< the physical surfaces' tags (> 0), sorted, unique
};

struct GmshMesh {
  enum class CellType { tetrahedron, hexahedron };

  std::string file;     ///< as given to the reader (messages)
  std::string version;  ///< "2.2" or "4.1"
  CellType cell_type = CellType::tetrahedron;
  std::vector<std::array<double, 3>> vertices;  ///< coordinates as written in the file
  /// Each cell's vertices: 4 (tetrahedron) or 8 (hexahedron, deal.II's lexicographic order:
  /// x fastest, then y, then z, on the reference cell), with a positive volume.
  std::vector<std::vector<unsigned int>> cells;
  std::vector<MeshFace> faces;        ///< faces of physical surfaces, each face once
  std::vector<PhysicalName> names;    ///< $PhysicalNames, in the file's order
  std::size_t turned_over_cells = 0;  ///< cells written with a negative volume and turned over

  /// The tag of the physical surface called `name`, or 0 if there is none.
  int surface_tag(std::string_view name) const;
  /// The names of the physical surfaces, in the file's order ("none" if there are none).
  std::string surface_names() const;
  /// "tetrahedron" or "hexahedron".
  const char* cell_type_name() const;
};

/// The separate parts of the mesh, cells joined through shared vertices: each cell's part,
/// numbered from 0 in the order of the parts' first cells; `parts` is their count.
std::vector<unsigned int> mesh_parts(const GmshMesh& mesh, unsigned int& parts);

/// Whether each part (mesh_parts) has a face in one of the physical surfaces `tags`.
std::vector<bool> parts_touching(const GmshMesh& mesh, const std::vector<unsigned int>& part,
                                 unsigned int parts, const std::vector<int>& tags);

/// Parses the text of a .msh file; `file` names it in messages. Throws InputError.
GmshMesh parse_gmsh_mesh(std::string_view text, const std::string& file);

/// Reads and parses the .msh file at `path`. Throws InputError (also if it cannot be read).
GmshMesh read_gmsh_mesh(const std::string& path);

}  // namespace bearing::fem
