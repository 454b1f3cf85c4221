// Spectral peaks, refined in frequency and named after the nearest bearing frequency (MODEL.md §7).

#include "bearing/signal/peaks.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>

#include "bearing/errors.h"
#include "bearing/units.h"

namespace bearing {

namespace {

void check_frequency(const char* label, double f) {
  if (!(std::isfinite(f) && f >= 0))
    throw InputError(std::string("bearing frequency ") + label + " = " + format_number(f) +
                     " Hz: must be finite and not negative");
}

std::string harmonic_name(int h, const char* label) {
  return (h == 1 ? std::string() : std::to_string(h) + "x") + label;
}

// How many harmonics of f a family gets: max_harmonic, or those up to max_frequency.
struct HarmonicRange {
  int max_harmonic = 0;      ///< > 0: this many
  double max_frequency = 0;  ///< else: every k·f ≤ max_frequency, at most kMaxPerFamily
  int count(double f) const {
    constexpr double kMaxPerFamily = 4096;
    if (max_harmonic > 0) return max_harmonic;
    return static_cast<int>(std::min(std::floor(max_frequency / f), kMaxPerFamily));
  }
};

void add_harmonics(std::vector<NamedFrequency>& names, const char* label, double f,
                   HarmonicRange range) {
  check_frequency(label, f);
  if (f == 0) return;  // e.g. a shaft at rest: no line to name
  for (int h = 1; h <= range.count(f); ++h) names.push_back({harmonic_name(h, label), h * f, h});
}

// The sidebands k·f_c ± m·f_m, m = first … last, of the harmonics k = step, 2·step, … of f_c in
// `range`: "2xBPFI-fr", "BPFI+2fr", "4xBSF-FTF", …; a lower sideband only where it is above 0.
// Listed by m, then k (the first sidebands before the second); `harmonic` is the carrier's k.
void add_sidebands(std::vector<NamedFrequency>& names, const char* carrier, double fc,
                   const char* modulation, double fm, int first, int last, HarmonicRange range,
                   int step = 1) {
  if (!(fc > 0 && fm > 0)) return;
  for (int m = first; m <= last; ++m) {
    const std::string offset = (m == 1 ? std::string() : std::to_string(m)) + modulation;
    for (int k = step; k <= range.count(fc); k += step) {
      const std::string base = harmonic_name(k, carrier);
      if (k * fc - m * fm > 0) names.push_back({base + "-" + offset, k * fc - m * fm, k});
      names.push_back({base + "+" + offset, k * fc + m * fm, k});
    }
  }
}

std::vector<NamedFrequency> names_of(double shaft, double ftf, double bpfo, double bpfi, double bsf,
                                     HarmonicRange range, bool faults = false) {
  std::vector<NamedFrequency> names;
  add_harmonics(names, "fr", shaft, range);
  add_harmonics(names, "FTF", ftf, range);
  add_harmonics(names, "BPFO", bpfo, range);
  add_harmonics(names, "BPFI", bpfi, range);
  add_harmonics(names, "BSF", bsf, range);
  // The inner race turns with the shaft, so its lines come with shaft-rate sidebands
  // k·BPFI ± f_r (e.g. inner-race waviness under a fixed load zone). Listed after the plain
  // harmonics: a tie goes to the simpler name.
  add_sidebands(names, "BPFI", bpfi, "fr", shaft, 1, 1, range);
  if (!faults) return names;
  // A local fault's lines (the envelope's): an inner-race defect turns through the load zone once
  // per shaft turn, k·BPFI ± 2f_r too; a ball defect strikes both races, twice per spin (2k·BSF),
  // and is carried through the load zone by the cage (± m·FTF).
  add_sidebands(names, "BPFI", bpfi, "fr", shaft, 2, 2, range);
  add_sidebands(names, "BSF", bsf, "FTF", ftf, 1, 2, range, 2);
  return names;
}

// Offset δ ∈ [−½, ½] of the vertex of the parabola through (−1, a), (0, b), (1, c), for b a local
// maximum (b > a, b ≥ c). Fitted to log amplitudes when all three are positive: a windowed tone's
// main lobe is closer to a Gaussian than to a parabola, which cuts the worst bias for the Hann
// window from 0.053 to 0.016 bins (rectangular 0.23 → 0.17; flat-top 0.15 either way).
double parabola_vertex(double a, double b, double c) {
  if (a > 0 && c > 0) a = std::log(a), b = std::log(b), c = std::log(c);
  const double curvature = a - 2 * b + c;  // < 0 at a strict maximum
  if (!(curvature < 0)) return 0;
  return std::clamp(0.5 * (a - c) / curvature, -0.5, 0.5);
}

// The named frequency nearest to f within `tolerance` [Hz], else nullptr. Distances equal to
// `tie` [Hz] go to the lower harmonic number, then keep the earlier name.
const NamedFrequency* nearest_name(double f, double tolerance, double tie,
                                   const std::vector<NamedFrequency>& names) {
  const NamedFrequency* best = nullptr;
  double best_distance = std::numeric_limits<double>::infinity();
  for (const NamedFrequency& name : names) {
    const double d = std::abs(name.frequency - f);
    if (d > tolerance) continue;
    const bool tied = std::abs(d - best_distance) <= tie;
    if ((!tied && d < best_distance) || (tied && best && name.harmonic < best->harmonic))
      best = &name, best_distance = d;
  }
  return best;
}

}  // namespace

std::vector<NamedFrequency> bearing_frequency_names(double shaft, double ftf, double bpfo,
                                                    double bpfi, double bsf, int max_harmonic) {
  if (max_harmonic < 1)
    throw InputError("bearing frequency names: max_harmonic = " + std::to_string(max_harmonic) +
                     ": must be at least 1");
  return names_of(shaft, ftf, bpfo, bpfi, bsf, HarmonicRange{max_harmonic, 0});
}

std::vector<NamedFrequency> bearing_frequency_names_up_to(double max_frequency, double shaft,
                                                          double ftf, double bpfo, double bpfi,
                                                          double bsf) {
  if (!(std::isfinite(max_frequency) && max_frequency > 0))
    throw InputError("bearing frequency names: band up to " + format_number(max_frequency) +
                     " Hz: must be positive and finite");
  return names_of(shaft, ftf, bpfo, bpfi, bsf, HarmonicRange{0, max_frequency});
}

std::vector<NamedFrequency> fault_frequency_names_up_to(double max_frequency, double shaft,
                                                        double ftf, double bpfo, double bpfi,
                                                        double bsf) {
  if (!(std::isfinite(max_frequency) && max_frequency > 0))
    throw InputError("fault frequency names: band up to " + format_number(max_frequency) +
                     " Hz: must be positive and finite");
  return names_of(shaft, ftf, bpfo, bpfi, bsf, HarmonicRange{0, max_frequency}, true);
}

std::vector<Peak> find_peaks(const Spectrum& spectrum, const std::vector<NamedFrequency>& names,
                             int max_peaks, double relative_threshold, double tolerance_bins) {
  const std::vector<double>& a = spectrum.amplitude;
  if (spectrum.frequency.size() != a.size())
    throw InputError("find peaks: the spectrum has " + std::to_string(spectrum.frequency.size()) +
                     " frequencies but " + std::to_string(a.size()) + " amplitudes");
  if (!(std::isfinite(spectrum.resolution) && spectrum.resolution > 0))
    throw InputError("find peaks: spectrum resolution = " + format_number(spectrum.resolution) +
                     " Hz: must be positive and finite");
  if (max_peaks < 0)
    throw InputError("find peaks: max_peaks = " + std::to_string(max_peaks) +
                     ": must not be negative");
  if (!(relative_threshold >= 0 && relative_threshold <= 1))
    throw InputError("find peaks: relative_threshold = " + format_number(relative_threshold) +
                     ": must lie in [0, 1]");
  if (!(std::isfinite(tolerance_bins) && tolerance_bins >= 0))
    throw InputError("find peaks: tolerance_bins = " + format_number(tolerance_bins) +
                     ": must be finite and not negative");

  const std::size_t m = a.size();
  if (m < 2 || max_peaks == 0) return {};
  const double largest = *std::max_element(a.begin() + 1, a.end());
  const double threshold = relative_threshold * largest;

  std::vector<std::size_t> maxima;
  for (std::size_t k = 1; k < m; ++k) {
    const bool above_left = a[k] > a[k - 1];
    const bool not_below_right = k + 1 == m || a[k] >= a[k + 1];
    if (above_left && not_below_right && a[k] >= threshold) maxima.push_back(k);
  }
  // Largest first; equal amplitudes in frequency order, so the result does not depend on the
  // sort's stability.
  const auto larger = [&a](std::size_t i, std::size_t j) {
    return a[i] > a[j] || (a[i] == a[j] && i < j);
  };
  const std::size_t keep = std::min(maxima.size(), static_cast<std::size_t>(max_peaks));
  std::partial_sort(maxima.begin(), maxima.begin() + static_cast<std::ptrdiff_t>(keep),
                    maxima.end(), larger);
  maxima.resize(keep);

  std::vector<Peak> peaks;
  peaks.reserve(keep);
  for (std::size_t k : maxima) {
    const double delta = k + 1 < m ? parabola_vertex(a[k - 1], a[k], a[k + 1]) : 0.0;
    Peak p;
    p.frequency = spectrum.frequency[k] + delta * spectrum.resolution;
    p.amplitude = a[k];
    const NamedFrequency* name = nearest_name(p.frequency, tolerance_bins * spectrum.resolution,
                                              1e-9 * spectrum.resolution, names);
    if (name) p.label = name->label, p.label_error = p.frequency - name->frequency;
    peaks.push_back(std::move(p));
  }
  return peaks;
}

}  // namespace bearing
