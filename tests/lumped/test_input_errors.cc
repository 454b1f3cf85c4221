// Every malformed input gets one clear message naming the key, the value and what is allowed.

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bearing/case_file.h"
#include "bearing/errors.h"

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
      {"unknown table", kPreset + "[solver]\ndt = 1e-6\n", {"solver", "Known tables"}},
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
      {"calibrated law not available",
       kPreset + "[model]\ncontact = \"calibrated\"\n",
       {"model.contact", "calibrated", "exact"}},
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
