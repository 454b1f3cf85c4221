#pragma once
// The report's title page: commit, date, machine, compiler, library versions.

#include <string>

#include "report.h"

namespace bearing::verify {

RunInfo run_info(const std::string& command, const std::string& level, const std::string& only,
                 int jobs, int mpi_processes, const std::string& fem_program);

}  // namespace bearing::verify
