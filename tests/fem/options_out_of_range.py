#!/usr/bin/env python3
"""Every out-of-range option of bearing-fem is bad input: exit 2 before any mesh is built.

usage: options_out_of_range.py BEARING_FEM OUT_DIR

The ranges are read from the program's own --help (each numeric option shows its range, e.g.
"--degree UINT:[1, 8]"), so an option added later is covered, and an option that takes a number
without showing a range fails this test. For each range: a value below it, a value above it and
NaN. Then the rules that tie options together or that no range can say (a choice not offered, a
malformed microphone, --load-min above --load-max, ...), listed below.

Each call must exit with 2, print one line on stderr that names the option, print nothing on
stdout from the solver (at most the one line announcing it: the physical radius is checked
against the bodies' extent by the solver, before its mesh), and leave no file in its output
folder (no mesh, no result).
"""
import concurrent.futures
import os
import re
import shutil
import subprocess
import sys

RANGE = re.compile(r"^\s+(--[a-z-]+) (FLOAT|UINT|INT):([\[(])([-0-9.e+]+), ([-0-9.e+]+)\]")
NUMERIC = re.compile(r"^\s+(--[a-z-]+) (FLOAT|UINT|INT)\b")
# The line each subcommand prints just before the FE solver (and its mesh) starts.
INTRO = ("radiate: ", "bearing-fem contact: ")
HERE = os.path.dirname(os.path.abspath(__file__))
# What each subcommand needs besides the option under test (all valid).
BASE = {
    "contact": ["--race", "inner"],
    "calibrate": [],
    "radiate": ["--source", "cylinder-dipole", "--radius", "0.01"],
    "modes": [],  # the structure file, written by main()
}
# `modes`: a box of tetrahedra gmsh wrote (the fuzz seed) and a valid structure file for it.
STRUCTURE = """mesh = "{mesh}"
mesh_unit = "mm"
[material]
young = "210 GPa"
poisson = 0.3
density = "7850 kg/m^3"
[boundary]
fixed = ["fixed"]
seat = "seat"
"""


def ranges(fem, sub):
    text = subprocess.run([fem, sub, "--help"], capture_output=True, text=True, check=True).stdout
    found, unranged = [], []
    for line in text.splitlines():
        m = RANGE.match(line)
        if m:
            found.append((m.group(1), m.group(2), m.group(3) == "(", float(m.group(4)),
                          float(m.group(5))))
        elif NUMERIC.match(line):
            unranged.append(NUMERIC.match(line).group(1))
    return found, unranged


def bad_values(kind, open_low, low, high):
    below = low if open_low else low - 1
    if kind == "UINT" and below < 0:
        below = -1  # CLI11 refuses a negative unsigned: a conversion error, still exit 2
    above = high * 2 + 1
    values = [below, above]
    if kind == "FLOAT":
        values.append("nan")
    return [str(int(v)) if kind != "FLOAT" and not isinstance(v, str) else str(v) for v in values]


def check(fem, out_root, index, sub, args, names, failures, label):
    out = os.path.join(out_root, f"{sub}_{index}")
    target = os.path.join(out, "cal.json") if sub == "calibrate" else out
    cmd = [fem, sub] + BASE[sub] + args + ["--out", target]
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    problems = []
    if r.returncode != 2:
        problems.append(f"exit {r.returncode}, expected 2")
    err = r.stderr.strip()
    if "\n" in err or not err:
        problems.append(f"stderr is not one line: {err!r}")
    if not any(n in err for n in names):
        problems.append(f"stderr does not name {names}: {err!r}")
    # At most the announcement printed before the solver starts; the solver's own lines (mesh
    # cells, unknowns, gmsh) mean a mesh was built.
    for line in r.stdout.splitlines():
        if not line.startswith(INTRO) or re.search(r"cells|unknowns|DoF|gmsh|mesh", line):
            problems.append(f"the run went on: stdout {r.stdout.strip()[:300]!r}")
            break
    if os.path.isdir(out):
        files = [os.path.join(d, f) for d, _, fs in os.walk(out) for f in fs]
        if files:
            problems.append(f"left files: {files}")
    if problems:
        failures.append(f"{label}: {' '.join(cmd)}\n    " + "\n    ".join(problems))
    return 1


def main():
    fem, out_root = sys.argv[1], sys.argv[2]
    shutil.rmtree(out_root, ignore_errors=True)
    os.makedirs(out_root)
    structure = os.path.join(out_root, "structure.toml")
    with open(structure, "w") as f:
        f.write(STRUCTURE.format(mesh=os.path.join(
            HERE, "..", "fuzz", "corpus", "gmsh_mesh", "box_tetrahedra_22.msh")))
    BASE["modes"] = [structure]
    failures, calls = [], []
    for sub in BASE:
        found, unranged = ranges(fem, sub)
        if not found:
            failures.append(f"{sub}: no ranged option found in --help (format changed?)")
        for name in unranged:
            failures.append(f"{sub} {name}: takes a number but shows no range in --help")
        for name, kind, open_low, low, high in found:
            for v in bad_values(kind, open_low, low, high):
                calls.append((sub, [name, v], [name], f"{sub} {name} {v}"))
    # The rules no single range says.
    rules = [
        ("contact", ["--race", "middle"], ["--race"]),
        ("contact", ["--geometry", "sphere"], ["--geometry"]),
        ("contact", ["--gap", "tight"], ["--gap"]),
        ("contact", ["--load-min", "50", "--load-max", "40"], ["--load-min"]),
        ("contact", ["--load-max", "100", "--peak-pressure", "2e9"], ["--load-max", "--peak-pressure"]),
        ("contact", ["--steps", "2.5"], ["--steps"]),
        ("contact", ["--set", "bearing.balls=2"], ["bearing.balls"]),
        ("calibrate", ["--geometry", "sphere"], ["--geometry"]),
        ("calibrate", ["--load-min", "50", "--load-max", "40"], ["--load-min"]),
        ("radiate", ["--microphone", "1;0"], ["--microphone"]),
        ("radiate", ["--microphone", "0.005,0"], ["--microphone"]),
        ("radiate", ["--frequencies", "100,0"], ["--frequencies"]),
        ("radiate", ["--reference", "sphere-dipole"], ["--reference"]),
        ("radiate", ["--physical-radius", "0.005"], ["physical radius"]),
        ("modes", ["--degree", "3"], ["--degree"]),
        ("modes", ["--frf", ",".join(str(k) for k in range(1, 22))], ["--frf"]),
        ("modes", ["--count", "2.5"], ["--count"]),
    ]
    calls += [(sub, args, names, f"{sub} {' '.join(args)}") for sub, args, names in rules]
    # Each call spends most of its ~1 s waiting in MPI's start-up, not computing: four at a time
    # take a quarter of the wall time on two cores (ctest runs the suite serially in CI).
    with concurrent.futures.ThreadPoolExecutor(max_workers=4) as pool:
        count = sum(pool.map(lambda ic: check(fem, out_root, ic[0], *ic[1], failures),
                             enumerate(calls)))
    failures.sort()
    print(f"{count} out-of-range calls of bearing-fem")
    if failures:
        print(f"{len(failures)} not refused as bad input before the mesh:")
        print("\n".join(failures))
        return 1
    print("every one exited with 2, one line naming the option, nothing run, no file left")
    return 0


if __name__ == "__main__":
    sys.exit(main())
