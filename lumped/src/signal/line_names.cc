// The names of a bearing's spectral lines: its frequency families, their harmonics, sidebands and
// the subharmonics of the ball pass (docs/model.md §7).

#include "bearing/signal/line_names.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "bearing/errors.h"
#include "bearing/units.h"

namespace bearing {

namespace {

// The m of the subharmonics (k/m)·BPFO: a response that repeats every 2, 3 or 4 ball passes. All
// three appear in the 2-DOF 6308 under light loads, where the balls lose contact: period 2 in the
// default case (2000 rpm, P_d 14 µm, 20 N), period 3 at 4000 rpm, 20 µm, 30 N, period 4 at
// 6000 rpm, 30 µm, 100 N; period 6 and higher show only now and then among quasi-periodic
// responses, whose lines no family names. More m would crowd the names (m ≤ 4 puts five in every
// BPFO) until any line had one within a bin.
constexpr int kSubharmonicDenominators[] = {2, 3, 4};

void check_frequency(const char* label, double f) {
  if (!(std::isfinite(f) && f >= 0))
    throw InputError(std::string("bearing frequency ") + label + " = " + format_number(f) +
                     " Hz: must be finite and not negative");
}

std::string harmonic_name(int h, const char* label) {
  return (h == 1 ? std::string() : std::to_string(h) + "x") + label;
}

// How many harmonics of f a family gets: max_harmonic, or those up to max_frequency.
struct HarmonicRange {
  int max_harmonic = 0;      ///< > 0: this many
  double max_frequency = 0;  ///< else: every k·f ≤ max_frequency, at most kMaxPerFamily
  int count(double f) const {
    constexpr double kMaxPerFamily = 4096;
    if (max_harmonic > 0) return max_harmonic;
    return static_cast<int>(std::min(std::floor(max_frequency / f), kMaxPerFamily));
  }
};

void add_harmonics(std::vector<NamedFrequency>& names, const char* label, double f,
                   HarmonicRange range) {
  if (f == 0) return;  // e.g. a shaft at rest: no line to name
  for (int h = 1; h <= range.count(f); ++h) names.push_back({harmonic_name(h, label), h * f, h});
}

// (k/m)·f for m in kSubharmonicDenominators and k/m in lowest terms and not whole: "1/2xBPFO",
// "3/2xBPFO", …, "1/3xBPFO", …; by m, then k.
void add_subharmonics(std::vector<NamedFrequency>& names, const char* label, double f,
                      HarmonicRange range) {
  if (f == 0) return;
  for (int m : kSubharmonicDenominators)
    for (int k = 1; k <= range.count(f / m); ++k)
      if (std::gcd(k, m) == 1)
        names.push_back({std::to_string(k) + "/" + std::to_string(m) + "x" + label,
                         static_cast<double>(k) * f / m, k, m});
}

// The sidebands k·f_c ± m·f_m, m = first … last, of the harmonics k = step, 2·step, … of f_c in
// `range`: "2xBPFI-fr", "BPFI+2fr", "4xBSF-FTF", …; a lower sideband only where it is above 0.
// Listed by m, then k (the first sidebands before the second); `harmonic` is the carrier's k.
void add_sidebands(std::vector<NamedFrequency>& names, const char* carrier, double fc,
                   const char* modulation, double fm, int first, int last, HarmonicRange range,
                   int step = 1) {
  if (!(fc > 0 && fm > 0)) return;
  for (int m = first; m <= last; ++m) {
    const std::string offset = (m == 1 ? std::string() : std::to_string(m)) + modulation;
    for (int k = step; k <= range.count(fc); k += step) {
      const std::string base = harmonic_name(k, carrier);
      if (k * fc - m * fm > 0) names.push_back({base + "-" + offset, k * fc - m * fm, k});
      names.push_back({base + "+" + offset, k * fc + m * fm, k});
    }
  }
}

// Which lines beside the families' harmonics and the inner race's ±f_r sidebands: none (the plain
// list), a raw spectrum's (the ball pass's shaft sidebands and subharmonics), or an envelope's (a
// local fault's sidebands).
enum class Extras { none, raw, envelope };

std::vector<NamedFrequency> names_of(double shaft, double ftf, double bpfo, double bpfi, double bsf,
                                     HarmonicRange range, const LineFamilies& families,
                                     Extras extras) {
  check_frequency("fr", shaft);
  check_frequency("FTF", ftf);
  check_frequency("BPFO", bpfo);
  check_frequency("BPFI", bpfi);
  check_frequency("BSF", bsf);
  std::vector<NamedFrequency> names;
  if (families.shaft) add_harmonics(names, "fr", shaft, range);
  if (families.cage) add_harmonics(names, "FTF", ftf, range);
  if (families.outer) add_harmonics(names, "BPFO", bpfo, range);
  if (families.inner) add_harmonics(names, "BPFI", bpfi, range);
  if (families.spin) add_harmonics(names, "BSF", bsf, range);
  // The inner race turns with the shaft, so its lines come with shaft-rate sidebands
  // k·BPFI ± f_r (e.g. inner-race waviness under a fixed load zone). Listed after the plain
  // harmonics: a tie goes to the simpler name.
  if (families.inner) add_sidebands(names, "BPFI", bpfi, "fr", shaft, 1, 1, range);
  // The second shaft sidebands k·BPFI ± 2f_r: inner-race waviness of an order 2 off a multiple of
  // Z, and a defect on the turning race that passes through the load zone once a shaft turn.
  if (families.inner && extras != Extras::none)
    add_sidebands(names, "BPFI", bpfi, "fr", shaft, 2, 2, range);
  if (extras == Extras::raw) {
    // A load turning with the shaft (unbalance, inner-race features) meets a compliance that
    // varies at the ball pass: k·BPFO ± f_r.
    if (families.shaft && families.outer)
      add_sidebands(names, "BPFO", bpfo, "fr", shaft, 1, 1, range);
    if (families.outer_subharmonics) add_subharmonics(names, "BPFO", bpfo, range);
  } else if (extras == Extras::envelope) {
    // A ball defect's lines: it strikes both races, twice per spin (2k·BSF), and is carried
    // through the load zone by the cage (± m·FTF).
    add_sidebands(names, "BSF", bsf, "FTF", ftf, 1, 2, range, 2);
  }
  return names;
}

HarmonicRange band(double max_frequency, const char* what) {
  if (!(std::isfinite(max_frequency) && max_frequency > 0))
    throw InputError(std::string(what) + ": band up to " + format_number(max_frequency) +
                     " Hz: must be positive and finite");
  return HarmonicRange{0, max_frequency};
}

}  // namespace

std::vector<std::string> line_family_names(const LineFamilies& families) {
  std::vector<std::string> out;
  if (families.shaft) out.push_back("fr");
  if (families.cage) out.push_back("FTF");
  if (families.outer) out.push_back("BPFO");
  if (families.outer_subharmonics) out.push_back("BPFO/m");
  if (families.inner) out.push_back("BPFI");
  if (families.spin) out.push_back("BSF");
  return out;
}

std::vector<NamedFrequency> bearing_frequency_names(double shaft, double ftf, double bpfo,
                                                    double bpfi, double bsf, int max_harmonic) {
  if (max_harmonic < 1)
    throw InputError("bearing frequency names: max_harmonic = " + std::to_string(max_harmonic) +
                     ": must be at least 1");
  return names_of(shaft, ftf, bpfo, bpfi, bsf, HarmonicRange{max_harmonic, 0}, LineFamilies::all(),
                  Extras::none);
}

std::vector<NamedFrequency> bearing_frequency_names_up_to(double max_frequency, double shaft,
                                                          double ftf, double bpfo, double bpfi,
                                                          double bsf,
                                                          const LineFamilies& families) {
  return names_of(shaft, ftf, bpfo, bpfi, bsf, band(max_frequency, "bearing frequency names"),
                  families, Extras::raw);
}

std::vector<NamedFrequency> fault_frequency_names_up_to(double max_frequency, double shaft,
                                                        double ftf, double bpfo, double bpfi,
                                                        double bsf) {
  return names_of(shaft, ftf, bpfo, bpfi, bsf, band(max_frequency, "fault frequency names"),
                  LineFamilies::all(), Extras::envelope);
}

}  // namespace bearing
