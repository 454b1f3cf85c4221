// The envelope stage and the diagnosis (issue 17): synthetic fault signals are named after their
// family (an impact train at BPFO → outer; at BPFI, modulated at the shaft rate → inner; at
// 2×BSF, modulated at the cage rate → ball), steady bearing lines are not (→ none); the default
// case's healthy bearing, with and without waviness, is not diagnosed; output.envelope_band reads,
// checks, round-trips and drives `bearing-sim run`'s envelope.csv and summary blocks.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bearing/case_file.h"
#include "bearing/constants.h"
#include "bearing/diagnosis.h"
#include "bearing/errors.h"
#include "bearing/kinematics.h"
#include "bearing/simulation.h"
#include "cli_helpers.h"
#include "synthetic_signals.h"

namespace bearing {
namespace {

namespace fs = std::filesystem;
using test::fresh_dir;
using test::ImpactTrain;
using test::kShort;
using test::read;
using test::sim;

constexpr double kFs = 20000;      // [Hz]
constexpr std::size_t kN = 20000;  // 1 s: 1 Hz bins

// The default case's 6308 at 2000 rpm: fr 33.33, FTF 12.80, BPFO 102.40, BPFI 164.27,
// BSF 67.97 Hz.
BearingFrequencies default_frequencies() {
  const Case c = default_case();
  return bearing_frequencies(c.bearing, c.operation.speed, 0.0, 0.0);
}

// A steady vibration of a healthy bearing: BPFO harmonics 1 … 5 (varying compliance) with
// amplitude 1/k [m/s²], and two waviness lines (2·BPFI + fr, 9·fr).
std::vector<double> steady_lines(const BearingFrequencies& f) {
  std::vector<double> x(kN, 0.0);
  for (std::size_t i = 0; i < kN; ++i) {
    const double t = static_cast<double>(i) / kFs;
    for (int k = 1; k <= 5; ++k) x[i] += std::sin(two_pi * k * f.bpfo * t + 0.3 * k) / k;
    x[i] += 0.3 * std::sin(two_pi * (2 * f.bpfi + f.shaft) * t) +
            0.2 * std::sin(two_pi * 9 * f.shaft * t + 1);
  }
  return x;
}

// Impacts on a 5 kHz resonance (ζ = 0.05: each rings down within a sixth of the ball-pass period)
// over the steady lines, with white noise 10 dB below the impacts (fixed seed).
std::vector<double> faulty(const ImpactTrain& train, const BearingFrequencies& f,
                           std::uint64_t seed) {
  std::vector<double> impacts = test::impact_train(train, kN, kFs);
  for (double& v : impacts) v *= 20;  // the impacts' RMS ~ the steady lines'
  std::vector<double> x = test::with_noise(impacts, 10, seed);
  const std::vector<double> lines = steady_lines(f);
  for (std::size_t i = 0; i < kN; ++i) x[i] += lines[i];
  return x;
}

EnvelopeSummary auto_envelope(const std::vector<double>& x, const BearingFrequencies& f) {
  return analyse_envelope("ay", "m/s^2", x, kFs, f, {EnvelopeBandSource::automatic, {}},
                          Window::hann, 10);
}

TEST(FaultFamily, FromLabels) {
  for (const char* l : {"BPFO", "3xBPFO", "12xBPFO"})
    EXPECT_EQ(fault_family(l), FaultFamily::outer) << l;
  for (const char* l : {"BPFI", "2xBPFI", "BPFI-fr", "2xBPFI+fr", "BPFI+2fr", "3xBPFI-2fr"})
    EXPECT_EQ(fault_family(l), FaultFamily::inner) << l;
  for (const char* l : {"BSF", "3xBSF", "2xBSF-FTF", "4xBSF+2FTF"})
    EXPECT_EQ(fault_family(l), FaultFamily::ball) << l;
  for (const char* l : {"", "fr", "2xfr", "FTF", "12xFTF", "BPFO+fr", "BPFI+FTF", "BSF-fr", "xBPFO",
                        "3BPFO", "BPFI+", "BPFIX"})
    EXPECT_EQ(fault_family(l), FaultFamily::none) << l;
  // A subharmonic of the ball pass (a period-2 or period-3 response of a bearing with clearance)
  // is no outer-race fault line: a spall strikes at whole multiples of BPFO.
  for (const char* l : {"1/2xBPFO", "5/2xBPFO", "4/3xBPFO", "7/4xBPFO"})
    EXPECT_EQ(fault_family(l), FaultFamily::none) << l;
}

TEST(Diagnosis, ImpactsAtBpfoAreAnOuterRaceFault) {
  const BearingFrequencies f = default_frequencies();
  ImpactTrain train;
  train.rate = f.bpfo;
  train.damping_ratio = 0.05;
  const EnvelopeSummary e = auto_envelope(faulty(train, f, 1), f);
  EXPECT_LE(e.band.low, 5000.0);
  EXPECT_GE(e.band.high, 5000.0);
  ASSERT_FALSE(e.peaks.empty());
  EXPECT_EQ(e.peaks[0].label, "BPFO");
  const Diagnosis d = diagnose({e}, f);
  EXPECT_EQ(d.family, FaultFamily::outer) << d.reason;
  EXPECT_EQ(d.channel, "ay");
  EXPECT_EQ(d.unit, "m/s^2");
  EXPECT_GE(d.spectral_kurtosis, d.thresholds.min_spectral_kurtosis);
  ASSERT_GE(d.evidence.size(), 3u);
  EXPECT_EQ(d.evidence[0].label, "BPFO");
  for (const Peak& p : d.evidence) EXPECT_EQ(fault_family(p.label), FaultFamily::outer);
  EXPECT_NE(d.reason.find("outer race lines (k·BPFO, BPFO = 102.4 Hz)"), std::string::npos)
      << d.reason;
}

namespace {

// An impulsive envelope (ax, SK 8) with an outer-race line, an inner-race line and the shaft's.
EnvelopeSummary outer_and_inner_lines() {
  EnvelopeSummary e;
  e.channel = "ax";
  e.unit = "m/s^2";
  e.spectral_kurtosis = 8;
  e.peaks = {{102.4, 1.0, "BPFO", 0}, {164.3, 0.9, "BPFI", 0}, {33.3, 5.0, "fr", 0}};
  return e;
}

}  // namespace

// The diagnosis does not depend on the signal's scale (its unit): the same envelope lines 10^4
// times smaller read the same, the families' shares of the fault lines included.
TEST(Diagnosis, DoesNotDependOnTheSignalsScale) {
  const BearingFrequencies f = default_frequencies();
  const EnvelopeSummary e = outer_and_inner_lines();
  EnvelopeSummary small = e;
  for (Peak& p : small.peaks) p.amplitude *= 1e-4;
  const Diagnosis d = diagnose({e}, f), ds = diagnose({small}, f);
  EXPECT_EQ(ds.family, d.family);
  EXPECT_NE(d.reason.find("outer 53 %, inner 47 %, ball 0 %"), std::string::npos) << d.reason;
  EXPECT_EQ(ds.reason, d.reason);
}

TEST(Diagnosis, ImpactsAtBpfiModulatedByTheShaftAreAnInnerRaceFault) {
  const BearingFrequencies f = default_frequencies();
  ImpactTrain train;  // the defect passes through the load zone once a shaft turn
  train.rate = f.bpfi;
  train.damping_ratio = 0.05;
  train.modulation = f.shaft;
  train.depth = 0.8;
  const EnvelopeSummary e = auto_envelope(faulty(train, f, 2), f);
  const Diagnosis d = diagnose({e}, f);
  EXPECT_EQ(d.family, FaultFamily::inner) << d.reason;
  bool bpfi = false, sideband = false;
  for (const Peak& p : d.evidence) {
    bpfi = bpfi || p.label == "BPFI";
    sideband = sideband || p.label == "BPFI-fr" || p.label == "BPFI+fr";
  }
  EXPECT_TRUE(bpfi && sideband) << d.reason;
}

TEST(Diagnosis, ImpactsAtTwiceBsfModulatedByTheCageAreABallFault) {
  const BearingFrequencies f = default_frequencies();
  ImpactTrain train;  // a ball defect strikes both races once a spin each, the cage carries it
  train.rate = 2 * f.bsf;
  train.damping_ratio = 0.05;
  train.modulation = f.ftf;
  train.depth = 0.8;
  const EnvelopeSummary e = auto_envelope(faulty(train, f, 3), f);
  const Diagnosis d = diagnose({e}, f);
  EXPECT_EQ(d.family, FaultFamily::ball) << d.reason;
  bool line = false, sideband = false;
  for (const Peak& p : d.evidence) {
    line = line || p.label == "2xBSF";
    sideband = sideband || p.label == "2xBSF-FTF" || p.label == "2xBSF+FTF";
  }
  EXPECT_TRUE(line && sideband) << d.reason;
}

TEST(Diagnosis, SteadyBearingLinesAreNoFault) {
  // BPFO harmonics and waviness lines with a little noise: lines in every envelope, but nothing
  // impulsive (SK of a few steady tones is at most 0).
  const BearingFrequencies f = default_frequencies();
  const EnvelopeSummary e = auto_envelope(test::with_noise(steady_lines(f), 30, 4), f);
  EXPECT_LT(e.spectral_kurtosis, 1.0);
  const Diagnosis d = diagnose({e}, f);
  EXPECT_EQ(d.family, FaultFamily::none);
  EXPECT_TRUE(d.evidence.empty());
  EXPECT_EQ(d.reason.rfind("not impulsive: spectral kurtosis", 0), 0u) << d.reason;
}

TEST(Diagnosis, NeedsADominantFamilyAndPicksTheMostImpulsiveEnvelope) {
  const BearingFrequencies f = default_frequencies();
  const EnvelopeSummary e = outer_and_inner_lines();
  Diagnosis d = diagnose({e}, f);  // outer 53 %, inner 47 %: neither dominates
  EXPECT_EQ(d.family, FaultFamily::none);
  EXPECT_NE(d.reason.find("no fault family dominates"), std::string::npos) << d.reason;
  EXPECT_NEAR(d.family_share, 1.0 / 1.9, 1e-12);
  EnvelopeSummary y = e;
  y.channel = "ay";
  y.spectral_kurtosis = 6;
  y.peaks = {{164.3, 0.9, "BPFI", 0}, {131, 0.5, "BPFI-fr", 0}, {12.8, 3, "FTF", 0}};
  d = diagnose({e, y}, f);  // only ay counts, though ax is more impulsive
  EXPECT_EQ(d.family, FaultFamily::inner);
  EXPECT_EQ(d.channel, "ay");
  ASSERT_EQ(d.evidence.size(), 2u);
  EXPECT_DOUBLE_EQ(d.family_share, 1.0);
  y.spectral_kurtosis = 4.9;  // below the threshold
  d = diagnose({y}, f);
  EXPECT_EQ(d.family, FaultFamily::none);
  DiagnosisSettings lenient;
  lenient.min_spectral_kurtosis = 4;
  EXPECT_EQ(diagnose({y}, f, lenient).family, FaultFamily::inner);
  y.peaks = {{12.8, 3, "FTF", 0}};
  y.spectral_kurtosis = 9;
  EXPECT_NE(diagnose({y}, f).reason.find("none of its envelope lines is a fault frequency"),
            std::string::npos);
  EXPECT_EQ(diagnose({}, f).reason, "no envelope analysis (output.envelope_band = \"none\")");
}

// The healthy default bearing: its 2-DOF response rattles at BPFO under the light load (ay
// kurtosis 5.8) and its envelopes are BPFO harmonics, but they are not impulsive enough to be a
// fault — with or without outer-race waviness.
TEST(EnvelopeAnalysis, HealthyDefaultCaseIsNotDiagnosed) {
  for (const char* waviness : {"", "[{order = 9, amplitude = \"0.5 um\"}]"}) {
    std::vector<Override> o = {{"output.envelope_band", "\"auto\""}};
    if (*waviness) o.push_back({"waviness.outer", waviness});
    const Case c = default_case(o);
    const SimulationResult r = simulate(c);
    const RunSummary s = summarize(c, r);
    ASSERT_EQ(s.envelopes.size(), 2u);
    EXPECT_EQ(s.envelopes[0].channel, "ax");
    EXPECT_EQ(s.envelopes[1].channel, "ay");
    for (const EnvelopeSummary& e : s.envelopes) {
      EXPECT_EQ(e.source, EnvelopeBandSource::automatic);
      EXPECT_FALSE(e.kurtogram.empty());
      EXPECT_GE(e.band.high - e.band.low, envelope_min_bandwidth(r.frequencies));
      EXPECT_LT(e.spectral_kurtosis, 3.0) << e.channel;
      ASSERT_FALSE(e.peaks.empty());
      EXPECT_EQ(e.peaks[0].label, "BPFO") << e.channel;
    }
    ASSERT_TRUE(s.diagnosis);
    EXPECT_EQ(s.diagnosis->family, FaultFamily::none) << waviness << ": " << s.diagnosis->reason;
  }
}

// A given band: its spectral kurtosis, no kurtogram; the default ("none") analyses nothing.
// The energy fraction reported for the chosen band is that band's, not a neighbour's sharing
// one edge; a given band the kurtogram did not compute has none.
TEST(EnvelopeAnalysis, BandEnergyFractionIsTheChosenBands) {
  EnvelopeSummary e;
  e.band = {500, 1000};
  KurtogramBand whole, lower, upper;
  whole.band = {0, 1000};
  whole.energy_fraction = 1.0;
  lower.band = {0, 500};
  lower.energy_fraction = 0.3;
  upper.band = {500, 1000};
  upper.energy_fraction = 0.7;
  e.kurtogram = {whole, lower, upper};
  ASSERT_TRUE(band_energy_fraction(e).has_value());
  EXPECT_EQ(*band_energy_fraction(e), 0.7);
  e.band = {250, 750};
  EXPECT_FALSE(band_energy_fraction(e).has_value());
}

// A narrowest band asked for is honoured: the kurtogram then picks no band narrower.
TEST(EnvelopeAnalysis, KurtogramKeepsTheNarrowestBandAskedFor) {
  const BearingFrequencies f = default_frequencies();
  ImpactTrain train;
  train.rate = f.bpfo;
  train.damping_ratio = 0.05;
  const std::vector<double> x = faulty(train, f, 1);
  const EnvelopeSummary free = auto_envelope(x, f);
  const double wide = 2.5 * (free.band.high - free.band.low);
  const EnvelopeSummary e = analyse_envelope(
      "ay", "m/s^2", x, kFs, f, {EnvelopeBandSource::automatic, {}}, Window::hann, 10, wide);
  EXPECT_GE(e.band.high - e.band.low, wide * (1 - 1e-12));
}

TEST(EnvelopeAnalysis, GivenBandAndNone) {
  const Case c = default_case({{"output.envelope_band", "[\"2 kHz\", \"8 kHz\"]"}});
  EXPECT_EQ(c.output.envelope_band.source, EnvelopeBandSource::given);
  EXPECT_EQ(c.output.envelope_band.band.low, 2000.0);
  EXPECT_EQ(c.output.envelope_band.band.high, 8000.0);
  const SimulationResult r = simulate(c);
  const RunSummary s = summarize(c, r);
  ASSERT_EQ(s.envelopes.size(), 2u);
  for (const EnvelopeSummary& e : s.envelopes) {
    EXPECT_EQ(e.band.low, 2000.0);
    EXPECT_EQ(e.band.high, 8000.0);
    EXPECT_TRUE(e.kurtogram.empty());
    EXPECT_DOUBLE_EQ(e.spectral_kurtosis,
                     spectral_kurtosis(r.response.steady(e.channel), r.response.rate, e.band,
                                       kEnvelopeNoiseFloor));
  }
  const Case none = default_case();
  EXPECT_EQ(none.output.envelope_band.source, EnvelopeBandSource::none);
  const RunSummary n = summarize(none, r);
  EXPECT_TRUE(n.envelopes.empty());
  EXPECT_FALSE(n.diagnosis);
}

// ----------------------------------------------------------------------------------------------
// The case key

std::string error_of(const std::vector<Override>& o) {
  try {
    default_case(o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(EnvelopeBandKey, ReadsChecksAndRoundTripsExactly) {
  for (const char* value : {"\"auto\"", "[\"2 kHz\", \"8 kHz\"]", "[0, 10000]",
                            "[\"1234.5678901234 Hz\", \"9.87654321 kHz\"]", "\"none\""}) {
    const Case a = default_case({{"output.envelope_band", value}});
    const std::string toml = case_to_toml(a);
    const Case b = parse_case(toml, "case.toml");
    EXPECT_EQ(b.output.envelope_band.source, a.output.envelope_band.source) << value;
    EXPECT_EQ(b.output.envelope_band.band.low, a.output.envelope_band.band.low) << value;
    EXPECT_EQ(b.output.envelope_band.band.high, a.output.envelope_band.band.high) << value;
    // "none", the default, is not written: a case.toml without envelope analysis is unchanged.
    EXPECT_EQ(toml.find("envelope_band") == std::string::npos,
              a.output.envelope_band.source == EnvelopeBandSource::none)
        << value;
  }
  EXPECT_EQ(case_to_toml(default_case()),
            case_to_toml(default_case({{"output.envelope_band", "\"none\""}})));
  // The overrides as a shell passes them (`--set output.envelope_band=auto`).
  EXPECT_EQ(default_case({parse_override("output.envelope_band=auto")}).output.envelope_band.source,
            EnvelopeBandSource::automatic);
  EXPECT_EQ(default_case({parse_override("output.envelope_band=[\"2 kHz\",\"8 kHz\"]")})
                .output.envelope_band.band.high,
            8000.0);

  const auto expect_error = [](const std::vector<Override>& o, const std::string& part) {
    const std::string e = error_of(o);
    EXPECT_NE(e.find(part), std::string::npos) << "lacks \"" << part << "\": " << e;
  };
  expect_error({{"output.envelope_band", "[\"8 kHz\", \"2 kHz\"]"}},
               "output.envelope_band = [8000 Hz, 2000 Hz]: allowed 0 <= low < high <= 10000 Hz "
               "(solver.output_rate / 2)");
  expect_error({{"output.envelope_band", "[\"2 kHz\", \"12 kHz\"]"}},
               "output.envelope_band = [2000 Hz, 12000 Hz]: allowed 0 <= low < high <= 10000 Hz");
  expect_error(
      {{"output.envelope_band", "[\"2 kHz\", \"12 kHz\"]"}, {"solver.output_rate", "\"50 kHz\""}},
      "no error");
  expect_error({{"output.envelope_band", "[-1, 100]"}}, "output.envelope_band = [-1 Hz, 100 Hz]");
  expect_error({{"output.envelope_band", "\"kurtogram\""}},
               "output.envelope_band = \"kurtogram\": expected \"none\", \"auto\"");
  expect_error({{"output.envelope_band", "\"given\""}}, "output.envelope_band = \"given\"");
  expect_error({{"output.envelope_band", "[1, 2, 3]"}}, "or a band [low, high]");
  expect_error({{"output.envelope_band", "2000"}}, "output.envelope_band = 2000");
  expect_error({{"output.envelope_band", "[\"2 kHz\", \"8 m\"]"}}, "output.envelope_band[1]");
}

// ----------------------------------------------------------------------------------------------
// bearing-sim run

TEST(EnvelopeCli, AutoWritesEnvelopeCsvAndTheSummaryBlocks) {
  const fs::path d = fresh_dir("run_envelope");
  std::string out;
  ASSERT_EQ(sim("run --out " + d.string() + kShort + " --set output.envelope_band=auto", &out), 0)
      << out;
  const std::string csv = read(d / "envelope.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "frequency,env_ax,env_ay");
  // 0.2 s analysed at 20 kHz: 4000 samples, bins 0 … 2000 at 5 Hz, plus the header.
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 2002);
  EXPECT_EQ(csv.find("nan"), std::string::npos);

  const auto j = nlohmann::json::parse(read(d / "summary.json"));
  for (const char* ch : {"ax", "ay"}) {
    const auto& e = j["envelope"][ch];
    ASSERT_EQ(e["band"].size(), 2u) << ch;
    EXPECT_LT(e["band"][0].get<double>(), e["band"][1].get<double>());
    EXPECT_EQ(e["band_source"], "auto");
    EXPECT_TRUE(e["spectral_kurtosis"].is_number());
    EXPECT_FALSE(e["kurtogram"].empty());
    ASSERT_FALSE(e["peaks"].empty());
    for (const char* k : {"frequency", "amplitude", "label_error"})
      EXPECT_TRUE(e["peaks"][0][k].is_number()) << k;
    EXPECT_TRUE(e["peaks"][0]["label"].is_string());
  }
  const auto& g = j["diagnosis"];
  EXPECT_EQ(g["family"], "none");
  EXPECT_TRUE(g["channel"] == "ax" || g["channel"] == "ay");
  EXPECT_TRUE(g["evidence"].is_array());
  EXPECT_TRUE(g["reason"].is_string());
  EXPECT_EQ(j["units"]["envelope.*.band"], "Hz");
  EXPECT_NE(out.find("Envelope spectra"), std::string::npos) << out;
  EXPECT_NE(out.find("Diagnosis: none — not impulsive"), std::string::npos) << out;
  EXPECT_NE(read(d / "case.toml").find("envelope_band = \"auto\""), std::string::npos);

  // The resolved case repeats the envelope analysis; a run without it removes envelope.csv and
  // writes no envelope or diagnosis block.
  const fs::path again = fresh_dir("run_envelope_again");
  ASSERT_EQ(sim("run " + (d / "case.toml").string() + " --out " + again.string() + " --quiet"), 0);
  EXPECT_EQ(read(again / "envelope.csv"), csv);
  ASSERT_EQ(sim("run --out " + d.string() + kShort), 0);
  EXPECT_FALSE(fs::exists(d / "envelope.csv"));
  const auto plain = nlohmann::json::parse(read(d / "summary.json"));
  EXPECT_FALSE(plain.contains("envelope"));
  EXPECT_FALSE(plain.contains("diagnosis"));
}

TEST(EnvelopeCli, GivenBandAndBadBands) {
  const fs::path d = fresh_dir("run_envelope_given");
  std::string out;
  ASSERT_EQ(sim("run --out " + d.string() + kShort +
                    " --set 'output.envelope_band=[\"2 kHz\",\"8 kHz\"]'",
                &out),
            0)
      << out;
  const auto j = nlohmann::json::parse(read(d / "summary.json"));
  EXPECT_EQ(j["envelope"]["ay"]["band"][0], 2000.0);
  EXPECT_EQ(j["envelope"]["ay"]["band"][1], 8000.0);
  EXPECT_EQ(j["envelope"]["ay"]["band_source"], "given");
  EXPECT_FALSE(j["envelope"]["ay"].contains("kurtogram"));
  EXPECT_NE(read(d / "case.toml").find("envelope_band = [2000.0, 8000.0]"), std::string::npos);
  const fs::path bad = fresh_dir("run_envelope_bad");
  EXPECT_EQ(sim("run --out " + bad.string() + kShort +
                    " --set 'output.envelope_band=[\"2 kHz\",\"20 kHz\"]'",
                &out),
            2);
  EXPECT_NE(out.find("output.envelope_band = [2000 Hz, 20000 Hz]: allowed 0 <= low < high <= "
                     "10000 Hz"),
            std::string::npos)
      << out;
  EXPECT_FALSE(fs::exists(bad / "summary.json"));
  EXPECT_EQ(sim("run --out " + bad.string() + kShort + " --set output.envelope_band=automatic"), 2);
}

}  // namespace
}  // namespace bearing
