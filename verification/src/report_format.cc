#include "report_format.h"

#include <cmath>
#include <cstdio>

#include "families.h"

namespace bearing::verify {

std::string with_unit(double value, const std::string& unit) {
  if (!std::isfinite(value)) return "—";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", value);
  return unit == "-" ? std::string(buf) : std::string(buf) + " " + unit;
}

std::string tolerance_text(const Check& c) {
  char buf[64];
  if (c.tolerance.kind == Tolerance::Kind::relative)
    std::snprintf(buf, sizeof buf, "±%.3g %%", 100 * c.tolerance.bound);
  else
    std::snprintf(buf, sizeof buf, "±%.3g%s%s", c.tolerance.bound, c.unit == "-" ? "" : " ",
                  c.unit == "-" ? "" : c.unit.c_str());
  return buf;
}

std::string deviation_text(const CheckResult& r) {
  if (r.status == Status::skipped || !std::isfinite(r.deviation)) return "—";
  char buf[64];
  if (r.check->tolerance.kind == Tolerance::Kind::relative)
    std::snprintf(buf, sizeof buf, "%.3g %%", 100 * r.deviation);
  else
    std::snprintf(buf, sizeof buf, "%.3g%s%s", r.deviation, r.check->unit == "-" ? "" : " ",
                  r.check->unit == "-" ? "" : r.check->unit.c_str());
  return buf;
}

std::string verdict_text(const Report& r) {
  const std::string n = std::to_string(r.results.size());
  if (r.failed() > 0) return std::to_string(r.failed()) + " of " + n + " checks FAILED.";
  const std::string apart =
      (r.pinned() > 0 ? ", " + std::to_string(r.pinned()) + " regression pins held" : "") +
      (r.reported() > 0 ? ", " + std::to_string(r.reported()) + " reported without a verdict"
                        : std::string());
  if (r.skipped() > 0)
    return "No check failed: " + std::to_string(r.passed()) + " passed" + apart + ", " +
           std::to_string(r.skipped()) + " skipped (each skipped row says why).";
  if (!apart.empty())
    return "No check failed: " + std::to_string(r.passed()) + " passed" + apart + ".";
  return "Every check passed (" + n + " checks).";
}

PaperVerdicts paper_verdicts(const Report& r) {
  PaperVerdicts v;
  for (const auto& c : r.results) {
    if (c.verdict == "agree") ++v.agree;
    if (c.verdict == "disagree-tested") ++v.disagree_tested;
    if (c.verdict == "disagree-untested") ++v.disagree_untested;
  }
  return v;
}

std::string paper_verdicts_text(const Report& r) {
  const PaperVerdicts v = paper_verdicts(r);
  return "Source papers: " + std::to_string(v.agree) + " agree, " +
         std::to_string(v.disagree_tested) + " disagree (explained and tested), " +
         std::to_string(v.disagree_untested) + " disagree (explanation not tested).";
}

std::string level_text(const RunInfo& info) {
  if (info.only.empty()) return info.level;
  return info.level + (info.command == "mutate" ? " (mutations matching " : " (checks matching ") +
         info.only + ")";
}

std::string seconds_text(double s) {
  char buf[32];
  if (s < 1.0)
    std::snprintf(buf, sizeof buf, "%.0f ms", 1000 * s);
  else
    std::snprintf(buf, sizeof buf, "%.1f s", s);
  return buf;
}

std::vector<FamilyCount> family_counts(const Report& report) {
  std::vector<FamilyCount> out;
  for (const auto& f : kFamilies) {
    FamilyCount c{f.id, f.title};
    for (const auto& r : report.results) {
      if (r.check->family != f.id) continue;
      const bool pinned = r.check->tolerance.basis == Tolerance::Basis::pin;
      (r.status == Status::pass       ? (pinned ? c.pinned : c.passed)
       : r.status == Status::fail     ? c.failed
       : r.status == Status::reported ? c.reported
                                      : c.skipped)++;
    }
    out.push_back(c);
  }
  return out;
}

int mutations_caught(const Report& report) {
  int n = 0;
  for (const auto& m : report.mutations) n += m.caught() ? 1 : 0;
  return n;
}

}  // namespace bearing::verify
