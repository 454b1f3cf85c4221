#pragma once
// The discrete Fourier transform of real data, both ways, for any length N in O(N log N); and of
// complex data, for the fast lengths fast_fft_length() gives.

#include <complex>
#include <cstddef>
#include <memory>
#include <vector>

namespace bearing {

/// DFT of real sequences of one length N:
///   forward  X_k = Σ_n x_n e^{−2πi kn/N},  k = 0 … ⌊N/2⌋ (the other bins are X_{N−k} = conj X_k);
///   inverse  x_n = (1/N) Σ_{k=0}^{N−1} X_k e^{+2πi kn/N}, from X_0 … X_{⌊N/2⌋} of a Hermitian
///            spectrum (Im X_0 and, for even N, Im X_{N/2} are ignored: they are zero for real x).
/// With these signs bin k holds the e^{+iω_k t} part of x, ω_k = 2πk f_s/N: the time convention
/// e^{iωt} of the acoustics (docs/model.md §8).
///
/// GSL's mixed-radix real FFT when every prime factor of N is at most 64; otherwise (e.g. a prime
/// N, where GSL's generic pass is O(N²): 0.55 s at N = 24001) Bluestein's algorithm on GSL's
/// complex FFT of a 2-3-5-smooth length ≥ 2N − 1. The tables are built once by the constructor;
/// the transforms use the object's scratch space: one RealFft per thread.
class RealFft {
 public:
  /// Throws InputError for N < 2, SolverError if GSL cannot allocate its tables.
  explicit RealFft(std::size_t n);
  ~RealFft();
  RealFft(RealFft&&) noexcept;
  RealFft& operator=(RealFft&&) noexcept;

  std::size_t size() const { return n_; }

  /// X_0 … X_{⌊N/2⌋} of x (x.size() must be N; x is used as scratch and overwritten).
  std::vector<std::complex<double>> forward(std::vector<double>& x);

  /// x_0 … x_{N−1} from X_0 … X_{⌊N/2⌋} (X.size() must be ⌊N/2⌋ + 1).
  std::vector<double> inverse(const std::vector<std::complex<double>>& X);

 private:
  class Tables;  // GSL tables and scratch (fft.cc)
  std::size_t n_;
  std::unique_ptr<Tables> tables_;
};

/// The smallest length M ≥ n whose prime factors are 2, 3 and 5 only (GSL's fastest radices), for
/// zero padding; n ≤ 1 gives 1.
std::size_t fast_fft_length(std::size_t n);

/// DFT of complex sequences of one length N whose prime factors are all at most 64 (e.g. a
/// fast_fft_length()), in place, unscaled both ways:
///   forward  X_k = Σ_n x_n e^{−2πi kn/N},   inverse  x_n = Σ_k X_k e^{+2πi kn/N}  (no 1/N).
/// GSL's mixed-radix complex FFT; the tables are built once by the constructor, the transforms use
/// the object's scratch space: one ComplexFft per thread.
class ComplexFft {
 public:
  /// Throws InputError for N < 1 or a prime factor of N above 64, SolverError if GSL cannot
  /// allocate its tables.
  explicit ComplexFft(std::size_t n);
  ~ComplexFft();
  ComplexFft(ComplexFft&&) noexcept;
  ComplexFft& operator=(ComplexFft&&) noexcept;

  std::size_t size() const { return n_; }

  /// x ← DFT(x) (x.size() must be N).
  void forward(std::vector<std::complex<double>>& x);
  /// x ← N · IDFT(x) (x.size() must be N).
  void inverse(std::vector<std::complex<double>>& x);

 private:
  class Tables;  // GSL tables and scratch (fft.cc)
  std::size_t n_;
  std::unique_ptr<Tables> tables_;
};

}  // namespace bearing
