#pragma once
// `bearing-fem radiate`: the Helmholtz radiation reference's command (radiate.cc).

#include <string>
#include <vector>

#include <mpi.h>

namespace CLI {
class App;
}

namespace bearing::fem {

struct RadiateOptions {
  std::vector<std::string> source;  ///< {NAME} or {"bearing", CASE}
  std::vector<std::string> sets;    ///< case overrides (bearing)
  std::string reference;            ///< exact source compared with (default: the source itself)
  double radius = 0;                ///< body radius [m] (single source)
  std::vector<std::string> microphones;  ///< "r,angle" [m, deg]
  std::vector<double> frequencies;       ///< [Hz]
  double density = 0, sound_speed = 0;   ///< 0: air at 20 °C (or the case's [acoustics])
  unsigned int degree = 4;
  double cells_per_wavelength = 1.5;
  double cells_per_radius = 4;
  unsigned int refinements = 0;
  double physical_radius = 0, pml_thickness = 0;
  unsigned int pml_layers = 0;  ///< 0: automatic
  double pml_attenuation = 12;
  double gap = 0;                      ///< bearing: ring-to-ball clearance [m]; 0: 5 % of D
  double ball_angle = -90;             ///< bearing: ball 1's angle [deg] from +x
  std::string ball_motion = "radial";  ///< bearing: radial (translating) | breathing
  std::string out_dir;
  bool vtu = true;
  bool quiet = false;
};

/// Adds the `radiate` subcommand to `app`, filling `o`.
CLI::App* add_radiate_command(CLI::App& app, RadiateOptions& o);

/// Runs it: writes DIR/radiation.csv, DIR/radiation.json and DIR/vtu/*.vtu. Returns the exit
/// code. Throws InputError for bad input.
int run_radiate(const RadiateOptions& o, MPI_Comm comm);

}  // namespace bearing::fem
