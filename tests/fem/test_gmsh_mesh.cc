// The gmsh reader of fem/mesh/ (no deal.II): files gmsh 4.8 wrote (tests/fuzz/corpus/gmsh_mesh/,
// made by tests/fuzz/make_mesh_seeds.sh) read in both versions, hexahedra in deal.II's order, cells
// turned over where written inside out, physical surfaces, and every kind of bad file refused with
// a message naming the file and the line.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "bearing/errors.h"
#include "mesh/gmsh_mesh.h"

namespace bearing::fem {
namespace {

const std::string kSeeds = BEARING_SOURCE_DIR "/tests/fuzz/corpus/gmsh_mesh/";

// The message of the InputError `f` throws ("" if it throws none).
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

using P = std::array<double, 3>;
P minus(const P& a, const P& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
double det(const P& a, const P& b, const P& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
         a[2] * (b[0] * c[1] - b[1] * c[0]);
}

// Signed volume of a cell in deal.II's order: a tetrahedron's, or a hexahedron's as the sum of
// the six tetrahedra of its main diagonal 0-7 (exact for a parallelepiped).
double volume(const GmshMesh& m, const std::vector<unsigned int>& c) {
  const auto& x = m.vertices;
  if (c.size() == 4)
    return det(minus(x[c[1]], x[c[0]]), minus(x[c[2]], x[c[0]]), minus(x[c[3]], x[c[0]])) / 6;
  double v = 0;
  const int path[6][2] = {{1, 3}, {3, 2}, {2, 6}, {6, 4}, {4, 5}, {5, 1}};
  for (const auto& p : path)
    v += det(minus(x[c[p[0]]], x[c[0]]), minus(x[c[p[1]]], x[c[0]]), minus(x[c[7]], x[c[0]])) / 6;
  return v;
}

double total_volume(const GmshMesh& m) {
  double v = 0;
  for (const auto& c : m.cells) {
    const double cv = volume(m, c);
    EXPECT_GT(cv, 0);
    v += cv;
  }
  return v;
}

std::size_t faces_in(const GmshMesh& m, const std::string& name) {
  const int tag = m.surface_tag(name);
  return std::count_if(m.faces.begin(), m.faces.end(), [&](const MeshFace& f) {
    return std::find(f.physicals.begin(), f.physicals.end(), tag) != f.physicals.end();
  });
}

// The area of the faces of physical surface `name`.
double area_of(const GmshMesh& m, const std::string& name) {
  const int tag = m.surface_tag(name);
  double area = 0;
  for (const MeshFace& f : m.faces) {
    if (std::find(f.physicals.begin(), f.physicals.end(), tag) == f.physicals.end()) continue;
    const auto& x = m.vertices;
    const auto tri = [&](unsigned a, unsigned b, unsigned c) {
      const P u = minus(x[b], x[a]), v = minus(x[c], x[a]);
      const P n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
      return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    };
    const auto& v = f.vertices;
    area += v.size() == 3 ? tri(v[0], v[1], v[2]) : tri(v[0], v[1], v[3]) + tri(v[0], v[3], v[2]);
  }
  return area;
}

TEST(GmshMesh, TetrahedraInBothVersionsAreTheSameMesh) {
  const GmshMesh a = read_gmsh_mesh(kSeeds + "box_tetrahedra_22.msh");
  const GmshMesh b = read_gmsh_mesh(kSeeds + "box_tetrahedra_41.msh");
  EXPECT_EQ(a.version, "2.2");
  EXPECT_EQ(b.version, "4.1");
  for (const GmshMesh* m : {&a, &b}) {
    EXPECT_EQ(m->cell_type, GmshMesh::CellType::tetrahedron);
    EXPECT_NEAR(total_volume(*m), 20.0 * 10 * 6, 1e-9);  // the box, exactly
    EXPECT_NEAR(area_of(*m, "fixed"), 10.0 * 6, 1e-9);   // the face x = 0
    EXPECT_NEAR(area_of(*m, "seat"), 10.0 * 6, 1e-9);    // the face x = 20
    EXPECT_EQ(m->surface_names(), "\"fixed\", \"seat\"");
    EXPECT_EQ(m->surface_tag("body"), 0);  // a volume, not a surface
    EXPECT_EQ(m->turned_over_cells, 0u);
  }
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.cells, b.cells);
  EXPECT_EQ(a.faces.size(), b.faces.size());
}

TEST(GmshMesh, HexahedraAreInDealIIsLexicographicOrder) {
  for (const char* file : {"box_hexahedra_22.msh", "box_hexahedra_41.msh"}) {
    const GmshMesh m = read_gmsh_mesh(kSeeds + file);
    EXPECT_EQ(m.cell_type, GmshMesh::CellType::hexahedron);
    ASSERT_EQ(m.cells.size(), 2u) << file;
    for (const auto& c : m.cells) {
      // Vertex 1 lies along +x of vertex 0, 2 along +y, 4 along +z; 3 = 1 + 2 - 0.
      const auto& x = m.vertices;
      const P ex = minus(x[c[1]], x[c[0]]), ey = minus(x[c[2]], x[c[0]]),
              ez = minus(x[c[4]], x[c[0]]);
      EXPECT_GT(det(ex, ey, ez), 0) << file;
      for (int d = 0; d < 3; ++d)
        EXPECT_NEAR(x[c[3]][d], x[c[1]][d] + x[c[2]][d] - x[c[0]][d], 1e-9) << file;
    }
    EXPECT_NEAR(total_volume(m), 2.0, 1e-12) << file;
    EXPECT_EQ(faces_in(m, "fixed"), 2u) << file;  // z = 0, two quadrilaterals
    EXPECT_NEAR(area_of(m, "fixed"), 2.0, 1e-12) << file;
    EXPECT_NEAR(area_of(m, "seat"), 2.0, 1e-12) << file;
    for (const MeshFace& f : m.faces) EXPECT_EQ(f.vertices.size(), 4u);
  }
}

TEST(GmshMesh, AFaceMayLieInSeveralPhysicalSurfaces) {
  for (const char* file : {"overlapping_surfaces_22.msh", "overlapping_surfaces_41.msh"}) {
    const GmshMesh m = read_gmsh_mesh(kSeeds + file);
    EXPECT_NEAR(area_of(m, "outside"), 6 * 16.0, 1e-9) << file;
    EXPECT_NEAR(area_of(m, "bolts"), 16.0, 1e-9) << file;
    // Each face once, the bolts' faces with both tags.
    EXPECT_EQ(m.faces.size(), faces_in(m, "outside")) << file;
    for (const MeshFace& f : m.faces)
      EXPECT_TRUE(f.physicals.size() == 1 || f.physicals.size() == 2);
  }
}

TEST(GmshMesh, ParametricNodesAndFilesWithoutPhysicalGroupsAreRead) {
  const GmshMesh c = read_gmsh_mesh(kSeeds + "cylinder_parametric_41.msh");
  // The polyhedron inscribed in the cylinder r = 5, h = 3: a little less than pi r^2 h.
  const double v = total_volume(c), exact = M_PI * 25 * 3;
  EXPECT_LT(v, exact);
  EXPECT_GT(v, 0.9 * exact);
  const GmshMesh n = read_gmsh_mesh(kSeeds + "no_physical_groups_41.msh");
  EXPECT_NEAR(total_volume(n), 6.0, 1e-12);
  EXPECT_TRUE(n.faces.empty());
  EXPECT_EQ(n.surface_names(), "none");
}

// A one-tetrahedron file in version 2.2, with `cell` as its element line.
std::string one_cell(const std::string& nodes, const std::string& elements) {
  return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n2 7 \"seat\"\n"
         "$EndPhysicalNames\n$Nodes\n" +
         nodes + "$EndNodes\n$Elements\n" + elements + "$EndElements\n";
}
const std::string kFourNodes = "4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
const std::string kEightNodes =
    "8\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0 0 1\n6 1 0 1\n7 1 1 1\n8 0 1 1\n";

TEST(GmshMesh, CellsWrittenInsideOutAreTurnedOver) {
  const GmshMesh t = parse_gmsh_mesh(one_cell(kFourNodes, "1\n1 4 0 1 3 2 4\n"), "t.msh");
  EXPECT_EQ(t.turned_over_cells, 1u);
  EXPECT_NEAR(volume(t, t.cells[0]), 1.0 / 6, 1e-15);
  // The hexahedron with its top and bottom faces exchanged.
  const GmshMesh h = parse_gmsh_mesh(one_cell(kEightNodes, "1\n1 5 0 5 6 7 8 1 2 3 4\n"), "h.msh");
  EXPECT_EQ(h.turned_over_cells, 1u);
  EXPECT_NEAR(volume(h, h.cells[0]), 1.0, 1e-15);
}

TEST(GmshMesh, ATriangleOfAPhysicalSurfaceTakesItsCellsVertexOrder) {
  const GmshMesh t =
      parse_gmsh_mesh(one_cell(kFourNodes, "2\n1 4 0 1 2 3 4\n2 2 2 7 1 4 3 2\n"), "t.msh");
  ASSERT_EQ(t.faces.size(), 1u);
  EXPECT_EQ(t.faces[0].physicals, std::vector<int>{7});
  EXPECT_EQ(t.faces[0].vertices, (std::vector<unsigned>{1, 2, 3}));
}

TEST(GmshMesh, BadFilesAreRefusedNamingTheFileAndTheLine) {
  const auto error = [](const std::string& text) {
    return input_error([&] { parse_gmsh_mesh(text, "bad.msh"); });
  };
  const std::string tet = "1\n1 4 0 1 2 3 4\n";
  struct Case {
    std::string text, says;
  } cases[] = {
      {"", "empty"},
      {"solid foo\n", "bad.msh:1: a .msh file starts with $MeshFormat"},
      {"$MeshFormat\n4.1 1 8\n$EndMeshFormat\n", "bad.msh:2: a binary MSH file"},
      {"$MeshFormat\n3.0 0 8\n$EndMeshFormat\n", "bad.msh:2: MSH version 3.0"},
      {"$MeshFormat\n2.2 0 8\n", "the file ends where $EndMeshFormat should follow"},
      {"$MeshFormat\n2.2 0 8\n$EndMeshFormat\n", "no $Elements section"},
      {one_cell(kFourNodes, "1\n1 4 0 1 2 3 9\n"),
       "bad.msh:17: the element names node 9, which "
       "$Nodes does not define"},
      {one_cell(kFourNodes, "1\n1 2 2 7 1 1 2 3 4\n"), "bad.msh:17: unexpected \"4\""},
      {one_cell(kFourNodes, "1\n1 2 2 7 1 1 2 3\n"), "no volume elements"},
      {one_cell(kFourNodes, "1\n1 11 0 1 2 3 4 1 2 3 4 1 2\n"), "10-node second-order"},
      {one_cell("6\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 0 1\n6 0 1 1\n",
                "1\n1 6 0 1 2 3 4 5 6\n"),
       "a 6-node prism in the volume"},
      {one_cell(kEightNodes, "2\n1 4 0 1 2 3 5\n2 5 0 1 2 3 4 5 6 7 8\n"),
       "bad.msh:22: an 8-node hexahedron in a mesh whose first volume element (line 21)"},
      {one_cell("4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 1 1 0\n", tet),
       "bad.msh:17: a tetrahedron of zero volume"},
      {one_cell(kEightNodes, "1\n1 5 0 1 2 4 3 5 6 7 8\n"),
       "bad.msh:21: a hexahedron that is flat, tangled"},
      {one_cell(kFourNodes, "2\n1 4 0 1 2 3 4\n2 3 2 7 1 1 2 3 4\n"),
       "bad.msh:18: this surface element is no face of a volume element"},
      {one_cell("4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n1 0 0 1\n", tet),
       "bad.msh:13: node 1 is defined twice"},
      {one_cell("4\n1 0 0 0\n2 nan 0 0\n3 0 1 0\n4 0 0 1\n", tet),
       "the node's x \"nan\" is not a finite number"},
      {one_cell("5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n", tet),
       "bad.msh:14: the node tag \"$EndNodes\" is not an integer"},
      {one_cell(kFourNodes, "1\n1 99 0 1 2 3 4\n"), "element type 99"},
      {one_cell(kFourNodes, "1\n1 4 0 1 2 2 4\n"), "names node 2 twice"},
      {"$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Elements\n0\n$EndElements\n",
       "$Elements before $Nodes"},
      {"$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PartitionedEntities\n", "a partitioned mesh"},
      {"$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 4 1 4\n3 1 0 5\n",
       "the number of nodes in the block 5 is outside [0, 4]"},
  };
  for (const Case& c : cases) {
    const std::string e = error(c.text);
    EXPECT_NE(e.find(c.says), std::string::npos) << "message: " << e << "\nexpected: " << c.says;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
  EXPECT_NE(input_error([] { read_gmsh_mesh("/nonexistent/x.msh"); }).find("cannot open"),
            std::string::npos);
  EXPECT_NE(
      input_error([] { read_gmsh_mesh(kSeeds + "second_order_22.msh"); }).find("second-order"),
      std::string::npos);
}

}  // namespace
}  // namespace bearing::fem
