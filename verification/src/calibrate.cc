// `bearing-verify calibrate`: bearing-fem calibrate (the law the lumped model reads), the other
// geometry's FE curve beside it, then every contact law side by side over the calibrated load
// range and in the lumped response. Writes DIR/calibration.json and DIR/calibration_report.*.
#include "calibrate.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "bearing/calibration.h"
#include "bearing/case_file.h"
#include "bearing/errors.h"
#include "bearing/simulation.h"
#include "calibration_report.h"
#include "fem_runner.h"

namespace bearing::verify {

namespace fs = std::filesystem;

CLI::App* add_calibrate_command(CLI::App& app, CalibrateOptions& o) {
  auto* cmd = app.add_subcommand(
      "calibrate",
      "the stiffness calibration run: FE contact of both races (Hertz-reduced and groove), "
      "calibration.json, and the calibrated law against exact Hertz, Hamrock-Brewe and Harris "
      "with the lumped response under each");
  cmd->add_option("CASE", o.case_path, "TOML case file")->required();
  cmd->add_option("--out", o.out, "output folder (calibration.json, calibration_report.*)")
      ->required();
  cmd->add_option("--geometry", o.geometry,
                  "the FE geometry calibration.json is fitted to: hertz (Hertz-reduced block, "
                  "default) or groove (the ring segment with its true groove); the other is run "
                  "beside it for comparison")
      ->check(CLI::IsMember({"hertz", "groove"}));
  cmd->add_option("--cells", o.cells, "FE cells across the contact's minor semi-axis [2, 32]")
      ->check(CLI::Range(2, 32));
  cmd->add_option("--grading", o.grading, "FE mesh grading away from the contact [2, 16]")
      ->check(CLI::Range(2, 16));
  cmd->add_option("--mpi", o.mpi, "run each FE reference under mpirun -np N [1, 64]")
      ->check(CLI::Range(1, 64));
  cmd->add_option("--fem", o.fem, "the bearing-fem program (default: the one built beside this)");
  cmd->add_flag("--quiet", o.quiet, "no progress lines on stderr");
  return cmd;
}

namespace {

void say(const CalibrateOptions& o, const std::string& line) {
  if (!o.quiet) std::fprintf(stderr, "%s\n", line.c_str());
}

// Runs bearing-fem; throws SolverError with the end of its log when it fails.
void run_fem(const CalibrateOptions& o, const std::vector<std::string>& args, const fs::path& log) {
  const std::string command = fem_command(o.fem, o.mpi, args);
  if (run_logged(command, log.string()) != 0)
    throw SolverError("bearing-fem failed: " + command + "\n" + tail_of(log.string(), 800));
}

std::vector<std::string> mesh_args(const CalibrateOptions& o) {
  return {"--cells", std::to_string(o.cells), "--grading", std::to_string(o.grading), "--quiet"};
}

// The force–approach points bearing-fem wrote (force_approach.csv: approach, force, …) [m, N].
FeCurve read_curve(const fs::path& csv, const std::string& label) {
  std::ifstream in(csv);
  if (!in) throw SolverError("bearing-fem wrote no " + csv.string());
  FeCurve curve{label, {}, {}};
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string a, f;
    std::getline(ss, a, ',');
    std::getline(ss, f, ',');
    curve.approach.push_back(std::stod(a));
    curve.force.push_back(std::stod(f));
  }
  return curve;
}

// The lumped run of the case under each law (model.contact), the calibrated one reading `file`.
std::vector<LawResponse> responses(const CalibrateOptions& o, const fs::path& file) {
  std::vector<LawResponse> out;
  for (const char* law : {"exact", "hamrock-brewe", "harris-table", "calibrated"}) {
    std::vector<Override> overrides = {{"model.contact", std::string("\"") + law + "\""}};
    if (std::string(law) == "calibrated")
      overrides.push_back({"model.calibration", "\"" + fs::absolute(file).string() + "\""});
    const Case c = read_case_file(o.case_path, overrides);
    say(o, std::string("lumped run with contact = ") + law);
    const SimulationResult r = simulate(c);
    out.push_back({law, summarize(c, r), r.contact});
  }
  return out;
}

}  // namespace

int calibrate_command(const CalibrateOptions& o) {
  if (o.fem.empty())
    throw InputError("--fem: bearing-fem was not built (deal.II not found); give its path");
  if (!fs::exists(o.fem)) throw InputError("--fem = \"" + o.fem + "\": no such file");
  const Case c = read_case_file(o.case_path);  // bad input stops here, before any FE run
  const fs::path out(o.out);
  fs::create_directories(out);
  const fs::path file = out / "calibration.json";
  for (const char* stale : {"calibration.json", "calibration_report.html", "calibration_report.md",
                            "calibration_report.json"})
    fs::remove(out / stale);

  say(o, "bearing-fem calibrate (" + o.geometry + ") …");
  std::vector<std::string> args = {"calibrate",   o.case_path,  "--out",
                                   file.string(), "--geometry", o.geometry};
  for (const auto& a : mesh_args(o)) args.push_back(a);
  run_fem(o, args, out / "calibrate.log");
  const ContactCalibration cal = read_calibration(file.string(), "calibration.json");
  check_calibration_bearing(cal, c.bearing, "calibration.json");

  CalibrationStudy study;
  study.case_path = o.case_path;
  study.bearing = c.bearing;
  study.calibration = cal;
  study.geometry = o.geometry;
  study.mesh = "cells " + std::to_string(o.cells) + ", grading " + std::to_string(o.grading);
  const std::string other = o.geometry == "hertz" ? "groove" : "hertz";
  for (Race race : {Race::inner, Race::outer}) {
    const std::string name = to_string(race);
    RaceStudy rs{race, {}};
    rs.curves.push_back(read_curve(out / ("calibration_" + name) / "force_approach.csv",
                                   "FE " + o.geometry + " (calibrated)"));
    say(o, "bearing-fem contact --race " + name + " --geometry " + other + " …");
    const fs::path dir = out / (other + "_" + name);
    std::vector<std::string> a = {"contact",    o.case_path,
                                  "--race",     name,
                                  "--geometry", other,
                                  "--load-min", std::to_string(cal.load_min),
                                  "--load-max", std::to_string(cal.load_max),
                                  "--no-vtu",   "--out",
                                  dir.string()};
    for (const auto& m : mesh_args(o)) a.push_back(m);
    run_fem(o, a, out / (other + "_" + name + ".log"));
    rs.curves.push_back(read_curve(dir / "force_approach.csv", "FE " + other));
    study.races.push_back(rs);
  }
  // At rest the lumped run only settles to its static state: its "response" would be round-off
  // (an RMS of 1e-17 m, peaks anywhere), so a static case says so instead of comparing it.
  study.static_case = c.operation.speed == 0.0;
  if (study.static_case)
    say(o, "operation.speed = 0: a static case, no lumped response to compare");
  else
    study.responses = responses(o, file);
  write_calibration_report(study, out.string());
  std::printf("calibration.json: inner K = %.6g N/m^%.5g, outer K = %.6g N/m^%.5g; report: %s\n",
              cal.inner.K, cal.inner.exponent, cal.outer.K, cal.outer.exponent,
              (out / "calibration_report.html").c_str());
  return 0;
}

}  // namespace bearing::verify
