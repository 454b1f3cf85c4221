#!/usr/bin/env bash
# Issue 42's judge of a hot-path change: every output of tests/outputs/run_matrix.sh stays
# byte-identical, or moves by less than the integrator's own error on that output.
#
#   bench/output_change.sh OLD_SIM NEW_SIM [WORK]
#
#   OLD_SIM  the previous build's bearing-sim (e.g. a worktree of the commit before the change,
#            built as bench/perf_guard.sh builds it: /tmp/bearing-perf-guard/REF/build/lumped/...)
#   NEW_SIM  this build's (e.g. build/lumped/bearing-sim)
#   WORK     where the four matrices go (default /tmp/bearing-output-change)
#
# Runs the matrix with OLD_SIM, NEW_SIM, OLD_SIM at each integrator's finer setting (dt/2, or
# tolerance/10 for an adaptive method) and OLD_SIM with round-off perturbations (speed and load
# one unit in the last place up, and down),
# then prints every output that changed: by how much, against which bound, and the cases that
# amplify round-off (bench/output_change.py says how each is judged). Exit 0: all within bound.
# About 1.5 min. Paste its table into the note of a hot-path change.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
[[ $# -ge 2 && $# -le 3 ]] || { echo "usage: bench/output_change.sh OLD_SIM NEW_SIM [WORK]" >&2; exit 2; }
for s in "$1" "$2"; do
  [[ -x $s ]] || { echo "output_change.sh: $s: not an executable bearing-sim" >&2; exit 2; }
done
work=${3:-/tmp/bearing-output-change}
mkdir -p "$work"
matrix=$here/../tests/outputs/run_matrix.sh
echo "output_change.sh: the matrix with the old build, the new, the old at the finer setting, the old perturbed" >&2
"$matrix" "$1" "$work/old" >/dev/null
"$matrix" "$2" "$work/new" >/dev/null
"$matrix" "$1" "$work/fine" finer "$work/old" >/dev/null
"$matrix" "$1" "$work/perturbed" perturbed "$work/old" >/dev/null
"$matrix" "$1" "$work/perturbed-down" perturbed-down "$work/old" >/dev/null
exec /usr/bin/python3 "$here/output_change.py" compare "$work/old" "$work/new" "$work/fine" \
  "$work/perturbed" "$work/perturbed-down" --report "$work/report.md"
