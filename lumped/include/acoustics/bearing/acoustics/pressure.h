#pragma once
// Sound pressure in the time domain (docs/model.md §8): a source's velocity record → FFT → transfer
// function → inverse FFT → p(t) at a point; RMS and summation over sources.
//
// The record u_0 … u_{N−1} (N samples at rate f_s, T = N/f_s) is filtered as one period of a
// periodic signal, as the spectra are: bin k is the frequency k f_s/N, and the band is
// f_s/N … 0.8 f_s/2 (kPressureBandFraction; bins above are set to zero). The top of the sampled
// band is left out because a moving source's delays are interpolated, and the interpolation
// attenuates there (below): a ball's velocity with kinks (a ball entering contact) has energy up
// to f_s/2, weighted up by the field's iω, and leaving it in made the level depend on each
// delay's fractional sample by ~0.04 dB. For the full audible band, sample at 50 kHz. A record is
// rarely a whole period, and the jump where its end wraps onto its start would radiate as a
// spike (the near field goes with du/dt): 0.3 dB of the RMS at 10 mm from seed 000's 608. So the
// caller also passes u_N, the sample after the record, and the trend β t, β = (u_N − u_0)/T, is
// taken out first: the rest joins without a jump. A ramp's steady pressure is the constant
// β lim_{ω→0} H/(iω) (AcousticSource::ramp_pressure), added back: exact for the ramp, and what
// is left at the wrap is a kink: p jumps there by about its own amplitude J, and the band-limited
// jump rings as J/(πn) at n samples from the ends (its energy is of order J², whatever N: 0.01 dB
// on the RMS of 1 s at 20 kHz).
//
// A moving body (a ball on its orbit) changes its distance r_n and angle ψ_n to the microphone
// from sample to sample. With its field written H = Θ(ψ) e^{−iω(r−a)/c₀} Σ_m (a/r)^m F_m(ω)
// (sources.h), the pressure is filtered once per term and then placed sample by sample:
//     p_n = Θ(ψ_n) Σ_m (a/r_n)^m q_m(t_n − (r_n − a)/c₀),   q_m = F⁻¹[F_m(ω) U(ω)],
// the geometry frozen at each instant (the ball moves at ~10⁻³ c₀: the Doppler factor and the
// change of geometry during one delay are of that order). The delayed values q_m(t − τ) come from
// a Kaiser-windowed sinc interpolation of the periodic record (32 taps, stopband −80 dB). Measured
// error on a unit tone: ≤ 3e-5 up to 0.4 of the Nyquist frequency f_s/2, ≤ 2e-4 up to 0.84 of
// it, then the interpolation attenuates (6 % at 0.9, 48 % at 0.96): the top 10 % of the band of a
// moving source would not be reliable, hence the band.

#include <array>
#include <complex>
#include <cstddef>
#include <string>
#include <vector>

#include "bearing/acoustics/sources.h"
#include "bearing/choice.h"
#include "bearing/signal/fft.h"

namespace bearing {

/// The pressure's band ends at this fraction of the Nyquist frequency f_s/2.
constexpr double kPressureBandFraction = 0.8;

/// Pressure p_0 … p_{N−1} [Pa] at a point fixed relative to a body that does not move:
/// p = F⁻¹[H(ω_k; r, cos ψ) U(ω_k)] + β ramp_pressure, U the DFT of the detrended record, ω_k =
/// 2πk·rate/N. `velocity` [m/s] holds N + 1 samples at `rate` [Hz]: the record u_0 … u_{N−1} and
/// the sample u_N that follows it. `fft` must have length N ≥ 2. Throws InputError for bad
/// arguments (see AcousticSource::transfer) or a non-finite velocity.
std::vector<double> radiate_fixed(const AcousticSource& source, const std::vector<double>& velocity,
                                  double rate, double r, double cos_angle, RealFft& fft);

/// radiate_fixed at several points: velocities[i] (N + 1 samples) is the record seen at r[i],
/// cos_angle[i]. The same records, bit for bit, as one radiate_fixed per point; the transfer
/// function is evaluated for all the points at once at each frequency (what depends on the body
/// alone, once). Throws as radiate_fixed.
std::vector<std::vector<double>> radiate_fixed(const AcousticSource& source,
                                               const std::vector<std::vector<double>>& velocities,
                                               double rate, const std::vector<double>& r,
                                               const std::vector<double>& cos_angle, RealFft& fft);

/// Where a moving body is, seen from the point, at each sample.
struct SourcePath {
  std::vector<double> distance;  ///< r_n ≥ a, from the body's centre to the point [m]
  std::vector<double>
      cos_angle;  ///< cos ψ_n, direction of motion against the direction to the point
};

/// Pressure p_0 … p_{N−1} [Pa] at a point from a body moving along `path` (N entries), its
/// velocity `velocity` [m/s] (N + 1 samples, as radiate_fixed) along its direction of motion
/// (translating) or on its surface (breathing): p_n = Θ_n Σ_m (a/r_n)^m [q_m(t_n − τ_n) + β
/// ramp_factor(m)]. Same conventions and errors as radiate_fixed; also InputError if the path
/// does not have N entries or the point is inside the body at some sample.
/// Band-limited value of a periodic record x (period N samples) at the fractional sample
/// position s (any real; s = n gives x_n): the Kaiser-windowed sinc interpolation radiate_moving
/// uses for its delays. Building its kernel table costs ~1 ms: build one and share it.
class PeriodicInterpolator {
 public:
  static constexpr int kTaps = 32;

  /// The taps for position s in a record of period n: the first sample index and the weights.
  struct Taps {
    std::size_t first = 0;
    std::array<double, kTaps> weight{};
  };

  PeriodicInterpolator();
  Taps taps(double s, std::size_t n) const;
  /// The same taps written to weight[0 … kTaps−1]; returns the first sample index.
  std::size_t taps(double s, std::size_t n, double* weight) const;
  /// Σ_t weight_t x_{(first + t) mod N}.
  static double apply(const Taps& taps, const std::vector<double>& x);
  double operator()(const std::vector<double>& x, double s) const {
    return apply(taps(s, x.size()), x);
  }
  /// The kernel table: its rows 0 … kPhases/2 of kTaps weights (phase p / kPhases of a sample;
  /// the kernel is even, so row kPhases − p is row p reversed).
  const double* table() const { return table_.data(); }

 private:
  std::vector<double> table_;  // kernel at phases i / kPhases of each tap
};

std::vector<double> radiate_moving(const RadialSeriesSource& source,
                                   const std::vector<double>& velocity, double rate,
                                   const SourcePath& path, RealFft& fft,
                                   const PeriodicInterpolator& interpolator);

/// The part of radiate_moving that does not depend on where the point is: the velocity record
/// filtered once per term of the source's series, q_m = F⁻¹[F_m(ω) U(ω)], and each term's ramp
/// pressure β ramp_factor(m). One per ball serves every microphone.
class FilteredRecord {
 public:
  /// terms[m] = q_m(t_n), n = 0 … N−1 [Pa at r = a] (M ≥ 1 terms of one length N ≥ 1);
  /// ramp[m] = β ramp_factor(m) [Pa]. Throws std::invalid_argument otherwise.
  FilteredRecord(const std::vector<std::vector<double>>& terms, std::vector<double> ramp);
  std::size_t size() const { return n_; }             ///< N
  std::size_t terms() const { return ramp_.size(); }  ///< M
  const std::vector<double>& ramp() const { return ramp_; }
  /// q_m(t_i) for i = 0 … N + kTaps − 2, continued periodically past N: the taps of any delayed
  /// position are one contiguous run. m < terms().
  const double* term(std::size_t m) const { return terms_[m].data(); }

 private:
  std::size_t n_;
  std::vector<double> ramp_;
  std::vector<std::vector<double>> terms_;
};

/// A series source's factors F_m(ω_k) at the bins k = 0 … N/2 of an N-sample record at `rate`,
/// zero at DC and above the band: what filter_moving multiplies a record's spectrum by. Alike
/// bodies (the balls of a bearing) share one. `source` must outlive it.
class SeriesFactors {
 public:
  SeriesFactors(const RadialSeriesSource& source, double rate, std::size_t n);
  const RadialSeriesSource& source() const { return source_; }
  double rate() const { return rate_; }
  std::size_t size() const { return n_; }  ///< N
  /// F_m(ω_k) [Pa/(m/s)] for the m-th power of source().powers(), k = 0 … N/2.
  const std::vector<std::complex<double>>& term(std::size_t m) const { return factors_[m]; }

 private:
  const RadialSeriesSource& source_;
  double rate_;
  std::size_t n_;
  std::vector<std::vector<std::complex<double>>> factors_;
};

/// The filtered record of `velocity` (N + 1 samples at `rate`, as radiate_fixed). Throws as
/// radiate_fixed for a bad record.
FilteredRecord filter_moving(const RadialSeriesSource& source, const std::vector<double>& velocity,
                             double rate, RealFft& fft);
/// The same with the factors evaluated once (the same bits); `fft` of length factors.size().
FilteredRecord filter_moving(const SeriesFactors& factors, const std::vector<double>& velocity,
                             RealFft& fft);

/// radiate_moving from a filtered record of `source`: p_n = Θ_n Σ_m (a/r_n)^m [q_m(t_n − τ_n) +
/// ramp_m]. Throws InputError if the path does not have N entries or the point is inside the
/// body at some sample. radiate_moving(…) == pressure_from(source, filter_moving(…), rate, …)
/// exactly.
std::vector<double> pressure_from(const RadialSeriesSource& source, const FilteredRecord& record,
                                  double rate, const SourcePath& path,
                                  const PeriodicInterpolator& interpolator);
/// The same into `p` (resized to N; its storage reused from call to call).
void pressure_from(const RadialSeriesSource& source, const FilteredRecord& record, double rate,
                   const SourcePath& path, const PeriodicInterpolator& interpolator,
                   std::vector<double>& p);

/// The same with an interpolator of its own (for one-off calls).
std::vector<double> radiate_moving(const RadialSeriesSource& source,
                                   const std::vector<double>& velocity, double rate,
                                   const SourcePath& path, RealFft& fft);

/// How source pressures add up at a microphone.
enum class Summation {
  coherent,   ///< p = Σ_i p_i(t): the pressure itself (interference included)
  energetic,  ///< p = sqrt(Σ_i p_i(t)²) (seed 000 eq. 26): an envelope whose RMS is sqrt(Σ
              ///< p_rms,i²)
};
inline constexpr Named<Summation> kSummations[] = {{Summation::coherent, "coherent"},
                                                   {Summation::energetic, "energetic"}};

/// "coherent" or "energetic"; InputError naming `key` otherwise.
Summation parse_summation(const std::string& name, const std::string& key);

/// The sum of equally long pressure records under `summation` (an empty list gives an empty
/// record).
std::vector<double> sum_pressures(const std::vector<std::vector<double>>& pressures,
                                  Summation summation);

/// Root mean square of a record [unit of x] (about zero, not the mean: a pressure's mean is the
/// static pressure, which the transfer functions never produce).
double root_mean_square(const std::vector<double>& x);

}  // namespace bearing
