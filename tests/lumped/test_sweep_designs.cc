// The designs of a sweep: random cases drawn from (seed, case, key) alone, list files, parts that
// tile the design, and the errors that name the option.

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "bearing/errors.h"
#include "bearing/sweep.h"

namespace {

namespace fs = std::filesystem;
using bearing::InputError;

// Case i's value of a key depends on the seed, i and the key only: not on the other keys, the
// number of cases or the order points are asked for.
TEST(SweepDesign, RandomValueDependsOnSeedCaseAndKeyOnly) {
  const auto speed = bearing::parse_sample("operation.speed=uniform(1000rpm, 3000rpm)");
  const auto clearance = bearing::parse_sample("bearing.clearance=normal(10um, 2um)");
  const auto both = bearing::random_design({speed, clearance}, 100, 7);
  const auto alone = bearing::random_design({speed}, 1000, 7);
  for (std::size_t i : {99u, 0u, 42u}) {
    const auto p = both->point(i);
    EXPECT_EQ(p.values[0], alone->point(i).values[0]);
    EXPECT_EQ(p.values, both->point(i).values);
    EXPECT_GE(p.values[0], 1000 * 2 * M_PI / 60);
    EXPECT_LE(p.values[0], 3000 * 2 * M_PI / 60);
  }
  EXPECT_NE(both->point(3).values,
            bearing::random_design({speed, clearance}, 100, 8)->point(3).values);
  // The JSON record rebuilds the same design.
  const auto back = bearing::design_from_json(both->json());
  EXPECT_EQ(back->size(), 100u);
  for (std::size_t i = 0; i < 100; ++i) EXPECT_EQ(back->point(i).values, both->point(i).values);
}

TEST(SweepDesign, RandomDistributions) {
  const auto n = bearing::random_design(
      {bearing::parse_sample("bearing.clearance=normal(10um, 2um)")}, 20000, 1);
  double sum = 0, sum2 = 0;
  for (std::size_t i = 0; i < n->size(); ++i) {
    const double v = n->point(i).values[0];
    sum += v, sum2 += v * v;
  }
  const double mean = sum / 20000, sd = std::sqrt(sum2 / 20000 - mean * mean);
  EXPECT_NEAR(mean, 10e-6, 0.05e-6);
  EXPECT_NEAR(sd, 2e-6, 0.05e-6);
  const auto lu = bearing::random_design(
      {bearing::parse_sample("operation.axial_load=loguniform(1 N, 1 kN)")}, 20000, 1);
  std::size_t below = 0;  // log-uniform: half the values below the geometric mean (31.6 N)
  for (std::size_t i = 0; i < lu->size(); ++i) below += lu->point(i).values[0] < std::sqrt(1e3);
  EXPECT_NEAR(static_cast<double>(below) / 20000, 0.5, 0.02);
  const auto balls =
      bearing::random_design({bearing::parse_sample("bearing.balls=uniform(7, 9)")}, 3000, 1);
  std::set<double> seen;
  for (std::size_t i = 0; i < balls->size(); ++i) seen.insert(balls->point(i).values[0]);
  EXPECT_EQ(seen, (std::set<double>{7, 8, 9}));
  EXPECT_EQ(balls->point(0).overrides[0].value.find('.'), std::string::npos);
}

TEST(SweepDesign, SampleErrorsNameTheOptionAndWhatIsAllowed) {
  for (const char* bad :
       {"operation.speed=uniform(1000rpm)", "operation.speed=gauss(1, 2)",
        "operation.speed=uniform(3000rpm, 1000rpm)", "operation.axial_load=loguniform(0, 1)",
        "model.kind=uniform(1, 2)", "operation.speed=uniform(1 kg, 2 kg)",
        "bearing.clearance=normal(1um, -1um)"}) {
    try {
      bearing::parse_sample(bad);
      ADD_FAILURE() << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("--sample"), std::string::npos) << e.what();
    }
  }
}

TEST(SweepDesign, ListFromCsvWithUnits) {
  const fs::path f = fs::path(::testing::TempDir()) / "cases.csv";
  std::ofstream(f) << "operation.speed, bearing.clearance,bearing.balls\n"
                      "1000 rpm, 10um, 8\n\n"
                      "104.72 rad/s, 1e-5, 9\n";
  const auto d = bearing::list_design_from_csv(f.string());
  ASSERT_EQ(d->size(), 2u);
  EXPECT_NEAR(d->point(0).values[0], 1000 * 2 * M_PI / 60, 1e-12);
  EXPECT_EQ(d->point(0).values[1], 10e-6);
  EXPECT_EQ(d->point(1).values, (std::vector<double>{104.72, 1e-5, 9}));
  EXPECT_EQ(d->keys()[1].key, "bearing.clearance");
  std::ofstream(f) << "operation.speed,bearing.balls\n1000rpm,8.5\n";
  try {
    bearing::list_design_from_csv(f.string());
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bearing.balls"), std::string::npos) << e.what();
  }
  std::ofstream(f) << "operation.speed,bearing.balls\n1000rpm\n";
  EXPECT_THROW(bearing::list_design_from_csv(f.string()), InputError);
  std::ofstream(f) << "operation.sped\n1000rpm\n";
  EXPECT_THROW(bearing::list_design_from_csv(f.string()), InputError);
}

// The parts 1 … N of a design are contiguous and cover it once.
TEST(SweepDesign, PartsTileTheDesign) {
  for (std::size_t cases : {0u, 1u, 7u, 1000u, 1000003u})
    for (std::size_t n : {1u, 2u, 3u, 16u, 100u}) {
      std::size_t at = 0;
      for (std::size_t k = 1; k <= n; ++k) {
        const auto [first, end] = bearing::part_range(cases, {k, n});
        EXPECT_EQ(first, at);
        EXPECT_LE(end - first, cases / n + 1);
        at = end;
      }
      EXPECT_EQ(at, cases);
    }
  EXPECT_EQ(bearing::parse_part("3/16").index, 3u);
  for (const char* bad : {"0/4", "5/4", "3", "a/4", "1/0", "2/3x"})
    EXPECT_THROW(bearing::parse_part(bad), InputError) << bad;
}

TEST(SweepDesign, MorePartsThanCasesIsAnInputError) {
  bearing::SweepPlan plan;
  std::vector<bearing::SweepAxis> axes = {bearing::parse_vary("operation.speed=1000rpm:2000rpm:3")};
  plan.design = bearing::grid_design(std::move(axes));
  plan.base = bearing::sweep_base("", {{"solver.duration", "0.01 s"}, {"solver.transient", "0 s"}});
  plan.part = bearing::parse_part("2/4");
  const auto dir = std::filesystem::temp_directory_path() / "bearing_sweep_parts_check";
  std::filesystem::remove_all(dir);
  try {
    bearing::write_sweep(dir.string(), plan, 1);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--part 2/4"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("3 cases"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir));  // checked before anything is written
  std::filesystem::remove_all(dir);
}

}  // namespace
