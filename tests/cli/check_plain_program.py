#!/usr/bin/python3
"""ctest cli.plain_program (issue 31): a plain bearing-sim loads neither MPI nor HDF5, and hands
what needs them to bearing-sim-full cleanly.

    check_plain_program.py BEARING_SIM hdf5|no-hdf5     (whether the build writes sweep.h5)

1. `ldd BEARING_SIM` lists no MPI, HDF5 or matio library (matio loads HDF5), nor libhwy (its
   static initialiser calibrates a timer in every process that loads it).
2. A copy of bearing-sim alone (no bearing-sim-full beside it) still runs `--version`, but
   `sweep --save` fails with exit 1, names bearing-sim-full and leaves no sweep.csv; the same for
   `analyse` of a .mat record when this build reads .mat through bearing-sim-full.
3. Beside its bearing-sim-full (in a build with HDF5), `sweep --save` hands over: exit 0,
   sweep.csv and sweep.h5 written.
Exit 0 when all hold, 1 otherwise (each failure printed)."""

import os
import shutil
import subprocess
import sys
import tempfile


def run(argv):
    return subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def main():
    sim = os.path.abspath(sys.argv[1])
    with_hdf5 = sys.argv[2] == "hdf5"
    failures = []
    libs = run(["ldd", sim]).stdout
    heavy = [l.split()[0] for l in libs.splitlines()
             if any(k in l for k in ("mpi", "hdf5", "matio", "libhwy"))]
    if heavy:
        failures.append("bearing-sim links %s" % ", ".join(heavy))
    full = os.path.join(os.path.dirname(sim), "bearing-sim-full")
    sweep = ["sweep", "--vary", "operation.speed=1000rpm:2000rpm:2", "--set",
             "solver.duration=0.3", "--save", "summary", "--jobs", "1", "--quiet"]
    with tempfile.TemporaryDirectory() as tmp:
        alone = os.path.join(tmp, "alone")
        os.makedirs(alone)
        shutil.copy2(sim, alone)
        lone = os.path.join(alone, "bearing-sim")
        if run([lone, "--version"]).returncode != 0:
            failures.append("bearing-sim --version fails without bearing-sim-full beside it")
        if os.access(full, os.X_OK) and with_hdf5:
            out = os.path.join(tmp, "lone-sweep")
            p = run([lone] + sweep + ["--out", out])
            if p.returncode != 1 or "bearing-sim-full" not in p.stderr:
                failures.append("sweep --save without bearing-sim-full: exit %d, stderr %r; "
                                "expected exit 1 naming bearing-sim-full" % (p.returncode,
                                                                             p.stderr[-300:]))
            if os.path.exists(os.path.join(out, "sweep.csv")):
                failures.append("sweep --save without bearing-sim-full left a sweep.csv")
            record = os.path.join(tmp, "record.mat")
            open(record, "wb").close()
            help_text = run([sim, "analyse", "--help"]).stdout
            if ".mat" in help_text and "libmatio-dev" not in help_text.split(".mat", 1)[1][:200]:
                p = run([lone, "analyse", record, "--set", "bearing.preset=6205", "--out",
                         os.path.join(tmp, "lone-analyse")])
                if p.returncode != 1 or "bearing-sim-full" not in p.stderr:
                    failures.append("analyse of a .mat without bearing-sim-full: exit %d, stderr "
                                    "%r" % (p.returncode, p.stderr[-300:]))
            out = os.path.join(tmp, "sweep")
            p = run([sim] + sweep + ["--out", out])
            if p.returncode != 0 or not all(os.path.exists(os.path.join(out, f))
                                            for f in ("sweep.csv", "sweep.h5")):
                failures.append("sweep --save through bearing-sim-full: exit %d, stderr %r" % (
                    p.returncode, p.stderr[-300:]))
        else:
            print("no bearing-sim-full with HDF5 in this build: steps 2-3 skipped")
    for f in failures:
        print("FAIL:", f)
    print("plain bearing-sim:", "ok" if not failures else "%d failures" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
