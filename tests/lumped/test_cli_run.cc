// bearing-sim run and sweep end to end: the files, their keys, reproducibility, and that a failed
// run leaves no result files behind.

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bearing/presets.h"
#include "calibration_files.h"
#include "cli_helpers.h"

namespace {

namespace fs = std::filesystem;
using bearing::test::fresh_dir;
using bearing::test::kShort;
using bearing::test::read;
using bearing::test::sim;

TEST(CliRun, WritesTheFourFilesWithTheDocumentedKeys) {
  const fs::path d = fresh_dir("run_default");
  ASSERT_EQ(sim("run --out " + d.string() + kShort + " --set output.ball_loads=true"), 0);
  for (const char* f : {"response.csv", "spectrum.csv", "summary.json", "case.toml"})
    EXPECT_TRUE(fs::exists(d / f)) << f;
  for (const auto& e : fs::directory_iterator(d))
    EXPECT_EQ(e.path().filename().string().find(".partial"), std::string::npos);

  const std::string csv = read(d / "response.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "t,x,y,vx,vy,ax,ay,Q1,Q2,Q3,Q4,Q5,Q6,Q7,Q8");
  // 0.3 s at 20 kHz: samples 0 … 6000, plus the header.
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 6002);
  EXPECT_EQ(csv.find("nan"), std::string::npos);

  const std::string spec = read(d / "spectrum.csv");
  EXPECT_EQ(spec.substr(0, spec.find('\n')), "frequency,x,y,vx,vy,ax,ay");

  const auto j = nlohmann::json::parse(read(d / "summary.json"));
  for (const char* ch : {"x", "y", "vx", "vy", "ax", "ay", "Q1"})
    for (const char* k : {"rms", "ptp", "kurtosis", "crest"})
      EXPECT_TRUE(j["channels"][ch][k].is_number()) << ch << "." << k;
  ASSERT_FALSE(j["peaks"]["y"].empty());
  EXPECT_TRUE(j["peaks"]["y"][0]["frequency"].is_number());
  EXPECT_TRUE(j["peaks"]["y"][0]["amplitude"].is_number());
  EXPECT_EQ(j["peaks"]["y"][0]["label"], "BPFO");
  EXPECT_NEAR(j["frequencies"]["bpfo"].get<double>(), 102.4, 0.05);
}

// case.toml is the fully resolved case: running it again gives the same response, bit for bit.
TEST(CliRun, ResolvedCaseRepeatsTheRunExactly) {
  const fs::path a = fresh_dir("run_a"), b = fresh_dir("run_b");
  ASSERT_EQ(sim("run --out " + a.string() + kShort + " --set model.kind=3dof" +
                " --set operation.axial_load=50"),
            0);
  ASSERT_EQ(sim("run " + (a / "case.toml").string() + " --out " + b.string() + " --quiet"), 0);
  EXPECT_EQ(read(a / "response.csv"), read(b / "response.csv"));
  EXPECT_EQ(read(a / "summary.json").substr(read(a / "summary.json").find("\"channels\"")),
            read(b / "summary.json").substr(read(b / "summary.json").find("\"channels\"")));
  EXPECT_EQ(read(a / "response.csv").substr(0, 20).find("t,x,y,z"), 0u);
}

// A run that blows up (here: a 1 nm displacement bound) fails with status 3 and writes nothing.
TEST(CliRun, FailedRunLeavesNoResultFiles) {
  const fs::path d = fresh_dir("run_fail");
  EXPECT_EQ(sim("run --out " + d.string() + kShort + " --set solver.max_displacement=1e-9"), 3);
  for (const char* f : {"response.csv", "spectrum.csv", "summary.json", "case.toml"})
    EXPECT_FALSE(fs::exists(d / f)) << f;
}

TEST(CliRun, BadInputExitsWithStatusTwo) {
  EXPECT_EQ(sim("run --out " + fresh_dir("run_bad").string() + " --set solver.dt=0"), 2);
  EXPECT_NE(sim("run"), 0);  // --out is required
}

// A sweep runs every combination; a case that fails is reported in its row, the others go on.
TEST(CliSweep, OneRowPerCaseAndFailuresInTheirRow) {
  const fs::path d = fresh_dir("sweep");
  ASSERT_EQ(sim("sweep --vary bearing.balls=2:4:3 --vary operation.speed=1000rpm:2000rpm:2 --out " +
                d.string() + kShort + " --jobs 2"),
            0);
  const std::string csv = read(d / "sweep.csv");
  std::istringstream lines(csv);
  std::string header, line;
  std::getline(lines, header);
  EXPECT_EQ(header.rfind("bearing.balls,operation.speed,status,error,x.rms", 0), 0u) << header;
  int rows = 0, failed = 0;
  while (std::getline(lines, line)) {
    ++rows;
    if (line.find(",failed,") != std::string::npos) {
      ++failed;
      EXPECT_EQ(line.rfind("2,", 0), 0u) << line;  // Z = 2 is the invalid one
      EXPECT_NE(line.find("at least 3 balls"), std::string::npos) << line;
    }
  }
  EXPECT_EQ(rows, 6);
  EXPECT_EQ(failed, 2);
  EXPECT_NE(sim("sweep --vary model.kind=1:2:2 --out " + d.string()), 0);  // not numeric
}

// Runs bearing-sim with `args`; stdout and stderr into `out` and `err`; returns the exit status.
int sim_capture(const std::string& args, std::string& out, std::string& err) {
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const fs::path dir = fs::path(::testing::TempDir());
  const fs::path o = dir / (test + ".stdout.txt"), e = dir / (test + ".stderr.txt");
  const std::string cmd =
      std::string(BEARING_SIM) + " " + args + " >" + o.string() + " 2>" + e.string();
  const int status = std::system(cmd.c_str());
  out = read(o);
  err = read(e);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

const std::string kCalibratedExample =
    std::string(BEARING_SOURCE_DIR) + "/examples/seed003_6308_calibrated.toml";

// The example's case with a calibration of the exact Hertz constants (exponent 1.5), written by
// the test: the law must then run exactly like contact = "exact" (the example's own file holds
// real FE constants).
std::string hertz_calibrated_example() {
  const std::string file = bearing::test::write_calibration(
      "hertz_calibration.json", bearing::test::hertz_calibration_doc(bearing::preset("6308")));
  return kCalibratedExample + " --set model.calibration=" + file;
}

// (f) info shows which contact law is in use: the calibrated one with its file, geometry, date and
// constants, in text and JSON; a file for another bearing stops it with exit status 2.
TEST(CliCalibrated, InfoShowsTheCalibratedLaw) {
  std::string out, err;
  ASSERT_EQ(sim_capture("info " + kCalibratedExample, out, err), 0) << err;
  for (const char* s : {"Contact law: calibrated (FE, hertz geometry, file ",
                        "seed003_6308_calibration.json", "inner K = ", "N/m^1.50",
                        "ball between both races K = ", "exact Hertz solution", "exponent n"})
    EXPECT_NE(out.find(s), std::string::npos) << "lacks \"" << s << "\":\n" << out;
  ASSERT_EQ(sim_capture("info " + hertz_calibrated_example(), out, err), 0) << err;
  for (const char* s : {"hertz_calibration.json", "N/m^1.5, n = 1.5"})
    EXPECT_NE(out.find(s), std::string::npos) << "lacks \"" << s << "\":\n" << out;

  ASSERT_EQ(sim_capture("info " + hertz_calibrated_example() + " --json", out, err), 0) << err;
  const auto j = nlohmann::json::parse(out);
  EXPECT_EQ(j["contact"]["method"], "calibrated");
  EXPECT_EQ(j["contact"]["inner"]["exponent"], 1.5);
  EXPECT_EQ(j["contact"]["exponent"], 1.5);
  const auto& cal = j["contact"]["calibration"];
  EXPECT_TRUE(fs::path(cal["file"].get<std::string>()).is_absolute());
  EXPECT_EQ(cal["geometry"], "hertz");
  EXPECT_TRUE(cal["method"].is_string());
  EXPECT_TRUE(cal["date"].is_string());
  EXPECT_EQ(cal["load_range"].size(), 2u);
  EXPECT_EQ(cal["series_fit_residual"], 0.0);
  EXPECT_EQ(j["units"]["contact.K"], "N/m^exponent");

  // Unequal exponents: the fitted ball law and its residual.
  nlohmann::json doc = bearing::test::hertz_calibration_doc(bearing::preset("6308"));
  doc["inner"]["exponent"] = 1.5012;
  doc["outer"]["exponent"] = 1.4996;
  const fs::path file = fs::path(::testing::TempDir()) / "CliCalibrated.unequal.json";
  std::ofstream(file) << doc.dump(2);
  ASSERT_EQ(sim_capture("info " + kCalibratedExample + " --set model.calibration=" + file.string(),
                        out, err),
            0)
      << err;
  for (const char* s : {"N/m^1.5012, n = 1.5012", "N/m^1.4996, n = 1.4996", "least-squares fit",
                        "relative RMS residual"})
    EXPECT_NE(out.find(s), std::string::npos) << "lacks \"" << s << "\":\n" << out;
  ASSERT_EQ(
      sim_capture("info " + kCalibratedExample + " --json --set model.calibration=" + file.string(),
                  out, err),
      0);
  const auto k = nlohmann::json::parse(out)["contact"];
  EXPECT_GT(k["calibration"]["series_fit_residual"].get<double>(), 0.0);
  EXPECT_GT(k["exponent"].get<double>(), 1.4996);
  EXPECT_LT(k["exponent"].get<double>(), 1.5012);

  // Another bearing: exit status 2, one line naming the field and both values, nothing on stdout.
  EXPECT_EQ(
      sim_capture("info " + kCalibratedExample + " --set bearing.ball_diameter=15.875mm", out, err),
      2);
  EXPECT_TRUE(out.empty()) << out;
  for (const char* s : {"model.calibration", "bearing.ball_diameter = 15.081 mm",
                        "the case has 15.875 mm", "bearing-fem calibrate"})
    EXPECT_NE(err.find(s), std::string::npos) << "lacks \"" << s << "\": " << err;
}

// run records the law in summary.json, and case.toml (with the calibration's absolute path)
// repeats the run bit for bit from another folder; with the exact Hertz constants the run is the
// exact-law run.
TEST(CliCalibrated, RunRecordsTheLawAndRepeatsFromCaseToml) {
  const fs::path a = fresh_dir("cal_run_a"), b = fresh_dir("cal_run_b"),
                 e = fresh_dir("cal_run_exact");
  ASSERT_EQ(sim("run " + hertz_calibrated_example() + " --out " + a.string() + kShort), 0);
  const std::string toml = read(a / "case.toml");
  EXPECT_NE(toml.find("contact = \"calibrated\""), std::string::npos) << toml;
  const auto j = nlohmann::json::parse(read(a / "summary.json"));
  EXPECT_EQ(j["case"]["contact"], "calibrated");
  EXPECT_EQ(j["contact"]["method"], "calibrated");
  EXPECT_EQ(j["contact"]["exponent"], 1.5);
  const std::string file = j["case"]["calibration"]["file"];
  EXPECT_TRUE(fs::path(file).is_absolute()) << file;
  EXPECT_NE(toml.find("calibration = \"" + file + "\""), std::string::npos) << toml;

  const fs::path elsewhere = fresh_dir("cal_run_cwd");
  fs::create_directories(elsewhere);
  const std::string cmd = "cd " + elsewhere.string() + " && " + BEARING_SIM + " run " +
                          (a / "case.toml").string() + " --out " + b.string() +
                          " --quiet >/dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  EXPECT_EQ(read(a / "response.csv"), read(b / "response.csv"));

  ASSERT_EQ(sim("run " + std::string(BEARING_SOURCE_DIR) + "/examples/seed003_6308.toml --out " +
                e.string() + kShort),
            0);
  EXPECT_EQ(read(a / "response.csv"), read(e / "response.csv"));
}

// The quasi-static example (seed 000): the ring's and every ball's channels, and the quasi-static
// solver's figures in summary.json.
TEST(CliRun, QuasiStaticExampleWritesBallMotionAndSolverKeys) {
  const fs::path d = fresh_dir("run_quasistatic");
  const std::string example =
      std::string(BEARING_SOURCE_DIR) + "/examples/seed000_608_quasistatic.toml";
  ASSERT_EQ(sim("run " + example + " --out " + d.string() + kShort), 0);
  const std::string csv = read(d / "response.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "t,x,y,vx,vy,ax,ay,Q1,Q2,Q3,Q4,Q5,Q6,Q7,r1,r2,r3,r4,r5,r6,r7,"
            "vr1,vr2,vr3,vr4,vr5,vr6,vr7");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 6002);
  const std::string spec = read(d / "spectrum.csv");
  EXPECT_EQ(spec.substr(0, spec.find('\n')), "frequency,x,y,vx,vy,ax,ay");
  const auto j = nlohmann::json::parse(read(d / "summary.json"));
  EXPECT_EQ(j["case"]["model"], "quasistatic");
  EXPECT_EQ(j["solver"]["method"], "quasistatic newton");
  EXPECT_EQ(j["solver"]["steps"], 6001);
  for (const char* k : {"newton_iterations", "fallbacks", "max_relative_residual",
                        "min_loaded_balls", "jumps", "minimum_load"})
    EXPECT_TRUE(j["solver"][k].is_number()) << k;
  EXPECT_LT(j["solver"]["max_relative_residual"].get<double>(), 1e-9);
  EXPECT_GE(j["solver"]["min_loaded_balls"].get<int>(), 2);
  EXPECT_TRUE(j["channels"]["vr1"]["rms"].is_number());
  EXPECT_FALSE(j["peaks"].contains("vr1"));
  EXPECT_TRUE(j["peaks"].contains("y"));
  // Too light a load: a clear error, no files.
  const fs::path bad = fresh_dir("run_quasistatic_light");
  EXPECT_NE(
      sim("run " + example + " --out " + bad.string() + kShort + " --set operation.load=[0,-5]"),
      0);
  EXPECT_FALSE(fs::exists(bad / "summary.json"));
}

// [acoustics]: pressure.csv over the analysis window, the levels in summary.json and on stdout;
// a later run without acoustics into the same folder leaves no stale pressure.csv; a sweep gets
// the levels as columns.
TEST(CliRun, AcousticsWritesPressureAndLevels) {
  const fs::path d = fresh_dir("run_acoustics");
  const std::string mics =
      " --set 'acoustics.microphones=[[\"0.1 m\", \"0 deg\"], [\"0.3 m\", \"-90 deg\"]]'";
  std::string out, err;
  ASSERT_EQ(sim_capture("run --out " + d.string() + kShort + mics, out, err), 0) << err;
  EXPECT_NE(out.find("microphone 2 at 300 mm, -90 deg:  total"), std::string::npos) << out;
  const std::string csv = read(d / "pressure.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "t,p1,p2");
  // The analysis window [0.1 s, 0.3 s) at 20 kHz: 4000 samples, plus the header.
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4001);
  EXPECT_EQ(csv.substr(csv.find('\n') + 1, 4), "0.1,");
  EXPECT_EQ(csv.find("nan"), std::string::npos);

  const auto j = nlohmann::json::parse(read(d / "summary.json"));
  const auto& a = j["acoustics"];
  EXPECT_EQ(a["ring_source"], "cylinder-dipole");
  EXPECT_EQ(a["ball_model"], "oscillating-sphere");
  EXPECT_EQ(a["summation"], "coherent");
  EXPECT_DOUBLE_EQ(a["band"][1].get<double>(), 8000.0);
  ASSERT_EQ(a["microphones"].size(), 2u);
  const auto& m = a["microphones"][1];
  EXPECT_NEAR(m["position"][0].get<double>(), 0.0, 1e-15);
  EXPECT_NEAR(m["position"][1].get<double>(), -0.3, 1e-15);
  for (const char* k : {"spl_total", "spl_ring", "spl_balls", "p_rms", "nearest_ball_surface"})
    EXPECT_TRUE(m[k].is_number()) << k;
  // The RMS of the written column is the summary's p_rms (to the CSV's 12 digits).
  double sum = 0;
  std::size_t rows = 0;
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);
  while (std::getline(lines, line)) {
    const double p2 = std::stod(line.substr(line.rfind(',') + 1));
    sum += p2 * p2, ++rows;
  }
  EXPECT_NEAR(std::sqrt(sum / rows), m["p_rms"].get<double>(), 1e-10 * m["p_rms"].get<double>());
  EXPECT_NEAR(m["spl_total"].get<double>(), 20 * std::log10(m["p_rms"].get<double>() / 20e-6),
              1e-9);
  // The resolved case keeps the table: it repeats the sound bit for bit.
  const fs::path again = fresh_dir("run_acoustics_again");
  ASSERT_EQ(sim("run " + (d / "case.toml").string() + " --out " + again.string() + " --quiet"), 0);
  EXPECT_EQ(read(again / "pressure.csv"), csv);

  ASSERT_EQ(sim("run --out " + d.string() + kShort), 0);
  EXPECT_FALSE(fs::exists(d / "pressure.csv"));

  const fs::path sw = fresh_dir("sweep_acoustics");
  ASSERT_EQ(sim("sweep --vary operation.speed=1000rpm:2000rpm:2 --out " + sw.string() + kShort +
                mics + " --set acoustics.ring_source=none"),
            0);
  const std::string table = read(sw / "sweep.csv");
  const std::string header = table.substr(0, table.find('\n'));
  EXPECT_NE(header.find(",mic1.spl_total,mic1.spl_ring,mic1.spl_balls,mic2.spl_total"),
            std::string::npos)
      << header;
  // Ring "none": its level column is empty, the ball level is a number.
  const auto fields = [](const std::string& text) {
    std::vector<std::string> f;
    std::istringstream in(text);
    for (std::string x; std::getline(in, x, ',');) f.push_back(x);
    if (!text.empty() && text.back() == ',') f.push_back("");
    return f;
  };
  const auto names = fields(header);
  std::istringstream rows_in(table);
  std::string row;
  std::getline(rows_in, row);
  std::getline(rows_in, row);
  const auto values = fields(row);
  ASSERT_EQ(values.size(), names.size()) << row;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == "mic1.spl_ring") EXPECT_EQ(values[i], "") << row;
    if (names[i] == "mic1.spl_balls" || names[i] == "mic1.spl_total")
      EXPECT_GT(std::stod(values[i]), -100.0) << row;
  }
}

}  // namespace

// Issue 21, guard rails: a static load whose peak Hertz pressure passes ISO 76's 4.2 GPa is
// reported by `info` (text and JSON) and warned about by `run`, which still runs; below it,
// nothing is said. The pressure follows Hertz's p_max ∝ Q^{1/3} between two loads.
namespace {

TEST(CliRun, ALoadBeyondTheElasticLimitIsReportedAndWarned) {
  std::string out;
  ASSERT_EQ(sim("info --json --set 'operation.load=[0, -40000]'", &out), 0) << out;
  const auto heavy = nlohmann::json::parse(out)["static"];
  EXPECT_FALSE(heavy["elastic"].get<bool>());
  EXPECT_EQ(heavy["pressure_limit"].get<double>(), 4.2e9);
  EXPECT_GT(heavy["peak_pressure"]["inner"].get<double>(), 4.2e9);

  ASSERT_EQ(sim("info --json --set 'operation.load=[0, -5000]'", &out), 0) << out;
  const auto light = nlohmann::json::parse(out)["static"];
  EXPECT_TRUE(light["elastic"].get<bool>());
  const double ratio =
      heavy["peak_pressure"]["inner"].get<double>() / light["peak_pressure"]["inner"].get<double>();
  const double load_ratio = heavy["q_max"].get<double>() / light["q_max"].get<double>();
  EXPECT_NEAR(ratio, std::cbrt(load_ratio), 1e-9 * ratio);

  ASSERT_EQ(sim("info --set 'operation.load=[0, -40000]'", &out), 0);
  EXPECT_NE(out.find("WARNING: the most loaded ball's peak Hertz pressure"), std::string::npos);
  const fs::path dir = fresh_dir("elastic_limit");
  ASSERT_EQ(sim("run --set 'operation.load=[0, -40000]'" + kShort + " --out " + dir.string(), &out),
            0)
      << out;
  EXPECT_NE(out.find("bearing-sim: warning:"), std::string::npos) << out;
  EXPECT_NE(out.find("4.2 GPa (ISO 76)"), std::string::npos) << out;
  ASSERT_EQ(sim("run" + kShort + " --out " + dir.string(), &out), 0);
  EXPECT_EQ(out.find("warning"), std::string::npos) << out;
}

// With an axial load (a kind that carries it) the peak pressure is read at the kind's static state:
// under the axial load alone every ball carries Q with Z Q sin α = F_z (the equilibrium, checked
// here independently of the solver), the peak load is that Q, and a heavy axial load alone passes
// the limit. Without an axial load the peak load is the radial distribution's Q_max.
TEST(CliRun, AnAxialLoadCountsTowardTheElasticLimit) {
  std::string out;
  const std::string axial_only = " --set 'operation.load=[0, 0]' --set model.kind=3dof";
  ASSERT_EQ(sim("info --json" + axial_only + " --set operation.axial_load=2000", &out), 0) << out;
  const auto s = nlohmann::json::parse(out)["static"];
  const double Q = s["axial"]["ball_load"].get<double>();
  const double alpha = s["axial"]["contact_angle"].get<double>();
  EXPECT_NEAR(8 * Q * std::sin(alpha), 2000.0, 1e-9 * 2000.0);  // the 6308 has Z = 8
  EXPECT_NEAR(s["peak_load"].get<double>(), Q, 1e-9 * Q);
  EXPECT_TRUE(s["elastic"].get<bool>());

  ASSERT_EQ(sim("info --json" + axial_only + " --set operation.axial_load=150000", &out), 0) << out;
  const auto heavy = nlohmann::json::parse(out)["static"];
  EXPECT_FALSE(heavy["elastic"].get<bool>());
  const double ratio =
      heavy["peak_pressure"]["inner"].get<double>() / s["peak_pressure"]["inner"].get<double>();
  EXPECT_NEAR(ratio, std::cbrt(heavy["peak_load"].get<double>() / Q), 1e-9 * ratio);
  ASSERT_EQ(sim("info" + axial_only + " --set operation.axial_load=150000", &out), 0);
  EXPECT_NE(out.find("or operation.axial_load"), std::string::npos) << out;

  ASSERT_EQ(sim("info --json --set 'operation.load=[0, -3000]'", &out), 0) << out;
  const auto radial = nlohmann::json::parse(out)["static"];
  EXPECT_FALSE(radial.contains("axial"));
  EXPECT_EQ(radial["peak_load"].get<double>(), radial["q_max"].get<double>());
}

}  // namespace

// A command-line error (an unknown option, an option's value out of its range, a value that is
// not a number) is bad input like a case file's: exit 2 and one line naming the option; --help
// and --version still give 0.
TEST(CliRun, CommandLineErrorsAreInputErrors) {
  const fs::path dir = fresh_dir("cli_errors");
  const struct {
    std::string args, named;
  } bad[] = {{"sweep --jobs -3 --vary bearing.balls=8:9:2", "--jobs"},
             {"sweep --jobs nan --vary bearing.balls=8:9:2", "--jobs"},
             {"sweep --samples 0 --sample 'bearing.balls=uniform(8, 9)'", "--samples"},
             {"run --no-such-option", "--no-such-option"},
             {"run --jobs 2", "--jobs"}};
  for (const auto& b : bad) {
    std::string out;
    EXPECT_EQ(sim(b.args + " --out " + dir.string(), &out), 2) << b.args << ": " << out;
    EXPECT_NE(out.find(b.named), std::string::npos) << b.args << ": " << out;
    EXPECT_EQ(out.find('\n'), out.size() - 1) << b.args << ": not one line: " << out;
    EXPECT_TRUE(!fs::exists(dir) || fs::is_empty(dir)) << b.args;
  }
  std::string out;
  EXPECT_EQ(sim("--help", &out), 0);
  EXPECT_EQ(sim("--version", &out), 0);
}
