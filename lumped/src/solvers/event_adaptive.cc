// "rk8pd-events": GSL's Prince–Dormand 8(7) step (gsl_odeiv2_step_rk8pd, as "rk8pd") in an own
// stepping loop with PI step-size control, which locates the system's switching events
// (MechanicalSystem::switching_functions: a bearing model's signed ball approaches δ_j) and ends
// a step on each, so that no step straddles a contact opening or closing.
//
// Why. Q = K [δ]₊^{3/2} has an unbounded second derivative where δ_j changes sign: a step that
// straddles the kink has a local error far above the smooth estimate, so the error control
// rejects it and retries smaller steps around the change. A step that ends on the kink is smooth
// on its whole length; the next one starts on the other side, smooth except at its first point.
//
// The loop, from (t, y = [q, v], y'(t)) with g = switching_functions(t, q):
//   1. Attempt a step of h (rk8pd with dydt_in = y'(t): 12 stage evaluations + y'(t + h), 13 in
//      all; y'(t + h) is the next step's dydt_in, so a step costs 13 rather than the 14 of
//      gsl_odeiv2_evolve_apply, which evaluates dydt_in again). StepControl (step_control.h)
//      accepts or rejects it on the error ratio of gsl_adaptive.cc (same atol, rtol and per-DOF
//      scales) and proposes the next h'.
//   2. If some g_k changes sign between t and t + h (the ends only: a contact that closes and
//      opens again inside one step is not seen), the earliest crossing τ is found on the step's
//      quintic Hermite interpolant (q, v, a at both ends; Illinois regula falsi on g_k(τ, q(τ)),
//      converged when g_k is on the new side and within 1e-3 atol of 0), and the step is retried
//      with length τ − t + kLandingMargin h, ending just past the kink (the attempt counts as
//      rejected). This happens also when the control rejected the attempt, as long as τ − t ≤ h'
//      (the crossing is what made the attempt fail). A g_k that starts within atol of 0 is the
//      event the step starts on (a landing a rounding short of the kink): it needs no landing.
//   3. Otherwise a rejected attempt is retried with h', an accepted one is taken. The step after a
//      landing starts with the length of the attempt that crossed the event, not with the
//      control's proposal after the short landing step.
//
// Dense output as in gsl_adaptive.cc (every output time inside an accepted step by Hermite
// interpolation of q, v, a at its ends, a = M⁻¹ f evaluated afresh at each output, counted), with
// the degree-8 interpolant (the previous step's start as a third node) only where no event lies
// between the nodes: the first step and every step that starts on an event use the quintic.
//
// Measured on the default case (bench/README.md, issue 18 target 3): 1e-4 on RMS ay at about
// 11× fewer force evaluations than RK4 5 µs. What limits it is not the events (~250 per second,
// ~26 evaluations each) but the ~1 kHz contact resonance, which needs ~4 000 steps per simulated
// second at that accuracy, and the 20 000 output evaluations per second.

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "bearing/errors.h"
#include "bearing/numerics/roots.h"
#include "bearing/solvers/integrator.h"
#include "integrator_detail.h"
#include "step_control.h"

namespace bearing {
namespace solvers_detail {

namespace {

// A landing ends this fraction of the crossing attempt past the located root, so that the
// interpolant's error in the root does not leave the landing step short of the kink.
constexpr double kLandingMargin = 1e-4;

struct StepFree {
  void operator()(gsl_odeiv2_step* s) const { gsl_odeiv2_step_free(s); }
};

// The sign side of a switching value: true for g > 0 (a loaded contact).
inline bool side(double g) {
  return g > 0;
}

// The switching functions of a system at the ends of a step and the search for the earliest
// sign change inside it.
class EventLocator {
 public:
  EventLocator(const MechanicalSystem& system, double atol)
      : system_(system),
        count_(system.switching_count()),
        atol_(atol),
        start_(static_cast<std::size_t>(count_)),
        end_(start_.size()),
        probe_(start_.size()) {}

  bool active() const { return count_ > 0; }
  void set_start(double t, const double* q) {
    if (count_ > 0) system_.switching_functions(t, q, start_.data());
  }
  /// After an accepted step: its end values become the next step's start values.
  void advance() { start_.swap(end_); }

  /// The earliest time in (t0, t1] where some g_k changes sign along `step` (whose ends are t0,
  /// where g = start values, and t1 with q1), ending on the new side: the time to land on. Returns
  /// 0 when no g_k changes sign, or only ones that start within atol of 0.
  double crossing(const HermiteStep& step, double t0, double t1, const double* q1, int n) {
    if (count_ == 0) return 0.0;
    system_.switching_functions(t1, q1, end_.data());
    double earliest = 0.0;
    for (int k = 0; k < count_; ++k) {
      const double g0 = start_[static_cast<std::size_t>(k)], g1 = end_[static_cast<std::size_t>(k)];
      if (side(g0) == side(g1) || std::abs(g0) <= atol_) continue;
      const double tau = root(step, k, t0, g0, earliest > 0 ? earliest : t1, n);
      if (earliest == 0.0 || tau < earliest) earliest = tau;
    }
    return earliest;
  }

 private:
  // Illinois regula falsi on s g_k(τ, q(τ)), s making it rise from negative at t0 to positive
  // at `hi` (the sign at hi is that of g_k(t1) unless an earlier crossing shortened it, in which
  // case the bracket is checked first).
  double root(const HermiteStep& step, int k, double t0, double g0, double hi, int n) {
    const double s = side(g0) ? -1.0 : 1.0;
    qv_.resize(2 * static_cast<std::size_t>(n));
    const auto f = [&](double tau) {
      step.at(tau, qv_.data(), qv_.data() + n);
      system_.switching_functions(tau, qv_.data(), probe_.data());
      return s * probe_[static_cast<std::size_t>(k)];
    };
    const double f_hi = f(hi);
    if (!(f_hi > 0)) return hi;  // no change of g_k before an earlier crossing: keep that one
    numerics::RegulaFalsiOptions o;
    o.max_iterations = 60;
    const double tol = 1e-3 * atol_;
    const numerics::RegulaFalsiResult r = numerics::regula_falsi(
        f, t0, s * g0, hi, f_hi, [&](double, double fx) { return fx > 0 && fx <= tol; }, o);
    return r.converged ? r.x : r.hi;
  }

  const MechanicalSystem& system_;
  int count_;
  double atol_;
  std::vector<double> start_, end_, probe_, qv_;
};

class EventAdaptive final : public Integrator {
 public:
  explicit EventAdaptive(const IntegratorSettings& settings) : settings_(settings) {}

  IntegrationStats integrate(const MechanicalSystem& system, double t0,
                             const std::vector<double>& q0, const std::vector<double>& v0,
                             const std::vector<double>& output_times, const Observer& observe,
                             const Progress& progress) const override;

  std::string name() const override { return name_of(kIntegratorMethods, settings_.method); }

 private:
  IntegratorSettings settings_;
};

// The outputs of one accepted step [t0, t1]: interpolated, checked, observed.
class DenseOutput {
 public:
  DenseOutput(const std::string& method, const MechanicalSystem& system,
              MechanicalSystem::Workspace* workspace, const double* inv_mass, const double* bound,
              const std::vector<double>& times, const Observer& observe, GslContext& context)
      : method_(method),
        system_(system),
        workspace_(workspace),
        inv_mass_(inv_mass),
        bound_(bound),
        times_(times),
        observe_(observe),
        context_(context),
        n_(system.dofs()),
        q_(static_cast<std::size_t>(n_)),
        v_(q_.size()),
        a_(q_.size()) {}

  bool done() const { return next_ >= times_.size(); }
  bool due(double t) const { return next_ < times_.size() && times_[next_] <= t; }
  std::size_t next() const { return next_; }

  /// Output at time t from a given state (the initial one).
  void emit_state(double t, const double* q, const double* v, long step, double dt) {
    for (; due(t); ++next_) emit(times_[next_], q, v, step, dt);
  }
  /// Every output time up to t1 from `step`'s interpolant, each reported as progress.
  void serve(const HermiteStep& step, double t1, long number, double dt, ProgressThrottle& report) {
    for (; due(t1); ++next_) {
      step.at(times_[next_], q_.data(), v_.data());
      emit(times_[next_], q_.data(), v_.data(), number, dt);
      report.update(times_[next_]);
    }
  }

 private:
  void emit(double t, const double* q, const double* v, long step, double dt) {
    check_state(method_, t, step, dt, q, v, n_, bound_);
    system_.force_with(workspace_, t, q, v, a_.data());
    ++context_.force_evaluations;
    for (int i = 0; i < n_; ++i) a_[static_cast<std::size_t>(i)] *= inv_mass_[i];
    check_acceleration(method_, t, step, dt, a_.data(), n_);
    if (observe_) observe_(t, q, v, a_.data());
  }

  const std::string& method_;
  const MechanicalSystem& system_;
  MechanicalSystem::Workspace* workspace_;
  const double* inv_mass_;
  const double* bound_;
  const std::vector<double>& times_;
  const Observer& observe_;
  GslContext& context_;
  int n_;
  std::size_t next_ = 0;
  std::vector<double> q_, v_, a_;
};

IntegrationStats EventAdaptive::integrate(const MechanicalSystem& system, double t0,
                                          const std::vector<double>& q0,
                                          const std::vector<double>& v0,
                                          const std::vector<double>& output_times,
                                          const Observer& observe, const Progress& progress) const {
  const std::string method = name();
  const std::vector<double> inv_mass = check_call(method, system, t0, q0, v0, output_times);
  const int n = system.dofs();
  const auto dim = static_cast<std::size_t>(2 * n);
  const std::vector<double> bounds = displacement_bounds(system, settings_.max_displacement);
  IntegrationStats stats;
  std::vector<double> y(dim), y_try(dim), y_err(dim), dydt(dim), dydt_end(dim);
  std::copy(q0.begin(), q0.end(), y.begin());
  std::copy(v0.begin(), v0.end(), y.begin() + n);
  check_state(method, t0, 0, settings_.dt, y.data(), y.data() + n, n, bounds.data());
  if (output_times.empty()) return stats;

  GslContextData data(system, inv_mass);
  GslContext& context = data.context;
  MechanicalSystem::Workspace* const workspace = data.workspace();
  const std::vector<double> scale =
      tolerance_scales(system, t0, q0, v0, inv_mass, settings_.dt, context);
  gsl_odeiv2_system ode{first_order_rhs, nullptr, dim, &context};
  const std::unique_ptr<gsl_odeiv2_step, StepFree> stepper(
      gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, dim));
  if (!stepper) throw SolverError(method + ": GSL could not allocate the rk8pd stepper");

  DenseOutput out(method, system, workspace, inv_mass.data(), bounds.data(), output_times, observe,
                  context);
  out.emit_state(t0, y.data(), y.data() + n, 0, settings_.dt);
  const double t_end = output_times.back();
  ProgressThrottle report(progress, t0, t_end);
  EventLocator events(system, settings_.atol);
  events.set_start(t0, y.data());
  check_step(method, first_order_rhs(t0, y.data(), dydt.data(), &context), context, t0, 0,
             settings_.dt);

  StepControl control(dim, settings_.atol, settings_.rtol, scale.data());
  HermiteStep step;
  std::vector<double> y_before(dim), a_before(static_cast<std::size_t>(n));
  double t = t0, t_before = t0, h = settings_.dt;
  bool smooth_before = false;  // whether [t_before, t] is a step on the same side of every event
  bool landing = false;        // whether this attempt ends on an event
  double h_crossing = 0.0;     // the attempt that crossed the event being landed on
  while (t < t_end) {
    if (!landing && settings_.max_step > 0) h = std::min(h, settings_.max_step);
    const bool final_step = !landing && t + h >= t_end;
    if (final_step) h = t_end - t;
    std::copy(y.begin(), y.end(), y_try.begin());
    const int status = gsl_odeiv2_step_apply(stepper.get(), t, h, y_try.data(), y_err.data(),
                                             dydt.data(), dydt_end.data(), &ode);
    check_step(method, status, context, t, stats.steps + 1, h);
    double h_next = h;
    const bool rejected = !control.adjust(y_try.data(), y_err.data(), h_next);
    const double t1 = final_step ? t_end : t + h;
    if (!landing && events.active()) {
      step.set(n, t, t1, y.data(), y.data() + n, dydt.data() + n, y_try.data(), y_try.data() + n,
               dydt_end.data() + n);
      const double tau = events.crossing(step, t, t1, y_try.data(), n);
      if (tau > t && tau < t1 && (!rejected || tau - t <= h_next)) {
        ++stats.rejected_steps;  // the attempt is not taken: the step ends on the event instead
        h_crossing = h;
        h = std::min(tau + kLandingMargin * h, t1) - t;
        landing = true;
        continue;
      }
    }
    if (rejected) {
      if (!(h_next < h && t + h_next != t))
        check_step(method, GSL_FAILURE, context, t, stats.steps + 1, h);
      ++stats.rejected_steps;
      h = h_next;
      landing = false;
      continue;
    }
    ++stats.steps;
    if (landing) ++stats.events;
    check_state(method, t1, stats.steps, h, y_try.data(), y_try.data() + n, n, bounds.data());
    if (landing)
      events.set_start(t1, y_try.data());  // the landing step's end, not the attempt's
    else if (events.active())
      events.advance();
    if (out.due(t1)) {
      step.set(n, t, t1, y.data(), y.data() + n, dydt.data() + n, y_try.data(), y_try.data() + n,
               dydt_end.data() + n);
      if (smooth_before)
        step.add_node(t_before, y_before.data(), y_before.data() + n, a_before.data());
      out.serve(step, t1, stats.steps, h, report);
    }
    y_before.swap(y);
    std::copy(dydt.begin() + n, dydt.end(), a_before.begin());
    t_before = t;
    y.swap(y_try);
    dydt.swap(dydt_end);
    t = t1;
    smooth_before = !landing;
    if (landing)
      h = h_crossing;
    else if (!final_step)
      h = h_next;
    landing = false;
    report.update(t);
  }
  stats.force_evaluations = context.force_evaluations;
  stats.jacobian_evaluations = context.jacobian_evaluations;
  report.finish();
  return stats;
}

}  // namespace

std::unique_ptr<Integrator> make_event_adaptive(const IntegratorSettings& settings) {
  return std::make_unique<EventAdaptive>(settings);
}

}  // namespace solvers_detail
}  // namespace bearing
