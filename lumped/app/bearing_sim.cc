// bearing-sim: the command line of the lumped bearing model. Parses, calls the library, prints;
// no physics here.

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <gsl/gsl_errno.h>
#include <CLI/CLI.hpp>

#include "bearing/case_file.h"
#include "bearing/contact_loop.h"
#include "bearing/errors.h"
#include "bearing/info_report.h"
#include "bearing/output.h"
#include "bearing/presets.h"
#include "bearing/simulation.h"
#include "bearing/sweep.h"
#ifdef BEARING_WITH_MPI
#include <mpi.h>

#include "bearing/sweep_mpi.h"
#endif

namespace {

#ifdef BEARING_WITH_MPI
// MPI is started only under a launcher (mpirun, srun: their variables are set), so a plain
// `bearing-sim` behaves exactly as one built without MPI. Under mpirun only rank 0 prints and
// writes; the other ranks only run sweep cases.
struct MpiSession {
  bool active = false;
  MpiSession(int& argc, char**& argv) {
    bool launched = false;
    for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
      launched = launched || std::getenv(v) != nullptr;
    if (!launched) return;
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    active = true;
    if (provided < MPI_THREAD_FUNNELED) {
      std::fprintf(stderr, "bearing-sim: error: this MPI cannot run threads beside MPI calls\n");
      MPI_Abort(MPI_COMM_WORLD, 1);
    }
  }
  ~MpiSession() {
    if (active) MPI_Finalize();
  }
};
int world_rank() {
  return bearing::mpi_rank();
}
int world_size() {
  return bearing::mpi_size();
}
// An error on one rank ends every rank (the others would wait for it forever).
int fail(int code) {
  if (world_size() > 1) MPI_Abort(MPI_COMM_WORLD, code);
  return code;
}
#else
int world_rank() {
  return 0;
}
int world_size() {
  return 1;
}
int fail(int code) {
  return code;
}
#endif
// "bearing-sim", or on ranks other than 0 "bearing-sim (rank N)".
std::string who() {
  return world_rank() == 0 ? "bearing-sim"
                           : "bearing-sim (rank " + std::to_string(world_rank()) + ")";
}

constexpr const char* kCaseHelp =
    "TOML case file (see docs/case-files.md and examples/); without it the built-in default case "
    "is used: "
    "a 6308 at 2000 rpm under a 20 N downward radial load";

std::vector<bearing::Override> overrides_of(const std::vector<std::string>& sets) {
  std::vector<bearing::Override> out;
  for (const auto& s : sets) out.push_back(bearing::parse_override(s));
  return out;
}

bearing::Case load(const std::string& path, const std::vector<bearing::Override>& overrides) {
  return path.empty() ? bearing::default_case(overrides) : bearing::read_case_file(path, overrides);
}

// The options every command shares: CASE, --set and the key list in the footer.
void add_case_options(CLI::App* cmd, std::string& path, std::vector<std::string>& sets) {
  cmd->add_option("CASE", path, kCaseHelp);
  cmd->add_option("--set", sets,
                  "Override one case-file value (repeat for more), e.g. "
                  "--set operation.speed=\"3000 rpm\" --set bearing.balls=9; keys below")
      ->type_name("TABLE.KEY=VALUE")
      ->allow_extra_args(false);
  cmd->footer("Case-file keys (plain numbers are SI; strings may carry a unit):\n" +
              bearing::case_keys_help());
}

// Progress on stderr only for a person watching: not with --quiet, not into a file or pipe.
struct ProgressLine {
  bool enabled;
  std::string label;
  int last = -1;
  void operator()(double fraction) {
    if (!enabled) return;
    const int percent = static_cast<int>(fraction * 100.0);
    if (percent == last) return;
    last = percent;
    std::fprintf(stderr, "\r%s %3d%%", label.c_str(), percent);
    if (percent >= 100) std::fprintf(stderr, "\r%*s\r", static_cast<int>(label.size()) + 6, "");
    std::fflush(stderr);
  }
};

// `run`: simulate, analyse, write the result files, print the summary.
int run_command(const std::string& case_path, const std::vector<bearing::Override>& overrides,
                const std::string& out_dir, bool json, bool quiet, bool tty) {
  const bearing::Case c = load(case_path, overrides);
  ProgressLine progress{tty, "run"};
  const auto start = std::chrono::steady_clock::now();
  const bearing::SimulationResult r = bearing::simulate(c, std::ref(progress));
  const bearing::RunSummary s = bearing::summarize(c, r);
  bearing::write_run(out_dir, c, r, s);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (json)
    std::cout << bearing::summary_json(c, r, s).dump(2) << "\n";
  else
    std::cout << bearing::summary_text(c, r, s);
  if (!quiet) std::fprintf(stderr, "run: wrote %s/ in %.3f s\n", out_dir.c_str(), seconds);
  return 0;
}

// `sweep`: every point of the --vary grid, in parallel; sweep.csv streamed to a temporary file
// and renamed into place only when complete.
int sweep_command(const std::string& case_path, const std::vector<bearing::Override>& base,
                  const std::vector<std::string>& vary, const std::string& out_dir, int jobs,
                  bool tty) {
  std::vector<bearing::SweepAxis> axes;
  for (const auto& v : vary) axes.push_back(bearing::parse_vary(v));
  // Check the base case before starting many runs of it.
  load(case_path, base);
  const auto loader = [&](const std::vector<bearing::Override>& point) {
    auto all = base;
    all.insert(all.end(), point.begin(), point.end());
    return load(case_path, all);
  };
  const auto progress = [&](std::size_t done, std::size_t total) {
    if (tty) std::fprintf(stderr, "\rsweep %zu/%zu cases", done, total);
    if (tty && done == total) std::fprintf(stderr, "\n");
  };
  bearing::SweepRunner runner;  // run_sweep; under mpirun the ranks share the cases
#ifdef BEARING_WITH_MPI
  if (world_size() > 1) runner = bearing::run_sweep_mpi;
  if (world_rank() != 0) {
    runner(loader, bearing::sweep_size(axes),
           [&](std::size_t i) { return bearing::sweep_point(axes, i); }, jobs, {}, {});
    return 0;
  }
#endif
  const bearing::SweepCounts counts =
      bearing::write_sweep(out_dir, axes, loader, jobs, progress, runner);
  const std::filesystem::path file = std::filesystem::path(out_dir) / "sweep.csv";
  std::cout << "sweep: " << counts.cases << " cases, " << counts.failed << " failed; wrote "
            << file.string() << "\n";
  return counts.failed == counts.cases ? 3 : 0;
}

}  // namespace

int main(int argc, char** argv) {
#ifdef BEARING_WITH_MPI
  MpiSession mpi(argc, argv);
#endif
  // GSL's default handler aborts; the library checks GSL's return codes itself.
  gsl_set_error_handler_off();

  CLI::App app{
      "bearing-sim: lumped Hertzian model of a deep-groove ball bearing (vibration and noise).\n"
      "Units: SI in every output (m, N, s, rad, Pa, Hz); case files accept units such as "
      "\"15.081 mm\", \"2000 rpm\", \"0.05 kN\", \"208 GPa\", \"30 deg\"."};
  app.require_subcommand(1);
  // The instruction set of the SIMD contact loop on this CPU (bearing/contact_loop.h).
  app.set_version_flag("--version",
                       "bearing-sim 0.1.0 (contact loop: simd as " + bearing::simd_target() + ")");

  std::string case_path;
  std::vector<std::string> sets;
  bool json = false;
  bool quiet = false;
  std::string out_dir;
  std::vector<std::string> vary;
  int jobs = 0;

  auto* info = app.add_subcommand(
      "info",
      "The contact law in use (a Hertz method, or the FE-calibrated constants of "
      "model.calibration), contact constants per race (sum rho, F(rho), ellipticity, delta*, K, "
      "exponent) and of the ball between both races, bearing frequencies (shaft, FTF, BPFO, "
      "BPFI, BSF) and the static load distribution (deflection, ball loads, Q_max) for a case");
  add_case_options(info, case_path, sets);
  info->add_flag("--json", json,
                 "Print JSON (SI units) with the keys kinematics.{shaft,ftf,bpfo,bpfi,bsf}, "
                 "contact.{inner,outer}.{sum_rho,f_rho,ellipticity,delta_star,K,exponent}, "
                 "contact.{K,exponent,method}, contact.calibration (calibrated law), "
                 "static.{deflection,ball_angles,ball_loads,q_max}");

  auto* run = app.add_subcommand(
      "run", "Simulate a case (model.kind " + bearing::names_of(bearing::kModelKinds, " | ") +
                 ") and write DIR/response.csv (t, "
                 "then x,y,vx,vy,ax,ay [,z,vz,az] [,Q1..QZ] [,r1..rZ,vr1..vrZ]), DIR/spectrum.csv "
                 "(one-sided amplitude spectra after the transient), "
                 "DIR/summary.json (channels.<name>.{rms,ptp,kurtosis,crest}, peaks.<name>[] with "
                 "frequency, "
                 "amplitude, label, label_error) and DIR/case.toml (the fully resolved case); "
                 "with output.format = \"npy\" the tables are DIR/response.npy, spectrum.npy, "
                 "... (float64, full precision) and DIR/columns.json names their columns and "
                 "units; prints the summary");
  add_case_options(run, case_path, sets);
  run->add_option("--out", out_dir, "Folder for the result files (created if missing)")->required();
  run->add_flag("--json", json, "Print summary.json instead of the readable summary");
  run->add_flag("--quiet", quiet, "No progress on stderr (also off when stderr is not a terminal)");

  auto* sweep = app.add_subcommand(
      "sweep",
      "Run a case for every combination of the --vary values, in parallel, and write "
      "DIR/sweep.csv: "
      "the varied values (SI), status, error, then each ring channel's rms, ptp, kurtosis, crest "
      "and largest peak. A failed case is reported in its row; the others go on.");
  add_case_options(sweep, case_path, sets);
  sweep
      ->add_option("--vary", vary,
                   "KEY=FROM:TO:N, N values from FROM to TO (units allowed), repeat for more keys "
                   "(Cartesian product), e.g. --vary operation.speed=1000rpm:3000rpm:5")
      ->required()
      ->allow_extra_args(false);
  sweep->add_option("--out", out_dir, "Folder for sweep.csv (created if missing)")->required();
  sweep
      ->add_option("--jobs", jobs,
                   "Parallel cases (default: all cores); under mpirun, per rank (default: the "
                   "cores shared among the machine's ranks)")
      ->check(CLI::NonNegativeNumber);
  sweep->add_flag("--quiet", quiet, "No progress on stderr");

  auto* presets = app.add_subcommand("presets", "List the catalogue bearings and their sources");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return world_rank() == 0 ? app.exit(e) : e.get_exit_code();
  }
  const bool tty = isatty(STDERR_FILENO) && !quiet && world_rank() == 0;
  // Under mpirun, every command but sweep runs on rank 0 alone.
  if (!*sweep && world_rank() != 0) return 0;

  try {
    if (*presets) {
      for (const auto& name : bearing::preset_names())
        std::cout << name << "\t" << bearing::preset_source(name) << "\n";
      return 0;
    }
    if (*info) {
      const bearing::Case c = load(case_path, overrides_of(sets));
      const bearing::InfoReport report = bearing::compute_info(c);
      if (json)
        std::cout << bearing::info_json(report).dump(2) << "\n";
      else
        std::cout << bearing::info_text(report);
      return 0;
    }
    if (*run) return run_command(case_path, overrides_of(sets), out_dir, json, quiet, tty);
    if (*sweep) return sweep_command(case_path, overrides_of(sets), vary, out_dir, jobs, tty);
  } catch (const bearing::InputError& e) {
    std::cerr << who() << ": error: " << e.what() << "\n";
    return fail(2);
  } catch (const bearing::SolverError& e) {
    std::cerr << who() << ": solver error: " << e.what() << "\n";
    return fail(3);
  } catch (const std::exception& e) {
    std::cerr << who() << ": internal error: " << e.what() << "\n";
    return fail(1);
  }
  return 0;
}
