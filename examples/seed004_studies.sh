#!/usr/bin/env bash
# Seed 004 (cage slip and friction, SKF 6304) reproduction studies with the ball-DOF model
# (model.kind = "balls", examples/seed004_6304.toml): Table 2 against the 2-DOF model and a
# sensitivity table over the parameters seed 004 does not give; the friction force on ball 1
# (§4.2, Figs. 8-10); the x-acceleration statistics against cage slip, friction, speed and load
# (§4.3, Figs. 12-13). examples/README.md, "6. Seed 004", discusses the tables. Usage, from
# anywhere:
#
#     examples/seed004_studies.sh [OUTDIR]    # default: out/studies/seed004 (relative to cwd)
#
# Environment: BEARING_SIM (default build/lumped/bearing-sim of this repository), JOBS (parallel
# runs, default 2), PLOTS (default 1; 0 skips plot_seed004.py, as run_studies.sh does, which plots
# into its own OUTDIR/plots). About 40 s on 2 cores. Writes OUTDIR/{table2,sensitivity,fig8,fig9,
# fig10,fig12,fig13}/ (run folders, sweep.csv), OUTDIR/{sensitivity,fig9,fig10}.csv,
# OUTDIR/tables.txt (what is printed) and, when /usr/bin/python3 has matplotlib, OUTDIR/plots/*.png.
#
# Integration: the case file's RK4 at 5 us for Table 2 (mu_m = 0.01) and the sensitivity rows that
# do not say otherwise; RK4 at 2 us for every run of §4.2 and §4.3. The ball spin relaxes onto its
# traction equilibrium with rate L^2 (mu_m/Dv_m)(Q_i + Q_o)/J (L = D/2): 1.1e6 1/s at
# mu_m = 0.05, 2000 N, beyond RK4's 2.785/dt = 5.6e5 1/s at 5 us. RK4 then runs into a bounded,
# spurious limit cycle (the traction saturates at +-mu_m Q; ax RMS 33 instead of 0.39 m/s^2, no
# blow-up); bearing-sim's step check refuses such a step.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=examples/studies_lib.sh
source "$here/studies_lib.sh"
root=$(dirname "$here")
out=${1:-out/studies/seed004}
sim=${BEARING_SIM:-$root/build/lumped/bearing-sim}
jobs=${JOBS:-2}
[[ -x $sim ]] || { echo "seed004_studies.sh: $sim not found; build first (bash setup.sh, see the top-level README.md)" >&2; exit 2; }
mkdir -p "$out"
out=$(cd "$out" && pwd)
start=$SECONDS
case4=$here/seed004_6304.toml
short=(--set solver.duration=0.4s --set solver.transient=0.2s)   # friction runs: 0.2 s window
fine=(--set solver.dt=2us)                                      # see the header: spin relaxation

sweep() { "$sim" sweep "$@" --jobs "$jobs" --quiet >/dev/null; }
# runs: one `bearing-sim run` per line of stdin ("CASE --out DIR --set ..."; paths double-quoted),
# JOBS at a time. Fails if any run fails (its error is on stderr).
# shellcheck disable=SC2120
runs() {
  local line pids=() p rc=0
  while IFS= read -r line; do
    while (($(jobs -rp | wc -l) >= jobs)); do wait -n || true; done
    eval "set -- $line"
    "$sim" run --quiet "$@" >/dev/null &
    pids+=($!)
  done
  for p in "${pids[@]}"; do wait "$p" || rc=1; done
  return $rc
}
# cage_speed DIR: summary.json cage.speed [rad/s].
cage_speed() {
  tr -d ' \n' <"$1/summary.json" | grep -oE '"cage":\{[^}]*\}' | grep -oE '"speed":[-+0-9.eE]+' |
    cut -d: -f2
}
# peaks DIR: over t >= 0.2 s of response.csv: max Fi1, max |Fo1|, max Q1, max Qo1 [N].
peaks() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
           $1 >= 0.2 { fi = $c["Fi1"]; fo = $c["Fo1"]; fo = fo < 0 ? -fo : fo
                       if (fi > a) a = fi; if (fo > b) b = fo
                       if ($c["Q1"] > q) q = $c["Q1"]; if ($c["Qo1"] > qo) qo = $c["Qo1"] }
           END { printf "%.6g %.6g %.6g %.6g\n", a, b, q, qo }' "$1/response.csv"
}
# predicted MU SLIP RPM QMAX: mu_m Q_max min(1, s w_i r_i / (2 Dv_m)), the traction of a ball whose
# spin balances the two contacts (Q_i = Q_o: massless ball, no centrifugal load), Dv_m = 0.1 m/s,
# r_i = (d_m - D)/2 = 13.2375 mm. See examples/README.md §6.
predicted() {
  awk -v mu="$1" -v s="$2" -v n="$3" -v q="$4" 'BEGIN {
    v = s * n * 3.14159265358979 / 30 * 0.0132375 / (2 * 0.1); if (v > 1) v = 1
    printf "%.4g", mu * q * v }'
}

# Everything printed goes through main, tee'd into OUTDIR/tables.txt.
main() {
# ------------------------------------------------------------------------------------------------
echo "=== Seed 004 (cage slip and friction), SKF 6304: Table 2, 2000 rpm, 2000 N along +x, s_c = 0"
d=$out/table2
mkdir -p "$d"
# The 2-DOF counterpart: the same case without the [cage] and [ball] tables (the 2dof reader
# rejects them), model.kind = "2dof".
case2=$out/seed004_6304_2dof.toml
{
  echo "# Derived by examples/seed004_studies.sh from seed004_6304.toml: [cage] and [ball] removed,"
  echo "# model.kind = \"2dof\" (Sunnersjo's pure-rolling model with massless balls)."
  awk '/^\[/ { skip = ($0 == "[cage]" || $0 == "[ball]") } !skip' "$case4" |
    sed -E 's/^kind = "balls"/kind = "2dof"/'
} >"$case2"
runs <<EOF
"$case4" --out "$d/balls"
"$case2" --out "$d/2dof"
EOF
b_ptp=$(stat "$d/balls" ax ptp); b_rms=$(stat "$d/balls" ax rms); b_k=$(stat "$d/balls" ax kurtosis)
t_ptp=$(stat "$d/2dof" ax ptp); t_rms=$(stat "$d/2dof" ax rms); t_k=$(stat "$d/2dof" ax kurtosis)
echo
echo "Inner-ring x acceleration ax over 1 s after 0.2 s, 20 kHz (seed004_6304.toml as is: per-ball gap"
echo "15 um, conformity 0.52, mu_m = 0.01, Dv_m = 0.1 m/s, ball damping 350 N s/m, RK4 5 us)."
printf "RMS about the mean; ax mean = %.2g m/s^2 (balls), so the plain RMS is the same.\n" \
  "$(stat "$d/balls" ax mean)"
printf "%-40s %10s %10s %10s\n" "" "PTP[m/s^2]" "RMS[m/s^2]" kurtosis
printf "%-40s %10.2f %10.2f %10.2f\n" "seed 004, proposed model" 5.53 0.61 10.05
printf "%-40s %10.2f %10.2f %10.2f\n" "seed 004, Sunnersjo's model" 5.84 0.65 9.79
awk 'BEGIN { printf "%-40s %+9.1f%% %+9.1f%% %+9.1f%%\n", "seed 004, proposed vs Sunnersjo",
             100 * (5.53 / 5.84 - 1), 100 * (0.61 / 0.65 - 1), 100 * (10.05 / 9.79 - 1) }'
printf "%-40s %10.3f %10.4f %10.2f\n" "ours, balls (seed004_6304.toml)" "$b_ptp" "$b_rms" "$b_k"
printf "%-40s %10.3f %10.4f %10.2f\n" "ours, 2dof (same case, no cage/balls)" "$t_ptp" "$t_rms" "$t_k"
awk -v a="$b_ptp" -v b="$b_rms" -v c="$b_k" -v x="$t_ptp" -v y="$t_rms" -v z="$t_k" 'BEGIN {
  printf "%-40s %+9.1f%% %+9.1f%% %+9.1f%%\n", "ours, balls vs 2dof", 100 * (a / x - 1),
         100 * (b / y - 1), 100 * (c / z - 1)
  printf "%-40s %10.2f %10.2f %10.2f\n", "ours / paper, balls / proposed", a / 5.53, b / 0.61, c / 10.05
  printf "%-40s %10.2f %10.2f %10.2f\n", "ours / paper, 2dof / Sunnersjo", x / 5.84, y / 0.65, z / 9.79 }'

# ------------------------------------------------------------------------------------------------
# Sensitivity: one change at a time from the case file. name|balls settings|2dof settings ("-": the
# parameter does not exist in the 2-DOF model).
d=$out/sensitivity
mkdir -p "$d"
rows=(
  "baseline (seed004_6304.toml)||"
  "clearance 15 um (gap 7.5 um = P_d/2)|--set bearing.clearance=15um|--set bearing.clearance=15um"
  "clearance 13 um (d_o - d_i - 2D)|--set bearing.clearance=13um|--set bearing.clearance=13um"
  "conformity 0.51 (both races)|--set bearing.inner_conformity=0.51 --set bearing.outer_conformity=0.51|--set bearing.inner_conformity=0.51 --set bearing.outer_conformity=0.51"
  "conformity 0.53 (both races)|--set bearing.inner_conformity=0.53 --set bearing.outer_conformity=0.53|--set bearing.inner_conformity=0.53 --set bearing.outer_conformity=0.53"
  "contact hamrock-brewe|--set model.contact=hamrock-brewe|--set model.contact=hamrock-brewe"
  "contact harris-table (Harris [33])|--set model.contact=harris-table|--set model.contact=harris-table"
  "ball damping 35 N s/m|--set ball.damping=35|-"
  "ball damping 0, RK4 5 us (chaotic)|--set ball.damping=0|-"
  "ball damping 0, RK4 2 us (chaotic)|--set ball.damping=0 --set solver.dt=2us|-"
  "centrifugal ball load on|--set ball.centrifugal=true|-"
  "mu_m 0 (no friction)|--set cage.friction=0|-"
  "mu_m 0.05 (RK4 2 us)|--set cage.friction=0.05 --set solver.dt=2us|-"
  "Dv_m 0.01 m/s (RK4 1 us)|--set cage.slide_speed=0.01 --set solver.dt=1us|-"
  "Dv_m 1 m/s|--set cage.slide_speed=1|-"
  "output rate 100 kHz|--set solver.output_rate=100kHz|--set solver.output_rate=100kHz"
  "window 0.2 s (duration 0.4 s)|--set solver.duration=0.4s|--set solver.duration=0.4s"
  "transient 0.05 s (window 1 s)|--set solver.transient=0.05s --set solver.duration=1.05s|--set solver.transient=0.05s --set solver.duration=1.05s"
  "RK4 2 us|--set solver.dt=2us|--set solver.dt=2us"
)
i=0
for r in "${rows[@]}"; do
  IFS='|' read -r _ sb s2 <<<"$r"
  echo "\"$case4\" --out \"$d/$i.balls\" $sb"
  [[ $s2 == - ]] || echo "\"$case2\" --out \"$d/$i.2dof\" $s2"
  i=$((i + 1))
done | runs
echo
echo "Sensitivity of Table 2 to what seed 004 does not give or leaves ambiguous: one change at a time"
echo "from the case file; ax over the analysis window (m/s^2). '-': not a parameter of the 2-DOF model."
printf "%-38s | %8s %8s %7s | %8s %8s %7s\n" "" "balls:" "" "" "2dof:" "" ""
printf "%-38s | %8s %8s %7s | %8s %8s %7s\n" "change" PTP RMS kurt PTP RMS kurt
echo "name,balls_ptp,balls_rms,balls_kurtosis,2dof_ptp,2dof_rms,2dof_kurtosis" >"$out/sensitivity.csv"
i=0
for r in "${rows[@]}"; do
  IFS='|' read -r name _ s2 <<<"$r"
  bp=$(stat "$d/$i.balls" ax ptp); br=$(stat "$d/$i.balls" ax rms); bk=$(stat "$d/$i.balls" ax kurtosis)
  if [[ $s2 == - ]]; then
    tp=; tq=; tk=
    right=$(printf "%8s %8s %7s" - - -)
  else
    tp=$(stat "$d/$i.2dof" ax ptp); tq=$(stat "$d/$i.2dof" ax rms); tk=$(stat "$d/$i.2dof" ax kurtosis)
    right=$(printf "%8.3f %8.4f %7.2f" "$tp" "$tq" "$tk")
  fi
  printf "%-38s | %8.3f %8.4f %7.2f | %s\n" "$name" "$bp" "$br" "$bk" "$right"
  echo "\"$name\",$bp,$br,$bk,$tp,$tq,$tk" >>"$out/sensitivity.csv"
  i=$((i + 1))
done
printf "%-38s | %8.2f %8.2f %7.2f | %8.2f %8.2f %7.2f\n" "seed 004 Table 2 (proposed|Sunnersjo)" \
  5.53 0.61 10.05 5.84 0.65 9.79

# ------------------------------------------------------------------------------------------------
echo
echo "=== Seed 004 §4.2: friction force on ball 1 (output.ball_dynamics), 0.2 s after 0.2 s, RK4 2 us"
dyn=(--set output.ball_dynamics=true --set output.ball_loads=true)
d=$out/fig8
echo "\"$case4\" --out \"$d\" ${short[*]} ${fine[*]} ${dyn[*]} --set cage.slip=0.02 --set cage.friction=0.05" |
  runs
wca=$(cage_speed "$d")
wca_s=$(printf "%.4f" "$wca")
echo
echo "Fig. 8: s_c = 2 %, mu_m = 0.05, 2000 rpm, 2000 N. Ball 1 at theta = w_ca t (w_ca = $wca_s rad/s)"
echo "from +x, the load direction. Means over 10-degree bins (every bin holds samples of 2-3 passes);"
echo "Fi1, Fo1: friction on the ball at its inner / outer contact, + in the direction of rotation."
awk -F, -v w="$wca" '
  NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
  $1 >= 0.2 { th = ($1 * w) % 6.283185307179586; if (th > 3.141592653589793) th -= 6.283185307179586
              deg = th * 57.29577951308232; b = int((deg + 185) / 10)
              n[b]++; fi[b] += $c["Fi1"]; fo[b] += $c["Fo1"]; q[b] += $c["Q1"]; qo[b] += $c["Qo1"]
              wb[b] += $c["wb1"]
              if (deg < -80 || deg > 80) { a = $c["Fi1"] < 0 ? -$c["Fi1"] : $c["Fi1"]; if (a > out) out = a } }
  END { printf "%9s %9s %9s %9s %9s %10s %10s\n", "theta[deg]", "Q1[N]", "Qo1[N]", "Fi1[N]", "Fo1[N]",
               "Fi1/Q1", "wb1[rad/s]"
        for (b = 0; b <= 36; b++) { deg = b * 10 - 180; if (deg < -90 || deg > 90 || !n[b]) continue
          r = q[b] > 0 ? sprintf("%10.5f", fi[b] / q[b]) : sprintf("%10s", "-")
          printf "%9d %9.1f %9.1f %9.3f %9.3f %s %10.2f\n", deg, q[b] / n[b], qo[b] / n[b], fi[b] / n[b],
                 fo[b] / n[b], r, wb[b] / n[b] }
        printf "largest |Fi1| outside +-80 deg: %.3g N (the load zone ends near +-70 deg)\n", out }' \
  "$d/response.csv"
read -r f_in f_out q qo <<<"$(peaks "$d")"
echo "peak Fi1 = $f_in N, peak |Fo1| = $f_out N at Q1 max = $q N; predicted mu_m Q_max min(1, s w_i r_i /"
echo "(2 Dv_m)) = $(predicted 0.05 0.02 2000 "$q") N (Dv_i = -Dv_o = s w_i r_i / 2 = 0.0277 m/s)."

d=$out/fig9
for mu in 0.01 0.03 0.05; do
  for s in 0 0.01 0.02 0.03 0.04 0.05; do
    echo "\"$case4\" --out \"$d/mu${mu}_s$s\" ${short[*]} ${fine[*]} ${dyn[*]} --set cage.slip=$s --set cage.friction=$mu"
  done
done | runs
echo "mu_m,slip,Fi1_peak,Fo1_peak,Q1_max,Qo1_max,predicted" >"$out/fig9.csv"
echo
echo "Fig. 9: peak friction on ball 1 vs cage slip, 2000 rpm, 2000 N: peak Fi1 [N] (predicted, as above)"
printf "%6s | %-22s | %-22s | %-22s | %s\n" "s_c[%]" "mu_m = 0.01" "mu_m = 0.03" "mu_m = 0.05" "peak |Fo1| at 0.05"
for s in 0 0.01 0.02 0.03 0.04 0.05; do
  line=$(printf "%6g" "$(awk -v s="$s" 'BEGIN { print 100 * s }')")
  for mu in 0.01 0.03 0.05; do
    read -r f_in f_out q qo <<<"$(peaks "$d/mu${mu}_s$s")"
    p=$(predicted "$mu" "$s" 2000 "$q")
    echo "$mu,$s,$f_in,$f_out,$q,$qo,$p" >>"$out/fig9.csv"
    line+=$(printf " | %9.3f (%9.3f)  " "$f_in" "$p")
  done
  echo "$line | $(printf "%9.3f" "$f_out")"
done

d=$out/fig10
for w in 1000 2000 3000; do
  for n in 1000 2000 3000 4000 5000; do
    echo "\"$case4\" --out \"$d/W${w}_n$n\" ${short[*]} ${fine[*]} ${dyn[*]} --set cage.slip=0.02 --set cage.friction=0.01 --set operation.speed=${n}rpm --set operation.load=[$w,0]"
  done
done | runs
echo "load,speed_rpm,Fi1_peak,Fo1_peak,Q1_max,Qo1_max,predicted" >"$out/fig10.csv"
echo
echo "Fig. 10: peak friction on ball 1 vs speed, s_c = 2 %, mu_m = 0.01: peak Fi1 [N] (predicted), Q1 max [N]"
printf "%7s | %-28s | %-28s | %-28s\n" "n[rpm]" "W = 1000 N" "W = 2000 N" "W = 3000 N"
for n in 1000 2000 3000 4000 5000; do
  line=$(printf "%7d" "$n")
  for w in 1000 2000 3000; do
    read -r f_in f_out q qo <<<"$(peaks "$d/W${w}_n$n")"
    p=$(predicted 0.01 0.02 "$n" "$q")
    echo "$w,$n,$f_in,$f_out,$q,$qo,$p" >>"$out/fig10.csv"
    line+=$(printf " | %7.3f (%7.3f) %7.1f  " "$f_in" "$p" "$q")
  done
  echo "$line"
done

# ------------------------------------------------------------------------------------------------
echo
echo "=== Seed 004 §4.3: x-acceleration statistics (ax over 1 s after 0.2 s, 20 kHz, RK4 2 us)"
d=$out/fig12
sweep "$case4" "${fine[@]}" --vary cage.friction=0.01:0.05:3 --vary cage.slip=0:0.05:6 --out "$d/mu"
sweep "$case4" "${fine[@]}" --set cage.friction=0 --vary cage.slip=0:0.05:6 --out "$d/mu0"
echo
echo "Fig. 12: 2000 rpm, 2000 N; mu_m = 0 is a control (no friction: only the cage, and with it BPFO,"
echo "slows down). x.peak: the x displacement's largest line = BPFO = (1 - s_c) 85.80 Hz (eq. 26)."
printf "%6s %7s | %-22s | %-22s | %-22s | %-22s\n" "" "" "mu_m = 0 (control)" "mu_m = 0.01" \
  "mu_m = 0.03" "mu_m = 0.05"
printf "%6s %7s |%7s %7s %6s |%7s %7s %6s |%7s %7s %6s |%7s %7s %6s\n" "s_c[%]" "x.peak" PTP RMS kurt \
  PTP RMS kurt PTP RMS kurt PTP RMS kurt
{
  paste -d' ' <(col "$d/mu0/sweep.csv" cage.slip) <(col "$d/mu0/sweep.csv" x.peak_frequency) \
    <(col "$d/mu0/sweep.csv" ax.ptp) <(col "$d/mu0/sweep.csv" ax.rms) \
    <(col "$d/mu0/sweep.csv" ax.kurtosis)
  # the friction sweep: friction slowest, 6 slips per friction value
  paste -d' ' <(col "$d/mu/sweep.csv" ax.ptp) <(col "$d/mu/sweep.csv" ax.rms) \
    <(col "$d/mu/sweep.csv" ax.kurtosis)
} | awk 'NR <= 6 { s[NR] = $1; pk[NR] = $2; row[NR] = sprintf("|%7.3f %7.4f %6.2f ", $3, $4, $5); next }
         { k = (NR - 7) % 6 + 1; row[k] = row[k] sprintf("|%7.3f %7.4f %6.2f ", $1, $2, $3) }
         END { for (k = 1; k <= 6; k++) printf "%6g %7.2f %s\n", 100 * s[k], pk[k], row[k] }'

d=$out/fig13
for w in 1000 2000 3000; do
  sweep "$case4" "${fine[@]}" --set cage.slip=0.02 --set "operation.load=[$w,0]" \
    --vary operation.speed=1000rpm:5000rpm:5 --out "$d/W$w"
  sweep "$case4" "${fine[@]}" --set cage.slip=0.02 --set cage.friction=0 --set "operation.load=[$w,0]" \
    --vary operation.speed=1000rpm:5000rpm:5 --out "$d/W${w}_mu0"
done
echo
echo "Fig. 13: s_c = 2 %, mu_m = 0.01; last column group: ax RMS of the same runs without friction"
echo "(mu_m = 0). ax.peak: the largest line of ax [Hz] (the ring's x contact resonance, 2.4-3.0 kHz)."
printf "%7s | %-29s | %-29s | %-29s | %-20s\n" "" "W = 1000 N" "W = 2000 N" "W = 3000 N" "RMS, mu_m = 0"
printf "%7s |%7s %7s %6s %6s |%7s %7s %6s %6s |%7s %7s %6s %6s |%6s %6s %6s\n" "n[rpm]" PTP RMS kurt \
  ax.peak PTP RMS kurt ax.peak PTP RMS kurt ax.peak 1000N 2000N 3000N
paste -d' ' <(col "$d/W1000/sweep.csv" operation.speed) \
  <(col "$d/W1000/sweep.csv" ax.ptp) <(col "$d/W1000/sweep.csv" ax.rms) \
  <(col "$d/W1000/sweep.csv" ax.kurtosis) <(col "$d/W1000/sweep.csv" ax.peak_frequency) \
  <(col "$d/W2000/sweep.csv" ax.ptp) <(col "$d/W2000/sweep.csv" ax.rms) \
  <(col "$d/W2000/sweep.csv" ax.kurtosis) <(col "$d/W2000/sweep.csv" ax.peak_frequency) \
  <(col "$d/W3000/sweep.csv" ax.ptp) <(col "$d/W3000/sweep.csv" ax.rms) \
  <(col "$d/W3000/sweep.csv" ax.kurtosis) <(col "$d/W3000/sweep.csv" ax.peak_frequency) \
  <(col "$d/W1000_mu0/sweep.csv" ax.rms) <(col "$d/W2000_mu0/sweep.csv" ax.rms) \
  <(col "$d/W3000_mu0/sweep.csv" ax.rms) |
  awk '{ printf "%7.0f |%7.3f %7.4f %6.2f %6.0f |%7.3f %7.4f %6.2f %6.0f |%7.3f %7.4f %6.2f %6.0f |%6.3f %6.3f %6.3f\n",
         $1 * 30 / 3.14159265358979, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12, $13, $14, $15, $16 }'

# ------------------------------------------------------------------------------------------------
echo
if [[ ${PLOTS:-1} != 0 ]]; then
  if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
    /usr/bin/python3 "$here/plot_seed004.py" "$out" && echo "Plots: $out/plots/seed004_*.png"
  else
    echo "Plots skipped: /usr/bin/python3 has no matplotlib (Debian: apt-get install python3-matplotlib)."
  fi
fi
echo "Seed 004 done in $((SECONDS - start)) s; results in $out (tables: $out/tables.txt)."
}

main | tee "$out/tables.txt"
