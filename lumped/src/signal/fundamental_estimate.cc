// The fundamental of a harmonic series: the comb search, then a least-squares refinement.

#include "bearing/signal/fundamental_estimate.h"

#include <algorithm>

#include "bearing/signal/peaks.h"

namespace bearing {

namespace {

// A harmonic enters the refinement if its refined peak lies within 0.1 bin of k f_1: ten times
// the Hann refinement's bias for a lone line (0.016 bin, peaks.h). A peak further off is pulled by
// a line of another source beside it (BSF 1.3 bins from 2 f_r in a 1 s simulation of the 6308;
// the mains' 60 Hz 1.4 bins from 2 f_r of the CWRU rig's 4-pole motor) and would bias f.
constexpr double kHarmonicAgreement = 0.1;

}  // namespace

FundamentalEstimate estimate_fundamental(const Spectrum& s, double nominal, double tolerance,
                                         int harmonics, double false_alarm) {
  HarmonicComb comb;
  comb.carrier = nominal;
  comb.harmonics = harmonics;
  comb.slip = tolerance;
  comb.anchored = true;
  comb.rated = {2 * s.resolution, s.frequency.empty() ? 0.0 : s.frequency.back()};
  FundamentalEstimate out;
  out.nominal = nominal;
  out.tolerance = tolerance;
  out.comb = search_comb(s, comb, false_alarm);
  out.found = out.comb.detected;
  out.frequency = out.comb.carrier;
  const std::vector<double>& a = s.amplitude;
  double fundamental = 0, sum_kf = 0, sum_kk = 0;
  for (const CombLine& l : out.comb.lines) {
    if (!l.rated) continue;
    HarmonicLine h;
    h.order = l.harmonic;
    h.level = l.level;
    // The largest of the three bins around the comb's, refined.
    auto k = static_cast<std::size_t>(std::lround(l.frequency / s.resolution));
    if (k > 1 && a[k - 1] > a[k]) --k;
    if (k + 1 < a.size() && a[k + 1] > a[k]) ++k;
    const double delta = (k >= 1 && k + 1 < a.size() && a[k] >= a[k - 1] && a[k] >= a[k + 1])
                             ? peak_vertex_offset(a[k - 1], a[k], a[k + 1])
                             : 0.0;
    h.frequency = (static_cast<double>(k) + delta) * s.resolution;
    h.amplitude = a[k];
    if (h.order == 1) fundamental = h.frequency;
    // The fundamental (on a peak: anchored), and the harmonics over the threshold whose peak lies
    // within kHarmonicAgreement of k times it.
    h.used = out.found && (h.order == 1 || (l.level >= out.comb.threshold && fundamental > 0 &&
                                            std::abs(h.frequency - h.order * fundamental) <=
                                                kHarmonicAgreement * s.resolution));
    if (h.used) sum_kf += h.order * h.frequency, sum_kk += h.order * h.order;
    out.harmonics.push_back(h);
  }
  if (sum_kk > 0) out.frequency = sum_kf / sum_kk;
  return out;
}

}  // namespace bearing
