// The benchmark method (benchmark_method.h): cepstral pre-whitening, the full-band squared envelope
// spectrum, and a call by a stated false-alarm rate.

#include "benchmark_method.h"

#include <algorithm>
#include <cmath>
#include <complex>

#include "bearing/errors.h"
#include "bearing/signal/fft.h"

namespace bearing::verify {

namespace {

using cd = std::complex<double>;

// The largest length ≤ n of prime factors 2, 3 and 5 (ComplexFft's lengths): the record is cut to
// it, losing at most a few per cent of its end.
std::size_t smooth_length_below(std::size_t n) {
  for (std::size_t m = n; m > 1; --m)
    if (fast_fft_length(m) == m) return m;
  return 1;
}

double median(std::vector<double> v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace

std::vector<double> benchmark_ses(const std::vector<double>& record) {
  const std::size_t n = smooth_length_below(record.size());
  if (n < 64) throw InputError("benchmark method: fewer than 64 samples");
  std::vector<cd> a(record.begin(), record.begin() + static_cast<std::ptrdiff_t>(n));
  double mean = 0;
  for (const cd& v : a) mean += v.real() / static_cast<double>(n);
  for (cd& v : a) v -= mean;
  ComplexFft fft(n);
  fft.forward(a);
  // Whitened (unit magnitude, its phase kept) and one-sided: the analytic signal's spectrum.
  for (std::size_t k = 0; k < n; ++k) {
    const double m = std::abs(a[k]);
    const bool positive = k > 0 && 2 * k < n;
    const bool nyquist = 2 * k == n;
    a[k] = m > 0 && (positive || nyquist) ? a[k] / m * (positive ? 2.0 : 1.0) : cd(0.0);
  }
  fft.inverse(a);  // n · a(t)
  std::vector<cd> e(n);
  double e_mean = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double v = std::norm(a[i] / static_cast<double>(n));
    e[i] = v;
    e_mean += v / static_cast<double>(n);
  }
  for (cd& v : e) v -= e_mean;
  fft.forward(e);
  std::vector<double> ses(n / 2 + 1);
  for (std::size_t k = 0; k < ses.size(); ++k) ses[k] = std::abs(e[k]) / static_cast<double>(n);
  return ses;
}

double exceedance_threshold(double p, int window) {
  return -std::log(-std::expm1(std::log1p(-p) / std::max(window, 1)));
}

double per_harmonic_probability(double alpha) {
  // 3p² − 2p³ rises monotonically from 0 to 1/2 on [0, 1/2]: bisection.
  double lo = 0, hi = 0.5;
  for (int i = 0; i < 200; ++i) {
    const double p = 0.5 * (lo + hi);
    (3 * p * p - 2 * p * p * p < alpha ? lo : hi) = p;
  }
  return 0.5 * (lo + hi);
}

BenchmarkVerdict benchmark_method(const std::vector<double>& x, double rate, double shaft,
                                  const DefectMultiples& m, double alpha) {
  if (!(alpha > 0 && alpha < 0.5))
    throw InputError("benchmark method: false-alarm rate must lie in (0, 0.5)");
  if (!(rate > 0) || !(shaft > 0) || !std::isfinite(rate) || !std::isfinite(shaft))
    throw InputError("benchmark method: the rate and the shaft frequency must be finite and > 0");
  for (double v : x)
    if (!std::isfinite(v))
      throw InputError("benchmark method: the record holds a non-finite value");
  const double top = 3.2 * std::max({m.bpfo, m.bpfi, m.ball}) * shaft;
  if (top >= 0.5 * rate)
    throw InputError("benchmark method: three harmonics of every family do not fit below Nyquist");
  const std::vector<double> ses = benchmark_ses(x);
  const std::size_t n = smooth_length_below(x.size());
  const double df = rate / static_cast<double>(n);
  const double p = per_harmonic_probability(alpha);

  BenchmarkVerdict v;
  v.false_alarm = alpha;
  v.samples = n;
  const std::pair<const char*, double> families[] = {
      {"outer", m.bpfo}, {"inner", m.bpfi}, {"ball", m.ball}};
  double best_score = -1e300;
  int best_count = 0;
  v.family = "none";
  for (const auto& [name, multiple] : families) {
    BenchmarkFamily f;
    f.family = name;
    f.rate = multiple * shaft;
    double score = 0;
    for (int h = 1; h <= 3; ++h) {
      const double c = h * f.rate;
      const auto bin = [&](double hz) {
        return std::min(ses.size() - 1, static_cast<std::size_t>(std::lround(hz / df)));
      };
      const std::size_t w0 = bin(0.98 * c), w1 = bin(1.02 * c);
      const std::size_t r0 = bin(std::max(df, c - 0.5 * f.rate)), r1 = bin(c + 0.5 * f.rate);
      std::vector<double> ring;
      for (std::size_t k = r0; k <= r1; ++k) ring.push_back(ses[k] * ses[k]);
      const double floor_mean = median(ring) / std::log(2.0);
      std::size_t at = w0;
      for (std::size_t k = w0; k <= w1; ++k)
        if (ses[k] > ses[at]) at = k;
      const int window = static_cast<int>(w1 - w0 + 1);
      const double t = exceedance_threshold(p, window);
      const double ratio = ses[at] * ses[at] / floor_mean;
      f.excess[h - 1] = 10 * std::log10(ratio);
      f.found[h - 1] = static_cast<double>(at) * df;
      f.threshold = std::max(f.threshold, 10 * std::log10(t));
      if (ratio > t) ++f.standing_out;
      score += f.excess[h - 1];
    }
    f.detected = f.standing_out >= 2;
    if (f.detected &&
        (f.standing_out > best_count || (f.standing_out == best_count && score > best_score))) {
      best_count = f.standing_out;
      best_score = score;
      v.family = name;
    }
    v.families.push_back(f);
  }
  return v;
}

}  // namespace bearing::verify
