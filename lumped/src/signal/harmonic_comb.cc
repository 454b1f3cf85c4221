// A comb of harmonics and sidebands searched within a slip window and rated over the floor.

#include "bearing/signal/harmonic_comb.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "bearing/errors.h"
#include "bearing/signal/line_floor.h"
#include "bearing/units.h"

namespace bearing {

namespace {

// The law of the comb's terms on a grid of kGridStep dB from 0 to kGridTop dB. Above 60 dB a ratio
// over a floor of the ≥ 50 samples a rated line has is below 1e-100.
constexpr double kGridStep = 0.1;
constexpr int kGridPoints = 601;  // 0 … 60 dB
// Levels are reported down to this (a bin at exactly zero would be −∞) [dB].
constexpr double kLowestLevel = -200;

void check_false_alarm(double false_alarm) {
  if (!(false_alarm > 0 && false_alarm < 1))
    throw InputError("comb search: false-alarm probability = " + format_number(false_alarm) +
                     ": allowed 0 < p < 1");
}

void check_comb(const HarmonicComb& c, double false_alarm) {
  if (!(std::isfinite(c.carrier) && c.carrier > 0))
    throw InputError("comb search: carrier = " + format_number(c.carrier) +
                     " Hz: must be positive and finite");
  if (c.harmonics < 1)
    throw InputError("comb search: harmonics = " + std::to_string(c.harmonics) + ": at least 1");
  if (!(std::isfinite(c.modulation) && c.modulation >= 0))
    throw InputError("comb search: modulation = " + format_number(c.modulation) +
                     " Hz: must be finite and not negative");
  if (!(c.slip >= 0 && c.slip < 0.5))
    throw InputError("comb search: slip = " + format_number(c.slip) + ": allowed 0 <= slip < 0.5");
  check_false_alarm(false_alarm);
}

// A line of the comb with what does not depend on the offset.
struct LineSetup {
  CombLine line;
  double rate = 0;  // dν/dδ [Hz]
};

std::vector<LineSetup> set_up_lines(const Spectrum& s, const HarmonicComb& c) {
  std::vector<LineSetup> out;
  const double res = s.resolution;
  for (int k = 1; k <= c.harmonics; ++k)
    for (int m = c.modulation > 0 ? -1 : 0; m <= (c.modulation > 0 ? 1 : 0); ++m) {
      LineSetup l;
      l.line.harmonic = k;
      l.line.sideband = m;
      l.line.nominal = k * c.carrier + m * c.modulation;
      l.rate = k * c.carrier + (c.modulation_slips ? m * c.modulation : 0.0);
      const double a = l.line.nominal - c.slip * l.rate, b = l.line.nominal + c.slip * l.rate;
      const double low = std::min(a, b), high = std::max(a, b);
      const double flank = std::max(high - low, kFloorFlankBins * res);
      const bool inside = low > 0 && low - flank >= c.rated.low && high + flank <= c.rated.high &&
                          std::lround(high / res) < static_cast<long>(s.amplitude.size());
      if (inside) {
        const LineFloor f = floor_around(s, low, high, c.rated.low, c.rated.high);
        l.line.floor = std::sqrt(f.power);
        l.line.floor_samples = f.samples;
        l.line.rated = f.samples > 0 && f.power > 0;
      }
      out.push_back(l);
    }
  return out;
}

bool in_zone(double f, const std::vector<FrequencyBand>& zones) {
  for (const FrequencyBand& z : zones)
    if (f >= z.low && f <= z.high) return true;
  return false;
}

// The bin nearest to f is a peak: above its left neighbour, not below its right one.
bool on_peak(const Spectrum& s, double f) {
  const long k = std::lround(f / s.resolution);
  const long last = static_cast<long>(s.amplitude.size()) - 1;
  if (k < 1 || k > last) return false;
  const auto a = [&s](long i) { return s.amplitude[static_cast<std::size_t>(i)]; };
  return a(k) > a(k - 1) && (k == last || a(k) >= a(k + 1));
}

// The lines at offset δ (bin, amplitude, level, excluded) and the comb's evidence there.
double evaluate(const Spectrum& s, const HarmonicComb& c, double delta,
                std::vector<LineSetup>& lines, int harmonics_rated) {
  std::vector<double> term(c.harmonics + 1, 0.0);
  for (LineSetup& l : lines) {
    CombLine& line = l.line;
    const double f = line.nominal + delta * l.rate;
    const long bin = std::max(0L, std::lround(f / s.resolution));
    line.frequency = bin * s.resolution;
    line.amplitude = bin < static_cast<long>(s.amplitude.size())
                         ? s.amplitude[static_cast<std::size_t>(bin)]
                         : 0;
    line.excluded = in_zone(line.frequency, c.excluded);
    line.level = 0;
    if (!line.rated || line.excluded) continue;
    const double power = line.amplitude * line.amplitude;
    const double floor = line.floor * line.floor;
    line.level = power > 0 ? std::max(kLowestLevel, 10 * std::log10(power / floor)) : kLowestLevel;
    term[line.harmonic] = std::max(term[line.harmonic], line.level);
  }
  double sum = 0;
  for (double t : term) sum += t;
  return harmonics_rated > 0 ? sum / harmonics_rated : 0;
}

// The law of one term (max over its lines of the level, 0 below 0 dB) on the grid, each value
// rounded up to the next grid point.
std::vector<double> term_law(const std::vector<int>& samples) {
  std::vector<double> pmf(kGridPoints);
  double previous = 0;
  for (int i = 0; i < kGridPoints; ++i) {
    const double ratio = std::pow(10.0, 0.1 * kGridStep * i);
    double cdf = 1;
    for (int n : samples) cdf *= 1 - floor_exceedance(ratio, n);
    pmf[i] = cdf - previous;
    previous = cdf;
  }
  pmf.back() += 1 - previous;  // above the grid's top (below 1e-100 for a rated line)
  return pmf;
}

}  // namespace

double comb_threshold(const std::vector<std::vector<int>>& floor_samples, double trials,
                      double false_alarm) {
  check_false_alarm(false_alarm);
  if (!(std::isfinite(trials) && trials >= 1))
    throw InputError("comb threshold: trials = " + format_number(trials) +
                     ": must be finite and at least 1");
  std::vector<double> sum = {1.0};  // the law of the sum of the terms so far: 0 with certainty
  int terms = 0;
  for (const std::vector<int>& lines : floor_samples) {
    for (int n : lines)
      if (n < 0)
        throw InputError("comb threshold: " + std::to_string(n) +
                         " floor samples: must not be negative");
    if (lines.empty()) continue;
    const std::vector<double> term = term_law(lines);
    std::vector<double> next(sum.size() + term.size() - 1, 0.0);
    for (std::size_t i = 0; i < sum.size(); ++i)
      for (std::size_t j = 0; j < term.size(); ++j) next[i + j] += sum[i] * term[j];
    sum = std::move(next);
    ++terms;
  }
  if (terms == 0) return 0;
  // The least grid point i with trials · P(S_d ≥ i) ≤ false_alarm, the tail summed from the
  // top. S_d, the sum of the rounded-up terms, lies on the grid and S_d ≥ S, so S > (i − 1)
  // implies S_d ≥ i: (i − 1) is a threshold for S, high by less than one step per term.
  double tail = 0;
  std::size_t least = sum.size();
  for (std::size_t i = sum.size(); i-- > 0;) {
    tail += sum[i];
    if (trials * tail > false_alarm) break;
    least = i;
  }
  const double below = least > 0 ? static_cast<double>(least - 1) : 0.0;
  return kGridStep * below / terms;
}

CombSearch search_comb(const Spectrum& s, const HarmonicComb& c, double false_alarm) {
  check_comb(c, false_alarm);
  std::vector<LineSetup> lines = set_up_lines(s, c);
  CombSearch out;
  out.false_alarm = false_alarm;
  std::vector<std::vector<int>> samples(c.harmonics);
  double fastest = 0;
  for (const LineSetup& l : lines)
    if (l.line.rated) {
      samples[l.line.harmonic - 1].push_back(l.line.floor_samples);
      fastest = std::max(fastest, std::abs(l.rate));
    }
  for (const auto& h : samples) out.rated_harmonics += h.empty() ? 0 : 1;
  // Offsets moving the fastest rated line by half a bin; the tries are the bins it crosses.
  const double res = s.resolution;
  const double step = fastest > 0 ? 0.5 * res / fastest : 2 * c.slip + 1;
  const long steps = c.slip > 0 ? static_cast<long>(std::ceil(2 * c.slip / step)) : 0;
  out.trials = std::floor(2 * c.slip * fastest / res) + 1;
  out.threshold = comb_threshold(samples, out.trials, false_alarm);
  double best = -1, best_delta = 0;
  for (long i = 0; i <= steps; ++i) {
    const double delta = steps > 0 ? -c.slip + 2 * c.slip * static_cast<double>(i) / steps : 0.0;
    if (c.anchored && !on_peak(s, c.carrier * (1 + delta))) continue;
    const double e = evaluate(s, c, delta, lines, out.rated_harmonics);
    if (e > best || (e == best && std::abs(delta) < std::abs(best_delta)))
      best = e, best_delta = delta;
  }
  if (best < 0) best_delta = 0;  // anchored, and no offset on a peak
  out.offset = best_delta;
  out.carrier = (1 + best_delta) * c.carrier;
  const double evidence = evaluate(s, c, best_delta, lines, out.rated_harmonics);  // the lines
  out.evidence = best < 0 ? 0.0 : evidence;
  out.detected = best >= 0 && out.rated_harmonics > 0 && out.evidence >= out.threshold;
  for (const LineSetup& l : lines) out.lines.push_back(l.line);
  return out;
}

}  // namespace bearing
