#pragma once
// Private to the gmsh reader: the nodes and elements as the sections give them (gmsh_mesh.cc),
// before the cells are checked and the faces matched to them (gmsh_cells.cc).

#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "mesh/gmsh_mesh.h"
#include "mesh/gmsh_text.h"

namespace bearing::fem::gmsh {

/// A gmsh element type: its node count, dimension and order.
struct ElementType {
  int nodes;
  int dimension;
  int order;
  const char* name;
};

/// The type `type` (1-31, gmsh's numbering); fails on `lines` for any other.
const ElementType& element_type(long long type, const Lines& lines);

/// A volume element as read: its nodes (indices into RawMesh::nodes, gmsh's order).
struct RawCell {
  std::vector<std::size_t> nodes;
  int line;
};

/// A surface element of a physical surface as read.
struct RawFace {
  std::vector<std::size_t> nodes;
  std::vector<int> physicals;
  int line;
};

struct RawMesh {
  std::string version;
  std::vector<std::array<double, 3>> nodes;
  std::unordered_map<long long, std::size_t> node_index;  ///< node tag -> index into nodes
  long long cell_type = 0;                                ///< 4 or 5 once a cell is read
  int cell_type_line = 0;
  std::vector<RawCell> cells;
  std::vector<RawFace> faces;
  std::map<std::pair<int, int>, std::vector<int>> entity_physicals;  ///< (dim, tag) -> tags (4.1)
  std::vector<PhysicalName> names;
};

/// Adds the element of type `type` with node tags `nodes` and physical tags `physicals` (line
/// `lines.number()`): a volume cell, a face of a physical surface, or nothing (points, lines,
/// faces of no physical surface). Fails on a node that $Nodes does not define, a second-order
/// element, a 3-D element that is not the mesh's one kind of tetrahedron or hexahedron.
void add_element(const Lines& lines, RawMesh& raw, long long type,
                 const std::vector<long long>& nodes, const std::vector<int>& physicals);

/// The mesh: cells in deal.II's order with a positive volume, faces matched to the cells, the
/// vertices of the cells only. Throws InputError (naming `file` and the element's line).
GmshMesh finish_mesh(RawMesh raw, const std::string& file);

}  // namespace bearing::fem::gmsh
