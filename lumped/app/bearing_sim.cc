// bearing-sim: the command line of the lumped bearing model. Parses, calls the library, prints;
// no physics here.

#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <gsl/gsl_errno.h>
#include <CLI/CLI.hpp>

#include "analyse_command.h"
#include "bearing/case_file.h"
#include "bearing/cli_options.h"
#include "bearing/contact_loop.h"
#include "bearing/errors.h"
#include "bearing/info_report.h"
#include "bearing/output.h"
#include "bearing/presets.h"
#include "bearing/simulation.h"
#include "bearing/sweep.h"
#include "full_program.h"
#include "stiffness_command.h"
#ifdef BEARING_WITH_HDF5
#include "bearing/sweep_dataset.h"
#include "bearing/sweep_save.h"
#endif
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
    if (!bearing_app::launched_in_parallel()) return;
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
[[maybe_unused]] int world_size() {  // read only where MPI is built in
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
  // Beyond the elastic limit the run is still made (a user may study it), with a warning.
  const std::string warning = bearing::elastic_limit_warning(
      bearing::compute_info(c, bearing::InfoParts::without_stiffness));
  if (!warning.empty()) std::cerr << "bearing-sim: warning: " << warning << "\n";
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

constexpr const char* kVersion = "bearing-sim 0.1.0";

// The sweep options of the command line, as given.
struct SweepOptions {
  std::vector<std::string> vary, sample, sets;
  std::size_t samples = 0;
  std::uint64_t seed = 1;
  std::string cases, part, resume, out_dir, case_path;
  std::vector<std::string> save;
  int jobs = 0;
};

// `--save`'s list: given on the command line, or on --resume read from the killed sweep's spool
// (sweep_save.h). Without HDF5 in the build, --save is an error.
std::vector<bearing::SweepSave> save_list(const SweepOptions& o) {
#ifdef BEARING_WITH_HDF5
  return o.resume.empty() ? bearing::parse_sweep_save(o.save) : bearing::spooled_save(o.resume);
#else
  if (!o.save.empty())
    throw bearing::InputError(
        "--save: this bearing-sim was built without HDF5 (Debian: libhdf5-dev), so it cannot "
        "write sweep.h5");
  return {};
#endif
}

// write_sweep's hook for --save (sweep_save.h), empty without it.
bearing::SweepRowHook save_hook(const std::string& dir, const bearing::SweepPlan& plan,
                                const std::vector<bearing::SweepSave>& what, bool resume) {
#ifdef BEARING_WITH_HDF5
  return bearing::sweep_save_hook(dir, plan, what, resume);
#else
  (void)dir, (void)plan, (void)what, (void)resume;
  return {};
#endif
}

// The design the options name: --vary (grid), --sample (random) or --cases (list), one of them.
std::shared_ptr<const bearing::SweepDesign> design_of(const SweepOptions& o) {
  const int kinds = !o.vary.empty() + !o.sample.empty() + !o.cases.empty();
  if (kinds != 1)
    throw bearing::InputError(
        "sweep: give one design: --vary KEY=FROM:TO:N (grid), --sample KEY=DIST(...) with "
        "--samples N (random) or --cases FILE.csv (list); they do not mix");
  if (!o.vary.empty()) {
    std::vector<bearing::SweepAxis> axes;
    for (const auto& v : o.vary) axes.push_back(bearing::parse_vary(v));
    return bearing::grid_design(std::move(axes));
  }
  if (!o.cases.empty()) return bearing::list_design_from_csv(o.cases);
  if (o.samples == 0)
    throw bearing::InputError("--sample needs --samples N (the number of cases, N ≥ 1)");
  std::vector<bearing::SweepSample> samples;
  for (const auto& s : o.sample) samples.push_back(bearing::parse_sample(s));
  return bearing::random_design(std::move(samples), o.samples, o.seed);
}

// `--resume DIR` of a sweep whose sweep.csv is complete (bearing::finished_sweep): its counts, and
// nothing to run. Rank 0 decides and tells the other ranks, which would otherwise wait for cases
// (and a whole sweep's record, which they read, is gone once it is complete).
std::optional<bearing::SweepCounts> already_finished(const std::string& dir) {
  std::optional<bearing::SweepCounts> done;
  if (world_rank() == 0) done = bearing::finished_sweep(dir);
#ifdef BEARING_WITH_MPI
  if (world_size() > 1) {
    int finished = done ? 1 : 0;
    MPI_Bcast(&finished, 1, MPI_INT, 0, MPI_COMM_WORLD);
    if (finished && !done) done = bearing::SweepCounts{};
  }
#endif
  return done;
}

// `sweep`: every case of the design (or of its --part), in parallel; sweep.csv streamed to a
// temporary file and renamed into place only when complete; --resume DIR continues one.
int sweep_command(const SweepOptions& o, bool tty, const bearing_app::CommandLine& cl) {
  const bool resume = !o.resume.empty();
  // sweep.h5 (--save, or the --save a --resume's spool may hold) is bearing-sim-full's.
  if (bearing_app::hands_over() && (resume || !o.save.empty()))
    bearing_app::hand_over(cl, resume ? "sweep --resume" : "sweep --save");
  if (resume && (!o.vary.empty() || !o.sample.empty() || !o.cases.empty() || !o.sets.empty() ||
                 !o.case_path.empty() || !o.part.empty() || !o.out_dir.empty()))
    throw bearing::InputError("--resume " + o.resume +
                              " takes the design, case and part from its sweep.design.json; give "
                              "only --jobs and --quiet with it");
  if (!resume && o.out_dir.empty()) throw bearing::InputError("sweep: --out DIR is required");
  if (resume) {
    if (const auto done = already_finished(o.resume)) {
      // Nothing is touched: neither sweep.csv nor a sweep.h5 beside it.
      if (world_rank() == 0)
        std::cout << "sweep: " << o.resume << " is complete: " << done->cases << " cases, "
                  << done->failed << " failed in "
                  << (std::filesystem::path(o.resume) / "sweep.csv").string()
                  << "; nothing to resume\n";
      return 0;
    }
  }
  const auto progress = [&](std::size_t done, std::size_t total) {
    if (tty) std::fprintf(stderr, "\rsweep %zu/%zu cases", done, total);
    if (tty && done == total) std::fprintf(stderr, "\n");
  };
  bearing::SweepRunner runner;  // run_sweep; under mpirun the ranks share the cases
#ifdef BEARING_WITH_MPI
  if (world_size() > 1) {
    // Rank 0 tells the workers how many cases remain (fewer than the part's on --resume); they
    // are the part's last ones, so every rank maps rank 0's case numbers to the same points.
    runner = [](const bearing::SweepLoader& load, std::size_t cases, const auto& point, int jobs,
                const auto& sink, const bearing::SweepProgress& progress, const auto& save) {
      unsigned long long n = cases;
      MPI_Bcast(&n, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
      bearing::run_sweep_mpi(load, cases, point, jobs, sink, progress, save);
    };
  }
  if (world_rank() != 0) {  // a worker: the same plan; rank 0 deals the cases and writes
    bearing::SweepPlan plan;
    if (resume) {
      plan = bearing::read_sweep_record(o.resume);
    } else {
      plan.design = design_of(o);
      plan.base = bearing::sweep_base(o.case_path, overrides_of(o.sets));
      if (!o.part.empty()) plan.part = bearing::parse_part(o.part);
    }
    const std::size_t end = bearing::part_range(plan.design->size(), plan.part).second;
    unsigned long long n = 0;
    MPI_Bcast(&n, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
    const std::size_t start = end - static_cast<std::size_t>(n);
    bearing::run_sweep_mpi(
        [&](const std::vector<bearing::Override>& p) {
          return bearing::load_sweep_case(plan.base, p);
        },
        n, [&](std::size_t i) { return plan.design->point(start + i); }, o.jobs, {}, {},
        save_list(o));
    return 0;
  }
#endif
  bearing::SweepCounts counts;
  std::string out_dir = o.out_dir;
  bool saved = false;  // sweep.h5 written too
  const std::vector<bearing::SweepSave> what = save_list(o);
  if (resume) {
    const bearing::SweepRowHook hook =
        save_hook(o.resume, bearing::read_sweep_record(o.resume), what, true);
    counts = bearing::resume_sweep(o.resume, o.jobs, progress, runner, hook);
    out_dir = o.resume;
    saved = static_cast<bool>(hook.add);
  } else {
    bearing::SweepPlan plan;
    plan.design = design_of(o);
    plan.base = bearing::sweep_base(o.case_path, overrides_of(o.sets));
    // A base case its kind cannot run (an axial load without an axial DOF, a moment) is refused
    // before any case runs, as the case reader refuses a bad value.
    bearing::check_run_loads(bearing::load_sweep_case(plan.base, {}));
    if (!o.part.empty()) plan.part = bearing::parse_part(o.part);
    plan.program = kVersion;
    const bearing::SweepRowHook hook = save_hook(out_dir, plan, what, false);
    counts = bearing::write_sweep(out_dir, plan, o.jobs, progress, runner, false, hook);
    saved = static_cast<bool>(hook.add);
  }
  // A sweep.h5 an earlier sweep left here does not belong to this sweep.csv.
  if (!saved) std::filesystem::remove(std::filesystem::path(out_dir) / "sweep.h5");
  const std::filesystem::path file = std::filesystem::path(out_dir) / "sweep.csv";
  std::cout << "sweep: " << counts.cases << " cases, " << counts.failed << " failed; wrote "
            << file.string() << (saved ? " and sweep.h5" : "") << "\n";
  return counts.failed == counts.cases ? 3 : 0;
}

// `merge OUT DIR…`: the parts' sweep.csv into OUT/sweep.csv, and their sweep.h5 (all parts have
// one, or none) into OUT/sweep.h5; if that fails, the merged sweep.csv is removed again.
int merge_command(const std::string& out, const std::vector<std::string>& dirs,
                  const bearing_app::CommandLine& cl) {
  namespace fs = std::filesystem;
  std::vector<std::string> datasets;
  for (const auto& d : dirs)
    if (fs::exists(fs::path(d) / "sweep.h5"))
      datasets.push_back((fs::path(d) / "sweep.h5").string());
  if (!datasets.empty() && datasets.size() != dirs.size())
    throw bearing::InputError("merge: " + std::to_string(datasets.size()) + " of the " +
                              std::to_string(dirs.size()) +
                              " parts have a sweep.h5: run every part with the same --save");
  if (!datasets.empty() && bearing_app::hands_over())
    bearing_app::hand_over(cl, "merging sweep.h5");
#ifndef BEARING_WITH_HDF5
  if (!datasets.empty())
    throw bearing::InputError(
        "merge: the parts have sweep.h5, and this bearing-sim was built without HDF5 (Debian: "
        "libhdf5-dev)");
#endif
  const bearing::SweepCounts counts = bearing::merge_sweeps(out, dirs);
  const fs::path csv = fs::path(out) / "sweep.csv";
#ifdef BEARING_WITH_HDF5
  if (!datasets.empty()) {
    try {
      bearing::merge_datasets((fs::path(out) / "sweep.h5").string(), datasets);
    } catch (...) {
      fs::remove(csv);
      throw;
    }
  }
#endif
  std::cout << "merge: " << counts.cases << " cases, " << counts.failed << " failed; wrote "
            << csv.string() << (datasets.empty() ? "" : " and sweep.h5") << "\n";
  return 0;
}

// The sweep options on `cmd`.
void add_sweep_options(CLI::App* cmd, SweepOptions& o) {
  cmd->add_option(
         "--vary", o.vary,
         "Grid design: KEY=FROM:TO:N, N values from FROM to TO (units allowed), repeat "
         "for more keys (Cartesian product), e.g. --vary operation.speed=1000rpm:3000rpm:5")
      ->allow_extra_args(false);
  cmd->add_option("--sample", o.sample,
                  "Random design: KEY=uniform(a, b) | normal(mean, sd) | loguniform(a, b) "
                  "(units allowed), repeat for more keys; with --samples and --seed")
      ->allow_extra_args(false);
  cmd->add_option("--samples", o.samples, "Number of cases of a random design")
      ->check(bearing::cli::range(1, 1e9));
  cmd->add_option("--seed", o.seed,
                  "Seed of a random design (default 1): the same seed gives the same cases")
      ->capture_default_str();
  cmd->add_option("--cases", o.cases,
                  "List design: a CSV file, header = case-file keys, one row per case (SI "
                  "numbers or values with units)");
  cmd->add_option("--part", o.part,
                  "K/N: run only the K-th (1..N) of N contiguous blocks of the cases; the parts "
                  "are joined by `bearing-sim merge`");
  cmd->add_option("--resume", o.resume,
                  "Continue the sweep killed in DIR: the design is read from "
                  "DIR/sweep.design.json, finished rows are kept, the rest run (a finished sweep "
                  "is left as it is, exit 0)");
  cmd->add_option("--out", o.out_dir,
                  "Folder for sweep.csv and, while running (and for a --part), sweep.design.json");
  cmd->add_option("--save", o.save,
                  "response,spectrum,envelope,summary (any of them; comma list or repeated): "
                  "each case's arrays into DIR/sweep.h5 (HDF5)")
      ->allow_extra_args(false);
  cmd->add_option("--jobs", o.jobs,
                  "Parallel cases (default: all cores); under mpirun, per rank (default: the "
                  "cores shared among the machine's ranks)")
      ->check(bearing::cli::range(0, 4096));
}

// `info`: the case's contact law, constants, frequencies, static state and stiffness.
CLI::App* add_info_command(CLI::App& app, std::string& case_path, std::vector<std::string>& sets,
                           bool& json) {
  auto* info = app.add_subcommand(
      "info",
      "The contact law in use (a Hertz method, or the FE-calibrated constants of "
      "model.calibration), contact constants per race (sum rho, F(rho), ellipticity, delta*, K, "
      "exponent) and of the ball between both races, bearing frequencies (shaft, FTF, BPFO, "
      "BPFI, BSF), the static load distribution (deflection, ball loads, Q_max) and the 5x5 "
      "stiffness at the case's loads (5-DOF static solution, as `stiffness`) for a case");
  add_case_options(info, case_path, sets);
  info->add_flag("--json", json,
                 "Print JSON (SI units) with the keys kinematics.{shaft,ftf,bpfo,bpfi,bsf}, "
                 "contact.{inner,outer}.{sum_rho,f_rho,ellipticity,delta_star,K,exponent}, "
                 "contact.{K,exponent,method}, contact.calibration (calibrated law), "
                 "static.{deflection,ball_angles,ball_loads,q_max}, stiffness.{load, "
                 "displacement, matrix (5x5 K = dF/dq at every load of the case), q_max}");
  return info;
}

// `run`: simulate a case and write its result files.
CLI::App* add_run_command(CLI::App& app, std::string& case_path, std::vector<std::string>& sets,
                          std::string& out_dir, bool& json, bool& quiet) {
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
  return run;
}

}  // namespace

int main(int argc, char** argv) {
  const bearing_app::CommandLine command_line{argc, argv};
  // Under mpirun a plain bearing-sim is bearing-sim-full from the start (MPI_Init in every rank).
  if (bearing_app::hands_over() && bearing_app::launched_in_parallel()) {
    try {
      bearing_app::hand_over(command_line, "a command under mpirun");
    } catch (const std::exception& e) {
      std::cerr << "bearing-sim: internal error: " << e.what() << "\n";
      return 1;
    }
  }
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
  app.set_version_flag("--version", std::string(kVersion) + " (contact loop: simd as " +
                                        bearing::simd_target() + ")");

  std::string case_path;
  std::vector<std::string> sets;
  bool json = false;
  bool quiet = false;
  std::string out_dir;

  auto* info = add_info_command(app, case_path, sets, json);
  auto* run = add_run_command(app, case_path, sets, out_dir, json, quiet);

  SweepOptions so;
  auto* sweep = app.add_subcommand(
      "sweep",
      "Run a case for every point of a design (--vary grid, --sample random or --cases list), "
      "in parallel, and write DIR/sweep.csv: the design's values (SI), status, error, then each "
      "ring channel's rms, ptp, kurtosis, crest and largest peak (with output.envelope_band also "
      "each envelope's band, spectral kurtosis and largest line, and the diagnosis). A failed "
      "case is reported in its row; the others go on. A killed sweep continues with --resume "
      "DIR.");
  add_case_options(sweep, so.case_path, so.sets);
  add_sweep_options(sweep, so);
  sweep->add_flag("--quiet", quiet, "No progress on stderr");

  std::string merge_out;
  std::vector<std::string> merge_dirs;
  auto* merge = app.add_subcommand(
      "merge",
      "Join the folders of the parts (--part K/N) of one sweep into OUT/sweep.csv, the same "
      "file as one run of the whole design; refuses parts of different designs, missing or "
      "repeated parts");
  merge->add_option("OUT", merge_out, "Folder for the merged sweep.csv")->required();
  merge->add_option("DIRS", merge_dirs, "The parts' folders")->required();

  bearing_app::AnalyseOptions ao;
  auto* analyse = bearing_app::add_analyse_command(app, ao);

  bearing_app::StiffnessOptions stiffness_options;
  auto* stiffness = bearing_app::add_stiffness_command(app, stiffness_options, kCaseHelp);
  stiffness->footer("Case-file keys (plain numbers are SI; strings may carry a unit):\n" +
                    bearing::case_keys_help());

  auto* presets = app.add_subcommand("presets", "List the catalogue bearings and their sources");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (world_rank() != 0) return e.get_exit_code() == 0 ? 0 : 2;
    return bearing::cli::parse_error_exit(app, e, "bearing-sim");
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
    if (*sweep) return sweep_command(so, tty, command_line);
    if (*merge) return merge_command(merge_out, merge_dirs, command_line);
    if (*analyse) return bearing_app::analyse_command(ao, command_line);
    if (*stiffness) return bearing_app::stiffness_command(stiffness_options);
  } catch (const bearing::InputError& e) {
    std::cerr << who() << ": error: " << e.what() << "\n";
    return fail(2);
  } catch (const bearing::SolverError& e) {
    std::cerr << who() << ": solver error: " << e.what() << "\n";
    return fail(3);
  } catch (const bearing::OutputError& e) {
    std::cerr << who() << ": write error: " << e.what() << "\n";
    return fail(3);
  } catch (const std::exception& e) {
    std::cerr << who() << ": internal error: " << e.what() << "\n";
    return fail(1);
  }
  return 0;
}
