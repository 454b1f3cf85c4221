// Real DFT both ways: GSL's mixed-radix FFT, or Bluestein's algorithm for lengths with a large
// prime factor; complex DFT of fast lengths: GSL's mixed-radix FFT.

#include "bearing/signal/fft.h"

#include <gsl/gsl_fft_complex.h>
#include <gsl/gsl_fft_halfcomplex.h>
#include <gsl/gsl_fft_real.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "bearing/constants.h"
#include "bearing/errors.h"

namespace bearing {

namespace {

// Above this largest prime factor of N, GSL's mixed-radix FFT falls back on an O(N·p) generic
// pass (O(N²) for prime N: 0.55 s at N = 24001), so Bluestein's algorithm is used instead.
constexpr std::size_t kLargestMixedRadixFactor = 64;

std::size_t largest_prime_factor(std::size_t n) {
  std::size_t largest = 1;
  for (std::size_t p = 2; p * p <= n; ++p)
    while (n % p == 0) largest = p, n /= p;
  return n > 1 ? n : largest;
}

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
  throw SolverError("FFT: GSL could not allocate its tables for " + std::to_string(n) + " points");
}

struct RealTableFree {
  void operator()(gsl_fft_real_wavetable* p) const { gsl_fft_real_wavetable_free(p); }
};
struct HalfcomplexTableFree {
  void operator()(gsl_fft_halfcomplex_wavetable* p) const { gsl_fft_halfcomplex_wavetable_free(p); }
};
struct RealWorkFree {
  void operator()(gsl_fft_real_workspace* p) const { gsl_fft_real_workspace_free(p); }
};
struct ComplexTableFree {
  void operator()(gsl_fft_complex_wavetable* p) const { gsl_fft_complex_wavetable_free(p); }
};
struct ComplexWorkFree {
  void operator()(gsl_fft_complex_workspace* p) const { gsl_fft_complex_workspace_free(p); }
};

}  // namespace

// Bluestein's chirp z-transform: with c_n = exp(iπn²/N), nk = (n² + k² − (k−n)²)/2 turns the DFT
// into X_k = c̄_k Σ_n (x_n c̄_n) c_{k−n}, a circular convolution done with complex FFTs of a length
// M ≥ 2N − 1 with factors 2, 3, 5 only. The inverse uses x = conj(DFT(conj X)) / N on the full
// Hermitian spectrum. The tables (and, for Bluestein, the chirp and its transform) depend on N
// only and are built once.
class RealFft::Tables {
 public:
  explicit Tables(std::size_t n) : n_(n) {
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
      chirp_[j] = std::polar(1.0, two_pi * 0.5 * static_cast<double>(r) / static_cast<double>(n));
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

  std::vector<std::complex<double>> forward(std::vector<double>& data) {
    const std::size_t bins = n_ / 2 + 1;
    if (real_table_) {
      // GSL's half-complex layout: data[0] = Re X_0; data[2k−1], data[2k] = Re, Im X_k; for even
      // N the last element is Re X_{N/2}.
      if (gsl_fft_real_transform(data.data(), 1, n_, real_table_.get(), real_work_.get()) != 0)
        throw SolverError("FFT: GSL real transform failed for " + std::to_string(n_) + " points");
      std::vector<std::complex<double>> X(bins);
      X[0] = data[0];
      for (std::size_t k = 1; 2 * k < n_; ++k) X[k] = {data[2 * k - 1], data[2 * k]};
      if (n_ % 2 == 0) X[n_ / 2] = data[n_ - 1];
      return X;
    }
    std::vector<std::complex<double>> x(data.begin(), data.end());
    return bluestein(x, bins);
  }

  std::vector<double> inverse(const std::vector<std::complex<double>>& X) {
    std::vector<double> x(n_);
    if (real_table_) {
      if (!halfcomplex_table_) {
        halfcomplex_table_.reset(gsl_fft_halfcomplex_wavetable_alloc(n_));
        if (!halfcomplex_table_) no_tables(n_);
      }
      x[0] = X[0].real();
      for (std::size_t k = 1; 2 * k < n_; ++k) x[2 * k - 1] = X[k].real(), x[2 * k] = X[k].imag();
      if (n_ % 2 == 0) x[n_ - 1] = X[n_ / 2].real();
      if (gsl_fft_halfcomplex_inverse(x.data(), 1, n_, halfcomplex_table_.get(),
                                      real_work_.get()) != 0)
        throw SolverError("FFT: GSL half-complex inverse failed for " + std::to_string(n_) +
                          " points");
      return x;
    }
    // conj X over all N bins (X_{N−k} = conj X_k), then x = Re conj(DFT(conj X)) / N.
    std::vector<std::complex<double>> full(n_);
    for (std::size_t k = 0; k < n_; ++k) {
      const std::size_t m = 2 * k <= n_ ? k : n_ - k;
      std::complex<double> v = X[m];
      if (m == 0 || 2 * m == n_) v = v.real();  // DC and Nyquist of real data are real
      full[k] = 2 * k <= n_ ? std::conj(v) : v;
    }
    const std::vector<std::complex<double>> y = bluestein(full, n_);
    const double scale = 1.0 / static_cast<double>(n_);
    for (std::size_t j = 0; j < n_; ++j) x[j] = scale * y[j].real();
    return x;
  }

 private:
  // The first `count` bins of the DFT of complex x (length N).
  std::vector<std::complex<double>> bluestein(const std::vector<std::complex<double>>& x,
                                              std::size_t count) {
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
    std::vector<std::complex<double>> X(count);
    for (std::size_t k = 0; k < count; ++k)
      X[k] = inverse_scale * std::conj(chirp_[k]) * std::complex<double>(a[2 * k], a[2 * k + 1]);
    return X;
  }

  void complex_transform(std::vector<double>& packed, gsl_fft_direction sign) {
    if (gsl_fft_complex_transform(packed.data(), 1, m_, complex_table_.get(), complex_work_.get(),
                                  sign) != 0)
      throw SolverError("FFT: GSL complex transform failed for " + std::to_string(m_) + " points");
  }

  std::size_t n_;
  std::unique_ptr<gsl_fft_real_wavetable, RealTableFree> real_table_;
  std::unique_ptr<gsl_fft_halfcomplex_wavetable, HalfcomplexTableFree> halfcomplex_table_;
  std::unique_ptr<gsl_fft_real_workspace, RealWorkFree> real_work_;
  std::size_t m_ = 0;  // Bluestein: convolution length
  std::vector<std::complex<double>> chirp_;
  std::vector<double> chirp_transform_;
  std::unique_ptr<gsl_fft_complex_wavetable, ComplexTableFree> complex_table_;
  std::unique_ptr<gsl_fft_complex_workspace, ComplexWorkFree> complex_work_;
};

RealFft::RealFft(std::size_t n) : n_(n) {
  if (n < 2)
    throw InputError("FFT: " + std::to_string(n) + " samples given; at least 2 are needed");
  tables_ = std::make_unique<Tables>(n);
}

RealFft::~RealFft() = default;
RealFft::RealFft(RealFft&&) noexcept = default;
RealFft& RealFft::operator=(RealFft&&) noexcept = default;

std::vector<std::complex<double>> RealFft::forward(std::vector<double>& x) {
  if (x.size() != n_)
    throw InputError("FFT: " + std::to_string(x.size()) + " samples given to a transform of " +
                     std::to_string(n_));
  return tables_->forward(x);
}

std::vector<double> RealFft::inverse(const std::vector<std::complex<double>>& X) {
  if (X.size() != n_ / 2 + 1)
    throw InputError("FFT: " + std::to_string(X.size()) + " bins given to an inverse of " +
                     std::to_string(n_) + " points (needs " + std::to_string(n_ / 2 + 1) + ")");
  return tables_->inverse(X);
}

std::size_t fast_fft_length(std::size_t n) {
  return n <= 1 ? 1 : smooth_length(n);
}

class ComplexFft::Tables {
 public:
  explicit Tables(std::size_t n)
      : table_(gsl_fft_complex_wavetable_alloc(n)), work_(gsl_fft_complex_workspace_alloc(n)) {
    if (!table_ || !work_) no_tables(n);
  }
  // std::complex<double> is laid out as double[2] (the standard guarantees it): GSL's packed
  // complex array.
  void transform(std::vector<std::complex<double>>& x, gsl_fft_direction sign) {
    if (gsl_fft_complex_transform(reinterpret_cast<double*>(x.data()), 1, x.size(), table_.get(),
                                  work_.get(), sign) != 0)
      throw SolverError("FFT: GSL complex transform failed for " + std::to_string(x.size()) +
                        " points");
  }

 private:
  std::unique_ptr<gsl_fft_complex_wavetable, ComplexTableFree> table_;
  std::unique_ptr<gsl_fft_complex_workspace, ComplexWorkFree> work_;
};

ComplexFft::ComplexFft(std::size_t n) : n_(n) {
  if (n < 1) throw InputError("complex FFT: 0 points given; at least 1 is needed");
  if (largest_prime_factor(n) > kLargestMixedRadixFactor)
    throw InputError("complex FFT: " + std::to_string(n) + " points has the prime factor " +
                     std::to_string(largest_prime_factor(n)) + "; allowed: factors up to " +
                     std::to_string(kLargestMixedRadixFactor) + " (see fast_fft_length)");
  tables_ = std::make_unique<Tables>(n);
}

ComplexFft::~ComplexFft() = default;
ComplexFft::ComplexFft(ComplexFft&&) noexcept = default;
ComplexFft& ComplexFft::operator=(ComplexFft&&) noexcept = default;

void ComplexFft::forward(std::vector<std::complex<double>>& x) {
  if (x.size() != n_)
    throw InputError("complex FFT: " + std::to_string(x.size()) +
                     " values given to a transform of " + std::to_string(n_));
  tables_->transform(x, gsl_fft_forward);
}

void ComplexFft::inverse(std::vector<std::complex<double>>& x) {
  if (x.size() != n_)
    throw InputError("complex FFT: " + std::to_string(x.size()) +
                     " values given to a transform of " + std::to_string(n_));
  tables_->transform(x, gsl_fft_backward);  // GSL's backward: unscaled, e^{+2πi kn/N}
}

}  // namespace bearing
