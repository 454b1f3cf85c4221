// Time-domain sound pressure from velocity records (pressure.h).

#include "bearing/acoustics/pressure.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/units.h"
#include "delay_kernel.h"

namespace bearing {

namespace {

// Windowed-sinc interpolation (delay_kernel.h: kHalfWidth, kPhases): Kaiser β for an 80 dB
// stopband (Kaiser's formula β = 0.1102 (A − 8.7)); the kernel is tabulated at kPhases
// fractional positions per sample and interpolated linearly between them (error ~(π/kPhases)²/8
// per tap).
using detail::kHalfWidth;
using detail::kPhases;
constexpr double kKaiserBeta = 0.1102 * (80.0 - 8.7);

// I₀(x_j) for every x_j ≤ kKaiserBeta side by side (the loop over j vectorises): its power
// series Σ_k (x²/4)^k/(k!)², every term positive; at x = β (x²/4 ≈ 15.4) the terms after the
// 30th are below 1e-24 of the sum.
std::vector<double> bessel_i0(const std::vector<double>& x) {
  std::vector<double> y(x.size()), term(x.size(), 1.0), sum(x.size(), 1.0);
  for (std::size_t j = 0; j < x.size(); ++j) y[j] = 0.25 * x[j] * x[j];
  for (int k = 1; k <= 30; ++k) {
    const double inverse = 1.0 / (static_cast<double>(k) * k);
    for (std::size_t j = 0; j < x.size(); ++j) {
      term[j] *= y[j] * inverse;
      sum[j] += term[j];
    }
  }
  return sum;
}

// The kernel at u_j = j / kPhases [samples], j = 0 … kHalfWidth·kPhases: sinc(u) times the Kaiser
// window I₀(β √(1 − (u/kHalfWidth)²)) / I₀(β). sin(πu) from one half period,
// sin(π(q + r/kPhases)) = (−1)^q sin(πr/kPhases): kPhases sines instead of one per point.
std::vector<double> kernel_grid() {
  const int size = kHalfWidth * kPhases + 1;
  std::vector<double> x(static_cast<std::size_t>(size + 1));
  for (int j = 0; j < size; ++j) {
    const double t = static_cast<double>(j) / (kHalfWidth * kPhases);
    x[static_cast<std::size_t>(j)] = kKaiserBeta * std::sqrt(std::max(0.0, 1 - t * t));
  }
  x.back() = kKaiserBeta;  // the norm's
  const std::vector<double> window = bessel_i0(x);
  std::vector<double> half(static_cast<std::size_t>(kPhases));
  for (int r = 0; r < kPhases; ++r)
    half[static_cast<std::size_t>(r)] = std::sin(pi * static_cast<double>(r) / kPhases);
  std::vector<double> grid(static_cast<std::size_t>(size), 0.0);  // 0 at |t| = 1
  grid[0] = 1.0;
  for (int j = 1; j < size - 1; ++j) {
    const double u = static_cast<double>(j) / kPhases;
    const double sine = (j / kPhases % 2 ? -1 : 1) * half[static_cast<std::size_t>(j % kPhases)];
    grid[static_cast<std::size_t>(j)] =
        sine / (pi * u) * window[static_cast<std::size_t>(j)] / window.back();
  }
  return grid;
}

void check_record(const std::vector<double>& velocity, double rate, const RealFft& fft) {
  if (velocity.size() != fft.size() + 1)
    throw InputError("sound pressure: a velocity record of " + std::to_string(velocity.size()) +
                     " samples given to an FFT of " + std::to_string(fft.size()) +
                     " (it needs N + 1: the record and the sample after it)");
  if (!(std::isfinite(rate) && rate > 0))
    throw InputError("sound pressure: sample rate = " + format_number(rate) +
                     " Hz: must be positive and finite");
  for (std::size_t i = 0; i < velocity.size(); ++i)
    if (!std::isfinite(velocity[i]))
      throw InputError("sound pressure: velocity sample " + std::to_string(i) + " = " +
                       format_number(velocity[i]) + ": every sample must be finite");
}

// The record u_0 … u_{N−1} less its trend β t_n, t_n = n/rate, β = (u_N − u_0)·rate/N [m/s²]:
// periodic without a jump. Returns the DFT of the detrended record and β.
struct Detrended {
  std::vector<std::complex<double>> spectrum;
  double slope = 0;
};
Detrended detrend(const std::vector<double>& velocity, double rate, RealFft& fft) {
  const std::size_t n = fft.size();
  const double jump = velocity[n] - velocity[0];
  std::vector<double> u(n);
  for (std::size_t i = 0; i < n; ++i)
    u[i] = velocity[i] - jump * static_cast<double>(i) / static_cast<double>(n);
  Detrended d;
  d.spectrum = fft.forward(u);
  d.slope = jump * rate / static_cast<double>(n);
  return d;
}

double angular_frequency(std::size_t k, double rate, std::size_t n) {
  return two_pi * static_cast<double>(k) * rate / static_cast<double>(n);
}

// The spectrum of the record times `gain(ω_k)` within the band, back in time. DC is zero (no body
// radiates a steady velocity); so is every bin above kPressureBandFraction of Nyquist.
template <class Gain>
std::vector<double> filter(const std::vector<std::complex<double>>& U, double rate, RealFft& fft,
                           const Gain& gain) {
  const std::size_t n = fft.size();
  std::vector<std::complex<double>> P(U.size());
  for (std::size_t k = 1; k < U.size(); ++k)
    if (2 * static_cast<double>(k) <= kPressureBandFraction * static_cast<double>(n))
      P[k] = gain(angular_frequency(k, rate, n)) * U[k];
  return fft.inverse(P);
}

}  // namespace

PeriodicInterpolator::PeriodicInterpolator() {
  static_assert(kTaps == detail::kDelayTaps, "taps");
  // Every entry is the even kernel at u = j / kPhases for an integer j (tap l, phase p:
  // j = p − l·kPhases): evaluate it once per |j|.
  const std::vector<double> grid = kernel_grid();
  table_.resize(static_cast<std::size_t>(detail::kTableRows * kTaps));
  for (int p = 0; p < detail::kTableRows; ++p)
    for (int l = -kHalfWidth + 1; l <= kHalfWidth; ++l)
      table_[static_cast<std::size_t>(p * kTaps + l + kHalfWidth - 1)] =
          grid[static_cast<std::size_t>(std::abs(p - l * kPhases))];
}

PeriodicInterpolator::Taps PeriodicInterpolator::taps(double s, std::size_t n) const {
  Taps t;
  t.first = taps(s, n, t.weight.data());
  return t;
}

std::size_t PeriodicInterpolator::taps(double s, std::size_t n, double* weight) const {
  const double floor_s = std::floor(s);
  const double phase = (s - floor_s) * kPhases;
  const int p = std::min(static_cast<int>(phase), kPhases - 1);
  detail::interpolate_rows(table_.data(), p, phase - p, weight);
  long first = (static_cast<long>(floor_s) - kHalfWidth + 1) % static_cast<long>(n);
  if (first < 0) first += static_cast<long>(n);
  return static_cast<std::size_t>(first);
}

double PeriodicInterpolator::apply(const Taps& t, const std::vector<double>& x) {
  const std::size_t n = x.size();
  double sum = 0;
  std::size_t i = t.first;
  if (i + kTaps <= n) {  // no wrap: a plain dot product
    for (std::size_t k = 0; k < kTaps; ++k) sum += t.weight[k] * x[i + k];
    return sum;
  }
  for (std::size_t k = 0; k < kTaps; ++k) {
    sum += t.weight[k] * x[i];
    if (++i == n) i = 0;
  }
  return sum;
}

std::vector<double> radiate_fixed(const AcousticSource& source, const std::vector<double>& velocity,
                                  double rate, double r, double cos_angle, RealFft& fft) {
  check_record(velocity, rate, fft);
  source.transfer(1.0, r, cos_angle);  // checks the geometry once, with its message
  const Detrended d = detrend(velocity, rate, fft);
  std::vector<double> p = filter(
      d.spectrum, rate, fft, [&](double omega) { return source.transfer(omega, r, cos_angle); });
  const double ramp = d.slope * source.ramp_pressure(r, cos_angle);
  for (double& v : p) v += ramp;
  return p;
}

std::vector<std::vector<double>> radiate_fixed(const AcousticSource& source,
                                               const std::vector<std::vector<double>>& velocities,
                                               double rate, const std::vector<double>& r,
                                               const std::vector<double>& cos_angle, RealFft& fft) {
  const std::size_t points = velocities.size(), n = fft.size();
  if (r.size() != points || cos_angle.size() != points)
    throw std::logic_error("radiate_fixed: one distance and one angle per record");
  std::vector<Detrended> d;
  for (std::size_t i = 0; i < points; ++i) {
    check_record(velocities[i], rate, fft);
    source.transfer(1.0, r[i], cos_angle[i]);  // checks the geometry once, with its message
    d.push_back(detrend(velocities[i], rate, fft));
  }
  // filter() for every point, the frequency loop outside.
  std::vector<std::vector<std::complex<double>>> P(points);
  for (auto& spectrum : P) spectrum.resize(n / 2 + 1);
  std::vector<std::complex<double>> H;
  for (std::size_t k = 1; k <= n / 2; ++k)
    if (2 * static_cast<double>(k) <= kPressureBandFraction * static_cast<double>(n)) {
      source.transfer(angular_frequency(k, rate, n), r, cos_angle, H);
      for (std::size_t i = 0; i < points; ++i) P[i][k] = H[i] * d[i].spectrum[k];
    }
  std::vector<std::vector<double>> p;
  for (std::size_t i = 0; i < points; ++i) {
    p.push_back(fft.inverse(P[i]));
    const double ramp = d[i].slope * source.ramp_pressure(r[i], cos_angle[i]);
    for (double& v : p.back()) v += ramp;
  }
  return p;
}

std::vector<double> radiate_moving(const RadialSeriesSource& source,
                                   const std::vector<double>& velocity, double rate,
                                   const SourcePath& path, RealFft& fft) {
  return radiate_moving(source, velocity, rate, path, fft, PeriodicInterpolator());
}

std::vector<double> radiate_moving(const RadialSeriesSource& source,
                                   const std::vector<double>& velocity, double rate,
                                   const SourcePath& path, RealFft& fft,
                                   const PeriodicInterpolator& at) {
  return pressure_from(source, filter_moving(source, velocity, rate, fft), rate, path, at);
}

FilteredRecord::FilteredRecord(const std::vector<std::vector<double>>& terms,
                               std::vector<double> ramp)
    : n_(terms.empty() ? 0 : terms.front().size()), ramp_(std::move(ramp)) {
  const std::size_t M = terms.size();
  if (M == 0 || n_ == 0 || ramp_.size() != M)
    throw std::invalid_argument("FilteredRecord: needs M ≥ 1 terms of N ≥ 1 samples, M ramps");
  for (const auto& q : terms)
    if (q.size() != n_) throw std::invalid_argument("FilteredRecord: terms of unequal lengths");
  const std::size_t length = n_ + PeriodicInterpolator::kTaps - 1;
  terms_.resize(M);
  for (std::size_t m = 0; m < M; ++m) {
    terms_[m].resize(length);
    for (std::size_t i = 0, k = 0; i < length; ++i, k = k + 1 == n_ ? 0 : k + 1)
      terms_[m][i] = terms[m][k];
  }
}

SeriesFactors::SeriesFactors(const RadialSeriesSource& source, double rate, std::size_t n)
    : source_(source), rate_(rate), n_(n) {
  for (std::size_t m = 0; m < source.powers().size(); ++m) {
    std::vector<std::complex<double>>& F = factors_.emplace_back(n / 2 + 1);
    for (std::size_t k = 1; k < F.size(); ++k)  // filter()'s band
      if (2 * static_cast<double>(k) <= kPressureBandFraction * static_cast<double>(n))
        F[k] = source.factor(m, angular_frequency(k, rate, n));
  }
}

FilteredRecord filter_moving(const RadialSeriesSource& source, const std::vector<double>& velocity,
                             double rate, RealFft& fft) {
  return filter_moving(SeriesFactors(source, rate, fft.size()), velocity, fft);
}

FilteredRecord filter_moving(const SeriesFactors& factors, const std::vector<double>& velocity,
                             RealFft& fft) {
  if (factors.size() != fft.size())
    throw std::logic_error("filter_moving: factors for another record length");
  const double rate = factors.rate();
  check_record(velocity, rate, fft);
  const Detrended d = detrend(velocity, rate, fft);
  std::vector<std::vector<double>> terms;
  std::vector<double> ramp;
  for (std::size_t m = 0; m < factors.source().powers().size(); ++m) {
    const std::vector<std::complex<double>>& F = factors.term(m);
    std::vector<std::complex<double>> P(d.spectrum.size());
    for (std::size_t k = 1; k < P.size(); ++k) P[k] = F[k] * d.spectrum[k];
    terms.push_back(fft.inverse(P));
    ramp.push_back(d.slope * factors.source().ramp_factor(m));
  }
  return FilteredRecord(terms, std::move(ramp));
}

std::vector<double> pressure_from(const RadialSeriesSource& source, const FilteredRecord& record,
                                  double rate, const SourcePath& path,
                                  const PeriodicInterpolator& at) {
  std::vector<double> p;
  pressure_from(source, record, rate, path, at, p);
  return p;
}

void pressure_from(const RadialSeriesSource& source, const FilteredRecord& record, double rate,
                   const SourcePath& path, const PeriodicInterpolator& at, std::vector<double>& p) {
  const std::vector<int> powers = source.powers();
  if (record.terms() != powers.size())
    throw std::logic_error("pressure_from: a record filtered for another source");
  const std::size_t n = record.size();
  if (path.distance.size() != n || path.cos_angle.size() != n)
    throw InputError("sound pressure: the source path has " + std::to_string(path.distance.size()) +
                     " distances and " + std::to_string(path.cos_angle.size()) +
                     " angles for a record of " + std::to_string(n) + " samples");
  const double a = source.radius();
  for (std::size_t i = 0; i < n; ++i)
    if (!(std::isfinite(path.distance[i]) && path.distance[i] >= a &&
          std::isfinite(path.cos_angle[i])))
      throw InputError("sound pressure: at sample " + std::to_string(i) + " the point is " +
                       format_number(path.distance[i]) + " m from the centre of " +
                       std::string(source.name()) + " of radius " + format_number(a) +
                       " m: it must lie outside the body");

  const double* terms[3];
  if (powers.size() > 3) throw std::logic_error("pressure_from: a source of more than 3 terms");
  for (std::size_t m = 0; m < powers.size(); ++m) terms[m] = record.term(m);
  const detail::DelayedPlacement pl{
      terms,
      n,
      path.distance.data(),
      source.pattern() == Pattern::breathing ? nullptr : path.cos_angle.data(),
      powers.data(),
      record.ramp().data(),
      a,
      source.delayed() ? rate / source.air().sound_speed : 0.0,
      at.table()};
  p.resize(n);
  detail::place_delayed(pl, static_cast<int>(powers.size()), p.data());
}

Summation parse_summation(const std::string& name, const std::string& key) {
  return parse_named(kSummations, name, key, "summation");
}

std::vector<double> sum_pressures(const std::vector<std::vector<double>>& pressures,
                                  Summation summation) {
  if (pressures.empty()) return {};
  const std::size_t n = pressures.front().size();
  std::vector<double> total(n, 0.0);
  for (const auto& p : pressures) {
    if (p.size() != n)
      throw InputError("sound pressure: records of " + std::to_string(n) + " and " +
                       std::to_string(p.size()) + " samples cannot be summed");
    for (std::size_t i = 0; i < n; ++i)
      total[i] += summation == Summation::coherent ? p[i] : p[i] * p[i];
  }
  if (summation == Summation::energetic)
    for (double& v : total) v = std::sqrt(v);
  return total;
}

double root_mean_square(const std::vector<double>& x) {
  if (x.empty()) return 0.0;
  double largest = 0;
  for (double v : x) largest = std::max(largest, std::fabs(v));
  if (largest == 0 || !std::isfinite(largest)) return largest;
  double sum = 0;
  for (double v : x) sum += (v / largest) * (v / largest);
  return largest * std::sqrt(sum / static_cast<double>(x.size()));
}

}  // namespace bearing
