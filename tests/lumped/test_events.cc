// rk8pd-events (issue 18, target 3): event location against an analytic contact.
//
// A mass m flies freely at v0 towards a Hertzian wall at w and bounces off it:
//     m q̈ = −K [q − w]₊^{3/2},   q(0) = 0,   q̇(0) = v0 > 0,
// with the switching function g = q − w. Contact begins at t_c = w / v0. Inside, energy gives the
// largest approach δ_max = (5 m v0² / (4 K))^{2/5}, and the contact lasts
//     T = 2 (δ_max / v0) ∫₀¹ du / √(1 − u^{5/2}) = 2 (δ_max / v0) (2/5) B(2/5, 1/2)
// (Hertz's impact time, 2.94 δ_max / v0). Without damping the mass leaves at −v0, so after
// t_c + T it flies back: q(t) = w − v0 (t − t_c − T).

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../../lumped/src/solvers/step_control.h"
#include "bearing/solvers/integrator.h"

namespace {

using namespace bearing;

class HertzWall final : public MechanicalSystem {
 public:
  HertzWall(double m, double K, double w, bool events) : m_(m), K_(K), w_(w), events_(events) {}
  int dofs() const override { return 1; }
  void mass(double* m) const override { m[0] = m_; }
  void force(double t, const double* q, const double* /*v*/, double* f) const override {
    const double g = q[0] - w_;
    f[0] = g > 0 ? -K_ * g * std::sqrt(g) : 0.0;
    calls.push_back(t);
  }
  int switching_count() const override { return events_ ? 1 : 0; }
  void switching_functions(double /*t*/, const double* q, double* g) const override {
    g[0] = q[0] - w_;
  }
  mutable std::vector<double> calls;  // the times force() was called at

 private:
  double m_, K_, w_;
  bool events_;
};

constexpr double kMass = 1.0, kK = 1e10, kWall = 1e-5, kV0 = 0.1;

double contact_start() {
  return kWall / kV0;
}
double contact_duration() {
  const double delta_max = std::pow(5 * kMass * kV0 * kV0 / (4 * kK), 0.4);
  const double beta = std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);  // B(2/5, 1/2)
  return 2 * delta_max / kV0 * 0.4 * beta;
}

struct Bounce {
  IntegrationStats stats;
  std::vector<double> t, q, calls;
};

Bounce bounce(const std::string& method, bool events) {
  IntegratorSettings s;
  s.method = find_named(kIntegratorMethods, method).value();
  s.dt = 1e-6;
  s.rtol = 1e-10;
  s.atol = 1e-16;
  const HertzWall wall(kMass, kK, kWall, events);
  std::vector<double> times;
  for (int k = 1; k <= 20; ++k) times.push_back(k * 1e-4);  // to 2 ms: contact ≈ 0.1–0.61 ms
  Bounce r;
  r.stats = make_integrator(s)->integrate(
      wall, 0.0, {0.0}, {kV0}, times, [&](double t, const double* q, const double*, const double*) {
        r.t.push_back(t);
        r.q.push_back(q[0]);
      });
  r.calls = wall.calls;
  return r;
}

// The force calls nearest to t from above (a landing ends just past the kink).
double first_call_from(const std::vector<double>& calls, double t) {
  double best = INFINITY;
  for (const double c : calls)
    if (c >= t && c < best) best = c;
  return best;
}

TEST(EventLocation, HertzBounceEntryAndExitAtTheAnalyticTimes) {
  const double tc = contact_start(), T = contact_duration();
  ASSERT_NEAR(T / (std::pow(5 * kMass * kV0 * kV0 / (4 * kK), 0.4) / kV0), 2.9432, 1e-4);
  const Bounce r = bounce("rk8pd-events", true);
  EXPECT_EQ(r.stats.events, 2);  // entry and exit
  // Each landing step ends on its event, at most kLandingMargin (1e-4) of a step (< 0.3 ms here)
  // past the root: a force evaluation (the step's end derivative) lies in [t_event, t_event + 30
  // ns]. The entry time is exact (free flight); the exit time carries the integration error.
  EXPECT_LE(first_call_from(r.calls, tc) - tc, 3e-8);
  EXPECT_LE(first_call_from(r.calls, tc + T - 1e-9) - (tc + T), 3e-8);
  // After the exit the mass flies back at −v0 from w.
  for (std::size_t k = 0; k < r.t.size(); ++k) {
    if (r.t[k] < tc + T) continue;
    const double exact = kWall - kV0 * (r.t[k] - tc - T);
    EXPECT_NEAR(r.q[k], exact, 1e-12) << "t = " << r.t[k];
  }
}

TEST(EventLocation, WithoutSwitchingFunctionsItIsAPlainAdaptiveMethod) {
  // The same bounce with the switching function hidden (switching_count() = 0, the default of a
  // MechanicalSystem): no event is located, the steps straddle the kinks, and the error control
  // alone keeps it accurate. (On this single bounce locating the events saves nothing: 996
  // against 944 evaluations; the saving shows on the bearing, bench/README.md.)
  const Bounce located = bounce("rk8pd-events", true);
  const Bounce blind = bounce("rk8pd-events", false);
  EXPECT_EQ(blind.stats.events, 0);
  const double exact = kWall - kV0 * (blind.t.back() - contact_start() - contact_duration());
  EXPECT_NEAR(located.q.back(), exact, 1e-12);
  EXPECT_NEAR(blind.q.back(), exact, 1e-12);
}

TEST(EventLocation, AStartOnTheKinkIsNotAnEvent) {
  // Started on the wall (g = 0) moving into it: the step from the kink is not an event (a landing
  // leaves g within atol of 0 on purpose; locating it again would land on it once more). The
  // exit from the contact is the one event, at the analytic time.
  IntegratorSettings s;
  s.method = find_named(kIntegratorMethods, "rk8pd-events").value();
  s.dt = 1e-6;
  s.rtol = 1e-10;
  s.atol = 1e-16;
  const HertzWall wall(kMass, kK, 0.0, true);
  std::vector<double> times;
  for (int k = 1; k <= 10; ++k) times.push_back(k * 1e-4);
  const IntegrationStats stats = make_integrator(s)->integrate(
      wall, 0.0, {0.0}, {kV0}, times, [](double, const double*, const double*, const double*) {});
  EXPECT_EQ(stats.events, 1);
  EXPECT_LE(first_call_from(wall.calls, contact_duration() - 1e-9) - contact_duration(), 3e-8);
}

}  // namespace

// --- rk8pd-events' step-size control (step_control.h) ------------------------------------------
// The acceptance rule is the tolerance's contract: a step is accepted exactly when every
// component's error is within atol s_i + rtol |y_i|, i.e. for the error ratio r ≤ 1.

TEST(StepControl, AcceptsExactlyTheStepsWithinTheTolerance) {
  const double scale[2] = {2.0, 1.0};
  const double y1[2] = {0.5, -4.0};
  const double atol = 1e-6, rtol = 1e-3;
  // The ratio of each component: |err_i| / (atol s_i + rtol |y_i|); component 1 sets r.
  const double bound1 = atol * scale[1] + rtol * std::abs(y1[1]);
  for (const double r : {0.3, 0.999, 1.0}) {
    solvers_detail::StepControl control(2, atol, rtol, scale);
    const double err[2] = {0.0, r * bound1};
    double h = 1e-3;
    EXPECT_TRUE(control.adjust(y1, err, h)) << "error ratio " << r;
  }
  for (const double r : {1.001, 1.05, 3.0}) {
    solvers_detail::StepControl control(2, atol, rtol, scale);
    const double err[2] = {0.0, -r * bound1};
    double h = 1e-3;
    EXPECT_FALSE(control.adjust(y1, err, h)) << "error ratio " << r;
    // A rejected step shrinks by S r^(-1/8), never below 0.2 h.
    EXPECT_NEAR(h, 1e-3 * std::max(0.2, 0.9 * std::pow(r, -1.0 / 8.0)), 1e-15) << r;
  }
}

TEST(StepControl, TheNextStepFollowsThePiRule) {
  const double scale[1] = {1.0};
  const double y1[1] = {1.0};
  const double atol = 1e-8, rtol = 1e-6, bound = atol + rtol;
  solvers_detail::StepControl control(1, atol, rtol, scale);
  double h = 1e-3;
  const double e1[1] = {0.5 * bound};
  ASSERT_TRUE(control.adjust(y1, e1, h));
  // After an accepted step: h S r^(-0.7/8) r_prev^(0.4/8), r_prev = 1e-4 at the start, in [0.2, 5].
  const double first = 0.9 * std::pow(0.5, -0.7 / 8) * std::pow(1e-4, 0.4 / 8);
  EXPECT_NEAR(h, 1e-3 * std::clamp(first, 0.2, 5.0), 1e-15);
  const double h1 = h;
  const double e2[1] = {0.25 * bound};
  ASSERT_TRUE(control.adjust(y1, e2, h));
  const double second = 0.9 * std::pow(0.25, -0.7 / 8) * std::pow(0.5, 0.4 / 8);
  EXPECT_NEAR(h, h1 * std::clamp(second, 0.2, 5.0), 1e-15);
}
