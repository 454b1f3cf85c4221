// bearing-verify: the verification report of the toolkit. Parses, runs the check tables, writes
// the report; the checks themselves are in checks/, the report in report_*.cc.

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <regex>
#include <string>
#include <vector>

#include <gsl/gsl_errno.h>
#include <CLI/CLI.hpp>

#include "bearing/errors.h"
#include "calibrate.h"
#include "families.h"
#include "fem_runner.h"
#include "run_info.h"
#include "runner.h"

namespace fs = std::filesystem;
using namespace bearing::verify;

namespace {

const std::map<std::string, Level> kLevels = {
    {"quick", Level::quick}, {"standard", Level::standard}, {"full", Level::full}};

struct Options {
  std::string level = "standard";
  std::string only;
  int jobs = 2;
  int mpi = 1;
  std::string out;
  std::string fem = BEARING_VERIFY_FEM;
  std::string plant;  ///< run --plant: a mutation planted in this run
  bool quiet = false;
  bool fail_fast = false;  ///< run --fail-fast: cheapest checks first, stop at the first failure
  bool source = false;     ///< mutate --source: code mutants of the physics sources
  int mutants = 150;       ///< mutate --source: how many are drawn from lumped/src/
  int fem_mutants = 10;    ///< mutate --source: how many from fem/ (judged where deal.II is)
  int seed = 30;           ///< mutate --source: the draw's seed
};

// The perturbation `run --plant ID` asks for (identity without it).
Perturbation planted(const std::string& id) {
  if (id.empty()) return {};
  const Mutation* m = find_mutation(id);
  if (m == nullptr) {
    std::string allowed;
    for (const auto& x : mutations()) allowed += (allowed.empty() ? "" : ", ") + x.id;
    throw bearing::InputError("--plant = \"" + id + "\": unknown mutation; allowed: " + allowed);
  }
  return m->perturbation;
}

void check_regex(const std::string& only) {
  try {
    std::regex r(only, std::regex::ECMAScript);
  } catch (const std::regex_error& e) {
    throw bearing::InputError("--only = \"" + only + "\": not a regular expression (" + e.what() +
                              "); allowed: an ECMAScript regex searched in each id");
  }
}

// The progress line on stderr, for a person watching.
void say(const Options& o, const std::string& line) {
  if (!o.quiet) std::fprintf(stderr, "%s\n", line.c_str());
}

int list_command(const Options& o) {
  check_regex(o.only);
  const auto all = all_checks();
  const auto selected = select_checks(all, kLevels.at(o.level), o.only);
  std::printf("%-58s %-11s %-12s %-10s %8s  %s\n", "id", "family", "reference", "level", "cost s",
              "tolerance");
  for (const Check* c : selected) {
    const auto& t = c->tolerance;
    char tol[64];
    if (t.kind == Tolerance::Kind::relative)
      std::snprintf(tol, sizeof tol, "±%.3g %%", 100 * t.bound);
    else
      std::snprintf(tol, sizeof tol, "±%.3g %s", t.bound, c->unit.c_str());
    std::printf("%-58s %-11s %-12s %-10s %8.1f  %s\n", c->id.c_str(), c->family.c_str(),
                to_string(c->reference), to_string(c->level), c->cost, tol);
    std::printf("    %s\n", c->compares.c_str());
  }
  std::printf("%zu checks at level %s\n", selected.size(), o.level.c_str());
  return 0;
}

int mutations_command() {
  for (const auto& m : mutations()) std::printf("%-28s %s\n", m.id.c_str(), m.description.c_str());
  return 0;
}

std::string fem_program(const Options& o) {
  if (o.fem.empty()) return "";
  if (!fs::exists(o.fem))
    throw bearing::InputError("--fem = \"" + o.fem +
                              "\": no such file; allowed: the path of bearing-fem");
  return o.fem;
}

void prepare_out(const std::string& out) {
  std::error_code ec;
  fs::create_directories(fs::path(out) / "fem", ec);
  if (ec)
    throw bearing::InputError("--out = \"" + out + "\": cannot create it (" + ec.message() + ")");
}

Report run_report(const Options& o, const std::string& command, FemRunner& fem,
                  const std::vector<Check>& all, std::vector<const Check*>& selected) {
  Report report;
  report.info = run_info(command, o.level, o.only, o.jobs, o.mpi, fem.program());
  report.info.planted = o.plant;
  selected = select_checks(all, kLevels.at(o.level), command == "mutate" ? "" : o.only);
  if (o.fail_fast) selected = cheapest_first(selected);
  const Context context(kLevels.at(o.level), planted(o.plant), &fem, BEARING_SOURCE_DIR);
  say(o, command + ": " + std::to_string(selected.size()) + " checks at level " + o.level);
  report.results = run_checks(
      selected, context, o.jobs,
      [&](const CheckResult& r, int n) {
        say(o, "[" + std::to_string(n) + "/" + std::to_string(selected.size()) + "] " +
                   to_string(r.status) + "  " + r.check->id);
      },
      o.fail_fast);
  return report;
}

int run_command(const Options& o) {
  check_regex(o.only);
  const auto start = std::chrono::steady_clock::now();
  prepare_out(o.out);
  FemRunner fem(fem_program(o), o.mpi, (fs::path(o.out) / "fem").string());
  const auto all = all_checks();
  std::vector<const Check*> selected;
  Report report = run_report(o, "run", fem, all, selected);
  report.info.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_report(report, o.out, BEARING_VERIFY_PLOT_SCRIPT);
  std::printf(
      "%d passed, %d pinned, %d failed, %d skipped, %d reported of %zu checks; report: %s\n",
      report.passed(), report.pinned(), report.failed(), report.skipped(), report.reported(),
      report.results.size(), (fs::path(o.out) / "report.html").c_str());
  if (o.fail_fast && report.failed() > 0) {
    const auto first = std::find_if(report.results.begin(), report.results.end(),
                                    [](const CheckResult& r) { return r.status == Status::fail; });
    std::printf("fail-fast: stopped after %s failed (%zu of %zu checks ran)\n",
                first->check->id.c_str(), report.results.size(), selected.size());
  }
  return report.failed() > 0 ? 4 : 0;
}

int mutate_command(const Options& o) {
  check_regex(o.only);
  const auto start = std::chrono::steady_clock::now();
  prepare_out(o.out);
  FemRunner fem(fem_program(o), o.mpi, (fs::path(o.out) / "fem").string());
  const auto all = all_checks();
  std::vector<const Check*> selected;
  Report report = run_report(o, "mutate", fem, all, selected);
  std::vector<const Mutation*> chosen;
  const std::regex pattern(o.only.empty() ? std::string(".*") : o.only);
  for (const auto& m : mutations())
    if (std::regex_search(m.id, pattern)) chosen.push_back(&m);
  if (chosen.empty())
    throw bearing::InputError("--only = \"" + o.only +
                              "\": matches no mutation id (bearing-verify list --mutations)");
  report.has_mutations = true;
  report.mutations = run_mutations(
      chosen, report.results,
      [&](const Perturbation& p) {
        return Context(kLevels.at(o.level), p, &fem, BEARING_SOURCE_DIR);
      },
      o.jobs,
      [&](const MutationResult& m) {
        say(o, "mutation " + m.id + ": " +
                   (m.caught() ? "caught by " + std::to_string(m.caught_by.size()) + " checks"
                               : std::string("NOT CAUGHT")));
      });
  report.info.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_report(report, o.out, BEARING_VERIFY_PLOT_SCRIPT);
  int caught = 0;
  for (const auto& m : report.mutations) caught += m.caught() ? 1 : 0;
  std::printf(
      "mutation score %d/%zu; baseline %d passed, %d pinned, %d failed, %d skipped, %d reported; "
      "report: %s\n",
      caught, report.mutations.size(), report.passed(), report.pinned(), report.failed(),
      report.skipped(), report.reported(), (fs::path(o.out) / "report.html").c_str());
  return caught == static_cast<int>(report.mutations.size()) && report.failed() == 0 ? 0 : 4;
}

// mutate --source: the code mutants are drawn, built and judged by source_mutants.py (it copies
// the commit, rebuilds this program per mutant and runs `run --fail-fast`); this hands over to it.
int source_mutants_command(const Options& o) {
  if (!o.only.empty())
    throw bearing::InputError(
        "--only = \"" + o.only +
        "\": not used with --source; allowed: --mutants N, --fem-mutants M and --seed S");
  const std::string script = BEARING_VERIFY_SOURCE_MUTANTS;
  std::vector<std::string> args = {"/usr/bin/python3",
                                   script,
                                   "run",
                                   "--repo",
                                   BEARING_SOURCE_DIR,
                                   "--out",
                                   o.out,
                                   "--level",
                                   o.level,
                                   "--jobs",
                                   std::to_string(o.jobs),
                                   "--mutants",
                                   std::to_string(o.mutants),
                                   "--fem-mutants",
                                   std::to_string(o.fem_mutants),
                                   "--seed",
                                   std::to_string(o.seed)};
  if (o.quiet) args.push_back("--quiet");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(nullptr);
  execv(argv[0], argv.data());
  throw std::runtime_error("cannot start /usr/bin/python3 " + script);
}

void add_common(CLI::App* cmd, Options& o) {
  cmd->add_option(
         "--level", o.level,
         "quick (CI), standard (default; FE at accurate meshes) or full (adds convergence studies)")
      ->check(CLI::IsMember({"quick", "standard", "full"}));
  cmd->add_option("--only", o.only,
                  "ECMAScript regex: only the ids it matches (mutate: mutation ids)");
}

void add_running(CLI::App* cmd, Options& o) {
  cmd->add_option("--jobs", o.jobs, "checks run in parallel [1, 64]")->check(CLI::Range(1, 64));
  cmd->add_option("--mpi", o.mpi, "run each FE reference under mpirun -np N [1, 64]")
      ->check(CLI::Range(1, 64));
  cmd->add_option("--fem", o.fem,
                  "the bearing-fem program (default: the one built beside this program)");
  cmd->add_flag("--quiet", o.quiet, "no progress lines on stderr");
}

}  // namespace

int main(int argc, char** argv) {
  gsl_set_error_handler_off();
  CLI::App app{
      "bearing-verify: the toolkit checked against closed forms, finite elements, "
      "conservation laws and the source papers; writes a report a reviewer can read"};
  app.require_subcommand(1);
  Options o;
  auto* list =
      app.add_subcommand("list", "every check: id, family, reference, level, cost, tolerance");
  add_common(list, o);
  bool list_mutations = false;
  list->add_flag("--mutations", list_mutations, "list the mutations instead of the checks");
  list->callback([&] { o.level = list->count("--level") ? o.level : "full"; });
  auto* run = app.add_subcommand("run",
                                 "run the checks; writes DIR/report.{html,md,json} and "
                                 "DIR/figures/; exit 0 all pass, 4 a check failed");
  add_common(run, o);
  add_running(run, o);
  run->add_option("--out", o.out, "report folder")->required();
  run->add_option("--plant", o.plant,
                  "plant one mutation (bearing-verify list --mutations) to see a caught bug: the "
                  "report says so on its first line");
  run->add_flag("--fail-fast", o.fail_fast,
                "run the cheapest checks first and stop at the first failure (exit 4); the "
                "report holds the checks that ran");
  auto* mutate = app.add_subcommand(
      "mutate",
      "plant each mutation, rerun the checks, report which caught it; exit 4 if one is not caught");
  add_common(mutate, o);
  add_running(mutate, o);
  mutate->add_option("--out", o.out, "report folder (default mutate-report)");
  mutate->add_flag("--source", o.source,
                   "code mutants: mutate the physics sources themselves, rebuild, run the quick "
                   "checks (--fail-fast); writes DIR/source_mutants.{json,md}; exit 4 when fewer "
                   "than 90 % of the non-equivalent mutants are killed");
  mutate
      ->add_option("--mutants", o.mutants,
                   "--source: how many code mutants of lumped/src/ (default 150) [64, 100000]")
      ->check(CLI::Range(64, 100000));
  mutate
      ->add_option("--fem-mutants", o.fem_mutants,
                   "--source: how many of fem/, judged in a build with deal.II (default 10; 0 "
                   "none) [0, 10000]")
      ->check(CLI::Range(0, 10000));
  mutate->add_option("--seed", o.seed, "--source: the seed of the draw (default 30)");
  CalibrateOptions co;
  auto* calibrate = add_calibrate_command(app, co);
  try {
    app.parse(argc, argv);
    if (o.out.empty()) o.out = "mutate-report";
    if (o.source && mutate->count("--level") == 0) o.level = "quick";
    if (*list) return list_mutations ? mutations_command() : list_command(o);
    if (*run) return run_command(o);
    if (*mutate) return o.source ? source_mutants_command(o) : mutate_command(o);
    if (*calibrate) return calibrate_command(co);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const bearing::InputError& e) {
    std::fprintf(stderr, "bearing-verify: %s\n", e.what());
    return 2;
  } catch (const bearing::SolverError& e) {
    std::fprintf(stderr, "bearing-verify: %s\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bearing-verify: internal error: %s\n", e.what());
    return 1;
  }
  return 0;
}
