#!/usr/bin/python3
"""`bearing-sim sweep --save …` read back with h5py: a 3-case sweep writes DIR/sweep.h5 whose root
names the design (keys, key_units, saved, cases, format_version); each case's group holds its
index, values and resolved case TOML; `bearing-sim run` of that very TOML with output.format = "npy"
gives files equal to the group's tables bit for bit, with the names and units columns.json lists,
and the summary's summary_json equals the run's summary.json (but for case.source and
case.bearing). Datasets are chunked with shuffle + gzip 4. A failed case keeps its group with the
error; a sweep.h5 that cannot be put in place fails the sweep and leaves no sweep.csv; --save
leaves sweep.csv (with the envelope columns) as it is without; a finished sweep resumed keeps its
sweep.h5. Skipped
(exit 77) when h5py cannot be imported.

    check_sweep_h5.py BEARING_SIM WORK_DIR
"""
import json
import pathlib
import shutil
import subprocess
import sys

try:
    import h5py
    import numpy as np
except ImportError as e:
    print(f"SKIP: h5py is not importable by {sys.executable} ({e}); "
          "install python3-h5py to run this check")
    sys.exit(77)

sim, work = sys.argv[1], pathlib.Path(sys.argv[2])
shutil.rmtree(work, ignore_errors=True)
short = ["--quiet", "--set", "solver.duration=0.3", "--set", "solver.transient=0.1",
         "--set", "output.envelope_band=auto"]
subprocess.run([sim, "sweep", "--out", str(work / "sweep"), "--jobs", "2",
                "--vary", "operation.speed=1000rpm:3000rpm:3", "--save", "response,spectrum",
                "--save", "envelope", "--save", "summary", *short],
               check=True, stdout=subprocess.DEVNULL)

failures = 0


def check(what, ok):
    global failures
    print(f"{what}: {'ok' if ok else 'FAILED'}")
    failures += not ok


def same_bits(a, b):
    return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()


files = sorted(p.name for p in (work / "sweep").iterdir())
check("only sweep.csv and sweep.h5, no temporary file", files == ["sweep.csv", "sweep.h5"])
with h5py.File(work / "sweep" / "sweep.h5", "r") as f:
    check("root format", f.attrs["format"] == "bearing-sim sweep")
    check("root format_version 1", int(f.attrs["format_version"]) == 1)
    check("root keys", list(f.attrs["keys"]) == ["operation.speed"])
    check("root key_units", list(f.attrs["key_units"]) == ["rad/s"])
    check("root saved", list(f.attrs["saved"]) == ["response", "spectrum", "envelope", "summary"])
    check("root cases", int(f.attrs["cases"]) == 3)
    check("groups in case order", list(f["cases"]) == ["000000", "000001", "000002"])
    speeds = [2 * np.pi * rpm / 60 for rpm in (1000, 2000, 3000)]
    for i, name in enumerate(f["cases"]):
        g = f["cases"][name]
        check(f"{name}: index", int(g.attrs["index"]) == i)
        check(f"{name}: values", np.allclose(g.attrs["values"], [speeds[i]], rtol=1e-12))
        check(f"{name}: status ok", g.attrs["status"] == "ok")
        # The stored case, run on its own, gives the same arrays.
        case = work / f"case{i}.toml"
        case.write_text(g.attrs["case_toml"])
        out = work / f"run{i}"
        subprocess.run([sim, "run", str(case), "--out", str(out), "--quiet",
                        "--set", "output.format=npy"], check=True, stdout=subprocess.DEVNULL)
        columns = json.loads((out / "columns.json").read_text())["tables"]
        for stem in ("response", "spectrum", "envelope"):
            d = g[stem]
            table = columns[f"{stem}.npy"]
            check(f"{name}/{stem}: bit for bit {stem}.npy",
                  same_bits(d[()], np.load(out / f"{stem}.npy")))
            check(f"{name}/{stem}: columns as columns.json", list(d.attrs["columns"]) == table["columns"])
            check(f"{name}/{stem}: units as columns.json", list(d.attrs["units"]) == table["units"])
            check(f"{name}/{stem}: chunked, shuffle, gzip 4",
                  d.chunks is not None and d.shuffle and d.compression == "gzip"
                  and d.compression_opts == 4)
        summary = json.loads((out / "summary.json").read_text())
        stored = json.loads(g["summary"].attrs["summary_json"])
        # Where the case came from differs (the file here), and the resolved TOML keeps the
        # preset's numbers but not its name (a rerun says bearing "custom").
        for s in (summary, stored):
            del s["case"]["source"], s["case"]["bearing"]
        check(f"{name}/summary: summary_json as summary.json", stored == summary)
        s = g["summary"]
        rows, cols = list(s.attrs["rows"]), list(s.attrs["columns"])
        check(f"{name}/summary: rms of ay as summary.json",
              s[rows.index("rms"), cols.index("ay")] == summary["channels"]["ay"]["rms"])

# --save changes nothing in sweep.csv, whose rows carry the envelope figures and the diagnosis.
subprocess.run([sim, "sweep", "--out", str(work / "nosave"), "--jobs", "2",
                "--vary", "operation.speed=1000rpm:3000rpm:3", *short],
               check=True, stdout=subprocess.DEVNULL)
saved_csv = (work / "sweep" / "sweep.csv").read_bytes()
check("--save: sweep.csv as without --save", saved_csv == (work / "nosave" / "sweep.csv").read_bytes())
check("--save: sweep.csv has the envelope and diagnosis columns",
      b",env_ay.spectral_kurtosis," in saved_csv and b",diagnosis.family," in saved_csv)

# A failed case keeps its group, with the error; the others go on.
tiny = ["--quiet", "--set", "solver.duration=0.05", "--set", "solver.transient=0.01"]
subprocess.run([sim, "sweep", "--out", str(work / "failed"), "--save", "summary",
                "--vary", "bearing.clearance=-100um:10um:2", *tiny],
               check=True, stdout=subprocess.DEVNULL)
with h5py.File(work / "failed" / "sweep.h5", "r") as f:
    g = f["cases/000000"]
    check("failed case: status", g.attrs["status"] == "failed")
    check("failed case: error names the key", "bearing.clearance" in g.attrs["error"])
    check("failed case: no tables", len(g) == 0)
    check("next case ok", f["cases/000001"].attrs["status"] == "ok" and "summary" in f["cases/000001"])

# All or nothing: when sweep.h5 cannot be put in place (a folder of that name is in the way), the
# sweep fails (exit 2), writes no sweep.csv and leaves no temporary HDF5 file; the sweep's own
# record, partial rows and spooled tables stay, as after any interrupted sweep (--resume).
blocked = work / "blocked"
(blocked / "sweep.h5" / "x").mkdir(parents=True)
run = subprocess.run([sim, "sweep", "--out", str(blocked), "--save", "summary",
                      "--vary", "operation.speed=1000rpm:2000rpm:2", *tiny],
                     stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
check("blocked: exit 2", run.returncode == 2)
check("blocked: the message names sweep.h5", "sweep.h5" in run.stderr)
check("blocked: nothing else written", sorted(p.name for p in blocked.iterdir()) ==
      [".sweep.csv.partial", ".sweep.h5.cases", "sweep.design.json", "sweep.h5"])
# A sweep without --save into the folder of one with it removes the sweep.h5 that no longer
# belongs to its sweep.csv.
subprocess.run([sim, "sweep", "--out", str(work / "failed"), "--vary",
                "bearing.clearance=0um:10um:2", *tiny], check=True, stdout=subprocess.DEVNULL)
check("rerun without --save: the old sweep.h5 is gone",
      not (work / "failed" / "sweep.h5").exists() and (work / "failed" / "sweep.csv").exists())

# Parts with --save merged: sweep.h5 holds the whole sweep's groups, datasets and attributes.
def same_file(x, y):
    def attrs(o):
        return {k: (v.tolist() if hasattr(v, "tolist") else v) for k, v in o.attrs.items()}
    with h5py.File(x, "r") as a, h5py.File(y, "r") as b:
        same = attrs(a) == attrs(b) and list(a["cases"]) == list(b["cases"])
        for g in a["cases"]:
            ga, gb = a["cases"][g], b["cases"][g]
            same &= attrs(ga) == attrs(gb) and list(ga) == list(gb)
            for d in ga:
                same &= ga[d][()].tobytes() == gb[d][()].tobytes() and attrs(ga[d]) == attrs(gb[d])
        return same

design = ["--vary", "operation.speed=1000rpm:3000rpm:5", "--save", "response,summary", *tiny]
subprocess.run([sim, "sweep", "--out", str(work / "whole"), *design], check=True,
               stdout=subprocess.DEVNULL)
for k in (1, 2):
    subprocess.run([sim, "sweep", "--out", str(work / f"part{k}"), "--part", f"{k}/2", *design],
                   check=True, stdout=subprocess.DEVNULL)
subprocess.run([sim, "merge", str(work / "merged"), str(work / "part2"), str(work / "part1")],
               check=True, stdout=subprocess.DEVNULL)
check("merge: sweep.csv as one run",
      (work / "whole" / "sweep.csv").read_bytes() == (work / "merged" / "sweep.csv").read_bytes())
check("merge: sweep.h5 as one run", same_file(work / "whole" / "sweep.h5",
                                              work / "merged" / "sweep.h5"))

# A --save sweep killed (SIGKILL) and resumed: sweep.csv and sweep.h5 as an uninterrupted run.
import signal, time
long = ["--vary", "operation.speed=1000rpm:3000rpm:150", "--save", "response,summary", "--quiet",
        "--set", "solver.duration=0.1", "--set", "solver.transient=0.02", "--jobs", "2"]
subprocess.run([sim, "sweep", "--out", str(work / "uncut"), *long], check=True,
               stdout=subprocess.DEVNULL)
killed = subprocess.Popen([sim, "sweep", "--out", str(work / "killed"), *long],
                          stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
partial = work / "killed" / ".sweep.csv.partial"
for _ in range(400):
    if partial.exists() and partial.read_text().count("\n") > 30:
        break
    time.sleep(0.05)
killed.send_signal(signal.SIGKILL)
killed.wait()
if (work / "killed" / "sweep.csv").exists():
    check("resume --save: the sweep was killed before it finished", False)
else:
    subprocess.run([sim, "sweep", "--resume", str(work / "killed"), "--quiet"], check=True,
                   stdout=subprocess.DEVNULL)
    check("resume --save: sweep.csv as uninterrupted",
          (work / "uncut" / "sweep.csv").read_bytes() == (work / "killed" / "sweep.csv").read_bytes())
    check("resume --save: sweep.h5 as uninterrupted",
          same_file(work / "uncut" / "sweep.h5", work / "killed" / "sweep.h5"))
    check("resume --save: no spool left", not (work / "killed" / ".sweep.h5.cases").exists())
    # Resumed once more, the finished sweep is left as it is, sweep.h5 included.
    before = {p.name: p.read_bytes() for p in (work / "killed").iterdir()}
    again = subprocess.run([sim, "sweep", "--resume", str(work / "killed"), "--quiet"],
                           capture_output=True, text=True)
    check("resume of a finished --save sweep: exit 0, said complete",
          again.returncode == 0 and "is complete: 150 cases" in again.stdout)
    check("resume of a finished --save sweep: sweep.csv and sweep.h5 untouched",
          {p.name: p.read_bytes() for p in (work / "killed").iterdir()} == before)

print(f"{failures} failed")
sys.exit(1 if failures else 0)
