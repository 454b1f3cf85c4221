#!/usr/bin/env bash
# `mpirun -np N bearing-sim sweep` writes the sweep.csv of `bearing-sim sweep --jobs 1`, byte for
# byte (issue 20): 2 and 3 ranks, 1 and 2 threads per rank, failed cases (negative clearance),
# microphone levels and envelope figures in the rows; only rank 0 prints; an input error ends every
# rank (no hang); a killed sweep resumes, and a finished one resumed is left as it is.
#
#   tests/cli/sweep_mpi.sh BEARING_SIM WORK_DIR mpi|nompi
#
# Exit 77 (skipped, with the reason) when bearing-sim was built without MPI or mpirun is missing.
set -euo pipefail
sim=$1
work=$2
built=$3

if [[ $built != mpi ]]; then
  echo "skipped: bearing-sim was built without MPI (install mpi-default-dev and reconfigure)"
  exit 77
fi
if ! command -v mpirun >/dev/null; then
  echo "skipped: mpirun not found (Debian package mpi-default-bin)"
  exit 77
fi
# This test may run as root (containers) and on fewer cores than ranks.
flags=(--oversubscribe)
if [[ $(id -u) -eq 0 ]]; then flags+=(--allow-run-as-root); fi
mpi() { timeout 300 mpirun "${flags[@]}" "$@"; }

rm -rf "$work"
mkdir -p "$work"
sweep=(sweep --vary bearing.clearance=-20um:20um:3 --vary operation.speed=1000rpm:3000rpm:5
  --set solver.duration=0.05 --set solver.transient=0.01
  --set 'acoustics.microphones=[[0.5, "0 deg"], [1.0, "90 deg"]]' --quiet)

"$sim" "${sweep[@]}" --jobs 1 --out "$work/serial" >/dev/null
status=0
for run in "2 1" "2 2" "3 1"; do
  read -r ranks jobs <<<"$run"
  out=$work/np${ranks}_jobs${jobs}
  mpi -np "$ranks" "$sim" "${sweep[@]}" --jobs "$jobs" --out "$out" >"$out.stdout"
  if cmp "$work/serial/sweep.csv" "$out/sweep.csv"; then
    echo "ok: mpirun -np $ranks, --jobs $jobs: the same sweep.csv as --jobs 1"
  else
    echo "FAILED: mpirun -np $ranks, --jobs $jobs: sweep.csv differs from --jobs 1"
    status=1
  fi
  if [[ $(grep -c '^sweep: 15 cases, 5 failed' "$out.stdout") -ne 1 ]]; then
    echo "FAILED: mpirun -np $ranks: expected one summary line (rank 0's), got:"
    cat "$out.stdout"
    status=1
  fi
done

# An error on every rank (an unknown key) ends the run with an error, not a hang.
set +e
mpi -np 2 "$sim" sweep --vary operation.sped=1:2:2 --out "$work/bad" >"$work/bad.log" 2>&1
rc=$?
set -e
if [[ $rc -eq 0 || $rc -eq 124 ]]; then
  echo "FAILED: an unknown key under mpirun: exit $rc (0: no error, 124: hung)"
  cat "$work/bad.log"
  status=1
elif ! grep -q 'operation.sped' "$work/bad.log"; then
  echo "FAILED: an unknown key under mpirun: the message does not name it"
  cat "$work/bad.log"
  status=1
else
  echo "ok: an input error under mpirun ends every rank (exit $rc)"
fi
# A sweep killed under mpirun (SIGKILL to every process) and resumed under mpirun gives the file of
# an uninterrupted run: rank 0 tells the workers how many cases remain, so they map its case
# numbers to the same points.
many=(--vary operation.speed=1000rpm:3000rpm:150 --set solver.duration=0.1
      --set solver.transient=0.02)
"$sim" sweep "${many[@]}" --out "$work/whole" --jobs 1 --quiet >/dev/null
mpi -np 2 "$sim" sweep "${many[@]}" --out "$work/killed" --jobs 1 >/dev/null 2>&1 &
launcher=$!
for _ in $(seq 1 400); do
  if [[ -f $work/killed/.sweep.csv.partial ]] &&
     (($(wc -l <"$work/killed/.sweep.csv.partial") > 20)); then
    break
  fi
  sleep 0.05
done
pkill -9 -f -- "--out $work/killed" || true
wait "$launcher" 2>/dev/null || true
if [[ -f $work/killed/sweep.csv ]]; then
  echo "FAILED: the sweep to kill finished before it was killed; make it longer"
  status=1
else
  mpi -np 2 "$sim" sweep --resume "$work/killed" --jobs 1 >"$work/resume.log" 2>&1 || true
  if cmp "$work/whole/sweep.csv" "$work/killed/sweep.csv"; then
    echo "ok: killed and resumed under mpirun: the same sweep.csv as an uninterrupted run"
  else
    echo "FAILED: killed and resumed under mpirun: sweep.csv differs"
    cat "$work/resume.log"
    status=1
  fi
  # Resumed again when finished (its record gone): every rank stops at once, exit 0, one line.
  stamp=$(stat -c "%y %s" "$work/killed/sweep.csv")
  set +e
  mpi -np 2 "$sim" sweep --resume "$work/killed" --jobs 1 >"$work/again.log" 2>&1
  rc=$?
  set -e
  if [[ $rc -eq 0 && $(grep -c "is complete: 150 cases" "$work/again.log") -eq 1 ]] &&
     cmp -s "$work/whole/sweep.csv" "$work/killed/sweep.csv" &&
     [[ $(stat -c "%y %s" "$work/killed/sweep.csv") == "$stamp" ]]; then
    echo "ok: a finished sweep resumed under mpirun: exit 0, said complete once, left as it was"
  else
    echo "FAILED: a finished sweep resumed under mpirun: exit $rc (124: hung)"
    cat "$work/again.log"
    status=1
  fi
fi
# With the envelope analysis the rows (envelopes and diagnosis) travel to rank 0 whole: the same
# sweep.csv as --jobs 1.
envelope=(sweep --vary bearing.clearance=-20um:20um:3 --vary operation.speed=1000rpm:3000rpm:2
  --set solver.duration=0.05 --set solver.transient=0.01 --set output.envelope_band=auto --quiet)
"$sim" "${envelope[@]}" --jobs 1 --out "$work/env1" >/dev/null
mpi -np 2 "$sim" "${envelope[@]}" --jobs 1 --out "$work/env2" >/dev/null
if cmp "$work/env1/sweep.csv" "$work/env2/sweep.csv" && grep -q diagnosis.family "$work/env1/sweep.csv"; then
  echo "ok: with the envelope analysis under mpirun: the same sweep.csv as --jobs 1"
else
  echo "FAILED: with the envelope analysis under mpirun: sweep.csv differs from --jobs 1"
  status=1
fi
# --save under mpirun: the workers' tables travel to rank 0, and sweep.h5 holds the same groups,
# datasets and attributes as a --jobs 1 sweep's (compared with h5py where it is installed).
save=(--vary operation.speed=1000rpm:3000rpm:6 --set solver.duration=0.05
      --set solver.transient=0.01 --save response,spectrum,summary --quiet)
if "$sim" sweep "${save[@]}" --out "$work/save1" --jobs 1 >/dev/null 2>"$work/save1.log"; then
  mpi -np 2 "$sim" sweep "${save[@]}" --out "$work/save2" --jobs 1 >/dev/null
  if ! cmp "$work/save1/sweep.csv" "$work/save2/sweep.csv"; then
    echo "FAILED: --save under mpirun: sweep.csv differs from --jobs 1"
    status=1
  elif /usr/bin/python3 -c "import h5py" 2>/dev/null; then
    if /usr/bin/python3 - "$work/save1/sweep.h5" "$work/save2/sweep.h5" <<'PY'
import sys, h5py, numpy as np
a, b = h5py.File(sys.argv[1]), h5py.File(sys.argv[2])
def attrs(o): return {k: (v.tolist() if hasattr(v, "tolist") else v) for k, v in o.attrs.items()}
same = attrs(a) == attrs(b) and list(a["cases"]) == list(b["cases"]) and len(a["cases"]) == 6
for g in a["cases"]:
    ga, gb = a["cases"][g], b["cases"][g]
    same &= attrs(ga) == attrs(gb) and list(ga) == list(gb)
    for d in ga:
        same &= ga[d][()].tobytes() == gb[d][()].tobytes() and attrs(ga[d]) == attrs(gb[d])
sys.exit(0 if same else 1)
PY
    then
      echo "ok: --save under mpirun: the same sweep.h5 (every group, dataset and attribute)"
    else
      echo "FAILED: --save under mpirun: sweep.h5 differs from --jobs 1"
      status=1
    fi
  else
    echo "ok: --save under mpirun: the same sweep.csv (sweep.h5 not compared: no h5py)"
  fi
else
  echo "skipped: --save (this bearing-sim was built without HDF5)"
fi
exit $status
