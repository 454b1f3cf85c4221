#!/usr/bin/python3
"""`bearing-sim stiffness --format ross`: stiffness_ross.csv read back with the csv module as ROSS's
BearingElement table reader (ross.utils.read_table_file) would take it: its column names (kxx and
cxx required; kyy, kxy, kyx, cyy, cxy, cyx and frequency optional, matched lower-cased), one row
per speed in rad/s, strictly ascending (ROSS interpolates over it), only numbers, and no cell
that ROSS's reader takes for imperial units or rpm ("lb", "inches", "rpm" anywhere switch its
conversions on). The values are K averaged over one ball pass: stiffness.json's rotor.stiffness and
ball_pass.mean (not stiffness_at_cage_angle), with k_xy == k_yx and the damping 0.

    check_stiffness_ross.py BEARING_SIM EXAMPLES_DIR
"""
import csv
import json
import math
import pathlib
import subprocess
import sys
import tempfile

ROSS_COLUMNS = ["frequency", "kxx", "kxy", "kyx", "kyy", "cxx", "cxy", "cyx", "cyy"]


def main():
    sim, examples = sys.argv[1], pathlib.Path(sys.argv[2])
    with tempfile.TemporaryDirectory() as tmp:
        out = pathlib.Path(tmp) / "ross"
        subprocess.run([sim, "stiffness", str(examples / "seed003_6308.toml"), "--set",
                        "operation.axial_load=50", "--vary", "operation.speed=3000rpm:500rpm:6",
                        "--format", "ross", "--quiet", "--out", str(out)], check=True)
        with open(out / "stiffness_ross.csv", newline="") as f:
            rows = list(csv.reader(f))
        with open(out / "stiffness.json") as f:
            points = json.load(f)["points"]
    header, body = rows[0], rows[1:]
    assert header == ROSS_COLUMNS, header
    assert all(name == name.lower() for name in header)
    for cell in (c for row in rows for c in row):
        assert not any(word in cell.lower() for word in ("lb", "inches", "rpm")), cell
    table = [[float(c) for c in row] for row in body]  # every cell a number
    assert len(table) == 6, len(table)
    speeds = [r[0] for r in table]
    assert all(a < b for a, b in zip(speeds, speeds[1:])), speeds
    expected = sorted(500 + 500 * i for i in range(6))
    for got, rpm in zip(speeds, expected):
        assert math.isclose(got, rpm * 2 * math.pi / 60, rel_tol=1e-12), (got, rpm)
    by_speed = {p["speed"]: p for p in points}
    for row in table:
        values = dict(zip(header, row))
        point = by_speed[values["frequency"]]
        k = point["rotor"]["stiffness"]
        assert k == point["ball_pass"]["mean"], "rotor.stiffness is the ball pass's mean"
        assert [values["kxx"], values["kxy"], values["kyx"], values["kyy"]] == \
            [k[0][0], k[0][1], k[1][0], k[1][1]], (values, k)
        assert values["kxy"] == values["kyx"]
        assert values["kxx"] > 0 and values["kyy"] > 0
        assert [values[c] for c in ("cxx", "cxy", "cyx", "cyy")] == [0.0] * 4
    print("stiffness_ross.csv: ROSS's columns, %d speeds ascending in rad/s, values of "
          "stiffness.json's rotor.stiffness (the ball-pass mean)" % len(table))


if __name__ == "__main__":
    main()
