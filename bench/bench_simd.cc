// Issue 18, target 1: the SIMD contact loop against the scalar one and against a bare scalar RK4
// loop, in interleaved rounds (each round times every row once, so load from other processes
// spreads over all of them); prints a table of minima and medians (bench/README.md).
//
//   bearing_bench_simd [ROUNDS] [BEARING_SIM|""] [ROW]   (ROW: run only the rows whose name
//                                                        holds it, untimed, e.g. under perf)
//
// Rows, all on the built-in default case (6308, 2000 rpm, 20 N, 2-DOF, Z = 8):
//   force evaluation     MechanicalSystem::force_with at a new t every call (the ball frame is
//                        evaluated every time: the phasor, the rotation, the contacts) at the
//                        static state; 960 000 calls; simd and scalar contact loops
//   RK4 integration      make_integrator(rk4, 5 us)->integrate over 1.2 s with the 20 kHz output
//                        times observed (nothing stored); simd and scalar; and the 2-DOF kind's
//                        own RK4 (make_two_dof_rk4: the force inlined), what `run` uses
//   bare scalar loop     the yardstick: RK4 written out by hand for the same 2-DOF case,
//                        1.2 s at 5 us, the ball angles advanced by rotating them by the phasor of
//                        ω_c h/2 twice a step, the contact force inline, nothing written
//   seed 004             issue 7's problems (examples/seed004_6304.toml, 1 s at 5 us, the 1 kHz
//                        observer): the 2-DOF model, and the ball-DOF model with cage slip 0.02
//                        and mu_m = 0.01; simd and scalar (target 4: balls <= 1.5x the 2-DOF);
//                        each through its kind's own RK4, as `run` integrates it
//   bearing-sim run      the whole process (case, simulation, FFT, CSV and JSON into a temporary
//                        folder), when BEARING_SIM is given; simd and scalar

#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bearing/case_file.h"
#include "bearing/contact_loop.h"
#include "bearing/models/ball_dofs.h"
#include "bearing/models/bearing_model.h"
#include "bearing/models/two_dof.h"
#include "bearing/simulation.h"
#include "bearing/solvers/integrator.h"
#include "seed004_case.h"

extern char** environ;

namespace {

constexpr double kDuration = 1.2;  // [s], the default case's
constexpr double kDt = 5e-6;       // [s]
constexpr double kOutputRate = 20e3;

using Clock = std::chrono::steady_clock;

double seconds(const std::function<void()>& f) {
  const auto start = Clock::now();
  f();
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double minimum(const std::vector<double>& v) {
  return *std::min_element(v.begin(), v.end());
}

bearing::Case default_with(bearing::ContactLoop loop) {
  return bearing::default_case(
      {{"solver.contact_loop", loop == bearing::ContactLoop::simd ? "simd" : "scalar"}});
}

volatile double g_sink = 0;  // keeps the results alive

// force_with at a new t each call, at the static state.
double force_loop(const bearing::BearingModel& m, const std::vector<double>& q0) {
  const auto ws = m.make_workspace();
  const std::vector<double> v(q0.size(), 0.0);
  double f[2], sum = 0;
  const long calls = std::lround(4 * kDuration / kDt);
  for (long i = 0; i < calls; ++i) {
    m.force_with(ws.get(), static_cast<double>(i) * (kDt / 4), q0.data(), v.data(), f);
    sum += f[1];
  }
  return sum;
}

// RK4 at kDt through `make` (make_integrator: the force behind the MechanicalSystem interface; a
// kind's own make_*_rk4: its force inlined, what `bearing-sim run` uses).
using MakeRk4 = std::unique_ptr<bearing::Integrator> (*)(const bearing::IntegratorSettings&);

double rk4_run(const bearing::BearingModel& m, const std::vector<double>& q0,
               const std::vector<double>& v0, const std::vector<double>& times,
               MakeRk4 make = &bearing::make_integrator) {
  bearing::IntegratorSettings s;
  s.method = bearing::IntegratorMethod::rk4;
  s.dt = kDt;
  double sum = 0;
  make(s)->integrate(m, 0.0, q0, v0, times,
                     [&](double, const double*, const double*, const double* a) { sum += a[1]; });
  return sum;
}

// The bare scalar RK4 loop: the default case's numbers, written out.
struct Bare {
  int Z;
  double m, c, K, gap, wc, Fx, Fy, phase;
};

double bare_rk4(const Bare& b, double x, double y) {
  double cs[16], sn[16];
  for (int j = 0; j < b.Z; ++j) {
    cs[j] = std::cos(b.phase + 2 * M_PI * j / b.Z);
    sn[j] = std::sin(b.phase + 2 * M_PI * j / b.Z);
  }
  const double h = kDt, rc = std::cos(b.wc * h / 2), rs = std::sin(b.wc * h / 2);
  double vx = 0, vy = 0, sum = 0;
  auto force = [&](double px, double py, double pvx, double pvy, double& ax, double& ay) {
    double fx = b.Fx - b.c * pvx, fy = b.Fy - b.c * pvy;
    for (int j = 0; j < b.Z; ++j) {
      const double d = px * cs[j] + py * sn[j] - b.gap;
      if (d <= 0) continue;
      const double q = b.K * d * std::sqrt(d);
      fx -= q * cs[j];
      fy -= q * sn[j];
    }
    ax = fx / b.m;
    ay = fy / b.m;
  };
  auto rotate = [&] {
    for (int j = 0; j < b.Z; ++j) {
      const double c = cs[j] * rc - sn[j] * rs;
      sn[j] = sn[j] * rc + cs[j] * rs;
      cs[j] = c;
    }
  };
  const long steps = std::lround(kDuration / h);
  for (long i = 0; i < steps; ++i) {
    double a1x, a1y, a2x, a2y, a3x, a3y, a4x, a4y;
    force(x, y, vx, vy, a1x, a1y);
    rotate();
    force(x + h / 2 * vx, y + h / 2 * vy, vx + h / 2 * a1x, vy + h / 2 * a1y, a2x, a2y);
    force(x + h / 2 * (vx + h / 2 * a1x), y + h / 2 * (vy + h / 2 * a1y), vx + h / 2 * a2x,
          vy + h / 2 * a2y, a3x, a3y);
    rotate();
    force(x + h * (vx + h / 2 * a2x), y + h * (vy + h / 2 * a2y), vx + h * a3x, vy + h * a3y, a4x,
          a4y);
    x += h / 6 * (vx + 2 * (vx + h / 2 * a1x) + 2 * (vx + h / 2 * a2x) + (vx + h * a3x));
    y += h / 6 * (vy + 2 * (vy + h / 2 * a1y) + 2 * (vy + h / 2 * a2y) + (vy + h * a3y));
    vx += h / 6 * (a1x + 2 * a2x + 2 * a3x + a4x);
    vy += h / 6 * (a1y + 2 * a2y + 2 * a3y + a4y);
    sum += a4y;
  }
  return sum + x + y;
}

bool run_process(const std::string& sim, const char* loop, const std::string& out) {
  const std::string set = std::string("solver.contact_loop=") + loop;
  const char* argv[] = {sim.c_str(), "run", "--set", set.c_str(), "--out", out.c_str(), nullptr};
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", 1 /*O_WRONLY*/, 0);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, sim.c_str(), &fa, nullptr, const_cast<char**>(argv), environ);
  posix_spawn_file_actions_destroy(&fa);
  int status = 0;
  return rc == 0 && waitpid(pid, &status, 0) == pid && WIFEXITED(status) &&
         WEXITSTATUS(status) == 0;
}

// Seed 004's 6304 (seed004_case.h), with the contact loop and, for the balls, slip and traction.
bearing::Case seed004(bool balls, const char* loop) {
  std::vector<bearing::Override> o = {{"solver.contact_loop", loop}};
  if (balls) {
    o.push_back({"cage.slip", "0.02"});
    o.push_back({"cage.friction", "0.01"});
  }
  return bench::seed004_case(balls, o);
}

struct Row {
  std::string name;
  double evals;  // force evaluations per run (0: a whole process)
  std::function<void()> body;
  std::vector<double> times;
};

// The table of minima and medians, then the ratios the targets are judged on (row order of main).
void print_table(const std::vector<Row>& rows, int rounds, bool with_runs) {
  std::printf("contact loop: simd runs as %s\n\n", bearing::simd_target().c_str());
  std::printf("| row | rounds | min [ms] | median [ms] | per force evaluation (min) [ns] |\n");
  std::printf("| --- | ---: | ---: | ---: | ---: |\n");
  for (const Row& r : rows) {
    std::printf("| %s | %d | %.2f | %.2f | ", r.name.c_str(), rounds, 1e3 * minimum(r.times),
                1e3 * median(r.times));
    if (r.evals > 0)
      std::printf("%.1f |\n", 1e9 * minimum(r.times) / r.evals);
    else
      std::printf("– |\n");
  }
  auto ratio = [&](int a, int b) { return minimum(rows[a].times) / minimum(rows[b].times); };
  std::printf(
      "\nratios of minima: force simd/scalar %.3f (scalar/simd %.2fx); RK4 simd/scalar "
      "%.3f; RK4 simd / bare loop %.3f; RK4 scalar / bare loop %.3f",
      ratio(0, 1), ratio(1, 0), ratio(2, 3), ratio(2, 4), ratio(3, 4));
  std::printf("; seed 004 balls/2-DOF: simd %.3f, scalar %.3f; balls simd/scalar %.3f", ratio(7, 5),
              ratio(8, 6), ratio(7, 8));
  std::printf("; RK4 2-DOF kind's own (run's path) / bare loop %.3f, / RK4 simd %.3f", ratio(9, 4),
              ratio(9, 2));
  if (with_runs)
    std::printf("; run simd / bare loop %.3f; run scalar / bare loop %.3f", ratio(10, 4),
                ratio(11, 4));
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 11;
  const std::string sim = argc > 2 ? argv[2] : "";
  const std::string filter = argc > 3 ? argv[3] : "";
  const double kEvals = 4 * kDuration / kDt, kSeed004Evals = 4 * 1.0 / kDt;
  using bearing::ContactLoop;

  struct Model {
    std::unique_ptr<bearing::BearingModel> m;
    std::vector<double> q0, v0;
  };
  auto make = [](ContactLoop loop) {
    Model p;
    p.m = bearing::make_model(default_with(loop));
    p.q0 = p.m->initial_displacement();
    p.v0 = p.m->initial_velocity();
    return p;
  };
  const Model simd = make(ContactLoop::simd), scalar = make(ContactLoop::scalar);
  auto make_case = [](const bearing::Case& c) {
    Model p;
    p.m = bearing::make_model(c);
    p.q0 = p.m->initial_displacement();
    p.v0 = p.m->initial_velocity();
    return p;
  };
  const Model s4_two = make_case(seed004(false, "simd")),
              s4_two_scalar = make_case(seed004(false, "scalar")),
              s4_balls = make_case(seed004(true, "simd")),
              s4_balls_scalar = make_case(seed004(true, "scalar"));
  std::vector<double> sparse;  // 1 s at 1 kHz, as bench_dynamics.cc's BM_Seed004
  for (int k = 0; k <= 1000; ++k) sparse.push_back(k * 1e-3);
  std::vector<double> times;
  for (long k = 0; k <= std::lround(kDuration * kOutputRate); ++k)
    times.push_back(static_cast<double>(k) / kOutputRate);

  const bearing::Case c = bearing::default_case();
  const bearing::ContactConstants k = bearing::contact_constants(c);
  const Bare bare{c.bearing.balls,
                  c.rotor.mass,
                  c.rotor.damping,
                  k.K,
                  c.bearing.ball_gap(),
                  simd.m->cage_speed(),
                  c.operation.load.x(),
                  c.operation.load.y(),
                  0.0};  // the case has no cage phase: ball 0 at angle 0

  std::vector<Row> rows = {
      {"force evaluation, simd",
       kEvals,
       [&] { g_sink = g_sink + force_loop(*simd.m, simd.q0); },
       {}},
      {"force evaluation, scalar",
       kEvals,
       [&] { g_sink = g_sink + force_loop(*scalar.m, scalar.q0); },
       {}},
      {"RK4 integration, simd",
       kEvals,
       [&] { g_sink = g_sink + rk4_run(*simd.m, simd.q0, simd.v0, times); },
       {}},
      {"RK4 integration, scalar",
       kEvals,
       [&] { g_sink = g_sink + rk4_run(*scalar.m, scalar.q0, scalar.v0, times); },
       {}},
      {"bare scalar RK4 loop",
       kEvals,
       [&] { g_sink = g_sink + bare_rk4(bare, simd.q0[0], simd.q0[1]); },
       {}},
      {"seed 004, 2-DOF, simd",
       kSeed004Evals,
       [&] {
         g_sink =
             g_sink + rk4_run(*s4_two.m, s4_two.q0, s4_two.v0, sparse, &bearing::make_two_dof_rk4);
       },
       {}},
      {"seed 004, 2-DOF, scalar",
       kSeed004Evals,
       [&] {
         g_sink = g_sink + rk4_run(*s4_two_scalar.m, s4_two_scalar.q0, s4_two_scalar.v0, sparse,
                                   &bearing::make_two_dof_rk4);
       },
       {}},
      {"seed 004, balls (slip 0.02, mu_m 0.01), simd",
       kSeed004Evals,
       [&] {
         g_sink = g_sink + rk4_run(*s4_balls.m, s4_balls.q0, s4_balls.v0, sparse,
                                   &bearing::make_ball_dof_rk4);
       },
       {}},
      {"seed 004, balls (slip 0.02, mu_m 0.01), scalar",
       kSeed004Evals,
       [&] {
         g_sink = g_sink + rk4_run(*s4_balls_scalar.m, s4_balls_scalar.q0, s4_balls_scalar.v0,
                                   sparse, &bearing::make_ball_dof_rk4);
       },
       {}},
      {"RK4 integration, simd, the 2-DOF kind's own (make_two_dof_rk4)",
       kEvals,
       [&] {
         g_sink = g_sink + rk4_run(*simd.m, simd.q0, simd.v0, times, &bearing::make_two_dof_rk4);
       },
       {}},
  };
  if (!sim.empty()) {
    const std::string out = "/tmp/bearing_bench_simd_run";
    rows.push_back({"bearing-sim run, simd", 0, [=] { run_process(sim, "simd", out); }, {}});
    rows.push_back({"bearing-sim run, scalar", 0, [=] { run_process(sim, "scalar", out); }, {}});
    if (!run_process(sim, "simd", out)) {
      std::fprintf(stderr, "bearing_bench_simd: %s run failed\n", sim.c_str());
      return 1;
    }
  }
  if (!filter.empty()) {  // profiling one row: no ratios
    rows.erase(
        std::remove_if(rows.begin(), rows.end(),
                       [&](const Row& r) { return r.name.find(filter) == std::string::npos; }),
        rows.end());
    for (int i = 0; i < rounds; ++i)
      for (Row& r : rows) r.body();
    return 0;
  }
  for (Row& r : rows) r.body();  // warm-up round
  for (int i = 0; i < rounds; ++i)
    for (Row& r : rows) r.times.push_back(seconds(r.body));

  print_table(rows, rounds, !sim.empty());
  return 0;
}
