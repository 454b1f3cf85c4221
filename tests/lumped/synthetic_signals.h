#pragma once
// Test signals shared by the signal and envelope-analysis tests: a fixed-seed random generator of
// our own (std:: distributions differ between standard libraries) and the vibration of a
// structural resonance struck by a train of impacts, the signature of a local bearing fault.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "bearing/constants.h"

namespace bearing::test {

/// SplitMix64 (Steele, Lea & Flood 2014): uniform and normal variates, the same on every platform.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return (static_cast<double>(next() >> 11) + 0.5) * 0x1.0p-53; }  // (0, 1)
  // Box–Muller; the second variate is dropped to keep it short.
  double normal() {
    const double u1 = uniform(), u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(two_pi * u2);
  }

 private:
  std::uint64_t state_;
};

/// A resonance struck by impacts: each impact at t_j = j / rate rings as
/// a_j e^{−ζ ω_n (t − t_j)} sin(ω_d (t − t_j)), ω_d = ω_n √(1 − ζ²), with the strength
/// a_j = 1 + depth · cos(2π f_m t_j) (a defect passing through the load zone: f_m = f_r for the
/// inner race, FTF for a ball).
struct ImpactTrain {
  double rate = 97;             ///< impacts per second [Hz]
  double resonance = 5000;      ///< f_n [Hz]
  double damping_ratio = 0.02;  ///< ζ [-]
  double modulation = 0;        ///< f_m [Hz]
  double depth = 0;             ///< modulation depth [-], ≤ 1
  /// Each impact's time jitters by this fraction of the period (normal, standard deviation) [-]:
  /// a real fault's balls slip, so its train is not periodic (0: exactly periodic).
  double jitter = 0;
  std::uint64_t seed = 1;  ///< of the jitter
};

/// n samples at `sample_rate` [Hz] of the train (each impact's ringing followed for 20 time
/// constants).
inline std::vector<double> impact_train(const ImpactTrain& p, std::size_t n, double sample_rate) {
  std::vector<double> x(n, 0.0);
  const double wn = two_pi * p.resonance, decay = p.damping_ratio * wn;
  const double wd = wn * std::sqrt(1 - p.damping_ratio * p.damping_ratio);
  const double duration = static_cast<double>(n) / sample_rate;
  SplitMix64 g(p.seed);
  for (int j = 0; j / p.rate < duration; ++j) {
    const double tj = std::max(0.0, (j + (p.jitter > 0 ? p.jitter * g.normal() : 0.0)) / p.rate);
    const double a = 1 + p.depth * std::cos(two_pi * p.modulation * tj);
    const auto first = static_cast<std::size_t>(std::ceil(tj * sample_rate));
    for (std::size_t i = first; i < n; ++i) {
      const double t = static_cast<double>(i) / sample_rate - tj;
      if (decay * t > 20) break;
      x[i] += a * std::exp(-decay * t) * std::sin(wd * t);
    }
  }
  return x;
}

/// The RMS of x [unit of x].
inline double rms(const std::vector<double>& x) {
  double s = 0;
  for (double v : x) s += v * v;
  return std::sqrt(s / static_cast<double>(x.size()));
}

/// x plus white Gaussian noise whose RMS is rms(x) / 10^(snr_db / 20), from `seed`.
inline std::vector<double> with_noise(std::vector<double> x, double snr_db, std::uint64_t seed) {
  SplitMix64 g(seed);
  const double sigma = rms(x) / std::pow(10.0, snr_db / 20);
  for (double& v : x) v += sigma * g.normal();
  return x;
}

}  // namespace bearing::test
