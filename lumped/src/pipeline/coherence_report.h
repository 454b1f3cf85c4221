#pragma once
// Private to the record writers (record_output.cc): the coherence diagnosis as summary.json
// blocks and as lines of the readable summary.

#include <string>

#include <nlohmann/json.hpp>

#include "bearing/coherence_diagnosis.h"

namespace bearing {

/// summary.json `coherence`: settings, bands ([low, high] [Hz], level, shifted), map (each
/// family's margin per band [dB], −100 unrated), families (each one's best band and test:
/// harmonics, decoys, side lines, margin [dB]; harmonic_bands: the bands its harmonics alone
/// passed in).
nlohmann::json coherence_json(const CoherenceDiagnosis& d);

/// summary.json `diagnosis` under the coherence rule: family ("outer" | "inner" | "ball" |
/// "several" | "none"), named, margin [dB], band [Hz] (the first named family's, or the best
/// family's), evidence[] (label, frequency [Hz], excess [dB]) of the named families, false_alarm,
/// reason.
nlohmann::json coherence_diagnosis_json(const CoherenceDiagnosis& d);

/// The `units` entries of both blocks.
void add_coherence_units(nlohmann::json& units);

/// The readable summary's lines: one per family (best band, harmonics over threshold, decoys,
/// side line, margin), then "Diagnosis: …".
std::string coherence_text(const CoherenceDiagnosis& d);

}  // namespace bearing
