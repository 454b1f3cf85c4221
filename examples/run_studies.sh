#!/usr/bin/env bash
# Runs every reproduction study of examples/ and prints its tables (examples/README.md discusses
# them against the papers). Usage, from anywhere:
#
#     examples/run_studies.sh [OUTDIR]        # default: out/studies (relative to the current dir)
#
# Environment: BEARING_SIM (default build/lumped/bearing-sim of this repository), JOBS (parallel
# cases per sweep and runs, default 2). About 2.5 minutes on 2 cores (seed 000's noise study, 70
# runs of seed000_noise.sh, takes ~20 s and seed 004's, seed004_studies.sh, ~40 s at the end).
# Writes OUTDIR/<study>/... (sweep.csv, run folders; seed 004 in OUTDIR/seed004/) and
# OUTDIR/tables.txt (what is printed), and PNG plots in OUTDIR/plots/ when
# /usr/bin/python3 has matplotlib (Debian: python3-matplotlib); otherwise plotting is skipped.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=examples/studies_lib.sh
source "$here/studies_lib.sh"
root=$(dirname "$here")
out=${1:-out/studies}
sim=${BEARING_SIM:-$root/build/lumped/bearing-sim}
jobs=${JOBS:-2}
[[ -x $sim ]] || { echo "run_studies.sh: $sim not found; build first (bash setup.sh, see the top-level README.md)" >&2; exit 2; }
mkdir -p "$out"
out=$(cd "$out" && pwd)
start=$SECONDS

sweep() { "$sim" sweep "$@" --jobs "$jobs" --quiet >/dev/null; }
run() { "$sim" run "$@" --quiet >/dev/null; }


exec > >(tee "$out/tables.txt")

# ------------------------------------------------------------------------------------------------
echo "=== Seed 001 (Purohit & Purohit): number of balls (Fig. 3) and preload (Fig. 4), 3-DOF Newmark"
c1=$here/seed001_balls_preload.toml
d=$out/seed001
sweep "$c1" --vary bearing.balls=5:15:11 --out "$d/balls_P10"
sweep "$c1" --set operation.axial_load=0N --vary bearing.balls=5:15:11 --out "$d/balls_P0"
sweep "$c1" --set bearing.balls=8 --vary operation.axial_load=0N:30N:7 --out "$d/preload_Z8"
sweep "$c1" --set bearing.balls=8 --vary operation.axial_load=0.25N:1N:4 --out "$d/preload_Z8_fine"
sweep "$c1" --set bearing.balls=8 --vary operation.axial_load=50N:100N:2 --out "$d/preload_Z8_heavy"
ftf=$("$sim" info "$c1" --json | tr -d ' \n' | grep -oE '"ftf":[-+0-9.eE]+' | cut -d: -f2)
echo
echo "Fig. 3: number of balls, W = 6 N, 5000 rpm; Z*FTF at alpha = 0 (FTF = $ftf Hz; the preload"
echo "angle shifts it by < 0.1 %). Displacements in m, acceleration in m/s^2 (RMS about the mean)."
printf "%3s %7s | %-44s | %-44s\n" "" "" "---------- preload P_l = 10 N ----------" \
  "---------- no preload (P_l = 0) ---------"
printf "%3s %7s | %10s %10s %10s %10s | %10s %10s %10s %8s\n" Z "Z*FTF" x.ptp y.ptp z.ptp y.rms \
  x.ptp y.ptp ay.rms "y.peak"
paste <(col "$d/balls_P10/sweep.csv" bearing.balls) \
  <(col "$d/balls_P10/sweep.csv" x.ptp) <(col "$d/balls_P10/sweep.csv" y.ptp) \
  <(col "$d/balls_P10/sweep.csv" z.ptp) <(col "$d/balls_P10/sweep.csv" y.rms) \
  <(col "$d/balls_P0/sweep.csv" x.ptp) <(col "$d/balls_P0/sweep.csv" y.ptp) \
  <(col "$d/balls_P0/sweep.csv" ay.rms) <(col "$d/balls_P0/sweep.csv" y.peak_frequency) |
  awk -v f="$ftf" '{printf "%3d %7.1f | %10.3g %10.3g %10.3g %10.3g | %10.3g %10.3g %10.4f %8.1f\n",
                    $1, $1 * f, $2, $3, $4, $5, $6, $7, $8, $9}'
echo
echo "Fig. 4: axial preload, Z = 8 (the text's N_b = 8), W = 6 N, 5000 rpm (BPF = 8*FTF = 284.2 Hz)"
printf "%8s %10s %10s %10s %10s %10s %10s %9s\n" "P_l[N]" x.ptp y.ptp z.ptp y.rms ay.rms az.rms \
  "y.peak"
for s in preload_Z8 preload_Z8_fine preload_Z8_heavy; do
  paste <(col "$d/$s/sweep.csv" operation.axial_load) <(col "$d/$s/sweep.csv" x.ptp) \
    <(col "$d/$s/sweep.csv" y.ptp) <(col "$d/$s/sweep.csv" z.ptp) <(col "$d/$s/sweep.csv" y.rms) \
    <(col "$d/$s/sweep.csv" ay.rms) <(col "$d/$s/sweep.csv" az.rms) \
    <(col "$d/$s/sweep.csv" y.peak_frequency)
done | sort -g -k1,1 |
  awk '{printf "%8.2f %10.3g %10.3g %10.3g %10.3g %10.3g %10.3g %9.1f\n", $1,$2,$3,$4,$5,$6,$7,$8}'
echo
if /usr/bin/python3 -c "" 2>/dev/null; then
  echo "Linearised natural frequencies and BPF (examples/seed001_natural_frequencies.py):"
  /usr/bin/python3 "$here/seed001_natural_frequencies.py" "$sim"
else
  echo "(no /usr/bin/python3: natural-frequency table skipped)"
fi

# ------------------------------------------------------------------------------------------------
echo
echo "=== Seed 002 (Shao & Liu): RMS acceleration vs waviness order, TVD vs TVDS, 6308, 20 N, 2000 rpm"
c2=$here/seed002_tvds.toml
d=$out/seed002
psi=0.25268025514207865     # asin(2/8), as in the case file
psi_pert=0.2526812551420786 # psi + 1e-6 rad: moves the profile by 8 pm
run "$c2" --set waviness.inner.0.amplitude=0um --out "$d/perfect"
for race in inner outer; do
  if [[ $race == inner ]]; then other=(); else other=(--set waviness.inner.0.amplitude=0um); fi
  for amp in 8um 0.5um; do
    base=(--set "waviness.$race.0.amplitude=$amp" "${other[@]}")
    v=(--vary "waviness.$race.0.order=7:25:19")
    sweep "$c2" "${base[@]}" "${v[@]}" --out "$d/${race}_${amp}_tvd"
    sweep "$c2" "${base[@]}" --set model.waviness_stiffness=true "${v[@]}" --out "$d/${race}_${amp}_tvds"
    sweep "$c2" "${base[@]}" --set "waviness.$race.0.phase=${psi_pert}rad" "${v[@]}" \
      --out "$d/${race}_${amp}_tvd_psi"
  done
done
echo
echo "Perfect bearing (Table 1 case 1): ax.rms = $(stat "$d/perfect" ax rms), ay.rms = $(stat "$d/perfect" ay rms) m/s^2"
for race in inner outer; do
  for amp in 8um 0.5um; do
    p=$d/${race}_${amp}
    echo
    echo "$race race, A = ${amp/um/ um}, psi = asin(2/8) (* = Table 1 order; min/MAX = local extremum of TVD ay.rms)."
    echo "dTVDS = (TVDS - TVD)/TVD; dpsi = same TVD run with psi + 1e-6 rad (sensitivity, not physics)."
    printf "%5s %9s %9s %8s %9s %8s | %9s %9s %8s | %9s %9s %4s\n" N "TVD ay" "TVDS ay" dTVDS \
      "psi' ay" dpsi "TVD ax" "TVDS ax" dTVDS "y.ptp" "ay.peak" ""
    paste <(col "${p}_tvd/sweep.csv" "waviness.$race.0.order") \
      <(col "${p}_tvd/sweep.csv" ay.rms) <(col "${p}_tvds/sweep.csv" ay.rms) \
      <(col "${p}_tvd_psi/sweep.csv" ay.rms) <(col "${p}_tvd/sweep.csv" ax.rms) \
      <(col "${p}_tvds/sweep.csv" ax.rms) <(col "${p}_tvd/sweep.csv" y.ptp) \
      <(col "${p}_tvd/sweep.csv" ay.peak_frequency) |
      awk '{ n[NR]=$1; a[NR]=$2; b[NR]=$3; c[NR]=$4; x[NR]=$5; xs[NR]=$6; y[NR]=$7; pk[NR]=$8 }
           END { for (i = 1; i <= NR; i++) {
                   t = (n[i] % 8 == 0 || n[i] % 8 == 1 || n[i] % 8 == 7) ? "*" : " "
                   e = ""
                   if (i > 1 && i < NR && a[i] < a[i-1] && a[i] < a[i+1]) e = "min"
                   if (i > 1 && i < NR && a[i] > a[i-1] && a[i] > a[i+1]) e = "MAX"
                   printf "%4d%s %9.3f %9.3f %+7.2f%% %9.3f %+7.2f%% | %9.3f %9.3f %+7.2f%% | %9.3g %9.1f %4s\n",
                     n[i], t, a[i], b[i], 100*(b[i]-a[i])/a[i], c[i], 100*(c[i]-a[i])/a[i],
                     x[i], xs[i], 100*(xs[i]-x[i])/x[i], y[i], pk[i], e } }'
  done
done

for race in inner outer; do
  if [[ $race == inner ]]; then other=(); else other=(--set waviness.inner.0.amplitude=0um); fi
  sweep "$c2" "${other[@]}" --vary "waviness.$race.0.amplitude=1um:8um:8" \
    --vary "waviness.$race.0.order=7:25:19" --out "$d/${race}_amplitude_scan"
  echo
  echo "$race race, TVD: ay.rms [m/s^2] vs order (rows) and amplitude A (columns); per-ball gap 7 um."
  echo "Marks: - local minimum, + local maximum over the orders (at that amplitude)."
  paste -d, <(col "$d/${race}_amplitude_scan/sweep.csv" "waviness.$race.0.amplitude") \
    <(col "$d/${race}_amplitude_scan/sweep.csv" "waviness.$race.0.order") \
    <(col "$d/${race}_amplitude_scan/sweep.csv" ay.rms) |
    awk -F, '{ a = sprintf("%g", $1 * 1e6); if (!(a in seen)) { seen[a]; amps[++na] = a }
               if (!($2 in seenn)) { seenn[$2]; ords[++no] = $2 }; v[a, $2] = $3 }
         END { printf "%5s", "N"; for (i = 1; i <= na; i++) printf " %9s", "A=" amps[i] "um"; print ""
               for (j = 1; j <= no; j++) {
                 n = ords[j]; printf "%4d%s", n, (n % 8 == 0 ? "*" : " ")
                 for (i = 1; i <= na; i++) {
                   a = amps[i]; m = " "
                   if (j > 1 && j < no && v[a, n] < v[a, ords[j-1]] && v[a, n] < v[a, ords[j+1]]) m = "-"
                   if (j > 1 && j < no && v[a, n] > v[a, ords[j-1]] && v[a, n] > v[a, ords[j+1]]) m = "+"
                   printf " %8.2f%s", v[a, n], m }
                 print "" } }'
done

# ------------------------------------------------------------------------------------------------
echo
echo "=== Seed 003 (Chen et al.) §4.3: waviness amplitude, order 7, P_d = 2 um, 20 N, 2000 rpm"
c3=$here/seed003_amplitude.toml
d=$out/seed003_amplitude
run "$c3" --set waviness.inner.0.amplitude=0um --out "$d/perfect"
sweep "$c3" --vary waviness.inner.0.amplitude=0.2um:1.2um:6 --out "$d/inner"
sweep "$c3" --set waviness.inner.0.amplitude=0um --vary waviness.outer.0.amplitude=0.2um:1.2um:6 \
  --out "$d/outer"
echo
echo "Perfect bearing: y.ptp = $(stat "$d/perfect" y ptp) m, ay.rms = $(stat "$d/perfect" ay rms) m/s^2"
for race in inner outer; do
  echo
  echo "$race race (Figs. $([[ $race == inner ]] && echo "10, 11" || echo "13, 14")): y peak-to-peak and ay RMS vs amplitude A"
  printf "%7s %10s %8s %10s %10s %10s %10s\n" "A[um]" "y.ptp[um]" "ptp/A" "ay.rms" "ax.rms" \
    "y.peak[Hz]" "ay.peak"
  paste <(col "$d/$race/sweep.csv" "waviness.$race.0.amplitude") <(col "$d/$race/sweep.csv" y.ptp) \
    <(col "$d/$race/sweep.csv" ay.rms) <(col "$d/$race/sweep.csv" ax.rms) \
    <(col "$d/$race/sweep.csv" y.peak_frequency) <(col "$d/$race/sweep.csv" ay.peak_frequency) |
    awk '{ a=$1*1e6; p=$2*1e6; printf "%7.2f %10.4f %8.3f %10.4f %10.4f %10.1f %10.1f\n", a, p, p/a, $3, $4, $5, $6
           n++; sa+=a; sp+=p; sr+=$3; saa+=a*a; sap+=a*p; sar+=a*$3 }
         END { den = n*saa - sa*sa
               printf "least squares: y.ptp = %.4f A %+.4f um;  ay.rms = %.4f A %+.4f m/s^2 (A in um)\n",
                 (n*sap - sa*sp)/den, (sp - (n*sap - sa*sp)/den*sa)/n,
                 (n*sar - sa*sr)/den, (sr - (n*sar - sa*sr)/den*sa)/n }'
done

# ------------------------------------------------------------------------------------------------
echo
echo "=== Seed 003 (Chen et al.) Table 3: measured inner-race waviness (orders 4-100), 6308, 20 N, 2000 rpm"
c4=$here/seed003_measured.toml
d=$out/seed003_measured
run "$c4" --out "$d/Pd2um"
run "$c4" --set bearing.clearance=14um --out "$d/Pd14um"
run "$c3" --set waviness.inner.0.amplitude=0um --set bearing.clearance=14um --out "$d/perfect_Pd14um"
cp -r "$out/seed003_amplitude/perfect" "$d/perfect_Pd2um" 2>/dev/null || true
printf "\n%-16s %10s %10s %10s %10s %10s %10s\n" case x.ptp y.ptp y.rms ax.rms ay.rms ay.kurt
for r in perfect_Pd2um Pd2um perfect_Pd14um Pd14um; do
  printf "%-16s %10.4g %10.4g %10.4g %10.4g %10.4g %10.4g\n" "$r" "$(stat "$d/$r" x ptp)" \
    "$(stat "$d/$r" y ptp)" "$(stat "$d/$r" y rms)" "$(stat "$d/$r" ax rms)" \
    "$(stat "$d/$r" ay rms)" "$(stat "$d/$r" ay kurtosis)"
done
if /usr/bin/python3 -c "" 2>/dev/null; then
  for r in Pd2um Pd14um; do
    echo
    echo "Largest spectral lines, measured waviness, $r: frequency [Hz] (origin): amplitude."
    echo "Origin: inner-race order N seen through a load zone fixed in space gives |N fr - p BPFO|"
    echo "(p = 1: N fr - BPFO = BPFI + (N - 8) fr); k.5fr / k.5BPFO: half orders (period 2)."
    /usr/bin/python3 - "$d/$r/summary.json" <<'EOF'
import json, sys
s = json.load(open(sys.argv[1]))
fr, bpfo = s["frequencies"]["shaft"], s["frequencies"]["bpfo"]


def tag(f):
    """Inner-race order N under a load zone fixed in space: |N fr - p BPFO|; else half orders."""
    for p in (1, 0, 2):
        for n in range(0 if p else 1, 101):
            if abs(f - abs(n * fr - p * bpfo)) < 0.5:
                pb = f"{p if p > 1 else ''}BPFO"
                return pb if n == 0 else f"{n}fr" + (f"-{pb}" if p else "")
    for base, name in ((fr, "fr"), (bpfo, "BPFO")):
        k = f / base - 0.5
        if abs(k - round(k)) * base < 0.5:
            return f"{round(k)}.5{name}"
    return "-"


for ch, unit in (("y", "um"), ("ay", "m/s^2")):
    scale = 1e6 if unit == "um" else 1.0
    cells = [f"{p['frequency']:.1f} ({tag(p['frequency'])}): {p['amplitude'] * scale:.3g}"
             for p in s["peaks"][ch][:8]]
    print(f"  {ch:2s} [{unit}]  " + "; ".join(cells))
EOF
  done
fi

# ------------------------------------------------------------------------------------------------
echo
BEARING_SIM=$sim "$here/seed000_noise.sh" "$out"

# ------------------------------------------------------------------------------------------------
echo
BEARING_SIM=$sim JOBS=$jobs PLOTS=0 "$here/seed004_studies.sh" "$out/seed004"

# ------------------------------------------------------------------------------------------------
echo
if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  /usr/bin/python3 "$here/plot_studies.py" "$out" &&
    /usr/bin/python3 "$here/plot_seed004.py" "$out/seed004" "$out/plots" &&
    echo "Plots: $out/plots/*.png"
else
  echo "Plots skipped: /usr/bin/python3 has no matplotlib (Debian: apt-get install python3-matplotlib)."
fi
echo "Done in $((SECONDS - start)) s; results in $out (tables: $out/tables.txt)."
