// The fault families' combs in a squared envelope spectrum, and the line-to-floor diagnosis.

#include "bearing/fault_lines.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "bearing/errors.h"
#include "bearing/units.h"

namespace bearing {

namespace {

void check_settings(const FaultLineSettings& s) {
  if (!(s.slip >= 0 && s.slip < 0.5))
    throw InputError("fault lines: slip = " + format_number(s.slip) +
                     ": allowed 0 <= slip < 0.5 (a fraction: 0.02 is 2 %)");
  if (s.harmonics < 1)
    throw InputError("fault lines: harmonics = " + std::to_string(s.harmonics) + ": at least 1");
  if (!(s.false_alarm > 0 && s.false_alarm < 1))
    throw InputError("fault lines: false-alarm probability = " + format_number(s.false_alarm) +
                     ": allowed 0 < p < 1");
  if (!(std::isfinite(s.shaft_exclusion) && s.shaft_exclusion >= 0))
    throw InputError("fault lines: shaft exclusion = " + format_number(s.shaft_exclusion) +
                     ": must be finite and not negative");
}

std::string format(const char* pattern, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, pattern, v);
  return buf;
}

// "BPFO", "3xBPFO"; "2xBPFI-fr"; ball (carrier 2·BSF): "2xBSF", "4xBSF+FTF".
std::string line_label(FaultFamily family, int k, int m) {
  const auto times = [](int n, const char* base) {
    return (n == 1 ? std::string() : std::to_string(n) + "x") + base;
  };
  switch (family) {
    case FaultFamily::outer:
      return times(k, "BPFO");
    case FaultFamily::inner:
      return times(k, "BPFI") + (m < 0 ? "-fr" : m > 0 ? "+fr" : "");
    case FaultFamily::ball:
      return times(2 * k, "BSF") + (m < 0 ? "-FTF" : m > 0 ? "+FTF" : "");
    case FaultFamily::several:
    case FaultFamily::none:
      break;
  }
  return "";
}

// The zones around the shaft harmonics n·f_r up to `top` [Hz].
std::vector<FrequencyBand> shaft_zones(double shaft, double top, double resolution,
                                       double relative) {
  std::vector<FrequencyBand> zones;
  if (!(shaft > 0)) return zones;
  for (int n = 1; n * shaft <= top + shaft; ++n) {
    const double centre = n * shaft;
    const double half = std::max(2 * resolution, relative * centre);
    zones.push_back({centre - half, centre + half});
  }
  return zones;
}

// "outer 6.1 dB (threshold 8.3)"
std::string family_text(const FamilyLines& f) {
  return std::string(name_of(kFaultFamilies, f.family)) + " " + format("%.1f dB", f.comb.evidence) +
         " (threshold " + format("%.1f dB", f.comb.threshold) + ")";
}

// "k·BPFI ± fr, BPFI found at 161.7 Hz (−0.30 % from 162.2 Hz)"
std::string lines_text(const FamilyLines& f) {
  const char* lines = f.family == FaultFamily::outer   ? "k·BPFO"
                      : f.family == FaultFamily::inner ? "k·BPFI ± fr"
                                                       : "k·2BSF ± FTF";
  const char* rate = f.family == FaultFamily::outer   ? "BPFO"
                     : f.family == FaultFamily::inner ? "BPFI"
                                                      : "2xBSF";
  return std::string(lines) + ", " + rate + " found at " + format("%.5g Hz", f.comb.carrier) +
         " (" + format("%+.2f %%", 100 * f.comb.offset) + " from " + format("%.5g Hz", f.nominal) +
         ")";
}

// One family's comb: its rate, sideband spacing and whether that moves with the rate.
struct FamilySpec {
  FaultFamily family;
  double carrier, modulation;
  bool slips;
};

std::vector<FamilySpec> family_specs(const BearingFrequencies& f) {
  return {{FaultFamily::outer, f.bpfo, 0.0, false},
          {FaultFamily::inner, f.bpfi, f.shaft, false},
          {FaultFamily::ball, 2 * f.bsf, f.ftf, true}};
}

FamilyLines search_family(const Spectrum& ses, const FamilySpec& spec, const FaultLineSettings& s,
                          FrequencyBand rated, const std::vector<FrequencyBand>& zones) {
  HarmonicComb comb;
  comb.carrier = spec.carrier;
  comb.harmonics = s.harmonics;
  comb.modulation = spec.modulation;
  comb.modulation_slips = spec.slips;
  comb.slip = s.slip;
  comb.rated = rated;
  comb.excluded = zones;
  FamilyLines family;
  family.family = spec.family;
  family.nominal = spec.carrier;
  family.modulation = spec.modulation;
  family.comb = search_comb(ses, comb, s.false_alarm);
  for (const CombLine& l : family.comb.lines)
    family.labels.push_back(line_label(spec.family, l.harmonic, l.sideband));
  return family;
}

double margin(const FamilyLines& f) {
  return f.comb.evidence - f.comb.threshold;
}

// The zones around every line of a detected family up to `top` [Hz] at the rate it was found at:
// its harmonics n·c and their sidebands n·c ± g, n·c ± 2g (the squared envelope of impacts whose
// strength goes as 1 + d cos 2πgt carries (1 + d cos)²: both), each ±(2 + n/(2K)) bins (the rate
// is found to half a bin at the K-th harmonic; a line's window main lobe spans ±1 bin).
std::vector<FrequencyBand> family_zones(const FamilyLines& f, double top, double resolution,
                                        const FaultLineSettings& s) {
  std::vector<FrequencyBand> zones;
  const double c = f.comb.carrier;
  const double g =
      f.family == FaultFamily::ball ? f.modulation * (1 + f.comb.offset) : f.modulation;
  for (int n = 1; n * c <= top + g; ++n) {
    const double half = (2 + 0.5 * n / s.harmonics) * resolution;
    for (int m = g > 0 ? -2 : 0; m <= (g > 0 ? 2 : 0); ++m)
      zones.push_back({n * c + m * g - half, n * c + m * g + half});
  }
  return zones;
}

}  // namespace

std::vector<FamilyLines> search_fault_lines(const Spectrum& ses, double band_width,
                                            const BearingFrequencies& f,
                                            const FaultLineSettings& s) {
  check_settings(s);
  for (double v : {f.shaft, f.ftf, f.bpfo, f.bpfi, f.bsf})
    if (!(std::isfinite(v) && v > 0))
      throw InputError("fault lines: bearing frequency = " + format_number(v) +
                       " Hz: must be positive and finite (is the shaft turning?)");
  const FrequencyBand rated{3 * ses.resolution, band_width};
  std::vector<FrequencyBand> zones =
      shaft_zones(f.shaft, band_width, ses.resolution, s.shaft_exclusion);
  std::vector<FamilyLines> out;
  for (const FamilySpec& spec : family_specs(f))
    out.push_back(search_family(ses, spec, s, rated, zones));
  // Each line to one source: the detected family furthest over its threshold keeps its lines,
  // which are then left out of the others' search (3·BPFO lies 0.7 % from 2·BPFI of the 6205:
  // a strong outer race would otherwise lend the inner race one harmonic); repeat with the rest.
  std::vector<bool> fixed(out.size(), false);
  for (;;) {
    std::size_t next = out.size();
    for (std::size_t i = 0; i < out.size(); ++i)
      if (!fixed[i] && out[i].comb.detected &&
          (next == out.size() || margin(out[i]) > margin(out[next])))
        next = i;
    if (next == out.size()) break;
    fixed[next] = true;
    const std::vector<FrequencyBand> lines = family_zones(out[next], band_width, ses.resolution, s);
    zones.insert(zones.end(), lines.begin(), lines.end());
    for (std::size_t i = 0; i < out.size(); ++i)
      if (!fixed[i]) {
        std::vector<FaultFamily> excluding = out[i].excluding;
        excluding.push_back(out[next].family);
        out[i] = search_family(ses, family_specs(f)[i], s, rated, zones);
        out[i].excluding = std::move(excluding);
      }
  }
  return out;
}

std::vector<std::size_t> evidence_lines(const FamilyLines& family) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < family.comb.lines.size(); ++i)
    if (family.comb.lines[i].rated && !family.comb.lines[i].excluded) out.push_back(i);
  std::stable_sort(out.begin(), out.end(), [&](std::size_t a, std::size_t b) {
    return family.comb.lines[a].level > family.comb.lines[b].level;
  });
  return out;
}

LineDiagnosis diagnose_lines(std::vector<FamilyLines> families, const FaultLineSettings& s,
                             const std::string& where) {
  LineDiagnosis d;
  d.settings = s;
  d.families = std::move(families);
  const FamilyLines* named = nullptr;  // detected, furthest over its threshold
  const FamilyLines* nearest = nullptr;
  for (const FamilyLines& f : d.families) {
    if (f.comb.rated_harmonics == 0) continue;
    if (!nearest || margin(f) > margin(*nearest)) nearest = &f;
    if (f.comb.detected && (!named || margin(f) > margin(*named))) named = &f;
  }
  const std::string rate = format("%.3g", s.false_alarm);
  if (!nearest) {
    d.reason = where +
               ": no fault line could be rated (each family's lines and the floor beside "
               "them must lie below the band's width; the band or the record is too short)";
    return d;
  }
  if (!named) {
    d.margin = margin(*nearest);
    std::string all;
    for (const FamilyLines& f : d.families)
      if (f.comb.rated_harmonics > 0) all += (all.empty() ? "" : ", ") + family_text(f);
    d.reason = where + ": no family's lines stand over their threshold for a false-alarm rate of " +
               rate + " (evidence, the mean level of the first harmonics over the floor: " + all +
               ")";
    return d;
  }
  d.family = named->family;
  d.margin = margin(*named);
  std::string others;
  for (const FamilyLines& f : d.families)
    if (&f != named && f.comb.detected) others += (others.empty() ? "" : ", ") + family_text(f);
  d.reason = where + ": the " + fault_family_text(named->family) + " lines (" + lines_text(*named) +
             ") stand " + format("%.1f dB", named->comb.evidence) +
             " over the floor, the mean of " + std::to_string(named->comb.rated_harmonics) +
             " harmonics, against a threshold of " + format("%.1f dB", named->comb.threshold) +
             " for a false-alarm rate of " + rate +
             (others.empty() ? "" : "; also over their threshold, by less: " + others);
  return d;
}

}  // namespace bearing
