// bearing-verify's own machinery: the check table's rules, the judging of a check, the report's
// red rows, and the mutation runner's bookkeeping. (The checks themselves are judged by running
// them: ctest verify.quick and verify.mutate_quick.)
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "families.h"
#include "mutations.h"
#include "report.h"
#include "runner.h"

namespace bearing::verify {
namespace {

Check synthetic(std::function<Outcome(const Context&)> measure, Tolerance t) {
  Check c;
  c.id = "test.synthetic";
  c.family = "hertz";
  c.compares = "value: a number; reference: another";
  c.unit = "m";
  c.tolerance = std::move(t);
  c.catches = {"sound-speed-x1.02"};
  c.measure = std::move(measure);
  return c;
}

Context plain() {
  return Context(Level::quick, {}, nullptr, BEARING_SOURCE_DIR);
}

TEST(CheckTable, IsWellFormedAndCoversEveryFamilyAndMutation) {
  const auto all = all_checks();  // throws on a duplicate id, unknown mutation, no justification
  std::set<std::string> families, named;
  for (const auto& c : all) {
    families.insert(c.family);
    named.insert(c.catches.begin(), c.catches.end());
  }
  for (const auto& f : kFamilies) EXPECT_TRUE(families.count(f.id)) << "no check in " << f.id;
  for (const auto& m : mutations()) EXPECT_TRUE(named.count(m.id)) << "no check names " << m.id;
}

TEST(CheckTable, AToleranceTakenFromTheErrorItJudgesIsOnlyAPin) {
  // The phrasings the FE rows used before they became pins; a derived bound merely rounded up
  // is not one of them.
  for (const char* why : {"the FE K at this mesh is +1.14 % off Hertz, rounded up to 1.5 %",
                          "fem/README.md's measured largest |FE - exact| error: 8.98e-8 dB, "
                          "rounded up to one significant digit",
                          "the block's error at level 1, measured +0.80 %; rounded up to 1.2 %"}) {
    EXPECT_TRUE(judged_by_its_own_error(why)) << why;
    const Check derived = synthetic(
        [](const Context&) {
          return Outcome{1, 1};
        },
        relative(0.015, why));
    EXPECT_THROW(validate_checks({derived}), std::logic_error) << why;
    Check pinned = derived;
    pinned.tolerance = pin(pinned.tolerance);
    EXPECT_NO_THROW(validate_checks({pinned})) << why;
    EXPECT_EQ(pinned.tolerance.why.rfind("regression pin: ", 0), 0u);
  }
  EXPECT_FALSE(judged_by_its_own_error("<= 1e-8 dB on a difference, rounded up to 1e-7 dB"));
  // Every row of the real table: a derived bound never reads as the judged error.
  for (const auto& c : all_checks())
    if (c.tolerance.basis == Tolerance::Basis::derived)
      EXPECT_FALSE(judged_by_its_own_error(c.tolerance.why)) << c.id;
}

TEST(Report, PinsAndReportedRowsAreCountedApart) {
  Report report;
  Check pinned = synthetic([](const Context&) { return Outcome{1, 1}; }, pin(relative(0.1, "t")));
  Check derived = synthetic([](const Context&) { return Outcome{1, 1}; }, relative(0.1, "t"));
  Check reported = derived;
  reported.judged = false;
  for (const Check* c : {&pinned, &derived, &reported})
    report.results.push_back(run_check(*c, plain()));
  EXPECT_EQ(report.passed(), 1);
  EXPECT_EQ(report.pinned(), 1);
  EXPECT_EQ(report.reported(), 1);
  EXPECT_EQ(report.results[2].status, Status::reported);
}

TEST(CheckTable, QuickLevelHasAtLeastSixtyChecks) {
  const auto all = all_checks();
  EXPECT_GE(select_checks(all, Level::quick, "").size(), 60u);
  EXPECT_LE(select_checks(all, Level::quick, "").size(),
            select_checks(all, Level::full, "").size());
}

TEST(RunCheck, JudgesRelativeAndAbsoluteTolerances) {
  const Check rel = synthetic(
      [](const Context&) {
        return Outcome{1.004, 1.0};
      },
      relative(0.005, "test"));
  EXPECT_EQ(run_check(rel, plain()).status, Status::pass);
  EXPECT_NEAR(run_check(rel, plain()).deviation, 0.004, 1e-12);
  const Check abs = synthetic(
      [](const Context&) {
        return Outcome{2.0, 1.0};
      },
      absolute(0.5, "test"));
  const CheckResult r = run_check(abs, plain());
  EXPECT_EQ(r.status, Status::fail);
  EXPECT_EQ(r.verdict, "fail");
}

TEST(RunCheck, NaNAndErrorsFailAndSkipsAreSkips) {
  const Check nan = synthetic([](const Context&) { return Outcome{NAN, 1.0}; }, relative(1, "t"));
  EXPECT_EQ(run_check(nan, plain()).status, Status::fail);
  const Check error = synthetic([](const Context&) -> Outcome { throw std::runtime_error("boom"); },
                                relative(1, "t"));
  const CheckResult e = run_check(error, plain());
  EXPECT_EQ(e.status, Status::fail);
  EXPECT_NE(e.detail.find("boom"), std::string::npos);
  const Check skip =
      synthetic([](const Context&) -> Outcome { throw Skipped("no FE"); }, relative(1, "t"));
  EXPECT_EQ(run_check(skip, plain()).status, Status::skipped);
}

TEST(RunCheck, PaperVerdictsSayAgreeOrDisagreeTestedOrNot) {
  Check c = synthetic([](const Context&) { return Outcome{10.0, 10.0}; }, absolute(0.1, "t"));
  c.paper = PaperValue{10.0, "seed", ""};
  EXPECT_EQ(run_check(c, plain()).verdict, "agree");
  c.paper = PaperValue{20.0, "seed", "the paper halves it"};
  EXPECT_EQ(run_check(c, plain()).verdict, "disagree-untested");
  c.paper->explanation_tested = true;
  EXPECT_EQ(run_check(c, plain()).verdict, "disagree-tested");
  c.measure = [](const Context&) { return Outcome{20.0, 10.0}; };  // ours took the paper's value
  EXPECT_EQ(run_check(c, plain()).verdict, "fail");
}

TEST(Report, AFailedCheckIsARedRowAndTheBannerSaysSo) {
  const Check c = synthetic([](const Context&) { return Outcome{2.0, 1.0}; }, relative(0.01, "t"));
  Report report;
  report.info.commit = "test";
  report.results.push_back(run_check(c, plain()));
  const std::string html = report_html(report, "/nonexistent");
  EXPECT_NE(html.find("<tr class=\"fail\" id=\"test.synthetic\">"), std::string::npos);
  EXPECT_NE(html.find("1 of 1 checks FAILED."), std::string::npos);
  EXPECT_NE(report_markdown(report).find("**FAIL**"), std::string::npos);
  EXPECT_NE(report_markdown(report).find("1 of 1 checks FAILED."), std::string::npos);
  EXPECT_EQ(report_json(report)["totals"]["failed"], 1);
}

TEST(Mutations, OnlyChecksThatReadATurnedKnobAreRerunAndCaught) {
  int runs = 0;
  // Reads the air: the sound-speed mutation changes it, the mass mutation cannot.
  const Check c = synthetic(
      [&runs](const Context& ctx) {
        ++runs;
        return Outcome{ctx.air().sound_speed, 343.2};
      },
      relative(1e-9, "t"));
  const std::vector<const Check*> checks = {&c};
  const auto baseline = run_checks(checks, plain(), 1, {});
  ASSERT_EQ(baseline[0].status, Status::pass);
  const std::vector<const Mutation*> ms = {find_mutation("sound-speed-x1.02"),
                                           find_mutation("mass-x1.05")};
  const auto results = run_mutations(
      ms, baseline,
      [](const Perturbation& p) { return Context(Level::quick, p, nullptr, BEARING_SOURCE_DIR); },
      1, {});
  EXPECT_EQ(runs, 2);  // baseline + sound speed; the mass mutation did not rerun it
  EXPECT_EQ(results[0].caught_by, std::vector<std::string>{"test.synthetic"});
  EXPECT_FALSE(results[1].caught());
  EXPECT_EQ(results[1].rerun, 0);
}

TEST(RunChecks, FailFastRunsCheapestFirstAndStopsAtTheFirstFailure) {
  std::vector<int> order;  // which checks ran, in order (jobs = 1)
  auto make = [&order](int n, double cost, double value) {
    Check c = synthetic(
        [&order, n, value](const Context&) {
          order.push_back(n);
          return Outcome{value, 1.0};
        },
        relative(1e-9, "t"));
    c.id = "test.c" + std::to_string(n);
    c.cost = cost;
    return c;
  };
  const Check expensive = make(0, 9.0, 1.0), failing = make(1, 0.5, 2.0), cheap = make(2, 0.1, 1.0);
  const auto sorted = cheapest_first({&expensive, &failing, &cheap});
  ASSERT_EQ(sorted.size(), 3u);
  EXPECT_EQ(sorted[0], &cheap);
  EXPECT_EQ(sorted[2], &expensive);
  const auto fast = run_checks(sorted, plain(), 1, {}, true);
  EXPECT_EQ(order, (std::vector<int>{2, 1}));  // the expensive check never started
  ASSERT_EQ(fast.size(), 2u);
  EXPECT_EQ(fast[1].status, Status::fail);
  order.clear();
  const auto all = run_checks(sorted, plain(), 1, {});  // without fail-fast every check runs
  EXPECT_EQ(all.size(), 3u);
  EXPECT_EQ(order.size(), 3u);
}

}  // namespace
}  // namespace bearing::verify
