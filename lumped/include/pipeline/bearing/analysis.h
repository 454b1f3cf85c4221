#pragma once
// The post-processing of a run's response: statistics of every channel over the analysis window,
// spectra with named peaks of the ring's channels, and (asked for) the envelope analysis of its
// accelerations.

#include <optional>
#include <string>
#include <vector>

#include "bearing/diagnosis.h"
#include "bearing/envelope_analysis.h"
#include "bearing/kinematics.h"
#include "bearing/noise.h"
#include "bearing/response.h"
#include "bearing/signal/line_names.h"
#include "bearing/signal/peaks.h"
#include "bearing/signal/spectrum.h"
#include "bearing/signal/statistics.h"

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

struct ChannelSummary {
  std::string name;
  std::string unit;
  ChannelGroup group = ChannelGroup::ring;
  ChannelStatistics statistics;  ///< over the post-transient window
  std::vector<Peak> peaks;       ///< largest first (ring channels only)
};

struct RunSummary {
  std::vector<ChannelSummary> channels;        ///< in response order
  std::vector<std::string> spectrum_channels;  ///< channels with a spectrum (the ring's)
  std::vector<Spectrum> spectra;               ///< one per spectrum channel
  std::vector<EnvelopeSummary> envelopes;      ///< one per ring acceleration, if asked for
  std::optional<Diagnosis> diagnosis;          ///< diagnose(envelopes), with envelopes only
  std::optional<BearingNoise> noise;           ///< sound at the microphones ([acoustics] only)
  /// The families that named the ring channels' peaks (the settings' `lines`).
  LineFamilies peak_families;
};

/// Statistics of every channel, and spectra and peaks (labelled with `frequencies`, by the
/// families settings.lines) of the ring's channels, over the post-transient window; with
/// settings.envelope, analyse_envelopes() and diagnose() (default thresholds). Leaves `noise`
/// empty.
RunSummary analyse(const Response& response, const BearingFrequencies& frequencies,
                   const AnalysisSettings& settings);

}  // namespace bearing
