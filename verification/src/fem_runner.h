#pragma once
// Runs the FE reference program `bearing-fem` as a child process, under `mpirun -np N` when asked,
// once per distinct argument list (memoised, thread-safe), each run in its own folder.

#include <future>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace bearing::verify {

/// The shell command running `program ARGS` (under `mpirun -np N` when mpi_processes > 1).
std::string fem_command(const std::string& program, int mpi_processes,
                        const std::vector<std::string>& args);

/// Runs a shell command with its output into `log`; its exit status (-1: not started).
int run_logged(const std::string& command, const std::string& log);

/// The last `chars` characters of a file (a failed run's log, for the error message).
std::string tail_of(const std::string& file, std::size_t chars);

class FemRunner {
 public:
  /// `program`: bearing-fem's path ("" when it was not built: every run throws Skipped);
  /// `mpi_processes` ≥ 1 (1: run directly); `work_dir`: where the run folders go.
  FemRunner(std::string program, int mpi_processes, std::string work_dir);

  /// The JSON file `json_name` that `bearing-fem ARGS --out DIR` wrote (DIR/json_name), plus
  /// "dir": DIR and "wall_time_total". Throws Skipped (no program) or SolverError (it failed:
  /// the message carries its exit status and the end of its output).
  nlohmann::json run(const std::vector<std::string>& args, const std::string& json_name);

  /// Writes `text` to WORK_DIR/inputs/STEM-HASH.EXTENSION unless that file was written already by
  /// this runner (thread-safe) and returns its path: input files the checks write for bearing-fem
  /// (structure files, .geo), named by their content so that equal arguments mean equal inputs.
  std::string input_file(const std::string& stem, const std::string& extension,
                         const std::string& text);

  bool available() const { return !program_.empty(); }
  const std::string& program() const { return program_; }
  int mpi_processes() const { return mpi_; }

 private:
  nlohmann::json execute(const std::vector<std::string>& args, const std::string& json_name,
                         int index) const;

  std::string program_;
  int mpi_;
  std::string work_dir_;
  std::mutex mutex_;
  std::map<std::string, std::shared_future<nlohmann::json>> runs_;
  std::mutex inputs_mutex_;
  std::map<std::string, std::string> inputs_;  ///< path -> text written
};

}  // namespace bearing::verify
