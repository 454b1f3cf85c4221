#pragma once
// Number and text formatting shared by the Markdown and HTML reports (one place for each rule).

#include <string>

#include "report.h"

namespace bearing::verify {

/// A value with its unit, 6 significant digits ("3.5067e+10 N/m^1.5"); "—" for NaN/inf.
std::string with_unit(double value, const std::string& unit);
/// The tolerance as a reader sees it: "±0.5 %" or "±0.01 dB".
std::string tolerance_text(const Check& c);
/// The deviation in the tolerance's terms: "0.12 %" or "0.003 dB".
std::string deviation_text(const CheckResult& r);
/// The one-line verdict at the top of a report.
std::string verdict_text(const Report& report);
/// The level and the --only filter as the title page shows them.
std::string level_text(const RunInfo& info);
/// "1.2 s", "85 ms".
std::string seconds_text(double s);
/// Passed/total per family and in all.
/// The paper checks' verdicts, counted apart: a disagreement whose explanation no comparison tests
/// is a claim, not a verification.
struct PaperVerdicts {
  int agree = 0, disagree_tested = 0, disagree_untested = 0;
};
PaperVerdicts paper_verdicts(const Report& report);
/// "Source papers: 2 agree, 5 disagree (explained and tested), 4 disagree (explanation not
/// tested)."
std::string paper_verdicts_text(const Report& report);

struct FamilyCount {
  std::string id, title;
  int passed = 0, failed = 0, skipped = 0, reported = 0, pinned = 0;
};
std::vector<FamilyCount> family_counts(const Report& report);
/// Mutations caught / total.
int mutations_caught(const Report& report);

}  // namespace bearing::verify
