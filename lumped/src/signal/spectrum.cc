// Amplitude spectrum through GSL's mixed-radix real FFT (MODEL.md §7).

#include "bearing/signal/spectrum.h"

#include <gsl/gsl_fft_complex.h>
#include <gsl/gsl_fft_real.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>

#include "../edit_distance.h"
#include "bearing/errors.h"
#include "bearing/units.h"

namespace bearing {

namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

struct WindowName {
  std::string_view name;
  Window window;
};
constexpr std::array<WindowName, 3> kWindows{
    {{"hann", Window::hann}, {"flattop", Window::flattop}, {"rectangular", Window::rectangular}}};

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
    table[i] = std::cos(kTwoPi * static_cast<double>(i) / static_cast<double>(n));
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

// The GSL FFT tables, freed however the call ends.
struct WavetableFree {
  void operator()(gsl_fft_real_wavetable* p) const { gsl_fft_real_wavetable_free(p); }
};
struct WorkspaceFree {
  void operator()(gsl_fft_real_workspace* p) const { gsl_fft_real_workspace_free(p); }
};

// Above this largest prime factor of N, GSL's mixed-radix FFT falls back on an O(N·p) generic
// pass (O(N²) for prime N: 0.55 s at N = 24001), so Bluestein's algorithm is used instead.
constexpr std::size_t kLargestMixedRadixFactor = 64;

std::size_t largest_prime_factor(std::size_t n) {
  std::size_t largest = 1;
  for (std::size_t p = 2; p * p <= n; ++p)
    while (n % p == 0) largest = p, n /= p;
  return n > 1 ? n : largest;
}

struct ComplexWavetableFree {
  void operator()(gsl_fft_complex_wavetable* p) const { gsl_fft_complex_wavetable_free(p); }
};
struct ComplexWorkspaceFree {
  void operator()(gsl_fft_complex_workspace* p) const { gsl_fft_complex_workspace_free(p); }
};

// Smallest M ≥ n whose prime factors are 2, 3 and 5 (GSL's fast radices).
std::size_t smooth_length(std::size_t n) {
  std::size_t best = 1;
  while (best < n) best *= 2;
  for (std::size_t p5 = 1; p5 < best; p5 *= 5)
    for (std::size_t p35 = p5; p35 < best; p35 *= 3) {
      std::size_t m = p35;
      while (m < n) m *= 2;
      best = std::min(best, m);
    }
  return best;
}

[[noreturn]] void no_tables(std::size_t n) {
  throw SolverError("amplitude spectrum: GSL could not allocate FFT tables for " +
                    std::to_string(n) + " points");
}

}  // namespace

// X_0 … X_{⌊N/2⌋} of real data of one length N. GSL's mixed-radix real FFT when N's prime
// factors are small; otherwise Bluestein's chirp z-transform: with c_n = exp(iπn²/N),
// nk = (n² + k² − (k−n)²)/2 turns the DFT into X_k = c̄_k Σ_n (x_n c̄_n) c_{k−n}, a circular
// convolution done with complex FFTs of a length M ≥ 2N − 1 with factors 2, 3, 5 only. O(N log N)
// for any N; the bins are still those of length N (no padding of x). The tables (and, for
// Bluestein, the chirp and its transform) depend on N only and are built once.
class SpectrumPlan::Dft {
 public:
  explicit Dft(std::size_t n) : n_(n) {
    if (largest_prime_factor(n) <= kLargestMixedRadixFactor) {
      real_table_.reset(gsl_fft_real_wavetable_alloc(n));
      real_work_.reset(gsl_fft_real_workspace_alloc(n));
      if (!real_table_ || !real_work_) no_tables(n);
      return;
    }
    m_ = smooth_length(2 * n - 1);
    // n² mod 2N in integers keeps the chirp phase exact for large n.
    chirp_.resize(n);
    const std::uint64_t period = 2 * static_cast<std::uint64_t>(n);
    for (std::size_t j = 0; j < n; ++j) {
      const std::uint64_t r = (static_cast<std::uint64_t>(j) * j) % period;
      chirp_[j] = std::polar(1.0, kTwoPi * 0.5 * static_cast<double>(r) / static_cast<double>(n));
    }
    complex_table_.reset(gsl_fft_complex_wavetable_alloc(m_));
    complex_work_.reset(gsl_fft_complex_workspace_alloc(m_));
    if (!complex_table_ || !complex_work_) no_tables(m_);
    // The chirp's transform, packed complex (re, im, …); c_{−j} = c_j sits at M − j.
    chirp_transform_.assign(2 * m_, 0.0);
    for (std::size_t j = 0; j < n; ++j) {
      chirp_transform_[2 * j] = chirp_[j].real();
      chirp_transform_[2 * j + 1] = chirp_[j].imag();
      if (j > 0) {
        chirp_transform_[2 * (m_ - j)] = chirp_[j].real();
        chirp_transform_[2 * (m_ - j) + 1] = chirp_[j].imag();
      }
    }
    complex_transform(chirp_transform_, gsl_fft_forward);
  }

  /// The bins of `data` (length N; overwritten).
  std::vector<std::complex<double>> operator()(std::vector<double>& data) {
    return real_table_ ? mixed_radix(data) : bluestein(data);
  }

 private:
  // Unpacked from GSL's half-complex layout: data[0] = Re X_0; data[2k−1], data[2k] = Re, Im X_k;
  // for even N the last element is Re X_{N/2}.
  std::vector<std::complex<double>> mixed_radix(std::vector<double>& data) {
    if (gsl_fft_real_transform(data.data(), 1, n_, real_table_.get(), real_work_.get()) != 0)
      throw SolverError("amplitude spectrum: GSL real FFT failed for " + std::to_string(n_) +
                        " samples");
    std::vector<std::complex<double>> X(n_ / 2 + 1);
    X[0] = data[0];
    for (std::size_t k = 1; 2 * k < n_; ++k) X[k] = {data[2 * k - 1], data[2 * k]};
    if (n_ % 2 == 0) X[n_ / 2] = data[n_ - 1];
    return X;
  }

  std::vector<std::complex<double>> bluestein(const std::vector<double>& x) {
    std::vector<double> a(2 * m_, 0.0);
    for (std::size_t j = 0; j < n_; ++j) {
      const std::complex<double> v = x[j] * std::conj(chirp_[j]);
      a[2 * j] = v.real();
      a[2 * j + 1] = v.imag();
    }
    complex_transform(a, gsl_fft_forward);
    const std::vector<double>& b = chirp_transform_;
    for (std::size_t j = 0; j < m_; ++j) {
      const std::complex<double> p = std::complex<double>(a[2 * j], a[2 * j + 1]) *
                                     std::complex<double>(b[2 * j], b[2 * j + 1]);
      a[2 * j] = p.real();
      a[2 * j + 1] = p.imag();
    }
    complex_transform(a, gsl_fft_backward);  // unscaled: the 1/M is applied below
    const double inverse_scale = 1.0 / static_cast<double>(m_);
    std::vector<std::complex<double>> X(n_ / 2 + 1);
    for (std::size_t k = 0; k < X.size(); ++k)
      X[k] = inverse_scale * std::conj(chirp_[k]) * std::complex<double>(a[2 * k], a[2 * k + 1]);
    return X;
  }

  void complex_transform(std::vector<double>& packed, gsl_fft_direction sign) {
    if (gsl_fft_complex_transform(packed.data(), 1, m_, complex_table_.get(), complex_work_.get(),
                                  sign) != 0)
      throw SolverError("amplitude spectrum: GSL complex FFT failed for " + std::to_string(m_) +
                        " points");
  }

  std::size_t n_;
  std::unique_ptr<gsl_fft_real_wavetable, WavetableFree> real_table_;
  std::unique_ptr<gsl_fft_real_workspace, WorkspaceFree> real_work_;
  std::size_t m_ = 0;  // Bluestein: convolution length
  std::vector<std::complex<double>> chirp_;
  std::vector<double> chirp_transform_;
  std::unique_ptr<gsl_fft_complex_wavetable, ComplexWavetableFree> complex_table_;
  std::unique_ptr<gsl_fft_complex_workspace, ComplexWorkspaceFree> complex_work_;
};

namespace {}  // namespace

Window parse_window(std::string_view name, const std::string& key) {
  for (const WindowName& w : kWindows)
    if (name == w.name) return w.window;

  std::string_view nearest = kWindows[0].name;
  std::size_t best = detail::edit_distance(name, nearest);
  for (const WindowName& w : kWindows) {
    const std::size_t d = detail::edit_distance(name, w.name);
    if (d < best) best = d, nearest = w.name;
  }
  std::string msg = key + " = \"" + std::string(name) +
                    "\": unknown window; allowed: \"hann\", \"flattop\", \"rectangular\"";
  if (best <= 3) msg += " (did you mean \"" + std::string(nearest) + "\"?)";
  throw InputError(msg);
}

std::string_view window_name(Window window) {
  for (const WindowName& w : kWindows)
    if (w.window == window) return w.name;
  return "unknown";
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
  dft_ = std::make_unique<Dft>(n);
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
  const std::vector<std::complex<double>> X = (*dft_)(data);

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
