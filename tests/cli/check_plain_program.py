#!/usr/bin/python3
"""ctest cli.plain_program (issue 31): a plain bearing-sim loads neither MPI, HDF5 nor libsndfile,
and hands what needs them to bearing-sim-full cleanly.

    check_plain_program.py BEARING_SIM hdf5|no-hdf5     (whether the build writes sweep.h5)

1. `ldd BEARING_SIM` lists no MPI, HDF5 or matio library (matio loads HDF5), nor libhwy (its
   static initialiser calibrates a timer in every process that loads it), nor libsndfile (it
   loads seven codec libraries, FLAC, Vorbis, Opus, Ogg, mpg123 and LAME: a quarter of the CPU
   time of `bearing-sim --version`; the .wav reader is bearing-sim-full's).
2. A copy of bearing-sim alone (no bearing-sim-full beside it) still runs `--version`, but
   `sweep --save` fails with exit 1, names bearing-sim-full and leaves no sweep.csv (in a build
   with HDF5); the same for `analyse` of a .mat or a .wav record when this build reads that
   format through bearing-sim-full.
3. Beside its bearing-sim-full, `sweep --save` hands over (in a build with HDF5): exit 0,
   sweep.csv and sweep.h5 written; and `analyse` of a .wav (1 s of a 16-bit PCM sine at 12 kHz,
   written with Python's wave) hands over when this build reads .wav: exit 0, summary.json
   naming the record's rate from the WAV header.
Exit 0 when all hold, 1 otherwise (each failure printed)."""

import json
import math
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import wave


def run(argv):
    return subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def reads(sim, extension):
    """Whether bearing-sim reads `extension`, itself or through bearing-sim-full: its row in
    analyse --help names no reason it cannot ("(this build cannot read ...)")."""
    for line in run([sim, "analyse", "--help"]).stdout.splitlines():
        if line.strip().startswith(extension + " "):
            return "cannot read" not in line and "does not read" not in line
    return False


def write_wav(path, rate=12000, seconds=1.0, frequency=157.0):
    """A mono 16-bit PCM WAV of a sine at half full scale."""
    n = int(rate * seconds)
    samples = (int(16384 * math.sin(2 * math.pi * frequency * i / rate)) for i in range(n))
    with wave.open(path, "wb") as w:
        w.setnchannels(1)
        w.setsampwidth(2)
        w.setframerate(rate)
        w.writeframes(b"".join(struct.pack("<h", v) for v in samples))


def main():
    sim = os.path.abspath(sys.argv[1])
    with_hdf5 = sys.argv[2] == "hdf5"
    failures = []
    libs = run(["ldd", sim]).stdout
    heavy = [l.split()[0] for l in libs.splitlines()
             if any(k in l for k in ("mpi", "hdf5", "matio", "libhwy", "sndfile"))]
    if heavy:
        failures.append("bearing-sim links %s" % ", ".join(heavy))
    full = os.path.join(os.path.dirname(sim), "bearing-sim-full")
    sweep = ["sweep", "--vary", "operation.speed=1000rpm:2000rpm:2", "--set",
             "solver.duration=0.3", "--save", "summary", "--jobs", "1", "--quiet"]
    # The formats whose readers are bearing-sim-full's, when this build reads them.
    handed = [e for e in (".mat", ".wav") if reads(sim, e)]
    with tempfile.TemporaryDirectory() as tmp:
        alone = os.path.join(tmp, "alone")
        os.makedirs(alone)
        shutil.copy2(sim, alone)
        lone = os.path.join(alone, "bearing-sim")
        if run([lone, "--version"]).returncode != 0:
            failures.append("bearing-sim --version fails without bearing-sim-full beside it")
        if not os.access(full, os.X_OK):
            print("no bearing-sim-full in this build: steps 2-3 skipped")
        if os.access(full, os.X_OK) and with_hdf5:
            out = os.path.join(tmp, "lone-sweep")
            p = run([lone] + sweep + ["--out", out])
            if p.returncode != 1 or "bearing-sim-full" not in p.stderr:
                failures.append("sweep --save without bearing-sim-full: exit %d, stderr %r; "
                                "expected exit 1 naming bearing-sim-full" % (p.returncode,
                                                                             p.stderr[-300:]))
            if os.path.exists(os.path.join(out, "sweep.csv")):
                failures.append("sweep --save without bearing-sim-full left a sweep.csv")
            out = os.path.join(tmp, "sweep")
            p = run([sim] + sweep + ["--out", out])
            if p.returncode != 0 or not all(os.path.exists(os.path.join(out, f))
                                            for f in ("sweep.csv", "sweep.h5")):
                failures.append("sweep --save through bearing-sim-full: exit %d, stderr %r" % (
                    p.returncode, p.stderr[-300:]))
        elif os.access(full, os.X_OK):
            print("no HDF5 in this build: the sweep --save checks skipped")
        if os.access(full, os.X_OK):
            # An empty file suffices: the hand-over comes before the record is opened.
            for extension in handed:
                record = os.path.join(tmp, "record" + extension)
                open(record, "wb").close()
                p = run([lone, "analyse", record, "--set", "bearing.preset=6205", "--out",
                         os.path.join(tmp, "lone-analyse")])
                if p.returncode != 1 or "bearing-sim-full" not in p.stderr:
                    failures.append("analyse of a %s without bearing-sim-full: exit %d, stderr "
                                    "%r; expected exit 1 naming bearing-sim-full" % (
                                        extension, p.returncode, p.stderr[-300:]))
            if ".wav" in handed:
                record = os.path.join(tmp, "sine.wav")
                write_wav(record)
                out = os.path.join(tmp, "analyse-wav")
                p = run([sim, "analyse", record, "--set", "bearing.preset=6205", "--set",
                         "operation.speed=1797rpm", "--unit", "g", "--json", "--quiet", "--out",
                         out])
                summary = os.path.join(out, "summary.json")
                rate = None
                if p.returncode == 0 and os.path.exists(summary):
                    with open(summary) as f:
                        rate = json.load(f).get("record", {}).get("rate")
                if p.returncode != 0 or rate != 12000:
                    failures.append("analyse of a .wav through bearing-sim-full: exit %d, rate "
                                    "%r (expected 12000), stderr %r" % (p.returncode, rate,
                                                                        p.stderr[-300:]))
            else:
                print("this build reads no .wav through bearing-sim-full: the .wav checks skipped")
    for f in failures:
        print("FAIL:", f)
    print("plain bearing-sim:", "ok" if not failures else "%d failures" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
