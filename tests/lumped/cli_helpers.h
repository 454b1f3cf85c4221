#pragma once
// The test programs' way of running the bearing-sim executable (BEARING_SIM, set by CMake) and
// reading what it wrote: shared by the end-to-end tests of run, sweep and the envelope outputs.

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace bearing::test {

namespace fs = std::filesystem;

/// The whole file as bytes ("" if it cannot be read).
inline std::string read(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

/// Runs `bearing-sim ARGS`; its exit status (-1 if it did not exit). With `out`, its stdout and
/// stderr together.
inline int sim(const std::string& args, std::string* out = nullptr) {
  // One file per test process (ctest -j runs tests side by side).
  const fs::path o =
      fs::path(::testing::TempDir()) / ("bearing_sim.stdout." + std::to_string(getpid()) + ".txt");
  const std::string cmd =
      std::string(BEARING_SIM) + " " + args + " >" + (out ? o.string() : "/dev/null") + " 2>&1";
  const int status = std::system(cmd.c_str());
  if (out) *out = read(o), fs::remove(o);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// An empty folder name under the test's temporary directory (removed if it exists).
inline fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::path(::testing::TempDir()) / name;
  fs::remove_all(d);
  return d;
}

/// A short run of the default case: 0.3 s with 0.1 s of transient, no progress.
inline const std::string kShort = " --set solver.duration=0.3 --set solver.transient=0.1 --quiet";

}  // namespace bearing::test
