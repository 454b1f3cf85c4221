// Amplitude spectrum through the real FFT of fft.h (docs/model.md §7).

#include "bearing/signal/spectrum.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/signal/fft.h"
#include "bearing/units.h"

namespace bearing {

namespace {

// Periodic cosine-sum windows w_j = Σ_m c_m cos(m·2πj/N); signs folded into c_m.
constexpr std::array<double, 2> kHann{0.5, -0.5};
// HFT90D (Heinzel, Rüdiger & Schilling 2002, §D) in their scale (c_0 = 1); the scale cancels in
// the coherent gain.
constexpr std::array<double, 5> kHft90d{1.0, -1.942604, 1.340318, -0.440811, 0.043097};

// cos(m·2πj/N) is read from one table of cos(2πi/N) at i = m·j mod N: one cosine per sample
// instead of M − 1, and exact periodicity.
template <std::size_t M>
std::vector<double> cosine_sum(std::size_t n, const std::array<double, M>& c) {
  std::vector<double> table(n);
  for (std::size_t i = 0; i < n; ++i)
    table[i] = std::cos(two_pi * static_cast<double>(i) / static_cast<double>(n));
  std::vector<double> w(n);
  for (std::size_t j = 0; j < n; ++j) {
    double s = c[0];
    for (std::size_t m = 1; m < M; ++m) s += c[m] * table[(m * j) % n];
    w[j] = s;
  }
  return w;
}

std::vector<double> window_values(Window window, std::size_t n) {
  switch (window) {
    case Window::hann:
      return cosine_sum(n, kHann);
    case Window::flattop:
      return cosine_sum(n, kHft90d);
    case Window::rectangular:
      break;
  }
  return std::vector<double>(n, 1.0);
}

}  // namespace

Window parse_window(std::string_view name, const std::string& key) {
  return parse_named(kWindows, name, key, "window");
}

std::string_view window_name(Window window) {
  return name_of(kWindows, window);
}

SpectrumPlan::SpectrumPlan(std::size_t n, double sample_rate, Window window)
    : n_(n), sample_rate_(sample_rate) {
  if (n < 2)
    throw InputError("amplitude spectrum: " + std::to_string(n) +
                     " samples given; at least 2 are needed");
  if (!(std::isfinite(sample_rate) && sample_rate > 0))
    throw InputError("amplitude spectrum: sample rate = " + format_number(sample_rate) +
                     " Hz: must be positive and finite");
  window_ = window_values(window, n);
  for (double w : window_) window_sum_ += w;
  dft_ = std::make_unique<RealFft>(n);
}

SpectrumPlan::~SpectrumPlan() = default;
SpectrumPlan::SpectrumPlan(SpectrumPlan&&) noexcept = default;
SpectrumPlan& SpectrumPlan::operator=(SpectrumPlan&&) noexcept = default;

Spectrum SpectrumPlan::operator()(const std::vector<double>& x) {
  const std::size_t n = n_;
  if (x.size() != n)
    throw InputError("amplitude spectrum: " + std::to_string(x.size()) +
                     " samples given to a plan for " + std::to_string(n));
  double largest = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(x[i]))
      throw InputError("amplitude spectrum: sample " + std::to_string(i) + " = " +
                       format_number(x[i]) + ": every sample must be finite");
    largest = std::max(largest, std::abs(x[i]));
  }
  // Work on x / 2^e ≤ 1 (exact) so neither the mean nor the FFT can overflow for huge values
  // (and |X_k| ≤ N, so the modulus needs no hypot).
  int exponent = 0;
  std::frexp(largest, &exponent);
  const double scale = std::ldexp(1.0, exponent);
  double sum = 0;
  for (double v : x) sum += v / scale;
  const double mean = sum / static_cast<double>(n);

  std::vector<double> data(n);
  for (std::size_t i = 0; i < n; ++i) data[i] = window_[i] * (x[i] / scale - mean);
  const std::vector<std::complex<double>> X = dft_->forward(data);

  const std::size_t bins = n / 2 + 1;
  Spectrum s;
  s.resolution = sample_rate_ / static_cast<double>(n);
  s.frequency.resize(bins);
  s.amplitude.resize(bins);
  const double gain = scale / window_sum_;  // window_sum_ = N × coherent gain
  for (std::size_t k = 0; k < bins; ++k) {
    s.frequency[k] = static_cast<double>(k) * s.resolution;
    const bool single = k == 0 || 2 * k == n;  // DC and Nyquist have no mirror bin
    const double modulus = std::sqrt(X[k].real() * X[k].real() + X[k].imag() * X[k].imag());
    s.amplitude[k] = (single ? 1.0 : 2.0) * gain * modulus;
  }
  return s;
}

Spectrum amplitude_spectrum(const std::vector<double>& x, double sample_rate, Window window) {
  SpectrumPlan plan(x.size(), sample_rate, window);
  return plan(x);
}

}  // namespace bearing
