#pragma once
// The summary of vibration channels, simulated or measured: each channel's statistics over the
// analysed window, the spectra with named peaks, the envelope spectra and the diagnosis they make.
// A run's summary (pipeline's analysis.h: RunSummary) is this and the sound at the microphones; a
// measured record's (record_analysis.h) is this for its one channel.

#include <optional>
#include <string>
#include <vector>

#include "bearing/channel_group.h"
#include "bearing/diagnosis.h"
#include "bearing/envelope_analysis.h"
#include "bearing/signal/line_names.h"
#include "bearing/signal/peaks.h"
#include "bearing/signal/spectrum.h"
#include "bearing/signal/statistics.h"

namespace bearing {

/// One channel: its statistics and its spectrum's largest peaks.
struct ChannelSummary {
  std::string name;
  std::string unit;
  ChannelGroup group = ChannelGroup::ring;
  ChannelStatistics statistics;  ///< over the analysed (a run's post-transient) window
  std::vector<Peak> peaks;       ///< largest first (channels with a spectrum: a run's ring ones)
};

/// The channels, their spectra and envelopes, and the diagnosis.
struct VibrationSummary {
  std::vector<ChannelSummary> channels;        ///< in response order (a record's: its one)
  std::vector<std::string> spectrum_channels;  ///< channels with a spectrum (a run's: the ring's)
  std::vector<Spectrum> spectra;               ///< one per spectrum channel
  std::vector<EnvelopeSummary> envelopes;  ///< one per ring acceleration (or record), if asked for
  std::optional<Diagnosis> diagnosis;      ///< diagnose(envelopes), with envelopes only
  /// The families that named the ring channels' peaks (the settings' `lines`).
  LineFamilies peak_families;
};

}  // namespace bearing
