// Issue 29: the analysis of a measured record. A run's own response analysed as a record gives the
// run's analysis; the speed is estimated from shaft harmonics (a synthetic record, a run with
// unbalance); synthetic faults (impacts at a resonance, jittered, in noise) are named and noise
// alone is not, at no more than the stated false-alarm rate; input errors name what is wrong; the
// result folder holds run's files and keys, all or nothing.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bearing/case_file.h"
#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/fault_lines.h"
#include "bearing/presets.h"
#include "bearing/record_analysis.h"
#include "bearing/record_output.h"
#include "bearing/signal/harmonic_comb.h"
#include "bearing/simulation.h"
#include "synthetic_signals.h"

namespace bearing {
namespace {

namespace fs = std::filesystem;

constexpr double kRate = 12000;  // [Hz], the CWRU fault records' rate
const double kSpeed = 1797 * two_pi / 60;

Bearing cwru_bearing() {
  return preset("6205");
}

SpeedSetting given(double speed = kSpeed) {
  return {SpeedSource::option, speed};
}

void expect_same_peaks(const std::vector<Peak>& a, const std::vector<Peak>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].frequency, b[i].frequency) << i;
    EXPECT_EQ(a[i].amplitude, b[i].amplitude) << i;
    EXPECT_EQ(a[i].label, b[i].label) << i;
    EXPECT_EQ(a[i].label_error, b[i].label_error) << i;
  }
}

// Shaft harmonics are not fault lines: with BPFO = 3 f_r every outer-race line lies on a shaft
// harmonic, and a record whose envelope is modulated by the shaft alone (lines at every n·f_r)
// must not read as an outer-race fault; the zones around n·f_r keep those lines out.
TEST(RecordAnalysis, ShaftHarmonicsAreNotFaultLines) {
  Spectrum ses;
  ses.resolution = 0.1;
  for (int k = 0; k <= 5000; ++k) {
    ses.frequency.push_back(k * ses.resolution);
    ses.amplitude.push_back(k % 100 == 0 && k > 0 ? 30.0 : 1.0);  // n·10 Hz over a flat floor
  }
  BearingFrequencies f;
  f.shaft = 10.0;
  f.bpfo = 30.0;
  f.bpfi = 54.3;
  f.bsf = 23.7;
  f.ftf = 4.1;
  const std::vector<FamilyLines> families = search_fault_lines(ses, 500.0, f, FaultLineSettings{});
  ASSERT_EQ(families.size(), 3u);
  for (const FamilyLines& fam : families)
    EXPECT_LT(fam.comb.evidence, fam.comb.threshold) << name_of(kFaultFamilies, fam.family);
  // The same lines off the shaft harmonics (BPFO = 31.7 Hz) are the outer race's: detected.
  Spectrum off = ses;
  for (int k = 1; k <= 3; ++k) off.amplitude[static_cast<std::size_t>(std::lround(317.0 * k))] = 30;
  f.bpfo = 31.7;
  const std::vector<FamilyLines> found = search_fault_lines(off, 500.0, f, FaultLineSettings{});
  EXPECT_GE(found[0].comb.evidence, found[0].comb.threshold);
  // An outer-race defect is fixed in the load zone: its lines have no sidebands.
  EXPECT_EQ(found[0].modulation, 0.0);
  EXPECT_EQ(found[0].labels, (std::vector<std::string>{"BPFO", "2xBPFO", "3xBPFO"}));
}

TEST(RecordAnalysis, OfARunsResponseIsTheRunsAnalysis) {
  // The CWRU-like outer-race spall (48 kHz, envelope band by the kurtogram), its ay channel over
  // the run's analysis window, with the run's window, peaks, line families and narrowest band.
  const Case c =
      read_case_file(std::string(BEARING_SOURCE_DIR) + "/examples/cwru_6205_outer.toml", {});
  const SimulationResult r = simulate(c);
  const RunSummary run = summarize(c, r);
  const AnalysisSettings& as = run_settings(c).analysis;
  RecordAnalysisSettings s;
  s.window = as.window;
  s.peaks = as.peaks;
  s.peak_families = as.lines;
  s.envelope = as.envelope;
  s.min_bandwidth = envelope_min_bandwidth(r.frequencies);
  s.rule = DiagnosisRule::envelope_peaks;
  s.prewhiten = false;  // a run's envelope is of the response as it is
  const RecordAnalysis a =
      analyse_record(r.response.steady("ay"), r.response.rate, "ay", "m/s^2", c.bearing,
                     {SpeedSource::case_file, c.operation.speed}, s);
  // Frequencies, statistics, spectrum and peaks: bit for bit.
  EXPECT_EQ(a.frequencies.shaft, r.frequencies.shaft);
  EXPECT_EQ(a.frequencies.bpfo, r.frequencies.bpfo);
  EXPECT_EQ(a.frequencies.bpfi, r.frequencies.bpfi);
  EXPECT_EQ(a.frequencies.bsf, r.frequencies.bsf);
  EXPECT_EQ(a.frequencies.ftf, r.frequencies.ftf);
  std::size_t ay = 0;
  while (run.channels[ay].name != "ay") ++ay;
  const ChannelStatistics &x = a.summary.channels.front().statistics,
                          &y = run.channels[ay].statistics;
  EXPECT_EQ(x.mean, y.mean);
  EXPECT_EQ(x.rms, y.rms);
  EXPECT_EQ(x.ptp, y.ptp);
  EXPECT_EQ(x.kurtosis, y.kurtosis);
  EXPECT_EQ(x.crest, y.crest);
  std::size_t spectrum = 0;
  while (run.spectrum_channels[spectrum] != "ay") ++spectrum;
  EXPECT_EQ(a.summary.spectra.front().amplitude, run.spectra[spectrum].amplitude);
  expect_same_peaks(a.summary.channels.front().peaks, run.channels[ay].peaks);
  // The envelope: band, spectral kurtosis, kurtogram, spectrum, peaks.
  std::size_t env = 0;
  while (run.envelopes[env].channel != "ay") ++env;
  const EnvelopeSummary &e = a.summary.envelopes.front(), &f = run.envelopes[env];
  EXPECT_EQ(e.band.low, f.band.low);
  EXPECT_EQ(e.band.high, f.band.high);
  EXPECT_EQ(e.spectral_kurtosis, f.spectral_kurtosis);
  EXPECT_EQ(e.kurtogram.size(), f.kurtogram.size());
  EXPECT_EQ(e.spectrum.amplitude, f.spectrum.amplitude);
  expect_same_peaks(e.peaks, f.peaks);
  // The diagnosis by run's rule: that of the ay envelope, and the run's own where ay decides.
  const Diagnosis d = diagnose({f}, r.frequencies);
  ASSERT_TRUE(a.summary.diagnosis);
  EXPECT_EQ(a.summary.diagnosis->family, d.family);
  EXPECT_EQ(a.summary.diagnosis->reason, d.reason);
  EXPECT_EQ(a.family(), d.family);
  if (run.diagnosis->channel == "ay") {
    EXPECT_EQ(a.summary.diagnosis->family, run.diagnosis->family);
    EXPECT_EQ(a.summary.diagnosis->reason, run.diagnosis->reason);
  }
  // The outer-race spall is named by both rules.
  EXPECT_EQ(d.family, FaultFamily::outer) << d.reason;
  ASSERT_TRUE(a.lines);
  EXPECT_EQ(a.lines->family, FaultFamily::outer) << a.lines->reason;
}

TEST(RecordAnalysis, EstimatesTheSpeedOfARunWithUnbalance) {
  // The default 6308 at 2000 rpm with an unbalance: a line at f_r = 33.3 Hz in ay, beside the
  // ball pass's. The nominal speed 5 % off either way.
  const Case c = default_case({parse_override("operation.unbalance=2e-5 kg m")});
  const SimulationResult r = simulate(c);
  const std::vector<double> ay = r.response.steady("ay");
  for (double nominal : {0.95 * c.operation.speed, 1.05 * c.operation.speed}) {
    const RecordAnalysis a = analyse_record(ay, r.response.rate, "ay", "m/s^2", c.bearing,
                                            {SpeedSource::estimate, nominal});
    ASSERT_TRUE(a.speed.estimate);
    EXPECT_EQ(a.speed.source, SpeedSource::estimate);
    // Within a tenth of a bin: a twentieth of the fault lines' ±2 % slip window at this speed.
    const double resolution = r.response.rate / static_cast<double>(ay.size());
    EXPECT_NEAR(a.speed.speed / two_pi, c.operation.speed / two_pi, 0.1 * resolution);
    EXPECT_TRUE(a.speed.estimate->harmonics.front().used);
    EXPECT_NEAR(a.frequencies.shaft, a.speed.speed / two_pi, 1e-12);
  }
}

// n samples of white noise (standard deviation sigma) plus shaft harmonics of f_r.
std::vector<double> shaft_record(std::size_t n, double fr, double sigma, std::uint64_t seed) {
  test::SplitMix64 g(seed);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / kRate;
    x[i] = 0.5 * std::sin(two_pi * fr * t) + 0.3 * std::sin(two_pi * 2 * fr * t + 1) +
           0.2 * std::sin(two_pi * 3 * fr * t + 2) + sigma * g.normal();
  }
  return x;
}

// A speed given 2.4 % off (CWRU fan-end record 279's stored rpm) is refined from the record's
// shaft lines within ±3 %; beyond the refinement's reach, or with it off, it is used as given.
TEST(RecordAnalysis, AGivenSpeedIsRefinedByTheRecordsShaftLines) {
  const double fr = 1773.0 / 60;
  const std::vector<double> x = shaft_record(60000, fr, 1.0, 4);
  const double stored = 1732 * two_pi / 60;
  const RecordAnalysis a = analyse_record(x, kRate, "DE", "m/s^2", cwru_bearing(), given(stored));
  ASSERT_TRUE(a.speed.given);
  EXPECT_EQ(*a.speed.given, stored);
  EXPECT_EQ(a.speed.source, SpeedSource::option);
  EXPECT_NEAR(a.speed.speed / two_pi, fr, 0.02 * kRate / 60000);
  EXPECT_NEAR(a.frequencies.shaft, a.speed.speed / two_pi, 1e-12);
  RecordAnalysisSettings off;
  off.speed_refinement = 0;
  const RecordAnalysis b =
      analyse_record(x, kRate, "DE", "m/s^2", cwru_bearing(), given(stored), off);
  EXPECT_FALSE(b.speed.given);
  EXPECT_EQ(b.speed.speed, stored);
  const RecordAnalysis c =
      analyse_record(x, kRate, "DE", "m/s^2", cwru_bearing(), given(0.95 * two_pi * fr));
  EXPECT_FALSE(c.speed.given);  // the shaft lines lie 5 % away: nothing within ±3 %
  RecordAnalysisSettings wide;
  wide.speed_refinement = 0.2;
  EXPECT_THROW(analyse_record(x, kRate, "DE", "m/s^2", cwru_bearing(), given(stored), wide),
               InputError);
}

TEST(RecordAnalysis, EstimatesTheSpeedOfASyntheticRecord) {
  const double fr = 1791.3 / 60;  // off the nominal 1797 rpm by 0.3 %, between bins
  const std::vector<double> x = shaft_record(60000, fr, 1.0, 3);
  const RecordAnalysis a =
      analyse_record(x, kRate, "DE", "m/s^2", cwru_bearing(), {SpeedSource::estimate, kSpeed});
  // 0.2 Hz bins; the refined lines are biased by at most 0.016 bin (Hann), the noise adds less.
  EXPECT_NEAR(a.speed.speed / two_pi, fr, 0.02 * kRate / 60000);
  for (const HarmonicLine& h : a.speed.estimate->harmonics) EXPECT_TRUE(h.used) << h.order;
  EXPECT_NEAR(a.frequencies.bpfi / a.frequencies.shaft, 5.4152, 1e-4);
  // The kurtogram's narrowest band: (harmonics + 1) times the fastest fault rate, here BPFI
  // (2·BSF = 4.71 f_r is below it, 3·BSF = 7.07 f_r would not be).
  EXPECT_DOUBLE_EQ(a.settings.min_bandwidth, (a.settings.lines.harmonics + 1) * a.frequencies.bpfi);
}

// A local fault: impacts at `rate` ringing a 3 kHz resonance, each jittered by 1 % of the period,
// modulated at `modulation` (depth 0.8), in white noise 6 dB below the impacts' RMS, plus shaft
// harmonics; 4 s at 12 kHz.
std::vector<double> fault_record(double rate, double modulation, std::uint64_t seed) {
  test::ImpactTrain p;
  p.rate = rate;
  p.resonance = 3000;
  p.damping_ratio = 0.03;
  p.modulation = modulation;
  p.depth = modulation > 0 ? 0.8 : 0;
  p.jitter = 0.01;
  p.seed = seed;
  const std::size_t n = 48000;
  std::vector<double> x = test::with_noise(test::impact_train(p, n, kRate), 6, seed + 1);
  const std::vector<double> shaft = shaft_record(n, kSpeed / two_pi, 0.0, 0);
  const double scale = test::rms(x);
  for (std::size_t i = 0; i < n; ++i) x[i] += scale * shaft[i];
  return x;
}

TEST(RecordAnalysis, NamesSyntheticFaultsAndNotNoise) {
  const BearingFrequencies f = bearing_frequencies(cwru_bearing(), kSpeed);
  struct Fault {
    FaultFamily family;
    double rate, modulation;
  };
  for (const Fault& fault :
       {Fault{FaultFamily::outer, f.bpfo, 0.0}, Fault{FaultFamily::inner, f.bpfi, f.shaft},
        Fault{FaultFamily::ball, 2 * f.bsf, f.ftf}})
    for (bool prewhiten : {false, true}) {
      RecordAnalysisSettings s;
      s.prewhiten = prewhiten;
      const RecordAnalysis a = analyse_record(fault_record(fault.rate, fault.modulation, 5), kRate,
                                              "DE", "m/s^2", cwru_bearing(), given(), s);
      ASSERT_TRUE(a.lines);
      EXPECT_EQ(a.lines->family, fault.family) << prewhiten << ": " << a.lines->reason;
      EXPECT_EQ(a.family(), fault.family);
      EXPECT_EQ(a.prewhitened, prewhiten);
      // Each line to one source: the named family's lines (3·BPFO beside 2·BPFI, …) lend the
      // others nothing, so no other family is detected.
      for (const FamilyLines& other : a.lines->families)
        if (other.family != fault.family) {
          EXPECT_FALSE(other.comb.detected) << prewhiten << ": " << a.lines->reason;
          ASSERT_FALSE(other.excluding.empty());
          EXPECT_EQ(other.excluding.front(), fault.family);
        }
    }
  test::SplitMix64 g(8);
  std::vector<double> noise(48000);
  for (double& v : noise) v = g.normal();
  const RecordAnalysis a = analyse_record(noise, kRate, "DE", "m/s^2", cwru_bearing(), given());
  EXPECT_EQ(a.family(), FaultFamily::none) << a.lines->reason;
  EXPECT_NE(a.lines->reason.find("no family's lines stand over their threshold"), std::string::npos)
      << a.lines->reason;
}

TEST(RecordAnalysis, EnvelopePeaksAreNamedAtTheRatesFound) {
  // An outer race striking 0.6 % faster than the catalogue's BPFO (2.6 bins of 0.25 Hz): run's
  // naming (one bin) leaves its envelope lines unnamed; named at the rate found, they are BPFO.
  const BearingFrequencies f = bearing_frequencies(cwru_bearing(), kSpeed);
  const std::vector<double> x = fault_record(1.006 * f.bpfo, 0, 7);
  const auto label_at = [](const RecordAnalysis& a, double frequency) {
    for (const Peak& p : a.summary.envelopes.front().peaks)
      if (std::abs(p.frequency - frequency) < 0.5) return p.label;
    return std::string("(no peak)");
  };
  const RecordAnalysis a = analyse_record(x, kRate, "DE", "m/s^2", cwru_bearing(), given());
  ASSERT_EQ(a.family(), FaultFamily::outer) << a.lines->reason;
  EXPECT_EQ(label_at(a, 1.006 * f.bpfo), "BPFO");
  EXPECT_EQ(label_at(a, 2 * 1.006 * f.bpfo), "2xBPFO");
  RecordAnalysisSettings runs_rule;
  runs_rule.rule = DiagnosisRule::envelope_peaks;
  const RecordAnalysis b =
      analyse_record(x, kRate, "DE", "m/s^2", cwru_bearing(), given(), runs_rule);
  EXPECT_EQ(label_at(b, 1.006 * f.bpfo), "");
}

TEST(RecordAnalysis, GaussianNoiseFalseAlarmsStayWithinTheStatedRate) {
  // 120 records of white Gaussian noise, 2 s at 12 kHz, analysed at a false-alarm probability of
  // 0.05 per family: each family's count is at most binomial(120, 0.05) (the union bound over
  // correlated offsets makes it fewer); 15 is that law's 99.9 % quantile. At the default 1e-3,
  // from the same combs' thresholds: 360 family tries, 0.36 alarms expected; 3 or more has
  // probability 0.006.
  RecordAnalysisSettings s;
  s.lines.false_alarm = 0.05;
  int alarms[3] = {0, 0, 0}, strict = 0;
  for (std::uint64_t seed = 1; seed <= 120; ++seed) {
    test::SplitMix64 g(1000 + seed);
    std::vector<double> x(24000);
    for (double& v : x) v = g.normal();
    const RecordAnalysis a = analyse_record(x, kRate, "DE", "m/s^2", cwru_bearing(), given(), s);
    for (std::size_t i = 0; i < 3; ++i) {
      const CombSearch& comb = a.lines->families[i].comb;
      alarms[i] += comb.detected;
      std::vector<std::vector<int>> samples(3);
      for (const CombLine& l : comb.lines)
        if (l.rated) samples[l.harmonic - 1].push_back(l.floor_samples);
      strict += comb.evidence >= comb_threshold(samples, comb.trials, 1e-3);
    }
  }
  for (int count : alarms) EXPECT_LE(count, 15);
  EXPECT_LE(strict, 2);
}

// The verdict follows the rule: each rule's own diagnosis, whatever the others say.
TEST(RecordAnalysis, TheVerdictIsTheRulesOwn) {
  const BearingFrequencies f = bearing_frequencies(cwru_bearing(), kSpeed);
  const std::vector<double> x = fault_record(f.bpfo, 0, 9);
  for (DiagnosisRule rule :
       {DiagnosisRule::coherence, DiagnosisRule::line_to_floor, DiagnosisRule::envelope_peaks}) {
    RecordAnalysisSettings s;
    s.rule = rule;
    RecordAnalysis a = analyse_record(x, kRate, "DE", "m/s^2", cwru_bearing(), given(), s);
    ASSERT_TRUE(a.coherence && a.lines && a.summary.diagnosis);
    // Make the three disagree, then ask.
    a.coherence->family = FaultFamily::several;
    a.lines->family = FaultFamily::inner;
    a.summary.diagnosis->family = FaultFamily::ball;
    const FaultFamily expected = rule == DiagnosisRule::coherence       ? FaultFamily::several
                                 : rule == DiagnosisRule::line_to_floor ? FaultFamily::inner
                                                                        : FaultFamily::ball;
    EXPECT_EQ(a.family(), expected) << name_of(kDiagnosisRules, rule);
  }
}

TEST(RecordAnalysis, InputErrorsNameWhatIsWrong) {
  const auto message = [](const std::vector<double>& x, double rate, SpeedSetting speed) {
    try {
      analyse_record(x, rate, "DE", "m/s^2", cwru_bearing(), speed);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const auto contains = [](const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
  };
  std::vector<double> x = shaft_record(24000, kSpeed / two_pi, 1.0, 1);
  x[1234] = std::nan("");
  std::string m = message(x, kRate, given());
  EXPECT_TRUE(contains(m, "record DE") && contains(m, "sample 1234")) << m;
  x[1234] = 0;
  for (std::size_t at : {std::size_t{0}, x.size() - 1}) {  // the ends too
    std::vector<double> y = x;
    y[at] = -INFINITY;
    m = message(y, kRate, given());
    EXPECT_TRUE(contains(m, "sample " + std::to_string(at))) << m;
  }
  m = message(x, 0, given());
  EXPECT_TRUE(contains(m, "sample rate = 0 Hz")) << m;
  m = message(x, -kRate, given());
  EXPECT_TRUE(contains(m, "sample rate")) << m;
  m = message({1.0}, kRate, given());
  EXPECT_TRUE(contains(m, "1 samples; at least 2")) << m;
  // 0.5 s at 1797 rpm: 15 revolutions, fewer than the 20 needed.
  m = message(std::vector<double>(x.begin(), x.begin() + 6000), kRate, given());
  EXPECT_TRUE(contains(m, "shaft revolutions") && contains(m, "at least 20")) << m;
  m = message(x, kRate, given(-1));
  EXPECT_TRUE(contains(m, "speed = -1 rad/s")) << m;
  // Noise without shaft lines: the estimate finds none.
  test::SplitMix64 g(4);
  std::vector<double> noise(24000);
  for (double& v : noise) v = g.normal();
  m = message(noise, kRate, {SpeedSource::estimate, kSpeed});
  EXPECT_TRUE(contains(m, "speed estimate: no shaft line within ±10 %") &&
              contains(m, "1797 rpm") && contains(m, "give the speed"))
      << m;
}

std::string read(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

TEST(RecordOutput, WritesRunsFilesAndKeysAllOrNothing) {
  const BearingFrequencies f = bearing_frequencies(cwru_bearing(), kSpeed);
  const RecordAnalysis a = analyse_record(fault_record(f.bpfo, 0, 5), kRate, "DE", "m/s^2",
                                          cwru_bearing(), {SpeedSource::estimate, kSpeed});
  const fs::path dir = fs::temp_directory_path() / "bearing_record_output_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "response.csv") << "t,ay\n0,0\n";  // an earlier run's
  const RecordOrigin origin{"rig/130.mat", "cwru.toml", ""};
  write_record_analysis(dir.string(), a, origin);
  EXPECT_FALSE(fs::exists(dir / "response.csv"));
  const std::string spectrum = read(dir / "spectrum.csv");
  EXPECT_EQ(spectrum.substr(0, spectrum.find('\n')), "frequency,DE");
  const std::string envelope = read(dir / "envelope.csv");
  EXPECT_EQ(envelope.substr(0, envelope.find('\n')), "frequency,env_DE,ses_DE");
  const auto j = nlohmann::json::parse(read(dir / "summary.json"));
  EXPECT_EQ(j["record"]["file"], "rig/130.mat");
  EXPECT_EQ(j["record"]["channel"], "DE");
  EXPECT_EQ(j["record"]["rate"], kRate);
  EXPECT_EQ(j["speed"]["source"], "estimate");
  EXPECT_EQ(j["speed"]["value"], a.speed.speed);
  EXPECT_EQ(j["case"]["source"], "cwru.toml");
  EXPECT_EQ(j["channels"]["DE"]["rms"], a.summary.channels.front().statistics.rms);
  EXPECT_EQ(j["peaks"]["DE"].size(), a.summary.channels.front().peaks.size());
  EXPECT_EQ(j["envelope"]["DE"]["band"][0], a.summary.envelopes.front().band.low);
  EXPECT_EQ(j["diagnosis"]["family"], "outer");
  EXPECT_EQ(j["diagnosis"]["rule"], "coherence");
  EXPECT_EQ(j["diagnosis"]["margin"], a.coherence->margin);
  EXPECT_EQ(j["diagnosis"]["named"][0], "outer");
  EXPECT_EQ(j["coherence"]["bands"].size(), 25u);
  EXPECT_EQ(j["coherence"]["map"]["inner"].size(), 25u);
  EXPECT_EQ(j["coherence"]["families"]["outer"]["margin"], a.coherence->families[0].test.margin);
  EXPECT_TRUE(j["coherence"]["families"]["outer"]["named"].get<bool>());
  EXPECT_EQ(j["units"]["coherence.map"], "dB");
  EXPECT_EQ(j["fault_lines"]["outer"]["evidence"], a.lines->families[0].comb.evidence);
  EXPECT_TRUE(j["fault_lines"]["outer"]["detected"].get<bool>());
  EXPECT_TRUE(j["units"].contains("fault_lines.*.{evidence,threshold}"));
  // The readable summary says the same.
  const std::string text = record_summary_text(a, origin);
  EXPECT_NE(text.find("Diagnosis: outer race (margin +"), std::string::npos) << text;
  EXPECT_NE(text.find("Cyclic coherence by band (25 bands"), std::string::npos) << text;
  EXPECT_NE(text.find("rig/130.mat"), std::string::npos) << text;
  // A value that is not finite: nothing written, the earlier files as they were.
  const std::string before = read(dir / "summary.json");
  RecordAnalysis bad = a;
  bad.squared_envelope->amplitude[100] = std::nan("");  // streamed last, into envelope.csv
  EXPECT_THROW(write_record_analysis(dir.string(), bad, origin), SolverError);
  EXPECT_EQ(read(dir / "summary.json"), before);
  EXPECT_EQ(read(dir / "envelope.csv"), envelope);
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename().string().find(".partial"), std::string::npos) << entry.path();
  // As .npy with columns.json; the CSV tables go.
  write_record_analysis(dir.string(), a, origin, OutputFormat::npy);
  EXPECT_TRUE(fs::exists(dir / "spectrum.npy") && fs::exists(dir / "columns.json"));
  EXPECT_FALSE(fs::exists(dir / "spectrum.csv"));
  fs::remove_all(dir);
}

TEST(RecordOutput, RunsRuleWritesRunsDiagnosisBlock) {
  const BearingFrequencies f = bearing_frequencies(cwru_bearing(), kSpeed);
  RecordAnalysisSettings s;
  s.rule = DiagnosisRule::envelope_peaks;
  const RecordAnalysis a = analyse_record(fault_record(f.bpfi, f.shaft, 6), kRate, "DE", "m/s^2",
                                          cwru_bearing(), given(), s);
  const auto j = record_summary_json(a, {});
  EXPECT_EQ(j["diagnosis"]["rule"], "envelope_peaks");
  EXPECT_EQ(j["diagnosis"]["family"], name_of(kFaultFamilies, a.summary.diagnosis->family));
  EXPECT_EQ(j["diagnosis"]["reason"], a.summary.diagnosis->reason);
  EXPECT_TRUE(j["diagnosis"].contains("family_share"));
  EXPECT_TRUE(j.contains("fault_lines"));  // the lines are reported whatever the rule
}

}  // namespace
}  // namespace bearing
