// Speed of the lumped dynamics (issue 3). Two kinds of measurement, one program:
//
//   bearing_bench [Google Benchmark flags]   timings, targets 1-4 and amplitude_spectrum:
//     BM_Integrate2Dof/rk4|rkf45|rk8pd   1 s of the 6308 2-DOF default case, output at 1 kHz
//     BM_BareForceLoop/replay|static     as many MechanicalSystem::force calls as the RK4 run
//     BM_Integrate3Dof/rk4               1 s of the 3-DOF case (axial 100 N, radial 20 N)
//     BM_AmplitudeSpectrum/N             N = 20000, 100000 (smooth) and the prime 100003
//   bearing_bench --accuracy                 target 6 as a table (not a timing, see below)
//
// Why two kinds: targets 1-4 are wall times, which Google Benchmark measures well (repetitions,
// min/median, counters for force evaluations per run and time per evaluation). Target 6 is a
// question about accuracy at a cost measured in force evaluations, which are deterministic: it
// needs one run per tolerance, a search for the loosest passing tolerance and a table with the
// relative error beside each count, so it is a small table-printing mode of the same program.
//
// Cases come from the built-in default case (bearing::default_case: 6308, 2000 rpm, 20 N down,
// no waviness) through the same overrides the CLI takes, so they are the CLI's cases exactly.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <gsl/gsl_errno.h>

#include "bearing/case_file.h"
#include "bearing/models/bearing_model.h"
#include "bearing/signal/spectrum.h"
#include "bearing/signal/statistics.h"
#include "bearing/simulation.h"
#include "bearing/solvers/integrator.h"

namespace {

using bearing::Case;
using bearing::IntegrationStats;
using bearing::IntegratorSettings;
using bearing::Override;

constexpr double kDuration = 1.0;      // simulated time of targets 1-4 [s]
constexpr double kDt = 5e-6;           // RK4 step [s]
constexpr double kObserverRate = 1e3;  // the sparse observer [Hz]

// A model with its starting state and the sparse output grid 0, 1 ms, ..., 1 s.
struct Problem {
  Case c;
  std::unique_ptr<bearing::BearingModel> model;
  std::vector<double> q0, v0, times;
};

Problem make_problem(const std::vector<Override>& overrides) {
  Problem p;
  p.c = bearing::default_case(overrides);
  p.model = bearing::make_model(p.c);
  p.q0 = p.model->initial_displacement();
  p.v0.assign(p.q0.size(), 0.0);
  const auto samples = static_cast<std::size_t>(std::llround(kDuration * kObserverRate)) + 1;
  for (std::size_t k = 0; k < samples; ++k)
    p.times.push_back(static_cast<double>(k) / kObserverRate);
  return p;
}

const Problem& two_dof() {
  static const Problem p = make_problem({});
  return p;
}

const Problem& three_dof() {
  static const Problem p =
      make_problem({{"model.kind", "3dof"}, {"operation.axial_load", "100 N"}});
  return p;
}

// The sparse observer: sums a_y over the output times so the work cannot be optimised away.
struct Sink {
  double value = 0;
  bearing::Observer observer() {
    return [this](double, const double*, const double*, const double* a) { value += a[1]; };
  }
};

IntegratorSettings settings_for(const std::string& method) {
  IntegratorSettings s;
  s.method = method;
  s.dt = kDt;     // the step (rk4) or the first step (adaptive)
  s.rtol = 1e-6;  // adaptive methods (target 2)
  return s;
}

void report(benchmark::State& state, const IntegrationStats& s) {
  state.counters["steps"] = static_cast<double>(s.steps);
  state.counters["rejected"] = static_cast<double>(s.rejected_steps);
  state.counters["evals"] = static_cast<double>(s.force_evaluations);
  // Seconds per force evaluation (printed with an SI prefix: "25n" is 25 ns).
  state.counters["t/eval"] = benchmark::Counter(
      static_cast<double>(s.force_evaluations),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void integrate(benchmark::State& state, const Problem& p, const std::string& method) {
  const auto integrator = bearing::make_integrator(settings_for(method));
  Sink sink;
  const bearing::Observer observe = sink.observer();
  IntegrationStats stats;
  for (auto _ : state) {
    stats = integrator->integrate(*p.model, 0.0, p.q0, p.v0, p.times, observe);
    benchmark::DoNotOptimize(sink.value);
  }
  report(state, stats);
}

// Targets 1 and 2.
void BM_Integrate2Dof(benchmark::State& state, const char* method) {
  integrate(state, two_dof(), method);
}

// Target 4.
void BM_Integrate3Dof(benchmark::State& state, const char* method) {
  integrate(state, three_dof(), method);
}

// Target 3: the bare contact-force loop, the same number of MechanicalSystem::force calls as the
// RK4 run of target 1, through the same virtual call, with no integrator around it.
//   replay: at exactly the (t, q, v) the RK4 run passes, recorded beforehand (a real run's
//           loaded-ball pattern and branches; reading the 5 recorded doubles per call streams
//           ~32 MB, which the RK4 run does not have to do, so this is a slight over-estimate)
//   static: at the RK4 run's times (t, t + h/2, t + h/2, t + h per step) at the static
//           equilibrium q0, v = 0 (no memory traffic; the loaded zone of the mean state)
class Recorder final : public bearing::MechanicalSystem {
 public:
  explicit Recorder(const bearing::MechanicalSystem& s) : s_(s) {}
  int dofs() const override { return s_.dofs(); }
  void mass(double* m) const override { s_.mass(m); }
  void force(double t, const double* q, const double* v, double* f) const override {
    log.push_back(t);
    log.insert(log.end(), q, q + s_.dofs());
    log.insert(log.end(), v, v + s_.dofs());
    s_.force(t, q, v, f);
  }
  mutable std::vector<double> log;

 private:
  const bearing::MechanicalSystem& s_;
};

void BM_BareForceLoop(benchmark::State& state, bool replay) {
  const Problem& p = two_dof();
  const bearing::MechanicalSystem& system = *p.model;
  const int n = system.dofs();
  const std::size_t stride = 1 + 2 * static_cast<std::size_t>(n);
  Recorder recorder(system);
  Sink sink;
  const IntegrationStats rk4 = bearing::make_integrator(settings_for("rk4"))
                                   ->integrate(recorder, 0.0, p.q0, p.v0, p.times, sink.observer());
  const std::size_t calls = recorder.log.size() / stride;
  if (calls != static_cast<std::size_t>(rk4.force_evaluations)) {
    state.SkipWithError("recorded calls != force_evaluations");
    return;
  }
  std::vector<double> times(calls);
  for (std::size_t i = 0; i < calls; ++i) times[i] = recorder.log[i * stride];
  if (!replay) recorder.log = {};

  std::vector<double> force(static_cast<std::size_t>(n));
  double* const f = force.data();
  for (auto _ : state) {
    double sum = 0;
    if (replay) {
      const double* r = recorder.log.data();
      for (std::size_t i = 0; i < calls; ++i, r += stride) {
        system.force(r[0], r + 1, r + 1 + n, f);
        sum += f[1];
      }
    } else {
      for (std::size_t i = 0; i < calls; ++i) {
        system.force(times[i], p.q0.data(), p.v0.data(), f);
        sum += f[1];
      }
    }
    benchmark::DoNotOptimize(sum);
  }
  state.counters["evals"] = static_cast<double>(calls);
  state.counters["t/eval"] =
      benchmark::Counter(static_cast<double>(calls), benchmark::Counter::kIsIterationInvariantRate |
                                                         benchmark::Counter::kInvert);
}

// amplitude_spectrum for a smooth N (GSL mixed radix) and a prime N (Bluestein). The timed unit
// test this replaces checked that a prime length is not O(N^2).
void BM_AmplitudeSpectrum(benchmark::State& state) {
  constexpr double kTwoPi = 6.283185307179586;
  const auto n = static_cast<std::size_t>(state.range(0));
  std::mt19937_64 rng(42);
  std::normal_distribution<double> noise;
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i)
    x[i] = std::sin(kTwoPi * 133.0 * static_cast<double>(i) / 20000.0) + 0.1 * noise(rng);
  for (auto _ : state) {
    bearing::Spectrum s = bearing::amplitude_spectrum(x, 20000.0, bearing::Window::hann);
    benchmark::DoNotOptimize(s.amplitude.data());
  }
}

double minimum(const std::vector<double>& v) {
  return *std::min_element(v.begin(), v.end());
}

void register_benchmarks() {
  const auto common = [](benchmark::internal::Benchmark* b) {
    b->Unit(benchmark::kMillisecond)
        ->Repetitions(5)
        ->ReportAggregatesOnly(true)
        ->ComputeStatistics("min", minimum);
  };
  for (const char* m : {"rk4", "rkf45", "rk8pd"})
    common(benchmark::RegisterBenchmark((std::string("BM_Integrate2Dof/") + m).c_str(),
                                        BM_Integrate2Dof, m));
  common(benchmark::RegisterBenchmark("BM_BareForceLoop/replay", BM_BareForceLoop, true));
  common(benchmark::RegisterBenchmark("BM_BareForceLoop/static", BM_BareForceLoop, false));
  common(benchmark::RegisterBenchmark("BM_Integrate3Dof/rk4", BM_Integrate3Dof, "rk4"));
  common(benchmark::RegisterBenchmark("BM_AmplitudeSpectrum", BM_AmplitudeSpectrum)
             ->Arg(20000)
             ->Arg(100000)
             ->Arg(100003));
}

// ---- Target 6: adaptive vs RK4, accuracy against cost -------------------------------------------
//
// The default case as `bearing-sim run` solves it (1.2 s, 0.2 s transient, 20 kHz output); the
// figure compared is the RMS of ay over the post-transient window, the cost is
// IntegrationStats::force_evaluations (output evaluations included, as in summary.json).

struct Outcome {
  bool ok = false;
  std::string error;
  double rms = 0;
  long evals = 0, steps = 0, rejected = 0;
  double ms = 0;
};

Outcome run_default(const std::vector<Override>& overrides) {
  Outcome o;
  try {
    const Case c = bearing::default_case(overrides);
    const auto start = std::chrono::steady_clock::now();
    const bearing::SimulationResult r = bearing::simulate(c);
    o.ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    o.rms = bearing::channel_statistics(r.response.steady("ay")).rms;
    o.evals = r.stats.force_evaluations;
    o.steps = r.stats.steps;
    o.rejected = r.stats.rejected_steps;
    o.ok = true;
  } catch (const std::exception& e) {
    o.error = e.what();
  }
  return o;
}

std::string tol_text(double rtol) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", rtol);
  return buf;
}

Outcome run_adaptive(const std::string& method, double rtol) {
  return run_default({{"solver.method", method}, {"solver.tolerance", tol_text(rtol)}});
}

// RMS of ay at 20 kHz over [transient, duration), as simulate()/summarize() compute it, but with
// the integrator called directly so that atol can be varied on its own (simulate() sets it to
// solver.tolerance × the displacement scale).
double direct_rms_ay(const std::string& method, double rtol, double atol, long& evals) {
  const Case c = bearing::default_case();
  const auto model = bearing::make_model(c);
  IntegratorSettings s = settings_for(method);
  s.rtol = rtol;
  s.atol = atol;
  const auto samples =
      static_cast<std::size_t>(std::floor(c.solver.duration * c.solver.output_rate + 1e-9)) + 1;
  std::vector<double> times(samples), ay;
  for (std::size_t k = 0; k < samples; ++k)
    times[k] = static_cast<double>(k) / c.solver.output_rate;
  const auto first =
      static_cast<std::ptrdiff_t>(std::ceil(c.solver.transient * c.solver.output_rate - 1e-9));
  const std::vector<double> q0 = model->initial_displacement(), v0(q0.size(), 0.0);
  const IntegrationStats st = bearing::make_integrator(s)->integrate(
      *model, 0.0, q0, v0, times,
      [&](double, const double*, const double*, const double* a) { ay.push_back(a[1]); });
  evals = st.force_evaluations;
  return bearing::channel_statistics(std::vector<double>(ay.begin() + first, ay.end() - 1)).rms;
}

// What limits the adaptive accuracy at tight rtol: the absolute tolerance (1e-12 m by default).
void atol_study(double ref_rms) {
  std::printf(
      "Absolute tolerance varied on its own (simulate() uses atol = solver.tolerance x "
      "max(|q0|, P_d/2, 1 um)):\n%-6s %9s %9s %12s %10s\n",
      "", "atol [m]", "rtol", "rel.err", "evals");
  for (const std::string method : {"rkf45", "rk8pd"})
    for (const double atol : {1e-12, 1e-14, 1e-15})
      for (const double rtol : {1e-6, 1e-10}) {
        long evals = 0;
        const double rms = direct_rms_ay(method, rtol, atol, evals);
        std::printf("%-6s %9.0e %9.0e %12.3e %10ld\n", method.c_str(), atol, rtol,
                    std::abs(rms / ref_rms - 1), evals);
      }
  std::printf("\n");
}

// Where the adaptive steps go when the output grid does not clip them (1 kHz observer, 1 s, rtol
// 1e-6): how many force evaluations fall within +-50 us of a change of the set of loaded balls (a
// ball entering or leaving contact, where Q = K [delta]_+^{3/2} has an unbounded second
// derivative), against the share of time those windows cover.
class LoadedSetRecorder final : public bearing::MechanicalSystem {
 public:
  // The loaded set is a 64-bit mask: at most 64 balls (the 6308 has 8).
  explicit LoadedSetRecorder(const bearing::BearingModel& m)
      : m_(m), loads_(static_cast<std::size_t>(std::min(m.balls(), 64))) {}
  int dofs() const override { return m_.dofs(); }
  void mass(double* x) const override { m_.mass(x); }
  void force(double t, const double* q, const double* v, double* f) const override {
    m_.ball_loads(t, q, loads_.data());
    unsigned long long set = 0;
    for (std::size_t j = 0; j < loads_.size(); ++j)
      if (loads_[j] > 0) set |= 1ull << j;
    log.emplace_back(t, set);
    m_.force(t, q, v, f);
  }
  void force_jacobian(double t, const double* q, const double* v, double* dq,
                      double* dv) const override {
    m_.force_jacobian(t, q, v, dq, dv);
  }
  mutable std::vector<std::pair<double, unsigned long long>> log;

 private:
  const bearing::BearingModel& m_;
  mutable std::vector<double> loads_;
};

void contact_event_study() {
  std::printf(
      "Adaptive steps and contact events (1 kHz observer, 1 s, rtol 1e-6, no output "
      "clipping below 1 ms):\n");
  const Problem& p = two_dof();
  if (p.model->balls() > 64) return;
  for (const std::string method : {"rkf45", "rk8pd"}) {
    LoadedSetRecorder rec(*p.model);
    const IntegrationStats st = bearing::make_integrator(settings_for(method))
                                    ->integrate(rec, 0.0, p.q0, p.v0, p.times, {});
    auto log = rec.log;
    std::stable_sort(log.begin(), log.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<double> events;  // midpoints of consecutive calls with different loaded sets
    for (std::size_t i = 1; i < log.size(); ++i)
      if (log[i].second != log[i - 1].second && log[i].first > log[i - 1].first) {
        const double e = 0.5 * (log[i].first + log[i - 1].first);
        if (events.empty() || e - events.back() > 20e-6) events.push_back(e);
      }
    const double w = 50e-6;
    long near = 0;
    for (const auto& call : log) {
      const auto it = std::lower_bound(events.begin(), events.end(), call.first - w);
      if (it != events.end() && *it <= call.first + w) ++near;
    }
    const double share_calls = double(near) / double(log.size());
    const double share_time = std::min(1.0, double(events.size()) * 2 * w / kDuration);
    std::printf(
        "%-6s %ld evals, %ld steps, %ld rejected (%.0f%% of attempts); %zu contact-set "
        "changes; %.1f%% of evals within +-50 us of one, in %.1f%% of the time (%.1fx "
        "denser)\n",
        method.c_str(), st.force_evaluations, st.steps, st.rejected_steps,
        100.0 * st.rejected_steps / double(st.steps + st.rejected_steps), events.size(),
        100 * share_calls, 100 * share_time, share_calls / share_time);
  }
}

int accuracy_table() {
  const double target = 1e-4, cost_factor = 5.0;
  std::printf(
      "Target 6: adaptive vs RK4 on the default case (6308 2-DOF, 2000 rpm, 20 N, 1.2 s, "
      "transient 0.2 s, 20 kHz output)\nfigure: RMS of ay over the post-transient window; "
      "cost: force evaluations (output evaluations included)\n\n");

  const Outcome ref = run_default({});
  if (!ref.ok) {
    std::printf("RK4 reference failed: %s\n", ref.error.c_str());
    return 1;
  }
  const Outcome half = run_default({{"solver.dt", "2.5 us"}});
  const Outcome quarter = run_default({{"solver.dt", "1.25 us"}});
  std::printf("RK4 dt = 5 us    : rms(ay) = %.10e m/s^2, %ld evals, %ld steps, %.1f ms\n", ref.rms,
              ref.evals, ref.steps, ref.ms);
  std::printf("RK4 dt = 2.5 us  : rms(ay) = %.10e m/s^2 (rel. diff. to dt = 5 us: %.2e)\n",
              half.rms, std::abs(half.rms / ref.rms - 1));
  std::printf("RK4 dt = 1.25 us : rms(ay) = %.10e m/s^2 (rel. diff. to dt = 5 us: %.2e)\n",
              quarter.rms, std::abs(quarter.rms / ref.rms - 1));
  const long budget = static_cast<long>(std::floor(ref.evals / cost_factor));
  std::printf("target: |rms/rms_RK4 - 1| <= %.0e with <= %ld evals (RK4 / %.0f)\n\n", target,
              budget, cost_factor);

  for (const std::string method : {"rkf45", "rk8pd"}) {
    std::printf("%-6s %9s %12s %10s %9s %9s %10s %9s\n", method.c_str(), "rtol", "rel.err", "evals",
                "RK4/evals", "steps", "rejected", "ms");
    // rtol = 1e-1 (the largest make_integrator accepts) ... 1e-12 in half decades, loosest first.
    std::vector<double> rtols;
    for (int k = 2; k <= 24; ++k) rtols.push_back(std::pow(10.0, -k / 2.0));
    std::vector<Outcome> outs;
    const auto line = [&](double rtol, const Outcome& o) {
      if (!o.ok) {
        std::printf("%-6s %9s  failed: %s\n", "", tol_text(rtol).c_str(), o.error.c_str());
        return;
      }
      const double err = std::abs(o.rms / ref.rms - 1);
      std::printf("%-6s %9s %12.3e %10ld %9.2f %9ld %10ld %9.1f%s\n", "", tol_text(rtol).c_str(),
                  err, o.evals, double(ref.evals) / double(o.evals), o.steps, o.rejected, o.ms,
                  err <= target ? (o.evals <= budget ? "  <- meets both" : "  accurate") : "");
    };
    for (double rtol : rtols) {
      outs.push_back(run_adaptive(method, rtol));
      line(rtol, outs.back());
    }
    const auto passes = [&](const Outcome& o) {
      return o.ok && std::abs(o.rms / ref.rms - 1) <= target;
    };
    // The loosest rtol from which every tighter one in the scan passes too (robust to a lucky
    // cancellation at a loose tolerance), refined by bisection in log(rtol).
    std::size_t first = rtols.size();
    while (first > 0 && passes(outs[first - 1])) --first;
    if (first == rtols.size()) {
      std::printf("%-6s no rtol down to %g reaches %.0e\n\n", "", rtols.back(), target);
      continue;
    }
    double good = rtols[first];
    Outcome best = outs[first];
    if (first > 0) {
      double bad = rtols[first - 1];
      for (int i = 0; i < 5; ++i) {
        const double mid = std::sqrt(good * bad);
        const Outcome o = run_adaptive(method, mid);
        line(mid, o);
        if (passes(o))
          good = mid, best = o;
        else
          bad = mid;
      }
    }
    std::printf(
        "%-6s loosest rtol reaching %.0e: %s -> %ld evals (RK4/evals = %.2f; target "
        ">= %.0f: %s)\n\n",
        "", target, tol_text(good).c_str(), best.evals, double(ref.evals) / double(best.evals),
        cost_factor, best.evals <= budget ? "MET" : "NOT MET");
  }
  std::printf(
      "The adaptive methods step freely and interpolate the outputs (dense output), so their "
      "cost does not depend on the output rate.\n\n");
  atol_study(ref.rms);
  contact_event_study();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  gsl_set_error_handler_off();  // as bearing-sim: the library checks GSL's return codes
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--accuracy") == 0) return accuracy_table();
  register_benchmarks();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
