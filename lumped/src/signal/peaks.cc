// Spectral peaks, refined in frequency and named after the nearest bearing frequency (docs/model.md
// §7).

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

// The named frequency nearest to f within `tolerance` [Hz], else nullptr. Distances equal to
// `tie` [Hz] go to the lower order k/m, then keep the earlier name.
const NamedFrequency* nearest_name(double f, double tolerance, double tie,
                                   const std::vector<NamedFrequency>& names) {
  const NamedFrequency* best = nullptr;
  double best_distance = std::numeric_limits<double>::infinity();
  for (const NamedFrequency& name : names) {
    const double d = std::abs(name.frequency - f);
    if (d > tolerance) continue;
    const bool tied = std::abs(d - best_distance) <= tie;
    const bool lower_order =  // k/m < k'/m', in integers
        best && static_cast<long long>(name.harmonic) * best->subharmonic <
                    static_cast<long long>(best->harmonic) * name.subharmonic;
    if ((!tied && d < best_distance) || (tied && lower_order)) best = &name, best_distance = d;
  }
  return best;
}

}  // namespace

double peak_vertex_offset(double a, double b, double c) {
  // Fitted to log amplitudes when all three are positive: a windowed tone's main lobe is closer to
  // a Gaussian than to a parabola, which cuts the worst bias for the Hann window from 0.053 to
  // 0.016 bins (rectangular 0.23 → 0.17; flat-top 0.15 either way).
  if (a > 0 && c > 0) a = std::log(a), b = std::log(b), c = std::log(c);
  const double curvature = a - 2 * b + c;  // < 0 at a strict maximum
  if (!(curvature < 0)) return 0;
  return std::clamp(0.5 * (a - c) / curvature, -0.5, 0.5);
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
    const double delta = k + 1 < m ? peak_vertex_offset(a[k - 1], a[k], a[k + 1]) : 0.0;
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
