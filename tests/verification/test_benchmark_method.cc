// The benchmark method of the measured family (verification/src/benchmark_method.h) on synthetic
// signals with a known answer: its threshold's closed forms, its false-alarm rate on Gaussian noise
// (measured, against the stated α), cyclostationary impulses with jitter, and a deterministic line.

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "bearing/errors.h"
#include "benchmark_method.h"

namespace bearing::verify {
namespace {

constexpr double kPi = 3.14159265358979323846;
// The 6205 of the CWRU data: BPFO, BPFI and 2·BSF as multiples of the shaft frequency.
const DefectMultiples k6205{3.5848, 5.4152, 4.7135};

TEST(BenchmarkMethod, ThresholdsSolveTheirDefinitions) {
  for (double alpha : {1e-3, 0.05}) {
    const double p = per_harmonic_probability(alpha);
    EXPECT_NEAR(3 * p * p - 2 * p * p * p, alpha, 1e-12 * alpha);
    for (int w : {1, 7, 40}) {
      const double t = exceedance_threshold(p, w);
      EXPECT_NEAR(1 - std::pow(1 - std::exp(-t), w), p, 1e-12);
    }
  }
}

// White Gaussian records: each family is detected at the stated rate. 400 records of 2^14 samples
// at α = 0.05 per family: the count per family is binomial(400, α) under the method's null model,
// so 20 ± 4.4; the bound is 5 standard deviations (a false failure once in ~3.5 million runs).
TEST(BenchmarkMethod, FalseAlarmRateOnGaussianNoiseIsTheStatedOne) {
  const double alpha = 0.05;
  const int records = 400;
  std::mt19937_64 gen(41);
  std::normal_distribution<double> noise(0.0, 1.0);
  int detected[3] = {0, 0, 0}, verdicts = 0;
  for (int r = 0; r < records; ++r) {
    std::vector<double> x(16384);
    for (double& v : x) v = noise(gen);
    const BenchmarkVerdict v = benchmark_method(x, 12000.0, 29.93, k6205, alpha);
    for (int f = 0; f < 3; ++f) detected[f] += v.families[static_cast<std::size_t>(f)].detected;
    verdicts += v.family != "none";
  }
  const double mean = alpha * records, sd = std::sqrt(records * alpha * (1 - alpha));
  for (int f = 0; f < 3; ++f) EXPECT_NEAR(detected[f], mean, 5 * sd) << "family " << f;
  EXPECT_LE(verdicts, detected[0] + detected[1] + detected[2]);
}

// Impulses at BPFO with 1 % jitter of each interval (Antoni & Randall's model), each ringing a
// 3 kHz resonance, in white noise of the same RMS: the method says outer; the other families stay
// below detection.
TEST(BenchmarkMethod, JitteredImpulsesAtBpfoAreOuter) {
  const double fs = 12000.0, fr = 29.93, bpfo = k6205.bpfo * fr;
  std::mt19937_64 gen(7);
  std::normal_distribution<double> unit(0.0, 1.0);
  std::vector<double> x(120000, 0.0);
  double t = 0.01;
  while (t < x.size() / fs) {
    const std::size_t i0 = static_cast<std::size_t>(t * fs);
    for (std::size_t i = i0; i < std::min(x.size(), i0 + 240); ++i) {
      const double s = (static_cast<double>(i) - t * fs) / fs;
      x[i] += std::exp(-600.0 * s) * std::sin(2 * kPi * 3000.0 * s);
    }
    t += (1.0 + 0.01 * unit(gen)) / bpfo;
  }
  double rms = 0;
  for (double v : x) rms += v * v / static_cast<double>(x.size());
  rms = std::sqrt(rms);
  for (double& v : x) v += rms * unit(gen);
  const BenchmarkVerdict v = benchmark_method(x, fs, fr, k6205);
  EXPECT_EQ(v.family, "outer");
  EXPECT_EQ(v.families[0].standing_out, 3);
  EXPECT_NEAR(v.families[0].found[0], bpfo, 0.02 * bpfo);
  EXPECT_FALSE(v.families[1].detected);
  EXPECT_FALSE(v.families[2].detected);
}

// Deterministic lines at BPFI and its harmonics, off the FFT's bins, each with half the noise's
// power: cepstral pre-whitening sets every bin's magnitude to one, so they weigh no more than the
// noise: none. (Much stronger lines are another matter: a whole-record FFT leaks a line over
// hundreds of bins whose phases stay coherent after whitening, and five lines 7 dB over the whole
// broadband noise make the inner family stand out; benchmark_method.h says so.)
TEST(BenchmarkMethod, DeterministicLinesAreNotAFault) {
  const double fs = 12000.0, fr = 29.93, bpfi = k6205.bpfi * fr;
  std::mt19937_64 gen(3);
  std::normal_distribution<double> unit(0.0, 1.0);
  std::vector<double> x(120000);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double s = static_cast<double>(i) / fs;
    x[i] = unit(gen);
    for (int h = 1; h <= 5; ++h) x[i] += std::sin(2 * kPi * h * bpfi * s + h);
  }
  const BenchmarkVerdict v = benchmark_method(x, fs, fr, k6205);
  EXPECT_EQ(v.family, "none");
  EXPECT_FALSE(v.families[1].detected);
}

TEST(BenchmarkMethod, BadInputIsRefused) {
  const std::vector<double> x(4096, 0.0);
  EXPECT_THROW(benchmark_method(x, 12000.0, 29.93, k6205, 0.0), InputError);
  EXPECT_THROW(benchmark_method(x, 100.0, 29.93, k6205), InputError);  // above Nyquist
  EXPECT_THROW(benchmark_method(std::vector<double>(10, 1.0), 12000.0, 29.93, k6205), InputError);
  std::vector<double> bad(4096, 0.0);
  bad[5] = std::nan("");
  EXPECT_THROW(benchmark_method(bad, 12000.0, 29.93, k6205), InputError);
}

}  // namespace
}  // namespace bearing::verify
