// Every malformed input gets one clear message naming the key, the value and what is allowed.

#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bearing/case_file.h"
#include "bearing/errors.h"
#include "bearing/models/model_registry.h"
#include "bearing/simulation.h"

namespace {

struct BadCase {
  const char* what;                    // what is wrong
  std::string toml;                    // the case text
  std::vector<std::string> expect;     // substrings the message must contain
  std::vector<std::string> sets = {};  // --set overrides
};

// A complete valid geometry that each case breaks in one place.
std::string geometry(const std::string& replace_key = "", const std::string& with = "") {
  const std::vector<std::pair<std::string, std::string>> keys = {{"ball_diameter", "\"15.081 mm\""},
                                                                 {"pitch_diameter", "\"65 mm\""},
                                                                 {"balls", "8"},
                                                                 {"inner_conformity", "0.52"},
                                                                 {"outer_conformity", "0.52"},
                                                                 {"clearance", "\"14 um\""}};
  std::string s = "[bearing]\n";
  for (const auto& [k, v] : keys) {
    if (k == replace_key) {
      if (!with.empty()) s += k + " = " + with + "\n";
    } else {
      s += k + " = " + v + "\n";
    }
  }
  return s;
}

const std::string kPreset = "[bearing]\npreset = \"6308\"\n";

std::vector<BadCase> bad_cases() {
  return {
      // unknown names
      {"unknown key, nearest suggested", kPreset + "bals = 9\n", {"bearing.bals", "bearing.balls"}},
      {"unknown key in operation",
       kPreset + "[operation]\nsped = \"2000 rpm\"\n",
       {"operation.sped", "operation.speed"}},
      {"key in the wrong table",
       kPreset + "speed = \"2000 rpm\"\n",
       {"bearing.speed", "operation.speed"}},
      {"unknown table, nearest suggested",
       kPreset + "[solvr]\ndt = 1e-6\n",
       {"solvr", "solver", "Known tables"}},
      {"unknown top-level key", "speed = 3\n" + kPreset, {"speed", "operation.speed"}},
      {"unknown material key",
       kPreset + "[material]\nyoungs = \"208 GPa\"\n",
       {"material.youngs", "material.young"}},
      {"unknown sub-table key",
       kPreset + "[material.ball]\nE = \"208 GPa\"\n",
       {"material.ball.E", "young"}},
      {"unknown preset", "[bearing]\npreset = \"6309\"\n", {"bearing.preset", "6309", "6308"}},
      {"unknown contact method",
       kPreset + "[model]\ncontact = \"hertz\"\n",
       {"model.contact", "hertz", "exact", "hamrock-brewe", "harris-table"}},
      // wrong types
      {"balls as string", geometry("balls", "\"eight\""), {"bearing.balls", "eight", "integer"}},
      {"balls not whole", geometry("balls", "8.5"), {"bearing.balls", "8.5", "whole number"}},
      {"diameter as boolean",
       geometry("ball_diameter", "true"),
       {"bearing.ball_diameter", "true", "boolean", "unit"}},
      {"load not a pair",
       kPreset + "[operation]\nload = \"-20 N\"\n",
       {"operation.load", "-20 N", "[x, y]"}},
      {"load with three values",
       kPreset + "[operation]\nload = [0, -20, 5]\n",
       {"operation.load", "two values"}},
      {"preset as float", "[bearing]\npreset = 6308.0\n", {"bearing.preset", "6308", "string"}},
      {"material not a table", kPreset + "[material]\nball = 3\n", {"material.ball", "3", "table"}},
      {"contact method not a string",
       kPreset + "[model]\ncontact = 1\n",
       {"model.contact", "1", "string"}},
      // units
      {"missing unit on speed",
       kPreset + "[operation]\nspeed = 2000\n",
       {"operation.speed", "2000", "missing unit", "rpm"}},
      {"missing unit on angle",
       geometry() + "contact_angle = 15\n",
       {"bearing.contact_angle", "15", "missing unit", "deg"}},
      {"string without unit",
       geometry("clearance", "\"14\""),
       {"bearing.clearance", "14", "missing unit", "um"}},
      {"unknown unit",
       geometry("ball_diameter", "\"15 mmm\""),
       {"bearing.ball_diameter", "mmm", "accepted units", "mm"}},
      {"unit of another dimension",
       kPreset + "[operation]\nspeed = \"2000 mm\"\n",
       {"operation.speed", "mm", "length", "rpm"}},
      {"unit on a dimensionless number",
       geometry("inner_conformity", "\"0.52 mm\""),
       {"bearing.inner_conformity", "0.52 mm", "dimensionless"}},
      {"not a number",
       geometry("pitch_diameter", "\"sixty mm\""),
       {"bearing.pitch_diameter", "sixty mm", "number"}},
      {"load entry with bad unit",
       kPreset + "[operation]\nload = [\"0 N\", \"-20 kg\"]\n",
       {"operation.load[1]", "kg", "mass", "N"}},
      // ranges
      {"negative ball diameter",
       geometry("ball_diameter", "\"-15 mm\""),
       {"bearing.ball_diameter", "-15 mm", "positive"}},
      {"zero pitch diameter",
       geometry("pitch_diameter", "0"),
       {"bearing.pitch_diameter", "0 mm", "positive"}},
      {"too few balls", geometry("balls", "2"), {"bearing.balls", "2", "at least 3"}},
      {"negative balls", geometry("balls", "-8"), {"bearing.balls", "-8", "at least 3"}},
      {"groove radius not larger than ball radius",
       geometry("inner_conformity", "0.5"),
       {"bearing.inner_conformity", "0.5", "groove radius", "> 0.5"}},
      {"outer groove too tight",
       geometry("outer_conformity", "0.45"),
       {"bearing.outer_conformity", "0.45", "> 0.5"}},
      {"pitch not larger than ball",
       geometry("pitch_diameter", "\"15 mm\""),
       {"bearing.pitch_diameter", "15 mm", "larger than the ball diameter", "15.081 mm"}},
      {"balls do not fit", geometry("balls", "20"), {"bearing.balls", "20", "do not fit"}},
      {"negative clearance",
       geometry("clearance", "\"-2 um\""),
       {"bearing.clearance", "-2 um", ">= 0"}},
      {"clearance in mm by mistake",
       geometry("clearance", "\"14 mm\""),
       {"bearing.clearance", "14000 um", "ball diameter"}},
      {"contact angle too large",
       geometry() + "contact_angle = \"95 deg\"\n",
       {"bearing.contact_angle", "95 deg", "[0 deg, 90 deg)"}},
      {"Poisson ratio 0.5",
       kPreset + "[material]\npoisson = 0.5\n",
       {"poisson", "0.5", "(-1, 0.5)"}},
      {"Poisson ratio -1",
       kPreset + "[material.ball]\npoisson = -1\n",
       {"material.ball.poisson", "-1", "(-1, 0.5)"}},
      {"zero modulus",
       kPreset + "[material.rings]\nyoung = \"0 GPa\"\n",
       {"material.rings.young", "0", "positive"}},
      {"negative speed",
       kPreset + "[operation]\nspeed = \"-100 rpm\"\n",
       {"operation.speed", "-100 rpm", ">= 0"}},
      {"missing geometry without preset",
       geometry("balls", ""),
       {"bearing.balls", "missing", "preset"}},
      {"calibrated law without its file",
       kPreset + "[model]\ncontact = \"calibrated\"\n",
       {"model.contact", "calibrated", "needs model.calibration"}},
      {"calibration file without the calibrated law",
       kPreset + "[model]\ncalibration = \"cal.json\"\n",
       {"model.calibration", "cal.json", "model.contact = \"exact\""}},
      // dynamics tables
      {"rotor mass zero", kPreset + "[rotor]\nmass = 0\n", {"rotor.mass", "0 kg", "positive"}},
      {"negative damping",
       kPreset + "[rotor]\ndamping = \"-5 N s/m\"\n",
       {"rotor.damping", "-5", ">= 0"}},
      {"gravity not a boolean",
       kPreset + "[operation]\ngravity = \"yes\"\n",
       {"operation.gravity", "yes", "true or false"}},
      {"unbalance with a length unit",
       kPreset + "[operation]\nunbalance = \"3 mm\"\n",
       {"operation.unbalance", "mm", "length", "g mm"}},
      {"waviness order zero",
       kPreset + "[[waviness.inner]]\norder = 0\namplitude = \"1 um\"\n",
       {"waviness.inner[0].order", "0", ">= 1"}},
      {"waviness negative amplitude",
       kPreset + "[[waviness.outer]]\norder = 8\namplitude = \"-1 um\"\n",
       {"waviness.outer[0].amplitude", "-1e-06 m", ">= 0"}},
      {"waviness amplitude in mm by mistake",
       kPreset + "[[waviness.outer]]\norder = 8\namplitude = \"1 mm\"\n",
       {"waviness.outer[0].amplitude", "0.001 m", "1 %"}},
      {"waviness entry without amplitude",
       kPreset + "[[waviness.inner]]\norder = 8\n",
       {"waviness.inner[0]", "order and amplitude"}},
      {"waviness unknown key",
       kPreset + "[[waviness.inner]]\norder = 8\namplitude = 1e-6\namp = 1e-6\n",
       {"waviness.inner[0].amp", "amplitude"}},
      {"waviness table and harmonic in one entry",
       kPreset + "[[waviness.inner]]\ntable = \"w.csv\"\norder = 8\n",
       {"waviness.inner[0].order", "either table"}},
      {"waviness table unreadable",
       kPreset + "[[waviness.inner]]\ntable = \"/nonexistent.csv\"\n",
       {"waviness.inner[0].table", "/nonexistent.csv"}},
      {"waviness not entries",
       kPreset + "[waviness]\ninner = 8\n",
       {"waviness.inner", "8", "[[waviness.inner]]"}},
      {"ball errors count",
       kPreset + "[ball_errors]\nvalues = [\"1 um\", \"2 um\"]\n",
       {"ball_errors.values", "2 entries", "one per ball (8)"}},
      {"ball errors values and band",
       kPreset + "[ball_errors]\nvalues = [0,0,0,0,0,0,0,0]\nband = \"2 um\"\n",
       {"ball_errors", "either values", "band"}},
      {"ball errors seed without band",
       kPreset + "[ball_errors]\nseed = 3\n",
       {"ball_errors.seed", "3", "band"}},
      {"ball errors band too wide",
       kPreset + "[ball_errors]\nband = \"1 mm\"\n",
       {"ball_errors.band", "0.001 m", "2 %"}},
      {"cage slip of 100 %",
       kPreset + "[model]\nkind = \"balls\"\n[cage]\nslip = 1.0\n",
       {"cage.slip", "1", "[0, 1)"}},
      {"cage table without the ball model",
       kPreset + "[cage]\nslip = 0.02\n",
       {"[cage]", "balls", "2dof"}},
      {"ball inertia not positive",
       kPreset + "[model]\nkind = \"balls\"\n[ball]\ninertia = \"0 kg m^2\"\n",
       {"ball.inertia", "0 kg m^2", "positive"}},
      {"model kind unknown",
       kPreset + "[model]\nkind = \"4dof\"\n",
       {"model.kind", "4dof", "2dof, 3dof"}},
      {"solver method unknown",
       kPreset + "[solver]\nmethod = \"euler\"\n",
       {"solver.method", "euler", "rk4", "rk8pd", "newmark", "bdf"}},
      {"solver dt zero", kPreset + "[solver]\ndt = 0\n", {"solver.dt", "0 s", "(0, 1 ms]"}},
      {"solver transient too long",
       kPreset + "[solver]\nduration = \"1 s\"\ntransient = \"2 s\"\n",
       {"solver.transient", "2 s", "shorter than solver.duration", "1 s"}},
      {"solver tolerance too loose",
       kPreset + "[solver]\ntolerance = 0.5\n",
       {"solver.tolerance", "0.5", "(0, 0.1]"}},
      {"solver dt without unit as string",
       kPreset + "[solver]\ndt = \"5\"\n",
       {"solver.dt", "missing unit", "us"}},
      {"too few samples",
       kPreset + "[solver]\noutput_rate = \"10 Hz\"\n",
       {"solver.output_rate", "10 Hz", "fewer than 16"}},
      {"output window unknown",
       kPreset + "[output]\nwindow = \"hamming\"\n",
       {"output.window", "hamming", "hann", "flattop"}},
      {"output peaks negative", kPreset + "[output]\npeaks = -1\n", {"output.peaks", "-1"}},
      // acoustics
      {"acoustics without microphones",
       kPreset + "[acoustics]\nsummation = \"energetic\"\n",
       {"acoustics.microphones", "at least one"}},
      {"microphone not a pair",
       kPreset + "[acoustics]\nmicrophones = [[\"10 mm\"]]\n",
       {"acoustics.microphones", "entry 0", "[r, angle]"}},
      {"microphone angle without unit",
       kPreset + "[acoustics]\nmicrophones = [[\"10 mm\", 90]]\n",
       {"acoustics.microphones[0][1] (angle)", "missing unit", "deg"}},
      {"microphone at the centre",
       kPreset + "[acoustics]\nmicrophones = [[0, \"0 deg\"]]\n",
       {"acoustics.microphones[0] r", "(0, 100 m]"}},
      {"unknown ball source",
       kPreset + "[acoustics]\nmicrophones = [[\"1 m\", \"0 deg\"]]\nball_source = \"sphere\"\n",
       {"acoustics.ball_source", "sphere", "oscillating-sphere", "pulsating-sphere"}},
      {"nothing radiates",
       kPreset + "[acoustics]\nmicrophones = [[\"1 m\", \"0 deg\"]]\nring_source = \"none\"\n"
                 "ball_source = \"none\"\n",
       {"acoustics", "both \"none\""}},
      {"microphone inside the ring",
       kPreset + "[acoustics]\nmicrophones = [[\"1 m\", \"0 deg\"], [\"5 mm\", \"0 deg\"]]\n",
       {"acoustics.microphones[1] r", "0.005 m", "inside the ring source", "0.0249595 m"}},
      {"microphone where the balls pass",
       kPreset + "[acoustics]\nmicrophones = [[\"28 mm\", \"0 deg\"]]\n",
       {"acoustics.microphones[0] r", "0.028 m", "annulus the balls sweep", "0.0400405 m",
        "ball_source"}},
      {"ring radius beyond the pitch circle",
       kPreset + "[acoustics]\nmicrophones = [[\"1 m\", \"0 deg\"]]\nring_radius = \"40 mm\"\n",
       {"acoustics.ring_radius", "0.04 m", "d_m/2"}},
      {"sound speed in the wrong unit",
       kPreset + "[acoustics]\nmicrophones = [[\"1 m\", \"0 deg\"]]\nsound_speed = \"343 Hz\"\n",
       {"acoustics.sound_speed", "Hz"}},
      // syntax and command line
      {"TOML syntax error", "[bearing\npreset = \"6308\"\n", {"t.toml:1", "TOML syntax error"}},
      {"override of an unknown key",
       kPreset,
       {"bearing.ballz", "bearing.balls"},
       {"bearing.ballz=9"}},
      {"override with bad value",
       kPreset,
       {"bearing.balls", "2", "at least 3"},
       {"bearing.balls=2"}},
      // [lubricant] (issue 43): key, value and range in the message
      {"lubricant viscosity out of range",
       kPreset + "[lubricant]\nviscosity = \"200 Pa s\"\npressure_viscosity = \"2e-8 1/Pa\"\n"
                 "roughness = \"0.1 um\"\n",
       {"lubricant.viscosity", "200", "[1e-6, 100] Pa s"}},
      {"lubricant pressure-viscosity zero",
       kPreset + "[lubricant]\nviscosity = \"20 mPa s\"\npressure_viscosity = 0\n"
                 "roughness = \"0.1 um\"\n",
       {"lubricant.pressure_viscosity", "0", "(0, 1e-7] 1/Pa"}},
      {"lubricant viscosity missing",
       kPreset + "[lubricant]\npressure_viscosity = \"2e-8 1/Pa\"\nroughness = \"0.1 um\"\n",
       {"lubricant.viscosity", "missing"}},
      {"lubricant bare temperature",
       kPreset + "[lubricant]\nviscosity = \"20 mPa s\"\npressure_viscosity = \"2e-8 1/Pa\"\n"
                 "roughness = \"0.1 um\"\ntemperature = 80\n",
       {"lubricant.temperature", "80", "degC"}},
      {"lubricant temperature law beyond its span",
       kPreset + "[lubricant]\nviscosity = \"20 mPa s\"\npressure_viscosity = \"2e-8 1/Pa\"\n"
                 "roughness = \"0.1 um\"\ntemperature = \"100 degC\"\n"
                 "reference_temperature = \"40 degC\"\nviscosity_temperature = \"0.03 1/K\"\n",
       {"lubricant.temperature", "373.15", "reference_temperature"}},
      {"lubricant temperature without its reference",
       kPreset + "[lubricant]\nviscosity = \"20 mPa s\"\npressure_viscosity = \"2e-8 1/Pa\"\n"
                 "roughness = \"0.1 um\"\ntemperature = \"60 degC\"\n",
       {"lubricant.reference_temperature", "missing"}},
      {"override through a value",
       kPreset,
       {"bearing.preset", "not a table"},
       {"bearing.preset.x=1"}},
  };
}

}  // namespace

TEST(InputErrors, EachMalformedCaseGetsAClearMessage) {
  const auto cases = bad_cases();
  ASSERT_GE(cases.size(), 30u);
  for (const auto& bc : cases) {
    std::vector<bearing::Override> sets;
    for (const auto& s : bc.sets) sets.push_back(bearing::parse_override(s));
    try {
      bearing::parse_case(bc.toml, "t.toml", sets);
      ADD_FAILURE() << bc.what << ": no error for\n" << bc.toml;
    } catch (const bearing::InputError& e) {
      const std::string m = e.what();
      EXPECT_EQ(m.rfind("t.toml", 0), 0u) << bc.what << ": message does not name the file: " << m;
      for (const auto& s : bc.expect)
        EXPECT_NE(m.find(s), std::string::npos)
            << bc.what << ": message lacks \"" << s << "\": " << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << bc.what << ": not one line: " << m;
    }
  }
}

// Loads a model kind cannot carry are refused when it is to run (run_settings: run, sweep, Python's
// run), with one message naming the key, the value, why and what is allowed; the case itself
// reads, since the static analyses (info, stiffness) carry every load whatever the kind.
TEST(InputErrors, LoadsAKindCannotCarryAreRefusedWhenItRuns) {
  const std::vector<BadCase> cases = {
      {"axial load on the 2-DOF model",
       kPreset + "[operation]\nload = [0, -100]\naxial_load = \"50 N\"\n",
       {"operation.axial_load = 50 N", "model.kind = \"2dof\"", "no axial degree of freedom",
        "allowed: 0", "\"3dof\" or \"balls\""}},
      {"axial-only load: no static solution without an axial DOF",
       kPreset + "[operation]\nload = [0, 0]\naxial_load = \"50 N\"\n[model]\n"
                 "kind = \"quasistatic\"\n",
       {"operation.axial_load = 50 N", "\"quasistatic\"", "no ball is in its load zone",
        "static solution does not exist", "\"3dof\""}},
      {"a moment on any kind",
       kPreset + "[operation]\nmoment = [\"1.5 N m\", 0]\n[model]\nkind = \"3dof\"\n",
       {"operation.moment = [1.5, 0] N m", "\"3dof\"", "no tilt degree of freedom",
        "allowed: [0, 0]", "stiffness"}},
  };
  for (const auto& bc : cases) {
    const bearing::Case c = bearing::parse_case(bc.toml, "t.toml");
    try {
      bearing::run_settings(c);
      ADD_FAILURE() << bc.what << ": no error for\n" << bc.toml;
    } catch (const bearing::InputError& e) {
      const std::string m = e.what();
      for (const auto& s : bc.expect)
        EXPECT_NE(m.find(s), std::string::npos)
            << bc.what << ": message lacks \"" << s << "\": " << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << bc.what << ": not one line: " << m;
    }
    EXPECT_THROW(bearing::check_run_loads(c), bearing::InputError) << bc.what;
  }
}

// The registry row decides: each kind that carries an axial load runs one (an axial-only load
// included), each other kind refuses it, so a new kind is covered by its row.
TEST(InputErrors, AxialLoadFollowsTheModelRegistry) {
  for (const bearing::ModelDescriptor& d : bearing::model_registry()) {
    const std::string kind = bearing::name_of(bearing::kModelKinds, d.kind);
    const std::string toml =
        "[bearing]\npreset = \"6308\"\n[operation]\nload = [0, 0]\n"
        "axial_load = \"200 N\"\n[model]\nkind = \"" +
        kind + "\"\n";
    const bearing::Case c = bearing::parse_case(toml, "t.toml");  // every kind reads it
    if (d.axial_load) {
      EXPECT_NO_THROW(bearing::run_settings(c)) << kind;
      continue;
    }
    EXPECT_THROW(bearing::run_settings(c), bearing::InputError) << kind;
    // The library refuses it as well, for a caller that builds ModelInputs itself.
    bearing::ModelInputs in = bearing::model_inputs(bearing::parse_case(
        "[bearing]\npreset = \"6308\"\n[model]\nkind = \"" + kind + "\"\n", "t.toml"));
    in.axial_load = 200;
    EXPECT_THROW(bearing::make_run(d.kind, in, bearing::SolverSettings{}), bearing::InputError)
        << kind;
  }
}

TEST(InputErrors, UnreadableFileIsNamed) {
  try {
    bearing::read_case_file("/nonexistent/case.toml");
    FAIL();
  } catch (const bearing::InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("/nonexistent/case.toml"), std::string::npos) << m;
    EXPECT_NE(m.find("cannot read"), std::string::npos) << m;
  }
}

TEST(InputErrors, CommandLineExitsNonZeroWithOneMessageAndNoOutput) {
  const std::string dir = ::testing::TempDir();
  const std::string bad = dir + "/bad_case.toml";
  std::ofstream(bad) << "[bearing]\npreset = \"6308\"\nbals = 9\n";
  const std::string out = dir + "/bad_out.txt", err = dir + "/bad_err.txt";
  const std::string cmd =
      std::string(BEARING_SIM) + " info " + bad + " --json > " + out + " 2> " + err;
  const int status = std::system(cmd.c_str());
  EXPECT_NE(status, 0);
  std::ifstream o(out), e(err);
  const std::string stdout_text((std::istreambuf_iterator<char>(o)), {});
  const std::string stderr_text((std::istreambuf_iterator<char>(e)), {});
  EXPECT_TRUE(stdout_text.empty()) << stdout_text;
  EXPECT_NE(stderr_text.find("bearing.bals"), std::string::npos) << stderr_text;
  EXPECT_NE(stderr_text.find("bearing.balls"), std::string::npos) << stderr_text;
}

// A bad [lubricant] value on the command line: exit 2 (an input error), one message on stderr
// naming the key, the value and the range, nothing on stdout.
TEST(InputErrors, BadLubricantExitsTwoNamingKeyValueAndRange) {
  const std::string dir = ::testing::TempDir();
  const std::string bad = dir + "/bad_lubricant.toml";
  std::ofstream(bad) << "[bearing]\npreset = \"6205\"\n[lubricant]\nviscosity = \"20 mPa s\"\n"
                        "pressure_viscosity = \"2e-8 1/Pa\"\nroughness = \"20 um\"\n";
  const std::string out = dir + "/bad_lub_out.txt", err = dir + "/bad_lub_err.txt";
  const std::string cmd = std::string(BEARING_SIM) + " info " + bad + " > " + out + " 2> " + err;
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  std::ifstream o(out), e(err);
  const std::string stdout_text((std::istreambuf_iterator<char>(o)), {});
  const std::string stderr_text((std::istreambuf_iterator<char>(e)), {});
  EXPECT_TRUE(stdout_text.empty()) << stdout_text;
  for (const char* s : {"lubricant.roughness", "2e-05", "(0, 10 um]"})
    EXPECT_NE(stderr_text.find(s), std::string::npos) << s << ": " << stderr_text;
}
