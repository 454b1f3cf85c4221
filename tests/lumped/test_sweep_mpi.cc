// run_sweep_mpi under `mpirun -np 2` (or more): the rows of run_sweep in case order on rank 0, an
// exception from the sink rethrown on rank 0 with every rank returning, and no case handed out
// more than the window ahead of the oldest unfinished one. Every rank runs every test.

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "bearing/sweep.h"
#include "bearing/sweep_mpi.h"

namespace {

using bearing::SweepAxis;
using bearing::SweepPoint;
using bearing::SweepRow;

const std::vector<SweepAxis> kAxes = {bearing::parse_vary("operation.speed=1000rpm:3000rpm:5"),
                                      bearing::parse_vary("bearing.clearance=-10um:20um:4")};

bearing::Case load(const std::vector<bearing::Override>& point) {
  std::vector<bearing::Override> all = {bearing::parse_override("solver.duration=0.02"),
                                        bearing::parse_override("solver.transient=0.005")};
  all.insert(all.end(), point.begin(), point.end());
  return bearing::default_case(all);
}

SweepPoint point(std::size_t i) {
  return bearing::sweep_point(kAxes, i);
}

TEST(SweepMpi, RowsOfRunSweepInCaseOrderOnRankZero) {
  ASSERT_GE(bearing::mpi_size(), 2) << "run under mpirun -np 2 or more";
  const std::size_t cases = bearing::sweep_size(kAxes);
  for (int threads : {1, 2}) {
    std::vector<SweepRow> rows;
    std::vector<std::size_t> order;
    std::size_t last_progress = 0;
    bearing::run_sweep_mpi(
        load, cases, point, threads,
        [&](std::size_t i, SweepRow&& row) {
          order.push_back(i);
          rows.push_back(std::move(row));
        },
        [&](std::size_t done, std::size_t total) {
          EXPECT_EQ(total, cases);
          EXPECT_EQ(done, last_progress + 1);
          last_progress = done;
        });
    if (bearing::mpi_rank() != 0) {
      EXPECT_TRUE(rows.empty());
      EXPECT_EQ(last_progress, 0u);
      continue;
    }
    ASSERT_EQ(order.size(), cases);
    for (std::size_t i = 0; i < cases; ++i) EXPECT_EQ(order[i], i);
    EXPECT_EQ(last_progress, cases);
    const auto serial = bearing::run_sweep(load, bearing::sweep_points(kAxes), 1);
    EXPECT_EQ(bearing::sweep_csv(kAxes, rows), bearing::sweep_csv(kAxes, serial));
    EXPECT_EQ(std::count_if(rows.begin(), rows.end(), [](const SweepRow& r) { return !r.ok; }),
              5);  // clearance −10 µm
  }
}

TEST(SweepMpi, ASinkErrorIsRethrownOnRankZeroAndEveryRankReturns) {
  const std::size_t cases = bearing::sweep_size(kAxes);
  std::size_t handed = 0;
  const auto sink = [&](std::size_t i, SweepRow&&) {
    if (i == 6) throw std::runtime_error("disk full");
    ++handed;
  };
  if (bearing::mpi_rank() == 0) {
    EXPECT_THROW(bearing::run_sweep_mpi(load, cases, point, 1, sink), std::runtime_error);
    EXPECT_EQ(handed, 6u);
  } else {
    EXPECT_NO_THROW(bearing::run_sweep_mpi(load, cases, point, 1, sink));
  }
  // Nothing of that sweep is left in flight: the next one runs normally.
  std::size_t rows = 0;
  bearing::run_sweep_mpi(load, 3, point, 1, [&](std::size_t, SweepRow&&) { ++rows; });
  EXPECT_EQ(rows, bearing::mpi_rank() == 0 ? 3u : 0u);
}

TEST(SweepMpi, NoCaseRunsMoreThanTheWindowAhead) {
  // Case 0 is slow, so every other rank runs ahead until the window stops it.
  const std::size_t cases = 200;
  const auto slow_first = [](std::size_t i) {
    if (i == 0) std::this_thread::sleep_for(std::chrono::milliseconds(300));
    SweepPoint p = bearing::sweep_point(kAxes, i % bearing::sweep_size(kAxes));
    return p;
  };
  int size = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  // Slots: 1 thread on rank 0, 1 thread + 1 case asked ahead on every other rank.
  const std::size_t window = 4 * (1 + 2 * static_cast<std::size_t>(size - 1));
  std::size_t done = 0, ahead = 0;
  bearing::run_sweep_mpi(
      load, cases, slow_first, 1,
      [&](std::size_t i, SweepRow&&) { ahead = std::max(ahead, done - i); },
      [&](std::size_t d, std::size_t) { done = d; });
  if (bearing::mpi_rank() != 0) return;
  EXPECT_EQ(done, cases);
  EXPECT_LE(ahead, window);
  EXPECT_GE(ahead, window / 2);  // the window was reached, not just a short sweep
}

}  // namespace

int main(int argc, char** argv) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  ::testing::InitGoogleTest(&argc, argv);
  const int status = RUN_ALL_TESTS();
  int worst = 0;
  MPI_Allreduce(&status, &worst, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Finalize();
  return worst;
}
