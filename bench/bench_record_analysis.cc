// Issues 29 and 41's benchmark: analyse_record() of a 10 s record at 12 kHz (target < 0.5 s on one
// core, the kurtogram and the default rule's cyclic-coherence map included). The record is
// synthetic and of the CWRU rig's kind: a 6205 at 1797 rpm whose inner race strikes a 3 kHz
// resonance at BPFI (1 % jitter), modulated at the shaft rate, in Gaussian noise, with shaft
// harmonics. Rows: the kurtogram's band, the same with pre-whitening, with the speed estimated, and
// a given band; each timed in interleaved rounds (one row after the other, round after round, so
// load from other processes spreads over all of them), min and median. A second length, 121 265
// samples (CWRU record 105's, with the prime factor 24 253), shows the cost of a length without
// small factors (Bluestein FFTs). Prints a table (bench/README.md).
//
//   bearing_bench_record [ROUNDS]      (default 15)

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bearing/constants.h"
#include "bearing/presets.h"
#include "bearing/record_analysis.h"

namespace {

// SplitMix64 normal variates (as the tests' synthetic_signals.h): the same record everywhere.
struct Noise {
  unsigned long long state;
  double uniform() {
    unsigned long long z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (static_cast<double>(z >> 11) + 0.5) * 0x1.0p-53;
  }
  double normal() {
    const double u1 = uniform(), u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(bearing::two_pi * u2);
  }
};

std::vector<double> record(std::size_t n, double rate, double shaft, double bpfi) {
  std::vector<double> x(n, 0.0);
  Noise noise{7};
  const double wn = bearing::two_pi * 3000, decay = 0.05 * wn;
  for (int j = 0; j / bpfi < n / rate; ++j) {
    // Each impact jitters by 1 % of the period (the balls slip): a real fault's train is not
    // periodic, which is what pre-whitening (it flattens discrete lines) relies on.
    const double tj = (j + 0.01 * noise.normal()) / bpfi;
    const double a = 1 + 0.5 * std::cos(bearing::two_pi * shaft * tj);
    for (auto i = static_cast<std::size_t>(std::ceil(std::max(0.0, tj) * rate)); i < n; ++i) {
      const double t = i / rate - tj;
      if (decay * t > 20) break;
      x[i] += a * std::exp(-decay * t) * std::sin(wn * t);
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double t = i / rate;
    x[i] += 0.5 * noise.normal() + 0.3 * std::sin(bearing::two_pi * shaft * t) +
            0.2 * std::sin(bearing::two_pi * 2 * shaft * t + 1);
  }
  return x;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 15;
  const double rate = 12000, speed = 1797 * bearing::two_pi / 60;
  const bearing::Bearing b = bearing::preset("6205");
  const bearing::BearingFrequencies f = bearing::bearing_frequencies(b, speed);
  struct Row {
    const char* name;
    std::size_t n;
    bearing::RecordAnalysisSettings settings;
    bearing::SpeedSource speed;
  };
  bearing::RecordAnalysisSettings automatic, whitened, given;
  whitened.prewhiten = true;
  given.envelope = {bearing::EnvelopeBandSource::given, {2000, 4000}};
  const std::vector<Row> rows = {
      {"kurtogram", 120000, automatic, bearing::SpeedSource::option},
      {"kurtogram, pre-whitened", 120000, whitened, bearing::SpeedSource::option},
      {"kurtogram, speed estimated", 120000, automatic, bearing::SpeedSource::estimate},
      {"kurtogram, pre-whitened, speed estimated", 120000, whitened,
       bearing::SpeedSource::estimate},
      {"given band 2-4 kHz", 120000, given, bearing::SpeedSource::option},
      {"kurtogram, 121 265 samples", 121265, automatic, bearing::SpeedSource::option},
  };
  std::vector<std::vector<double>> records;
  for (const Row& r : rows) records.push_back(record(r.n, rate, f.shaft, f.bpfi));
  std::vector<std::vector<double>> seconds(rows.size());
  std::vector<std::string> verdicts(rows.size());
  for (int round = -1; round < rounds; ++round)  // round −1: warm-up, not counted
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const auto start = std::chrono::steady_clock::now();
      const bearing::RecordAnalysis a = bearing::analyse_record(
          records[i], rate, "DE", "m/s^2", b, {rows[i].speed, speed}, rows[i].settings);
      const auto stop = std::chrono::steady_clock::now();
      verdicts[i] = bearing::name_of(bearing::kFaultFamilies, a.family());
      if (round >= 0) seconds[i].push_back(std::chrono::duration<double>(stop - start).count());
    }
  std::printf(
      "| analysis (6205, 1797 rpm, 12 kHz) | samples | rounds | min [ms] | median [ms] | "
      "diagnosis | target | status |\n");
  std::printf("| --- | ---: | ---: | ---: | ---: | --- | --- | --- |\n");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double lo = *std::min_element(seconds[i].begin(), seconds[i].end());
    const double mid = median(seconds[i]);
    std::printf("| %s | %zu | %d | %.1f | %.1f | %s | < 500 ms | %s |\n", rows[i].name, rows[i].n,
                rounds, 1e3 * lo, 1e3 * mid, verdicts[i].c_str(),
                mid < 0.5 ? "**MET**" : "NOT MET");
  }
  return 0;
}
