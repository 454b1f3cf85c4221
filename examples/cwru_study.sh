#!/usr/bin/env bash
# The CWRU-like fault study (examples/README.md §7): the 6205 of examples/cwru_6205_outer.toml at
# 1797 rpm with its 0.533 mm spall on the outer race (the file as it is), moved to the inner race
# and to a ball, and the bearing without a spall but with 0.3/0.5 um of inner/outer waviness; each
# run's envelope spectrum and diagnosis, and a table of its lines against the CWRU data set's
# published defect frequencies. Usage, from anywhere:
#
#     examples/cwru_study.sh [OUTDIR]    # default: out/studies/cwru (relative to cwd)
#
# Environment: BEARING_SIM (default build/lumped/bearing-sim of this repository). About 2 s.
# Writes OUTDIR/{outer,inner,ball,healthy}/ (run folders) and .log (their summaries),
# OUTDIR/table.md and, when
# /usr/bin/python3 has matplotlib, OUTDIR/cwru_spectra.png.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(dirname "$here")
out=${1:-out/studies/cwru}
sim=${BEARING_SIM:-$root/build/lumped/bearing-sim}
case_file=$here/cwru_6205_outer.toml
mkdir -p "$out"

"$sim" run "$case_file" --quiet --out "$out/outer" > "$out/outer.log"
"$sim" run "$case_file" --quiet --out "$out/inner" > "$out/inner.log" \
  --set defects.0.location=inner --set defects.0.position=0
"$sim" run "$case_file" --quiet --out "$out/ball" > "$out/ball.log" \
  --set defects.0.location=ball --set defects.0.ball=0 --set defects.0.position=0
# Healthy: the [[defects]] entry made harmless is not the same as none, so a case without it.
sed '/^\[\[defects\]\]/,/^depth/d' "$case_file" > "$out/healthy.toml"
cat >> "$out/healthy.toml" <<'TOML'

[[waviness.inner]]
order = 8
amplitude = "0.3 um"
[[waviness.outer]]
order = 10
amplitude = "0.5 um"
TOML
"$sim" run "$out/healthy.toml" --quiet --out "$out/healthy" > "$out/healthy.log"

/usr/bin/python3 "$here/plot_cwru.py" "$out"
