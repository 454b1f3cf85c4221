#!/usr/bin/python3
"""output.format = "npy" read by NumPy itself: numpy.load gives each table with the shape and
column names that columns.json states, equal to the CSV run's values to the CSV's 12 digits
(1e-11 relative). Skipped (exit 77) when numpy cannot be imported.

    check_npy.py BEARING_SIM WORK_DIR
"""
import json
import pathlib
import shutil
import subprocess
import sys

try:
    import numpy as np
except ImportError as e:
    print(f"SKIP: numpy is not importable by {sys.executable} ({e}); "
          "install python3-numpy to run this check")
    sys.exit(77)

sim, work = sys.argv[1], pathlib.Path(sys.argv[2])
shutil.rmtree(work, ignore_errors=True)
args = ["--quiet", "--set", "solver.duration=0.3", "--set", "solver.transient=0.1",
        "--set", 'acoustics.microphones=[["0.1 m", "0 deg"], ["0.3 m", "-90 deg"]]',
        "--set", "output.envelope_band=auto", "--set", "output.ball_approach=true"]
for fmt in ("csv", "npy"):
    subprocess.run([sim, "run", "--out", str(work / fmt), "--set", f"output.format={fmt}", *args],
                   check=True, stdout=subprocess.DEVNULL)

meta = json.loads((work / "npy" / "columns.json").read_text())
failures = 0
for stem in ("response", "spectrum", "pressure", "envelope"):
    a = np.load(work / "npy" / f"{stem}.npy")
    table = meta["tables"][f"{stem}.npy"]
    with open(work / "csv" / f"{stem}.csv") as f:
        header = f.readline().strip().split(",")
    csv = np.loadtxt(work / "csv" / f"{stem}.csv", delimiter=",", skiprows=1, ndmin=2)
    checks = {
        "dtype float64 little-endian": a.dtype == np.dtype("<f8"),
        "C order": a.flags["C_CONTIGUOUS"] and a.ndim == 2,
        "shape as columns.json": list(a.shape) == table["shape"],
        "columns as the CSV header": table["columns"] == header,
        "a unit per column": len(table["units"]) == len(header),
        "shape as the CSV": a.shape == csv.shape,
    }
    if a.shape == csv.shape:
        checks["values to 1e-11 relative"] = bool(np.all(np.abs(a - csv) <= 1e-11 * np.abs(csv)))
    for what, ok in checks.items():
        print(f"{stem}.npy: {what}: {'ok' if ok else 'FAILED'}")
        failures += not ok
print(f"{failures} failed")
sys.exit(1 if failures else 0)
