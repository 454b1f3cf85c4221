#pragma once
// `bearing-sim analyse RECORD [CASE] --out DIR`: a measured record read (records layer), analysed
// (analyse_record) and written in run's files (write_record_analysis). Parsing and wiring only;
// no physics here.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "full_program.h"

namespace bearing_app {

/// The analyse options as given on the command line.
struct AnalyseOptions {
  std::string record, case_path, out_dir;
  std::vector<std::string> sets;
  std::string channel, rate, unit, dataset;
  double scale = 1.0;
  /// "" (the record's stored speed, else the case's operation.speed), "1797rpm", "estimate" or
  /// "estimate:1800rpm".
  std::string speed;
  std::string band = "auto";  ///< "auto" (kurtogram), "none" or "LOW:HIGH" ("2kHz:4kHz")
  bool prewhiten = true;
  std::string rule = "coherence";
  double false_alarm = 1e-3;
  double slip = 0.02;
  int harmonics = 3;
  double speed_refinement = 0.03;
  bool json = false;
  bool quiet = false;
};

/// Adds the `analyse` subcommand to `app`, filling `o`.
CLI::App* add_analyse_command(CLI::App& app, AnalyseOptions& o);

/// Runs it: 0 on success; throws bearing::InputError (exit 2), OutputError or SolverError (3).
/// A record that only bearing-sim-full reads (.mat, .h5) is handed over to it (full_program.h).
int analyse_command(const AnalyseOptions& o, const CommandLine& cl);

}  // namespace bearing_app
