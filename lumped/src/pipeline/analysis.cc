#include "bearing/analysis.h"

#include <memory>

namespace bearing {

RunSummary analyse(const Response& resp, const BearingFrequencies& f,
                   const AnalysisSettings& settings) {
  RunSummary s;
  // Every harmonic up to the band (Nyquist), so 8×BPFO is not left to 5×BPFI nearby, of the
  // families the signal's excitations make (settings.lines): a name from a family the case lacks
  // (12xFTF on identical balls) would send an analyst after a source that is not there. A fault's
  // other sidebands (the ball's 2k·BSF ± m·FTF) stay in the envelope spectra, which demodulate
  // them: in a raw spectrum a high-order line takes the nearest of many names, and with them 291
  // labels of tests/outputs/run_matrix.sh's healthy runs changed, mostly from a plain harmonic or
  // none to a sideband that merely lay nearer (28xfr → 14xBSF-2FTF, 5xBPFO → 8xBSF-2FTF on 10 Hz
  // bins): fault names on bearings without a fault.
  const auto names = bearing_frequency_names_up_to(0.5 * resp.rate, f.shaft, f.ftf, f.bpfo, f.bpfi,
                                                   f.bsf, settings.lines);
  s.peak_families = settings.lines;
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
  s.envelopes = analyse_envelopes(resp, f, settings.envelope, settings.window, settings.peaks);
  if (!s.envelopes.empty()) s.diagnosis = diagnose(s.envelopes, f);
  return s;
}

std::vector<EnvelopeSummary> analyse_envelopes(const Response& response,
                                               const BearingFrequencies& f,
                                               const EnvelopeBandSetting& setting, Window window,
                                               int max_peaks) {
  std::vector<EnvelopeSummary> out;
  if (setting.source == EnvelopeBandSource::none) return out;
  for (const Channel& ch : response.channels)
    if (ch.group == ChannelGroup::ring && ch.derivative == 2)
      out.push_back(analyse_envelope(ch.name, ch.unit, response.steady(ch.name), response.rate, f,
                                     setting, window, max_peaks));
  return out;
}

}  // namespace bearing
