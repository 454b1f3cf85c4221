#pragma once
// Private to the writers (output.cc): the envelope analysis and the diagnosis as summary.json
// blocks and as lines of the readable summary.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bearing/vibration_summary.h"

namespace bearing {

/// summary.json `envelope`: per channel {band [Hz], band_source "given" | "auto",
/// spectral_kurtosis, noise_floor, energy_fraction (auto), kurtogram[] (auto: level, bands, index,
/// band [Hz], spectral_kurtosis, energy_fraction), peaks[] (frequency [Hz], amplitude [channel
/// unit], label, label_error [Hz])}.
nlohmann::json envelope_json(const std::vector<EnvelopeSummary>& envelopes);

/// summary.json `diagnosis`: {family "outer" | "inner" | "ball" | "none", channel, unit, band
/// [Hz], band_source, spectral_kurtosis, family_share, thresholds, evidence[] (label, frequency
/// [Hz], amplitude [unit]), reason}.
nlohmann::json diagnosis_json(const Diagnosis& d);

/// The `units` entries of both blocks.
void add_envelope_units(nlohmann::json& units);

/// The readable summary's lines: one per envelope (band, SK, its largest lines) and the
/// diagnosis ("Diagnosis: outer race — envelope of ay, 2.1–4.2 kHz (kurtogram): BPFO 0.31
/// m/s^2, …").
std::string envelope_text(const VibrationSummary& s);

}  // namespace bearing
