#include "fem_runner.h"

#include <sys/wait.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "bearing/errors.h"
#include "check.h"

namespace bearing::verify {

namespace fs = std::filesystem;

namespace {

std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

std::string tail_of(const std::string& file, std::size_t chars) {
  std::ifstream in(file);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string s = ss.str();
  return s.size() <= chars ? s : "…" + s.substr(s.size() - chars);
}

std::string fem_command(const std::string& program, int mpi_processes,
                        const std::vector<std::string>& args) {
  std::string command;
  if (mpi_processes > 1)
    command =
        "mpirun --allow-run-as-root --oversubscribe -np " + std::to_string(mpi_processes) + " ";
  command += quoted(program);
  for (const auto& a : args) command += " " + quoted(a);
  return command;
}

int run_logged(const std::string& command, const std::string& log) {
  const int status = std::system((command + " > " + quoted(log) + " 2>&1").c_str());
  return status == -1 ? -1 : (WIFEXITED(status) ? WEXITSTATUS(status) : 128);
}

FemRunner::FemRunner(std::string program, int mpi_processes, std::string work_dir)
    : program_(std::move(program)), mpi_(mpi_processes), work_dir_(std::move(work_dir)) {}

nlohmann::json FemRunner::run(const std::vector<std::string>& args, const std::string& json_name) {
  if (program_.empty())
    throw Skipped("bearing-fem was not built (deal.II not found, BEARING_WITH_FEM=OFF)");
  std::string key = json_name;
  for (const auto& a : args) key += '\x1f' + a;
  // One FE run at a time: each already takes the cores it is given (mpirun -np N).
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = runs_.find(key);
  if (it == runs_.end()) {
    std::promise<nlohmann::json> promise;
    const int index = static_cast<int>(runs_.size());
    it = runs_.emplace(key, promise.get_future().share()).first;
    try {
      promise.set_value(execute(args, json_name, index));
    } catch (...) {
      promise.set_exception(std::current_exception());
    }
  }
  return it->second.get();
}

std::string FemRunner::input_file(const std::string& stem, const std::string& extension,
                                  const std::string& text) {
  // FNV-1a of the text: a stable name for the same content, within and across runs.
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(h));
  const fs::path dir = fs::path(work_dir_) / "inputs";
  const std::string path = (dir / (stem + "-" + std::string(hash, 8) + "." + extension)).string();
  std::lock_guard<std::mutex> lock(inputs_mutex_);
  if (inputs_.count(path) == 0) {
    fs::create_directories(dir);
    std::ofstream(path) << text;
    inputs_[path] = text;
  }
  return path;
}

nlohmann::json FemRunner::execute(const std::vector<std::string>& args,
                                  const std::string& json_name, int index) const {
  char name[32];
  std::snprintf(name, sizeof name, "run%03d", index);
  const fs::path dir = fs::path(work_dir_) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::vector<std::string> all = args;
  all.insert(all.end(), {"--out", dir.string()});
  const std::string command = fem_command(program_, mpi_, all);
  { std::ofstream(dir / "command.txt") << command << "\n"; }
  const auto start = std::chrono::steady_clock::now();
  const int code = run_logged(command, (dir / "log.txt").string());
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const fs::path json_file = json_name.empty() ? fs::path() : dir / json_name;
  if (code != 0 || !fs::exists(json_file))
    throw SolverError("bearing-fem failed (exit " + std::to_string(code) + "): " + command + "\n" +
                      tail_of((dir / "log.txt").string(), 600));
  std::ifstream in(json_file);
  nlohmann::json j = nlohmann::json::parse(in);
  j["dir"] = dir.string();
  j["wall_time_total"] = seconds;
  return j;
}

}  // namespace bearing::verify
