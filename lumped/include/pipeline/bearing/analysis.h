#pragma once
// The post-processing of a run's response: statistics of every channel over the analysis window,
// and spectra with named peaks of the ring's channels.

#include <optional>
#include <string>
#include <vector>

#include "bearing/kinematics.h"
#include "bearing/noise.h"
#include "bearing/response.h"
#include "bearing/signal/peaks.h"
#include "bearing/signal/spectrum.h"
#include "bearing/signal/statistics.h"

namespace bearing {

/// How a response is analysed ([output] window and peaks).
struct AnalysisSettings {
  Window window = Window::hann;  ///< spectrum window
  int peaks = 10;                ///< peaks listed per ring channel
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
  std::optional<BearingNoise> noise;           ///< sound at the microphones ([acoustics] only)
};

/// Statistics of every channel, and spectra and peaks (labelled with `frequencies`) of the ring's
/// channels, over the post-transient window. Leaves `noise` empty.
RunSummary analyse(const Response& response, const BearingFrequencies& frequencies,
                   const AnalysisSettings& settings);

}  // namespace bearing
