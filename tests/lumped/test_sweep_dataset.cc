// SweepDataset (sweep.h5 of `bearing-sim sweep --save`) read back with the HDF5 C API: the tables'
// values bit for bit, the attributes of the root, the cases and the tables, the chunking and the
// shuffle + deflate filters, and all-or-nothing (nothing at the final name before close()).

#include <hdf5.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bearing/errors.h"
#include "bearing/sweep_dataset.h"

namespace {

namespace fs = std::filesystem;
using namespace bearing;

// Values whose every bit matters: not round in decimal, with a subnormal and a negative zero.
double value(std::size_t c, std::size_t k, std::size_t seed) {
  if (k == 3 && c == 1) return 4.9e-324;
  if (k == 4 && c == 1) return -0.0;
  return std::sin(0.1 * static_cast<double>(k) + 1.7 * static_cast<double>(c + seed)) / 3.0;
}

Response make_response(std::size_t seed, std::size_t samples) {
  Response r;
  r.channels = {{"x", "m"}, {"y", "m"}, {"ax", "m/s^2"}};
  for (std::size_t k = 0; k < samples; ++k) r.time.push_back(1e-4 * static_cast<double>(k));
  r.values.resize(r.channels.size());
  for (std::size_t c = 0; c < r.channels.size(); ++c)
    for (std::size_t k = 0; k < samples; ++k) r.values[c].push_back(value(c, k, seed));
  r.rate = 1e4;
  return r;
}

RunSummary make_summary(const Response& r, std::size_t seed) {
  RunSummary s;
  for (std::size_t c = 0; c < r.channels.size(); ++c) {
    ChannelSummary ch;
    ch.name = r.channels[c].name;
    ch.unit = r.channels[c].unit;
    ch.statistics.mean = value(c, 10, seed);
    ch.statistics.rms = value(c, 11, seed);
    ch.statistics.ptp = value(c, 12, seed);
    ch.statistics.kurtosis = 3 + value(c, 13, seed);
    ch.statistics.crest = 1.5 + value(c, 14, seed);
    s.channels.push_back(ch);
  }
  s.spectrum_channels = {"x", "ax"};
  for (std::size_t i = 0; i < 2; ++i) {
    Spectrum sp;
    for (std::size_t b = 0; b < 50; ++b) {
      sp.frequency.push_back(2.5 * static_cast<double>(b));
      sp.amplitude.push_back(std::fabs(value(i, b, seed + 7)));
    }
    s.spectra.push_back(sp);
  }
  return s;
}

// A 2-D float64 dataset: its shape and values.
std::vector<double> read_table(hid_t file, const std::string& path, hsize_t dims[2]) {
  const hid_t ds = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  EXPECT_GE(ds, 0) << path;
  const hid_t space = H5Dget_space(ds);
  EXPECT_EQ(H5Sget_simple_extent_ndims(space), 2);
  H5Sget_simple_extent_dims(space, dims, nullptr);
  std::vector<double> v(dims[0] * dims[1]);
  EXPECT_GE(H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), 0);
  const hid_t type = H5Dget_type(ds);
  EXPECT_TRUE(H5Tequal(type, H5T_IEEE_F64LE) > 0);
  H5Tclose(type);
  H5Sclose(space);
  H5Dclose(ds);
  return v;
}

// A string attribute (scalar or array) of the object at `path`.
std::vector<std::string> read_strings(hid_t file, const std::string& path, const char* name) {
  const hid_t a = H5Aopen_by_name(file, path.c_str(), name, H5P_DEFAULT, H5P_DEFAULT);
  EXPECT_GE(a, 0) << path << " @" << name;
  const hid_t space = H5Aget_space(a);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  std::vector<char*> p(static_cast<std::size_t>(n));
  EXPECT_GE(H5Aread(a, type, p.data()), 0);
  std::vector<std::string> out(p.begin(), p.end());
  H5Dvlen_reclaim(type, space, H5P_DEFAULT, p.data());
  H5Tclose(type);
  H5Sclose(space);
  H5Aclose(a);
  return out;
}

template <class T>
std::vector<T> read_numbers(hid_t file, const std::string& path, const char* name, hid_t type) {
  const hid_t a = H5Aopen_by_name(file, path.c_str(), name, H5P_DEFAULT, H5P_DEFAULT);
  EXPECT_GE(a, 0) << path << " @" << name;
  const hid_t space = H5Aget_space(a);
  std::vector<T> v(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  EXPECT_GE(H5Aread(a, type, v.data()), 0);
  H5Sclose(space);
  H5Aclose(a);
  return v;
}

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

class SweepDatasetTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // A folder per test: ctest runs the tests of this program in parallel.
    dir = fs::path(::testing::TempDir()) /
          (std::string("sweep_dataset_") +
           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
    path = dir / "sweep.h5";
  }
  fs::path dir, path;
};

TEST_F(SweepDatasetTest, ThreeCasesReadBackBitForBit) {
  const std::vector<SweepSave> what = {SweepSave::response, SweepSave::spectrum,
                                       SweepSave::envelope, SweepSave::summary};
  const std::size_t samples = 20000;  // > one chunk (256 KiB of 4 columns = 8192 rows)
  {
    SweepDataset d;
    d.open(path.string(), {{"operation.speed", "rad/s"}, {"bearing.balls", ""}}, what, 3);
    for (std::size_t i = 0; i < 3; ++i) {
      const Response r = make_response(i, samples);
      d.add_case(i, {100.0 + i, 8}, "# case " + std::to_string(i) + "\n", r, make_summary(r, i),
                 "{\"case\": " + std::to_string(i) + "}\n");
    }
    d.add_failed_case(3, {104, 8}, "solver blew up");
    EXPECT_FALSE(fs::exists(path)) << "the final name appears only at close()";
    d.close();
  }
  ASSERT_TRUE(fs::exists(path));
  EXPECT_FALSE(fs::exists(dir / ".sweep.h5.partial"));

  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  EXPECT_EQ(read_strings(f, "/", "format"), std::vector<std::string>{"bearing-sim sweep"});
  EXPECT_EQ(read_numbers<long long>(f, "/", "format_version", H5T_NATIVE_LLONG),
            std::vector<long long>{1});
  EXPECT_EQ(read_numbers<long long>(f, "/", "cases", H5T_NATIVE_LLONG), std::vector<long long>{4});
  EXPECT_EQ(read_strings(f, "/", "keys"),
            (std::vector<std::string>{"operation.speed", "bearing.balls"}));
  EXPECT_EQ(read_strings(f, "/", "key_units"), (std::vector<std::string>{"rad/s", ""}));
  EXPECT_EQ(read_strings(f, "/", "saved"),
            (std::vector<std::string>{"response", "spectrum", "envelope", "summary"}));

  for (std::size_t i = 0; i < 3; ++i) {
    const std::string g = "/cases/00000" + std::to_string(i);
    EXPECT_EQ(read_numbers<unsigned long long>(f, g, "index", H5T_NATIVE_ULLONG),
              std::vector<unsigned long long>{i});
    EXPECT_EQ(read_numbers<double>(f, g, "values", H5T_NATIVE_DOUBLE),
              (std::vector<double>{100.0 + i, 8}));
    EXPECT_EQ(read_strings(f, g, "case_toml")[0], "# case " + std::to_string(i) + "\n");
    EXPECT_EQ(read_strings(f, g, "status")[0], "ok");

    const Response r = make_response(i, samples);
    hsize_t dims[2];
    const std::vector<double> a = read_table(f, g + "/response", dims);
    ASSERT_EQ(dims[0], samples);
    ASSERT_EQ(dims[1], 4u);
    std::size_t mismatches = 0;
    for (std::size_t k = 0; k < samples; ++k) {
      mismatches += !same_bits(a[k * 4], r.time[k]);
      for (std::size_t c = 0; c < 3; ++c)
        mismatches += !same_bits(a[k * 4 + 1 + c], r.values[c][k]);
    }
    EXPECT_EQ(mismatches, 0u);
    EXPECT_EQ(read_strings(f, g + "/response", "columns"),
              (std::vector<std::string>{"t", "x", "y", "ax"}));
    EXPECT_EQ(read_strings(f, g + "/response", "units"),
              (std::vector<std::string>{"s", "m", "m", "m/s^2"}));

    const RunSummary s = make_summary(r, i);
    const std::vector<double> sp = read_table(f, g + "/spectrum", dims);
    ASSERT_EQ(dims[0], 50u);
    ASSERT_EQ(dims[1], 3u);
    for (std::size_t b = 0; b < 50; ++b) {
      EXPECT_TRUE(same_bits(sp[b * 3], s.spectra[0].frequency[b]));
      EXPECT_TRUE(same_bits(sp[b * 3 + 2], s.spectra[1].amplitude[b]));
    }
    EXPECT_EQ(read_strings(f, g + "/spectrum", "units"),
              (std::vector<std::string>{"Hz", "m", "m/s^2"}));
    EXPECT_LT(H5Lexists(f, (g + "/envelope").c_str(), H5P_DEFAULT), 1)
        << "no envelope spectra in the case: no envelope table";

    const std::vector<double> sum = read_table(f, g + "/summary", dims);
    ASSERT_EQ(dims[0], 5u);
    ASSERT_EQ(dims[1], 3u);
    EXPECT_TRUE(same_bits(sum[1 * 3 + 2], s.channels[2].statistics.rms));
    EXPECT_TRUE(same_bits(sum[4 * 3 + 0], s.channels[0].statistics.crest));
    EXPECT_EQ(read_strings(f, g + "/summary", "rows"),
              (std::vector<std::string>{"mean", "rms", "ptp", "kurtosis", "crest"}));
    EXPECT_EQ(read_strings(f, g + "/summary", "summary_json")[0],
              "{\"case\": " + std::to_string(i) + "}\n");
  }
  EXPECT_EQ(read_strings(f, "/cases/000003", "status")[0], "failed");
  EXPECT_EQ(read_strings(f, "/cases/000003", "error")[0], "solver blew up");
  H5Fclose(f);
}

TEST_F(SweepDatasetTest, ChunkedWithShuffleAndDeflate) {
  {
    SweepDataset d;
    d.open(path.string(), {}, {SweepSave::response});
    const Response r = make_response(0, 20000);
    d.add_case(0, {}, "", r, RunSummary{}, "");
    d.close();
  }
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  const hid_t ds = H5Dopen2(f, "/cases/000000/response", H5P_DEFAULT);
  ASSERT_GE(ds, 0);
  const hid_t plist = H5Dget_create_plist(ds);
  EXPECT_EQ(H5Pget_layout(plist), H5D_CHUNKED);
  hsize_t chunk[2] = {0, 0};
  EXPECT_EQ(H5Pget_chunk(plist, 2, chunk), 2);
  EXPECT_EQ(chunk[1], 4u) << "whole rows per chunk";
  EXPECT_EQ(chunk[0], 256u * 1024 / (8 * 4));
  std::vector<H5Z_filter_t> filters;
  for (int i = 0; i < H5Pget_nfilters(plist); ++i) {
    unsigned flags = 0, level[1] = {0};
    std::size_t n = 1;
    filters.push_back(
        H5Pget_filter2(plist, static_cast<unsigned>(i), &flags, &n, level, 0, nullptr, nullptr));
    if (filters.back() == H5Z_FILTER_DEFLATE) EXPECT_EQ(level[0], 4u);
  }
  EXPECT_EQ(filters, (std::vector<H5Z_filter_t>{H5Z_FILTER_SHUFFLE, H5Z_FILTER_DEFLATE}));
  // Compressed: the smooth test signal takes well under its raw size.
  EXPECT_LT(H5Dget_storage_size(ds), 20000u * 4 * 8);
  H5Pclose(plist);
  H5Dclose(ds);
  H5Fclose(f);
}

TEST_F(SweepDatasetTest, WithoutCloseNothingIsLeft) {
  {
    SweepDataset d;
    d.open(path.string(), {}, {SweepSave::response});
    d.add_case(0, {}, "", make_response(0, 100), RunSummary{}, "");
    EXPECT_TRUE(fs::exists(dir / ".sweep.h5.partial"));
  }
  EXPECT_FALSE(fs::exists(dir / ".sweep.h5.partial"));
  EXPECT_FALSE(fs::exists(path));
}

TEST_F(SweepDatasetTest, DuplicateCaseIsAnError) {
  SweepDataset d;
  d.open(path.string(), {}, {SweepSave::summary});
  d.add_failed_case(5, {}, "x");
  EXPECT_THROW(d.add_failed_case(5, {}, "x"), InputError);
}

TEST_F(SweepDatasetTest, GroupNamesSortInCaseOrder) {
  SweepDataset d;
  d.open(path.string(), {}, {}, 2000000);
  EXPECT_EQ(d.group_name(42), "0000042");
  SweepDataset small;
  small.open((dir / "other.h5").string(), {}, {});
  EXPECT_EQ(small.group_name(42), "000042");
}

TEST(SweepSave, ParsesCommaListsAndRepeats) {
  EXPECT_EQ(parse_sweep_save({"response,summary", "spectrum", "response"}),
            (std::vector<SweepSave>{SweepSave::response, SweepSave::summary, SweepSave::spectrum}));
  try {
    parse_sweep_save({"response,respons"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--save"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("respons\""), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("envelope"), std::string::npos);
  }
}

}  // namespace
