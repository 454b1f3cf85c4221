#!/usr/bin/python3
"""The timing half of bench/perf_guard.sh (issue 31): whole processes of two builds, interleaved.

    perf_guard.py --repo DIR --ref NAME --ref-build DIR --head-build DIR [--rounds N]

Each row is one command of bearing-sim (or the Python import) run as a user runs it, on core 0
(the guard pins itself there and its children inherit it), its output discarded; wall time from
spawn to exit. The spawn is vfork + exec (no Python code runs in the child), whose own cost the
table states as the time of /bin/true: ~0.5 ms, which a millisecond row carries. One warm-up round, then N rounds, each timing REF then HEAD for every row.
Prints a Markdown table: median and min–max of each build, HEAD/REF of the medians and the range
of the per-round ratios. A row a build cannot run (an older commit without the option or the
module) is shown as "—" with the reason below the table. Only the standard library."""

import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time


def rows(repo, work):
    sim = ["lumped/bearing-sim"]
    out = os.path.join(work, "out")
    return [
        ("`bearing-sim --version`", sim + ["--version"], {}),
        ("default run (6308 2-DOF, 1.2 s, RK4 5 µs, CSV)", sim + ["run", "--quiet", "--out", out],
         {}),
        ("ball model run (`model.kind = balls`)",
         sim + ["run", "--set", "model.kind=balls", "--quiet", "--out", out], {}),
        ("4-microphone run (`bench/acoustics_4mics.toml`)",
         sim + ["run", os.path.join(repo, "bench", "acoustics_4mics.toml"), "--quiet", "--out",
                out], {}),
        ("100-case sweep (`--vary operation.speed=1000rpm:3000rpm:100`, 0.3 s each, `--jobs 1`)",
         sim + ["sweep", "--vary", "operation.speed=1000rpm:3000rpm:100", "--set",
                "solver.duration=0.3", "--jobs", "1", "--quiet", "--out", out + "-sweep"], {}),
        ("Python `import bearing`", ["/usr/bin/python3", "-c", "import bearing"],
         {"PYTHONPATH": "python"}),
    ]


def command(build, argv, env):
    """argv with the build's paths; None when the build lacks the program or the module."""
    if argv[0].startswith("lumped/"):
        path = os.path.join(build, argv[0])
        if not os.access(path, os.X_OK):
            return None, None
        argv = [path] + argv[1:]
    e = dict(os.environ)
    for k, v in env.items():
        e[k] = os.path.join(build, v)
        if k == "PYTHONPATH" and not os.path.isdir(os.path.join(build, v, "bearing")):
            return None, None
    return argv, e


def time_once(argv, env):
    start = time.perf_counter()
    p = subprocess.run(argv, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    elapsed = time.perf_counter() - start
    if p.returncode != 0:
        return None, p.stderr.decode(errors="replace").strip().splitlines()[-1:] or ["exit %d"
                                                                                    % p.returncode]
    return elapsed * 1000.0, None


def libraries(build):
    sim = os.path.join(build, "lumped", "bearing-sim")
    out = subprocess.run(["ldd", sim], stdout=subprocess.PIPE, text=True).stdout
    names = [l.split()[0] for l in out.splitlines() if "=>" in l or l.strip().startswith("/")]
    heavy = sorted({n.split(".so")[0] for n in names if re.search(r"mpi|hdf5|matio", n)})
    return len(names), heavy


def fmt(values):
    if not values:
        return "—"
    return "%.1f (%.1f–%.1f)" % (statistics.median(values), min(values), max(values))


def main():
    a = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    a.add_argument("--repo", required=True)
    a.add_argument("--ref", required=True)
    a.add_argument("--ref-build", required=True)
    a.add_argument("--head-build", required=True)
    a.add_argument("--rounds", type=int, default=11)
    o = a.parse_args()
    if o.rounds < 3:
        print("perf_guard.py: --rounds = %d: too few; allowed: at least 3" % o.rounds,
              file=sys.stderr)
        return 2
    os.sched_setaffinity(0, {0})  # the children inherit it
    spawn = []
    for _ in range(21):
        ms, _ = time_once(["/bin/true"], dict(os.environ))
        spawn.append(ms)
    work = tempfile.mkdtemp(prefix="perf-guard-")
    try:
        table = rows(o.repo, work)
        builds = {"REF": o.ref_build, "HEAD": o.head_build}
        times = {(r[0], b): [] for r in table for b in builds}
        problems = {}
        for k in range(o.rounds + 1):  # round 0 warms the caches and is not kept
            for name, argv, env in table:
                for b, build in builds.items():
                    if (name, b) in problems:
                        continue
                    cmd, e = command(build, argv, env)
                    if cmd is None:
                        problems[(name, b)] = "not in this build"
                        continue
                    ms, err = time_once(cmd, e)
                    if ms is None:
                        problems[(name, b)] = "failed: " + err[0][:160]
                    elif k > 0:
                        times[(name, b)].append(ms)
            print("round %d/%d" % (k, o.rounds), file=sys.stderr, end="\r", flush=True)
        print(file=sys.stderr)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("Whole processes, pinned to one core, %d interleaved rounds after a warm-up; "
          "milliseconds, median (min–max). REF = %s (%s), HEAD = %s. The spawn itself "
          "(/bin/true) takes %.2f ms (median of 21)." % (
              o.rounds, o.ref, o.ref_build, o.head_build, statistics.median(spawn)))
    print()
    print("| measurement | REF %s [ms] | HEAD [ms] | HEAD / REF (range over the rounds) |" % o.ref)
    print("|---|---:|---:|---:|")
    for name, _, _ in table:
        r, h = times[(name, "REF")], times[(name, "HEAD")]
        ratio = "—"
        if r and h:
            per_round = [x / y for x, y in zip(h, r)]
            ratio = "%.3f (%.2f–%.2f)" % (statistics.median(h) / statistics.median(r),
                                          min(per_round), max(per_round))
        print("| %s | %s | %s | %s |" % (name, fmt(r), fmt(h), ratio))
    print()
    for b, build in builds.items():
        n, heavy = libraries(build)
        print("- %s's bearing-sim loads %d shared libraries (`ldd`); of MPI, HDF5 and matio: %s"
              % (b, n, ", ".join(heavy) if heavy else "none"))
    for (name, b), why in sorted(problems.items()):
        print("\n%s, %s: %s" % (b, name, why))
    return 0


if __name__ == "__main__":
    sys.exit(main())
