// rk8pd-events on the default case (issue 18, target 3): the event-located adaptive run agrees
// with RK4 5 us within the stated accuracy, 1e-4 on the RMS of ay over the post-transient window,
// the figure bench/README.md compares costs at. The whole default run (1.2 s simulated) takes
// ~40 ms with RK4 and ~5 ms with rk8pd-events, so the test runs the case itself rather than a
// shorter stand-in. No timing here: the cost (force evaluations, deterministic) is bounded only
// loosely, as a guard against a change that quietly stops locating events.

#include <cmath>

#include <gtest/gtest.h>

#include "bearing/case_file.h"
#include "bearing/signal/statistics.h"
#include "bearing/simulation.h"

namespace {

using namespace bearing;

TEST(EventDynamics, DefaultCaseAgreesWithRk4) {
  const SimulationResult rk4 = simulate(default_case());
  const SimulationResult events =
      simulate(default_case({{"solver.method", "rk8pd-events"}, {"solver.tolerance", "1e-5"}}));
  const double ref = channel_statistics(rk4.response.steady("ay")).rms;
  const double rms = channel_statistics(events.response.steady("ay")).rms;
  EXPECT_LE(std::abs(rms / ref - 1), 1e-4) << rms << " vs " << ref;
  // Contacts open and close ~250 times per second here, and each one ends a step.
  EXPECT_GT(events.stats.events, 200);
  EXPECT_LT(events.stats.force_evaluations, rk4.stats.force_evaluations / 8);
}

}  // namespace
