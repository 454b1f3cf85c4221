#include "run_info.h"

#include <sys/utsname.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <ctime>
#include <memory>

#include <gsl/gsl_version.h>
#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace bearing::verify {

namespace {

// First line a shell command prints, or "" (not found, failed).
std::string first_line(const std::string& command) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen((command + " 2>/dev/null").c_str(), "r"),
                                             pclose);
  if (!pipe) return "";
  std::array<char, 256> buffer{};
  std::string line;
  if (fgets(buffer.data(), buffer.size(), pipe.get()) != nullptr) line = buffer.data();
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
  return line;
}

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

}  // namespace

RunInfo run_info(const std::string& command, const std::string& level, const std::string& only,
                 int jobs, int mpi_processes, const std::string& fem_program) {
  RunInfo info;
  info.command = command;
  info.level = level;
  info.only = only;
  info.jobs = jobs;
  info.mpi_processes = mpi_processes;
  info.fem_program = fem_program;
  info.commit = first_line("git -C '" + std::string(BEARING_SOURCE_DIR) +
                           "' describe --always --dirty --tags");
  if (info.commit.empty()) info.commit = "unversioned";
  info.date = utc_now();
  utsname u{};
  uname(&u);
  info.machine = std::string(u.nodename) + ", " + u.sysname + " " + u.release + " " + u.machine +
                 ", " + std::to_string(sysconf(_SC_NPROCESSORS_ONLN)) + " cores";
  info.compiler = std::string(
#if defined(__clang__)
                      "clang "
#elif defined(__GNUC__)
                      "g++ "
#endif
                      ) +
                  __VERSION__;
  info.libraries = {
      {"Eigen", std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) +
                    "." + std::to_string(EIGEN_MINOR_VERSION)},
      {"GSL", GSL_VERSION},
      {"nlohmann_json", std::to_string(NLOHMANN_JSON_VERSION_MAJOR) + "." +
                            std::to_string(NLOHMANN_JSON_VERSION_MINOR) + "." +
                            std::to_string(NLOHMANN_JSON_VERSION_PATCH)},
      {"deal.II", BEARING_DEAL_II_VERSION},
  };
  const std::string mpi = first_line("mpirun --version");
  if (!mpi.empty()) info.libraries.push_back({"MPI", mpi});
  const std::string py = first_line(
      "/usr/bin/python3 -c 'import matplotlib, numpy; print(matplotlib.__version__, "
      "numpy.__version__)'");
  if (!py.empty()) info.libraries.push_back({"matplotlib, numpy", py});
  return info;
}

}  // namespace bearing::verify
