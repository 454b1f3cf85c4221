// The envelope analysis and the diagnosis in summary.json and in the readable summary.

#include "envelope_report.h"

#include <algorithm>
#include <cstdio>

namespace bearing {

namespace {

nlohmann::json peak_json(const Peak& p) {
  return {{"frequency", p.frequency},
          {"amplitude", p.amplitude},
          {"label", p.label},
          {"label_error", p.label_error}};
}

nlohmann::json band_json(const FrequencyBand& b) {
  return nlohmann::json::array({b.low, b.high});
}

// "BPFO 0.0082, 2xBPFO 0.0064, 767.98 Hz 0.0028 m/s^2": the first `count` lines.
std::string lines_text(const std::vector<Peak>& peaks, std::size_t count, const std::string& unit) {
  std::string out;
  char buf[96];
  for (std::size_t i = 0; i < std::min(count, peaks.size()); ++i) {
    const Peak& p = peaks[i];
    if (p.label.empty())
      std::snprintf(buf, sizeof buf, "%s%.2f Hz %.3g", i ? ", " : "", p.frequency, p.amplitude);
    else
      std::snprintf(buf, sizeof buf, "%s%s %.3g", i ? ", " : "", p.label.c_str(), p.amplitude);
    out += buf;
  }
  return out.empty() ? "no lines" : out + " " + unit;
}

const char* source_text(EnvelopeBandSource source) {
  return source == EnvelopeBandSource::automatic ? "kurtogram" : "given";
}

}  // namespace

nlohmann::json envelope_json(const std::vector<EnvelopeSummary>& envelopes) {
  using nlohmann::json;
  json out = json::object();
  for (const EnvelopeSummary& e : envelopes) {
    json peaks = json::array();
    for (const Peak& p : e.peaks) peaks.push_back(peak_json(p));
    json j = {{"band", band_json(e.band)},
              {"band_source", name_of(kEnvelopeBandSources, e.source)},
              {"spectral_kurtosis", e.spectral_kurtosis},
              {"noise_floor", kEnvelopeNoiseFloor},
              {"peaks", peaks}};
    if (e.source == EnvelopeBandSource::automatic) {
      json map = json::array();
      for (const KurtogramBand& b : e.kurtogram) {
        map.push_back({{"level", b.level},
                       {"bands", b.bands},
                       {"index", b.index},
                       {"band", band_json(b.band)},
                       {"spectral_kurtosis", b.spectral_kurtosis},
                       {"energy_fraction", b.energy_fraction}});
      }
      j["kurtogram"] = map;
      if (const auto fraction = band_energy_fraction(e)) j["energy_fraction"] = *fraction;
    }
    out[e.channel] = j;
  }
  return out;
}

nlohmann::json diagnosis_json(const Diagnosis& d) {
  using nlohmann::json;
  json evidence = json::array();
  for (const Peak& p : d.evidence)
    evidence.push_back(
        {{"label", p.label}, {"frequency", p.frequency}, {"amplitude", p.amplitude}});
  return {{"family", name_of(kFaultFamilies, d.family)},
          {"channel", d.channel},
          {"unit", d.unit},
          {"band", band_json(d.band)},
          {"band_source", name_of(kEnvelopeBandSources, d.source)},
          {"spectral_kurtosis", d.spectral_kurtosis},
          {"family_share", d.family_share},
          {"thresholds",
           {{"spectral_kurtosis", d.thresholds.min_spectral_kurtosis},
            {"family_share", d.thresholds.min_family_share}}},
          {"evidence", evidence},
          {"reason", d.reason}};
}

void add_envelope_units(nlohmann::json& units) {
  units["envelope.*.band"] = "Hz";
  units["envelope.*.peaks.frequency"] = "Hz";
  units["envelope.*.peaks.amplitude"] = "unit of the channel";
  units["envelope.*.peaks.label_error"] = "Hz";
  units["envelope.*.{spectral_kurtosis,noise_floor,energy_fraction}"] = "1";
  units["envelope.*.kurtogram.band"] = "Hz";
  units["diagnosis.band"] = "Hz";
  units["diagnosis.evidence.frequency"] = "Hz";
  units["diagnosis.evidence.amplitude"] = "diagnosis.unit";
  units["diagnosis.{spectral_kurtosis,family_share}"] = "1";
}

std::string envelope_text(const VibrationSummary& s) {
  if (s.envelopes.empty()) return "";
  std::string out;
  char buf[160];
  std::snprintf(buf, sizeof buf,
                "Envelope spectra (spectral kurtosis over a noise floor of %.3g of the energy):\n",
                kEnvelopeNoiseFloor);
  out += buf;
  int width = 3;  // the channel names in one column: ax, ay and ay_housing
  for (const EnvelopeSummary& e : s.envelopes)
    width = std::max(width, static_cast<int>(e.channel.size()));
  for (const EnvelopeSummary& e : s.envelopes) {
    std::snprintf(buf, sizeof buf, "  %-*s %s (%s), SK %.3g: ", width, e.channel.c_str(),
                  band_text(e.band).c_str(), source_text(e.source), e.spectral_kurtosis);
    out += buf + lines_text(e.peaks, 4, e.unit) + "\n";
  }
  if (!s.diagnosis) return out;
  const Diagnosis& d = *s.diagnosis;
  if (d.family == FaultFamily::none) return out + "Diagnosis: none — " + d.reason + "\n";
  std::snprintf(buf, sizeof buf,
                "; spectral kurtosis %.3g ≥ %.3g, %s lines %.0f %% of the fault lines",
                d.spectral_kurtosis, d.thresholds.min_spectral_kurtosis,
                fault_family_text(d.family), 100 * d.family_share);
  return out + "Diagnosis: " + fault_family_text(d.family) + " — envelope of " + d.channel + ", " +
         band_text(d.band) + " (" + source_text(d.source) +
         "): " + lines_text(d.evidence, 4, d.unit) + buf + "\n";
}

}  // namespace bearing
