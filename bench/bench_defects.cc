// Issue 17's benchmark: the cost of a run with a local defect against the same run without, for
// every dynamic model kind (target ≤ 1.2×). The case is examples/cwru_6205_outer.toml (0.533 mm
// outer-race spall, 1797 rpm), 0.5 s simulated, RK4 at 5 µs; "without" is the same case with its
// [[defects]] removed. The two are timed in interleaved rounds (with, without, with, …), so load
// from other processes spreads over both; the ratio is taken of the medians and of the minima.
// Prints a table (bench/README.md, "Local defects").

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bearing/case_file.h"
#include "bearing/simulation.h"

namespace {

double seconds_of(const bearing::Case& c) {
  const auto start = std::chrono::steady_clock::now();
  const bearing::SimulationResult r = bearing::simulate(c);
  const auto stop = std::chrono::steady_clock::now();
  if (r.response.time.empty()) std::puts("empty response");
  return std::chrono::duration<double>(stop - start).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 9;
  const std::string path = std::string(BEARING_EXAMPLES_DIR) + "/cwru_6205_outer.toml";
  std::printf(
      "| model | runs | with defect: min, median [ms] | without: min, median [ms] | "
      "ratio of medians | ratio of minima | target | status |\n");
  std::printf("| --- | ---: | ---: | ---: | ---: | ---: | --- | --- |\n");
  for (const char* kind : {"2dof", "3dof", "balls"}) {
    std::vector<bearing::Override> o{{"model.kind", kind}, {"solver.duration", "0.5 s"}};
    if (std::string(kind) == "3dof") o.push_back({"operation.axial_load", "100 N"});
    const bearing::Case with = bearing::read_case_file(path, o);
    bearing::Case without = with;
    without.excitation.defects.clear();
    std::vector<double> a, b;
    seconds_of(with), seconds_of(without);  // warm-up
    for (int i = 0; i < rounds; ++i) {
      a.push_back(seconds_of(with));
      b.push_back(seconds_of(without));
    }
    const double ratio = median(a) / median(b);
    const double ratio_min =
        *std::min_element(a.begin(), a.end()) / *std::min_element(b.begin(), b.end());
    std::printf("| %s | %d | %.1f, %.1f | %.1f, %.1f | %.3f× | %.3f× | ≤ 1.2× | %s |\n", kind,
                rounds, 1e3 * *std::min_element(a.begin(), a.end()), 1e3 * median(a),
                1e3 * *std::min_element(b.begin(), b.end()), 1e3 * median(b), ratio, ratio_min,
                std::max(ratio, ratio_min) <= 1.2 ? "**MET**" : "NOT MET");
  }
  return 0;
}
