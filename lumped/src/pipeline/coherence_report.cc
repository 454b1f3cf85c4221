// The coherence diagnosis in summary.json and in the readable summary.

#include "coherence_report.h"

#include <cstdio>

namespace bearing {

namespace {

using nlohmann::json;

template <class... Args>
std::string format(const char* pattern, Args... args) {
  char buf[160];
  std::snprintf(buf, sizeof buf, pattern, args...);
  return buf;
}

// "BPFO", "2xBPFO"; "BPFI"; ball (carrier 2·BSF): "2xBSF", "4xBSF".
std::string harmonic_label(FaultFamily family, int h) {
  const auto times = [](int n, const char* base) {
    return (n == 1 ? std::string() : std::to_string(n) + "x") + base;
  };
  if (family == FaultFamily::outer) return times(h, "BPFO");
  if (family == FaultFamily::inner) return times(h, "BPFI");
  return times(2 * h, "BSF");
}

json test_json(const FamilyEvidence& e, const CoherenceDiagnosis& d) {
  const FamilyTest& t = e.test;
  json harmonics = json::array();
  if (t.rated)
    for (const HarmonicTest& h : t.harmonics)
      harmonics.push_back({{"label", harmonic_label(e.family, h.harmonic)},
                           {"nominal", h.nominal},
                           {"frequency", h.frequency},
                           {"ratio", h.ratio},
                           {"threshold", h.threshold},
                           {"excess", h.excess},
                           {"window", h.window}});
  json side = json::array();
  for (const SideLine& s : t.side_lines)
    side.push_back({{"label", s.label}, {"frequency", s.frequency}, {"excess", s.excess}});
  const FrequencyBand& b = d.bands[e.band].band;
  return {{"nominal", e.nominal},
          {"rated", t.rated},
          {"band", {b.low, b.high}},
          {"band_index", e.band},
          {"stage", e.stage},
          {"harmonic_bands", e.harmonic_bands},
          {"explained_by", name_of(kFaultFamilies, e.explained_by)},
          {"named", e.named},
          {"detected", t.detected},
          {"standing_out", t.standing_out},
          {"needed", t.needed},
          {"score", t.score},
          {"margin", t.margin},
          {"harmonics", harmonics},
          {"decoys_applied", t.decoys_applied},
          {"decoys", t.decoys},
          {"decoy_score", t.decoy_score},
          {"physics", t.physics},
          {"side_lines", side}};
}

}  // namespace

json coherence_json(const CoherenceDiagnosis& d) {
  json bands = json::array(), levels = json::array(), shifted = json::array();
  for (const CoherenceBand& b : d.bands) {
    bands.push_back({b.band.low, b.band.high});
    levels.push_back(b.level);
    shifted.push_back(b.shifted);
  }
  json j = {{"settings",
             {{"slip", d.settings.slip},
              {"false_alarm", d.settings.false_alarm},
              {"decoy_span", d.settings.decoy_span},
              {"explained_sidebands", d.settings.explained_sidebands},
              {"shaft_exclusion", d.settings.shaft_exclusion}}},
            {"prewhitened", d.prewhitened},
            {"bands", bands},
            {"levels", levels},
            {"shifted", shifted},
            {"map", json::object()},
            {"families", json::object()}};
  for (std::size_t i = 0; i < d.families.size(); ++i) {
    const char* name = name_of(kFaultFamilies, d.families[i].family);
    j["map"][name] = d.map[i];
    j["families"][name] = test_json(d.families[i], d);
  }
  return j;
}

json coherence_diagnosis_json(const CoherenceDiagnosis& d) {
  json named = json::array(), evidence = json::array();
  const FamilyEvidence* lead = nullptr;
  for (const FamilyEvidence& e : d.families) {
    if (!lead || (e.named && !lead->named) ||
        (e.named == lead->named && !e.named && e.test.margin > lead->test.margin))
      lead = &e;
  }
  for (FaultFamily f : d.named) named.push_back(name_of(kFaultFamilies, f));
  for (const FamilyEvidence& e : d.families) {
    if (!e.named) continue;
    if (e.family == d.named.front()) lead = &e;
    for (const HarmonicTest& h : e.test.harmonics)
      evidence.push_back({{"label", harmonic_label(e.family, h.harmonic)},
                          {"frequency", h.frequency},
                          {"excess", h.excess}});
  }
  const FrequencyBand& b = d.bands[lead->band].band;
  return {{"family", name_of(kFaultFamilies, d.family)},
          {"rule", "coherence"},
          {"named", named},
          {"margin", d.margin},
          {"band", {b.low, b.high}},
          {"evidence", evidence},
          {"false_alarm", d.false_alarm},
          {"reason", d.reason}};
}

void add_coherence_units(json& units) {
  units["coherence.bands"] = "Hz";
  units["coherence.map"] = "dB";
  units["coherence.families.*.{nominal,band}"] = "Hz";
  units["coherence.families.*.harmonics.{nominal,frequency}"] = "Hz";
  units["coherence.families.*.harmonics.{ratio,threshold}"] = "1 (power over the floor's mean)";
  units["coherence.families.*.{score,margin,decoy_score}"] = "dB";
  units["coherence.families.*.{harmonics,side_lines}.excess"] = "dB";
  units["coherence.families.*.side_lines.frequency"] = "Hz";
  units["diagnosis.evidence.excess"] = "dB";
}

std::string coherence_text(const CoherenceDiagnosis& d) {
  std::string out = "Cyclic coherence by band (" + std::to_string(d.bands.size()) +
                    (d.prewhitened ? " bands of the pre-whitened record" : " bands of the record") +
                    ", slip ±" + format("%.3g %%", 100 * d.settings.slip) + ", false-alarm rate " +
                    format("%.3g", d.false_alarm) + " per family):\n";
  for (const FamilyEvidence& e : d.families) {
    const FamilyTest& t = e.test;
    out += format("  %-6s", name_of(kFaultFamilies, e.family));
    if (!t.rated) {
      out += " not rated in any band\n";
      continue;
    }
    const FrequencyBand& b = d.bands[e.band].band;
    out += format(" %5.0f–%5.0f Hz: %d of 3 harmonics", b.low, b.high, t.standing_out) +
           format(" (%d needed), margin %+6.1f dB", t.needed, t.margin);
    for (const HarmonicTest& h : t.harmonics)
      out += format("; %s %.2f Hz %+.1f", harmonic_label(e.family, h.harmonic).c_str(), h.frequency,
                    h.excess);
    if (t.decoys_applied)
      out += format("; score %.1f dB vs %d decoys' best %.1f", t.score, t.decoys, t.decoy_score);
    if (!t.side_lines.empty())
      out += format("; %s %+.1f dB", t.side_lines.front().label, t.side_lines.front().excess);
    if (e.named)
      out += " — named";
    else if (e.explained_by != FaultFamily::none)
      out += std::string(" — not named: its fundamental is a line of the ") +
             fault_family_text(e.explained_by) + "'s series";
    else if (t.detected)
      out += " — not named: a race family passes (the ball goes after the races)";
    out += "\n";
  }
  return out + "Diagnosis: " + fault_family_text(d.family) +
         format(" (margin %+.1f dB)", d.margin) + " — " + d.reason + "\n";
}

}  // namespace bearing
