#pragma once
// Scalar condition indicators of one channel (docs/model.md §7): mean, RMS, peak-to-peak, kurtosis
// and crest factor, computed over whatever window the caller passes (the post-transient part of a
// response; this layer does not know where the transient ends).

#include <vector>

namespace bearing {

/// Statistics of one sampled channel x. Every field is in the unit of x unless marked [-].
struct ChannelStatistics {
  double mean = 0;      ///< arithmetic mean (the static offset) [unit of x]
  double rms = 0;       ///< RMS of x − mean, i.e. the vibration without the offset [unit of x]
  double ptp = 0;       ///< peak to peak, max − min [unit of x]
  double kurtosis = 0;  ///< E[(x−mean)⁴] / E[(x−mean)²]²: 3 Gaussian, 1.5 sine, 1 square [-]
  double crest = 0;     ///< max |x − mean| / rms: √2 for a sine, 1 for a square wave [-]
};

/// Statistics of the samples x [unit of x], with population (1/N) moments. A constant signal
/// (max = min, so rms = 0) has kurtosis = 0 and crest = 0 by definition here, never NaN, so a
/// summary of a channel at rest stays valid JSON. Scale-free: the moments are taken of the
/// deviations divided by their largest magnitude, so tiny (nm) or huge signals neither under- nor
/// overflow. O(N), three passes.
/// Throws InputError if x is empty or holds a NaN or an infinity.
ChannelStatistics channel_statistics(const std::vector<double>& x);

}  // namespace bearing
