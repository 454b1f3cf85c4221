#pragma once
// Runs checks (in parallel, --jobs N) and judges each against its tolerance; plants mutations.

#include <functional>
#include <regex>
#include <vector>

#include "context.h"
#include "mutations.h"
#include "report.h"

namespace bearing::verify {

/// The checks of `all` that run at `level` and whose id matches `only` (ECMAScript regex, searched;
/// empty: all).
std::vector<const Check*> select_checks(const std::vector<Check>& all, Level level,
                                        const std::string& only);

/// Measures one check and judges it (an exception is a failure with its message; Skipped is a
/// skip).
CheckResult run_check(const Check& check, const Context& context);

/// Runs `checks` with `jobs` threads; results in the order of `checks`. `progress` (may be empty)
/// is called after each check with the count done. `fail_fast`: after the first failed check no
/// further check starts (those already running finish); the results then hold only the checks
/// that ran, still in the order of `checks` (used by source mutants, where one failure decides).
std::vector<CheckResult> run_checks(const std::vector<const Check*>& checks, const Context& context,
                                    int jobs,
                                    const std::function<void(const CheckResult&, int)>& progress,
                                    bool fail_fast = false);

/// `checks` cheapest first (by `cost`, stable): the order `run --fail-fast` runs them in, so a
/// failing cheap check ends the run early.
std::vector<const Check*> cheapest_first(std::vector<const Check*> checks);

/// For each mutation: reruns the checks that passed in `baseline` under it and lists those that
/// fail (caught_by) and those that name it but still pass.
std::vector<MutationResult> run_mutations(
    const std::vector<const Mutation*>& mutations, const std::vector<CheckResult>& baseline,
    const std::function<Context(const Perturbation&)>& context_for, int jobs,
    const std::function<void(const MutationResult&)>& progress);

}  // namespace bearing::verify
