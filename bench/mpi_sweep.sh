#!/usr/bin/env bash
# Sweeps across MPI ranks (issue 20): speed-up of `mpirun -np 2` over `-np 1`, and peak memory per
# rank against the number of cases; prints a table.
#
#   bench/mpi_sweep.sh [BEARING_SIM]      default: build/lumped/bearing-sim of this checkout
#
# Speed-up: `sweep --vary operation.speed=1000rpm:3000rpm:1000 --set solver.duration=0.3
# --set solver.transient=0.1 --jobs 1` (1000 cases, 0.3 s simulated each, one thread per rank)
# under `mpirun -np 1` and `mpirun -np 2`, interleaved (np 1, np 2, np 1, …) so a change of load
# hits both alike; wall time of mpirun (start-up included), median of REPEATS (default 3).
# Target: np 1 / np 2 ≥ 1.8. Every sweep.csv is compared with that of plain `--jobs 1`.
# Memory: the same sweep with 1000 and 10000 cases (solver.duration = 0.05 s, transient 0.01 s,
# as bench/memory.sh) under `mpirun -np 2 --jobs 1`; each rank runs under GNU time, and the
# figure is the largest rank's maximum resident set size (rank 0, which holds the reorder
# window). Target: 10000 cases within 10 % of 1000.
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
sim=${1:-$repo/build/lumped/bearing-sim}
repeats=${REPEATS:-3}
gnu_time=/usr/bin/time
for tool in mpirun "$gnu_time"; do
  if ! command -v "$tool" >/dev/null; then
    echo "mpi_sweep.sh: needs $tool (Debian packages mpi-default-bin, time)" >&2
    exit 2
  fi
done
if [[ ! -x $sim ]]; then
  echo "mpi_sweep.sh: no executable at $sim (build it: cmake --build build --target bearing-sim)" >&2
  exit 2
fi
flags=(--oversubscribe)
if [[ $(id -u) -eq 0 ]]; then flags+=(--allow-run-as-root); fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cases_of() {
  echo "--vary operation.speed=1000rpm:3000rpm:$1"
}
speed=($(cases_of 1000) --set solver.duration=0.3 --set solver.transient=0.1 --jobs 1 --quiet)

median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
# Wall seconds of "$@" on stdout; its CPU seconds (user + system, all ranks) added to $work/cpu.
seconds() {
  "$gnu_time" -f '%e %U %S' -o "$work/time" "$@" >/dev/null
  read -r wall user sys <"$work/time"
  echo "$user $sys" >>"$work/cpu"
  echo "$wall"
}
# CPU seconds the whole machine spent busy (all but idle and iowait), from /proc/stat.
busy() { awk '/^cpu / { print ($2 + $3 + $4 + $7 + $8 + $9) / 100 }' /proc/stat; }

"$sim" sweep "${speed[@]}" --out "$work/serial" >/dev/null  # reference, and a warm page cache
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
busy_before=$(busy)
: >"$work/cpu"
: >"$work/np1"
: >"$work/np2"
same=yes
for ((i = 0; i < repeats; ++i)); do
  for np in 1 2; do
    seconds mpirun "${flags[@]}" -np "$np" "$sim" sweep "${speed[@]}" --out "$work/out$np" \
      >>"$work/np$np"
    cmp -s "$work/serial/sweep.csv" "$work/out$np/sweep.csv" || same=no
  done
done
load_after=$(cut -d' ' -f1-3 /proc/loadavg)
others=$(awk -v a="$busy_before" -v b="$(busy)" '{ s += $1 + $2 } END { printf "%.1f", b - a - s }' \
  "$work/cpu")
t1=$(median <"$work/np1")
t2=$(median <"$work/np2")

# Peak RSS [kB] of the largest rank of `mpirun -np 2 bearing-sim sweep` over N cases.
peak_rss() {
  rm -f "$work"/rss.*
  mpirun "${flags[@]}" -np 2 bash -c \
    'o=$1; shift; exec "$0" -f %M -o "$o.${OMPI_COMM_WORLD_RANK:-$PMIX_RANK}" "$@"' \
    "$gnu_time" "$work/rss" \
    "$sim" sweep $(cases_of "$1") --set solver.duration=0.05 --set solver.transient=0.01 \
    --jobs 1 --quiet --out "$work/mem$1" >/dev/null
  tail -q -n 1 "$work"/rss.* | sort -g | tail -n 1
}
mem() {
  for ((i = 0; i < repeats; ++i)); do peak_rss "$1"; done | median
}
m1k=$(mem 1000)
m10k=$(mem 10000)

echo "bearing-sim sweep under mpirun — $(date '+%F %H:%M'), $(nproc) cores," \
  "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "load average before / after the timing: $load_before / $load_after;" \
  "CPU used by other processes during it: $others s"
printf '%-62s %10s\n' "1000 cases x 0.3 s, --jobs 1" "wall [s]"
printf '%-62s %10s\n' "mpirun -np 1 (runs: $(paste -sd' ' "$work/np1"))" "$t1"
printf '%-62s %10s\n' "mpirun -np 2 (runs: $(paste -sd' ' "$work/np2"))" "$t2"
ratio=$(awk -v a="$t1" -v b="$t2" 'BEGIN { printf "%.2f", a / b }')
echo "speed-up np 2 / np 1: ${ratio}x (target >= 1.8x:" \
  "$(awk -v r="$ratio" 'BEGIN { print (r >= 1.8 ? "MET" : "NOT MET") }'));" \
  "sweep.csv equal to --jobs 1 in every run: $same"
echo
mb() { awk -v k="$1" 'BEGIN { printf "%.1f", k / 1024 }'; }
printf '%-62s %10s\n' "mpirun -np 2, --jobs 1, x 0.05 s: largest rank's peak RSS" "[MB]"
printf '%-62s %10s\n' "1000 cases" "$(mb "$m1k")"
printf '%-62s %10s\n' "10000 cases" "$(mb "$m10k")"
mratio=$(awk -v a="$m10k" -v b="$m1k" 'BEGIN { printf "%.3f", a / b }')
echo "peak RSS 10000 / 1000 cases: ${mratio}x (target <= 1.10x:" \
  "$(awk -v r="$mratio" 'BEGIN { print (r <= 1.10 ? "MET" : "NOT MET") }'));" \
  "sweep.csv rows: $(($(wc -l <"$work/mem10000/sweep.csv") - 1))"
echo "(median of $repeats runs each)"
