// Measured records (records layer, issue 29): units to SI, the rules of rate and unit that
// finish_record applies for every format, the time-column rate, the choice of channel, the
// registry of formats, and the .npy parser on bytes built here by hand from numpy's format
// description. The readers against files other tools write: tests/records/check_readers.py.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/records/channel_choice.h"
#include "bearing/records/npy_record.h"
#include "bearing/records/raw_channel.h"
#include "bearing/records/record_formats.h"
#include "bearing/records/time_column.h"

namespace bearing {
namespace {

// The message of the InputError `f` throws ("" if it throws none).
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

RawChannel raw_of(std::vector<double> values) {
  RawChannel raw;
  raw.channel = "DE";
  raw.values = std::move(values);
  return raw;
}

TEST(RecordUnits, EachUnitItsQuantityAndFactor) {
  EXPECT_EQ(quantity_of(RecordUnit::g), MeasuredQuantity::acceleration);
  EXPECT_EQ(quantity_of(RecordUnit::m_per_s2), MeasuredQuantity::acceleration);
  EXPECT_EQ(quantity_of(RecordUnit::m_per_s), MeasuredQuantity::velocity);
  EXPECT_EQ(quantity_of(RecordUnit::m), MeasuredQuantity::displacement);
  EXPECT_EQ(si_factor(RecordUnit::g), 9.80665);  // standard gravity, exactly as defined
  EXPECT_EQ(si_factor(RecordUnit::m_per_s), 1.0);
  EXPECT_EQ(find_record_unit("m/s2"), RecordUnit::m_per_s2);
  EXPECT_EQ(find_record_unit("m/s\xC2\xB2"), RecordUnit::m_per_s2);
  EXPECT_FALSE(find_record_unit("G").has_value());  // g is not giga: case matters
  EXPECT_FALSE(find_record_unit("mm/s").has_value());
}

TEST(FinishRecord, ConvertsOnceToSiWithScaleThenUnit) {
  RecordOptions o;
  o.rate = 12000;
  o.unit = "g";
  o.scale = 50;
  const MeasuredRecord r = finish_record(raw_of({0.5, -0.25}), o, "a.npy");
  ASSERT_EQ(r.samples.size(), 2u);
  EXPECT_EQ(r.samples[0], 0.5 * 50 * 9.80665);
  EXPECT_EQ(r.samples[1], -0.25 * 50 * 9.80665);
  EXPECT_EQ(r.quantity, MeasuredQuantity::acceleration);
  EXPECT_EQ(r.rate, 12000);
  EXPECT_EQ(r.rate_source, RecordSource::option);
  EXPECT_EQ(r.unit_source, RecordSource::option);
  EXPECT_DOUBLE_EQ(r.duration(), 2.0 / 12000);
}

TEST(FinishRecord, TheFilesRateAndUnitWhenNoOptionGivesThem) {
  RawChannel raw = raw_of({1, 2, 3});
  raw.rate = 25600;
  raw.rate_origin = "the WAV header";
  raw.unit = "m/s";
  raw.unit_origin = "the header of column DE";
  const MeasuredRecord r = finish_record(raw, RecordOptions{}, "a.csv");
  EXPECT_EQ(r.rate, 25600);
  EXPECT_EQ(r.rate_source, RecordSource::file);
  EXPECT_EQ(r.rate_origin, "the WAV header");
  EXPECT_EQ(r.quantity, MeasuredQuantity::velocity);
  EXPECT_EQ(r.unit_source, RecordSource::file);
  EXPECT_EQ(r.samples, (std::vector<double>{1, 2, 3}));
}

TEST(FinishRecord, EachInputErrorNamesFileChannelAndProblem) {
  RecordOptions ok;
  ok.rate = 1000;
  ok.unit = "m";
  const auto error = [&](RawChannel raw, RecordOptions o) {
    return input_error([&] { finish_record(raw, o, "rec.npy"); });
  };
  EXPECT_EQ(error(raw_of({}), ok), "rec.npy: channel DE: no samples");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(error(raw_of({0, 1, nan}), ok), "rec.npy: channel DE: sample 2 (from 0) is NaN");
  EXPECT_EQ(error(raw_of({-inf}), ok), "rec.npy: channel DE: sample 0 (from 0) is -Inf");
  RecordOptions big = ok;
  big.unit = "g";
  EXPECT_NE(error(raw_of({1, 1e308}), big).find("sample 1 (from 0) = 1e+308 overflows in SI"),
            std::string::npos);

  RecordOptions no_rate = ok;
  no_rate.rate.reset();
  EXPECT_EQ(error(raw_of({1}), no_rate),
            "rec.npy: channel DE: no sampling rate: the file does not state one; give --rate in "
            "Hz");
  RecordOptions no_unit = ok;
  no_unit.unit.clear();
  EXPECT_EQ(error(raw_of({1}), no_unit),
            "rec.npy: channel DE: no unit: the file does not state one; give --unit (g, m/s^2, "
            "m/s, m)");
  RecordOptions furlong = ok;
  furlong.unit = "furlong";
  EXPECT_EQ(error(raw_of({1}), furlong),
            "rec.npy: channel DE: --unit: unknown unit \"furlong\"; allowed g, m/s^2, m/s, m");
  for (const double bad : {0.0, -5.0, nan, inf}) {
    RecordOptions r = ok;
    r.rate = bad;
    EXPECT_NE(error(raw_of({1}), r).find("--rate"), std::string::npos) << bad;
    EXPECT_NE(error(raw_of({1}), r).find("must be a finite rate > 0 Hz"), std::string::npos);
  }
  RecordOptions zero_scale = ok;
  zero_scale.scale = 0;
  EXPECT_NE(error(raw_of({1}), zero_scale).find("--scale 0: must be finite and nonzero"),
            std::string::npos);
}

TEST(FinishRecord, AnOptionTheFileContradictsIsAnError) {
  RawChannel raw = raw_of({1, 2});
  raw.rate = 8000;
  raw.rate_origin = "the WAV header";
  raw.unit = "g";
  raw.unit_origin = "the header of column DE";
  RecordOptions o;
  o.rate = 8001;
  EXPECT_EQ(input_error([&] { finish_record(raw, o, "x.wav"); }),
            "x.wav: channel DE: --rate 8001 Hz contradicts the rate 8000 Hz of the WAV header");
  o.rate = 8000;  // agrees: taken, from the option
  EXPECT_EQ(finish_record(raw, o, "x.wav").rate_source, RecordSource::option);
  o.unit = "m/s^2";
  EXPECT_EQ(input_error([&] { finish_record(raw, o, "x.wav"); }),
            "x.wav: channel DE: --unit m/s^2 contradicts the file's unit g (the header of "
            "column DE)");
  o.unit = "g";
  EXPECT_EQ(finish_record(raw, o, "x.wav").samples[1], 2 * 9.80665);
  // A rate known only to some digits agrees within its tolerance, and only within it.
  raw.rate = 12000.0;
  raw.rate_tolerance = 1e-4;
  o.rate = 12000.0 * (1 + 0.9e-4);
  EXPECT_EQ(finish_record(raw, o, "x.wav").rate, *o.rate);
  o.rate = 12000.0 * (1 + 1.1e-4);
  EXPECT_NE(input_error([&] { finish_record(raw, o, "x.wav"); }), "");
}

TEST(RecordError, OneLineWhateverTheNamesHold) {
  const std::string m = record_error("a\nb.csv", "x\ry", "bad").what();
  EXPECT_EQ(m, "a\\x0ab.csv: channel x\\x0dy: bad");
}

TEST(TimeColumn, UniformTimesGiveTheirRateAndPrecision) {
  // 12 kHz written with 6 decimals, as a logger would: each time off by up to 0.5e-6 s; the
  // first written "0", whose precision (1) must not loosen the grid.
  std::vector<double> t{0}, q{1};
  for (int i = 1; i < 1200; ++i) {
    t.push_back(std::round(i / 12000.0 * 1e6) / 1e6);
    q.push_back(1e-6);
  }
  const TimeColumnRate r = time_column_rate(t, q, "f.csv", "DE", "t");
  // The rounding moves the fitted step by far less than the allowance.
  EXPECT_NEAR(r.rate, 12000, 12000 * r.tolerance);
  // The allowance: the column's precision (its finest, 1e-6) + 1 % of a step, over the span.
  const double span = t.back() - t.front();
  EXPECT_NEAR(r.tolerance, (1e-6 + 0.01 / r.rate) / span, 1e-12);
  // One time 0.2e-6 s further off than its allowance (0.5e-6 + 0.5e-6 + 0.83e-6 s): refused.
  std::vector<double> off = t;
  off[600] += 0.5e-6 + 0.5e-6 + 0.01 / 12000 + 0.2e-6;
  EXPECT_NE(input_error([&] {
              time_column_rate(off, q, "f.csv", "DE", "t");
            }).find("not uniform at sample 600 (from 0)"),
            std::string::npos);
}

TEST(TimeColumn, RefusesTimesOffTheGridOrNotIncreasing) {
  // Written with 5 decimals ("0.00310"): half a last digit (5e-6) + half the column's precision
  // (5e-6) + 1 % of a step (1e-5) = 2e-5 s allowed around the grid.
  std::vector<double> t{0, 0.001, 0.002, 0.0031, 0.004};
  const std::vector<double> q(t.size(), 1e-5);
  EXPECT_NE(input_error([&] {
              time_column_rate(t, q, "f.csv", "DE", "t");
            }).find("f.csv: channel DE: time column t: not uniform at sample 3 (from 0)"),
            std::string::npos);
  t[3] = 0.00301;  // 7e-6 s off the fitted line (step 1.001 ms): inside 2e-5 s
  EXPECT_NO_THROW(time_column_rate(t, q, "f.csv", "DE", "t"));
  EXPECT_NE(input_error([&] {
              time_column_rate({1, 0}, {0, 0}, "f.csv", "DE", "t");
            }).find("the times must increase"),
            std::string::npos);
  EXPECT_NE(
      input_error([&] { time_column_rate({1}, {0}, "f.csv", "DE", "t"); }).find("at least 2 times"),
      std::string::npos);
  EXPECT_TRUE(is_time_column_name("Time"));
  EXPECT_TRUE(is_time_column_name("t"));
  EXPECT_FALSE(is_time_column_name("time_s"));
}

TEST(ChannelChoice, TheOnlyOneTheNamedOneOrAnErrorListingThem) {
  RecordOptions o;
  EXPECT_EQ(choose_channel({"a"}, o, "f", "column"), 0u);
  EXPECT_EQ(input_error([&] {
              choose_channel({"a", "b"}, o, "f", "variable");
            }),
            "f: 2 variables (a, b): choose one with --channel");
  EXPECT_EQ(input_error([&] { choose_channel({}, o, "f", "column", "t (time)"); }),
            "f: no column to read; not channels: t (time)");
  o.channel = "b";
  EXPECT_EQ(choose_channel({"a", "b"}, o, "f", "column"), 1u);
  o.channel = "c";
  EXPECT_EQ(input_error([&] {
              choose_channel({"a", "b"}, o, "f", "variable", "cRPM (scalar)");
            }),
            "f: channel c: no such variable; the file has a, b; not channels: cRPM (scalar)");
}

TEST(RecordFormats, TheExtensionPicksTheRowAndUnknownOnesAreListed) {
  const std::vector<RecordFormat> base = base_record_formats();
  RecordOptions o;
  const std::string unsupported = input_error([&] { read_record("data/rec.txt", o, base); });
  EXPECT_EQ(unsupported.rfind("data/rec.txt: unsupported extension \".txt\"; supported: .csv, "
                              ".npy, .wav, .mat, .h5, .hdf5",
                              0),
            0u)
      << unsupported;
  // A row without a reader says why, naming its extension.
  const std::vector<RecordFormat> rows{{".mat", "MATLAB", nullptr,
                                        "this build cannot read .mat: libmatio-dev was not "
                                        "found at build time",
                                        false}};
  EXPECT_EQ(input_error([&] { read_record("x.MAT", o, rows); }),
            "x.MAT: this build cannot read .mat: libmatio-dev was not found at build time");
  // with_formats: a row of the same extension replaces the base's, others are appended.
  const auto reader = [](const std::filesystem::path&, const RecordOptions&) {
    return raw_of({1, 2});
  };
  const std::vector<RecordFormat> merged =
      with_formats(base, {{".mat", "m", +reader, "", false}, {".xyz", "x", +reader, "", false}});
  EXPECT_EQ(merged.size(), base.size() + 1);
  o.rate = 10;
  o.unit = "m";
  EXPECT_EQ(read_record("r.mat", o, merged).samples, (std::vector<double>{1, 2}));
  EXPECT_EQ(read_record("r.XYZ", o, merged).channel, "DE");
  o.dataset = "/a";
  EXPECT_EQ(input_error([&] { read_record("r.mat", o, merged); }),
            "r.mat: --dataset /a applies to HDF5 files only, not .mat");
}

// A .npy built byte by byte as numpy.lib.format describes version 1.0.
std::string npy(const std::string& dict, const std::string& data, int version = 1) {
  std::string header = dict;
  const std::size_t prefix = version == 1 ? 10 : 12;
  while ((prefix + header.size() + 1) % 64) header += ' ';
  header += '\n';
  std::string out("\x93NUMPY", 6);
  out += static_cast<char>(version);
  out += '\0';
  for (std::size_t k = 0; k < (version == 1 ? 2u : 4u); ++k)
    out += static_cast<char>((header.size() >> (8 * k)) & 0xff);
  return out + header + data;
}

std::string bytes_of(const std::vector<double>& v, bool big = false) {
  std::string out;
  for (const double d : v) {
    char b[8];
    std::memcpy(b, &d, 8);  // the host is little-endian (x86-64, as the tests run)
    if (big) std::reverse(b, b + 8);
    out.append(b, 8);
  }
  return out;
}

TEST(NpyRecord, OneAndTwoDimensionsBothOrdersAndByteOrders) {
  const std::vector<double> v{1.5, -2.25, 1e-310, 3.0};
  RecordOptions o;
  EXPECT_EQ(
      parse_npy_record(
          npy("{'descr': '<f8', 'fortran_order': False, 'shape': (4,), }", bytes_of(v)), "a.npy", o)
          .values,
      v);
  EXPECT_EQ(parse_npy_record(npy("{'descr': '>f8', 'fortran_order': False, 'shape': (4,), }",
                                 bytes_of(v, true), 2),
                             "a.npy", o)
                .values,
            v);
  // (2, 2) in C order: rows (1.5, -2.25), (1e-310, 3); column 1 is (-2.25, 3).
  o.channel = "1";
  EXPECT_EQ(parse_npy_record(
                npy("{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2), }", bytes_of(v)),
                "a.npy", o)
                .values,
            (std::vector<double>{-2.25, 3.0}));
  // The same bytes in Fortran order: column 1 is (1e-310, 3).
  EXPECT_EQ(parse_npy_record(
                npy("{'descr': '<f8', 'fortran_order': True, 'shape': (2, 2), }", bytes_of(v)),
                "a.npy", o)
                .values,
            (std::vector<double>{1e-310, 3.0}));
  const float f[2] = {0.1f, -7.5f};
  RecordOptions one;
  EXPECT_EQ(parse_npy_record(npy("{'descr': '<f4', 'fortran_order': False, 'shape': (1, 2), }",
                                 std::string(reinterpret_cast<const char*>(f), 8)),
                             "a.npy", one)
                .values,
            (std::vector<double>{0.1f, -7.5f}));
}

TEST(NpyRecord, BadFilesAreInputErrorsNamingTheFile) {
  RecordOptions o;
  const auto error = [&](const std::string& bytes) {
    return input_error([&] { parse_npy_record(bytes, "b.npy", o); });
  };
  EXPECT_EQ(error("hello"), "b.npy: not a .npy file numpy writes: no \\x93NUMPY magic");
  EXPECT_EQ(error(npy("{'descr': '<i2', 'fortran_order': False, 'shape': (1,), }", "ab")),
            "b.npy: dtype '<i2': allowed float32 or float64 ('<f4', '<f8', '>f4', '>f8')");
  EXPECT_NE(
      error(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (3,), }", bytes_of({1, 2})))
          .find("the data is cut short"),
      std::string::npos);
  EXPECT_NE(
      error(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (1,), }", bytes_of({1, 2})))
          .find("8 bytes after the array"),
      std::string::npos);
  EXPECT_NE(
      error(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (1, 1, 1), }", bytes_of({1})))
          .find("an array of 3 dimensions"),
      std::string::npos);
  EXPECT_NE(error(npy("{'descr': '<f8', 'fortran_order': False, 'shape': "
                      "(99999999999999999999,), }",
                      ""))
                .find("a dimension overflows"),
            std::string::npos);
  // A shape whose product overflows is "cut short", never a huge allocation.
  EXPECT_NE(error(npy("{'descr': '<f8', 'fortran_order': False, 'shape': "
                      "(4294967296, 4294967296), }",
                      ""))
                .find("cut short"),
            std::string::npos);
  o.channel = "2";
  EXPECT_EQ(
      error(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (1, 2), }", bytes_of({1, 2}))),
      "b.npy: channel 2: no such column; the file has 0");
}

}  // namespace
}  // namespace bearing
