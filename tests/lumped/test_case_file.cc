#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "bearing/case_file.h"
#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/presets.h"

using namespace bearing;

namespace {
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
  EXPECT_DOUBLE_EQ(c.operation.speed, 2000 * two_pi / 60);
  EXPECT_DOUBLE_EQ(c.operation.load.y(), -500.0);
  EXPECT_EQ(c.model.contact, ContactLaw::hamrock_brewe);
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
  EXPECT_EQ(c.model.contact, ContactLaw::exact);    // default method
}

TEST(CaseFile, CommandLineOverridesWinOverTheFile) {
  const std::vector<Override> sets = {
      parse_override("operation.speed=3000 rpm"), parse_override("bearing.balls=10"),
      parse_override("material.rings.young=200 GPa"), parse_override("operation.load=[0, -1000]"),
      parse_override("model.contact=harris-table")};
  const Case c = parse_case(kFull, "full.toml", sets);
  EXPECT_DOUBLE_EQ(c.operation.speed, 3000 * two_pi / 60);
  EXPECT_EQ(c.bearing.balls, 10);
  EXPECT_DOUBLE_EQ(c.bearing.rings.young, 200e9);
  EXPECT_DOUBLE_EQ(c.bearing.ball.young, 315e9);
  EXPECT_DOUBLE_EQ(c.operation.load.y(), -1000.0);
  EXPECT_EQ(c.model.contact, ContactLaw::harris_table);
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
  EXPECT_DOUBLE_EQ(c.operation.speed, 2000 * two_pi / 60);
  EXPECT_LT(c.operation.load.y(), 0.0);
  EXPECT_EQ(c.source, "built-in default case");
  const Case faster = bearing::default_case({parse_override("operation.speed=1000rpm")});
  EXPECT_DOUBLE_EQ(faster.operation.speed, 1000 * two_pi / 60);
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

namespace {
constexpr const char* kDynamics = R"(
[bearing]
preset = "6308"

[rotor]
mass = "0.8 kg"
damping = "350 N s/m"

[operation]
speed = "1800 rpm"
load = ["10 N", "-500 N"]
axial_load = "100 N"
unbalance = "2 g mm"
gravity = true

[[waviness.inner]]
order = 8
amplitude = "0.5 um"
phase = "30 deg"

[[waviness.outer]]
order = 16
amplitude = "0.2 um"

[ball_errors]
values = ["1 um", "-1 um", "0 um", "0.5 um", "0 um", "0 um", "0 um", "-0.5 um"]

[model]
kind = "3dof"
contact = "harris-table"
waviness_stiffness = true

[solver]
method = "rk8pd"
dt = "2 us"
duration = "0.5 s"
transient = "0.1 s"
tolerance = 1e-8
output_rate = "10 kHz"

[output]
ball_loads = true
window = "flattop"
peaks = 5
)";
}  // namespace

TEST(CaseFile, ReadsTheDynamicsTables) {
  const Case c = parse_case(kDynamics, "dyn.toml");
  EXPECT_DOUBLE_EQ(c.rotor.mass, 0.8);
  EXPECT_DOUBLE_EQ(c.rotor.damping, 350.0);
  EXPECT_DOUBLE_EQ(c.rotor.axial_mass, 0.8);  // defaults to the radial values
  EXPECT_DOUBLE_EQ(c.rotor.axial_damping, 350.0);
  EXPECT_DOUBLE_EQ(c.operation.axial_load, 100.0);
  EXPECT_DOUBLE_EQ(c.operation.unbalance, 2e-6);
  EXPECT_TRUE(c.operation.gravity);
  ASSERT_EQ(c.excitation.inner_waviness.size(), 1u);
  EXPECT_EQ(c.excitation.inner_waviness[0].order, 8);
  EXPECT_DOUBLE_EQ(c.excitation.inner_waviness[0].amplitude, 0.5e-6);
  EXPECT_DOUBLE_EQ(c.excitation.inner_waviness[0].phase, pi / 6);
  EXPECT_DOUBLE_EQ(c.excitation.outer_waviness[0].phase, 0.0);
  // values are D_j − D; the model wants ΔD_j = D − D_j (a larger ball adds approach).
  ASSERT_EQ(c.excitation.ball_size_errors.size(), 8u);
  EXPECT_DOUBLE_EQ(c.excitation.ball_size_errors[0], -1e-6);
  EXPECT_DOUBLE_EQ(c.excitation.ball_size_errors[1], 1e-6);
  EXPECT_EQ(c.model.kind, ModelKind::three_dof);
  EXPECT_TRUE(c.model.waviness_stiffness);
  EXPECT_EQ(c.solver.method, IntegratorMethod::rk8pd);
  EXPECT_DOUBLE_EQ(c.solver.dt, 2e-6);
  EXPECT_DOUBLE_EQ(c.solver.output_rate, 1e4);
  EXPECT_TRUE(c.output.ball_loads);
  EXPECT_EQ(c.output.window, Window::flattop);
  EXPECT_EQ(c.output.peaks, 5);
}

TEST(CaseFile, DefaultsMatchTheSeeds) {
  const Case c = bearing::default_case();
  EXPECT_DOUBLE_EQ(c.rotor.mass, 0.6);  // seeds 001–003
  EXPECT_DOUBLE_EQ(c.rotor.damping, 200.0);
  EXPECT_EQ(c.model.kind, ModelKind::two_dof);
  EXPECT_EQ(c.solver.method, IntegratorMethod::rk4);
  EXPECT_DOUBLE_EQ(c.solver.dt, 5e-6);  // seeds 002/003
  EXPECT_TRUE(c.excitation.inner_waviness.empty());
  EXPECT_TRUE(c.excitation.ball_size_errors.empty());
}

TEST(CaseFile, WavinessTableIsReadRelativeToTheCaseFile) {
  const std::string dir = ::testing::TempDir();
  {
    std::ofstream csv(dir + "/w.csv");
    csv << "# test table\norder,amplitude_um,phase_deg\n4,0.1,0\n5,0.2,90\n";
    std::ofstream toml(dir + "/case.toml");
    toml << "[bearing]\npreset = \"6308\"\n[[waviness.inner]]\ntable = \"w.csv\"\n"
            "[[waviness.inner]]\norder = 8\namplitude = \"1 um\"\n";
  }
  const Case c = bearing::read_case_file(dir + "/case.toml");
  ASSERT_EQ(c.excitation.inner_waviness.size(), 3u);
  EXPECT_EQ(c.excitation.inner_waviness[1].order, 5);
  EXPECT_DOUBLE_EQ(c.excitation.inner_waviness[1].amplitude, 0.2e-6);
  EXPECT_DOUBLE_EQ(c.excitation.inner_waviness[1].phase, pi / 2);
  EXPECT_EQ(c.excitation.inner_waviness[2].order, 8);
}

TEST(CaseFile, BandErrorsAreReproducibleAndRecorded) {
  const std::string text =
      "[bearing]\npreset = \"608\"\n[ball_errors]\nband = \"2 um\"\nseed = 7\n";
  const Case a = parse_case(text, "t");
  const Case b = parse_case(text, "t");
  ASSERT_EQ(a.excitation.ball_size_errors.size(), 7u);
  EXPECT_EQ(a.excitation.ball_size_errors, b.excitation.ball_size_errors);
  for (double e : a.excitation.ball_size_errors) EXPECT_LE(std::fabs(e), 1e-6);
  EXPECT_EQ(a.excitation.ball_error_seed, 7u);
  const Case other = parse_case(text, "t", {parse_override("ball_errors.seed=8")});
  EXPECT_NE(other.excitation.ball_size_errors, a.excitation.ball_size_errors);
}

TEST(CaseFile, OverrideReachesIntoWavinessEntries) {
  const Case c = parse_case(kDynamics, "t",
                            {parse_override("waviness.inner.0.amplitude=1.2um"),
                             parse_override("waviness.outer.0.order=24")});
  EXPECT_DOUBLE_EQ(c.excitation.inner_waviness[0].amplitude, 1.2e-6);
  EXPECT_EQ(c.excitation.outer_waviness[0].order, 24);
  EXPECT_EQ(bearing::key_dimension("waviness.inner.0.amplitude"), bearing::Dimension::length);
  EXPECT_EQ(bearing::key_dimension("operation.speed"), bearing::Dimension::angular_speed);
  EXPECT_TRUE(bearing::key_is_integer("bearing.balls"));
  EXPECT_THROW(bearing::key_dimension("model.kind"), bearing::InputError);
}

// case.toml must let a run be repeated exactly: every resolved value survives the round trip.
// The ball-DOF model's tables, with the defaults resolved (ball mass and inertia from the density,
// damping from the rotor), survive the resolved TOML exactly.
TEST(CaseFile, BallModelTablesRoundTripExactly) {
  const Case a = parse_case(
      "[bearing]\npreset = \"6304\"\n[model]\nkind = \"balls\"\n[cage]\nslip = 0.03\n"
      "slide_speed = \"0.05 m/s\"\n[ball]\ncentrifugal = false\n[output]\nball_dynamics = true\n",
      "balls.toml");
  const double D = a.bearing.ball_diameter;
  EXPECT_NEAR(a.ball.mass, 7850 * pi * D * D * D / 6, 1e-12);
  EXPECT_NEAR(a.ball.inertia, a.ball.mass * D * D / 10, 1e-18);
  EXPECT_EQ(a.ball.damping, a.rotor.damping);
  EXPECT_EQ(a.cage.friction, 0.01);
  const Case b = parse_case(bearing::case_to_toml(a), "case.toml");
  EXPECT_EQ(b.model.kind, ModelKind::balls);
  EXPECT_EQ(b.cage.slip, a.cage.slip);
  EXPECT_EQ(b.cage.friction, a.cage.friction);
  EXPECT_EQ(b.cage.slide_speed, a.cage.slide_speed);
  EXPECT_EQ(b.ball.mass, a.ball.mass);
  EXPECT_EQ(b.ball.inertia, a.ball.inertia);
  EXPECT_EQ(b.ball.damping, a.ball.damping);
  EXPECT_EQ(b.ball.centrifugal, a.ball.centrifugal);
  EXPECT_EQ(b.output.ball_dynamics, a.output.ball_dynamics);
}

// [lubricant] (issue 43): absent, the contacts are dry; present, its keys in SI, the temperature
// law's degC read as kelvin, and the table written back by case_to_toml reads the same numbers.
TEST(CaseFile, LubricantTableRoundTripsExactly) {
  const std::string base = "[bearing]\npreset = \"6205\"\n";
  const Case dry = parse_case(base, "dry.toml");
  EXPECT_FALSE(dry.lubricant.enabled);
  EXPECT_EQ(bearing::case_to_toml(dry).find("[lubricant]"), std::string::npos);
  const Case a = parse_case(base +
                                "[lubricant]\nviscosity = \"46 mPa s\"\npressure_viscosity = "
                                "\"2e-8 1/Pa\"\nroughness = \"0.1 um\"\ntemperature = \"60 "
                                "degC\"\nreference_temperature = \"40 degC\"\n"
                                "viscosity_temperature = \"0.03 1/K\"\n",
                            "oil.toml");
  ASSERT_TRUE(a.lubricant.enabled);
  EXPECT_DOUBLE_EQ(a.lubricant.viscosity, 0.046);
  EXPECT_DOUBLE_EQ(a.lubricant.pressure_viscosity, 2e-8);
  EXPECT_DOUBLE_EQ(a.lubricant.roughness, 1e-7);
  EXPECT_DOUBLE_EQ(a.lubricant.temperature, 333.15);
  EXPECT_DOUBLE_EQ(a.lubricant.reference_temperature, 313.15);
  EXPECT_DOUBLE_EQ(a.lubricant.viscosity_temperature, 0.03);
  EXPECT_NEAR(a.lubricant.operating_viscosity(), 0.046 * std::exp(-0.03 * 20), 1e-15);
  const std::string text = bearing::case_to_toml(a);
  EXPECT_NE(text.find("[lubricant]"), std::string::npos) << text;
  const Case b = parse_case(text, "case.toml");
  ASSERT_TRUE(b.lubricant.enabled);
  EXPECT_EQ(b.lubricant.viscosity, a.lubricant.viscosity);
  EXPECT_EQ(b.lubricant.pressure_viscosity, a.lubricant.pressure_viscosity);
  EXPECT_EQ(b.lubricant.roughness, a.lubricant.roughness);
  EXPECT_EQ(b.lubricant.temperature, a.lubricant.temperature);
  EXPECT_EQ(b.lubricant.reference_temperature, a.lubricant.reference_temperature);
  EXPECT_EQ(b.lubricant.viscosity_temperature, a.lubricant.viscosity_temperature);
  // Without the temperature law: the three required keys only, written back without the others.
  const Case c = parse_case(base + "[lubricant]\nviscosity = 0.02\npressure_viscosity = 2e-8\n"
                                   "roughness = 1e-7\n",
                            "oil.toml");
  EXPECT_FALSE(c.lubricant.has_temperature_law());
  EXPECT_EQ(c.lubricant.operating_viscosity(), 0.02);
  const Case d = parse_case(bearing::case_to_toml(c), "case.toml");
  EXPECT_FALSE(d.lubricant.has_temperature_law());
  EXPECT_EQ(d.lubricant.viscosity, 0.02);
}

TEST(CaseFile, ResolvedCaseRoundTripsExactly) {
  const Case a = parse_case(kDynamics, "dyn.toml");
  const Case b = parse_case(bearing::case_to_toml(a), "case.toml");
  EXPECT_EQ(b.bearing.ball_diameter, a.bearing.ball_diameter);
  EXPECT_EQ(b.bearing.pitch_diameter, a.bearing.pitch_diameter);
  EXPECT_EQ(b.bearing.balls, a.bearing.balls);
  EXPECT_EQ(b.bearing.inner_conformity, a.bearing.inner_conformity);
  EXPECT_EQ(b.bearing.clearance, a.bearing.clearance);
  EXPECT_EQ(b.bearing.contact_angle, a.bearing.contact_angle);
  EXPECT_EQ(b.bearing.ball.young, a.bearing.ball.young);
  EXPECT_EQ(b.bearing.rings.poisson, a.bearing.rings.poisson);
  EXPECT_EQ(b.rotor.mass, a.rotor.mass);
  EXPECT_EQ(b.rotor.axial_damping, a.rotor.axial_damping);
  EXPECT_EQ(b.operation.speed, a.operation.speed);
  EXPECT_EQ(b.operation.load, a.operation.load);
  EXPECT_EQ(b.operation.axial_load, a.operation.axial_load);
  EXPECT_EQ(b.operation.unbalance, a.operation.unbalance);
  EXPECT_EQ(b.operation.gravity, a.operation.gravity);
  ASSERT_EQ(b.excitation.inner_waviness.size(), a.excitation.inner_waviness.size());
  EXPECT_EQ(b.excitation.inner_waviness[0].amplitude, a.excitation.inner_waviness[0].amplitude);
  EXPECT_EQ(b.excitation.inner_waviness[0].phase, a.excitation.inner_waviness[0].phase);
  EXPECT_EQ(b.excitation.ball_size_errors, a.excitation.ball_size_errors);
  EXPECT_EQ(b.model.kind, a.model.kind);
  EXPECT_EQ(b.model.contact, a.model.contact);
  EXPECT_EQ(b.model.waviness_stiffness, a.model.waviness_stiffness);
  EXPECT_EQ(b.solver.method, a.solver.method);
  EXPECT_EQ(b.solver.dt, a.solver.dt);
  EXPECT_EQ(b.solver.duration, a.solver.duration);
  EXPECT_EQ(b.solver.transient, a.solver.transient);
  EXPECT_EQ(b.solver.tolerance, a.solver.tolerance);
  EXPECT_EQ(b.solver.output_rate, a.solver.output_rate);
  EXPECT_EQ(b.output.ball_loads, a.output.ball_loads);
  EXPECT_EQ(b.output.window, a.output.window);
  EXPECT_EQ(b.output.peaks, a.output.peaks);
}

// [acoustics]: its presence turns the outputs on; defaults are air at 20 °C, the exact ring
// dipole and the translating-ball dipole, the ring radiating from the inner raceway radius.
TEST(CaseFile, ReadsTheAcousticsTable) {
  const std::string base = "[bearing]\npreset = \"608\"\n";
  EXPECT_FALSE(parse_case(base, "a.toml").acoustics.enabled);
  const Case c = parse_case(base +
                                "[acoustics]\nmicrophones = [[\"10 mm\", \"-90 deg\"], [\"0.5 "
                                "m\", \"0.25 rad\"]]\nsummation = \"energetic\"\n",
                            "a.toml");
  const auto& ac = c.acoustics;
  EXPECT_TRUE(ac.enabled);
  ASSERT_EQ(ac.microphones.size(), 2u);
  EXPECT_DOUBLE_EQ(ac.microphones[0].radius, 0.010);
  EXPECT_DOUBLE_EQ(ac.microphones[0].angle, -pi / 2);
  EXPECT_DOUBLE_EQ(ac.microphones[1].radius, 0.5);
  EXPECT_DOUBLE_EQ(ac.microphones[1].angle, 0.25);
  EXPECT_EQ(ac.summation, Summation::energetic);
  EXPECT_EQ(ac.ring_source, RingSource::cylinder_dipole);
  EXPECT_EQ(ac.ball_source, BallSource::oscillating_sphere);
  EXPECT_DOUBLE_EQ(ac.ring_radius, 0.5 * c.bearing.inner_raceway_diameter());
  EXPECT_DOUBLE_EQ(ac.density, 1.204);
  EXPECT_DOUBLE_EQ(ac.sound_speed, 343.2);

  // Round trip through the resolved case, and an override that reaches into the table.
  const Case b = parse_case(bearing::case_to_toml(c), "case.toml",
                            {parse_override("acoustics.sound_speed=1235 km/h")});
  EXPECT_TRUE(b.acoustics.enabled);
  ASSERT_EQ(b.acoustics.microphones.size(), 2u);
  EXPECT_EQ(b.acoustics.microphones[1].radius, ac.microphones[1].radius);
  EXPECT_EQ(b.acoustics.microphones[1].angle, ac.microphones[1].angle);
  EXPECT_EQ(b.acoustics.summation, ac.summation);
  EXPECT_EQ(b.acoustics.ring_radius, ac.ring_radius);
  EXPECT_NEAR(b.acoustics.sound_speed, 1235 / 3.6, 1e-12);
}

// The schema drives reading and writing: the written case read back writes the same text, for
// every example and for a case that has every table (balls, waviness, ball errors, acoustics).
TEST(CaseSchema, WrittenCaseIsAFixedPointForEveryExample) {
  std::vector<Case> cases;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(BEARING_SOURCE_DIR) + "/examples"))
    if (entry.path().extension() == ".toml") cases.push_back(read_case_file(entry.path()));
  ASSERT_GE(cases.size(), 10u);
  cases.push_back(
      parse_case(kFull, "full.toml",
                 {parse_override("model.kind=balls"), parse_override("cage.slip=0.02"),
                  parse_override("ball.mass=0.03"), parse_override("ball_errors.band=\"1 um\""),
                  parse_override("acoustics.microphones=[[\"1 m\", \"30 deg\"]]"),
                  parse_override("output.ball_dynamics=true")}));
  // operation.moment, written only when set (issue 32), and an axial load on a 2dof case (read;
  // run refuses both).
  cases.push_back(read_case_file(std::string(BEARING_SOURCE_DIR) + "/examples/seed003_6308.toml",
                                 {parse_override("operation.moment=[\"2 N*m\", \"-0.3 N m\"]"),
                                  parse_override("operation.axial_load=50")}));
  // The text without its comments (the file it came from, where ball errors were drawn from).
  const auto body = [](const std::string& text) {
    std::istringstream in(text);
    std::string out;
    for (std::string line; std::getline(in, line);)
      if (line.rfind('#', 0) != 0) out += line + "\n";
    return out;
  };
  for (const Case& a : cases) {
    const std::string text = case_to_toml(a);
    const Case b = parse_case(text, "case.toml");
    EXPECT_EQ(body(case_to_toml(b)), body(text)) << a.source;
    EXPECT_EQ(b.acoustics.enabled, a.acoustics.enabled) << a.source;
    EXPECT_EQ(b.model.kind, a.model.kind) << a.source;
  }
}

// Every key the reader accepts is listed in --help with its units, and each numeric one has a
// dimension for sweeps.
TEST(CaseSchema, EveryKeyIsDocumented) {
  const std::string help = case_keys_help();
  for (const std::string& key : known_keys()) {
    EXPECT_NE(help.find("  " + key + " "), std::string::npos) << key;
    if (key_is_integer(key)) EXPECT_EQ(key_dimension(key), Dimension::dimensionless) << key;
  }
  EXPECT_EQ(key_dimension("operation.speed"), Dimension::angular_speed);
  EXPECT_EQ(key_dimension("waviness.outer.3.phase"), Dimension::angle);
  EXPECT_THROW(key_dimension("model.kind"), InputError);
}

// A whole number the int it lands in cannot hold is refused by name, never wrapped around.
TEST(CaseSchema, HugeIntegersAreRefused) {
  for (const char* set : {"bearing.balls=99999999999", "output.peaks=4294967306",
                          "waviness.inner=[{order=4294967297, amplitude=\"1 um\"}]",
                          "bearing.balls=-9223372036854775808",
                          "waviness.inner=[{order=-9223372036854775808, amplitude=\"1 um\"}]"}) {
    try {
      parse_case("[bearing]\npreset = \"6308\"\n", "t", {parse_override(set)});
      FAIL() << set;
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find(std::string(set).substr(0, std::string(set).find('='))), std::string::npos)
          << msg;
    }
  }
}

// A non-ASCII character outside a string or comment (a unit left outside the quotes) is a syntax
// error naming its line and column; inside strings and comments it is fine. (Found by
// tests/fuzz/: Debian's toml++ 3.3.0 reaches undefined behaviour on such text, so it never sees
// it.)
TEST(CaseFile, NonAsciiOutsideStringsIsAClearSyntaxError) {
  const std::string base = "[bearing]\npreset = \"6308\"\n";
  for (const char* bad : {"contact_angle = 15 \xC2\xB0\n", "contact_angle = \"15 deg\" \xC2\xB5\n",
                          "\xC2\xA7 = 1\n"}) {
    try {
      parse_case(base + bad, "t.toml");
      FAIL() << bad;
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find("t.toml:3:"), std::string::npos) << msg;
      EXPECT_NE(msg.find("non-ASCII character outside a string"), std::string::npos) << msg;
    }
  }
  try {
    parse_case("[bearing]\npreset = \"\"\"\\\n\xC2\xA7\"\"\"\n", "t.toml");
    FAIL() << "a line-ending backslash before a non-ASCII character";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("t.toml:3:1: TOML syntax error: a non-ASCII character "
                                         "right after a backslash"),
              std::string::npos)
        << e.what();
  }
  // A control character, anywhere (found by sanitize.fuzz: a NUL after '[' broke toml++'s
  // assumption about a key's first character).
  for (const std::string bad : {std::string("[\0bearing]\n", 11), std::string("a = \"\x01\"\n"),
                                std::string("# \x7F\n"), std::string("a = 1\x0B\n")}) {
    try {
      parse_case(bad, "t.toml");
      FAIL() << "control character accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("t.toml:1:"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("a control character (U+00"), std::string::npos)
          << e.what();
    }
  }
  // A table header that does not start with a name (sanitize.fuzz: toml++ assumed it did).
  // A bracket closing what it did not open ('[[}': toml++ took the '}' for a value).
  for (const char* bad : {"[(bearing]\n", "[[ =x]]\n", "[bearing]\na = 1\n[ .x]\n",
                          "[bearing]\npreset = [[[}}1]\n", "a = {b = [1}]\n", "a = {b = 1]\n"}) {
    try {
      parse_case(bad, "t.toml");
      FAIL() << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("TOML syntax error"), std::string::npos) << e.what();
    }
  }
  // Inside a bare value a quote opens no string for toml++: still outside a string.
  EXPECT_THROW(parse_case(base + "contact_angle = 15x=[[\"\xC2\xB0\"]]\n", "t.toml"), InputError);
  // Strings where keys and values start, in arrays and inline tables, are read (and then judged
  // by the schema).
  for (const char* ok :
       {"[operation]\nload = [\"1 N\", '2 \xC2\xB5N']\n",
        "[[waviness.inner]]\norder = 3\namplitude = \"1 \xC2\xB5m\"\n",
        "x = {a = \"\xC2\xB5\", b = [1, \"\xC2\xB5\"]}\n", "bearing.\"\xC2\xB5\" = 1\n"}) {
    try {
      parse_case(base + ok, "t.toml");
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).find("non-ASCII"), std::string::npos) << e.what();
    }
  }
  const Case c =
      parse_case(base + "# 15 \xC2\xB0\ncontact_angle = \"15 \xC2\xB0\"  # \xC2\xB5\n", "t.toml");
  EXPECT_DOUBLE_EQ(c.bearing.contact_angle, 15 * pi / 180);
  // On the command line such a value is taken as a string, and the unit is checked as usual.
  EXPECT_DOUBLE_EQ(
      default_case({parse_override("bearing.contact_angle=15 \xC2\xB0")}).bearing.contact_angle,
      15 * pi / 180);
  EXPECT_THROW(default_case({parse_override("operation.speed=2000 \xC2\xB0")}), InputError);
}

// An array index in a --set key beyond any std::size_t is refused like any index past the end
// (found by tests/fuzz/: std::stoul's out_of_range escaped).
TEST(CaseFile, HugeOverrideIndexIsRefusedByName) {
  const std::string text =
      "[bearing]\npreset = \"6308\"\n[[waviness.inner]]\norder = 3\namplitude = \"1 um\"\n";
  for (const char* index : {"1", "99999999999999999999"}) {
    try {
      parse_case(text, "t.toml",
                 {parse_override("waviness.inner." + std::string(index) + ".amplitude=2 um")});
      FAIL() << index;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("index ") + index +
                                           " is past the 1 entries of inner"),
                std::string::npos)
          << e.what();
    }
  }
}

// A message showing an array with a float below 1 (toml++ 3.3.0's array printer casts a negative
// log10 to size_t, undefined; found by tests/fuzz/) shows it element by element.
TEST(CaseFile, ArraysInMessagesAreShownElementByElement) {
  try {
    parse_case("[bearing]\npreset = \"6308\"\n[operation]\nload = [0.5, 0.25, [], 3]\n", "t.toml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("operation.load = [ 0.5, 0.25, [], 3 ]: expected two "
                                         "values"),
              std::string::npos)
        << e.what();
  }
}
