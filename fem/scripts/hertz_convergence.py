#!/usr/bin/env python3
"""Mesh-convergence study of the Hertz-reduced contact (fem/README.md's table).

Runs `bearing-fem contact` for the inner and the outer contact of a case on a sequence of meshes
where EVERY cell shrinks by about 1.4x per level: cells per semi-minor axis N_b and the grading m
(a cell at distance d from the contact patch has size >= d/m) grow together, so the contact zone
and the graded far field are both refined. Prints a Markdown table (K error against the exact
Hertz K, exponent, semi-axis errors at Q_max, wall time) and writes it to OUT/convergence.md.

usage: hertz_convergence.py BEARING_FEM CASE OUT [--np N] [--levels 0,1,2,3]
"""
import argparse, json, os, subprocess, sys

LEVELS = [(4, 3), (6, 4), (8, 6), (12, 8), (16, 12)]

ap = argparse.ArgumentParser()
ap.add_argument("bearing_fem"); ap.add_argument("case"); ap.add_argument("out")
ap.add_argument("--np", type=int, default=2)
ap.add_argument("--levels", default="0,1,2,3")
ap.add_argument("--races", default="inner,outer")
a = ap.parse_args()
os.makedirs(a.out, exist_ok=True)
rows = []
for race in a.races.split(","):
    for lev in [int(x) for x in a.levels.split(",")]:
        nb, m = LEVELS[lev]
        d = os.path.join(a.out, f"{race}_L{lev}")
        cmd = [a.bearing_fem, "contact", a.case, "--race", race, "--out", d, "--cells", str(nb),
               "--grading", str(m), "--no-vtu", "--quiet"]
        if a.np > 1:
            cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(a.np)] + cmd
        subprocess.run(cmd, check=True)
        j = json.load(open(os.path.join(d, "contact.json")))
        r = j["relative_difference"]
        rows.append((race, lev, nb, m, j["mesh"]["cells"], j["mesh"]["dofs"], 100 * r["K"],
                     j["fe"]["exponent"], 100 * r["semi_axes"][0], 100 * r["semi_axes"][1],
                     100 * r["peak_pressure"], j["fe"]["fit_residual"], j["wall_time"]))
        print(rows[-1], flush=True)
head = ("| race | level | N_b | m | cells | DoFs | K error % | exponent | a error % | b error % "
        "| p0 error % | fit residual | wall time s |\n|" + "---|" * 13)
lines = [head] + ["| %s | %d | %d | %g | %d | %d | %+.3f | %.4f | %+.3f | %+.3f | %+.3f | %.1e | %.1f |" % r
                  for r in rows]
text = "\n".join(lines) + f"\n\n(mpirun -np {a.np}; case {a.case})\n"
open(os.path.join(a.out, "convergence.md"), "w").write(text)
print(text)
