// Issue 40 §3, its cost target: 20 structure modes add at most 30 % to a 2-DOF run. Interleaved
// rounds (each round times every row once, so load from other processes spreads over all of
// them); prints a table of minima and medians and each row's ratio to the plain 2-DOF run
// (bench/README.md, "Issue 40").
//
//   bearing_bench_housing_modes [ROUNDS] [BEARING_SIM|""] [ROW]   (ROW: run only the rows whose
//                                                                  name holds it, untimed)
//
// Rows, all on the built-in default case (6308, 2000 rpm, 20 N, 2-DOF, RK4 at 5 us, 1.2 s,
// output at 20 kHz):
//   simulate             simulate(case): the model built, integrated and every output instant
//                        recorded (no analysis, no files): plain; on the 3.4 kHz resonator of
//                        [housing] mass/frequency; on M = 20 structure modes (1-20 kHz, a
//                        synthetic modes file written here, deterministic) with one sensor
//   the modes' RK4 floor  RK4 written out by hand for the 20 modes alone, as 20 damped oscillators
//                        (40 states, a constant force, no contact), the same 240 000 steps of 5 us:
//                        what integrating the modal coordinates costs before any coupling, the
//                        least that 20 modes can add to the plain run with RK4 on the whole state
//   bearing-sim run      the whole process (case, simulation, FFT, CSV and JSON into a temporary
//                        folder) for the same three cases, when BEARING_SIM is given

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "bearing/case_file.h"
#include "bearing/simulation.h"
#include "bearing/structure_modes.h"

extern char** environ;

namespace {

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

volatile double g_sink = 0;  // keeps the results alive

// M modes between 1 and 20 kHz with seat and sensor shapes of a few tenths of kg^-1/2 (a
// structure of a few kg), fixed by a seeded generator: the cost does not depend on the values.
std::string write_modes_file(const std::string& path, int modes) {
  std::mt19937_64 gen(40);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> f(static_cast<std::size_t>(modes));
  for (double& x : f) x = 1000.0 + 19000.0 * unit(gen);
  std::sort(f.begin(), f.end());
  const auto list = [&](bool shape) {
    std::string s = "[";
    for (int k = 0; k < modes; ++k) {
      char buf[40];
      std::snprintf(buf, sizeof buf, "%s%.17g", k ? ", " : "",
                    shape ? 0.6 * (unit(gen) - 0.5) : f[static_cast<std::size_t>(k)]);
      s += buf;
    }
    return s + "]";
  };
  std::ofstream out(path);
  out << "{\"format\": \"bearing-fem modes\", \"version\": 1, \"boundary\": {\"free\": false},\n"
      << " \"frequencies\": " << list(false) << ",\n"
      << " \"seat\": {\"x\": " << list(true) << ", \"y\": " << list(true)
      << ", \"z\": " << list(true) << "},\n"
      << " \"sensors\": [{\"name\": \"top\", \"point\": [0, 0.06, 0], \"x\": " << list(true)
      << ", \"y\": " << list(true) << ", \"z\": " << list(true) << "}]}\n";
  return path;
}

// The whole `bearing-sim run CASE --out DIR` as a child process, waited for.
void run_process(const std::string& sim, const std::string& case_file, const std::string& out) {
  std::vector<std::string> args{sim, "run", case_file, "--out", out};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  if (posix_spawn(&pid, sim.c_str(), &actions, nullptr, argv.data(), environ) != 0) {
    std::perror("posix_spawn");
    std::exit(1);
  }
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "bearing-sim run %s failed\n", case_file.c_str());
    std::exit(1);
  }
}

struct Row {
  std::string name;
  std::function<void()> work;
  std::size_t base = 0;  // the row its ratio is to
  std::vector<double> times;
};

// RK4 of M decoupled damped oscillators q'' = F - 2 zeta w q' - w^2 q (mass-normalised modes), the
// state's arithmetic of four stages per step; returns a value so the loop is not optimised away.
double modal_rk4_floor(int modes, long steps, double dt) {
  const std::size_t m = static_cast<std::size_t>(modes);
  std::vector<double> w2(m), c(m), q(m, 0.0), v(m, 0.0), kq[4], kv[4], qs(m), vs(m);
  for (std::size_t k = 0; k < m; ++k) {
    const double w = 2 * 3.141592653589793 * (1000.0 + 950.0 * static_cast<double>(k));
    w2[k] = w * w, c[k] = 2 * 0.02 * w;
  }
  for (auto& x : kq) x.assign(m, 0.0);
  for (auto& x : kv) x.assign(m, 0.0);
  const double a[] = {0.0, 0.5 * dt, 0.5 * dt, dt};
  for (long n = 0; n < steps; ++n) {
    for (int s = 0; s < 4; ++s) {
      for (std::size_t k = 0; k < m; ++k) {
        qs[k] = s ? q[k] + a[s] * kq[s - 1][k] : q[k];
        vs[k] = s ? v[k] + a[s] * kv[s - 1][k] : v[k];
        kq[s][k] = vs[k];
        kv[s][k] = 1.0 - c[k] * vs[k] - w2[k] * qs[k];
      }
    }
    for (std::size_t k = 0; k < m; ++k) {
      q[k] += dt / 6 * (kq[0][k] + 2 * kq[1][k] + 2 * kq[2][k] + kq[3][k]);
      v[k] += dt / 6 * (kv[0][k] + 2 * kv[1][k] + 2 * kv[2][k] + kv[3][k]);
    }
  }
  return q[0] + v[m - 1];
}

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::atoi(argv[1]) : 15;
  const std::string sim = argc > 2 ? argv[2] : "";
  const std::string only = argc > 3 ? argv[3] : "";
  char dir_template[] = "/tmp/bench_housing_modes.XXXXXX";
  const std::string dir = mkdtemp(dir_template);
  const std::string modes = write_modes_file(dir + "/modes20.json", 20);

  // The three cases as files (for the process rows) and as Cases (for simulate()).
  const std::string base(bearing::default_case_toml());
  const std::string resonator_toml =
      base + "\n[housing]\nmass = \"2 kg\"\nfrequency = \"3.4 kHz\"\ndamping_ratio = 0.05\n";
  const std::string modes_toml =
      base + "\n[housing]\nmodes = \"" + modes + "\"\ndamping_ratio = 0.02\n";
  const std::string files[] = {dir + "/plain.toml", dir + "/resonator.toml", dir + "/modes.toml"};
  const std::string texts[] = {base, resonator_toml, modes_toml};
  std::vector<bearing::Case> cases;
  for (int i = 0; i < 3; ++i) {
    std::ofstream(files[i]) << texts[i];
    cases.push_back(bearing::read_case_file(files[i]));
  }
  const char* names[] = {"plain 2-DOF", "resonator (2 DOFs)", "20 modes"};

  std::vector<Row> rows;
  for (int i = 0; i < 3; ++i)
    rows.push_back({std::string("simulate: ") + names[i],
                    [&cases, i] {
                      const bearing::SimulationResult r = bearing::simulate(cases[i]);
                      g_sink = g_sink + r.response.values[1].back();
                    },
                    0,
                    {}});
  // The default case's steps: duration / dt.
  const long steps = std::lround(cases[0].solver.duration / cases[0].solver.dt);
  const double dt = cases[0].solver.dt;
  rows.push_back({"the modes' RK4 floor (20, no contact)",
                  [steps, dt] { g_sink = g_sink + modal_rk4_floor(20, steps, dt); },
                  0,
                  {}});
  if (!sim.empty())
    for (int i = 0; i < 3; ++i)
      rows.push_back({std::string("bearing-sim run: ") + names[i],
                      [&sim, &files, &dir, i] { run_process(sim, files[i], dir + "/out"); },
                      4,
                      {}});

  if (!only.empty()) {
    for (Row& r : rows)
      if (r.name.find(only) != std::string::npos) r.work();
    return 0;
  }
  for (Row& r : rows) r.work();  // warm-up
  for (int k = 0; k < rounds; ++k)
    for (Row& r : rows) r.times.push_back(seconds(r.work));

  std::printf("%d interleaved rounds; ratios to the plain row of the same kind, on the minima\n",
              rounds);
  std::printf("%-36s %10s %10s %8s\n", "row", "min [ms]", "median", "ratio");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& base_row = rows[rows[i].base];
    std::printf("%-36s %10.2f %10.2f %8.3f\n", rows[i].name.c_str(), 1e3 * minimum(rows[i].times),
                1e3 * median(rows[i].times), minimum(rows[i].times) / minimum(base_row.times));
  }
  std::string cleanup = "rm -rf '" + dir + "'";
  return std::system(cleanup.c_str()) == 0 ? 0 : 1;
}
