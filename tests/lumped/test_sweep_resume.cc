// bearing-sim sweep end to end for the designs beyond the grid: --sample and --cases, --resume
// after a SIGKILL, --part and merge; each compared byte for byte with one uninterrupted run.

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "cli_helpers.h"

extern char** environ;

namespace {

namespace fs = std::filesystem;
using bearing::test::fresh_dir;
using bearing::test::read;
using bearing::test::sim;

const std::string kQuick = " --set solver.duration=0.05 --set solver.transient=0.01 --quiet";
const std::string kRandom =
    "sweep --sample \"operation.speed=uniform(1000rpm, 3000rpm)\" --sample "
    "\"bearing.clearance=normal(10um, 3e-6)\" --sample \"bearing.balls=uniform(2, 9)\" "
    "--samples 40" +
    kQuick;

std::size_t lines(const std::string& s) {
  return std::count(s.begin(), s.end(), '\n');
}

// The same seed gives the same file on any --jobs; another seed another one.
TEST(CliSweepDesigns, RandomDesignReproducibleFromItsSeed) {
  const fs::path a = fresh_dir("rand_a"), b = fresh_dir("rand_b"), c = fresh_dir("rand_c");
  ASSERT_EQ(sim(kRandom + " --seed 11 --jobs 1 --out " + a.string()), 0);
  ASSERT_EQ(sim(kRandom + " --seed 11 --jobs 3 --out " + b.string()), 0);
  EXPECT_EQ(lines(read(a / "sweep.csv")), 41u);
  EXPECT_EQ(read(a / "sweep.csv"), read(b / "sweep.csv"));
  EXPECT_EQ(read(a / "sweep.csv").find("operation.speed,bearing.clearance,bearing.balls,status"),
            0u);
  ASSERT_EQ(sim(kRandom + " --seed 12 --out " + c.string()), 0);
  EXPECT_NE(read(a / "sweep.csv"), read(c / "sweep.csv"));
  std::string out;
  EXPECT_EQ(sim("sweep --vary bearing.balls=7:9:3 --sample \"operation.speed=uniform(1rpm, 2rpm)\" "
                "--samples 2 --out " +
                    c.string(),
                &out),
            2);
  EXPECT_NE(out.find("do not mix"), std::string::npos) << out;
}

// A list file with the grid's points gives the grid's file.
TEST(CliSweepDesigns, ListDesignEqualsTheSameGrid) {
  const fs::path g = fresh_dir("list_grid"), l = fresh_dir("list_list");
  const fs::path f = fs::path(::testing::TempDir()) / "list_cases.csv";
  std::ofstream(f) << "bearing.balls,bearing.clearance\n7,0um\n7,10um\n8,0\n8,1e-05\n";
  ASSERT_EQ(sim("sweep --vary bearing.balls=7:8:2 --vary bearing.clearance=0um:10um:2" + kQuick +
                " --out " + g.string()),
            0);
  ASSERT_EQ(sim("sweep --cases " + f.string() + kQuick + " --out " + l.string()), 0);
  EXPECT_EQ(read(g / "sweep.csv"), read(l / "sweep.csv"));
}

// Starts bearing-sim ARGS in the background; its pid.
pid_t spawn(const std::string& args) {
  const std::string cmd = std::string("exec ") + BEARING_SIM + " " + args + " >/dev/null 2>&1";
  std::vector<char*> argv{const_cast<char*>("/bin/sh"), const_cast<char*>("-c"),
                          const_cast<char*>(cmd.c_str()), nullptr};
  pid_t pid = 0;
  EXPECT_EQ(posix_spawn(&pid, "/bin/sh", nullptr, nullptr, argv.data(), environ), 0);
  return pid;
}

// Killed mid-way (SIGKILL), resumed: the same bytes as a run that was never stopped.
TEST(CliSweepResume, ResumeAfterSigkillGivesTheUninterruptedFile) {
  const std::string args =
      "sweep --sample \"operation.speed=uniform(1000rpm, 3000rpm)\" --sample "
      "\"bearing.balls=uniform(2, 9)\" --samples 300 --seed 3 --set solver.duration=0.3 "
      "--set solver.transient=0.1 --quiet --jobs 2 --out ";
  const fs::path whole = fresh_dir("resume_whole"), killed = fresh_dir("resume_killed");
  ASSERT_EQ(sim(args + whole.string()), 0);
  const pid_t pid = spawn(args + killed.string());
  const fs::path partial = killed / ".sweep.csv.partial";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (lines(read(partial)) < 30 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  ASSERT_EQ(kill(pid, SIGKILL), 0);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the sweep ended before it was killed";
  ASSERT_FALSE(fs::exists(killed / "sweep.csv"));
  const std::size_t kept = lines(read(partial));
  EXPECT_GE(kept, 30u);
  EXPECT_LT(kept, 301u);
  // A torn last row (as a kill in the middle of a write leaves) is dropped and rerun.
  std::ofstream(partial, std::ios::app) << "4.5,7,ok,,1e-";
  std::string out;
  ASSERT_EQ(sim("sweep --resume " + killed.string() + " --jobs 2 --quiet", &out), 0) << out;
  EXPECT_NE(out.find("300 cases"), std::string::npos) << out;
  EXPECT_EQ(read(killed / "sweep.csv"), read(whole / "sweep.csv"));
  EXPECT_FALSE(fs::exists(partial));
  EXPECT_FALSE(fs::exists(killed / "sweep.design.json"));
  // Nothing left to do: said so, and the file stays as it is.
  const std::string done = read(killed / "sweep.csv");
  ASSERT_EQ(sim("sweep --resume " + killed.string() + " --quiet", &out), 0) << out;
  EXPECT_NE(out.find(killed.string() + " is complete: 300 cases"), std::string::npos) << out;
  EXPECT_EQ(read(killed / "sweep.csv"), done);
}

// The folder's files (name and size) and sweep.csv's modification time: what a run into it
// changes.
std::string snapshot(const fs::path& dir) {
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(dir))
    files.push_back(e.path().filename().string() + " " +
                    (e.is_regular_file() ? std::to_string(e.file_size()) : std::string("dir")));
  std::sort(files.begin(), files.end());
  std::string out;
  for (const auto& f : files) out += f + "\n";
  return out + std::to_string(fs::last_write_time(dir / "sweep.csv").time_since_epoch().count());
}

// --resume of a sweep that has finished: exit 0, the folder and its number of cases named, and
// nothing written — a whole sweep (whose record is removed at its end), a part (which keeps it), a
// merged folder (which never had one). A part resumed so is still merged.
TEST(CliSweepResume, AFinishedSweepIsLeftAsItIs) {
  const std::string grid =
      "sweep --vary bearing.balls=7:8:2 --vary operation.speed=1000rpm:3000rpm:3" + kQuick +
      " --out ";
  const fs::path whole = fresh_dir("done_whole"), p1 = fresh_dir("done_p1"),
                 p2 = fresh_dir("done_p2"), merged = fresh_dir("done_merged");
  ASSERT_EQ(sim(grid + whole.string()), 0);
  ASSERT_EQ(sim(grid + p1.string() + " --part 1/2"), 0);
  ASSERT_EQ(sim(grid + p2.string() + " --part 2/2"), 0);
  ASSERT_EQ(sim("merge " + merged.string() + " " + p1.string() + " " + p2.string()), 0);
  const std::vector<std::pair<fs::path, int>> finished = {{whole, 6}, {p2, 3}, {merged, 6}};
  for (const auto& [dir, cases] : finished) {
    const std::string bytes = read(dir / "sweep.csv"), files = snapshot(dir);
    std::string out;
    EXPECT_EQ(sim("sweep --resume " + dir.string() + " --jobs 2", &out), 0) << out;
    EXPECT_NE(
        out.find(dir.string() + " is complete: " + std::to_string(cases) + " cases, 0 failed"),
        std::string::npos)
        << out;
    EXPECT_EQ(read(dir / "sweep.csv"), bytes) << dir;
    EXPECT_EQ(snapshot(dir), files) << dir;
  }
  EXPECT_FALSE(fs::exists(whole / "sweep.design.json"));
  EXPECT_TRUE(fs::exists(p2 / "sweep.design.json"));
  const fs::path again = fresh_dir("done_again");
  ASSERT_EQ(sim("merge " + again.string() + " " + p1.string() + " " + p2.string()), 0);
  EXPECT_EQ(read(again / "sweep.csv"), read(whole / "sweep.csv"));
}

// A sweep.csv beside a record whose part has another number of cases is not that sweep's: a new
// sweep into the folder was killed before its first row. --resume runs that sweep; merge refuses a
// part with a stopped run in it; a folder without any sweep is an input error.
TEST(CliSweepResume, ARecordWithoutItsRowsIsRun) {
  const std::string grid =
      "sweep --vary bearing.balls=7:8:2 --vary operation.speed=1000rpm:3000rpm:3" + kQuick +
      " --out ";
  const fs::path whole = fresh_dir("norows_whole"), p1 = fresh_dir("norows_p1"),
                 p2 = fresh_dir("norows_p2"), out_dir = fresh_dir("norows_merged");
  ASSERT_EQ(sim(grid + whole.string()), 0);
  ASSERT_EQ(sim(grid + p1.string() + " --part 1/2"), 0);
  ASSERT_EQ(sim(grid + p2.string() + " --part 2/2"), 0);
  const std::string part2 = read(p2 / "sweep.csv");
  fs::copy_file(whole / "sweep.csv", p2 / "sweep.csv", fs::copy_options::overwrite_existing);
  std::string out;
  ASSERT_EQ(sim("sweep --resume " + p2.string() + " --quiet", &out), 0) << out;
  EXPECT_EQ(out.find("is complete"), std::string::npos) << out;
  EXPECT_NE(out.find("3 cases"), std::string::npos) << out;
  EXPECT_EQ(read(p2 / "sweep.csv"), part2);

  std::ofstream(p1 / ".sweep.csv.partial") << "";
  EXPECT_EQ(sim("merge " + out_dir.string() + " " + p1.string() + " " + p2.string(), &out), 2);
  EXPECT_NE(out.find("part 1/2 is not complete"), std::string::npos) << out;
  EXPECT_NE(out.find("--resume " + p1.string()), std::string::npos) << out;

  const fs::path empty = fresh_dir("norows_empty");
  fs::create_directories(empty);
  EXPECT_EQ(sim("sweep --resume " + empty.string(), &out), 2);
  EXPECT_NE(out.find("design record"), std::string::npos) << out;
}

// Two parts merged are one run of the whole design; parts of another design are refused.
TEST(CliSweepMerge, PartsMergedEqualOneRun) {
  const std::string grid =
      "sweep --vary bearing.balls=2:5:4 --vary operation.speed=1000rpm:3000rpm:3" + kQuick +
      " --out ";
  const fs::path whole = fresh_dir("merge_whole"), p1 = fresh_dir("merge_p1"),
                 p2 = fresh_dir("merge_p2"), out = fresh_dir("merge_out");
  ASSERT_EQ(sim(grid + whole.string()), 0);
  // Part 1 holds only failed cases (2 balls): its rows get the columns of part 2 in the merge.
  ASSERT_EQ(sim(grid + p1.string() + " --part 1/4"), 3);
  ASSERT_EQ(sim(grid + p2.string() + " --part 2/4"), 0);
  const fs::path p34 = fresh_dir("merge_p34"), p4 = fresh_dir("merge_p4");
  ASSERT_EQ(sim(grid + p34.string() + " --part 3/4"), 0);
  ASSERT_EQ(sim(grid + p4.string() + " --part 4/4 --jobs 3"), 0);
  EXPECT_TRUE(fs::exists(p2 / "sweep.design.json"));
  std::string msg;
  ASSERT_EQ(sim("merge " + out.string() + " " + p4.string() + " " + p2.string() + " " +
                    p1.string() + " " + p34.string(),
                &msg),
            0)
      << msg;
  EXPECT_EQ(read(out / "sweep.csv"), read(whole / "sweep.csv"));

  EXPECT_EQ(sim("merge " + out.string() + " " + p1.string() + " " + p2.string(), &msg), 2);
  EXPECT_NE(msg.find("part 3/4 is missing"), std::string::npos) << msg;
  EXPECT_EQ(sim("merge " + out.string() + " " + p1.string() + " " + p1.string(), &msg), 2);
  EXPECT_NE(msg.find("twice"), std::string::npos) << msg;
  const fs::path other = fresh_dir("merge_other");
  ASSERT_EQ(sim("sweep --vary bearing.balls=2:5:4 --vary operation.speed=1000rpm:3000rpm:3" +
                kQuick + " --set operation.unbalance=1e-6 --out " + other.string() + " --part 2/4"),
            0);
  EXPECT_EQ(sim("merge " + out.string() + " " + p1.string() + " " + other.string() + " " +
                    p34.string() + " " + p4.string(),
                &msg),
            2);
  EXPECT_NE(msg.find("not parts of the same sweep: their base differ"), std::string::npos) << msg;
}

}  // namespace
