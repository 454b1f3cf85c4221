// SweepRow ↔ bytes (rows sent between MPI ranks): every field comes back bit for bit, a real
// run's row gives the same sweep.csv line after the round trip, malformed bytes are refused.

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "bearing/diagnosis.h"
#include "bearing/sweep.h"
#include "bearing/sweep_row_codec.h"

namespace {

using bearing::SweepRow;

std::uint64_t bits(double v) {
  std::uint64_t b = 0;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

void expect_same(double a, double b) {
  EXPECT_EQ(bits(a), bits(b));
}

void expect_same(const std::optional<double>& a, const std::optional<double>& b) {
  ASSERT_EQ(a.has_value(), b.has_value());
  if (a) expect_same(*a, *b);
}

SweepRow full_row() {
  SweepRow row;
  row.values = {1.0 / 3.0, -0.0, std::numeric_limits<double>::denorm_min(),
                std::numeric_limits<double>::infinity(), std::nan("")};
  row.ok = true;
  row.error = "a, \"quoted\"\nmessage µm";
  bearing::ChannelSummary x;
  x.name = "ax";
  x.unit = "m/s^2";
  x.group = bearing::ChannelGroup::ring;
  x.statistics = {1e-9, 2.5, 3.25, 4.125, std::sqrt(2.0)};
  x.peaks = {{123.456, 7e-6, "BPFO", -0.01}, {246.9, 1e-7, "", 0}};
  bearing::ChannelSummary q = x;
  q.name = "Q3";
  q.unit = "N";
  q.group = bearing::ChannelGroup::ball;
  q.peaks.clear();
  row.channels = {x, q};
  bearing::MicrophoneLevels m;
  m.microphone = {0.5, 0.25};
  m.position = {0.1, -0.2};
  m.p_rms = 1e-3;
  m.p_rms_ring = 2e-3;
  m.p_rms_balls = 0;
  m.spl_total = 34.5;
  m.spl_ring = 30.25;
  m.nearest_ball_surface = 0.4;
  row.microphones = {m, bearing::MicrophoneLevels{}};
  bearing::SweepEnvelope e;
  e.channel = "ay";
  e.band = {1666.6666666666667, 2500.25};
  e.spectral_kurtosis = 9.375;
  e.energy_fraction = 1.0 / 7.0;
  e.peak = bearing::Peak{107.25, 3e-3, "BPFO", 0.125};
  bearing::SweepEnvelope given = e;
  given.channel = "ax";
  given.energy_fraction.reset();
  given.peak.reset();
  row.envelopes = {e, given};
  bearing::Diagnosis d;
  d.family = bearing::FaultFamily::inner;
  d.channel = "ay";
  d.unit = "m/s^2";
  d.band = e.band;
  d.source = bearing::EnvelopeBandSource::automatic;
  d.spectral_kurtosis = 27.5;
  d.family_share = 2.0 / 3.0;
  d.evidence = {{162.5, 2e-3, "BPFI", -0.5}, {132.5, 1e-3, "BPFI-fr", 0.25}};
  d.reason = "ay, 1.67–2.5 kHz (kurtogram): spectral kurtosis 27.5 ≥ 5, …";
  d.thresholds = {4.5, 0.625};
  row.diagnosis = d;
  return row;
}

void expect_same(const bearing::Peak& a, const bearing::Peak& b) {
  expect_same(a.frequency, b.frequency);
  expect_same(a.amplitude, b.amplitude);
  EXPECT_EQ(a.label, b.label);
  expect_same(a.label_error, b.label_error);
}

TEST(SweepRowCodec, EveryFieldRoundTripsBitForBit) {
  const SweepRow row = full_row();
  std::string bytes;
  bearing::encode_sweep_row(987654321, row, bytes);
  std::size_t index = 0;
  const SweepRow back = bearing::decode_sweep_row(bytes, index);
  EXPECT_EQ(index, 987654321u);
  ASSERT_EQ(back.values.size(), row.values.size());
  for (std::size_t i = 0; i < row.values.size(); ++i) expect_same(back.values[i], row.values[i]);
  EXPECT_EQ(back.ok, row.ok);
  EXPECT_EQ(back.error, row.error);
  ASSERT_EQ(back.channels.size(), 2u);
  for (std::size_t c = 0; c < 2; ++c) {
    const auto& a = back.channels[c];
    const auto& b = row.channels[c];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.unit, b.unit);
    EXPECT_EQ(a.group, b.group);
    expect_same(a.statistics.mean, b.statistics.mean);
    expect_same(a.statistics.rms, b.statistics.rms);
    expect_same(a.statistics.ptp, b.statistics.ptp);
    expect_same(a.statistics.kurtosis, b.statistics.kurtosis);
    expect_same(a.statistics.crest, b.statistics.crest);
    ASSERT_EQ(a.peaks.size(), b.peaks.size());
    for (std::size_t p = 0; p < a.peaks.size(); ++p) {
      expect_same(a.peaks[p].frequency, b.peaks[p].frequency);
      expect_same(a.peaks[p].amplitude, b.peaks[p].amplitude);
      EXPECT_EQ(a.peaks[p].label, b.peaks[p].label);
      expect_same(a.peaks[p].label_error, b.peaks[p].label_error);
    }
  }
  ASSERT_EQ(back.microphones.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& a = back.microphones[i];
    const auto& b = row.microphones[i];
    expect_same(a.microphone.radius, b.microphone.radius);
    expect_same(a.microphone.angle, b.microphone.angle);
    expect_same(a.position.x(), b.position.x());
    expect_same(a.position.y(), b.position.y());
    expect_same(a.p_rms, b.p_rms);
    expect_same(a.p_rms_ring, b.p_rms_ring);
    expect_same(a.p_rms_balls, b.p_rms_balls);
    expect_same(a.spl_total, b.spl_total);
    expect_same(a.spl_ring, b.spl_ring);
    expect_same(a.spl_balls, b.spl_balls);
    expect_same(a.nearest_ball_surface, b.nearest_ball_surface);
  }
  ASSERT_EQ(back.envelopes.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& a = back.envelopes[i];
    const auto& b = row.envelopes[i];
    EXPECT_EQ(a.channel, b.channel);
    expect_same(a.band.low, b.band.low);
    expect_same(a.band.high, b.band.high);
    expect_same(a.spectral_kurtosis, b.spectral_kurtosis);
    expect_same(a.energy_fraction, b.energy_fraction);
    ASSERT_EQ(a.peak.has_value(), b.peak.has_value());
    if (a.peak) expect_same(*a.peak, *b.peak);
  }
  ASSERT_TRUE(back.diagnosis);
  const bearing::Diagnosis &a = *back.diagnosis, &b = *row.diagnosis;
  EXPECT_EQ(a.family, b.family);
  EXPECT_EQ(a.channel, b.channel);
  EXPECT_EQ(a.unit, b.unit);
  expect_same(a.band.low, b.band.low);
  expect_same(a.band.high, b.band.high);
  EXPECT_EQ(a.source, b.source);
  expect_same(a.spectral_kurtosis, b.spectral_kurtosis);
  expect_same(a.family_share, b.family_share);
  ASSERT_EQ(a.evidence.size(), b.evidence.size());
  for (std::size_t p = 0; p < a.evidence.size(); ++p) expect_same(a.evidence[p], b.evidence[p]);
  EXPECT_EQ(a.reason, b.reason);
  expect_same(a.thresholds.min_spectral_kurtosis, b.thresholds.min_spectral_kurtosis);
  expect_same(a.thresholds.min_family_share, b.thresholds.min_family_share);
}

TEST(SweepRowCodec, AFailedRowRoundTrips) {
  SweepRow row;
  row.values = {2.0};
  row.error = "solver: step size underflow";
  std::string bytes;
  bearing::encode_sweep_row(0, row, bytes);
  std::size_t index = 1;
  const SweepRow back = bearing::decode_sweep_row(bytes, index);
  EXPECT_EQ(index, 0u);
  EXPECT_FALSE(back.ok);
  EXPECT_EQ(back.error, row.error);
  EXPECT_TRUE(back.channels.empty());
  EXPECT_TRUE(back.microphones.empty());
  EXPECT_TRUE(back.envelopes.empty());
  EXPECT_FALSE(back.diagnosis);
}

// A real sweep's rows (with acoustics and the envelope analysis) give the same sweep.csv after the
// round trip.
TEST(SweepRowCodec, RealRowsGiveTheSameCsv) {
  const std::vector<bearing::SweepAxis> axes = {
      bearing::parse_vary("operation.speed=1000rpm:3000rpm:2")};
  const auto load = [](const std::vector<bearing::Override>& point) {
    std::vector<bearing::Override> all = {
        bearing::parse_override("solver.duration=0.05"),
        bearing::parse_override("solver.transient=0.01"),
        bearing::parse_override("output.envelope_band=auto"),
        bearing::parse_override(R"(acoustics.microphones=[[0.5, "0 deg"], [1.0, "90 deg"]])")};
    all.insert(all.end(), point.begin(), point.end());
    return bearing::default_case(all);
  };
  const std::vector<SweepRow> rows = bearing::run_sweep(load, bearing::sweep_points(axes), 1);
  std::vector<SweepRow> back;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    std::string bytes;
    bearing::encode_sweep_row(i, rows[i], bytes);
    std::size_t index = 0;
    back.push_back(bearing::decode_sweep_row(bytes, index));
    EXPECT_EQ(index, i);
  }
  ASSERT_TRUE(rows.front().ok) << rows.front().error;
  EXPECT_FALSE(rows.front().microphones.empty());
  EXPECT_EQ(rows.front().envelopes.size(), 2u);  // ax, ay
  ASSERT_TRUE(rows.front().diagnosis);
  EXPECT_FALSE(rows.front().diagnosis->reason.empty());
  EXPECT_EQ(bearing::sweep_csv(axes, back), bearing::sweep_csv(axes, rows));
}

TEST(SweepRowCodec, MalformedBytesAreRefused) {
  std::string bytes;
  bearing::encode_sweep_row(3, full_row(), bytes);
  std::size_t index = 0;
  for (std::size_t n : {std::size_t{0}, std::size_t{5}, bytes.size() / 2, bytes.size() - 1})
    EXPECT_THROW(bearing::decode_sweep_row(std::string_view(bytes).substr(0, n), index),
                 std::runtime_error)
        << n;
  EXPECT_THROW(bearing::decode_sweep_row(bytes + "x", index), std::runtime_error);
}

TEST(SweepRowCodec, SavedTablesRoundTripBitForBit) {
  // `sweep --save` under mpirun: the tables built on a worker rank reach rank 0's sweep.h5.
  bearing::SweepRow row = full_row();
  auto t = std::make_shared<bearing::SweepCaseTables>();
  t->case_toml = "[bearing]\npreset = \"6308\"\n";
  t->summary_json = "{\"channels\": {}}\n";
  bearing::SweepTable response;
  response.name = "response";
  response.rows = 2;
  response.columns = {"t", "x"};
  response.units = {"s", "m"};
  response.values = {0.0, -0.0, 5e-6, std::numeric_limits<double>::denorm_min()};
  bearing::SweepTable summary;
  summary.name = "summary";
  summary.rows = 5;
  summary.columns = {"x"};
  summary.units = {"m"};
  summary.row_names = {"mean", "rms", "ptp", "kurtosis", "crest"};
  summary.values = {1.0, 2.0, 3.0, std::nan(""), std::numeric_limits<double>::infinity()};
  t->tables = {response, summary};
  row.tables = t;
  std::string bytes;
  bearing::encode_sweep_row(7, row, bytes);
  std::size_t index = 0;
  const bearing::SweepRow back = bearing::decode_sweep_row(bytes, index);
  ASSERT_TRUE(back.tables);
  EXPECT_EQ(back.tables->case_toml, t->case_toml);
  EXPECT_EQ(back.tables->summary_json, t->summary_json);
  ASSERT_EQ(back.tables->tables.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const bearing::SweepTable &a = t->tables[k], &b = back.tables->tables[k];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.rows, b.rows);
    EXPECT_EQ(a.columns, b.columns);
    EXPECT_EQ(a.units, b.units);
    EXPECT_EQ(a.row_names, b.row_names);
    ASSERT_EQ(a.values.size(), b.values.size());
    for (std::size_t i = 0; i < a.values.size(); ++i) expect_same(a.values[i], b.values[i]);
  }
  // A row without tables stays without.
  bytes.clear();
  bearing::encode_sweep_row(7, full_row(), bytes);
  EXPECT_FALSE(bearing::decode_sweep_row(bytes, index).tables);
}

}  // namespace
