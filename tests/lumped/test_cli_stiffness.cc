// bearing-sim stiffness end to end (issue 32): the files and their columns, the values against
// a direct solve_five_dof, the grid of --vary, info's matrix, operation.moment (read by every
// command, refused by run), the ball pass (stiffness_ball_pass.csv, stiffness.json's ball_pass,
// info's lines) against direct solves and the kinematics, and the errors: exit status, message,
// no output folder. ROSS's table and the rotor's matrix: test_cli_rotor_stiffness.cc.

#include <cmath>
#include <complex>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bearing/case_file.h"
#include "bearing/five_dof_static.h"
#include "bearing/info_report.h"
#include "cli_helpers.h"
#include "cli_stiffness_helpers.h"

namespace {

namespace fs = std::filesystem;
using bearing::test::fresh_dir;
using bearing::test::read;
using bearing::test::sim;
using namespace bearing::test::stiffness;

const char* const kKColumns[] = {"k_xx [N/m]",        "k_xy [N/m]",        "k_xz [N/m]",
                                 "k_x_gx [N/rad]",    "k_x_gy [N/rad]",    "k_yy [N/m]",
                                 "k_yz [N/m]",        "k_y_gx [N/rad]",    "k_y_gy [N/rad]",
                                 "k_zz [N/m]",        "k_z_gx [N/rad]",    "k_z_gy [N/rad]",
                                 "k_gx_gx [N*m/rad]", "k_gx_gy [N*m/rad]", "k_gy_gy [N*m/rad]"};

// The row's K_ij, q and load are the direct solution's, to the bit (shortest round-trip text).
void expect_row_is(const Csv& csv, std::size_t row, const bearing::FiveDofSolution& s) {
  int n = 0;
  for (int i = 0; i < 5; ++i)
    for (int j = i; j < 5; ++j) EXPECT_EQ(csv.at(row, kKColumns[n++]), s.at.stiffness(i, j));
  const char* q[] = {"x [m]", "y [m]", "z [m]", "gx [rad]", "gy [rad]"};
  for (int i = 0; i < 5; ++i) EXPECT_EQ(csv.at(row, q[i]), s.displacement(i)) << q[i];
  double q_max = 0;
  int loaded = 0;
  for (double Q : s.at.ball_loads) q_max = std::max(q_max, Q), loaded += Q > 0;
  EXPECT_EQ(csv.at(row, "q_max [N]"), q_max);
  EXPECT_EQ(csv.at(row, "loaded_balls"), loaded);
}

TEST(CliStiffness, OnePointEqualsTheDirectSolution) {
  const fs::path d = fresh_dir("stiffness_one");
  std::string out;
  const std::string sets =
      " --set operation.axial_load=100 --set 'operation.moment=[\"0.5 N*m\", 0]'";
  ASSERT_EQ(sim("stiffness " + kExample + sets + " --out " + d.string(), &out), 0) << out;
  const Csv csv = read_csv(d / "stiffness.csv");
  std::vector<std::string> header(std::begin(kKColumns), std::end(kKColumns));
  for (const char* c : {"x [m]", "y [m]", "z [m]", "gx [rad]", "gy [rad]", "q_max [N]",
                        "loaded_balls", "Fx [N]", "Fy [N]", "Fz [N]", "Mx [N*m]", "My [N*m]"})
    header.push_back(c);
  EXPECT_EQ(csv.header, header);
  ASSERT_EQ(csv.rows.size(), 1u);
  const bearing::FiveDofSolution s = direct({bearing::parse_override("operation.axial_load=100"),
                                             bearing::parse_override("operation.moment=[0.5, 0]")});
  expect_row_is(csv, 0, s);
  EXPECT_EQ(csv.at(0, "Fz [N]"), 100.0);
  EXPECT_EQ(csv.at(0, "Mx [N*m]"), 0.5);

  const auto j = nlohmann::json::parse(read(d / "stiffness.json"));
  const auto& K = j["points"][0]["stiffness_at_cage_angle"];
  EXPECT_EQ(j["points"][0]["cage_angle"].get<double>(), 0.0);  // the example's cage phase
  EXPECT_EQ(j["units"]["cage_angle"], "rad");
  for (int r = 0; r < 5; ++r)
    for (int c = 0; c < 5; ++c) {
      EXPECT_EQ(K[r][c].get<double>(), s.at.stiffness(r, c));
      EXPECT_EQ(K[r][c].get<double>(), K[c][r].get<double>());  // k_xy == k_yx
    }
  EXPECT_EQ(j["points"][0]["ball_loads"].size(), 8u);
  EXPECT_EQ(j["points"][0]["contact_angles"].size(), 8u);
  EXPECT_EQ(j["units"]["stiffness"][3][4], "N*m/rad");
  EXPECT_EQ(j["units"]["stiffness"][0][3], "N/rad");
  EXPECT_EQ(j["units"]["stiffness"][3][0], "N");
  EXPECT_NE(j["model"]["assumptions"].dump().find("centrifugal"), std::string::npos);
  // The matrix with its labels on stdout.
  for (const char* label : {"K = dF/dq", "Fx [N]", "My [N*m]", "gy [rad]", "N*m/rad"})
    EXPECT_NE(out.find(label), std::string::npos) << label << "\n" << out;
  EXPECT_EQ(sim("stiffness " + kExample + sets + " --quiet --out " + d.string(), &out), 0);
  EXPECT_EQ(out, "");
}

// The brief's grid: k_zz grows with the preload; every row is its own direct solution.
TEST(CliStiffness, GridOfAxialLoads) {
  const fs::path d = fresh_dir("stiffness_grid");
  std::string out;
  ASSERT_EQ(
      sim("stiffness " + kExample + " --vary operation.axial_load=0:200:3 --out " + d.string(),
          &out),
      0)
      << out;
  const Csv csv = read_csv(d / "stiffness.csv");
  ASSERT_EQ(csv.header.at(0), "operation.axial_load [N]");
  EXPECT_EQ(csv.header.at(1), "k_xx [N/m]");
  ASSERT_EQ(csv.rows.size(), 3u);
  for (std::size_t r = 0; r < 3; ++r) {
    EXPECT_EQ(csv.at(r, "operation.axial_load [N]"), 100.0 * r);
    expect_row_is(
        csv, r,
        direct({bearing::parse_override("operation.axial_load=" + std::to_string(100 * r))}));
  }
  EXPECT_LT(csv.at(0, "k_zz [N/m]"), csv.at(1, "k_zz [N/m]"));
  EXPECT_LT(csv.at(1, "k_zz [N/m]"), csv.at(2, "k_zz [N/m]"));
  const auto j = nlohmann::json::parse(read(d / "stiffness.json"));
  EXPECT_EQ(j["varied"][0]["key"], "operation.axial_load");
  EXPECT_EQ(j["varied"][0]["unit"], "N");
  EXPECT_EQ(j["points"][2]["values"]["operation.axial_load"], 200.0);
  EXPECT_NE(out.find("3 operating points"), std::string::npos) << out;
  EXPECT_NE(out.find("k_gx_gx [N*m/rad]"), std::string::npos) << out;
}

// info shows the same matrix, at every load of the case, whatever model.kind (a 2dof case with
// an axial load and a moment: run refuses both, info and stiffness carry them).
TEST(CliStiffness, InfoShowsTheMatrix) {
  std::string out;
  const std::string sets = " --set operation.axial_load=50 --set 'operation.moment=[0, -0.2]'";
  ASSERT_EQ(sim("info --json " + kExample + sets, &out), 0) << out;
  const auto j = nlohmann::json::parse(out);
  const bearing::FiveDofSolution s =
      direct({bearing::parse_override("operation.axial_load=50"),
              bearing::parse_override("operation.moment=[0, -0.2]")});
  for (int r = 0; r < 5; ++r)
    for (int c = 0; c < 5; ++c)
      EXPECT_EQ(j["stiffness"]["matrix"][r][c].get<double>(), s.at.stiffness(r, c));
  EXPECT_EQ(j["stiffness"]["load"][4], -0.2);
  EXPECT_EQ(j["stiffness"]["matrix_units"][4][4], "N*m/rad");
  ASSERT_EQ(sim("info " + kExample + sets, &out), 0) << out;
  EXPECT_NE(out.find("Stiffness at the operating point"), std::string::npos) << out;
  EXPECT_NE(out.find("K = dF/dq"), std::string::npos) << out;
}

// operation.moment: units, written back only when set, and refused by run and sweep (exit 2,
// the key, its value and why, no output) since no model kind has a tilt DOF.
TEST(CliStiffness, RunAndSweepRefuseAMoment) {
  const bearing::Case c = bearing::read_case_file(
      kExample, {bearing::parse_override("operation.moment=[\"2 N*m\", \"-300 N mm\"]")});
  EXPECT_EQ(c.operation.moment.x(), 2.0);
  EXPECT_DOUBLE_EQ(c.operation.moment.y(), -0.3);
  EXPECT_NE(bearing::case_to_toml(c).find("moment = [2.0, -0.29999999999999999]"),
            std::string::npos)
      << bearing::case_to_toml(c);
  EXPECT_EQ(bearing::case_to_toml(bearing::read_case_file(kExample)).find("moment"),
            std::string::npos);
  for (const std::string command : {"run", "sweep --vary operation.speed=1000rpm:2000rpm:2"}) {
    const fs::path d = fresh_dir("moment_refused");
    std::string out;
    EXPECT_EQ(sim(command + " " + kExample + " --set 'operation.moment=[1, 0]' --quiet --out " +
                      d.string(),
                  &out),
              2)
        << command;
    for (const char* s : {"operation.moment = [1, 0] N m", "no tilt degree of freedom",
                          "allowed: [0, 0]", "stiffness"})
      EXPECT_NE(out.find(s), std::string::npos) << command << ": " << s << "\n" << out;
    EXPECT_FALSE(fs::exists(d)) << command;
  }
  // A wrong unit names the key and the units a moment takes.
  std::string out;
  EXPECT_EQ(sim("stiffness --set 'operation.moment=[\"1 N\", 0]' --out " +
                    fresh_dir("moment_unit").string(),
                &out),
            2);
  for (const char* s : {"operation.moment[0]", "N m", "lbf in"})
    EXPECT_NE(out.find(s), std::string::npos) << s << "\n" << out;
}

// A 2dof case reads an axial load (stiffness and info carry it); run refuses it as before.
TEST(CliStiffness, RunStillRefusesAnAxialLoadItsKindCannotCarry) {
  std::string out;
  const fs::path d = fresh_dir("axial_2dof");
  EXPECT_EQ(
      sim("run " + kExample + " --set operation.axial_load=50 --quiet --out " + d.string(), &out),
      2);
  for (const char* s : {"operation.axial_load = 50 N", "model.kind = \"2dof\"",
                        "no axial degree of freedom", "\"3dof\" or \"balls\""})
    EXPECT_NE(out.find(s), std::string::npos) << s << "\n" << out;
  EXPECT_FALSE(fs::exists(d));
  EXPECT_EQ(sim("sweep " + kExample +
                    " --set operation.axial_load=50 --vary "
                    "operation.speed=1000rpm:2000rpm:2 --out " +
                    d.string(),
                &out),
            2)
      << out;
  EXPECT_FALSE(fs::exists(d));
}

// Bad input: exit 2, one message naming the key, value or allowed range, and no folder.
TEST(CliStiffness, InputErrorsLeaveNoFolder) {
  struct Bad {
    std::string args;
    std::vector<std::string> expect;
  };
  const std::vector<Bad> bad = {
      {"--vary operation.axial_lod=0:200:3", {"operation.axial_lod", "operation.axial_load"}},
      {"--vary operation.axial_load=0:200:-3", {"N = \"-3\"", "from 1 to 100000"}},
      {"--vary operation.axial_load=0:200:0", {"N = \"0\"", "from 1 to 100000"}},
      {"--vary operation.axial_load=0:200", {"FROM:TO:N"}},
      {"--vary model.kind=1:2:2", {"model.kind", "not a numeric"}},
      {"--vary bearing.balls=2:4:3", {"operating point 1 of 3 (bearing.balls = 2)", "at least 3"}},
      {"--set bearing.clearance=1.3mm", {"bearing.clearance", "P_d < 2 A0"}},
      {"--format xml", {"--format xml", "csv", "ross"}},
      {"--vary operation.axial_load=0:200:3 --format ross",
       {"--format ross", "operation.speed only", "operation.axial_load"}},
      {"--format ross --ball-pass 0",
       {"--format ross", "averaged over one ball pass", "--ball-pass 0", "--ball-pass N"}},
      {"--vary operation.axial_load=0:1e6:100001", {"from 1 to 100000"}},
      {"--ball-pass 3", {"--ball-pass 3", "from 4 to 4096", "or 0"}},
      {"--ball-pass 4097", {"--ball-pass 4097", "from 4 to 4096", "or 0"}},
      {"--ball-pass -1", {"--ball-pass -1", "from 4 to 4096"}},
      {"--ball-pass 16.5", {"--ball-pass 16.5", "an integer from 4 to 4096"}},
      {"--ball-pass x", {"--ball-pass x", "an integer from 4 to 4096"}},
  };
  for (const Bad& b : bad) {
    const fs::path d = fresh_dir("stiffness_bad");
    std::string out;
    EXPECT_EQ(sim("stiffness " + kExample + " " + b.args + " --out " + d.string(), &out), 2)
        << b.args << "\n"
        << out;
    for (const auto& s : b.expect)
      EXPECT_NE(out.find(s), std::string::npos) << b.args << ": lacks " << s << "\n" << out;
    EXPECT_EQ(out.find('\n'), out.size() - 1) << "not one line: " << out;
    EXPECT_FALSE(fs::exists(d)) << b.args;
  }
  EXPECT_EQ(sim("stiffness " + kExample), 2);  // --out is required
}

// Beyond the elastic limit the files are written, with a warning naming the points, as run does.
TEST(CliStiffness, ALoadBeyondTheElasticLimitIsWrittenWithAWarning) {
  const fs::path d = fresh_dir("stiffness_elastic");
  std::string out;
  ASSERT_EQ(sim("stiffness " + kExample +
                    " --vary operation.axial_load=100:150000:2 --quiet --out " + d.string(),
                &out),
            0)
      << out;
  for (const char* s : {"bearing-sim: warning: at 1 of 2 operating points",
                        "operation.axial_load = 150000 N", "elastic limit of 4.2 GPa"})
    EXPECT_NE(out.find(s), std::string::npos) << s << "\n" << out;
  const auto j = nlohmann::json::parse(read(d / "stiffness.json"));
  EXPECT_TRUE(j["points"][0]["elastic"].get<bool>());
  EXPECT_FALSE(j["points"][1]["elastic"].get<bool>());
  EXPECT_GT(j["points"][1]["peak_pressure"]["inner"].get<double>(), 4.2e9);
  EXPECT_EQ(j["pressure_limit"].get<double>(), 4.2e9);
  ASSERT_EQ(sim("stiffness " + kExample + " --quiet --out " + d.string(), &out), 0);
  EXPECT_EQ(out, "");  // no warning within the limit
}

// The acceptance: over 0 to 20 000 rpm the matrix changes with speed once the
// centrifugal load is on (ball.centrifugal, the default), and not at all with it off.
TEST(CliStiffness, SpeedChangesTheMatrixOnlyWithTheCentrifugalLoad) {
  const fs::path on = fresh_dir("stiffness_speed_on"), off = fresh_dir("stiffness_speed_off");
  const std::string vary = " --vary operation.speed=0rpm:20000rpm:11 --quiet --out ";
  ASSERT_EQ(sim("stiffness " + kExample + vary + on.string()), 0);
  ASSERT_EQ(sim("stiffness " + kExample + " --set model.kind=balls --set ball.centrifugal=false" +
                vary + off.string()),
            0);
  const Csv a = read_csv(on / "stiffness.csv"), b = read_csv(off / "stiffness.csv");
  ASSERT_EQ(a.rows.size(), 11u);
  ASSERT_EQ(b.rows.size(), 11u);
  for (std::size_t r = 1; r < 11; ++r) {
    EXPECT_NE(a.at(r, "k_yy [N/m]"), a.at(0, "k_yy [N/m]")) << r;
    for (const char* k : kKColumns) EXPECT_EQ(b.at(r, k), b.at(0, k)) << r << " " << k;
  }
  // At 0 rpm the centrifugal load is 0, on or off: the same matrix.
  for (const char* k : kKColumns) EXPECT_EQ(a.at(0, k), b.at(0, k)) << k;
  // At 20 000 rpm the centrifugal load takes part of the load off the inner contacts: the
  // radial stiffness differs by more than rounding.
  EXPECT_GT(std::abs(a.at(10, "k_yy [N/m]") / a.at(0, "k_yy [N/m]") - 1), 1e-3);
}

// At speed each ball's outer contact carries its centrifugal load as well, at its own angle:
// stiffness.json reports both races' loads and angles (the direct solution's), and the outer
// race's peak pressure is that of its own largest load, not of the inner one's.
TEST(CliStiffness, OuterContactsAtSpeedCarryTheCentrifugalLoad) {
  for (const std::string speed : {"0rpm", "20000rpm"}) {
    SCOPED_TRACE(speed);
    const fs::path d = fresh_dir("stiffness_outer_" + speed);
    ASSERT_EQ(sim("stiffness " + kExample + " --set operation.speed=" + speed +
                  " --ball-pass 0 --quiet --out " + d.string()),
              0);
    const nlohmann::json p = nlohmann::json::parse(read(d / "stiffness.json"))["points"][0];
    const bearing::FiveDofSolution s =
        direct({bearing::parse_override("operation.speed=" + speed)});
    const auto outer = p["outer_ball_loads"].get<std::vector<double>>();
    ASSERT_EQ(outer, s.at.outer_loads);
    ASSERT_EQ(p["outer_contact_angles"].get<std::vector<double>>(), s.at.outer_contact_angles);
    const auto inner = p["ball_loads"].get<std::vector<double>>();
    double outer_max = 0;
    for (std::size_t j = 0; j < outer.size(); ++j) {
      if (speed == "0rpm")
        EXPECT_EQ(outer[j], inner[j]) << j;
      else
        EXPECT_GT(outer[j], inner[j]) << j;  // F_c presses every ball on the outer race
      outer_max = std::max(outer_max, outer[j]);
    }
    const bearing::Case c = bearing::read_case_file(kExample, {});
    EXPECT_EQ(p["peak_pressure"]["outer"].get<double>(),
              bearing::contact_constants(c).outer.peak_pressure(outer_max));
  }
}

// docs/bearing-stiffness.md's bearing that is no preset (its inner geometry in the case file):
// every point is the direct solution of that geometry, bit for bit, and from 500 N of axial
// load on every ball carries load (the comparison the page describes needs a full set).
TEST(CliStiffness, CustomBearingExampleIsSolvedFromItsGeometry) {
  const std::string example =
      std::string(BEARING_SOURCE_DIR) + "/examples/stiffness_custom_bearing.toml";
  const fs::path d = fresh_dir("stiffness_custom");
  ASSERT_EQ(
      sim("stiffness " + example +
          " --vary operation.axial_load=0N:2000N:5 --ball-pass 0 --quiet --out " + d.string()),
      0);
  const nlohmann::json points = nlohmann::json::parse(read(d / "stiffness.json"))["points"];
  ASSERT_EQ(points.size(), 5u);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double Fz = 500.0 * static_cast<double>(i);
    const bearing::Case c = bearing::read_case_file(
        example, {bearing::parse_override("operation.axial_load=" + std::to_string(Fz))});
    ASSERT_EQ(c.bearing.balls, 10);
    const bearing::FiveDofBearing b =
        bearing::five_dof_bearing(c.bearing, bearing::contact_constants(c), 0.0);
    bearing::Vector5 f;
    f << c.operation.load.x(), c.operation.load.y(), Fz, c.operation.moment.x(),
        c.operation.moment.y();
    const bearing::FiveDofSolution s = bearing::solve_five_dof(b, f);
    for (int r = 0; r < 5; ++r)
      for (int k = 0; k < 5; ++k)
        EXPECT_EQ(points[i]["stiffness_at_cage_angle"][r][k].get<double>(), s.at.stiffness(r, k))
            << i;
    if (Fz >= 500) EXPECT_EQ(points[i]["loaded_balls"].get<int>(), 10) << i;
  }
}

// The ball pass of a grid over the speed (a radial load in the clearance: one or two balls carry
// it, so K ripples strongly): stiffness_ball_pass.csv, stiffness.csv and stiffness.json agree to
// the bit, the static value lies in the range, the mean too, and the stdout table shows it.
TEST(CliStiffness, BallPassFilesAgree) {
  const fs::path d = fresh_dir("stiffness_ball_pass");
  std::string out;
  ASSERT_EQ(sim("stiffness " + kExample +
                    " --vary operation.speed=0rpm:20000rpm:3 --ball-pass 16 --out " + d.string(),
                &out),
            0)
      << out;
  const Csv wide = read_csv(d / "stiffness.csv");
  const LongCsv bp = read_long_csv(d / "stiffness_ball_pass.csv");
  std::vector<std::string> header = {"operation.speed [rad/s]", "bpfo [Hz]", "entry", "unit",
                                     "at_cage_angle",           "mean",      "min",   "max"};
  for (int m = 1; m <= 7; ++m) header.push_back(std::to_string(m) + "xBPFO");  // N/2 - 1
  EXPECT_EQ(bp.header, header);
  ASSERT_EQ(bp.rows.size(), 3u * 15u);
  const auto j = nlohmann::json::parse(read(d / "stiffness.json"));
  EXPECT_NE(j.value("ball_pass_definition", "").find("cage angles"), std::string::npos);
  EXPECT_EQ(j["units"]["ball_pass.bpfo"], "Hz");
  EXPECT_EQ(j["units"]["ball_pass.cage_angles"], "rad");
  for (std::size_t p = 0; p < 3; ++p) {
    const auto& b = j["points"][p]["ball_pass"];
    ASSERT_TRUE(b.is_object()) << p;
    EXPECT_EQ(b["samples"], 16);
    ASSERT_EQ(b["cage_angles"].size(), 16u);
    EXPECT_EQ(b["cage_angles"][0].get<double>(), 0.0);  // from the case's cage phase
    EXPECT_NEAR(b["cage_angles"][15].get<double>(), 2 * M_PI / 8 * 15 / 16, 1e-15);
    ASSERT_EQ(b["harmonics"].size(), 7u);
    const double bpfo = b["bpfo"].get<double>();
    int n = 0;
    for (int i = 0; i < 5; ++i)
      for (int k = i; k < 5; ++k, ++n) {
        const std::size_t r = p * 15 + n;
        const std::string name = std::string(kKColumns[n]);
        EXPECT_EQ(bp.text(r, "entry") + " [" + bp.text(r, "unit") + "]", name);
        EXPECT_EQ(bp.at(r, "operation.speed [rad/s]"), wide.at(p, "operation.speed [rad/s]"));
        EXPECT_EQ(bp.at(r, "bpfo [Hz]"), bpfo);
        const double st = bp.at(r, "at_cage_angle"), mean = bp.at(r, "mean"), lo = bp.at(r, "min"),
                     hi = bp.at(r, "max");
        EXPECT_EQ(st, wide.at(p, name)) << name;  // stiffness.csv's value, to the bit
        EXPECT_EQ(st, entry(j["points"][p]["stiffness_at_cage_angle"], i, k)) << name;
        EXPECT_EQ(mean, entry(b["mean"], i, k)) << name;
        EXPECT_EQ(mean, entry(j["points"][p]["rotor"]["stiffness"], i, k)) << name;
        EXPECT_EQ(lo, entry(b["min"], i, k)) << name;
        EXPECT_EQ(hi, entry(b["max"], i, k)) << name;
        EXPECT_EQ(entry(b["min"], k, i), lo) << name;  // symmetric
        const double slack = 1e-12 * std::max(std::abs(lo), std::abs(hi));
        EXPECT_LE(lo, mean + slack) << name;
        EXPECT_LE(mean, hi + slack) << name;
        EXPECT_LE(lo, st) << name;
        EXPECT_LE(st, hi) << name;
        for (int m = 1; m <= 7; ++m) {
          const auto& h = b["harmonics"][m - 1];
          EXPECT_EQ(h["order"], m);
          EXPECT_EQ(h["frequency"].get<double>(), m * bpfo);
          EXPECT_EQ(bp.at(r, std::to_string(m) + "xBPFO"), entry(h["amplitude"], i, k)) << name;
        }
      }
    // The radial load in the clearance ripples k_yy by far more than rounding.
    EXPECT_GT(entry(b["max"], 1, 1) - entry(b["min"], 1, 1), 0.01 * entry(b["mean"], 1, 1));
    EXPECT_GT(entry(b["harmonics"][0]["amplitude"], 1, 1), 0.001 * entry(b["mean"], 1, 1));
    EXPECT_EQ(j["points"][p]["rotor"]["samples"], 16);
    EXPECT_EQ(j["points"][p]["rotor"]["warnings"], nlohmann::json::array());
  }
  EXPECT_EQ(j["units"]["rotor.stiffness"], "units.stiffness, entry by entry");
  EXPECT_NE(j.value("rotor_definition", "").find("averaged over one ball pass"), std::string::npos);
  for (const char* s : {"Over one ball pass", "16 cage angles", "BPFO [Hz]", "k_yy [N/m]", "1xBPFO",
                        "mean", "stiffness_ball_pass.csv", "at the case's cage angle"})
    EXPECT_NE(out.find(s), std::string::npos) << s << "\n" << out;
}

// The mean, range and first harmonic against direct solves at the same cage angles, at the
// case's speed (2000 rpm: the centrifugal load in each), without clearance under a radial load;
// a pure axial load loads every ball alike, so K does not ripple at all.
TEST(CliStiffness, BallPassEqualsDirectSolvesAndAnAxialLoadDoesNotRipple) {
  const fs::path d = fresh_dir("stiffness_ball_pass_direct");
  const std::vector<std::string> sets = {"bearing.clearance=0", "operation.load=[0, -500]"};
  ASSERT_EQ(sim("stiffness " + kExample +
                " --set bearing.clearance=0 --set 'operation.load=[0, -500]' --ball-pass 8 "
                "--quiet --out " +
                d.string()),
            0);
  std::vector<bearing::Override> overrides;
  for (const auto& s : sets) overrides.push_back(bearing::parse_override(s));
  const int N = 8, Z = 8;
  bearing::Matrix5 mean = bearing::Matrix5::Zero(), lo, hi;
  std::complex<double> first = 0;  // k_yy's DFT at m = 1
  for (int k = 0; k < N; ++k) {
    const bearing::Matrix5 K = direct(overrides, 2 * M_PI / Z * k / N).at.stiffness;
    mean += K / N;
    lo = k ? lo.cwiseMin(K) : K;
    hi = k ? hi.cwiseMax(K) : K;
    first += K(1, 1) * std::polar(1.0, -2 * M_PI * k / N);
  }
  const auto b = nlohmann::json::parse(read(d / "stiffness.json"))["points"][0]["ball_pass"];
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) {
      const double scale = 1e-12 * mean.cwiseAbs().maxCoeff();
      EXPECT_NEAR(entry(b["mean"], i, j), mean(i, j), scale) << i << j;
      EXPECT_NEAR(entry(b["min"], i, j), lo(i, j), scale) << i << j;
      EXPECT_NEAR(entry(b["max"], i, j), hi(i, j), scale) << i << j;
    }
  EXPECT_GT(hi(1, 1) - lo(1, 1), 1e-3 * mean(1, 1));  // it does ripple
  EXPECT_NEAR(entry(b["harmonics"][0]["amplitude"], 1, 1), 2.0 / N * std::abs(first),
              1e-12 * mean(1, 1));

  const fs::path a = fresh_dir("stiffness_ball_pass_axial");
  ASSERT_EQ(sim("stiffness " + kExample +
                " --set 'operation.load=[0, 0]' --set operation.axial_load=300 --quiet --out " +
                a.string()),
            0);
  const LongCsv bp = read_long_csv(a / "stiffness_ball_pass.csv");
  ASSERT_EQ(bp.rows.size(), 15u);
  const double k_zz = bp.at(9, "mean");
  ASSERT_EQ(bp.text(9, "entry"), "k_zz");
  ASSERT_GT(k_zz, 1e6);
  for (std::size_t r = 0; r < 15; ++r) {
    EXPECT_LE(bp.at(r, "max") - bp.at(r, "min"), 1e-9 * k_zz) << bp.text(r, "entry");
    for (int m = 1; m <= 15; ++m)
      EXPECT_LE(std::abs(bp.at(r, std::to_string(m) + "xBPFO")), 1e-9 * k_zz)
          << bp.text(r, "entry") << " " << m;
  }
}

// The BPFO is the kinematics' at the case's speed, outer ring fixed: Z/2 f_r (1 − D cos α/d_m)
// with α = 0 for this deep-groove bearing under no axial load, and harmonic m lies at m × BPFO.
TEST(CliStiffness, BallPassBpfoIsTheKinematicOne) {
  const fs::path d = fresh_dir("stiffness_bpfo");
  ASSERT_EQ(
      sim("stiffness " + kExample +
          " --vary operation.speed=1000rpm:20000rpm:2 --ball-pass 4 --quiet --out " + d.string()),
      0);
  const bearing::Case c = bearing::read_case_file(kExample);
  ASSERT_EQ(c.bearing.contact_angle, 0.0);
  const auto j = nlohmann::json::parse(read(d / "stiffness.json"));
  for (int p = 0; p < 2; ++p) {
    const double rpm = p ? 20000.0 : 1000.0;
    const double fr = rpm / 60.0;
    const double bpfo =
        c.bearing.balls / 2.0 * fr * (1 - c.bearing.ball_diameter / c.bearing.pitch_diameter);
    const auto& b = j["points"][p]["ball_pass"];
    EXPECT_NEAR(b["bpfo"].get<double>(), bpfo, 1e-12 * bpfo) << rpm;
    ASSERT_EQ(b["harmonics"].size(), 1u);  // N = 4: m = 1 alone
    EXPECT_EQ(b["harmonics"][0]["frequency"].get<double>(), b["bpfo"].get<double>());
  }
  // Seed 003's Table 2 gives 102.4 Hz at 2000 rpm: half of it at 1000 rpm.
  EXPECT_NEAR(j["points"][0]["ball_pass"]["bpfo"].get<double>(), 51.2, 0.05);
}

// --ball-pass 0: no ball-pass file (an earlier call's removed), nothing of it in stiffness.json
// or on stdout; the other files as with it.
TEST(CliStiffness, BallPassZeroLeavesItOut) {
  const fs::path d = fresh_dir("stiffness_no_ball_pass");
  ASSERT_EQ(sim("stiffness " + kExample + " --quiet --out " + d.string()), 0);
  ASSERT_TRUE(fs::exists(d / "stiffness_ball_pass.csv"));  // the default: 32 cage angles
  const std::string csv = read(d / "stiffness.csv");
  EXPECT_EQ(nlohmann::json::parse(read(d / "stiffness.json"))["points"][0]["ball_pass"]["samples"],
            32);
  std::string out;
  ASSERT_EQ(sim("stiffness " + kExample + " --ball-pass 0 --out " + d.string(), &out), 0) << out;
  EXPECT_FALSE(fs::exists(d / "stiffness_ball_pass.csv"));
  EXPECT_EQ(read(d / "stiffness.csv"), csv);
  const auto j = nlohmann::json::parse(read(d / "stiffness.json"));
  EXPECT_FALSE(j["points"][0].contains("ball_pass"));
  EXPECT_FALSE(j["points"][0].contains("rotor"));
  EXPECT_FALSE(j.contains("ball_pass_definition"));
  EXPECT_FALSE(j.contains("rotor_definition"));
  EXPECT_EQ(out.find("ball pass"), std::string::npos) << out;
  EXPECT_EQ(out.find("BPFO"), std::string::npos) << out;
}

// info: under the matrix, the diagonal's range over one ball pass and its 1×BPFO amplitude, at
// 16 cage angles: stiffness --ball-pass 16's numbers, to the bit.
TEST(CliStiffness, InfoShowsTheBallPass) {
  const fs::path d = fresh_dir("stiffness_info_ball_pass");
  ASSERT_EQ(sim("stiffness " + kExample + " --ball-pass 16 --quiet --out " + d.string()), 0);
  const auto expected = nlohmann::json::parse(read(d / "stiffness.json"))["points"][0]["ball_pass"];
  std::string out;
  ASSERT_EQ(sim("info --json " + kExample, &out), 0) << out;
  const auto j = nlohmann::json::parse(out);
  EXPECT_EQ(j["stiffness"]["ball_pass"], expected);
  EXPECT_EQ(j["stiffness"]["ball_pass"]["bpfo"].get<double>(),
            j["kinematics"]["bpfo"].get<double>());
  EXPECT_EQ(j["units"]["stiffness.ball_pass.bpfo"], "Hz");
  ASSERT_EQ(sim("info " + kExample, &out), 0) << out;
  for (const char* s : {"over one ball pass (16 cage angles", "BPFO = 102.4 Hz", "1xBPFO",
                        "k_yy [N/m]", "k_gy_gy [N*m/rad]"})
    EXPECT_NE(out.find(s), std::string::npos) << s << "\n" << out;
  // k_yy's line: its min and max over the pitch, and its amplitude at 1xBPFO.
  const std::size_t line = out.find("  k_yy [N/m]");
  ASSERT_NE(line, std::string::npos) << out;
  std::istringstream row(out.substr(line + 12, out.find('\n', line) - line - 12));
  double lo = 0, hi = 0, first = 0;
  row >> lo >> hi >> first;
  EXPECT_NEAR(lo, entry(expected["min"], 1, 1), 1e-3 * lo);
  EXPECT_NEAR(hi, entry(expected["max"], 1, 1), 1e-3 * hi);
  EXPECT_NEAR(first, entry(expected["harmonics"][0]["amplitude"], 1, 1), 1e-3 * first);
}

// `run` asks compute_info for the elastic-limit warning alone (lumped/app/bearing_sim.cc):
// without_stiffness leaves the 5-DOF stiffness and its ball pass out, so no run pays for them.
TEST(CliStiffness, RunsInfoPartHasNoStiffnessNorBallPass) {
  const bearing::Case c = bearing::read_case_file(kExample);
  const bearing::InfoReport r = bearing::compute_info(c, bearing::InfoParts::without_stiffness);
  EXPECT_FALSE(r.stiffness.has_value());
  EXPECT_EQ(r.stiffness_error, "");
  EXPECT_EQ(r.ball_pass_error, "");
  const bearing::InfoReport all = bearing::compute_info(c);
  ASSERT_TRUE(all.stiffness.has_value());
  ASSERT_TRUE(all.stiffness->ball_pass.has_value());
  EXPECT_EQ(all.stiffness->ball_pass->samples.size(),
            static_cast<std::size_t>(bearing::kInfoBallPassSamples));
}

}  // namespace
