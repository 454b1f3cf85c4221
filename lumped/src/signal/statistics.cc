// Mean, RMS, peak-to-peak, kurtosis and crest factor of one channel (docs/model.md §7).

#include "bearing/signal/statistics.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

#include "bearing/errors.h"
#include "bearing/units.h"

namespace bearing {

ChannelStatistics channel_statistics(const std::vector<double>& x) {
  if (x.empty()) throw InputError("channel statistics: no samples given; at least 1 is needed");
  const std::size_t n = x.size();
  double lo = x[0], hi = x[0];
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(x[i]))
      throw InputError("channel statistics: sample " + std::to_string(i) + " = " +
                       format_number(x[i]) + ": every sample must be finite");
    lo = std::min(lo, x[i]);
    hi = std::max(hi, x[i]);
  }

  ChannelStatistics s;
  if (lo == hi) {  // constant: the mean is exact and the shape factors are defined as 0
    s.mean = lo;
    return s;
  }

  // Scale by the power of two just above the largest magnitude (exact, no rounding), so the sum
  // cannot overflow for huge values.
  int exponent = 0;
  std::frexp(std::max(std::abs(lo), std::abs(hi)), &exponent);
  const double scale = std::ldexp(1.0, exponent);
  double sum = 0;
  for (double v : x) sum += v / scale;
  const double mean_scaled = sum / static_cast<double>(n);
  s.mean = mean_scaled * scale;
  s.ptp = hi - lo;

  // Deviations divided by the largest one lie in [−1, 1] with at least one of magnitude 1, so d⁴
  // neither under- nor overflows whatever the amplitude; kurtosis and crest are ratios anyway.
  const double dmax = std::max(hi / scale - mean_scaled, mean_scaled - lo / scale);
  double m2 = 0, m4 = 0;
  for (double v : x) {
    const double d = (v / scale - mean_scaled) / dmax;
    const double d2 = d * d;
    m2 += d2;
    m4 += d2 * d2;
  }
  m2 /= static_cast<double>(n);
  m4 /= static_cast<double>(n);
  const double rms_unit = std::sqrt(m2);  // RMS in units of the largest deviation
  s.rms = rms_unit * dmax * scale;
  s.kurtosis = m4 / (m2 * m2);
  s.crest = 1.0 / rms_unit;
  return s;
}

}  // namespace bearing
