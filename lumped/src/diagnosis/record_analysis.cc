// The analysis of a measured record: speed, statistics, spectrum, envelope, SES, fault lines.

#include "bearing/record_analysis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/signal/prewhitening.h"
#include "bearing/units.h"

namespace bearing {

namespace {

std::string rpm_text(double speed) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g rpm", speed * 60 / two_pi);
  return buf;
}

void check_record(const std::vector<double>& x, double rate, const std::string& channel) {
  if (!(std::isfinite(rate) && rate > 0))
    throw InputError("record " + channel + ": sample rate = " + format_number(rate) +
                     " Hz: must be positive and finite");
  if (x.size() < 2)
    throw InputError("record " + channel + ": " + std::to_string(x.size()) +
                     " samples; at least 2 are needed");
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!std::isfinite(x[i]))
      throw InputError("record " + channel + ": sample " + std::to_string(i) + " = " +
                       format_number(x[i]) + ": every sample must be finite");
}

void check_speed(const SpeedSetting& s, double duration, const std::string& channel) {
  const std::string what = s.source == SpeedSource::estimate ? "nominal speed" : "speed";
  if (!(std::isfinite(s.speed) && s.speed > 0))
    throw InputError("record " + channel + ": " + what + " = " + format_number(s.speed) +
                     " rad/s: must be positive and finite");
  const double revolutions = duration * s.speed / two_pi;
  if (revolutions < kMinShaftRevolutions) {
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  ": %.4g s holds %.3g shaft revolutions at %s; at least %.0f are needed "
                  "(%.4g s) so that the fault lines' slip windows span bins and their floors "
                  "lie above 0 Hz",
                  duration, revolutions, rpm_text(s.speed).c_str(), kMinShaftRevolutions,
                  kMinShaftRevolutions * two_pi / s.speed);
    throw InputError("record " + channel + buf);
  }
}

// "ay, 2–4 kHz (kurtogram), pre-whitened"
std::string where_text(const EnvelopeSummary& e, bool prewhitened) {
  return e.channel + ", " + band_text(e.band) +
         (e.source == EnvelopeBandSource::automatic ? " (kurtogram)" : " (given)") +
         (prewhitened ? ", pre-whitened" : "");
}

// The envelope peaks named at the rates the detected families were found at (the others at
// their nominal rates): a measured bearing's lines sit off the catalogue's by more than the one
// bin find_peaks() allows (the CWRU records' 0.3 %, 3–5 bins), and would stay unnamed. run's rule
// reads the names, so it keeps the nominal ones.
void rename_envelope_peaks(RecordAnalysis& a) {
  BearingFrequencies found = a.frequencies;
  const auto found_at = [&](FaultFamily family, double carrier) {
    if (family == FaultFamily::outer) found.bpfo = carrier;
    if (family == FaultFamily::inner) found.bpfi = carrier;
    if (family == FaultFamily::ball)
      found.bsf = 0.5 * carrier, found.ftf = a.frequencies.ftf * carrier / (2 * a.frequencies.bsf);
  };
  if (a.settings.rule == DiagnosisRule::coherence) {
    for (const FamilyEvidence& e : a.coherence->families)
      if (e.named) found_at(e.family, e.test.harmonics[0].frequency);
  } else {
    for (const FamilyLines& l : a.lines->families)
      if (l.comb.detected) found_at(l.family, l.comb.carrier);
  }
  EnvelopeSummary& e = a.summary.envelopes.front();
  const auto names = fault_frequency_names_up_to(0.5 * a.rate, found.shaft, found.ftf, found.bpfo,
                                                 found.bpfi, found.bsf);
  e.peaks = find_peaks(e.spectrum, names, a.settings.peaks);
}

// A given speed refined by the record's own shaft harmonics within ±settings.speed_refinement,
// where they stand out; kept as given where they do not.
void refine_speed(const Spectrum& hann, const RecordAnalysisSettings& s, RecordSpeed& speed) {
  if (s.speed_refinement <= 0) return;
  if (!(s.speed_refinement < 0.1))
    throw InputError("record analysis: speed refinement = " + format_number(s.speed_refinement) +
                     ": allowed 0 (off) … < 0.1");
  FundamentalEstimate e = estimate_fundamental(hann, speed.speed / two_pi, s.speed_refinement,
                                               s.speed_harmonics, s.lines.false_alarm);
  if (!e.found) return;
  speed.given = speed.speed;
  speed.speed = two_pi * e.frequency;
  speed.estimate = std::move(e);
}

}  // namespace

FaultFamily RecordAnalysis::family() const {
  if (settings.rule == DiagnosisRule::coherence)
    return coherence ? coherence->family : FaultFamily::none;
  if (settings.rule == DiagnosisRule::line_to_floor)
    return lines ? lines->family : FaultFamily::none;
  return summary.diagnosis ? summary.diagnosis->family : FaultFamily::none;
}

RecordSpeed estimate_speed(const Spectrum& spectrum, double nominal, double tolerance,
                           int harmonics, double false_alarm) {
  if (!(tolerance > 0 && tolerance < 0.5))
    throw InputError("speed estimate: tolerance = " + format_number(tolerance) +
                     ": allowed 0 < tolerance < 0.5 (0.1 is ±10 %)");
  RecordSpeed out;
  out.source = SpeedSource::estimate;
  out.estimate =
      estimate_fundamental(spectrum, nominal / two_pi, tolerance, harmonics, false_alarm);
  const FundamentalEstimate& e = *out.estimate;
  if (!e.found) {
    char buf[512];
    std::snprintf(
        buf, sizeof buf,
        "speed estimate: no shaft line within ±%.3g %% of the nominal %s (%.5g Hz): "
        "the best comb of f_r … %d f_r (at %.5g Hz) stands %.3g dB over the floor, "
        "below the %.3g dB a noise record reaches with probability %.3g%s; give the "
        "speed instead (--speed, or the case's operation.speed)",
        100 * tolerance, rpm_text(nominal).c_str(), nominal / two_pi, harmonics, e.comb.carrier,
        e.comb.evidence, e.comb.threshold, false_alarm,
        e.comb.rated_harmonics == 0 ? " (no harmonic could be rated: record too short)" : "");
    throw InputError(buf);
  }
  out.speed = two_pi * e.frequency;
  return out;
}

RecordAnalysis analyse_record(const std::vector<double>& x, double rate, const std::string& channel,
                              const std::string& unit, const Bearing& bearing,
                              const SpeedSetting& speed, const RecordAnalysisSettings& settings) {
  check_record(x, rate, channel);
  check_speed(speed, static_cast<double>(x.size()) / rate, channel);
  if (settings.peaks < 0)
    throw InputError("record analysis: peaks = " + std::to_string(settings.peaks) +
                     ": must not be negative");
  bearing.validate();
  RecordAnalysis a;
  a.channel = channel;
  a.unit = unit;
  a.rate = rate;
  a.samples = x.size();
  a.bearing = bearing.designation;
  a.settings = settings;
  // The speed estimate's spectrum is Hann's (its floor statistics); the summary's reuses it.
  Spectrum hann = amplitude_spectrum(x, rate, Window::hann);
  if (speed.source == SpeedSource::estimate) {
    a.speed = estimate_speed(hann, speed.speed, settings.speed_tolerance, settings.speed_harmonics,
                             settings.lines.false_alarm);
  } else {
    a.speed.source = speed.source;
    a.speed.speed = speed.speed;
    refine_speed(hann, settings, a.speed);
  }
  const BearingFrequencies& f = a.frequencies = bearing_frequencies(bearing, a.speed.speed);
  if (a.settings.min_bandwidth <= 0)
    a.settings.min_bandwidth =
        (settings.lines.harmonics + 1) * std::max({f.bpfo, f.bpfi, 2 * f.bsf});

  // Statistics and spectrum of the record as measured; peaks named by every family.
  VibrationSummary& s = a.summary;
  s.peak_families = settings.peak_families;
  ChannelSummary ch;
  ch.name = channel;
  ch.unit = unit;
  ch.statistics = channel_statistics(x);
  Spectrum spectrum = settings.window == Window::hann
                          ? std::move(hann)
                          : amplitude_spectrum(x, rate, settings.window);
  const auto names = bearing_frequency_names_up_to(0.5 * rate, f.shaft, f.ftf, f.bpfo, f.bpfi,
                                                   f.bsf, s.peak_families);
  ch.peaks = find_peaks(spectrum, names, settings.peaks);
  s.channels.push_back(std::move(ch));
  s.spectrum_channels.push_back(channel);
  s.spectra.push_back(std::move(spectrum));
  if (settings.envelope.source == EnvelopeBandSource::none) return a;

  // Envelope and SES of the (pre-whitened) record in one band; both diagnoses.
  a.prewhitened = settings.prewhiten;
  const std::vector<double> whitened =
      settings.prewhiten ? cepstral_prewhiten(x) : std::vector<double>();
  const std::vector<double>& y = settings.prewhiten ? whitened : x;
  std::vector<double> envelope;
  s.envelopes.push_back(analyse_envelope(channel, unit, y, rate, f, settings.envelope,
                                         settings.window, settings.peaks, a.settings.min_bandwidth,
                                         &envelope));
  const EnvelopeSummary& e = s.envelopes.front();
  s.diagnosis = diagnose(s.envelopes, f);
  // squared_envelope_spectrum() from the envelope at hand; Hann whatever the window: the fault
  // lines' floor statistics rest on its bin correlation.
  for (double& v : envelope) v *= v;
  a.squared_envelope = amplitude_spectrum(envelope, rate, Window::hann);
  a.lines = diagnose_lines(
      search_fault_lines(*a.squared_envelope, e.band.high - e.band.low, f, settings.lines),
      settings.lines, where_text(e, a.prewhitened));
  a.coherence = diagnose_coherence(x, rate, f, settings.coherence_levels, settings.coherence,
                                   settings.prewhiten);
  if (settings.rule != DiagnosisRule::envelope_peaks) rename_envelope_peaks(a);
  return a;
}

}  // namespace bearing
