// The envelope stage (issue 17): output.envelope_band reads, checks and round-trips, and drives
// the envelope analysis of the ring accelerations.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "bearing/case_file.h"
#include "bearing/envelope_analysis.h"
#include "bearing/errors.h"
#include "bearing/simulation.h"

namespace bearing {
namespace {

// The healthy default bearing: its 2-DOF response rattles at BPFO under the light load (ay
// kurtosis 5.8): its envelopes are BPFO harmonics, from bands at least 3·BPFI wide, mildly
// impulsive over the noise floor — with or without outer-race waviness.
TEST(EnvelopeAnalysis, KurtogramBandsOfTheHealthyDefaultCase) {
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
  }
}

// A given band: its spectral kurtosis, no kurtogram; the default ("none") analyses nothing.
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

}  // namespace
}  // namespace bearing
