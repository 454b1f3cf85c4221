#!/usr/bin/env bash
# Peak resident memory of the real bearing-sim executable (issue 18, target 7); prints a table.
#
#   bench/memory.sh [BEARING_SIM]      default: build/lumped/bearing-sim of this checkout
#
# Measured with GNU time (`/usr/bin/time -f %M`: the process's maximum resident set size, kB):
#   - `run` of the built-in default case (6308 2-DOF, RK4 5 us, 1.2 s, 20 kHz), as CSV and as .npy
#     (output.format = "npy"; "n/a" for a binary without that key);
#   - `sweep --vary operation.speed=1000rpm:3000rpm:N --set solver.duration=0.05
#     --set solver.transient=0.01` for N = 1000 and 10000 (SWEEP_JOBS workers, default 2).
# Target: a sweep's memory does not grow with the number of cases: peak RSS of 10000 cases within
# 10 % of that of 1000. Each figure is the median of REPEATS runs (default 3; RSS barely varies).
# The 10000-case sweep takes ~6 s with 2 jobs on an idle 2-core machine.
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
sim=${1:-$repo/build/lumped/bearing-sim}
repeats=${REPEATS:-3}
jobs=${SWEEP_JOBS:-2}
gnu_time=/usr/bin/time

if [[ ! -x $sim ]]; then
  echo "memory.sh: no executable at $sim (build it: cmake --build build --target bearing-sim)" >&2
  exit 2
fi
if [[ ! -x $gnu_time ]]; then
  echo "memory.sh: needs GNU time at $gnu_time (Debian package 'time')" >&2
  exit 2
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# "peak_kB wall_s" of one run of "$@", or "n/a n/a" if it fails.
measure() {
  if "$gnu_time" -f '%M %e' -o "$work/time" "$@" >/dev/null 2>"$work/stderr"; then
    tail -n 1 "$work/time"
  else
    echo "n/a n/a"
  fi
}

# "median_peak_kB median_wall_s" over $repeats runs of "$@".
median_of() {
  : >"$work/runs"
  for ((i = 0; i < repeats; ++i)); do measure "$@" >>"$work/runs"; done
  if grep -q 'n/a' "$work/runs"; then
    echo "n/a n/a"
    return
  fi
  local m w
  m=$(cut -d' ' -f1 "$work/runs" | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }')
  w=$(cut -d' ' -f2 "$work/runs" | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }')
  echo "$m $w"
}


"$sim" run --out "$work/warm" --quiet >/dev/null  # page cache, dynamic loader
read -r run_csv run_csv_s < <(median_of "$sim" run --out "$work/run_csv" --quiet)
read -r run_npy run_npy_s < <(median_of "$sim" run --out "$work/run_npy" --quiet \
  --set output.format=npy)
# The sweeps as arrays: GNU time runs programs, not shell functions.
sweep_common=(--set solver.duration=0.05 --set solver.transient=0.01 --jobs "$jobs" --quiet)
sweep1k=("$sim" sweep --vary operation.speed=1000rpm:3000rpm:1000 "${sweep_common[@]}"
  --out "$work/sweep1000")
sweep10k=("$sim" sweep --vary operation.speed=1000rpm:3000rpm:10000 "${sweep_common[@]}"
  --out "$work/sweep10000")
read -r s1k s1k_s < <(median_of "${sweep1k[@]}")
read -r s10k s10k_s < <(median_of "${sweep10k[@]}")

mb() { awk -v k="$1" 'BEGIN { if (k == "n/a") print k; else printf "%.1f", k / 1024 }'; }
echo "bearing-sim peak resident memory — $(date '+%F %H:%M'), $(nproc) cores, $sim"
printf '%-58s %12s %10s\n' "measurement" "peak [MB]" "wall [s]"
printf '%-58s %12s %10s\n' "run, default case, output.format = csv" "$(mb "$run_csv")" "$run_csv_s"
printf '%-58s %12s %10s\n' "run, default case, output.format = npy" "$(mb "$run_npy")" "$run_npy_s"
printf '%-58s %12s %10s\n' "sweep 1000 cases x 0.05 s, --jobs $jobs" "$(mb "$s1k")" "$s1k_s"
printf '%-58s %12s %10s\n' "sweep 10000 cases x 0.05 s, --jobs $jobs" "$(mb "$s10k")" "$s10k_s"
echo
if [[ $s1k == n/a || $s10k == n/a ]]; then
  echo "a sweep failed: no ratio"
else
  ratio=$(awk -v a="$s10k" -v b="$s1k" 'BEGIN { printf "%.3f", a / b }')
  verdict=$(awk -v r="$ratio" 'BEGIN { print (r <= 1.10 ? "MET" : "NOT MET") }')
  echo "sweep peak RSS 10000 / 1000 cases: ${ratio}x (target <= 1.10x: $verdict);" \
    "sweep.csv rows: $(($(wc -l <"$work/sweep10000/sweep.csv") - 1))"
fi
echo "(median of $repeats runs each; GNU time's maximum resident set size)"
