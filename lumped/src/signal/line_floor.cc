// A line's floor from the median of the bins beside it, and the exact chance of exceeding it.

#include "bearing/signal/line_floor.h"

#include <math.h>  // lgamma_r (glibc)

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "bearing/errors.h"
#include "bearing/units.h"

namespace bearing {

LineFloor floor_around(const Spectrum& s, double low, double high, double lowest, double highest) {
  if (s.frequency.size() != s.amplitude.size())
    throw InputError("line floor: the spectrum has " + std::to_string(s.frequency.size()) +
                     " frequencies but " + std::to_string(s.amplitude.size()) + " amplitudes");
  if (!(std::isfinite(s.resolution) && s.resolution > 0))
    throw InputError("line floor: spectrum resolution = " + format_number(s.resolution) +
                     " Hz: must be positive and finite");
  if (!(low <= high))
    throw InputError("line floor: window [" + format_number(low) + " Hz, " + format_number(high) +
                     " Hz]: low must not exceed high");
  const double res = s.resolution;
  const double w = std::max(high - low, kFloorFlankBins * res);
  const auto bin = [res](double f) { return static_cast<long>(std::floor(f / res + 1e-9)); };
  const long last = static_cast<long>(s.amplitude.size()) - 1;
  const long lo_limit = std::max(0L, static_cast<long>(std::ceil(lowest / res - 1e-9)));
  const long hi_limit = std::min(last, bin(highest));
  // Left flank: bins strictly below the window, counted outwards from it; right flank likewise.
  const long window_first = static_cast<long>(std::ceil(low / res - 1e-9));
  const long window_last = bin(high);
  std::vector<double> samples;
  for (long k = window_first - 1; k >= 0 && k * res >= low - w - 1e-9 * res; k -= 2)
    if (k >= lo_limit && k <= hi_limit) samples.push_back(s.amplitude[k] * s.amplitude[k]);
  for (long k = window_last + 1; k <= last && k * res <= high + w + 1e-9 * res; k += 2)
    if (k >= lo_limit && k <= hi_limit) samples.push_back(s.amplitude[k] * s.amplitude[k]);
  if (samples.empty()) return {};
  const std::size_t j = (samples.size() + 1) / 2;  // ⌈n/2⌉, 1-based
  std::nth_element(samples.begin(), samples.begin() + (j - 1), samples.end());
  return {samples[j - 1], static_cast<int>(samples.size())};
}

double floor_exceedance(double ratio, int samples) {
  if (!(ratio >= 0))
    throw InputError("floor exceedance: ratio = " + format_number(ratio) +
                     ": must be a number >= 0");
  if (samples < 0)
    throw InputError("floor exceedance: " + std::to_string(samples) +
                     " samples: must not be negative");
  if (std::isinf(ratio)) return samples > 0 ? 0.0 : 1.0;
  // Π_{i=1}^{j} m_i / (m_i + R), m_i = n − i + 1, in closed form:
  // Γ(n + 1) Γ(n − j + 1 + R) / (Γ(n − j + 1) Γ(n + 1 + R)), in logarithms (underflows only as
  // the probability does; lgamma's absolute error ~1e-16 of its value, 1e-9 at n + R ~ 1e6).
  // lgamma_r: std::lgamma writes the global signgam (a data race between threads).
  const auto log_gamma = [](double v) {
    int sign = 0;
    return ::lgamma_r(v, &sign);
  };
  const double n = samples, j = (samples + 1) / 2;
  const double log_p = log_gamma(n + 1) - log_gamma(n - j + 1) + log_gamma(n - j + 1 + ratio) -
                       log_gamma(n + 1 + ratio);
  return std::exp(log_p);
}

}  // namespace bearing
