// The structure file of `bearing-fem modes` (fem/modes/structure_file.h, no deal.II): the values
// in SI, the mesh's path relative to the file, the sensors in mesh units, and each bad input one
// line naming the key, the value and what is allowed; the names checked against a gmsh mesh.

#include <gtest/gtest.h>

#include <string>

#include "bearing/errors.h"
#include "mesh/gmsh_mesh.h"
#include "modes/structure_file.h"

namespace bearing::fem {
namespace {

template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const std::string kValid = R"(mesh = "housing.msh"
mesh_unit = "mm"
[material]
young = "210 GPa"
poisson = 0.3
density = "7850 kg/m^3"
[boundary]
fixed = ["bolts", "flange"]
seat = "seat"
[sensors]
top = [0, 60, 0]
side_2 = [45.5, 0, -3]
[modes]
count = 12
max_frequency = "20 kHz"
)";

TEST(StructureFile, ValuesAreReadInSI) {
  const StructureFile s = parse_structure(kValid, "examples/shield.toml");
  EXPECT_EQ(s.mesh, "housing.msh");
  EXPECT_EQ(s.mesh_path, "examples/housing.msh");
  EXPECT_EQ(s.mesh_unit, "mm");
  EXPECT_DOUBLE_EQ(s.mesh_scale, 1e-3);
  EXPECT_DOUBLE_EQ(s.young, 210e9);
  EXPECT_DOUBLE_EQ(s.poisson, 0.3);
  EXPECT_DOUBLE_EQ(s.density, 7850);
  EXPECT_EQ(s.fixed, (std::vector<std::string>{"bolts", "flange"}));
  EXPECT_EQ(s.seat, "seat");
  ASSERT_EQ(s.sensors.size(), 2u);
  EXPECT_EQ(s.sensors[1].name, "top");  // sorted by name
  EXPECT_DOUBLE_EQ(s.sensors[1].point[1], 0.06);
  EXPECT_DOUBLE_EQ(s.sensors[0].point[0], 0.0455);
  EXPECT_DOUBLE_EQ(s.sensors[0].written[0], 45.5);
  EXPECT_EQ(s.count, 12u);
  EXPECT_DOUBLE_EQ(s.max_frequency, 20e3);
}

TEST(StructureFile, DefaultsAreMetresFreeFreeAndTwentyModes) {
  const StructureFile s = parse_structure(
      "mesh = \"/abs/ring.msh\"\n[material]\nyoung = 7e10\npoisson = 0\ndensity = 2700\n"
      "[boundary]\nseat = \"bore\"\n",
      "ring.toml");
  EXPECT_EQ(s.mesh_path, "/abs/ring.msh");
  EXPECT_DOUBLE_EQ(s.mesh_scale, 1.0);
  EXPECT_TRUE(s.fixed.empty());
  EXPECT_TRUE(s.sensors.empty());
  EXPECT_EQ(s.count, 20u);
  EXPECT_EQ(s.max_frequency, 0.0);
}

TEST(StructureFile, BadInputIsOneLineNamingTheKeyTheValueAndTheRange) {
  struct Case {
    std::string from, to, says;
  } cases[] = {
      {"young = \"210 GPa\"", "young = \"-3 GPa\"",
       "s.toml: material.young = \"-3 GPa\": must lie in (0, 1e13] Pa"},
      {"young = \"210 GPa\"", "young = \"210 m\"", "material.young"},
      {"poisson = 0.3", "poisson = 0.5", "material.poisson = 0.5: must lie in [0, 0.5)"},
      {"poisson = 0.3", "poisson = -0.1", "material.poisson = -0.1: must lie in [0, 0.5)"},
      {"poisson = 0.3", "poisson = nan", "material.poisson = nan"},
      {"density = \"7850 kg/m^3\"", "density = 0",
       "material.density = 0: must lie in (0, 1e5] kg/m^3"},
      {"density = \"7850 kg/m^3\"", "", "material.density is missing"},
      {"count = 12", "count = 0", "modes.count = 0: must be a whole number in [1, 500]"},
      {"count = 12", "count = 501", "modes.count = 501"},
      {"count = 12", "count = 2.5", "modes.count = 2.5"},
      {"max_frequency = \"20 kHz\"", "max_frequency = \"-1 Hz\"", "modes.max_frequency"},
      {"mesh_unit = \"mm\"", "mesh_unit = \"cm\"", "mesh_unit = \"cm\": must be m or mm"},
      {"seat = \"seat\"", "", "boundary.seat is missing"},
      {"seat = \"seat\"", "seat = 3", "boundary.seat = 3: expected a string"},
      {"fixed = [\"bolts\", \"flange\"]", "fixed = \"bolts\"",
       "boundary.fixed = \"bolts\": expected an array"},
      {"fixed = [\"bolts\", \"flange\"]", "fixed = [\"bolts\", \"bolts\"]", "named twice"},
      {"top = [0, 60, 0]", "top-left = [0, 60, 0]", "sensors.top-left"},
      {"top = [0, 60, 0]", "top = [0, 60]", "sensors.top = an array: expected a point [x, y, z]"},
      {"top = [0, 60, 0]", "top = [0, \"60\", 0]", "sensors.top = \"60\": each coordinate"},
      {"top = [0, 60, 0]", "top = [0, 1e10, 0]", "sensors.top = 10000000000: each coordinate"},
      {"count = 12", "count = 12\ncolour = \"red\"",
       "modes.colour = \"red\": unknown key ([modes] has: count, max_frequency)"},
      {"mesh_unit = \"mm\"", "mesh_unit = \"mm\"\nunits = 1",
       "units = 1: unknown key (the file's top level has"},
      {"[material]", "[materials]", "unknown key"},
      {"poisson = 0.3", "poisson = 0.3 µ", "TOML syntax error"},
      {"poisson = 0.3", "poisson = = 0.3", "s.toml:5:"},
  };
  for (const Case& c : cases) {
    std::string text = kValid;
    const std::size_t at = text.find(c.from);
    ASSERT_NE(at, std::string::npos) << c.from;
    text.replace(at, c.from.size(), c.to);
    const std::string e = input_error([&] { parse_structure(text, "s.toml"); });
    EXPECT_NE(e.find(c.says), std::string::npos) << "message: " << e << "\nexpected: " << c.says;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
  EXPECT_NE(input_error([] { read_structure_file("/nonexistent/s.toml"); }).find("cannot open"),
            std::string::npos);
}

TEST(StructureFile, SurfacesAreCheckedAgainstTheMesh) {
  const GmshMesh mesh =
      read_gmsh_mesh(BEARING_SOURCE_DIR "/tests/fuzz/corpus/gmsh_mesh/box_tetrahedra_22.msh");
  StructureFile s = parse_structure(kValid, "s.toml");
  s.fixed = {"fixed"};
  EXPECT_NO_THROW(check_structure_against_mesh(s, mesh));
  s.fixed = {"bolts"};
  EXPECT_NE(
      input_error([&] { check_structure_against_mesh(s, mesh); })
          .find(
              "boundary.fixed = \"bolts\": no physical surface of that name in " BEARING_SOURCE_DIR
              "/tests/fuzz/corpus/gmsh_mesh/box_tetrahedra_22.msh (its physical surfaces: "
              "\"fixed\", \"seat\")"),
      std::string::npos);
  s.fixed = {"body"};
  EXPECT_NE(input_error([&] {
              check_structure_against_mesh(s, mesh);
            }).find("a physical group of the mesh that is not a surface"),
            std::string::npos);
  s.fixed = {"seat"};
  EXPECT_NE(
      input_error([&] { check_structure_against_mesh(s, mesh); }).find("is also in boundary.fixed"),
      std::string::npos);
}

}  // namespace
}  // namespace bearing::fem
