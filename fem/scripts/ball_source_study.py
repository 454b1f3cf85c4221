#!/usr/bin/env python3
"""The ball-source study of fem/README.md (issue 6): the FE field of a translating rigid ball (the
608's, a = D/2 = 1.9845 mm) against seed 000's pulsating sphere of the same surface speed, and
against the oscillating sphere, on the axis of motion at 10 mm and 30 mm, 100 Hz - 20 kHz.
Prints the markdown table (one row per octave, plus 12.5 kHz and 20 kHz). Standard library only.

usage: ball_source_study.py BEARING_FEM OUT_DIR
"""
import csv
import math
import os
import subprocess
import sys

RADIUS = 1.9845e-3
SOUND_SPEED = 343.2
ROWS = ["100", "250", "500", "1000", "2000", "4000", "8000", "12500", "16000", "20000"]


def run(exe, out, reference):
    cmd = [exe, "radiate", "--source", "sphere-dipole", "--radius", str(RADIUS),
           "--microphone", "0.01,0", "--microphone", "0.03,0", "--out", out, "--no-vtu", "--quiet"]
    if reference:
        cmd += ["--reference", reference]
    subprocess.run(cmd, check=True)
    rows = {}
    with open(os.path.join(out, "radiation.csv")) as f:
        for r in csv.DictReader(f):
            rows.setdefault(r["frequency"], []).append(r)
    return rows


def main():
    exe, out = sys.argv[1], sys.argv[2]
    pulsating = run(exe, os.path.join(out, "vs_pulsating"), "pulsating-sphere")
    oscillating = run(exe, os.path.join(out, "vs_oscillating"), None)
    print("| f [Hz] | ka | at 10 mm: FE − pulsating [dB] | phase [°] | at 30 mm: FE − pulsating [dB]"
          " | phase [°] | FE − oscillating, both [dB] |")
    print("|---|---|---|---|---|---|---|")
    for f in ROWS:
        (p10, p30), (o10, o30) = pulsating[f], oscillating[f]
        ka = 2 * math.pi * float(f) / SOUND_SPEED * RADIUS
        print("| %s | %.3f | %+.2f | %+.1f | %+.2f | %+.1f | %.0e, %.0e |" % (
            f, ka, float(p10["diff_db"]), float(p10["diff_phase_deg"]), float(p30["diff_db"]),
            float(p30["diff_phase_deg"]), abs(float(o10["diff_db"])), abs(float(o30["diff_db"]))))
    worst = max(abs(float(r["diff_db"])) for v in oscillating.values() for r in v)
    print("\nlargest |FE − oscillating sphere| over all 24 frequencies: %.1e dB" % worst)


if __name__ == "__main__":
    main()
