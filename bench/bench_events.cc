// Issue 18, target 3: event-located contacts (rk8pd-events) against RK4 5 us on the default case.
//
//   bearing_bench_events [rtol ...]
//
// The default case as `bearing-sim run` solves it (6308 2-DOF, 2000 rpm, 20 N, 1.2 s, 0.2 s
// transient, 20 kHz output); the figure is the RMS of ay over the post-transient window, the cost
// IntegrationStats::force_evaluations (the 24 001 output evaluations included, as in
// summary.json) and the wall time of simulate() (integration and the response record; no files).
//
// 1. RK4 5 us, the reference. 2. rk8pd-events (and rk8pd) over rtol in half decades, the loosest
// rtol from which every tighter one reaches 1e-4, refined by bisection in log(rtol). 3. Wall time
// of RK4 and of each method at that rtol in interleaved rounds (minimum over the rounds). 4. The
// floor: output evaluations + events x evaluations per event + steps between events.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <gsl/gsl_errno.h>

#include "bearing/case_file.h"
#include "bearing/signal/statistics.h"
#include "bearing/simulation.h"
#include "bearing/solvers/integrator.h"

namespace {

using bearing::Override;

struct Outcome {
  bool ok = false;
  std::string error;
  double rms = 0, ms = 0;
  bearing::IntegrationStats stats;
};

std::string text(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", value);
  return buf;
}

Outcome run(const std::string& method, double rtol) {
  Outcome o;
  try {
    std::vector<Override> overrides{{"solver.method", method}};
    if (rtol > 0) overrides.push_back({"solver.tolerance", text(rtol)});
    const bearing::Case c = bearing::default_case(overrides);
    const auto start = std::chrono::steady_clock::now();
    const bearing::SimulationResult r = bearing::simulate(c);
    o.ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    o.rms = bearing::channel_statistics(r.response.steady("ay")).rms;
    o.stats = r.stats;
    o.ok = true;
  } catch (const std::exception& e) {
    o.error = e.what();
  }
  return o;
}

constexpr double kTarget = 1e-4;

void line(const std::string& method, double rtol, const Outcome& o, const Outcome& ref) {
  if (!o.ok) {
    std::printf("%-13s %10s  failed: %s\n", method.c_str(), text(rtol).c_str(), o.error.c_str());
    return;
  }
  const double err = std::abs(o.rms / ref.rms - 1);
  const auto& s = o.stats;
  std::printf("%-13s %10s %10.3e %8ld %7.2f %6ld %6ld %6ld %7.1f%s\n", method.c_str(),
              text(rtol).c_str(), err, s.force_evaluations,
              double(ref.stats.force_evaluations) / double(s.force_evaluations), s.steps,
              s.rejected_steps, s.events, o.ms, err <= kTarget ? "  accurate" : "");
}

// The loosest rtol from which every tighter one in the scan reaches kTarget, refined by
// bisection in log(rtol); returns 0 when none does.
double loosest(const std::string& method, const Outcome& ref, const std::vector<double>& rtols) {
  const auto passes = [&](const Outcome& o) {
    return o.ok && std::abs(o.rms / ref.rms - 1) <= kTarget;
  };
  std::vector<Outcome> outs;
  for (const double rtol : rtols) {
    outs.push_back(run(method, rtol));
    line(method, rtol, outs.back(), ref);
  }
  std::size_t first = rtols.size();
  while (first > 0 && passes(outs[first - 1])) --first;
  if (first == rtols.size()) return 0.0;
  double good = rtols[first];
  if (first > 0) {
    double bad = rtols[first - 1];
    for (int i = 0; i < 5; ++i) {
      const double mid = std::sqrt(good * bad);
      const Outcome o = run(method, mid);
      line(method, mid, o, ref);
      (passes(o) ? good : bad) = mid;
    }
  }
  return good;
}

}  // namespace

int main(int argc, char** argv) {
  gsl_set_error_handler_off();
  const Outcome ref = run("rk4", 0.0);
  if (!ref.ok) {
    std::printf("RK4 failed: %s\n", ref.error.c_str());
    return 1;
  }
  std::printf("RK4 dt = 5 us: rms(ay) = %.10e m/s^2, %ld evals, %ld steps\n\n", ref.rms,
              ref.stats.force_evaluations, ref.stats.steps);
  std::printf("%-13s %10s %10s %8s %7s %6s %6s %6s %7s\n", "method", "rtol", "rel.err", "evals",
              "RK4/ev", "steps", "rej.", "events", "ms");
  std::vector<double> rtols;
  for (int i = 1; i < argc; ++i) rtols.push_back(std::atof(argv[i]));
  if (!rtols.empty()) {
    for (const double rtol : rtols) line("rk8pd-events", rtol, run("rk8pd-events", rtol), ref);
    return 0;
  }
  for (int k = 2; k <= 20; ++k) rtols.push_back(std::pow(10.0, -k / 2.0));
  struct Pick {
    std::string method;
    double rtol;
  };
  std::vector<Pick> picks;
  for (const std::string method : {"rk8pd-events", "rk8pd"}) {
    const double rtol = loosest(method, ref, rtols);
    std::printf("%-13s loosest rtol reaching %.0e: %s\n\n", method.c_str(), kTarget,
                rtol > 0 ? text(rtol).c_str() : "none");
    if (rtol > 0) picks.push_back({method, rtol});
  }

  // Wall time in interleaved rounds: RK4, then each pick, per round; the minimum of each.
  constexpr int kRounds = 9;
  std::vector<double> best(picks.size() + 1, 1e300);
  std::vector<Outcome> last(picks.size() + 1);
  for (int round = 0; round < kRounds; ++round) {
    for (std::size_t i = 0; i <= picks.size(); ++i) {
      last[i] = i == 0 ? run("rk4", 0.0) : run(picks[i - 1].method, picks[i - 1].rtol);
      best[i] = std::min(best[i], last[i].ms);
    }
  }
  std::printf("wall time of simulate(), min of %d interleaved rounds:\n", kRounds);
  std::printf("%-13s %10s %10s %8s %9s %9s %9s\n", "method", "rtol", "rel.err", "evals",
              "RK4/evals", "ms", "RK4/ms");
  for (std::size_t i = 0; i <= picks.size(); ++i) {
    const Outcome& o = last[i];
    std::printf("%-13s %10s %10.3e %8ld %9.2f %9.2f %9.2f\n",
                i == 0 ? "rk4" : picks[i - 1].method.c_str(),
                i == 0 ? "5 us" : text(picks[i - 1].rtol).c_str(), std::abs(o.rms / ref.rms - 1),
                o.stats.force_evaluations,
                double(ref.stats.force_evaluations) / double(o.stats.force_evaluations), best[i],
                best[0] / best[i]);
  }
  return 0;
}
