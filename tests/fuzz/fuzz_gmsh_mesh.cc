// Fuzz target: the gmsh mesh reader (fem/mesh/gmsh_mesh.h, no deal.II). The input is the text
// of a .msh file, parsed by parse_gmsh_mesh.
//
// After a successful parse it checks what gmsh_mesh.h promises of the mesh: at least one cell,
// every cell of the mesh's kind (4 or 8 vertices) with valid, distinct vertex indices and a
// positive volume (a tetrahedron's determinant, a hexahedron's Jacobian at vertex 0), every
// vertex finite, every face 3 or 4 valid vertices with sorted, unique, positive physical tags;
// mesh_parts numbers every cell with a part below the count it gives.

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_harness.h"
#include "mesh/gmsh_mesh.h"

namespace {

constexpr const char* kTarget = "fuzz_gmsh_mesh";
using P = std::array<double, 3>;

double det(const P& a, const P& b, const P& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
         a[2] * (b[0] * c[1] - b[1] * c[0]);
}
P minus(const P& a, const P& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

void check(const bearing::fem::GmshMesh& m) {
  using bearing::fuzz::property_failed;
  using CellType = bearing::fem::GmshMesh::CellType;
  if (m.cells.empty()) property_failed(kTarget, "a mesh without cells was accepted");
  for (const P& x : m.vertices)
    if (!(std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2])))
      property_failed(kTarget, "a vertex that is not finite was accepted");
  const std::size_t n = m.cell_type == CellType::tetrahedron ? 4 : 8;
  for (const auto& c : m.cells) {
    if (c.size() != n) property_failed(kTarget, "a cell with the wrong vertex count");
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (c[i] >= m.vertices.size()) property_failed(kTarget, "a cell vertex out of range");
      for (std::size_t j = 0; j < i; ++j)
        if (c[i] == c[j]) property_failed(kTarget, "a cell naming a vertex twice");
    }
    const P& x0 = m.vertices[c[0]];
    const double j = n == 4 ? det(minus(m.vertices[c[1]], x0), minus(m.vertices[c[2]], x0),
                                  minus(m.vertices[c[3]], x0))
                            : det(minus(m.vertices[c[1]], x0), minus(m.vertices[c[2]], x0),
                                  minus(m.vertices[c[4]], x0));
    if (!(j > 0)) property_failed(kTarget, "a cell without a positive volume was accepted");
  }
  unsigned int parts = 0;
  const std::vector<unsigned int> part = bearing::fem::mesh_parts(m, parts);
  if (part.size() != m.cells.size() || parts == 0 || parts > m.cells.size())
    property_failed(kTarget, "mesh_parts gave no part to a cell or too many parts");
  for (unsigned int p : part)
    if (p >= parts) property_failed(kTarget, "a cell's part beyond the count");
  parts_touching(m, part, parts, {1});
  for (const auto& f : m.faces) {
    if (f.vertices.size() != 3 && f.vertices.size() != 4)
      property_failed(kTarget, "a face with the wrong vertex count");
    for (unsigned v : f.vertices)
      if (v >= m.vertices.size()) property_failed(kTarget, "a face vertex out of range");
    if (f.physicals.empty()) property_failed(kTarget, "a face of no physical surface");
    for (std::size_t i = 0; i < f.physicals.size(); ++i)
      if (f.physicals[i] <= 0 || (i > 0 && f.physicals[i] <= f.physicals[i - 1]))
        property_failed(kTarget, "physical tags not positive, sorted and unique");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  bearing::fuzz::expect_only_input_errors(
      kTarget, [&] { check(bearing::fem::parse_gmsh_mesh(text, "fuzz.msh")); });
  return 0;
}
