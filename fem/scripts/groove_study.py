#!/usr/bin/env python3
"""Real groove geometry against Hertz (fem/README.md's groove table, issue 4).

For each bearing (608, 6304, 6308 from examples/), race and Hertz peak pressure (1.5, 3.0 and
4.2 GPa: operating, heavy, ISO 76's static limit) it runs `bearing-fem contact` three times on
the same mesh resolution:
  block       the Hertz-reduced block and paraboloid (discretisation + far-field reference),
  ring        the ring segment with Hertz's paraboloid gap (adds the ring's finite size, clamped
              at the bore / outside diameter),
  groove      the ring segment pressed by the rigid sphere (adds the exact groove and ball
              surfaces: the large-contact effect Hertz's theory neglects),
and tabulates F_FE/F_Hertz - 1 at the approach of the design load (the largest step), the semi-
axes against Hertz at the FE force, and the contact's size against the groove (a_Hertz / y_s,
y_s the groove's half-width at the land).

The column "gap effect" is (1 + groove)/(1 + ring) - 1: the exact surfaces against Hertz's
paraboloid on the same ring and mesh.

usage: groove_study.py BEARING_FEM OUT [--np 2] [--cells 6] [--grading 4] [--pressures 1.5,3,4.2]
                       [--reuse]   (take runs whose contact.json exists in OUT instead of rerunning)
"""
import argparse, json, math, os, subprocess

CASES = [("608", "examples/seed000_608.toml"), ("6304", "examples/seed004_6304.toml"),
         ("6308", "examples/seed003_6308.toml")]
VARIANTS = [("block", ["--geometry", "hertz"]),
            ("ring", ["--geometry", "groove", "--gap", "paraboloid"]),
            ("groove", ["--geometry", "groove", "--gap", "exact"])]

ap = argparse.ArgumentParser()
ap.add_argument("bearing_fem"); ap.add_argument("out")
ap.add_argument("--np", type=int, default=2)
ap.add_argument("--cells", default="6"); ap.add_argument("--grading", default="4")
ap.add_argument("--pressures", default="1.5,3.0,4.2")
ap.add_argument("--bearings", default="608,6304,6308")
ap.add_argument("--reuse", action="store_true")
a = ap.parse_args()
os.makedirs(a.out, exist_ok=True)
repo = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

def run(case, race, p0, variant, extra):
    d = os.path.join(a.out, f"{case[0]}_{race}_{p0}GPa_{variant}")
    cmd = [a.bearing_fem, "contact", os.path.join(repo, case[1]), "--race", race, "--out", d,
           "--peak-pressure", str(p0 * 1e9), "--load-min-fraction", "0.5", "--steps", "3",
           "--cells", a.cells, "--grading", a.grading, "--no-vtu", "--quiet"] + extra
    if a.np > 1:
        cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(a.np)] + cmd
    if not (a.reuse and os.path.exists(os.path.join(d, "contact.json"))):
        subprocess.run(cmd, check=True)
    return json.load(open(os.path.join(d, "contact.json")))

rows = []
for case in CASES:
    if case[0] not in a.bearings.split(","):
        continue
    for race in ("inner", "outer"):
        for p0 in [float(x) for x in a.pressures.split(",")]:
            r = {}
            for name, extra in VARIANTS:
                j = run(case, race, p0, name, extra)
                last = j["steps"][-1]
                r[name] = dict(f=last["force"] / last["hertz_force"] - 1,
                               a=last["semi_axis_a"] / last["hertz_semi_axis_a"] - 1,
                               b=last["semi_axis_b"] / last["hertz_semi_axis_b"] - 1,
                               n=math.log(j["steps"][-1]["force"] / j["steps"][-2]["force"]) /
                                 math.log(j["steps"][-1]["approach"] / j["steps"][-2]["approach"]),
                               t=j["wall_time"], j=j)
            g = r["groove"]["j"]
            ys = math.sqrt(max(0.0, g["raceway"]["groove_radius"] ** 2 -
                               (g["raceway"]["groove_radius"] - g["raceway"]["land_depth"]) ** 2))
            q = g["steps"][-1]["force"] / (1 + r["groove"]["f"])  # Hertz load at that approach
            a_h = g["steps"][-1]["hertz_semi_axis_a"]
            gap = (1 + r["groove"]["f"]) / (1 + r["ring"]["f"]) - 1
            rows.append((case[0], race, p0, q, a_h / ys, 100 * r["block"]["f"], 100 * r["ring"]["f"],
                         100 * r["groove"]["f"], 100 * gap, r["groove"]["n"], 100 * r["groove"]["a"],
                         100 * r["groove"]["b"], sum(v["t"] for v in r.values())))
            print(rows[-1], flush=True)

head = ("| bearing | race | p0 Hertz GPa | Q N | a/y_s | block: F/F_H-1 % | ring: F/F_H-1 % "
        "| groove: F/F_H-1 % | gap effect % | groove local n | groove a/a_H-1 % | groove b/b_H-1 % "
        "| wall s |\n|" + "---|" * 13)
lines = [head] + ["| %s | %s | %.1f | %.4g | %.2f | %+.2f | %+.2f | %+.2f | %+.2f | %.3f | %+.2f | %+.2f | %.0f |" % r
                  for r in rows]
total = sum(r[-1] for r in rows)
text = ("\n".join(lines) + f"\n\n(N_b = {a.cells}, m = {a.grading}; mpirun -np {a.np}; wall time of "
        f"the three runs per row, {total:.0f} s in all)\n")
open(os.path.join(a.out, "groove_study.md"), "w").write(text)
print(text)
