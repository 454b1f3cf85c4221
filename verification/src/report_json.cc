#include <cmath>

#include "families.h"
#include "mutations.h"
#include "report_format.h"

namespace bearing::verify {

namespace {

// A number, or null for NaN/inf (JSON has none; the verdict says why).
nlohmann::json number(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json();
}

nlohmann::json check_json(const CheckResult& r) {
  const Check& c = *r.check;
  nlohmann::json j = {
      {"id", c.id},
      {"family", c.family},
      {"reference_kind", to_string(c.reference)},
      {"compares", c.compares},
      {"quantity", c.quantity},
      {"unit", c.unit},
      {"value", number(r.value)},
      {"reference", number(r.reference)},
      {"deviation", number(r.deviation)},
      {"tolerance",
       {{"kind", c.tolerance.kind == Tolerance::Kind::relative ? "relative" : "absolute"},
        {"bound", c.tolerance.bound},
        {"why", c.tolerance.why},
        {"basis", c.tolerance.basis == Tolerance::Basis::pin ? "pin" : "derived"}}},
      {"status", to_string(r.status)},
      {"verdict", r.verdict},
      {"detail", r.detail},
      {"level", to_string(c.level)},
      {"wall_time", r.wall_time},
      {"catches", c.catches},
  };
  nlohmann::json figures = nlohmann::json::array();
  for (const auto& f : r.figures) figures.push_back("figures/" + f.name + ".png");
  j["figures"] = figures;
  if (c.paper)
    j["paper"] = {{"value", c.paper->value},
                  {"source", c.paper->source},
                  {"disagreement", c.paper->disagreement}};
  return j;
}

}  // namespace

nlohmann::json report_json(const Report& report) {
  const RunInfo& i = report.info;
  nlohmann::json libraries = nlohmann::json::object();
  for (const auto& [name, version] : i.libraries) libraries[name] = version;
  nlohmann::json j = {
      {"format", "bearing-verify report 1"},
      {"run",
       {{"command", i.command},
        {"level", i.level},
        {"commit", i.commit},
        {"date", i.date},
        {"machine", i.machine},
        {"compiler", i.compiler},
        {"libraries", libraries},
        {"only", i.only},
        {"planted", i.planted},
        {"jobs", i.jobs},
        {"mpi_processes", i.mpi_processes},
        {"fem_program", i.fem_program},
        {"wall_time", i.wall_time}}},
  };
  nlohmann::json summary = nlohmann::json::array();
  for (const auto& f : kFamilies) {
    int pass = 0, fail = 0, skip = 0, reported = 0, pinned = 0;
    for (const auto& r : report.results) {
      if (r.check->family != f.id) continue;
      const bool pin = r.check->tolerance.basis == Tolerance::Basis::pin;
      (r.status == Status::pass       ? (pin ? pinned : pass)
       : r.status == Status::fail     ? fail
       : r.status == Status::reported ? reported
                                      : skip)++;
    }
    summary.push_back({{"family", f.id},
                       {"title", f.title},
                       {"passed", pass},
                       {"failed", fail},
                       {"skipped", skip},
                       {"reported", reported},
                       {"pinned", pinned}});
  }
  j["summary"] = summary;
  const PaperVerdicts pv = paper_verdicts(report);
  j["paper_verdicts"] = {{"agree", pv.agree},
                         {"disagree_tested", pv.disagree_tested},
                         {"disagree_untested", pv.disagree_untested}};
  j["totals"] = {{"checks", report.results.size()}, {"passed", report.passed()},
                 {"failed", report.failed()},       {"skipped", report.skipped()},
                 {"reported", report.reported()},   {"pinned", report.pinned()}};
  nlohmann::json checks = nlohmann::json::array();
  for (const auto& r : report.results) checks.push_back(check_json(r));
  j["checks"] = checks;
  if (report.has_mutations) {
    nlohmann::json ms = nlohmann::json::array();
    for (const auto& m : report.mutations) {
      ms.push_back({{"id", m.id},
                    {"description", m.description},
                    {"caught", m.caught()},
                    {"caught_by", m.caught_by},
                    {"claimed_not_caught", m.claimed_not_caught},
                    {"checks_rerun", m.rerun},
                    {"wall_time", m.wall_time}});
    }
    j["mutations"] = ms;
    j["mutation_score"] = {{"caught", mutations_caught(report)},
                           {"total", report.mutations.size()}};
  }
  return j;
}

}  // namespace bearing::verify
