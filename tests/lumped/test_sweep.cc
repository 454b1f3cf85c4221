// Sweeps stream: points from their index, rows handed over in case order with a bounded reorder
// window, sweep.csv the same text whether built at once or row by row, and for any --jobs.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "bearing/errors.h"
#include "bearing/sweep.h"
#include "cli_helpers.h"

namespace {

namespace fs = std::filesystem;
using bearing::SweepAxis;
using bearing::SweepPoint;
using bearing::SweepRow;
using bearing::test::fresh_dir;
using bearing::test::read;
using bearing::test::sim;

std::vector<SweepAxis> two_axes() {
  return {bearing::parse_vary("bearing.balls=7:9:3"),
          bearing::parse_vary("operation.speed=1000rpm:2000rpm:2")};
}

// The i-th point is the i-th of the Cartesian product, the first axis slowest.
TEST(Sweep, PointFromItsIndex) {
  const auto axes = two_axes();
  ASSERT_EQ(bearing::sweep_size(axes), 6u);
  EXPECT_EQ(bearing::sweep_size({}), 0u);
  for (std::size_t i = 0; i < 6; ++i) {
    const SweepPoint p = bearing::sweep_point(axes, i);
    ASSERT_EQ(p.values.size(), 2u);
    EXPECT_EQ(p.values[0], axes[0].values[i / 2]) << i;
    EXPECT_EQ(p.values[1], axes[1].values[i % 2]) << i;
    EXPECT_EQ(p.overrides[0].key, "bearing.balls");
    EXPECT_EQ(p.overrides[0].value, std::to_string(7 + i / 2));
  }
  EXPECT_EQ(bearing::sweep_points(axes).size(), 6u);
}

// A plain FROM or TO is SI (as in a case file and in --cases), except for angles and speeds,
// whose bare 0 alone passes; an unknown key names the nearest known one.
TEST(Sweep, VaryTakesPlainNumbersAsSi) {
  EXPECT_EQ(bearing::parse_vary("operation.axial_load=0:200:3").values,
            (std::vector<double>{0, 100, 200}));
  EXPECT_EQ(bearing::parse_vary("bearing.clearance=0:1e-5:2").values,
            (std::vector<double>{0, 1e-5}));
  EXPECT_EQ(bearing::parse_vary("operation.speed=0:100rad/s:2").values,
            (std::vector<double>{0, 100}));
  for (const char* bad : {"operation.speed=0:3000:2", "bearing.contact_angle=0:10:2"})
    EXPECT_THROW(bearing::parse_vary(bad), bearing::InputError) << bad;
  try {
    bearing::parse_vary("operation.axial_lod=0:200:3");
    FAIL();
  } catch (const bearing::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean \"operation.axial_load\""),
              std::string::npos)
        << e.what();
  }
}

SweepRow failed_row(double v, const std::string& why) {
  SweepRow r;
  r.values = {v};
  r.error = why;
  return r;
}

SweepRow ok_row(double v) {
  SweepRow r;
  r.values = {v};
  r.ok = true;
  bearing::ChannelSummary ch;
  ch.name = "x";
  ch.statistics.rms = v;
  ch.peaks.push_back({});
  ch.peaks.back().frequency = 10 * v;
  ch.peaks.back().label = "BPFO, \"2\"";
  r.channels = {ch};
  return r;
}

// Rows written one by one give sweep_csv's text: failed rows before the first successful one
// wait for its columns; a sweep that never succeeds has no channel columns.
TEST(Sweep, StreamedCsvIsTheWholeTable) {
  SweepAxis mass;
  mass.key = "rotor.mass";
  mass.values = {1, 2, 3};
  const std::vector<SweepAxis> axes = {mass};
  const std::vector<SweepRow> rows = {failed_row(1, "bad, really"), ok_row(2), failed_row(3, "x")};
  std::string streamed;
  std::size_t writes_before_ok = 0;
  bearing::SweepCsvWriter writer(axes, [&](std::string_view s) { streamed.append(s); });
  writer.add(rows[0]);
  writes_before_ok = streamed.size();
  for (std::size_t i = 1; i < rows.size(); ++i) writer.add(rows[i]);
  writer.finish();
  EXPECT_EQ(writes_before_ok, 0u);
  EXPECT_EQ(streamed, bearing::sweep_csv(axes, rows));
  EXPECT_EQ(streamed.substr(0, streamed.find('\n')),
            "rotor.mass,status,error,x.rms,x.ptp,x.kurtosis,x.crest,x.peak_frequency,"
            "x.peak_label");
  EXPECT_NE(streamed.find("\n1,failed,\"bad, really\",,,,,,\n"), std::string::npos) << streamed;
  EXPECT_NE(streamed.find(",20,\"BPFO, \"\"2\"\"\"\n"), std::string::npos) << streamed;

  const std::vector<SweepRow> none = {failed_row(1, "a"), failed_row(2, "b")};
  std::string all_failed;
  bearing::SweepCsvWriter w2(axes, [&](std::string_view s) { all_failed.append(s); });
  for (const auto& r : none) w2.add(r);
  w2.finish();
  EXPECT_EQ(all_failed, "rotor.mass,status,error\n1,failed,a\n2,failed,b\n");
  EXPECT_EQ(all_failed, bearing::sweep_csv(axes, none));
}

// A row of an envelope sweep: ok_row(v) with the envelope of ax and its diagnosis.
SweepRow envelope_row(double v, bearing::FaultFamily family) {
  SweepRow r = ok_row(v);
  bearing::SweepEnvelope e;
  e.channel = "ax";
  e.band = {1000, 3000};
  e.spectral_kurtosis = v;
  e.peak = bearing::Peak{107.5, 0.25, "BPFO", 0};
  r.envelopes = {e};
  bearing::Diagnosis d;
  d.family = family;
  d.channel = "ax";
  d.spectral_kurtosis = v;
  d.family_share = 0.75;
  if (family != bearing::FaultFamily::none)
    d.evidence = {{107.5, 0.25, "BPFO", 0}, {215, 0.125, "2xBPFO", 0}};
  d.reason = "why, in \"words\"";
  r.diagnosis = d;
  return r;
}

// With envelopes the rows get env_<ch>.… and diagnosis.… after the other columns, the evidence as
// lists; a failed row leaves them empty; a writer continued after the header (--resume) writes the
// same lines as the uninterrupted one.
TEST(Sweep, EnvelopeAndDiagnosisColumns) {
  SweepAxis mass;
  mass.key = "rotor.mass";
  const std::vector<SweepAxis> axes = {mass};
  const std::vector<SweepRow> rows = {failed_row(1, "bad"),
                                      envelope_row(2, bearing::FaultFamily::outer),
                                      envelope_row(3, bearing::FaultFamily::none)};
  const std::string csv = bearing::sweep_csv(axes, rows);
  const std::string header = csv.substr(0, csv.find('\n'));
  EXPECT_EQ(header,
            "rotor.mass,status,error,x.rms,x.ptp,x.kurtosis,x.crest,x.peak_frequency,"
            "x.peak_label,env_ax.band_low,env_ax.band_high,env_ax.spectral_kurtosis,"
            "env_ax.energy_fraction,env_ax.peak_frequency,env_ax.peak_amplitude,"
            "env_ax.peak_label,diagnosis.family,diagnosis.channel,diagnosis.spectral_kurtosis,"
            "diagnosis.family_share,diagnosis.evidence_labels,diagnosis.evidence_frequencies,"
            "diagnosis.evidence_amplitudes,diagnosis.reason");
  // 6 channel, 7 envelope and 8 diagnosis fields, empty for the failed row.
  EXPECT_NE(csv.find("\n1,failed,bad" + std::string(21, ',') + "\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",1000,3000,2,,107.5,0.25,BPFO,outer,ax,2,0.75,BPFO;2xBPFO,107.5;215,"
                     "0.25;0.125,\"why, in \"\"words\"\"\"\n"),
            std::string::npos)
      << csv;
  EXPECT_NE(csv.find(",BPFO,none,ax,3,0.75,,,,\"why"), std::string::npos) << csv;

  const bearing::SweepColumns columns = bearing::sweep_columns(header);
  EXPECT_EQ(columns.channels, std::vector<std::string>{"x"});
  EXPECT_EQ(columns.envelopes, std::vector<std::string>{"ax"});
  EXPECT_TRUE(columns.diagnosis);
  EXPECT_EQ(columns.microphones, 0u);
  std::string continued;
  bearing::SweepCsvWriter writer(axes, [&](std::string_view s) { continued.append(s); });
  writer.continue_after(header);
  for (const auto& r : rows) writer.add(r);
  writer.finish();
  EXPECT_EQ(header + "\n" + continued, csv);

  // Without envelopes nothing of this: the columns end with the channels'.
  const std::string plain = bearing::sweep_csv(axes, {ok_row(2)});
  EXPECT_EQ(plain.substr(0, plain.find('\n')),
            "rotor.mass,status,error,x.rms,x.ptp,x.kurtosis,x.crest,x.peak_frequency,"
            "x.peak_label");
}

// Rows reach the sink in case order; while case 0 runs long, the other workers start at most the
// reorder window's cases (4 per worker) and then wait: what is held does not grow with the cases.
TEST(Sweep, RowsInOrderWithABoundedWindow) {
  constexpr std::size_t kCases = 200;
  constexpr int kThreads = 3;
  std::mutex m;
  std::size_t started = 0, started_while_first_ran = 0;
  std::atomic<bool> first_done{false};
  // A case is "loaded" and fails at once (no simulation); case 0 takes 300 ms.
  const bearing::SweepLoader load = [&](const std::vector<bearing::Override>& o) -> bearing::Case {
    const int i = std::stoi(o.at(0).value);
    {
      std::lock_guard<std::mutex> lock(m);
      ++started;
      if (!first_done) started_while_first_ran = started;
    }
    if (i == 0) {
      std::this_thread::sleep_for(std::chrono::milliseconds(300));
      first_done = true;
    }
    throw std::runtime_error("case " + std::to_string(i));
  };
  const auto point = [](std::size_t i) {
    SweepPoint p;
    p.values = {static_cast<double>(i)};
    p.overrides = {{"bearing.balls", std::to_string(i)}};
    return p;
  };
  std::vector<std::size_t> order;
  bearing::run_sweep(load, kCases, point, kThreads, [&](std::size_t i, SweepRow&& row) {
    EXPECT_EQ(row.values.at(0), static_cast<double>(i));
    EXPECT_EQ(row.error, "case " + std::to_string(i));
    order.push_back(i);
  });
  ASSERT_EQ(order.size(), kCases);
  for (std::size_t i = 0; i < kCases; ++i) EXPECT_EQ(order[i], i);
  EXPECT_EQ(started, kCases);
  EXPECT_LE(started_while_first_ran, 4u * kThreads);
  EXPECT_GE(started_while_first_ran, 2u);  // the others did run ahead meanwhile
}

// A sink that fails stops the sweep and its error comes out of run_sweep.
TEST(Sweep, SinkErrorStopsTheSweep) {
  const bearing::SweepLoader load = [](const std::vector<bearing::Override>&) -> bearing::Case {
    throw std::runtime_error("no case");
  };
  const auto point = [](std::size_t i) {
    SweepPoint p;
    p.values = {static_cast<double>(i)};
    return p;
  };
  std::size_t handed = 0;
  EXPECT_THROW(bearing::run_sweep(load, 1000, point, 2,
                                  [&](std::size_t i, SweepRow&&) {
                                    ++handed;
                                    if (i == 5) throw std::runtime_error("disk full");
                                  }),
               std::runtime_error);
  EXPECT_EQ(handed, 6u);
}

// The file is the same for any number of jobs, and only sweep.csv is left in the folder.
TEST(CliSweep, SameFileForAnyJobs) {
  const std::string args =
      "sweep --vary bearing.balls=2:4:3 --vary operation.speed=1000rpm:3000rpm:4 --set "
      "solver.duration=0.05 --set solver.transient=0.01 --quiet --jobs ";
  std::string first;
  for (int jobs : {1, 2, 3}) {
    const fs::path d = fresh_dir("sweep_jobs" + std::to_string(jobs));
    ASSERT_EQ(sim(args + std::to_string(jobs) + " --out " + d.string()), 0);
    const std::string csv = read(d / "sweep.csv");
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 13);
    if (first.empty())
      first = csv;
    else
      EXPECT_EQ(csv, first) << "--jobs " << jobs;
    std::size_t files = 0;
    for (const auto& e : fs::directory_iterator(d)) ++files, (void)e;
    EXPECT_EQ(files, 1u);
  }
}

}  // namespace
