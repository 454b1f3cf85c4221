#include "calibrate.h"

#include <stdexcept>

namespace bearing::verify {

CLI::App* add_calibrate_command(CLI::App& app, CalibrateOptions& o) {
  auto* cmd = app.add_subcommand("calibrate",
                                 "the stiffness calibration run: FE contact of both races, "
                                 "calibration.json, the laws side by side");
  cmd->add_option("CASE", o.case_path, "TOML case file")->required();
  cmd->add_option("--out", o.out, "output folder")->required();
  return cmd;
}

int calibrate_command(const CalibrateOptions&) {
  throw std::logic_error("calibrate: not implemented yet");
}

}  // namespace bearing::verify
