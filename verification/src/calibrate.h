#pragma once
// `bearing-verify calibrate CASE --out DIR`: the stiffness calibration run as a user does it — FE
// contact of both races (Hertz-reduced and groove), calibration.json, and the calibrated law
// against exact Hertz, Hamrock–Brewe and Harris over the case's load range, with the lumped
// response under each law side by side.

#include <string>

#include <CLI/CLI.hpp>

namespace bearing::verify {

struct CalibrateOptions {
  std::string case_path;
  std::string out;
  std::string geometry = "hertz";  ///< the geometry calibration.json is fitted to
  int cells = 8;                   ///< N_b of the FE meshes
  int grading = 6;
  int mpi = 1;
  std::string fem = BEARING_VERIFY_FEM;
  bool quiet = false;
};

CLI::App* add_calibrate_command(CLI::App& app, CalibrateOptions& o);
int calibrate_command(const CalibrateOptions& o);

}  // namespace bearing::verify
