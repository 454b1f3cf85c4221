// bearing-fem: command line of the deal.II finite-element references. Parses, calls the
// commands, maps their errors to exit codes; no physics here.
//
//   bearing-fem contact CASE --race inner|outer --out DIR     (app/contact.cc)
//   bearing-fem calibrate CASE --out FILE                     (app/contact.cc)
//   bearing-fem radiate --source NAME ... --out DIR           (app/radiate.cc)
//   bearing-fem modes STRUCTURE --out DIR                     (app/modes.cc)

#include <deal.II/base/mpi.h>

#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "app/contact.h"
#include "app/modes.h"
#include "app/radiate.h"
#include "app/rank_zero.h"
#include "bearing/cli_options.h"
#include "bearing/errors.h"

int main(int argc, char** argv) {
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  CLI::App app{"bearing-fem: deal.II finite-element references of the bearing toolkit"};
  app.require_subcommand(1);
  bearing::fem::ContactOptions o;
  bearing::fem::add_contact_command(app, o);
  bearing::fem::ContactOptions co;
  std::string calibration_file;
  auto* calibrate = bearing::fem::add_calibrate_command(app, co, calibration_file);
  bearing::fem::RadiateOptions ro;
  auto* radiate = bearing::fem::add_radiate_command(app, ro);
  bearing::fem::ModesOptions mo;
  auto* modes = bearing::fem::add_modes_command(app, mo);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return e.get_exit_code() == 0 ? 0 : 2;
    return bearing::cli::parse_error_exit(app, e, "bearing-fem");
  }
  try {
    if (*calibrate) return bearing::fem::run_calibrate(co, calibration_file, MPI_COMM_WORLD);
    if (*radiate) return bearing::fem::run_radiate(ro, MPI_COMM_WORLD);
    if (*modes) return bearing::fem::run_modes(mo, MPI_COMM_WORLD);
    return bearing::fem::run_contact(o, MPI_COMM_WORLD);
  } catch (const bearing::fem::FailedOnRankZero& e) {
    return e.status;  // rank 0 says why
  } catch (const bearing::InputError& e) {
    std::cerr << "bearing-fem: input error: " << e.what() << '\n';
    return 2;
  } catch (const bearing::OutputError& e) {
    std::cerr << "bearing-fem: write error: " << e.what() << '\n';
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "bearing-fem: error: " << e.what() << '\n';
    return 1;
  }
}
