#pragma once
// `bearing-sim sweep --save`: write_sweep's hook that makes DIR/sweep.h5, restartable. Each row
// (with its tables, sweep_tables.h) is spooled to DIR/.sweep.h5.cases/<index>.row (the row codec,
// written then renamed) before its line goes to sweep.csv, so a sweep killed at any moment has the
// tables of every row it kept; at the end sweep.h5 is built from the spool in case order
// (SweepDataset: one case in memory at a time) and the spool is removed. HDF5 files themselves are
// not crash-consistent, which is why the data set is written only at the end.

#include <string>
#include <vector>

#include "bearing/sweep.h"
#include "bearing/sweep_tables.h"

namespace bearing {

/// The hook for `plan`'s sweep (or part) in `dir` saving `what` (empty: an empty hook). Starts
/// the spool (records `what` in it) unless `resume`.
SweepRowHook sweep_save_hook(const std::string& dir, const SweepPlan& plan,
                             const std::vector<SweepSave>& what, bool resume);

/// What the sweep killed in `dir` was saving, from its spool (empty if it saved nothing).
std::vector<SweepSave> spooled_save(const std::string& dir);

}  // namespace bearing
