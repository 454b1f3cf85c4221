#!/usr/bin/env bash
# Wall time of `bearing-sim run` of the default case with output.format = "csv" against "npy"
# (issue 18, target 2); prints a table.
#
#   bench/output_format.sh [BEARING_SIM [OTHER_SIM]]   default: build/lumped/bearing-sim
#
# The default case (6308 2-DOF, RK4 5 us, 1.2 s, 20 kHz output: 24 001 x 7 response, 10 001 x 7
# spectrum), pinned to one core with taskset, ROUNDS rounds (default 21) after a warm-up; each
# round runs csv then npy (and OTHER_SIM's csv run, e.g. a build of the commit before, if given),
# so that load from other processes spreads over all of them. Figures are the minimum and the
# median of the rounds (wall time of the whole process); the status is judged on the minima (on a
# shared machine noise only adds time).
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
sim=${1:-$repo/build/lumped/bearing-sim}
other=${2:-}
rounds=${ROUNDS:-21}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

time_ms() {
  local start=$EPOCHREALTIME
  "$@" >/dev/null 2>"$work/stderr" || { cat "$work/stderr" >&2; exit 1; }
  local end=$EPOCHREALTIME
  awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f\n", (b - a) * 1000 }'
}
min_median() {
  sort -g "$1" | awk '{ v[NR] = $1 } END {
    m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
    printf "%.1f %.1f\n", v[1], m }'
}

csv=(taskset -c 1 "$sim" run --out "$work/csv" --quiet)
npy=(taskset -c 1 "$sim" run --out "$work/npy" --quiet --set output.format=npy)
old=(taskset -c 1 "$other" run --out "$work/old" --quiet)
"${csv[@]}" >/dev/null
"${npy[@]}" >/dev/null
[[ -n $other ]] && "${old[@]}" >/dev/null
: >"$work/csv.ms" && : >"$work/npy.ms" && : >"$work/old.ms"
for ((i = 0; i < rounds; ++i)); do
  time_ms "${csv[@]}" >>"$work/csv.ms"
  time_ms "${npy[@]}" >>"$work/npy.ms"
  [[ -n $other ]] && time_ms "${old[@]}" >>"$work/old.ms"
done
read -r csv_min csv_med < <(min_median "$work/csv.ms")
read -r npy_min npy_med < <(min_median "$work/npy.ms")
size() { du -k --apparent-size -c "$@" | tail -n 1 | cut -f1; }

echo "bearing-sim run, default case, taskset -c 1 — $(date '+%F %H:%M'), $rounds rounds, $sim"
printf '%-40s %10s %12s %12s\n' "output" "min [ms]" "median [ms]" "tables [kB]"
printf '%-40s %10s %12s %12s\n' "csv (response.csv, spectrum.csv)" "$csv_min" "$csv_med" \
  "$(size "$work"/csv/*.csv)"
printf '%-40s %10s %12s %12s\n' "npy (response.npy, spectrum.npy)" "$npy_min" "$npy_med" \
  "$(size "$work"/npy/*.npy)"
if [[ -n $other ]]; then
  read -r old_min old_med < <(min_median "$work/old.ms")
  printf '%-40s %10s %12s\n' "csv, $other" "$old_min" "$old_med"
fi
awk -v a="$npy_min" -v b="$csv_min" -v c="$npy_med" -v d="$csv_med" 'BEGIN {
  printf "npy / csv: %.3f (minima), %.3f (medians); saved %.1f ms (minima)\n", a / b, c / d, b - a }'
