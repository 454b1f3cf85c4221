#!/usr/bin/env python3
"""bench/output_change.py's judgement on matrices whose answer is known (issue 42).

    check_output_change.py SOURCE_DIR WORK_DIR

One case, `run_a`: a response table (t, x, ay), its summary.json and printed summary, written for
OLD, FINE (the integrator's error: ay off by 1e-3 sample by sample, the RMS by 1e-4), two
PERTURBED (round-off: ay off by 1e-12) and several NEW. Each NEW must get the verdict its change
deserves: byte-identical, within the error, a last-digit flip of a printed number, the solver's
cost, and — flagged, exit 1 — a change of ay beyond the error, of the RMS beyond its own error, and
a changed word. A case amplifying round-off (the perturbations move most of its summary beyond
the error) is judged by that count. Exit 0 when every verdict is the expected one.
"""
import json
import os
import shutil
import subprocess
import sys


def write_case(root, ay_shift, rms, printed_rms, evaluations, label="BPFO"):
    case = os.path.join(root, "run_a")
    os.makedirs(case, exist_ok=True)
    with open(os.path.join(case, "response.csv"), "w") as f:
        f.write("t,x,ay\n")
        for i in range(50):
            f.write(f"{i * 5e-05!r},{1e-6 * (i % 7)!r},{(i % 5) - 2 + ay_shift!r}\n")
    with open(os.path.join(case, "summary.json"), "w") as f:
        json.dump({"channels": {"ay": {"rms": rms, "unit": "m/s^2"}},
                   "peaks": [{"frequency": 102.4, "label": label}],
                   "solver": {"force_evaluations": evaluations, "method": "rk4"}}, f, indent=2)
    with open(root + "/run_a.stdout", "w") as f:
        f.write(f"  ay   rms {printed_rms} m/s^2  peak 102.41 Hz {label}\n"
                f"Solver: 20000 steps, {evaluations} force evaluations\n")
    with open(root + "/run_a.rc", "w") as f:
        f.write("0\n")


def verdict(script, roots):
    r = subprocess.run(["/usr/bin/python3", script, "compare", *roots], capture_output=True,
                       text=True)
    if r.returncode not in (0, 1):
        print(r.stdout, r.stderr)
        raise SystemExit(f"output_change.py failed: exit {r.returncode}")
    return r.returncode, r.stdout


def main(argv):
    source, work = argv
    script = os.path.join(source, "bench", "output_change.py")
    shutil.rmtree(work, ignore_errors=True)
    old, fine, p1, p2 = (os.path.join(work, n) for n in ("old", "fine", "p1", "p2"))
    write_case(old, 0.0, 2.0, "2.000", 80001)
    write_case(fine, 1e-3, 2.0001, "2.000", 160001)
    write_case(p1, 1e-12, 2.0 + 1e-13, "2.000", 80001)
    write_case(p2, -1e-12, 2.0 - 1e-13, "2.000", 80001)
    cases = [  # name, ay shift, rms, printed rms, evaluations, label, expected exit, expected text
        ("identical", 0.0, 2.0, "2.000", 80001, "BPFO", 0, "4 byte-identical"),
        ("within the error", 4e-4, 2.00003, "2.000", 80001, "BPFO", 0, "within bound"),
        ("a printed digit flips", 0.0, 2.0, "2.001", 80001, "BPFO", 0, "within bound"),
        ("the solver's cost", 0.0, 2.0, "2.000", 60001, "BPFO", 0, "within bound"),
        ("ay beyond the error", 5e-3, 2.0, "2.000", 80001, "BPFO", 1, "EXCEEDS"),
        ("the RMS beyond its error", 0.0, 2.001, "2.000", 80001, "BPFO", 1, "EXCEEDS"),
        ("a word changed", 0.0, 2.0, "2.000", 80001, "BPFI", 1, "TEXT CHANGED"),
    ]
    failures = 0
    for name, shift, rms, printed, evals, label, want, text in cases:
        new = os.path.join(work, "new")
        shutil.rmtree(new, ignore_errors=True)
        write_case(new, shift, rms, printed, evals, label)
        code, out = verdict(script, [old, new, fine, p1, p2])
        ok = code == want and text in out
        failures += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {name}: exit {code} (expected {want}), "
              f"'{text}' {'found' if text in out else 'missing'}")
        if not ok:
            print(out)
    # Round-off that moves the whole summary beyond the error (an adaptive method): a change
    # doing the same is like round-off, not a failure; the time series are not judged.
    write_case(p1, 2e-3, 2.0002, "2.000", 80001)
    new = os.path.join(work, "new")
    shutil.rmtree(new, ignore_errors=True)
    write_case(new, -2e-3, 2.0002, "2.000", 80001)
    code, out = verdict(script, [old, new, fine, p1, p2])
    ok = code == 0 and "1 cases amplify round-off" in out and "like round-off" in out
    failures += not ok
    print(f"{'ok  ' if ok else 'FAIL'} amplifying round-off: exit {code}")
    if not ok:
        print(out)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
