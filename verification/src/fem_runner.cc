#include "fem_runner.h"

#include <sys/wait.h>

#include <chrono>
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

std::string tail_of(const fs::path& file, std::size_t chars) {
  std::ifstream in(file);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string s = ss.str();
  return s.size() <= chars ? s : "…" + s.substr(s.size() - chars);
}

}  // namespace

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

nlohmann::json FemRunner::execute(const std::vector<std::string>& args,
                                  const std::string& json_name, int index) const {
  char name[32];
  std::snprintf(name, sizeof name, "run%03d", index);
  const fs::path dir = fs::path(work_dir_) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::string command;
  if (mpi_ > 1) command = "mpirun --oversubscribe -np " + std::to_string(mpi_) + " ";
  command += quoted(program_);
  for (const auto& a : args) command += " " + quoted(a);
  command += " --out " + quoted(dir.string());
  { std::ofstream(dir / "command.txt") << command << "\n"; }
  const auto start = std::chrono::steady_clock::now();
  const int status =
      std::system((command + " > " + quoted((dir / "log.txt").string()) + " 2>&1").c_str());
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const int code = status == -1 ? -1 : (WIFEXITED(status) ? WEXITSTATUS(status) : 128);
  const fs::path json_file = json_name.empty() ? fs::path() : dir / json_name;
  if (code != 0 || !fs::exists(json_file))
    throw SolverError("bearing-fem failed (exit " + std::to_string(code) + "): " + command + "\n" +
                      tail_of(dir / "log.txt", 600));
  std::ifstream in(json_file);
  nlohmann::json j = nlohmann::json::parse(in);
  j["dir"] = dir.string();
  j["wall_time_total"] = seconds;
  return j;
}

}  // namespace bearing::verify
