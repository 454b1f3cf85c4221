// output.format = "npy": every table as a NumPy .npy file (read back here by a small parser of
// the documented format) holding the CSV's values in full precision, columns.json naming its
// columns and units; the default stays CSV and leaves case.toml as before.

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bearing/analysis.h"
#include "bearing/case_file.h"
#include "bearing/errors.h"
#include "bearing/npy.h"
#include "bearing/output.h"
#include "bearing/simulation.h"
#include "cli_helpers.h"

namespace {

namespace fs = std::filesystem;
using bearing::test::fresh_dir;
using bearing::test::kShort;
using bearing::test::read;
using bearing::test::sim;

struct Array {
  std::size_t rows = 0, columns = 0;
  std::vector<double> values;  // row-major
  double at(std::size_t r, std::size_t c) const { return values[r * columns + c]; }
};

// A .npy file as numpy.lib.format documents version 1.0: magic, version, uint16 LE header length,
// a dict literal with descr, fortran_order and shape, padded so that the data is 64-byte aligned.
Array parse_npy(const std::string& bytes) {
  Array a;
  EXPECT_GE(bytes.size(), 10u);
  EXPECT_EQ(bytes.substr(0, 6), std::string("\x93NUMPY", 6));
  EXPECT_EQ(bytes[6], '\x01');
  EXPECT_EQ(bytes[7], '\x00');
  const std::size_t header_len =
      static_cast<unsigned char>(bytes[8]) |
      (static_cast<std::size_t>(static_cast<unsigned char>(bytes[9])) << 8);
  const std::string dict = bytes.substr(10, header_len);
  EXPECT_EQ((10 + header_len) % 64, 0u) << dict;
  EXPECT_EQ(dict.back(), '\n');
  EXPECT_NE(dict.find("'descr': '<f8'"), std::string::npos) << dict;
  EXPECT_NE(dict.find("'fortran_order': False"), std::string::npos) << dict;
  const std::size_t open = dict.find("'shape': (");
  EXPECT_NE(open, std::string::npos) << dict;
  std::istringstream shape(dict.substr(open + 10));
  char comma = 0;
  shape >> a.rows >> comma >> a.columns;
  EXPECT_EQ(comma, ',');
  const std::size_t data = 10 + header_len;
  EXPECT_EQ(bytes.size() - data, a.rows * a.columns * 8);
  a.values.resize(a.rows * a.columns);
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    std::uint64_t bits = 0;
    for (int b = 0; b < 8; ++b)
      bits |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[data + 8 * i + b]))
              << (8 * b);
    std::memcpy(&a.values[i], &bits, 8);
  }
  return a;
}

// A CSV table: its header's names and its rows of numbers.
struct Table {
  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;
};

Table parse_csv(const std::string& text) {
  Table t;
  std::istringstream lines(text);
  std::string line, field;
  std::getline(lines, line);
  for (std::istringstream h(line); std::getline(h, field, ',');) t.names.push_back(field);
  while (std::getline(lines, line)) {
    t.rows.emplace_back();
    for (std::istringstream r(line); std::getline(r, field, ',');)
      t.rows.back().push_back(std::stod(field));
  }
  return t;
}

TEST(NpyOutput, HeaderIsAlignedVersionOne) {
  for (std::size_t rows : {0u, 7u, 24001u, 123456789u}) {
    const std::string h = bearing::npy_header(rows, 7);
    EXPECT_EQ(h.size() % 64, 0u);
    EXPECT_EQ(static_cast<unsigned char>(h[8]) + 256u * static_cast<unsigned char>(h[9]),
              h.size() - 10);
    EXPECT_NE(h.find("'shape': (" + std::to_string(rows) + ", 7), }"), std::string::npos) << h;
  }
  // Three rows of two: 1 … 6 in C order.
  std::string file = bearing::npy_header(3, 2);
  for (int v = 1; v <= 6; ++v) {
    char b[8];
    bearing::store_f8_le(b, v);
    file.append(b, 8);
  }
  const Array a = parse_npy(file);
  ASSERT_EQ(a.rows, 3u);
  ASSERT_EQ(a.columns, 2u);
  EXPECT_EQ(a.at(1, 0), 3.0);
  EXPECT_EQ(a.at(2, 1), 6.0);
}

// Every table of a run with acoustics and envelope analysis: the .npy holds the CSV's numbers to
// the CSV's 12 digits (1e-11 relative), with the CSV's column names in columns.json.
TEST(NpyOutput, TablesEqualTheCsvValues) {
  const std::string extra =
      kShort + " --set 'acoustics.microphones=[[\"0.1 m\", \"0 deg\"]]'" +
      " --set 'output.envelope_band=[\"2 kHz\", \"8 kHz\"]' --set output.ball_loads=true";
  const fs::path csv = fresh_dir("npy_csv"), npy = fresh_dir("npy_npy");
  ASSERT_EQ(sim("run --out " + csv.string() + extra), 0);
  ASSERT_EQ(sim("run --out " + npy.string() + extra + " --set output.format=npy"), 0);
  EXPECT_EQ(read(npy / "summary.json"), read(csv / "summary.json"));
  const auto columns = nlohmann::json::parse(read(npy / "columns.json"));
  for (const char* stem : {"response", "spectrum", "pressure", "envelope"}) {
    SCOPED_TRACE(stem);
    const std::string file = std::string(stem) + ".npy";
    EXPECT_FALSE(fs::exists(npy / (std::string(stem) + ".csv")));
    const Table t = parse_csv(read(csv / (std::string(stem) + ".csv")));
    const Array a = parse_npy(read(npy / file));
    const auto& meta = columns["tables"][file];
    ASSERT_EQ(meta["columns"].get<std::vector<std::string>>(), t.names);
    ASSERT_EQ(meta["units"].size(), t.names.size());
    ASSERT_EQ(meta["shape"][0].get<std::size_t>(), t.rows.size());
    ASSERT_EQ(a.rows, t.rows.size());
    ASSERT_EQ(a.columns, t.names.size());
    std::size_t worse = 0;
    for (std::size_t r = 0; r < a.rows; ++r)
      for (std::size_t c = 0; c < a.columns; ++c)
        if (!(std::fabs(a.at(r, c) - t.rows[r][c]) <= 1e-11 * std::fabs(t.rows[r][c]))) ++worse;
    EXPECT_EQ(worse, 0u);
  }
  EXPECT_EQ(columns["tables"]["response.npy"]["units"][0], "s");
  EXPECT_EQ(columns["tables"]["response.npy"]["units"][6], "m/s^2");  // ay
  EXPECT_EQ(columns["tables"]["response.npy"]["units"][7], "N");      // Q1
  EXPECT_EQ(columns["tables"]["pressure.npy"]["units"][1], "Pa");
  EXPECT_EQ(columns["tables"]["spectrum.npy"]["units"][0], "Hz");
  // The resolved case says npy and repeats the run bit for bit; a csv case.toml does not name it.
  EXPECT_NE(read(npy / "case.toml").find("format = \"npy\""), std::string::npos);
  EXPECT_EQ(read(csv / "case.toml").find("format"), std::string::npos);
  const fs::path again = fresh_dir("npy_again");
  ASSERT_EQ(sim("run " + (npy / "case.toml").string() + " --out " + again.string() + " --quiet"),
            0);
  EXPECT_EQ(read(again / "response.npy"), read(npy / "response.npy"));
  // A csv run into the npy folder leaves none of the npy files behind, and the other way round.
  ASSERT_EQ(sim("run --out " + npy.string() + kShort), 0);
  for (const char* f : {"response.npy", "spectrum.npy", "pressure.npy", "columns.json"})
    EXPECT_FALSE(fs::exists(npy / f)) << f;
  ASSERT_EQ(sim("run --out " + csv.string() + kShort + " --set output.format=npy"), 0);
  for (const char* f : {"response.csv", "spectrum.csv", "pressure.csv", "envelope.csv"})
    EXPECT_FALSE(fs::exists(csv / f)) << f;
}

// A bad format names the key, the value and the allowed ones; nothing is written.
TEST(NpyOutput, UnknownFormatIsAnError) {
  const fs::path d = fresh_dir("npy_bad");
  std::string out;
  EXPECT_EQ(sim("run --out " + d.string() + kShort + " --set output.format=npz", &out), 2);
  EXPECT_NE(out.find("output.format = \"npz\""), std::string::npos) << out;
  EXPECT_NE(out.find("allowed: csv, npy"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(d));
}

// A file that cannot be written (here the last one, columns.json, whose temporary name is taken
// by a folder) stops an npy run with a write error (exit 3): the earlier run's files stay as they
// were and no temporary file is left.
TEST(NpyOutput, AllOrNothing) {
  const fs::path d = fresh_dir("npy_all_or_nothing");
  ASSERT_EQ(sim("run --out " + d.string() + kShort + " --set output.format=npy"), 0);
  const std::string before = read(d / "response.npy");
  fs::create_directory(d / ".columns.json.partial");
  std::string out;
  EXPECT_EQ(sim("run --out " + d.string() + kShort +
                    " --set output.format=npy --set operation.speed=\"3000 rpm\"",
                &out),
            3);
  EXPECT_NE(out.find("cannot write"), std::string::npos) << out;
  EXPECT_EQ(read(d / "response.npy"), before);
  for (const auto& e : fs::directory_iterator(d))
    EXPECT_EQ(e.path().filename().string().find(".partial"), std::string::npos)
        << e.path().filename();
}

// A non-finite value never reaches a result file: the writer refuses the whole set (SolverError,
// exit 3 in bearing-sim, naming the column) in either format, and an earlier result stays.
TEST(NpyOutput, ANonFiniteValueWritesNoFile) {
  for (const char* format : {"csv", "npy"}) {
    const bearing::Case c =
        bearing::default_case({bearing::parse_override("solver.duration=0.05"),
                               bearing::parse_override("solver.transient=0.01"),
                               bearing::parse_override(std::string("output.format=") + format)});
    bearing::SimulationResult r = bearing::simulate(c);
    const bearing::RunSummary s = bearing::summarize(c, r);
    const fs::path d = fresh_dir(std::string("non_finite_") + format);
    bearing::write_run(d.string(), c, r, s);
    const std::string response = std::string("response.") + format;
    const std::string before = read(d / response);
    r.response.values[r.response.index("y")][7] = std::nan("");
    try {
      bearing::write_run(d.string(), c, r, s);
      ADD_FAILURE() << format << ": a NaN was written";
    } catch (const bearing::SolverError& e) {
      EXPECT_NE(std::string(e.what()).find("not finite"), std::string::npos) << e.what();
    }
    EXPECT_EQ(read(d / response), before) << format;
    for (const auto& e : fs::directory_iterator(d))
      EXPECT_EQ(e.path().filename().string().find(".partial"), std::string::npos)
          << e.path().filename();
  }
}

}  // namespace
