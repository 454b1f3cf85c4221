#!/usr/bin/env python3
"""Refinement study of the Helmholtz radiation reference (fem/README.md, issue 6).

For each single source (the 608's ring and ball radii), runs `bearing-fem radiate` over the 24
one-third-octave centres 100 Hz - 20 kHz at global refinement levels 0, 1, 2 of the default mesh
and prints a markdown table: the largest |FE - exact| in dB and degrees over the band and both
microphones, the unknowns and the wall time. Standard library only.

usage: radiation_convergence.py BEARING_FEM OUT_DIR [--np N] [--levels 0,1,2]
"""
import argparse
import json
import os
import subprocess

SOURCES = [
    # name, radius [m] (608: ring (d_m - D)/2, ball D/2), microphones "r,angle" (10 mm: in the mesh for the ring, continued for the ball; 1 m: continued)
    ("cylinder-monopole", 5.7905e-3, ["0.01,30", "1,60"]),
    ("cylinder-dipole", 5.7905e-3, ["0.01,30", "1,60"]),
    ("sphere-monopole", 1.9845e-3, ["0.01,30", "1,60"]),
    ("sphere-dipole", 1.9845e-3, ["0.01,30", "1,60"]),
]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("bearing_fem")
    ap.add_argument("out")
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--levels", default="0,1,2")
    ap.add_argument("--extra", default="", help="further radiate options")
    a = ap.parse_args()
    print("| source | level | unknowns | max abs dB | max abs deg | wall time [s] (processes) |")
    print("|---|---|---|---|---|---|")
    for name, radius, mics in SOURCES:
        for level in map(int, a.levels.split(",")):
            out = os.path.join(a.out, f"{name}_l{level}")
            cmd = [a.bearing_fem, "radiate", "--source", name, "--radius", str(radius),
                   "--refinements", str(level), "--out", out, "--no-vtu", "--quiet"]
            for m in mics:
                cmd += ["--microphone", m]
            cmd += a.extra.split()
            if a.np > 1:
                cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(a.np)] + cmd
            subprocess.run(cmd, check=True)
            with open(os.path.join(out, "radiation.json")) as f:
                j = json.load(f)
            print(f"| {name} | {level} | {j['mesh']['unknowns']} | "
                  f"{j['max_abs_diff_db']:.2e} | {j['max_abs_diff_phase_deg']:.2e} | "
                  f"{j['wall_time']:.1f} ({j['mpi_processes']}) |", flush=True)


if __name__ == "__main__":
    main()
