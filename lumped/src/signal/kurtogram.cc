// Spectral kurtosis of bands from one FFT of the record, and the fast kurtogram (Antoni 2007).

#include "bearing/signal/kurtogram.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <map>
#include <string>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/signal/fft.h"
#include "bearing/units.h"

namespace bearing {

namespace {

// ⟨w²⟩² / ⟨w⁴⟩ of the periodic Hann window, (3/8)² / (35/128): the factor that takes the window's
// own kurtosis out of the ratio.
constexpr double kHannKurtosisCorrection = 18.0 / 35.0;

// Below this fraction of the record's energy a band holds rounding only: SK 0.
constexpr double kSilentBand = 1e-20;

void check_record(const std::vector<double>& x, double rate) {
  if (x.size() < 2)
    throw InputError("spectral kurtosis: " + std::to_string(x.size()) +
                     " samples; at least 2 needed");
  if (!(std::isfinite(rate) && rate > 0))
    throw InputError("spectral kurtosis: sample rate = " + format_number(rate) +
                     " Hz: must be positive and finite");
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!std::isfinite(x[i]))
      throw InputError("spectral kurtosis: sample " + std::to_string(i) + " = " +
                       format_number(x[i]) + ": must be finite");
}

void check_band(FrequencyBand band, double rate) {
  const double nyquist = 0.5 * rate;
  if (!(band.low >= 0 && band.low < band.high && band.high <= nyquist))
    throw InputError("spectral kurtosis band = [" + format_number(band.low) + " Hz, " +
                     format_number(band.high) + " Hz]: allowed 0 <= low < high <= " +
                     format_number(nyquist) + " Hz (the Nyquist frequency)");
}

void check_noise_floor(double noise_floor) {
  if (!(std::isfinite(noise_floor) && noise_floor >= 0))
    throw InputError("spectral kurtosis: noise floor = " + format_number(noise_floor) +
                     ": must be finite and not negative (a share of the record's energy)");
}

// The one-sided DFT X_0 … X_{⌊N/2⌋} of the record, mean removed and Hann-windowed, and its energy
// Σ_{k≥1} |X_k|²; the complex FFTs of the band lengths used so far.
class BandKurtosis {
 public:
  BandKurtosis(const std::vector<double>& x, double rate, double noise_floor)
      : n_(x.size()), rate_(rate), noise_floor_(noise_floor) {
    double mean = 0;
    for (double v : x) mean += v;
    mean /= static_cast<double>(n_);
    std::vector<double> windowed(n_);
    for (std::size_t j = 0; j < n_; ++j) {
      const double w = 0.5 - 0.5 * std::cos(two_pi * static_cast<double>(j) / n_);
      windowed[j] = w * (x[j] - mean);
    }
    RealFft fft(n_);
    spectrum_ = fft.forward(windowed);
    for (std::size_t k = 1; k < spectrum_.size(); ++k) energy_ += std::norm(spectrum_[k]);
  }

  double resolution() const { return rate_ / static_cast<double>(n_); }

  struct Result {
    double spectral_kurtosis = 0;  // [-]
    double energy_fraction = 0;    // of the record's (windowed, mean removed) energy [-]
  };

  // SK of the bins in [low, high] (inclusive, 1e-9 bin of slack; never DC).
  Result operator()(FrequencyBand band, std::size_t level_length = 0) {
    const double res = resolution();
    const double first = std::ceil(band.low / res - 1e-9);
    const double last = std::floor(band.high / res + 1e-9);
    const std::size_t k0 = first < 1 ? 1 : static_cast<std::size_t>(first);
    const std::size_t k1 = std::min(static_cast<std::size_t>(last), spectrum_.size() - 1);
    if (k1 < k0) return {};  // no bin inside the band
    const std::size_t m = k1 - k0 + 1;
    double band_energy = 0;
    for (std::size_t k = k0; k <= k1; ++k) band_energy += std::norm(spectrum_[k]);
    if (!(band_energy > kSilentBand * energy_)) return {0, energy_ > 0 ? band_energy / energy_ : 0};
    // c on L ≥ 2M − 1 points (the level's common length if long enough): the band's bins shifted
    // to baseband, zero padded, transformed back.
    const std::size_t length = std::max(fast_fft_length(2 * m - 1), level_length);
    auto [it, added] = transforms_.try_emplace(length, length);
    scratch_.assign(length, 0.0);
    for (std::size_t i = 0; i < m; ++i) scratch_[i] = spectrum_[k0 + i];
    it->second.inverse(scratch_);
    // Moments scaled by the band energy (⟨|c|²⟩ is Σ|X|² by Parseval), so large and tiny records
    // neither overflow nor underflow.
    double p2 = 0, p4 = 0;
    for (const std::complex<double>& c : scratch_) {
      const double a = std::norm(c) / band_energy;
      p2 += a;
      p4 += a * a;
    }
    p2 /= static_cast<double>(length);
    p4 /= static_cast<double>(length);
    const double sk = kHannKurtosisCorrection * p4 / (p2 * p2) - 2;
    // The floor's share of the band: ν E over the ⌊N/2⌋ bins 1 … ⌊N/2⌋, M of them here.
    const double floor =
        noise_floor_ * energy_ * static_cast<double>(m) / static_cast<double>(spectrum_.size() - 1);
    const double masked = band_energy / (band_energy + floor);
    return {sk * masked * masked, band_energy / energy_};
  }

 private:
  std::size_t n_;
  double rate_;
  double noise_floor_;
  std::vector<std::complex<double>> spectrum_;
  double energy_ = 0;
  std::map<std::size_t, ComplexFft> transforms_;
  std::vector<std::complex<double>> scratch_;
};

}  // namespace

double spectral_kurtosis(const std::vector<double>& x, double sample_rate, FrequencyBand band,
                         double noise_floor) {
  check_record(x, sample_rate);
  check_band(band, sample_rate);
  check_noise_floor(noise_floor);
  BandKurtosis sk(x, sample_rate, noise_floor);
  return sk(band).spectral_kurtosis;
}

Kurtogram fast_kurtogram(const std::vector<double>& x, double sample_rate,
                         const KurtogramSettings& settings) {
  check_record(x, sample_rate);
  if (!(std::isfinite(settings.min_bandwidth) && settings.min_bandwidth >= 0))
    throw InputError("kurtogram: minimum band width = " + format_number(settings.min_bandwidth) +
                     " Hz: must be finite and not negative");
  check_noise_floor(settings.noise_floor);
  BandKurtosis sk(x, sample_rate, settings.noise_floor);
  const double nyquist = 0.5 * sample_rate;
  const double narrowest = std::max(settings.min_bandwidth, kKurtogramMinBins * sk.resolution());
  // Band counts 1, 2, 3, 4, 6, 8, 12, …: the binary level 2^j, then (j ≥ 1) the third level
  // 3·2^(j−1), while the bands stay wide enough; the whole band always.
  std::vector<int> levels = {1};
  for (int binary = 2; nyquist / binary >= narrowest; binary *= 2) {
    levels.push_back(binary);
    if (nyquist / (3 * binary / 2) >= narrowest) levels.push_back(3 * binary / 2);
  }
  Kurtogram k;
  for (int bands : levels) {
    const double width = nyquist / bands;
    // One transform length for the level (its bands differ by a bin or two): one FFT table.
    const auto widest = static_cast<std::size_t>(std::ceil(width / sk.resolution())) + 2;
    const std::size_t level_length = fast_fft_length(2 * widest - 1);
    for (int i = 0; i < bands; ++i) {
      KurtogramBand b;
      b.level = std::log2(static_cast<double>(bands));
      b.bands = bands;
      b.index = i;
      b.band = {i * width, i + 1 == bands ? nyquist : (i + 1) * width};
      const BandKurtosis::Result r = sk(b.band, level_length);
      b.spectral_kurtosis = r.spectral_kurtosis;
      b.energy_fraction = r.energy_fraction;
      if (k.map.empty() || b.spectral_kurtosis > k.best.spectral_kurtosis) k.best = b;
      k.map.push_back(b);
    }
  }
  return k;
}

}  // namespace bearing
