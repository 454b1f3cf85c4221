// report.md: the same content as report.html, for a diff or a terminal.
#include <sstream>

#include "families.h"
#include "report_format.h"

namespace bearing::verify {

namespace {

// A table cell: no '|' or newline inside.
std::string cell(std::string s) {
  for (auto& c : s)
    if (c == '|' || c == '\n') c = c == '|' ? '/' : ' ';
  return s;
}

void title_page(std::ostringstream& md, const Report& report) {
  const RunInfo& i = report.info;
  md << "# bearing-verify: verification report\n\n";
  md << "| | |\n|---|---|\n";
  md << "| commit | " << cell(i.commit) << " |\n| date (UTC) | " << i.date << " |\n";
  md << "| level | " << cell(level_text(i)) << " |\n";
  if (!i.planted.empty())
    md << "| **planted mutation** | **" << i.planted << "** (a deliberately broken run) |\n";
  md << "| machine | " << cell(i.machine) << " |\n| compiler | " << cell(i.compiler) << " |\n";
  for (const auto& [name, version] : i.libraries)
    md << "| " << name << " | " << cell(version) << " |\n";
  md << "| FE program | "
     << (i.fem_program.empty() ? "not built: FE checks skipped" : i.fem_program)
     << " (MPI processes per FE run: " << i.mpi_processes << ") |\n";
  md << "| wall time | " << seconds_text(i.wall_time) << " (" << i.jobs << " jobs) |\n\n";
}

void summary(std::ostringstream& md, const Report& report) {
  md << "## Summary\n\n| family | passed | pinned (regression pins held) | failed | skipped | "
        "reported, not judged |\n|---|---|---|---|---|---|\n";
  for (const auto& f : family_counts(report))
    md << "| " << f.title << " | " << f.passed << " | " << f.pinned << " | " << f.failed << " | "
       << f.skipped << " | " << f.reported << " |\n";
  md << "| **all** | **" << report.passed() << "** | **" << report.pinned() << "** | **"
     << report.failed() << "** | **" << report.skipped() << "** | **" << report.reported()
     << "** |\n\n";
  md << "**Verdict: " << verdict_text(report) << "**\n\n" << paper_verdicts_text(report) << "\n\n";
}

void mutations(std::ostringstream& md, const Report& report) {
  if (!report.has_mutations) return;
  md << "## Mutation score: " << mutations_caught(report) << " / " << report.mutations.size()
     << "\n\nEach mutation plants one deliberate bug; a check catches it when it passes without "
        "the "
        "bug and fails with it.\n\n| mutation | bug | caught by | wall time |\n|---|---|---|---|\n";
  for (const auto& m : report.mutations) {
    std::string by;
    for (const auto& id : m.caught_by) by += (by.empty() ? "" : ", ") + id;
    md << "| " << m.id << " | " << cell(m.description) << " | "
       << (m.caught() ? std::to_string(m.caught_by.size()) + ": " + by : "**NOT CAUGHT (a gap)**")
       << " | " << seconds_text(m.wall_time) << " |\n";
  }
  md << "\n";
}

void family(std::ostringstream& md, const Report& report, const Family& f) {
  bool any = false;
  for (const auto& r : report.results) any = any || r.check->family == f.id;
  if (!any) return;
  md << "## " << f.title << "\n\n"
     << "| check | reference | value | reference value | deviation | tolerance | verdict | time |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : report.results) {
    const Check& c = *r.check;
    if (c.family != f.id) continue;
    const bool bad = r.status == Status::fail;
    md << "| " << (bad ? "**" + c.id + "**" : c.id) << " | " << to_string(c.reference) << " | "
       << with_unit(r.value, c.unit) << " | " << with_unit(r.reference, c.unit) << " | "
       << deviation_text(r) << " | " << tolerance_text(c) << " | " << (bad ? "**FAIL**" : r.verdict)
       << " | " << seconds_text(r.wall_time) << " |\n";
  }
  md << "\n";
  for (const auto& r : report.results) {
    const Check& c = *r.check;
    if (c.family != f.id) continue;
    md << "- `" << c.id << "`: " << c.compares << ". Tolerance: " << c.tolerance.why << ".";
    if (c.paper)
      md << " Paper (" << c.paper->source << "): " << with_unit(c.paper->value, c.unit) << "."
         << (c.paper->disagreement.empty() ? "" : " Disagreement: " + c.paper->disagreement);
    if (!r.detail.empty()) md << " " << r.detail;
    for (const auto& fig : r.figures)
      md << "\n  ![" << fig.title << "](figures/" << fig.name << ".png)";
    md << "\n";
  }
  md << "\n";
}

}  // namespace

std::string report_markdown(const Report& report) {
  std::ostringstream md;
  title_page(md, report);
  summary(md, report);
  mutations(md, report);
  for (const auto& f : kFamilies) family(md, report, f);
  return md.str();
}

}  // namespace bearing::verify
