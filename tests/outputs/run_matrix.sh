#!/usr/bin/env bash
# A refactoring's safety net: runs a fixed matrix of bearing-sim commands (every example, every
# model kind with every method, every output flag, acoustics, sweeps and ~30 input errors) and
# keeps every result file, stdout, stderr and exit code, so that two builds can be compared byte
# for byte:
#
#     tests/outputs/run_matrix.sh OLD/bearing-sim /tmp/old
#     tests/outputs/run_matrix.sh build/lumped/bearing-sim /tmp/new
#     diff -r /tmp/old /tmp/new
#
# About 5 s. Not part of ctest: its expected output is whatever the previous build wrote.
#
#     tests/outputs/run_matrix.sh BEARING_SIM OUTDIR finer FROM      each run and sweep at its
#     tests/outputs/run_matrix.sh BEARING_SIM OUTDIR perturbed FROM  integrator's finer setting, or
#     tests/outputs/run_matrix.sh BEARING_SIM OUTDIR perturbed-down FROM  with a round-off
#                                                                    perturbation (up or down)
# read from FROM (a matrix of the same build): bench/output_change.sh's reference runs (issue 42).
set -u
[[ $# -eq 2 || ( $# -eq 4 && ( $3 == finer || $3 == perturbed || $3 == perturbed-down ) ) ]] ||
  { echo "usage: $0 BEARING_SIM OUTDIR [finer|perturbed|perturbed-down FROM]" >&2; exit 2; }
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
sim=$(cd "$(dirname "$1")" && pwd)/$(basename "$1"); out=$2; ex=$root/examples
variant=${3:-}; from=${4:-}
extra() {  # extra NAME ARGS...: the variant's --set arguments for this command (none without one)
  [[ -n $variant ]] || return 0
  /usr/bin/python3 "$root/bench/output_change.py" "$variant" "$from/$1" "${@:2}"
}
rm -rf "$out"; mkdir -p "$out"
n=0
go() {  # go NAME ARGS...   (run gets --out $out/NAME)
  local name=$1; shift
  local cmd=$1; shift
  if [[ $cmd == run || $cmd == sweep ]]; then
    local more
    mapfile -t more < <(extra "$name" "$@")
    set -- "$@" "${more[@]}"
  fi
  if [[ $cmd == run ]]; then
    (cd "$root" && "$sim" run "$@" --out "$out/$name" --quiet >"$out/$name.stdout" 2>"$out/$name.stderr"; echo $? >"$out/$name.rc")
  elif [[ $cmd == sweep ]]; then
    (cd "$root" && "$sim" sweep "$@" --out "$out/$name" --quiet --jobs 2 >"$out/$name.stdout" 2>"$out/$name.stderr"; echo $? >"$out/$name.rc")
  else
    (cd "$root" && "$sim" $cmd "$@" >"$out/$name.stdout" 2>"$out/$name.stderr"; echo $? >"$out/$name.rc")
  fi
  n=$((n+1))
}
# every example as written, and its info (text and JSON)
for f in "$ex"/*.toml; do
  b=$(basename "$f" .toml)
  go "run_$b" run "$f"
  go "run_${b}_json" run "$f" --json --set solver.duration=0.3 --set solver.transient=0.1
  go "info_$b" info "$f"
  go "infojson_$b" info "$f" --json
done
go run_default run
go info_default info
go presets presets
go help_run run --help
go help_info info --help
go help_sweep sweep --help
S="--set solver.duration=0.15 --set solver.transient=0.05"
for m in rk4 rkf45 rk8pd rk8pd-events newmark bdf; do
  for k in 2dof 3dof; do
    go "m_${m}_${k}" run $S --set solver.method=$m --set model.kind=$k --set operation.axial_load=100 --set output.ball_loads=true --set output.ball_approach=true --set output.ball_motion=true --set output.window=flattop
  done
  go "m_${m}_balls" run "$ex/seed004_6304.toml" $S --set solver.method=$m --set solver.dt=2us --set output.ball_dynamics=true --set output.ball_loads=true --set output.ball_approach=true --set output.ball_motion=true --set cage.slip=0.02
done
go balls_axial run "$ex/seed004_6304.toml" $S --set operation.axial_load=300 --set output.ball_dynamics=true --set output.window=rectangular --set output.peaks=3
go qs_full run "$ex/seed000_608_quasistatic.toml" $S --set output.ball_loads=true --set output.ball_approach=true --set acoustics.summation=energetic --set acoustics.ball_source=paper --set acoustics.ring_source=paper
go qs_pulsating run "$ex/seed000_608_quasistatic.toml" $S --set acoustics.ball_source=pulsating-sphere --set acoustics.ring_source=none
go tvds run "$ex/seed002_tvds.toml" $S --set model.waviness_stiffness=true --set model.contact=hamrock-brewe
go harris run $S --set model.contact=harris-table --set operation.unbalance=1e-5 --set operation.gravity=true
go calibrated run "$ex/seed003_6308_calibrated.toml" $S --set model.kind=3dof --set operation.axial_load=50
go band run $S --set ball_errors.band=2um --set ball_errors.seed=7 --set model.waviness_stiffness=true
go npy run "$ex/seed000_608_quasistatic.toml" $S --set output.format=npy --set output.envelope_band=auto --set output.ball_loads=true
go sweep1 sweep "$ex/seed003_6308.toml" $S --vary operation.speed=1000rpm:3000rpm:3 --vary bearing.balls=7:9:2
go sweep_noise sweep "$ex/seed000_608_quasistatic.toml" $S --vary operation.load.1=-60:-40:2
go sweep_fail sweep $S --vary solver.dt=1us:2ms:2
# the housing and its sensor channels (2dof, 3dof; info lists the coupled modes)
H="--set housing.mass=1kg --set housing.frequency=3kHz"
go housing_2dof run "$ex/cwru_6205_outer.toml" $S $H --set output.ball_loads=true
go housing_3dof run $S $H --set model.kind=3dof --set operation.axial_load=100 --set solver.method=newmark
go info_housing info "$ex/cwru_6205_outer.toml" $H --json
# random slip ([slip], issue 40): every kind, the acoustics' balls, a spall, info, its errors
go slip_2dof run $S --set slip.rms=0.01 --set output.ball_motion=true --set output.ball_loads=true
go slip_3dof run $S --set model.kind=3dof --set operation.axial_load=100 --set slip.rms=0.02 --set slip.seed=3 --set output.ball_motion=true --set solver.method=rk8pd
go slip_balls run "$ex/seed004_6304.toml" $S --set solver.dt=2us --set cage.slip=0.02 --set slip.rms=0.01 --set output.ball_dynamics=true
go slip_qs run "$ex/seed000_608_quasistatic.toml" $S --set slip.rms=0.01 --set acoustics.ball_source=paper
go slip_spall run "$ex/cwru_6205_outer.toml" $S --set slip.rms=0.01 --set slip.correlation_time=2ms $H
go slip_info info --set slip.rms=0.01 --json
go e_slip_rms run --set slip.rms=0.2
go e_slip_fine run --set slip.rms=0.01 --set slip.correlation_time=1us --set solver.duration=300
# the structure's modes ([housing] modes, issue 40): the example end shield with its sensor
go modes_2dof run "$ex/cwru/outer_shield.toml" $S
go modes_3dof run "$ex/cwru/outer_shield.toml" $S --set model.kind=3dof --set operation.axial_load=100
go info_modes info "$ex/cwru/outer_shield.toml" --json
# input errors (messages and exit codes)
go e_housing_balls run "$ex/seed004_6304.toml" $H
go e_housing_freq run --set housing.mass=1kg
go e_housing_zeta run $H --set housing.damping_ratio=1
go e_kind run --set model.kind=4dof
go e_method run --set solver.method=euler
go e_contact run --set model.contact=calibratd
go e_window run --set output.window=hamming
go e_slip run "$ex/seed004_6304.toml" --set cage.slip=1
go e_cage run --set cage.slip=0.1
go e_axial run --set rotor.axial_mass=0
go e_mass run --set rotor.mass=-1
go e_unknown run --set bearing.bals=9
go e_unknown2 run --set solvr.dt=1us
go e_dt run --set solver.dt=2ms
go e_balls run --set bearing.balls=2
go e_speed run --set operation.speed=-5rpm
go e_mic run "$ex/seed000_608_quasistatic.toml" --set 'acoustics.microphones=[["4 mm", "0 deg"]]'
go e_src run "$ex/seed000_608_quasistatic.toml" --set acoustics.ring_source=monopole
go e_none run "$ex/seed000_608_quasistatic.toml" --set acoustics.ring_source=none --set acoustics.ball_source=none
go e_bd run --set output.ball_dynamics=true
go e_unit run --set bearing.clearance=5
go e_wav run --set waviness.inner.0.order=0
go e_calib run --set model.contact=calibrated
go e_peaks run --set output.peaks=2000
go e_format run --set output.format=npz
go e_rk4 run "$ex/seed004_6304.toml" --set solver.dt=20us
go e_bmass run "$ex/seed004_6304.toml" --set ball.mass=0
go e_friction run "$ex/seed004_6304.toml" --set cage.friction=2
go e_vary sweep --vary model.kind=1:2:2
# paths differ between runs: normalise them
sed -i -e "s#$out#OUT#g" -e "s#$sim#SIM#g" "$out"/*.stdout "$out"/*.stderr
echo "$n commands"
