#pragma once
// `bearing-sim stiffness [CASE] [--set …] [--vary KEY=FROM:TO:N …] --out DIR`: the bearing's 5×5
// stiffness at each operating point (pipeline/stiffness.h), written by stiffness_output.h. The
// grid of points is the sweep's (parse_vary, grid_design, load_sweep_case). Parsing and wiring
// only; no physics here.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace bearing_app {

/// The stiffness options as given on the command line.
struct StiffnessOptions {
  std::string case_path, out_dir;
  std::vector<std::string> sets, vary;
  std::string format = "csv";  ///< "csv" (stiffness.csv and .json) | "ross" (also ROSS's table)
  /// Cage angles a pitch of each point's ball pass, as given: an integer 4 … 4096, or 0 for none
  /// (checked by stiffness_command).
  std::string ball_pass = "32";
  bool quiet = false;
};

/// Adds the `stiffness` subcommand to `app`, filling `o`; `case_help` describes CASE.
CLI::App* add_stiffness_command(CLI::App& app, StiffnessOptions& o, const std::string& case_help);

/// Runs it: 0 on success; throws bearing::InputError (exit 2), SolverError naming the operating
/// point (exit 3) or OutputError (exit 3). Nothing is written unless every point is solved.
int stiffness_command(const StiffnessOptions& o);

}  // namespace bearing_app
