// The diagnosis from the band-integrated cyclic spectral coherence: families over bands, the
// race first, explained away, a second race looked for again.

#include "bearing/coherence_diagnosis.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "bearing/errors.h"
#include "bearing/units.h"

namespace bearing {

namespace {

constexpr double kUnrated = -100;

void check(const BearingFrequencies& f, const LineTestSettings& s) {
  for (double v : {f.shaft, f.ftf, f.bpfo, f.bpfi, f.bsf})
    if (!(std::isfinite(v) && v > 0))
      throw InputError("coherence diagnosis: bearing frequency = " + format_number(v) +
                       " Hz: must be positive and finite (is the shaft turning?)");
  if (!(s.slip >= 0.002 && s.slip <= 0.1))
    throw InputError("coherence diagnosis: slip = " + format_number(s.slip) +
                     ": allowed 0.002 … 0.1 (a fraction: 0.02 is 2 %)");
  if (!(s.false_alarm > 0 && s.false_alarm <= 0.1))
    throw InputError("coherence diagnosis: false-alarm rate = " + format_number(s.false_alarm) +
                     ": allowed 0 < rate ≤ 0.1");
  if (!(s.decoy_span >= 0 && s.decoy_span <= 0.9))
    throw InputError("coherence diagnosis: decoy span = " + format_number(s.decoy_span) +
                     ": allowed 0 … 0.9");
  if (s.explained_sidebands < 0 || s.explained_sidebands > 10)
    throw InputError("coherence diagnosis: explained sidebands = " +
                     std::to_string(s.explained_sidebands) + ": allowed 0 … 10");
  if (!(std::isfinite(s.shaft_exclusion) && s.shaft_exclusion >= 0 && s.shaft_exclusion < 0.05))
    throw InputError("coherence diagnosis: shaft exclusion = " + format_number(s.shaft_exclusion) +
                     ": allowed 0 … 0.05");
}

// Marks the bins within half-width `half` [Hz] of `centre` [Hz].
void mark(std::vector<char>& mask, double centre, double half, double df) {
  const long lo = std::max<long>(0, static_cast<long>(std::ceil((centre - half) / df)));
  const long hi = std::min<long>(static_cast<long>(mask.size()) - 1,
                                 static_cast<long>(std::floor((centre + half) / df)));
  for (long k = lo; k <= hi; ++k) mask[static_cast<std::size_t>(k)] = 1;
}

// The shaft harmonics' zones, ±max(2 bins, shaft_exclusion · n f_r).
void mark_shaft(std::vector<char>& mask, double shaft, double df, double relative) {
  const double top = static_cast<double>(mask.size()) * df;
  for (int n = 1; n * shaft <= top + shaft; ++n)
    mark(mask, n * shaft, std::max(2 * df, relative * n * shaft), df);
}

// A named family's series n·c + m·g, |m| ≤ M, each ±(2 + n/6) bins: its rate is found to half a
// bin at the third harmonic.
void mark_series(std::vector<char>& mask, const FamilyEvidence& e, double g, int M, double df) {
  const double c = e.test.harmonics[0].frequency;
  const double top = static_cast<double>(mask.size()) * df;
  for (int n = 1; n * c <= top + M * g; ++n)
    for (int m = -M; m <= M; ++m) mark(mask, n * c + m * g, (2 + n / 6.0) * df, df);
}

// Whether `hz` lies on a line n·c + m·g (n ≥ 1, |m| ≤ M, ±(2 + n/6) bins) of the series of `e`
// (c its first harmonic as found).
bool in_series(double hz, const FamilyEvidence& e, double g, int M, double df) {
  const double c = e.test.harmonics[0].frequency;
  for (int n = 1; n * c - M * g <= hz + 10 * df; ++n)
    for (int m = -M; m <= M; ++m)
      if (std::abs(hz - (n * c + m * g)) <= (2 + n / 6.0) * df) return true;
  return false;
}

bool is_race(FaultFamily f) {
  return f == FaultFamily::outer || f == FaultFamily::inner;
}

std::string format(const char* pattern, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, pattern, v);
  return buf;
}

std::string evidence_text(const FamilyEvidence& e, const std::vector<CoherenceBand>& bands) {
  const FamilyTest& t = e.test;
  const FrequencyBand& b = bands[e.band].band;
  std::string out = std::string(fault_family_text(e.family)) + " (" +
                    std::to_string(t.standing_out) + " of 3 harmonics over threshold in " +
                    format("%.0f", b.low) + "–" + format("%.0f Hz", b.high) + ", first at " +
                    format("%.2f Hz", t.harmonics[0].frequency) + ", margin " +
                    format("%+.1f dB", t.margin);
  if (t.decoys_applied)
    out += ", score " + format("%.1f dB", t.score) + " over " + std::to_string(t.decoys) +
           " decoys' best " + format("%.1f dB", t.decoy_score);
  if (!t.side_lines.empty() && e.family != FaultFamily::outer)
    out += std::string(", ") + t.side_lines.front().label +
           format(" %+.1f dB", t.side_lines.front().excess);
  return out + ")";
}

constexpr FaultFamily kFamilies[3] = {FaultFamily::outer, FaultFamily::inner, FaultFamily::ball};

// What every stage searches: the bands' SES power, the bins left out, the rates.
struct Search {
  std::vector<std::vector<double>> power;  // by band
  double df = 0;                           // [Hz]
  std::vector<char> mask;                  // 1: excluded
  double p_band = 0;                       // each family's false-alarm rate in one band
  std::array<double, 3> rates{};           // BPFO, BPFI, 2·BSF [Hz]
};

// Each open family's best band at `stage` (detected first, then the larger score over its decoys,
// else the larger margin); the map holds the first stage's margins. found[i]: some band rated.
std::vector<bool> search_bands(CoherenceDiagnosis& d, const Search& x, const BearingFrequencies& f,
                               const LineTestSettings& s, int stage,
                               const std::vector<bool>& open) {
  std::vector<bool> found(3, false);
  const int needed = stage == 0 ? 2 : 3;
  for (std::size_t b = 0; b < d.bands.size(); ++b) {
    const SesView view{&x.power[b], x.df, d.bands[b].band.high - d.bands[b].band.low, &x.mask};
    for (int i = 0; i < 3; ++i) {
      if (!open[i]) continue;
      FamilyTest t = test_harmonics(view, kFamilies[i], x.rates[i],
                                    harmonic_probability(x.p_band, 2), needed, s);
      if (!t.rated) continue;
      if (stage == 0 && t.detected) ++d.families[i].harmonic_bands;
      if (t.detected)
        t = test_family(view, kFamilies[i], x.rates[i], f.shaft, f.ftf, x.p_band, needed,
                        stage > 0 || t.standing_out < 3, s);
      if (stage == 0) d.map[i][b] = t.margin;
      FamilyEvidence& e = d.families[i];
      const double key = t.detected ? t.score - t.decoy_score : t.margin;
      const double best = e.test.detected ? e.test.score - e.test.decoy_score : e.test.margin;
      if (!found[i] || (t.detected && !e.test.detected) ||
          (t.detected == e.test.detected && key > best)) {
        e.band = b, e.test = t, e.stage = stage;
        found[i] = true;
      }
    }
  }
  return found;
}

// The family to name next, or −1. Of the candidates, one whose fundamental is a line of another's
// series while that one's is not of its series is that other's (a comb is anchored on its
// fundamental: the 6205's 2·BSF − 3·FTF lies 1.9 % below BPFO, the 6203's BPFO + f_r 1.6 % above
// 2·BSF); then a race before the ball, then the larger score over its decoys.
int next_family(CoherenceDiagnosis& d, const Search& x, const BearingFrequencies& f,
                const LineTestSettings& s, const std::vector<bool>& open,
                const std::vector<bool>& found) {
  std::vector<int> candidates;
  for (int i = 0; i < 3; ++i)
    if (open[i] && found[i] && d.families[i].test.detected &&
        (d.named.empty() || is_race(kFamilies[i])))
      candidates.push_back(i);
  const auto series_holds = [&](int owner, int other) {
    const FamilyEvidence& o = d.families[owner];
    const double g = owner == 2 ? f.ftf * o.test.harmonics[0].frequency / x.rates[2] : f.shaft;
    return in_series(d.families[other].test.harmonics[0].frequency, o, g, s.explained_sidebands,
                     x.df);
  };
  std::vector<int> own;
  std::vector<int> by(3, -1);  // the family whose series explains each candidate
  for (int i : candidates) {
    for (int j : candidates)
      if (by[i] < 0 && j != i && series_holds(j, i) && !series_holds(i, j)) by[i] = j;
    if (by[i] < 0) own.push_back(i);
  }
  if (own.empty()) own = candidates;
  const auto key = [&](int j) {
    const FamilyTest& t = d.families[j].test;
    return std::make_pair(is_race(kFamilies[j]), t.score - t.decoy_score);
  };
  int next = -1;
  for (int i : own)
    if (next < 0 || key(i) > key(next)) next = i;
  for (int i : candidates)
    if (by[i] == next && next >= 0) d.families[i].explained_by = kFamilies[next];
  return next;
}

// The verdict, its margin and its reason from the named families.
void conclude(CoherenceDiagnosis& d, const LineTestSettings& s) {
  if (d.named.empty()) {
    d.margin = kUnrated;
    std::string all;
    for (const FamilyEvidence& e : d.families) {
      d.margin = std::max(d.margin, e.test.margin);
      if (e.test.rated) all += (all.empty() ? "" : "; ") + evidence_text(e, d.bands);
    }
    d.reason = all.empty() ? "no family could be rated in any band (record too short?)"
                           : "no family's lines pass, at a false-alarm rate of " +
                                 format("%.3g", s.false_alarm) + " per family: " + all;
    return;
  }
  d.family = d.named.size() == 1 ? d.named.front() : FaultFamily::several;
  d.margin = 1e300;
  std::string named;
  for (const FamilyEvidence& e : d.families)
    if (e.named) {
      d.margin = std::min(d.margin, e.test.margin);
      named += (named.empty() ? "" : "; and ") + evidence_text(e, d.bands);
    }
  d.reason = (d.named.size() == 1 ? "" : "two families clearly present: ") + named +
             ", at a false-alarm rate of " + format("%.3g", s.false_alarm) + " per family";
}

}  // namespace

CoherenceDiagnosis diagnose_coherence(const std::vector<double>& x, double rate,
                                      const BearingFrequencies& f, int levels,
                                      const LineTestSettings& s, bool prewhiten) {
  check(f, s);
  CoherenceDiagnosis d;
  d.settings = s;
  d.false_alarm = s.false_alarm;
  d.bands = coherence_bands(rate, levels);
  d.prewhitened = prewhiten;
  const std::vector<std::complex<double>> X = whitened_spectrum(x, prewhiten);
  Search search;
  search.df = rate / static_cast<double>(x.size());
  std::size_t longest = 0;
  for (const CoherenceBand& b : d.bands) {
    std::vector<double> ses = band_squared_envelope(X, x.size(), rate, b.band);
    for (double& v : ses) v *= v;
    longest = std::max(longest, ses.size());
    search.power.push_back(std::move(ses));
  }
  search.p_band = s.false_alarm / static_cast<double>(d.bands.size());
  search.rates = {f.bpfo, f.bpfi, 2 * f.bsf};
  search.mask.assign(longest, 0);
  mark_shaft(search.mask, f.shaft, search.df, s.shaft_exclusion);
  const double modulation[3] = {f.shaft, f.shaft, f.ftf};

  d.families.resize(3);
  for (int i = 0; i < 3; ++i)
    d.families[i].family = kFamilies[i], d.families[i].nominal = search.rates[i];
  d.map.assign(3, std::vector<double>(d.bands.size(), kUnrated));
  std::vector<bool> open = {true, true, true};
  for (int stage = 0; stage < 3; ++stage) {
    const std::vector<bool> found = search_bands(d, search, f, s, stage, open);
    const int next = next_family(d, search, f, s, open, found);
    if (next < 0) break;
    d.families[next].named = true;
    d.named.push_back(kFamilies[next]);
    open[next] = false;
    open[2] = false;  // the ball is never a second family (step 3): its first-stage test stays
    mark_series(search.mask, d.families[next], modulation[next], s.explained_sidebands, search.df);
  }
  conclude(d, s);
  return d;
}

}  // namespace bearing
