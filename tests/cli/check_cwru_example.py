#!/usr/bin/python3
"""examples/cwru/compare.py end to end: it writes its table and one figure per condition, and the
model is consistent with itself where physics says it must be (not a comparison with the rig):

- each simulated spall is diagnosed as its own family by `bearing-sim analyse` (not pre-whitened:
  the model's impacts are exactly periodic, examples/cwru/README.md), and the simulated healthy
  bearing as none, pre-whitened or not;
- the family's rate found in the simulated record lies within one SES bin of its kinematic rate:
  the 2-DOF model without axial load runs at contact angle 0, so its lines are the catalogue's;
- table.md has a row per condition in each of its tables.

The measured records' diagnoses are not asserted here (tests/records and RecordAnalysis cover
them). Skipped (exit 77) without numpy, scipy or matplotlib for /usr/bin/python3.

    check_cwru_example.py BEARING_SIM WORK_DIR SOURCE_DIR
"""
import json
import pathlib
import shutil
import subprocess
import sys

try:
    import matplotlib  # noqa: F401
    import numpy  # noqa: F401
    import scipy  # noqa: F401
except ImportError as e:
    print(f"SKIP: {sys.executable} lacks {e.name}; install python3-numpy, -scipy, -matplotlib")
    sys.exit(77)

sim, work, source = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
shutil.rmtree(work, ignore_errors=True)
subprocess.run(["/usr/bin/python3", str(source / "examples" / "cwru" / "compare.py"), "--sim", sim,
                "--out", str(work)], check=True, stdout=subprocess.DEVNULL)

failures = []
conditions = {"healthy": None, "inner": "inner", "ball": "ball", "outer": "outer"}
for name, family in conditions.items():
    png = work / f"cwru-{name}.png"
    if not png.is_file() or png.read_bytes()[:8] != b"\x89PNG\r\n\x1a\n":
        failures.append(f"{png}: missing or not a PNG")
    raw = json.loads((work / "analyses" / f"{name}-simulated-raw" / "summary.json").read_text())
    white = json.loads((work / "analyses" / f"{name}-simulated-pw" / "summary.json").read_text())
    expected = family or "none"
    if raw["diagnosis"]["family"] != expected:
        failures.append(f"simulated {name} (not pre-whitened): diagnosis "
                        f"{raw['diagnosis']['family']}, expected {expected}")
    if family is None:
        if white["diagnosis"]["family"] != "none":
            failures.append(f"simulated healthy (pre-whitened): {white['diagnosis']['family']}")
        continue
    lines = raw["fault_lines"][family]
    with open(work / "analyses" / f"{name}-simulated-raw" / "envelope.csv") as f:
        f.readline()
        step = -float(f.readline().split(",")[0]) + float(f.readline().split(",")[0])
    if abs(lines["carrier"] - lines["nominal"]) > step:
        failures.append(f"simulated {name}: {family} found at {lines['carrier']} Hz, its kinematic "
                        f"rate {lines['nominal']} Hz is more than a bin ({step} Hz) away")

table = (work / "table.md").read_text()
for name in conditions:
    rows = [l for l in table.splitlines() if l.startswith(f"| {name} |")]
    if len(rows) != 3:  # the fault-line, the diagnosis and the level tables
        failures.append(f"table.md: {len(rows)} rows for {name}, expected one in each of 3 tables")

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
