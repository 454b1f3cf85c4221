// bearing-sim: the command line of the lumped bearing model. Parses, calls the library, prints;
// no physics here.

#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bearing/case_file.h"
#include "bearing/errors.h"
#include "bearing/info_report.h"
#include "bearing/presets.h"

namespace {

constexpr const char* kCaseHelp =
    "TOML case file (see README.md and examples/); without it the built-in default case is used: "
    "a 6308 at 2000 rpm under a 20 N downward radial load";

bearing::Case load(const std::string& path, const std::vector<std::string>& sets) {
  std::vector<bearing::Override> overrides;
  for (const auto& s : sets) overrides.push_back(bearing::parse_override(s));
  return path.empty() ? bearing::default_case(overrides) : bearing::read_case_file(path, overrides);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "bearing-sim: lumped Hertzian model of a deep-groove ball bearing (vibration and noise).\n"
      "Units: SI in every output (m, N, s, rad, Pa, Hz); case files accept units such as "
      "\"15.081 mm\", \"2000 rpm\", \"0.05 kN\", \"208 GPa\", \"30 deg\"."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "bearing-sim 0.1.0");

  std::string case_path;
  std::vector<std::string> sets;
  bool json = false;
  auto* info = app.add_subcommand(
      "info",
      "Contact constants per race (sum rho, F(rho), ellipticity, delta*, K) and of the ball "
      "between both races, bearing frequencies (shaft, FTF, BPFO, BPFI, BSF) and the static "
      "load distribution (deflection, ball loads, Q_max) for a case");
  info->add_option("CASE", case_path, kCaseHelp);
  info->add_option("--set", sets,
                   "Override one case-file value (repeat for more), e.g. "
                   "--set operation.speed=\"3000 rpm\" --set bearing.balls=9; keys below")
      ->type_name("TABLE.KEY=VALUE")
      ->allow_extra_args(false);
  info->footer("Case-file keys (plain numbers are SI; strings may carry a unit):\n" +
               bearing::case_keys_help());
  info->add_flag("--json", json,
                 "Print JSON (SI units) with the keys kinematics.{shaft,ftf,bpfo,bpfi,bsf}, "
                 "contact.{inner,outer}.{sum_rho,f_rho,ellipticity,delta_star,K}, contact.K, "
                 "contact.method, static.{deflection,ball_angles,ball_loads,q_max}");

  auto* presets = app.add_subcommand("presets", "List the catalogue bearings and their sources");

  CLI11_PARSE(app, argc, argv);

  try {
    if (*presets) {
      for (const auto& name : bearing::preset_names())
        std::cout << name << "\t" << bearing::preset_source(name) << "\n";
      return 0;
    }
    if (*info) {
      const bearing::Case c = load(case_path, sets);
      const bearing::InfoReport report = bearing::compute_info(c);
      if (json)
        std::cout << bearing::info_json(report).dump(2) << "\n";
      else
        std::cout << bearing::info_text(report);
      return 0;
    }
  } catch (const bearing::InputError& e) {
    std::cerr << "bearing-sim: error: " << e.what() << "\n";
    return 2;
  } catch (const bearing::SolverError& e) {
    std::cerr << "bearing-sim: solver error: " << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "bearing-sim: internal error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
