#pragma once
// `bearing-fem contact` and `bearing-fem calibrate`: the Hertz contact reference's commands
// (contact.cc).

#include <string>
#include <vector>

#include <mpi.h>

namespace CLI {
class App;
}

namespace bearing::fem {

struct ContactOptions {
  std::string case_path;
  std::vector<std::string> sets;
  std::string race = "inner";
  std::string geometry = "hertz";
  std::string out_dir;
  double cells = 8;    // cells per semi-minor axis b at the largest load
  double stretch = 2;  // cell aspect h_y/h_x
  double grading = 6;
  double domain = 256;
  unsigned int steps = 6;
  double tolerance = 1e-11;
  double load_min = 0;  // 0: load_max × load_min_fraction
  double load_min_fraction = 0.1;
  double load_max = 0;       // 0: Q_max of the case
  double peak_pressure = 0;  // > 0: load_max = the load whose Hertz peak pressure is this [Pa]
  bool vtu = true;
  bool quiet = false;
  // --geometry groove
  std::string gap = "exact";                // exact | paraboloid
  double groove_depth = 0.2;                // land depth over D
  double segment_angle = 0;                 // [deg]; 0: 180/Z (half the ball pitch)
  double bore = 0, outside = 0, width = 0;  // ring dimensions [m]; 0: ISO 15 by designation
};

/// Adds the `contact` subcommand to `app`, filling `o`.
CLI::App* add_contact_command(CLI::App& app, ContactOptions& o);

/// Adds the `calibrate` subcommand to `app`, filling `o` and the calibration file `out`.
CLI::App* add_calibrate_command(CLI::App& app, ContactOptions& o, std::string& out);

/// Runs `contact`: writes DIR/force_approach.csv, DIR/contact.json (and DIR/vtu/, with --geometry
/// groove DIR/raceway_segment.msh and its .log), all or nothing (bearing/atomic_file_set.h, on
/// rank 0). Returns the exit code. Throws InputError for bad input (before any file is written),
/// OutputError if the files cannot be written; FailedOnRankZero on the other ranks.
int run_contact(const ContactOptions& o, MPI_Comm comm);

/// Runs `calibrate`: both races, the calibration file `out` and the races' folders beside it, all
/// or nothing as run_contact's. Returns the exit code; throws as run_contact.
int run_calibrate(const ContactOptions& o, const std::string& out, MPI_Comm comm);

}  // namespace bearing::fem
