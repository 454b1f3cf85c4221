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

// The one-sided DFT X_0 … X_{⌊N/2⌋} of the record, mean removed and Hann-windowed, and its energy
// Σ_{k≥1} |X_k|²; the complex FFTs of the band lengths used so far.
class BandKurtosis {
 public:
  BandKurtosis(const std::vector<double>& x, double rate) : n_(x.size()), rate_(rate) {
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

  // SK of the bins in [low, high] (inclusive, 1e-9 bin of slack; never DC).
  double operator()(FrequencyBand band) {
    const double res = resolution();
    const double first = std::ceil(band.low / res - 1e-9);
    const double last = std::floor(band.high / res + 1e-9);
    const std::size_t k0 = first < 1 ? 1 : static_cast<std::size_t>(first);
    const std::size_t k1 = std::min(static_cast<std::size_t>(last), spectrum_.size() - 1);
    if (k1 < k0) return 0;  // no bin inside the band
    const std::size_t m = k1 - k0 + 1;
    double band_energy = 0;
    for (std::size_t k = k0; k <= k1; ++k) band_energy += std::norm(spectrum_[k]);
    if (!(band_energy > kSilentBand * energy_)) return 0;
    // c on L ≥ 2M − 1 points: the band's bins shifted to baseband, zero padded.
    const std::size_t length = fast_fft_length(2 * m - 1);
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
    return kHannKurtosisCorrection * p4 / (p2 * p2) - 2;
  }

 private:
  std::size_t n_;
  double rate_;
  std::vector<std::complex<double>> spectrum_;
  double energy_ = 0;
  std::map<std::size_t, ComplexFft> transforms_;
  std::vector<std::complex<double>> scratch_;
};

}  // namespace

double spectral_kurtosis(const std::vector<double>& x, double sample_rate, FrequencyBand band) {
  check_record(x, sample_rate);
  check_band(band, sample_rate);
  BandKurtosis sk(x, sample_rate);
  return sk(band);
}

Kurtogram fast_kurtogram(const std::vector<double>& x, double sample_rate, double min_bandwidth) {
  check_record(x, sample_rate);
  if (!(std::isfinite(min_bandwidth) && min_bandwidth >= 0))
    throw InputError("kurtogram: minimum band width = " + format_number(min_bandwidth) +
                     " Hz: must be finite and not negative");
  BandKurtosis sk(x, sample_rate);
  const double nyquist = 0.5 * sample_rate;
  const double narrowest = std::max(min_bandwidth, kKurtogramMinBins * sk.resolution());
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
    for (int i = 0; i < bands; ++i) {
      KurtogramBand b;
      b.level = std::log2(static_cast<double>(bands));
      b.bands = bands;
      b.index = i;
      b.band = {i * width, i + 1 == bands ? nyquist : (i + 1) * width};
      b.spectral_kurtosis = sk(b.band);
      if (k.map.empty() || b.spectral_kurtosis > k.best.spectral_kurtosis) k.best = b;
      k.map.push_back(b);
    }
  }
  return k;
}

}  // namespace bearing
