#pragma once
// The post-processing of a run's response: statistics of every channel over the analysis window,
// spectra with named peaks of the ring's channels, and (asked for) the envelope analysis of its
// accelerations.

#include <optional>
#include <string>
#include <vector>

#include "bearing/envelope_analysis.h"
#include "bearing/kinematics.h"
#include "bearing/noise.h"
#include "bearing/response.h"
#include "bearing/signal/envelope.h"
#include "bearing/signal/line_names.h"
#include "bearing/signal/spectrum.h"
#include "bearing/vibration_summary.h"

namespace bearing {

/// How a response is analysed ([output] window, peaks and envelope_band).
struct AnalysisSettings {
  Window window = Window::hann;  ///< spectrum window (the envelope spectra's too)
  int peaks = 10;                ///< peaks listed per ring channel and per envelope spectrum
  /// The families that name the ring channels' peaks: run_settings() takes the case's
  /// (excitation_families()); all of them for a signal whose excitations are unknown. The
  /// envelope spectra always take every fault family (fault_frequency_names_up_to()): the
  /// diagnosis reads them blind, as it would a measured signal.
  LineFamilies lines = LineFamilies::all();
  EnvelopeBandSetting envelope;  ///< envelope analysis of the accelerations: none by default
};

/// A run's summary: the vibration summary of its response (channels, spectra, envelopes,
/// diagnosis: vibration_summary.h) and the sound at its microphones.
struct RunSummary : VibrationSummary {
  std::optional<BearingNoise> noise;  ///< sound at the microphones ([acoustics] only)
};

/// Statistics of every channel, and spectra and peaks (labelled with `frequencies`, by the
/// families settings.lines) of the ring's channels, over the post-transient window; with
/// settings.envelope, analyse_envelopes() and diagnose() (default thresholds). Leaves `noise`
/// empty.
RunSummary analyse(const Response& response, const BearingFrequencies& frequencies,
                   const AnalysisSettings& settings);

/// analyse_envelope() (envelope_analysis.h) of every ring acceleration channel of the response
/// (group ring, derivative 2: ax, ay and, 3-DOF, az) over its analysis window; none for
/// setting.source none.
std::vector<EnvelopeSummary> analyse_envelopes(const Response& response,
                                               const BearingFrequencies& frequencies,
                                               const EnvelopeBandSetting& setting, Window window,
                                               int max_peaks);

}  // namespace bearing
