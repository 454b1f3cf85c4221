#!/usr/bin/env python3
"""bearing-fem modes' modes.json drives bearing-sim's [housing] modes (issue 40): the writer and the
reader agree on the file's units and conventions.

Runs `bearing-fem modes` on the box seed (tests/fuzz/corpus/gmsh_mesh/box_tetrahedra_22.msh, mm,
6 modes) and a 6205 at rest under F = (20, -50) N on those modes. At rest the run settles to its
static equilibrium, where the seat carries the whole load, so each modal coordinate is
q_m = (s_x,m F_x + s_y,m F_y) / ω_m² and the seat and sensor displacements are Σ_m shape_m q_m,
computed here from modes.json alone. The slowest mode (~12 kHz, 5 % damping) has decayed by
exp(-0.05 · 2π · 12 kHz · 0.3 s) ~ e^-1100 at the end, so the only error left is the CSV's 12
significant digits: the bound is 1e-10 of the largest displacement. A reader that took the seat
in mm, the shapes of another mode or the sensor's axes swapped misses it by orders of magnitude.
The run's summary.json carries the file's frequencies and the sensor's point unchanged.

    modes_drive_lumped.py BEARING_FEM BEARING_SIM MESH WORK_DIR
"""
import csv
import json
import pathlib
import shutil
import subprocess
import sys

fem, sim, mesh, work = sys.argv[1], sys.argv[2], pathlib.Path(sys.argv[3]), pathlib.Path(sys.argv[4])
shutil.rmtree(work, ignore_errors=True)
work.mkdir(parents=True)
(work / "structure.toml").write_text(f'''mesh = "{mesh.resolve()}"
mesh_unit = "mm"
[material]
young = "210 GPa"
poisson = 0.3
density = "7850 kg/m^3"
[boundary]
fixed = ["fixed"]
seat = "seat"
[sensors]
top = [10, 10, 3]
''')
subprocess.run([fem, "modes", str(work / "structure.toml"), "--out", str(work / "modes"),
                "--count", "6", "--no-vtu", "--quiet"], check=True)
F = (20.0, -50.0)
(work / "case.toml").write_text(f'''[bearing]
preset = "6205"
[operation]
speed = "0 rpm"
load = ["{F[0]} N", "{F[1]} N"]
[housing]
modes = "modes/modes.json"
damping_ratio = 0.05
sensors = ["top"]
[solver]
duration = "0.3 s"
transient = "0.2 s"
''')
subprocess.run([sim, "run", str(work / "case.toml"), "--out", str(work / "run"), "--quiet"],
               check=True, stdout=subprocess.DEVNULL)

modes = json.loads((work / "modes" / "modes.json").read_text())
seat, top = modes["seat"], modes["sensors"][0]
q = []
for m, f in enumerate(modes["frequencies"]):
    omega = 2 * 3.141592653589793 * f
    q.append((seat["x"][m] * F[0] + seat["y"][m] * F[1]) / omega**2)
expected = {"x_seat": seat["x"], "y_seat": seat["y"], "x_top": top["x"], "y_top": top["y"],
            "z_top": top["z"]}
expected = {k: sum(s * qm for s, qm in zip(v, q)) for k, v in expected.items()}

with open(work / "run" / "response.csv") as f:
    rows = list(csv.reader(f))
last = dict(zip(rows[0], (float(v) for v in rows[-1])))
bound = 1e-10 * max(abs(v) for v in expected.values())
failures = []
for k, v in expected.items():
    print(f"{k}: run {last[k]:.12e} m, modal statics {v:.12e} m, difference {last[k] - v:.2e}")
    if abs(last[k] - v) > bound:
        failures.append(f"{k}: {last[k]} m against {v} m (bound {bound:.2e} m)")
housing = json.loads((work / "run" / "summary.json").read_text())["housing"]
if housing["frequencies"] != modes["frequencies"]:
    failures.append(f"summary.json housing.frequencies {housing['frequencies']} != modes.json's")
if housing["sensors"][0]["point"] != top["point"]:
    failures.append(f"sensor point {housing['sensors'][0]['point']} != modes.json's {top['point']}")
for line in failures:
    print("FAIL:", line)
sys.exit(1 if failures else 0)
