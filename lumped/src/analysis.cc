#include "bearing/analysis.h"

#include <memory>

namespace bearing {

RunSummary analyse(const Response& resp, const BearingFrequencies& f,
                   const AnalysisSettings& settings) {
  RunSummary s;
  // Every harmonic up to the band (Nyquist), so 8×BPFO is not left to 5×BPFI nearby.
  const auto names =
      bearing_frequency_names_up_to(0.5 * resp.rate, f.shaft, f.ftf, f.bpfo, f.bpfi, f.bsf);
  std::unique_ptr<SpectrumPlan> plan;  // one window and FFT table for all channels
  for (const Channel& channel : resp.channels) {
    ChannelSummary ch;
    ch.name = channel.name;
    ch.unit = channel.unit;
    ch.group = channel.group;
    const std::vector<double> x = resp.steady(ch.name);
    ch.statistics = channel_statistics(x);
    if (ch.group == ChannelGroup::ring) {
      if (!plan) plan = std::make_unique<SpectrumPlan>(x.size(), resp.rate, settings.window);
      Spectrum spectrum = (*plan)(x);
      ch.peaks = find_peaks(spectrum, names, settings.peaks);
      s.spectrum_channels.push_back(ch.name);
      s.spectra.push_back(std::move(spectrum));
    }
    s.channels.push_back(std::move(ch));
  }
  return s;
}

}  // namespace bearing
