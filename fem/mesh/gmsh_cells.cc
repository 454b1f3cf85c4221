// The gmsh reader's second half (gmsh_raw.h): each element added as it is read, then the cells
// put in deal.II's vertex order with a positive volume, the faces of the physical surfaces matched
// to the cells' faces, and the vertices renumbered.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "bearing/errors.h"
#include "mesh/gmsh_raw.h"

namespace bearing::fem::gmsh {

namespace {

constexpr ElementType kTypes[] = {
    {2, 1, 1, "2-node line"},
    {3, 2, 1, "3-node triangle"},
    {4, 2, 1, "4-node quadrangle"},
    {4, 3, 1, "4-node tetrahedron"},
    {8, 3, 1, "8-node hexahedron"},
    {6, 3, 1, "6-node prism"},
    {5, 3, 1, "5-node pyramid"},
    {3, 1, 2, "3-node second-order line"},
    {6, 2, 2, "6-node second-order triangle"},
    {9, 2, 2, "9-node second-order quadrangle"},
    {10, 3, 2, "10-node second-order tetrahedron"},
    {27, 3, 2, "27-node second-order hexahedron"},
    {18, 3, 2, "18-node second-order prism"},
    {14, 3, 2, "14-node second-order pyramid"},
    {1, 0, 1, "1-node point"},
    {8, 2, 2, "8-node second-order quadrangle"},
    {20, 3, 2, "20-node second-order hexahedron"},
    {15, 3, 2, "15-node second-order prism"},
    {13, 3, 2, "13-node second-order pyramid"},
    {9, 2, 3, "9-node third-order triangle"},
    {10, 2, 3, "10-node third-order triangle"},
    {12, 2, 4, "12-node fourth-order triangle"},
    {15, 2, 4, "15-node fourth-order triangle"},
    {15, 2, 5, "15-node fifth-order triangle"},
    {21, 2, 5, "21-node fifth-order triangle"},
    {4, 1, 3, "4-node third-order line"},
    {5, 1, 4, "5-node fourth-order line"},
    {6, 1, 5, "6-node fifth-order line"},
    {20, 3, 3, "20-node third-order tetrahedron"},
    {35, 3, 4, "35-node fourth-order tetrahedron"},
    {56, 3, 5, "56-node fifth-order tetrahedron"},
};
constexpr long long kTetrahedron = 4, kHexahedron = 5;

// gmsh's hexahedron (bottom face counter-clockwise, then the top one) to deal.II's lexicographic
// order: deal.II vertex i is gmsh vertex kHexFromGmsh[i].
constexpr int kHexFromGmsh[8] = {0, 1, 3, 2, 4, 5, 7, 6};

// The faces of deal.II's reference cells, each in the cell's own order for that face.
constexpr int kTetFaces[4][3] = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
constexpr int kHexFaces[6][4] = {{0, 2, 4, 6}, {1, 3, 5, 7}, {0, 1, 4, 5},
                                 {2, 3, 6, 7}, {0, 1, 2, 3}, {4, 5, 6, 7}};

using Point = std::array<double, 3>;
using Key = std::array<std::size_t, 4>;  // a face's sorted nodes (a triangle's 4th: max)

Point minus(const Point& a, const Point& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
double det(const Point& a, const Point& b, const Point& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
         a[2] * (b[0] * c[1] - b[1] * c[0]);
}
double length(const Point& a) {
  return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

Key key_of(const std::vector<std::size_t>& nodes) {
  Key k;
  k.fill(std::numeric_limits<std::size_t>::max());
  std::copy(nodes.begin(), nodes.end(), k.begin());
  std::sort(k.begin(), k.end());
  return k;
}

[[noreturn]] void fail_at(const std::string& file, int line, const std::string& what) {
  throw InputError(file + ":" + std::to_string(line) + ": " + what);
}

// The longest edge of a cell's bounding box: the scale a volume is judged against.
double size_of(const RawMesh& raw, const std::vector<std::size_t>& nodes) {
  double s = 0;
  for (std::size_t a = 1; a < nodes.size(); ++a)
    s = std::max(s, length(minus(raw.nodes[nodes[a]], raw.nodes[nodes[0]])));
  return s;
}

// A tetrahedron with a positive volume: two vertices swapped where it had a negative one.
// Returns whether it was turned over; fails on a flat one (|6V| <= 1e-12 of its size cubed).
bool orient_tetrahedron(const RawMesh& raw, RawCell& c, const std::string& file) {
  const Point& p0 = raw.nodes[c.nodes[0]];
  const double v6 = det(minus(raw.nodes[c.nodes[1]], p0), minus(raw.nodes[c.nodes[2]], p0),
                        minus(raw.nodes[c.nodes[3]], p0));
  const double s = size_of(raw, c.nodes);
  if (!(std::fabs(v6) > 1e-12 * s * s * s))
    fail_at(file, c.line, "a tetrahedron of zero volume (its four nodes lie in one plane)");
  if (v6 > 0) return false;
  std::swap(c.nodes[2], c.nodes[3]);
  return true;
}

// A hexahedron in deal.II's order with a positive Jacobian at every vertex: its two z faces
// exchanged where all eight were negative. Fails on a flat, tangled or non-convex one.
bool orient_hexahedron(const RawMesh& raw, RawCell& c, const std::string& file) {
  std::vector<std::size_t> lex(8);
  for (int i = 0; i < 8; ++i) lex[i] = c.nodes[kHexFromGmsh[i]];
  c.nodes = lex;
  const double s = size_of(raw, c.nodes);
  int positive = 0, negative = 0;
  for (std::size_t v = 0; v < 8; ++v) {
    // The three edges leaving vertex v, each pointing in +x, +y, +z of the reference cell.
    Point e[3];
    for (std::size_t d = 0; d < 3; ++d) {
      const std::size_t bit = std::size_t(1) << d;
      e[d] = minus(raw.nodes[c.nodes[v | bit]], raw.nodes[c.nodes[v & ~bit]]);
    }
    const double j = det(e[0], e[1], e[2]);
    if (j > 1e-12 * s * s * s)
      ++positive;
    else if (j < -1e-12 * s * s * s)
      ++negative;
  }
  if (positive == 8) return false;
  if (negative != 8)
    fail_at(file, c.line,
            "a hexahedron that is flat, tangled or not convex (its vertices' Jacobians have "
            "different signs or vanish; gmsh's node order is bottom face, then top face, each "
            "counter-clockwise)");
  std::rotate(c.nodes.begin(), c.nodes.begin() + 4, c.nodes.end());
  return true;
}

// "a 6-node prism", "an 8-node hexahedron".
std::string a_(const ElementType& et) {
  const std::string n = et.name;
  const bool an = n[0] == '8' || n.compare(0, 2, "11") == 0 || n.compare(0, 2, "18") == 0;
  return (an ? "an " : "a ") + n;
}

}  // namespace

const ElementType& element_type(long long type, const Lines& lines) {
  if (type < 1 || type > static_cast<long long>(std::size(kTypes)))
    lines.fail("element type " + std::to_string(type) +
               ": not a gmsh element type this reader knows (1-31)");
  return kTypes[type - 1];
}

void add_element(const Lines& lines, RawMesh& raw, long long type,
                 const std::vector<long long>& nodes, const std::vector<int>& physicals) {
  const ElementType& et = element_type(type, lines);
  if (et.order > 1)
    lines.fail(a_(et) +
               ": this reader takes first-order elements (gmsh's default Mesh.ElementOrder = "
               "1); the FE degree is bearing-fem's --degree");
  if (et.dimension < 2) return;
  std::vector<std::size_t> index;
  for (long long tag : nodes) {
    const auto it = raw.node_index.find(tag);
    if (it == raw.node_index.end())
      lines.fail("the element names node " + std::to_string(tag) +
                 ", which $Nodes does not define");
    if (std::find(index.begin(), index.end(), it->second) != index.end())
      lines.fail("the element names node " + std::to_string(tag) + " twice");
    index.push_back(it->second);
  }
  if (et.dimension == 2) {
    if (!physicals.empty()) raw.faces.push_back({std::move(index), physicals, lines.number()});
    return;
  }
  if (type != kTetrahedron && type != kHexahedron)
    lines.fail(a_(et) +
               " in the volume: this reader takes 4-node tetrahedra or 8-node hexahedra "
               "(gmsh's default 3-D mesh is tetrahedra)");
  if (raw.cell_type != 0 && raw.cell_type != type)
    lines.fail(a_(et) + " in a mesh whose first volume element (line " +
               std::to_string(raw.cell_type_line) +
               ") is of the other kind: tetrahedra and hexahedra cannot be mixed");
  if (raw.cell_type == 0) raw.cell_type = type, raw.cell_type_line = lines.number();
  raw.cells.push_back({std::move(index), lines.number()});
}

GmshMesh finish_mesh(RawMesh raw, const std::string& file) {
  if (raw.cells.empty())
    throw InputError(file +
                     ": no volume elements (tetrahedra or hexahedra): mesh the volume (gmsh -3); "
                     "when physical groups are defined gmsh saves only their elements, so the "
                     "volume needs a Physical Volume (or Mesh.SaveAll = 1)");
  GmshMesh mesh;
  mesh.file = file;
  mesh.version = raw.version;
  mesh.names = std::move(raw.names);
  const bool tets = raw.cell_type == kTetrahedron;
  mesh.cell_type = tets ? GmshMesh::CellType::tetrahedron : GmshMesh::CellType::hexahedron;

  // The cells: each once (MSH 2.2 writes an element once per physical group it is in), oriented.
  std::set<std::vector<std::size_t>> seen;
  std::vector<RawCell> cells;
  for (RawCell& c : raw.cells) {
    std::vector<std::size_t> sorted = c.nodes;
    std::sort(sorted.begin(), sorted.end());
    if (!seen.insert(std::move(sorted)).second) continue;
    if (tets ? orient_tetrahedron(raw, c, file) : orient_hexahedron(raw, c, file))
      ++mesh.turned_over_cells;
    cells.push_back(std::move(c));
  }

  // The faces of physical surfaces, each once with all its physical tags, matched to a cell face
  // (whose vertex order it takes).
  std::map<Key, std::size_t> face_of;
  std::vector<RawFace> faces;
  for (RawFace& f : raw.faces) {
    const auto [it, added] = face_of.emplace(key_of(f.nodes), faces.size());
    if (added) {
      faces.push_back(std::move(f));
      faces.back().nodes.clear();  // filled from the cell below
    } else {
      std::vector<int>& p = faces[it->second].physicals;
      p.insert(p.end(), f.physicals.begin(), f.physicals.end());
    }
  }
  std::vector<std::size_t> face_nodes;
  for (const RawCell& c : cells) {
    const std::size_t n_faces = tets ? 4 : 6, per_face = tets ? 3 : 4;
    for (std::size_t k = 0; k < n_faces; ++k) {
      face_nodes.clear();
      for (std::size_t v = 0; v < per_face; ++v)
        face_nodes.push_back(c.nodes[tets ? kTetFaces[k][v] : kHexFaces[k][v]]);
      const auto it = face_of.find(key_of(face_nodes));
      if (it != face_of.end() && faces[it->second].nodes.empty())
        faces[it->second].nodes = face_nodes;
    }
  }
  for (const RawFace& f : faces)
    if (f.nodes.empty())
      fail_at(
          file, f.line,
          std::string("this surface element is no face of a volume element (") +
              (tets ? "tetrahedra have triangular faces" : "hexahedra have quadrilateral faces") +
              "; the surface and the volume must be meshed together, gmsh -3)");

  // The vertices of the cells, renumbered from 0 in the order the file lists them.
  std::vector<std::size_t> new_index(raw.nodes.size(), std::numeric_limits<std::size_t>::max());
  for (const RawCell& c : cells)
    for (std::size_t n : c.nodes) new_index[n] = 0;
  for (std::size_t n = 0; n < raw.nodes.size(); ++n)
    if (new_index[n] == 0) {
      new_index[n] = mesh.vertices.size();
      mesh.vertices.push_back(raw.nodes[n]);
    }
  for (const RawCell& c : cells) {
    std::vector<unsigned int> v;
    for (std::size_t n : c.nodes) v.push_back(static_cast<unsigned int>(new_index[n]));
    mesh.cells.push_back(std::move(v));
  }
  for (RawFace& f : faces) {
    MeshFace m;
    for (std::size_t n : f.nodes) m.vertices.push_back(static_cast<unsigned int>(new_index[n]));
    std::sort(f.physicals.begin(), f.physicals.end());
    f.physicals.erase(std::unique(f.physicals.begin(), f.physicals.end()), f.physicals.end());
    m.physicals = std::move(f.physicals);
    mesh.faces.push_back(std::move(m));
  }
  return mesh;
}

}  // namespace bearing::fem::gmsh
