// The fault family of a run's envelope spectra: impulsive band, dominant family, evidence.

#include "bearing/diagnosis.h"

#include <cctype>
#include <cstdio>

namespace bearing {

namespace {

constexpr FaultFamily kFamilies[] = {FaultFamily::outer, FaultFamily::inner, FaultFamily::ball};

// What one envelope's peaks say: the summed amplitude of each family's lines, and the leader.
struct Reading {
  double amplitude[4] = {0, 0, 0, 0};  // by FaultFamily
  double fault_total = 0;              // outer + inner + ball
  FaultFamily leader = FaultFamily::none;
  double share = 0;  // the leader's share of fault_total
};

Reading read_peaks(const EnvelopeSummary& e) {
  Reading r;
  for (const Peak& p : e.peaks) r.amplitude[static_cast<int>(fault_family(p.label))] += p.amplitude;
  for (FaultFamily f : kFamilies) {
    const double a = r.amplitude[static_cast<int>(f)];
    r.fault_total += a;
    if (a > 0 && (r.leader == FaultFamily::none || a > r.amplitude[static_cast<int>(r.leader)]))
      r.leader = f;
  }
  if (r.leader != FaultFamily::none)
    r.share = r.amplitude[static_cast<int>(r.leader)] / r.fault_total;
  return r;
}

std::string format(const char* pattern, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, pattern, v);
  return buf;
}

// "ay, 1.67–2.5 kHz (kurtogram)"
std::string envelope_text(const EnvelopeSummary& e) {
  return e.channel + ", " + band_text(e.band) +
         (e.source == EnvelopeBandSource::automatic ? " (kurtogram)" : " (given)");
}

// "outer 62 %, inner 38 %, ball 0 %"
std::string shares_text(const Reading& r) {
  std::string out;
  for (FaultFamily f : kFamilies) {
    const double share = r.fault_total > 0 ? r.amplitude[static_cast<int>(f)] / r.fault_total : 0;
    out += std::string(out.empty() ? "" : ", ") + name_of(kFaultFamilies, f) + " " +
           format("%.0f %%", 100 * share);
  }
  return out;
}

// "k·BPFO, BPFO = 102.4 Hz"
std::string family_lines_text(FaultFamily f, const BearingFrequencies& fr) {
  switch (f) {
    case FaultFamily::outer:
      return "k·BPFO, BPFO = " + format("%.4g Hz", fr.bpfo);
    case FaultFamily::inner:
      return "k·BPFI ± m·fr, BPFI = " + format("%.4g Hz", fr.bpfi);
    case FaultFamily::ball:
      return "k·BSF, 2k·BSF ± m·FTF, BSF = " + format("%.4g Hz", fr.bsf);
    case FaultFamily::several:
    case FaultFamily::none:
      break;
  }
  return "";
}

// Why the most impulsive envelope `e` (reading r) names no family.
std::string none_reason(const EnvelopeSummary& e, const Reading& r, const DiagnosisSettings& s) {
  const std::string sk = format("%.3g", e.spectral_kurtosis);
  const std::string limit = format("%.3g", s.min_spectral_kurtosis);
  if (e.spectral_kurtosis < s.min_spectral_kurtosis)
    return "not impulsive: spectral kurtosis " + sk + " < " + limit +
           " in the most impulsive envelope, " + envelope_text(e) +
           (r.fault_total > 0 ? "; its fault lines: " + shares_text(r) : "");
  if (r.fault_total == 0)
    return envelope_text(e) + " is impulsive (spectral kurtosis " + sk + " ≥ " + limit +
           ") but none of its envelope lines is a fault frequency";
  return envelope_text(e) + " is impulsive (spectral kurtosis " + sk + " ≥ " + limit +
         ") but no fault family dominates its envelope lines: " + shares_text(r) + " (< " +
         format("%.0f %%", 100 * s.min_family_share) + ")";
}

}  // namespace

const char* fault_family_text(FaultFamily family) {
  switch (family) {
    case FaultFamily::outer:
      return "outer race";
    case FaultFamily::inner:
      return "inner race";
    case FaultFamily::ball:
      return "ball";
    case FaultFamily::several:
      return "several families";
    case FaultFamily::none:
      break;
  }
  return "none";
}

FaultFamily fault_family(const std::string& label) {
  // [k "x"] base [("+" | "-") [m] modulation]
  const auto digits = [&label](std::size_t i) {
    while (i < label.size() && std::isdigit(static_cast<unsigned char>(label[i]))) ++i;
    return i;
  };
  std::size_t i = digits(0);
  if (i > 0) {
    if (i == label.size() || label[i] != 'x') return FaultFamily::none;
    ++i;
  }
  const std::size_t sign = label.find_first_of("+-", i);
  const std::string base = label.substr(i, sign == std::string::npos ? sign : sign - i);
  std::string modulation;
  if (sign != std::string::npos) {
    modulation = label.substr(digits(sign + 1));
    if (modulation.empty()) return FaultFamily::none;
  }
  if (base == "BPFO" && modulation.empty()) return FaultFamily::outer;
  if (base == "BPFI" && (modulation.empty() || modulation == "fr")) return FaultFamily::inner;
  if (base == "BSF" && (modulation.empty() || modulation == "FTF")) return FaultFamily::ball;
  return FaultFamily::none;
}

Diagnosis diagnose(const std::vector<EnvelopeSummary>& envelopes, const BearingFrequencies& f,
                   const DiagnosisSettings& s) {
  Diagnosis d;
  d.thresholds = s;
  if (envelopes.empty()) {
    d.reason = "no envelope analysis (output.envelope_band = \"none\")";
    return d;
  }
  const EnvelopeSummary* chosen = nullptr;   // the most impulsive envelope that counts
  const EnvelopeSummary* loudest = nullptr;  // the most impulsive envelope
  for (const EnvelopeSummary& e : envelopes) {
    if (!loudest || e.spectral_kurtosis > loudest->spectral_kurtosis) loudest = &e;
    const Reading r = read_peaks(e);
    const bool counts = e.spectral_kurtosis >= s.min_spectral_kurtosis &&
                        r.leader != FaultFamily::none && r.share >= s.min_family_share;
    if (counts && (!chosen || e.spectral_kurtosis > chosen->spectral_kurtosis)) chosen = &e;
  }
  const EnvelopeSummary& e = chosen ? *chosen : *loudest;
  const Reading r = read_peaks(e);
  d.channel = e.channel;
  d.unit = e.unit;
  d.band = e.band;
  d.source = e.source;
  d.spectral_kurtosis = e.spectral_kurtosis;
  d.family_share = r.share;
  if (!chosen) {
    d.reason = none_reason(e, r, s);
    return d;
  }
  d.family = r.leader;
  for (const Peak& p : e.peaks)
    if (fault_family(p.label) == d.family) d.evidence.push_back(p);
  d.reason = envelope_text(e) + ": spectral kurtosis " + format("%.3g", e.spectral_kurtosis) +
             " ≥ " + format("%.3g", s.min_spectral_kurtosis) + ", and the " +
             fault_family_text(d.family) + " lines (" + family_lines_text(d.family, f) + ") hold " +
             format("%.0f %%", 100 * r.share) + " of the fault-line amplitude";
  return d;
}

}  // namespace bearing
