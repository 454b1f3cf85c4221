#pragma once
// What a verification run produced, and the writers of its report (report.json, report.md,
// report.html, figures/). The JSON schema is verification/report.schema.json.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "check.h"

namespace bearing::verify {

/// reported: a check that is measured and shown but not judged (Check::judged is false).
enum class Status { pass, fail, skipped, reported };

struct CheckResult {
  const Check* check = nullptr;
  Status status = Status::fail;
  double value = 0.0;
  double reference = 0.0;
  double deviation = 0.0;  ///< |value/reference − 1| (relative) or |value − reference| (absolute)
  std::string verdict;     ///< "pass", "fail", "skipped", "reported"; papers: "agree",
                           ///< "disagree-tested", "disagree-untested" (PaperValue)
  std::string detail;      ///< the check's detail, or the error / skip reason
  double wall_time = 0.0;  ///< [s]
  std::vector<Figure> figures;
  unsigned knobs = 0;  ///< the perturbation knobs the check read (perturbation.h)
};

/// What one mutation did: the checks that failed under it (that passed without it).
struct MutationResult {
  std::string id;
  std::string description;
  std::vector<std::string> caught_by;
  std::vector<std::string> claimed_not_caught;  ///< checks naming it that still passed
  int rerun = 0;  ///< checks rerun (those that read a knob it turns; the others cannot change)
  double wall_time = 0.0;
  bool caught() const { return !caught_by.empty(); }
};

/// Where and how the report was made.
struct RunInfo {
  std::string command;  ///< "run", "mutate" or "calibrate"
  std::string level;
  std::string commit;   ///< git describe, or "unversioned"
  std::string date;     ///< UTC, ISO 8601
  std::string machine;  ///< host, OS, cores
  std::string compiler;
  std::vector<std::pair<std::string, std::string>> libraries;  ///< name, version
  std::string only;                                            ///< the --only filter, empty if none
  std::string planted;  ///< run --plant: the mutation planted in this run ("" normally)
  int jobs = 1;
  int mpi_processes = 1;
  std::string fem_program;  ///< bearing-fem used, or "" (FE checks skipped)
  double wall_time = 0.0;   ///< [s]
};

struct Report {
  RunInfo info;
  std::vector<CheckResult> results;
  std::vector<MutationResult> mutations;  ///< mutate only
  bool has_mutations = false;
  int failed() const;
  int passed() const;
  int skipped() const;
  int reported() const;
  /// Passed checks whose tolerance is a regression pin (counted apart from passed()).
  int pinned() const;
};

/// Writes DIR/report.json, DIR/report.md, DIR/report.html and DIR/figures/ (PNG through
/// plot_figures.py and /usr/bin/python3's matplotlib when present; otherwise the report says so).
/// Each file is written to a temporary name and renamed, so a report is complete or absent.
void write_report(const Report& report, const std::string& dir, const std::string& plot_script);

/// Writes the figures' data to DIR/figures.json and draws DIR/NAME.png with plot_script
/// (/usr/bin/python3 and matplotlib; without them DIR/NO_FIGURES.txt says why).
void draw_figures(const std::vector<Figure>& figures, const std::string& dir,
                  const std::string& plot_script);
/// Writes each result figure's data to DIR/figures.json and draws them with plot_script.
void write_figures(const Report& report, const std::string& dir, const std::string& plot_script);

nlohmann::json report_json(const Report& report);
std::string report_markdown(const Report& report);
std::string report_html(const Report& report, const std::string& figures_dir);

const char* to_string(Status s);
const char* to_string(ReferenceKind k);
const char* to_string(Level l);

}  // namespace bearing::verify
