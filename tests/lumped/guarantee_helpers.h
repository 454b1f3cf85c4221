#pragma once
// What the guarantee tests (issue 21, item 3) share: bearing-sim started in the background and
// waited for, a folder's files as bytes, the names a run may leave, and the NaN/Inf scan of a
// result file (CSV/JSON/TOML text and .npy).

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "cli_helpers.h"

extern char** environ;

namespace bearing::test {

/// Starts `bearing-sim ARGS` in the background, stdout to /dev/null, stderr to `log`; its pid.
inline pid_t spawn_sim(const std::string& args, const std::string& log = "/dev/null") {
  const std::string cmd = std::string("exec ") + BEARING_SIM + " " + args + " >/dev/null 2>" + log;
  std::vector<char*> argv{const_cast<char*>("/bin/sh"), const_cast<char*>("-c"),
                          const_cast<char*>(cmd.c_str()), nullptr};
  pid_t pid = 0;
  EXPECT_EQ(posix_spawn(&pid, "/bin/sh", nullptr, nullptr, argv.data(), environ), 0);
  return pid;
}

/// Waits for `pid`: its exit status, or minus the signal that ended it.
inline int wait_sim(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

/// Whether `pid` (a child) is still running; does not reap it.
inline bool running(pid_t pid) {
  siginfo_t info{};
  return waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 &&
         info.si_pid == 0;
}

/// Every regular file of `dir` (hidden ones too): name -> bytes.
inline std::map<std::string, std::string> files_of(const fs::path& dir) {
  std::map<std::string, std::string> out;
  if (!fs::exists(dir)) return out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file()) out[e.path().filename().string()] = read(e.path());
  return out;
}

inline bool hidden(const std::string& name) {
  return !name.empty() && name[0] == '.';
}

/// The files of `dir` under final (not hidden) names.
inline std::map<std::string, std::string> results_of(const fs::path& dir) {
  auto all = files_of(dir);
  for (auto it = all.begin(); it != all.end();) it = hidden(it->first) ? all.erase(it) : ++it;
  return all;
}

/// Every name `run` documents (docs/bearing-sim.md, "run: the result files", "NumPy output").
inline const std::set<std::string>& documented_results() {
  static const std::set<std::string> names = {"response.csv", "spectrum.csv", "pressure.csv",
                                              "envelope.csv", "response.npy", "spectrum.npy",
                                              "pressure.npy", "envelope.npy", "summary.json",
                                              "case.toml",    "columns.json"};
  return names;
}

/// A hidden name a run may leave behind when killed: the folder's lock (.run.lock) or the
/// temporary file of a documented result (".response.csv.partial").
inline bool allowed_leftover(const std::string& name) {
  if (name == ".run.lock") return true;
  for (const auto& r : documented_results())
    if (name == "." + r + ".partial") return true;
  return false;
}

/// Text with "case.source" / "# Source:" (the file a run read, which differs when the run reads
/// DIR/case.toml) blanked; every other byte kept.
inline std::string without_source(const std::string& text) {
  static const std::regex json(R"re("source": "[^"]*")re"), toml(R"re(# Source: [^\n]*)re");
  return std::regex_replace(std::regex_replace(text, json, "\"source\": \"\""), toml, "# Source:");
}

/// "" if `bytes` (the file `name`) holds only finite numbers, else what is not finite. Text files
/// are searched for nan/inf/infinity tokens (any case); a .npy's float64 data is decoded.
inline std::string non_finite_in(const std::string& name, const std::string& bytes) {
  if (name.size() > 4 && name.substr(name.size() - 4) == ".npy") {
    if (bytes.size() < 10 || bytes.compare(0, 6, "\x93NUMPY") != 0) return name + ": not a .npy";
    const std::size_t header =
        10 + static_cast<unsigned char>(bytes[8]) + 256 * static_cast<unsigned char>(bytes[9]);
    if (bytes.find("'<f8'") == std::string::npos || (bytes.size() - header) % 8 != 0)
      return name + ": not float64 data";
    for (std::size_t k = header; k + 8 <= bytes.size(); k += 8) {
      double v;
      std::memcpy(&v, bytes.data() + k, 8);  // little-endian host (x86-64, aarch64)
      if (!std::isfinite(v)) return name + ": value " + std::to_string((k - header) / 8);
    }
    return "";
  }
  // A token: "nan", "inf" or "infinity" in any case, not inside a longer word ("info", "inner").
  const auto letter = [](char ch) {
    return std::isalpha(static_cast<unsigned char>(ch)) || ch == '_';
  };
  for (std::size_t k = 0; k + 3 <= bytes.size(); ++k) {
    std::string w = bytes.substr(k, 3);
    for (char& ch : w) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (w != "nan" && w != "inf") continue;
    std::size_t end = k + 3;
    if (w == "inf" && bytes.size() >= k + 8) {
      std::string rest = bytes.substr(k + 3, 5);
      for (char& ch : rest) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      if (rest == "inity") end = k + 8;
    }
    if ((k == 0 || !letter(bytes[k - 1])) && (end == bytes.size() || !letter(bytes[end])))
      return name + ": \"" + bytes.substr(k, end - k) + "\" at byte " + std::to_string(k);
  }
  return "";
}

}  // namespace bearing::test
