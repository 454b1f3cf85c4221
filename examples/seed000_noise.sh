#!/usr/bin/env bash
# Seed 000 (Zhang, Yang & An 2018) noise study: the SPL of the 608 at point A (10 mm from the
# bearing centre) for every source model and summation, and the sweeps of its Figs. 15-20 (wave
# number, waviness amplitude, speed, load, ball-size error band). examples/README.md §5 discusses
# the tables against the paper. Usage, from anywhere:
#
#     examples/seed000_noise.sh [OUTDIR]      # default: out/studies (relative to the current dir)
#
# Environment: BEARING_SIM (default build/lumped/bearing-sim of this repository). About 30 s on
# one core. Writes OUTDIR/seed000/<study>.csv (value, spl_total, spl_ring, spl_balls, jumps) and
# run folders, and prints the tables (run_studies.sh calls it and keeps them in tables.txt).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=examples/studies_lib.sh
source "$here/studies_lib.sh"
root=$(dirname "$here")
out=${1:-out/studies}
sim=${BEARING_SIM:-$root/build/lumped/bearing-sim}
[[ -x $sim ]] || { echo "seed000_noise.sh: $sim not found; build first (bash setup.sh, see the top-level README.md)" >&2; exit 2; }
mkdir -p "$out/seed000"
d=$(cd "$out/seed000" && pwd)
case0=$here/seed000_608_quasistatic.toml

# value KEY FILE [INDEX]: a number of summary.json: "KEY":<number>, the INDEX-th (1-based) match.
value() {
  tr -d ' \n' <"$2" | grep -oE "\"$1\":(-?[0-9.eE+-]+|null)" | sed -n "${3:-1}p" | cut -d: -f2
}
# levels DIR [MIC]: spl_total spl_ring spl_balls of microphone MIC (1-based) of a run folder.
levels() {
  local s=$1/summary.json m=${2:-1}
  echo "$(value spl_total "$s" "$m") $(value spl_ring "$s" "$m") $(value spl_balls "$s" "$m")"
}
run() { "$sim" run "$case0" --quiet "$@" >/dev/null; }
point_a=(--set 'acoustics.microphones=[["10 mm", "-90 deg"]]')

# study NAME LABEL VALUE... -- SET-TEMPLATE...: one run per value at point A; "@" in the templates
# is replaced by the value. Writes NAME.csv and prints the table, with the ring's vertical
# displacement and acceleration RMS (the ring's near field follows its acceleration).
study() {
  local name=$1 label=$2
  shift 2
  local values=()
  while [[ $1 != -- ]]; do values+=("$1"); shift; done
  shift
  echo "value,spl_total,spl_ring,spl_balls,jumps,y_rms,ay_rms" >"$d/$name.csv"
  printf "%14s %10s %10s %10s %6s %11s %11s\n" "$label" "total[dB]" "ring[dB]" "balls[dB]" jumps \
    "y.rms[um]" "ay.rms"
  for v in "${values[@]}"; do
    local sets=()
    for t in "$@"; do sets+=(--set "${t//@/$v}"); done
    run "${point_a[@]}" "${sets[@]}" --out "$d/$name/$v"
    read -r tot ring balls <<<"$(levels "$d/$name/$v")"
    local jumps
    jumps=$(value jumps "$d/$name/$v/summary.json")
    local y ay
    y=$(stat "$d/$name/$v" y rms)
    ay=$(stat "$d/$name/$v" ay rms)
    echo "$v,$tot,$ring,$balls,$jumps,$y,$ay" >>"$d/$name.csv"
    printf "%14s %10.2f %10.2f %10.2f %6d %11.4f %11.4g\n" "$v" "$tot" "$ring" "$balls" "$jumps" \
      "$(awk -v v="$y" 'BEGIN { print v * 1e6 }')" "$ay"
  done
}

echo "=== Seed 000 (Zhang, Yang & An 2018): SPL of the 608 at point A, 720 rpm, 50 N"
echo "Case: seed000_608_quasistatic.toml (waviness order 7, 0.5 um on each race, ball errors band"
echo "2 um seed 1: assumed, see its header). SPL = 20 log10(p_rms/20 uPa), p_rms over 1 s (eq. 27)."
echo "Band 1 Hz ... 8 kHz. Microphones 10 mm from the centre at four directions (the paper gives the"
echo "distance only). Paper: 29.8 dB (its Fig. 14 average); measurements it cites: 27.8 and 29.4 dB."
echo
printf "%-38s %-10s %8s %8s %8s %8s   %s\n" "ring / ball source" summation "-90deg" "0deg" \
  "90deg" "180deg" "(ring, balls at -90deg)"
for ring in cylinder-dipole paper; do
  for ball in oscillating-sphere pulsating-sphere paper; do
    for sum in coherent energetic; do
      r=$d/sources/$ring.$ball.$sum
      run --set "acoustics.ring_source=$ring" --set "acoustics.ball_source=$ball" \
        --set "acoustics.summation=$sum" --out "$r"
      line=$(printf "%-38s %-10s" "$ring / $ball" "$sum")
      for m in 1 2 3 4; do line+=$(printf " %8.2f" "$(value spl_total "$r/summary.json" "$m")"); done
      read -r _ rl bl <<<"$(levels "$r" 1)"
      echo "$line   ($(printf "%.2f, %.2f" "$rl" "$bl"))"
    done
  done
done
r=$d/sources/2dof
run --set model.kind=2dof --set solver.method=rk8pd --out "$r"
line=$(printf "%-38s %-10s" "2-DOF model (rk8pd), defaults" coherent)
for m in 1 2 3 4; do line+=$(printf " %8.2f" "$(value spl_total "$r/summary.json" "$m")"); done
echo "$line"
echo "(seed 000's own choices: ring 'paper' = its eq. 19 as derived, ball 'paper' = its eq. 23,"
echo " energetic sum = its eq. 26; defaults: exact cylinder dipole, oscillating sphere, coherent.)"

echo
echo "Fig. 15-16: wave number N_w on both races (0.5 um each), point A (-90 deg)"
study order "N_w" 5 6 7 8 9 -- waviness.inner.0.order=@ waviness.outer.0.order=@
echo
echo "Fig. 17: waviness amplitude on both races [um], point A"
study amplitude "A[um]" 0 0.1 0.25 0.5 1 1.5 2 -- waviness.inner.0.amplitude=@um \
  waviness.outer.0.amplitude=@um
echo
echo "Fig. 18: speed [rpm], point A"
study speed "n[rpm]" 180 360 720 1440 2880 5760 -- operation.speed=@rpm
echo
echo "Fig. 19: radial load [N] (F_min = 12 N: below it no continuous orbit exists), point A"
study load "F[N]" 20 35 50 100 200 400 -- 'operation.load=[0, -@]'
echo
echo "Fig. 20: ball-size error band [um] (seed 1: the same draw scaled), point A"
study band "band[um]" 0 1 1.5 2 2.5 3 -- ball_errors.band=@um
echo
echo "Fig. 20 without waviness: what the ball-size errors alone do [um], point A"
study band_only "band[um]" 0 1 1.5 2 2.5 3 -- ball_errors.band=@um waviness.inner.0.amplitude=0um \
  waviness.outer.0.amplitude=0um
