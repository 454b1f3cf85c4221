// One fault family's line test in one squared envelope spectrum: harmonics, physics, decoys.

#include "bearing/family_test.h"

#include <algorithm>
#include <cmath>

namespace bearing {

namespace {

double median(std::vector<double>& v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

long bin_of(double hz, double df) {
  return std::lround(hz / df);
}

// The largest bin in [w0, w1] not excluded, against the floor of [r0, r1]; window 0 if none.
HarmonicTest read_line(const SesView& v, long w0, long w1, long r0, long r1, double p) {
  const std::vector<double>& P = *v.power;
  HarmonicTest l;
  std::vector<double> ring(P.begin() + r0, P.begin() + r1 + 1);
  const double floor_mean = median(ring) / std::log(2.0);
  long at = -1;
  for (long k = w0; k <= w1; ++k) {
    if (v.excluded && (*v.excluded)[static_cast<std::size_t>(k)]) continue;
    ++l.window;
    if (at < 0 || P[static_cast<std::size_t>(k)] > P[static_cast<std::size_t>(at)]) at = k;
  }
  if (at < 0 || !(floor_mean > 0)) return HarmonicTest{};
  l.frequency = static_cast<double>(at) * v.df;
  l.ratio = P[static_cast<std::size_t>(at)] / floor_mean;
  l.threshold = exceedance_threshold(p, l.window);
  l.excess = 10 * std::log10(l.ratio / l.threshold);
  return l;
}

// The k-th largest of three values (k = 1, 2, 3).
double kth_largest(std::array<double, 3> v, int k) {
  std::sort(v.begin(), v.end(), [](double a, double b) { return a > b; });
  return v[static_cast<std::size_t>(k - 1)];
}

// A side line at `hz` (±1.5 bins) over the floor of the 20 bins (≥ 10 Hz) each side of it.
bool side_line(const SesView& v, double hz, double p, SideLine& out) {
  const long k0 = static_cast<long>(std::floor(hz / v.df - 1.5));
  const long k1 = static_cast<long>(std::ceil(hz / v.df + 1.5));
  const long half = std::max<long>(20, bin_of(10.0, v.df));
  const long n = static_cast<long>(v.power->size());
  if (k0 - half < 3 || k1 + half >= n || (k1 + half) * v.df > v.width) return false;
  const std::vector<double>& P = *v.power;
  std::vector<double> ring(P.begin() + (k0 - half), P.begin() + k0);
  ring.insert(ring.end(), P.begin() + k1 + 1, P.begin() + k1 + 1 + half);
  const double floor_mean = median(ring) / std::log(2.0);
  double best = 0;
  for (long k = k0; k <= k1; ++k) best = std::max(best, P[static_cast<std::size_t>(k)]);
  if (!(floor_mean > 0) || !(best > 0)) return false;
  out.frequency = hz;
  out.excess =
      10 * std::log10(best / floor_mean / exceedance_threshold(p, static_cast<int>(k1 - k0 + 1)));
  return true;
}

void test_physics(const SesView& v, FamilyTest& t, double shaft, double ftf, double p_family) {
  if (t.family == FaultFamily::outer) return;
  const bool inner = t.family == FaultFamily::inner;
  const double f1 = t.harmonics[0].frequency, f2 = t.harmonics[1].frequency;
  // The ball's cage rate moves with the slip its lines show.
  const double g = inner ? shaft : ftf * f1 / t.harmonics[0].nominal;
  std::vector<std::pair<const char*, double>> lines =
      inner ? std::vector<std::pair<const char*, double>>{{"BPFI-fr", f1 - g},
                                                          {"BPFI+fr", f1 + g},
                                                          {"2xBPFI-fr", f2 - g},
                                                          {"2xBPFI+fr", f2 + g}}
            : std::vector<std::pair<const char*, double>>{
                  {"2xBSF-FTF", f1 - g}, {"2xBSF+FTF", f1 + g}, {"4xBSF-FTF", f2 - g},
                  {"4xBSF+FTF", f2 + g}, {"BSF", 0.5 * f1},     {"FTF", g}};
  const double p = p_family / static_cast<double>(lines.size());
  t.physics = false;
  for (const auto& [label, hz] : lines) {
    SideLine s;
    s.label = label;
    if (!side_line(v, hz, p, s)) continue;
    t.physics = t.physics || s.excess > 0;
    t.side_lines.push_back(s);
  }
  std::sort(t.side_lines.begin(), t.side_lines.end(),
            [](const SideLine& a, const SideLine& b) { return a.excess > b.excess; });
}

void test_decoys(const SesView& v, FamilyTest& t, double carrier, double g, double p,
                 const LineTestSettings& s) {
  t.decoys_applied = true;
  const double step = 2 * s.slip;
  const int steps = static_cast<int>(std::floor(s.decoy_span / step + 1e-9));
  for (int i = -steps; i <= steps; ++i) {
    const double decoy = carrier * (1 + i * step);
    bool own = false;  // near the family's own series c + m·g
    for (int m = -3; m <= 3 && !own; ++m)
      own = std::abs(decoy - (carrier + m * g)) <= step * carrier;
    if (own || decoy <= 0) continue;
    const FamilyTest d = test_harmonics(v, t.family, decoy, p, t.needed, s);
    if (!d.rated) continue;
    ++t.decoys;
    t.decoy_score = std::max(t.decoy_score, d.score);
  }
}

}  // namespace

double exceedance_threshold(double p, int window) {
  return -std::log(-std::expm1(std::log1p(-p) / std::max(window, 1)));
}

double harmonic_probability(double rate, int needed) {
  if (needed >= 3) return std::cbrt(rate);
  if (needed <= 1) return -std::expm1(std::log1p(-rate) / 3);
  // 3p² − 2p³ rises monotonically from 0 to 1/2 on [0, 1/2]: bisection.
  double lo = 0, hi = 0.5;
  for (int i = 0; i < 200; ++i) {
    const double p = 0.5 * (lo + hi);
    (3 * p * p - 2 * p * p * p < rate ? lo : hi) = p;
  }
  return 0.5 * (lo + hi);
}

FamilyTest test_harmonics(const SesView& v, FaultFamily family, double c, double p, int needed,
                          const LineTestSettings& s) {
  FamilyTest t;
  t.family = family;
  t.needed = needed;
  const long n = static_cast<long>(v.power->size());
  std::array<double, 3> excess{};
  for (int h = 1; h <= 3; ++h) {
    const double centre = h * c;
    const long w0 = bin_of(centre * (1 - s.slip), v.df), w1 = bin_of(centre * (1 + s.slip), v.df);
    const long r0 = std::max<long>(3, bin_of(centre - 0.5 * c, v.df));
    const long r1 = bin_of(centre + 0.5 * c, v.df);
    if (r1 >= n || static_cast<double>(r1) * v.df > v.width || w0 < r0 || w1 > r1) return t;
    HarmonicTest l = read_line(v, w0, w1, r0, r1, p);
    if (l.window == 0) return t;
    l.harmonic = h;
    l.nominal = centre;
    t.harmonics[static_cast<std::size_t>(h - 1)] = l;
    excess[static_cast<std::size_t>(h - 1)] = l.excess;
    if (l.excess > 0) ++t.standing_out, t.score += l.excess;
  }
  t.rated = true;
  t.detected = t.standing_out >= needed;
  t.margin = kth_largest(excess, needed);
  return t;
}

FamilyTest test_family(const SesView& v, FaultFamily family, double carrier, double shaft,
                       double ftf, double p_family, int needed, bool with_decoys,
                       const LineTestSettings& s) {
  // p of 2 of 3 at the family's rate; a second family needs all 3 at that p (rate p³).
  const double p = harmonic_probability(p_family, 2);
  FamilyTest t = test_harmonics(v, family, carrier, p, needed, s);
  if (!t.detected) return t;
  test_physics(v, t, shaft, ftf, p_family);
  if (!t.physics) {
    t.detected = false;
    t.margin = t.side_lines.empty() ? -100.0 : std::min(0.0, t.side_lines.front().excess);
    return t;
  }
  if (with_decoys) {
    test_decoys(v, t, carrier, family == FaultFamily::ball ? ftf : shaft, p, s);
    const double over = t.score - t.decoy_score;
    if (t.decoys == 0 || over <= 0) {
      t.detected = false;
      t.margin = t.decoys == 0 ? -100.0 : over;
      return t;
    }
    t.margin = std::min(t.margin, over);
  }
  return t;
}

}  // namespace bearing
