// bearing-sim → bearing-sim-full (full_program.h).

#include "full_program.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <system_error>

namespace bearing_app {

bool hands_over() {
#ifdef BEARING_FULL_PROGRAM
  return true;
#else
  return false;
#endif
}

bool launched_in_parallel() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(v) != nullptr) return true;
  return false;
}

void hand_over(const CommandLine& cl, const std::string& why) {
#ifdef BEARING_FULL_PROGRAM
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  const fs::path full = self.parent_path() / BEARING_FULL_PROGRAM;
  if (!ec) {
    std::cout.flush();
    std::fflush(nullptr);
    execv(full.c_str(), cl.argv);
  }
  const int err = ec ? ec.value() : errno;
  throw std::runtime_error(why + " needs " + BEARING_FULL_PROGRAM +
                           ", which belongs beside this program (" + full.string() +
                           "), and it cannot be started: " + std::strerror(err) +
                           "; reinstall bearing-sim");
#else
  (void)cl;
  throw std::runtime_error(why + " needs bearing-sim-full, and this build has none");
#endif
}

}  // namespace bearing_app
