#include "runner.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <thread>

namespace bearing::verify {

std::vector<const Check*> select_checks(const std::vector<Check>& all, Level level,
                                        const std::string& only) {
  const std::regex pattern(only.empty() ? std::string(".*") : only, std::regex::ECMAScript);
  std::vector<const Check*> out;
  for (const auto& c : all)
    if (static_cast<int>(c.level) <= static_cast<int>(level) && std::regex_search(c.id, pattern))
      out.push_back(&c);
  return out;
}

namespace {

double deviation(const Tolerance& t, double value, double reference) {
  if (t.kind == Tolerance::Kind::absolute) return std::abs(value - reference);
  if (reference == 0.0) return value == 0.0 ? 0.0 : INFINITY;
  return std::abs(value / reference - 1.0);
}

}  // namespace

CheckResult run_check(const Check& check, const Context& context) {
  CheckResult r;
  r.check = &check;
  const auto start = std::chrono::steady_clock::now();
  const KnobRecorder recorder;
  try {
    Outcome o = check.measure(context);
    r.value = o.value;
    r.reference = o.reference;
    r.detail = std::move(o.detail);
    r.figures = std::move(o.figures);
    r.deviation = deviation(check.tolerance, o.value, o.reference);
    // NaN fails: the comparison below is false for it.
    const bool within = std::isfinite(o.value) && std::isfinite(o.reference) &&
                        r.deviation <= check.tolerance.bound;
    r.status = !check.judged ? Status::reported : within ? Status::pass : Status::fail;
    if (!check.judged)
      r.verdict = "reported";
    else if (check.paper && within)
      r.verdict = check.paper->disagreement.empty() ? "agree"
                  : check.paper->explanation_tested ? "disagree-tested"
                                                    : "disagree-untested";
    else
      r.verdict = to_string(r.status);
  } catch (const Skipped& e) {
    r.status = Status::skipped;
    r.verdict = "skipped";
    r.detail = e.what();
  } catch (const std::exception& e) {
    r.status = Status::fail;
    r.verdict = "fail";
    r.detail = std::string("error: ") + e.what();
  }
  r.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.knobs = recorder.knobs();
  return r;
}

std::vector<CheckResult> run_checks(const std::vector<const Check*>& checks, const Context& context,
                                    int jobs,
                                    const std::function<void(const CheckResult&, int)>& progress,
                                    bool fail_fast) {
  std::vector<CheckResult> results(checks.size());
  std::vector<char> ran(checks.size(), 0);
  std::atomic<std::size_t> next{0};
  std::atomic<int> done{0};
  std::atomic<bool> failed{false};
  std::mutex report;
  auto worker = [&] {
    for (std::size_t i = next++; i < checks.size(); i = next++) {
      if (fail_fast && failed) break;
      results[i] = run_check(*checks[i], context);
      ran[i] = 1;
      if (results[i].status == Status::fail) failed = true;
      const int n = ++done;
      if (progress) {
        std::lock_guard<std::mutex> lock(report);
        progress(results[i], n);
      }
    }
  };
  std::vector<std::thread> threads;
  for (int t = 1; t < std::max(1, jobs); ++t) threads.emplace_back(worker);
  worker();
  for (auto& t : threads) t.join();
  if (!fail_fast) return results;
  std::vector<CheckResult> out;
  for (std::size_t i = 0; i < checks.size(); ++i)
    if (ran[i]) out.push_back(std::move(results[i]));
  return out;
}

std::vector<const Check*> cheapest_first(std::vector<const Check*> checks) {
  std::stable_sort(checks.begin(), checks.end(),
                   [](const Check* a, const Check* b) { return a->cost < b->cost; });
  return checks;
}

std::vector<MutationResult> run_mutations(
    const std::vector<const Mutation*>& mutations, const std::vector<CheckResult>& baseline,
    const std::function<Context(const Perturbation&)>& context_for, int jobs,
    const std::function<void(const MutationResult&)>& progress) {
  std::vector<MutationResult> out;
  for (const Mutation* m : mutations) {
    const auto start = std::chrono::steady_clock::now();
    // Only the passing checks that read a knob this mutation turns can change.
    std::vector<const Check*> affected;
    std::vector<std::string> untouched_claims;
    for (const auto& r : baseline) {
      if (r.status != Status::pass) continue;
      if (r.knobs & m->perturbation.changed())
        affected.push_back(r.check);
      else if (std::find(r.check->catches.begin(), r.check->catches.end(), m->id) !=
               r.check->catches.end())
        untouched_claims.push_back(r.check->id);
    }
    const Context context = context_for(m->perturbation);
    const auto results = run_checks(affected, context, jobs, {});
    MutationResult mr{m->id, m->description, {}, untouched_claims};
    mr.rerun = static_cast<int>(affected.size());
    for (const auto& r : results) {
      const auto& names = r.check->catches;
      const bool claimed = std::find(names.begin(), names.end(), m->id) != names.end();
      if (r.status == Status::fail)
        mr.caught_by.push_back(r.check->id);
      else if (claimed)
        mr.claimed_not_caught.push_back(r.check->id);
    }
    mr.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (progress) progress(mr);
    out.push_back(std::move(mr));
  }
  return out;
}

}  // namespace bearing::verify
