// report.html: one self-contained page (figures embedded as data: URIs, no script, no network),
// readable on a phone (tables scroll sideways inside their box, figures shrink to the width).
#include <sstream>

#include "families.h"
#include "html.h"
#include "report_format.h"

namespace bearing::verify {

namespace {

void title_page(std::ostringstream& h, const Report& report) {
  const RunInfo& i = report.info;
  h << "<h1>bearing-verify: verification report</h1>\n";
  if (!i.planted.empty())
    h << "<p class=\"banner planted\">Planted mutation: " << escape_html(i.planted)
      << " — this run was deliberately broken to show what a caught bug looks like.</p>\n";
  h << "<p class=\"banner "
    << (report.failed()    ? "bad"
        : report.skipped() ? "planted"
                           : "ok")
    << "\">" << escape_html(verdict_text(report)) << "</p>\n";
  h << "<div class=\"scroll\"><table><tbody>\n";
  auto row = [&](const std::string& k, const std::string& v) {
    h << "<tr><th>" << escape_html(k) << "</th><td>" << escape_html(v) << "</td></tr>\n";
  };
  row("commit", i.commit);
  row("date (UTC)", i.date);
  row("level", level_text(i));
  row("machine", i.machine);
  row("compiler", i.compiler);
  for (const auto& [name, version] : i.libraries) row(name, version);
  row("FE program",
      i.fem_program.empty()
          ? "not built: FE checks skipped"
          : i.fem_program + " (MPI processes per FE run: " + std::to_string(i.mpi_processes) + ")");
  row("wall time", seconds_text(i.wall_time) + " (" + std::to_string(i.jobs) + " jobs)");
  h << "</tbody></table></div>\n";
}

void summary(std::ostringstream& h, const Report& report) {
  h << "<h2>Summary</h2><div class=\"scroll\"><table><thead><tr><th>family</th><th>passed</th>"
       "<th>pinned (regression pins held)</th><th>failed</th><th>skipped</th><th>reported, not "
       "judged</th></tr></thead><tbody>\n";
  for (const auto& f : family_counts(report))
    h << "<tr" << (f.failed ? " class=\"fail\"" : "") << "><td>" << escape_html(f.title)
      << "</td><td class=\"num\">" << f.passed << "</td><td class=\"num\">" << f.pinned
      << "</td><td class=\"num\">" << f.failed << "</td><td class=\"num\">" << f.skipped
      << "</td><td class=\"num\">" << f.reported << "</td></tr>\n";
  h << "<tr><th>all</th><th>" << report.passed() << "</th><th>" << report.pinned() << "</th><th>"
    << report.failed() << "</th><th>" << report.skipped() << "</th><th>" << report.reported()
    << "</th></tr></tbody></table></div>\n"
    << "<p>" << escape_html(paper_verdicts_text(report)) << "</p>\n";
}

void mutations(std::ostringstream& h, const Report& report) {
  if (!report.has_mutations) return;
  const int caught = mutations_caught(report);
  h << "<h2 id=\"mutations\">Mutation score: " << caught << " / " << report.mutations.size()
    << "</h2>\n<p>Each mutation plants one deliberate bug in the toolkit's values; a check catches "
       "it when it passes without the bug and fails with it.</p>\n"
    << "<div class=\"scroll\"><table><thead><tr><th>mutation</th><th>bug</th><th>caught by</th>"
       "<th>time</th></tr></thead><tbody>\n";
  for (const auto& m : report.mutations) {
    std::string by;
    for (const auto& id : m.caught_by) by += (by.empty() ? "" : ", ") + id;
    h << "<tr class=\"" << (m.caught() ? "pass" : "fail") << "\"><td><code>" << escape_html(m.id)
      << "</code></td><td>" << escape_html(m.description) << "</td><td class=\"why\">"
      << (m.caught() ? std::to_string(m.caught_by.size()) + ": " + escape_html(by)
                     : std::string("<b>NOT CAUGHT — a gap in the verification</b>"))
      << "</td><td class=\"num\">" << seconds_text(m.wall_time) << "</td></tr>\n";
  }
  h << "</tbody></table></div>\n";
}

void check_row(std::ostringstream& h, const CheckResult& r) {
  const Check& c = *r.check;
  const char* cls = to_string(r.status);
  h << "<tr class=\"" << cls << "\" id=\"" << escape_html(c.id) << "\"><td><code>"
    << escape_html(c.id) << "</code></td><td>" << to_string(c.reference)
    << "</td><td class=\"num\">" << escape_html(with_unit(r.value, c.unit))
    << "</td><td class=\"num\">" << escape_html(with_unit(r.reference, c.unit))
    << "</td><td class=\"num\">" << escape_html(deviation_text(r)) << "</td><td class=\"num\">"
    << escape_html(tolerance_text(c)) << "</td><td class=\"verdict\">"
    << escape_html(r.status == Status::fail ? "FAIL" : r.verdict) << "</td><td class=\"num\">"
    << seconds_text(r.wall_time) << "</td></tr>\n";
  h << "<tr class=\"" << cls << "\"><td colspan=\"8\" class=\"why\">" << escape_html(c.compares)
    << ".<br>Tolerance: " << escape_html(c.tolerance.why) << ".";
  if (c.paper)
    h << "<br>Paper (" << escape_html(c.paper->source)
      << "): " << escape_html(with_unit(c.paper->value, c.unit)) << "."
      << (c.paper->disagreement.empty() ? ""
                                        : " Disagreement: " + escape_html(c.paper->disagreement));
  if (!r.detail.empty()) h << "<br>" << escape_html(r.detail);
  h << "</td></tr>\n";
}

void family(std::ostringstream& h, const Report& report, const Family& f,
            const std::string& figures_dir) {
  bool any = false;
  for (const auto& r : report.results) any = any || r.check->family == f.id;
  if (!any) return;
  h << "<h2 id=\"" << f.id << "\">" << escape_html(f.title)
    << "</h2>\n<div class=\"scroll\"><table>"
    << "<thead><tr><th>check</th><th>reference</th><th>value</th><th>reference value</th>"
       "<th>deviation</th><th>tolerance</th><th>verdict</th><th>time</th></tr></thead><tbody>\n";
  for (const auto& r : report.results)
    if (r.check->family == f.id) check_row(h, r);
  h << "</tbody></table></div>\n";
  for (const auto& r : report.results)
    if (r.check->family == f.id)
      for (const auto& fig : r.figures) h << figure_html(fig, figures_dir) << "\n";
}

}  // namespace

std::string report_html(const Report& report, const std::string& figures_dir) {
  std::ostringstream h;
  h << html_head("bearing-verify report — " + report.info.commit);
  title_page(h, report);
  summary(h, report);
  mutations(h, report);
  for (const auto& f : kFamilies) family(h, report, f, figures_dir);
  h << "</body></html>\n";
  return h.str();
}

}  // namespace bearing::verify
