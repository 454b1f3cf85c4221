// sweep.csv with output.envelope_band: each case's envelope figures and diagnosis are those
// `bearing-sim run` of the same case writes in summary.json; the columns survive --resume, --part
// and merge, and a sweep without the envelope analysis has none of them.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_helpers.h"

namespace {

namespace fs = std::filesystem;
using bearing::test::fresh_dir;
using bearing::test::read;
using bearing::test::sim;
using nlohmann::json;

// The fields of one CSV line ("" quoted fields with "" for a quote).
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"')
      out.back() += '"', ++i;
    else if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      out.emplace_back();
    else
      out.back() += c;
  }
  return out;
}

// sweep.csv as one map of column → field per row.
std::vector<std::map<std::string, std::string>> csv_rows(const std::string& text) {
  std::vector<std::string> lines;
  for (std::size_t at = 0, nl; (nl = text.find('\n', at)) != std::string::npos; at = nl + 1)
    lines.push_back(text.substr(at, nl - at));
  std::vector<std::map<std::string, std::string>> rows;
  if (lines.empty()) return rows;
  const auto header = csv_fields(lines.front());
  for (std::size_t r = 1; r < lines.size(); ++r) {
    const auto f = csv_fields(lines[r]);
    EXPECT_EQ(f.size(), header.size()) << lines[r];
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < header.size() && i < f.size(); ++i) row[header[i]] = f[i];
    rows.push_back(row);
  }
  return rows;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  if (s.empty()) return out;
  std::size_t at = 0;
  for (std::size_t p; (p = s.find(sep, at)) != std::string::npos; at = p + 1)
    out.push_back(s.substr(at, p - at));
  out.push_back(s.substr(at));
  return out;
}

// A sweep.csv number: the shortest decimal of the double, so it reads back bit for bit.
double number(const std::string& field) {
  EXPECT_FALSE(field.empty());
  return std::strtod(field.c_str(), nullptr);
}

const std::string kCwru = std::string(BEARING_SOURCE_DIR) + "/examples/cwru_6205_outer.toml";
const std::string kShorter = " --set solver.duration=0.6 --quiet";

// The CWRU-like 6205 with its outer-race spall in the load zone (-90°) and at the top (+90°, where
// no ball is loaded): sweep.csv's envelope columns and diagnosis equal summary.json of `run` of
// each case, bit for bit; the spall under load is named an outer-race fault, the unloaded one not.
TEST(CliSweepEnvelope, EachCaseIsDiagnosedAsItsRun) {
  const fs::path dir = fresh_dir("envelope_cwru");
  ASSERT_EQ(sim("sweep " + kCwru + " --vary defects.0.position=-90deg:90deg:2" + kShorter +
                " --jobs 2 --out " + dir.string()),
            0);
  const auto rows = csv_rows(read(dir / "sweep.csv"));
  ASSERT_EQ(rows.size(), 2u);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& row = rows[i];
    ASSERT_EQ(row.at("status"), "ok") << row.at("error");
    const std::string position = row.at("defects.0.position");
    const fs::path run = fresh_dir("envelope_cwru_run" + std::to_string(i));
    ASSERT_EQ(sim("run " + kCwru + " --set defects.0.position=\"" + position + " rad\"" + kShorter +
                  " --out " + run.string()),
              0);
    const json summary = json::parse(read(run / "summary.json"));
    for (const auto& [channel, e] : summary.at("envelope").items()) {
      const std::string p = "env_" + channel + ".";
      EXPECT_EQ(number(row.at(p + "band_low")), e.at("band").at(0).get<double>());
      EXPECT_EQ(number(row.at(p + "band_high")), e.at("band").at(1).get<double>());
      EXPECT_EQ(number(row.at(p + "spectral_kurtosis")), e.at("spectral_kurtosis").get<double>());
      EXPECT_EQ(number(row.at(p + "energy_fraction")), e.at("energy_fraction").get<double>());
      const json& peak = e.at("peaks").at(0);
      EXPECT_EQ(number(row.at(p + "peak_frequency")), peak.at("frequency").get<double>());
      EXPECT_EQ(number(row.at(p + "peak_amplitude")), peak.at("amplitude").get<double>());
      EXPECT_EQ(row.at(p + "peak_label"), peak.at("label").get<std::string>());
    }
    const json& d = summary.at("diagnosis");
    EXPECT_EQ(row.at("diagnosis.family"), d.at("family").get<std::string>());
    EXPECT_EQ(row.at("diagnosis.channel"), d.at("channel").get<std::string>());
    EXPECT_EQ(number(row.at("diagnosis.spectral_kurtosis")),
              d.at("spectral_kurtosis").get<double>());
    EXPECT_EQ(number(row.at("diagnosis.family_share")), d.at("family_share").get<double>());
    EXPECT_EQ(row.at("diagnosis.reason"), d.at("reason").get<std::string>());
    const auto labels = split(row.at("diagnosis.evidence_labels"), ';');
    const auto frequencies = split(row.at("diagnosis.evidence_frequencies"), ';');
    const auto amplitudes = split(row.at("diagnosis.evidence_amplitudes"), ';');
    const json& evidence = d.at("evidence");
    ASSERT_EQ(labels.size(), evidence.size());
    ASSERT_EQ(frequencies.size(), evidence.size());
    ASSERT_EQ(amplitudes.size(), evidence.size());
    for (std::size_t k = 0; k < evidence.size(); ++k) {
      EXPECT_EQ(labels[k], evidence[k].at("label").get<std::string>());
      EXPECT_EQ(number(frequencies[k]), evidence[k].at("frequency").get<double>());
      EXPECT_EQ(number(amplitudes[k]), evidence[k].at("amplitude").get<double>());
    }
  }
  EXPECT_EQ(rows[0].at("diagnosis.family"), "outer") << rows[0].at("diagnosis.reason");
  EXPECT_FALSE(rows[0].at("diagnosis.evidence_labels").empty());
  EXPECT_EQ(rows[1].at("diagnosis.family"), "none") << rows[1].at("diagnosis.reason");
  EXPECT_EQ(rows[1].at("diagnosis.evidence_labels"), "");
}

const std::string kGrid =
    "sweep --vary operation.speed=1000rpm:3000rpm:5 --vary bearing.clearance=-10um:10um:2 --set "
    "solver.duration=0.05 --set solver.transient=0.01 --set output.envelope_band=auto --quiet";

// Parts merged, and a part resumed from some of its rows, give the whole sweep's bytes; the failed
// cases (negative clearance) leave the envelope columns empty. Without the envelope the columns
// are not there.
TEST(CliSweepEnvelope, PartsResumeAndMergeKeepTheColumns) {
  const fs::path whole = fresh_dir("envelope_whole"), p1 = fresh_dir("envelope_p1"),
                 p2 = fresh_dir("envelope_p2"), merged = fresh_dir("envelope_merged");
  ASSERT_EQ(sim(kGrid + " --jobs 2 --out " + whole.string()), 0);
  const std::string csv = read(whole / "sweep.csv");
  const auto rows = csv_rows(csv);
  ASSERT_EQ(rows.size(), 10u);
  for (const auto& row : rows) {
    ASSERT_TRUE(row.count("env_ay.spectral_kurtosis") && row.count("diagnosis.family")) << csv;
    EXPECT_EQ(row.at("status") == "ok", !row.at("diagnosis.family").empty());
    EXPECT_EQ(row.at("status") == "ok", !row.at("env_ax.band_low").empty());
  }
  ASSERT_EQ(sim(kGrid + " --part 1/2 --out " + p1.string()), 0);
  ASSERT_EQ(sim(kGrid + " --part 2/2 --out " + p2.string()), 0);
  ASSERT_EQ(sim("merge " + merged.string() + " " + p1.string() + " " + p2.string()), 0);
  EXPECT_EQ(read(merged / "sweep.csv"), csv);

  // Part 2 as a kill leaves it: its header, two rows and a torn third; resumed, it is complete.
  const std::string part = read(p2 / "sweep.csv");
  std::size_t cut = 0;
  for (int line = 0; line < 3; ++line) cut = part.find('\n', cut) + 1;
  fs::remove(p2 / "sweep.csv");
  std::ofstream(p2 / ".sweep.csv.partial", std::ios::binary) << part.substr(0, cut + 20);
  std::string out;
  ASSERT_EQ(sim("sweep --resume " + p2.string() + " --quiet", &out), 0) << out;
  EXPECT_EQ(read(p2 / "sweep.csv"), part);

  const fs::path plain = fresh_dir("envelope_plain");
  ASSERT_EQ(sim(kGrid + " --set output.envelope_band=none --out " + plain.string()), 0);
  const std::string text = read(plain / "sweep.csv");
  EXPECT_EQ(text.find("env_"), std::string::npos);
  EXPECT_EQ(text.find("diagnosis."), std::string::npos);
}

}  // namespace
