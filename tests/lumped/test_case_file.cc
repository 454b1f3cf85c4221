#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "bearing/case_file.h"
#include "bearing/errors.h"
#include "bearing/presets.h"

using bearing::Case;
using bearing::Override;
using bearing::parse_case;
using bearing::parse_override;

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr const char* kFull = R"(
[bearing]
ball_diameter = "15.081 mm"
pitch_diameter = "65 mm"
balls = 8
inner_conformity = 0.52
outer_conformity = 0.53
clearance = "14 um"
contact_angle = "0 deg"

[material]
young = "208 GPa"
poisson = 0.3
density = "7850 kg/m^3"

[material.ball]
young = "315 GPa"   # ceramic ball
poisson = 0.26

[operation]
speed = "2000 rpm"
load = ["0 N", "-0.5 kN"]

[model]
contact = "hamrock-brewe"
)";
}  // namespace

TEST(CaseFile, ReadsEveryKeyInSI) {
  const Case c = parse_case(kFull, "full.toml");
  EXPECT_EQ(c.source, "full.toml");
  EXPECT_DOUBLE_EQ(c.bearing.ball_diameter, 15.081e-3);
  EXPECT_DOUBLE_EQ(c.bearing.pitch_diameter, 65e-3);
  EXPECT_EQ(c.bearing.balls, 8);
  EXPECT_DOUBLE_EQ(c.bearing.outer_conformity, 0.53);
  EXPECT_DOUBLE_EQ(c.bearing.clearance, 14e-6);
  EXPECT_DOUBLE_EQ(c.bearing.ball.young, 315e9);
  EXPECT_DOUBLE_EQ(c.bearing.ball.poisson, 0.26);
  EXPECT_DOUBLE_EQ(c.bearing.ball.density, 7850.0);  // from [material], not overridden
  EXPECT_DOUBLE_EQ(c.bearing.rings.young, 208e9);
  EXPECT_DOUBLE_EQ(c.operation.speed, 2000 * 2 * kPi / 60);
  EXPECT_DOUBLE_EQ(c.operation.load.y(), -500.0);
  EXPECT_EQ(c.model.contact, "hamrock-brewe");
}

TEST(CaseFile, PlainNumbersAreSI) {
  const Case c = parse_case(
      "[bearing]\npreset = \"6308\"\nclearance = 2e-5\n"
      "[operation]\nload = [100, -200.5]\n",
      "t");
  EXPECT_DOUBLE_EQ(c.bearing.clearance, 2e-5);
  EXPECT_DOUBLE_EQ(c.operation.load.x(), 100.0);
  EXPECT_DOUBLE_EQ(c.operation.load.y(), -200.5);
}

TEST(CaseFile, PresetThenFileKeysOverrideIt) {
  const Case c = parse_case("[bearing]\npreset = \"6304\"\nballs = 9\n", "t");
  const auto p = bearing::preset("6304");
  EXPECT_EQ(c.preset, "6304");
  EXPECT_EQ(c.bearing.balls, 9);
  EXPECT_DOUBLE_EQ(c.bearing.ball_diameter, p.ball_diameter);
  EXPECT_DOUBLE_EQ(c.bearing.ball.young, 2.07e11);  // preset material kept
  EXPECT_EQ(c.model.contact, "exact");              // default method
}

TEST(CaseFile, CommandLineOverridesWinOverTheFile) {
  const std::vector<Override> sets = {
      parse_override("operation.speed=3000 rpm"), parse_override("bearing.balls=10"),
      parse_override("material.rings.young=200 GPa"), parse_override("operation.load=[0, -1000]"),
      parse_override("model.contact=harris-table")};
  const Case c = parse_case(kFull, "full.toml", sets);
  EXPECT_DOUBLE_EQ(c.operation.speed, 3000 * 2 * kPi / 60);
  EXPECT_EQ(c.bearing.balls, 10);
  EXPECT_DOUBLE_EQ(c.bearing.rings.young, 200e9);
  EXPECT_DOUBLE_EQ(c.bearing.ball.young, 315e9);
  EXPECT_DOUBLE_EQ(c.operation.load.y(), -1000.0);
  EXPECT_EQ(c.model.contact, "harris-table");
}

TEST(CaseFile, OverrideCanChooseAPresetByNumber) {
  // `--set bearing.preset=608` reaches the reader as a TOML integer.
  const Case c = parse_case("", "t", {parse_override("bearing.preset=608")});
  EXPECT_EQ(c.bearing.balls, 7);
  EXPECT_EQ(c.preset, "608");
}

TEST(CaseFile, DefaultCaseIsThe6308At2000Rpm) {
  const Case c = bearing::default_case();
  EXPECT_EQ(c.preset, "6308");
  EXPECT_DOUBLE_EQ(c.operation.speed, 2000 * 2 * kPi / 60);
  EXPECT_LT(c.operation.load.y(), 0.0);
  EXPECT_EQ(c.source, "built-in default case");
  const Case faster = bearing::default_case({parse_override("operation.speed=1000rpm")});
  EXPECT_DOUBLE_EQ(faster.operation.speed, 1000 * 2 * kPi / 60);
}

TEST(CaseFile, ExamplesAllLoad) {
  for (const char* name : {"seed000_608.toml", "seed001_purohit.toml", "seed002_6308.toml",
                           "seed003_6308.toml", "seed004_6304.toml"}) {
    const std::string path = std::string(BEARING_SOURCE_DIR) + "/examples/" + name;
    EXPECT_NO_THROW(bearing::read_case_file(path)) << path;
  }
}

TEST(CaseFile, OverrideSyntax) {
  EXPECT_THROW(parse_override("operation.speed"), bearing::InputError);
  EXPECT_THROW(parse_override("speed=3000 rpm"), bearing::InputError);
  EXPECT_THROW(parse_override("operation.=1"), bearing::InputError);
  EXPECT_THROW(parse_override("operation.speed="), bearing::InputError);
  const Override o = parse_override("material.ball.young=315 GPa");
  EXPECT_EQ(o.key, "material.ball.young");
  EXPECT_EQ(o.value, "315 GPa");
}
