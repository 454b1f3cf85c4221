#!/usr/bin/env python3
"""`bearing-fem modes` refuses bad input: exit 2, one line on stderr naming the field (and the
value, the allowed range or the names that exist), no solve, no result file.

usage: modes_bad_input.py BEARING_FEM OUT_DIR

A valid structure (a 20 x 10 x 6 mm box of tetrahedra gmsh wrote, tests/fuzz/corpus/gmsh_mesh/)
runs first (exit 0, modes.json written: the control). Then each bad input below: a structure file
with one value changed, a bad mesh (no volume, two parts, a binary header, a second-order element,
a broken .geo), or an option no range can refuse (--degree 3 on tetrahedra, too many --frf).
The output folder may hold the lock `.run.lock` (created by a .geo run before gmsh), nothing else.
"""
import json
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SEED = os.path.join(HERE, "..", "fuzz", "corpus", "gmsh_mesh", "box_tetrahedra_22.msh")

VALID = """mesh = "box.msh"
mesh_unit = "mm"
[material]
young = "210 GPa"
poisson = 0.3
density = "7850 kg/m^3"
[boundary]
fixed = ["fixed"]
seat = "seat"
[sensors]
top = [10, 5, 6]
[modes]
count = 4
"""

# Two tetrahedra that share no node; the first has a face in the physical surface "fixed", the
# second one in "seat".
TWO_PARTS = """$MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
2
2 1 "fixed"
2 2 "seat"
$EndPhysicalNames
$Nodes
8
1 0 0 0
2 1 0 0
3 0 1 0
4 0 0 1
5 5 0 0
6 6 0 0
7 5 1 0
8 5 0 1
$EndNodes
$Elements
4
1 4 0 1 2 3 4
2 4 0 5 6 7 8
3 2 2 1 1 1 2 3
4 2 2 2 1 5 6 7
$EndElements
"""

SURFACE_ONLY = TWO_PARTS.replace("4\n1 4 0 1 2 3 4\n2 4 0 5 6 7 8\n", "2\n")
BINARY = "$MeshFormat\n4.1 1 8\n$EndMeshFormat\n"
SECOND_ORDER = TWO_PARTS.replace("1 4 0 1 2 3 4\n", "1 11 0 1 2 3 4 5 6 7 8 1 2\n")


def cases():
    """(name, structure text or None for VALID, files {name: text}, extra args, names)"""
    def changed(old, new):
        assert old in VALID, old
        return VALID.replace(old, new)

    yield "young", changed('young = "210 GPa"', 'young = "-1 GPa"'), {}, [], ["material.young"]
    yield "poisson", changed("poisson = 0.3", "poisson = 0.5"), {}, [], ["material.poisson"]
    yield "density", changed('density = "7850 kg/m^3"', "density = 0"), {}, [], [
        "material.density"]
    yield "count_low", changed("count = 4", "count = 0"), {}, [], ["modes.count"]
    yield "count_high", changed("count = 4", "count = 501"), {}, [], ["modes.count"]
    yield "max_frequency", changed("count = 4", 'max_frequency = "-5 Hz"'), {}, [], [
        "modes.max_frequency"]
    yield "sensor_name", changed("top = [", "top-1 = ["), {}, [], ["sensors.top-1"]
    yield "sensor_point", changed("top = [10, 5, 6]", "top = [10, 5]"), {}, [], ["sensors.top"]
    yield "mesh_unit", changed('mesh_unit = "mm"', 'mesh_unit = "cm"'), {}, [], ["mesh_unit"]
    yield "unknown_key", changed("[modes]", "[modes]\ncolour = 1"), {}, [], ["modes.colour"]
    yield "seat_unknown", changed('seat = "seat"', 'seat = "bore"'), {}, [], [
        'boundary.seat = "bore"', '"fixed", "seat"']
    yield "fixed_unknown", changed('fixed = ["fixed"]', 'fixed = ["bolts"]'), {}, [], [
        'boundary.fixed = "bolts"', '"fixed", "seat"']
    yield "seat_fixed", changed('fixed = ["fixed"]', 'fixed = ["seat"]'), {}, [], [
        "is also in boundary.fixed"]
    yield "mesh_missing", changed('mesh = "box.msh"', 'mesh = "none.msh"'), {}, [], [
        "none.msh", "cannot open"]
    yield "no_volume", changed('mesh = "box.msh"', 'mesh = "surface.msh"'), {
        "surface.msh": SURFACE_ONLY}, [], ["no volume elements"]
    yield "binary", changed('mesh = "box.msh"', 'mesh = "binary.msh"'), {
        "binary.msh": BINARY}, [], ["binary"]
    yield "second_order", changed('mesh = "box.msh"', 'mesh = "p2.msh"'), {
        "p2.msh": SECOND_ORDER}, [], ["second-order"]
    yield "rigid_left", changed('mesh = "box.msh"', 'mesh = "two.msh"'), {
        "two.msh": TWO_PARTS}, [], ["the fixed set leaves 6 rigid-body modes"]
    yield "free_parts", changed('mesh = "box.msh"', 'mesh = "two.msh"').replace(
        'fixed = ["fixed"]', "fixed = []"), {"two.msh": TWO_PARTS}, [], ["2 separate parts"]
    yield "geo_error", changed('mesh = "box.msh"', 'mesh = "bad.geo"'), {
        "bad.geo": "Point(1) = {0, 0, 0};\nFoo;\n"}, [], ["bad.geo", "gmsh failed"]
    yield "degree_3", None, {}, ["--degree", "3"], ["--degree 3", "tetrahedral"]
    yield "frf_many", None, {}, ["--frf", ",".join(str(100 * k) for k in range(1, 22))], ["--frf"]


def run(fem, structure, out, extra):
    return subprocess.run([fem, "modes", structure, "--out", out, "--no-vtu", "--quiet"] + extra,
                          capture_output=True, text=True, timeout=120)


def main():
    fem, root = sys.argv[1], sys.argv[2]
    shutil.rmtree(root, ignore_errors=True)
    failures, count = [], 0
    # The control: the valid structure runs.
    base = os.path.join(root, "valid")
    os.makedirs(base)
    shutil.copy(SEED, os.path.join(base, "box.msh"))
    with open(os.path.join(base, "s.toml"), "w") as f:
        f.write(VALID)
    r = run(fem, os.path.join(base, "s.toml"), os.path.join(base, "out"), [])
    if r.returncode != 0 or not os.path.exists(os.path.join(base, "out", "modes.json")):
        print(f"the valid structure failed ({r.returncode}): {r.stderr}")
        return 1
    print("valid structure: %d modes" % json.load(open(os.path.join(base, "out", "modes.json")))
          ["count"])
    for name, text, files, extra, names in cases():
        count += 1
        work = os.path.join(root, name)
        os.makedirs(work)
        shutil.copy(SEED, os.path.join(work, "box.msh"))
        for f, t in files.items():
            with open(os.path.join(work, f), "w") as h:
                h.write(t)
        with open(os.path.join(work, "s.toml"), "w") as h:
            h.write(text or VALID)
        out = os.path.join(work, "out")
        r = run(fem, os.path.join(work, "s.toml"), out, extra)
        problems = []
        if r.returncode != 2:
            problems.append(f"exit {r.returncode}, expected 2")
        err = r.stderr.strip()
        if not err or "\n" in err:
            problems.append(f"stderr is not one line: {err!r}")
        for n in names:
            if n not in err:
                problems.append(f"stderr does not say {n!r}: {err!r}")
        if "cells" in r.stdout:
            problems.append(f"the solve started: {r.stdout.strip()[:200]!r}")
        if os.path.isdir(out):
            left = [f for _, _, fs in os.walk(out) for f in fs if f != ".run.lock"]
            if left:
                problems.append(f"left files: {left}")
        if problems:
            failures.append(f"{name}:\n    " + "\n    ".join(problems))
    print(f"{count} bad inputs")
    if failures:
        print("\n".join(failures))
        return 1
    print("every one exited with 2, one line naming the field, no solve, no result file")
    return 0


if __name__ == "__main__":
    sys.exit(main())
