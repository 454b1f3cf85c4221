#!/usr/bin/python3
"""Code mutants of the physics sources (issue 30): `bearing-verify mutate --source` runs this.

    source_mutants.py generate [--mutants N] [--fem-mutants M] [--seed S] [--files REGEX]
                               [--repo DIR] [--json FILE]
    source_mutants.py run --out DIR [--mutants N] [--fem-mutants M] [--seed S] [--files REGEX]
                          [--level quick] [--jobs J] [--repo DIR] [--commit REV] [--scratch DIR]
                          [--min-score F]

`generate` finds mutation sites on the code lines of PHYSICS_FILES and FEM_FILES (arithmetic and
comparison operators, numeric literals, cos/sin, min/max, floor/ceil, a dropped term, swapped
arguments, &&/||) and draws a fixed-seed sample covering every file: N from lumped/src/, M from
fem/. `--files REGEX` keeps only the files whose path it matches (Python re.search), so a study of
new sources draws all its N (and M) from them, at least two a file; the hand-written mutants are
then left out unless their file matches too. `run` copies the commit under test to a scratch folder once (git archive), configures it
once (Release, FE off), and for each mutant writes the mutated line, rebuilds bearing-verify
(only the mutated file recompiles; ccache serves the rest), runs `bearing-verify run --level
quick --fail-fast` and classifies it: killed (a check failed, or bearing-verify crashed, exited
with an error, or timed out — each said in `detail`), survived, did not build; the file is
restored after each. The fem/ mutants are judged in a second copy configured with deal.II
(FE on): each rebuilds bearing-fem and bearing-verify and runs only the checks that need
bearing-fem (those the FE-off baseline reports as skipped), their FE runs under `mpirun -np J`.
Without deal.II they are left out, and the run says so. Survivors are judged by hand in
source_mutants_judged.json beside this script (by mutant id): "equivalent" (with the argument; then
counted apart from the score), "gap" (a real gap: the check that would kill it) or "limit" (a
stated limit); the judgement is shown beside each survivor.

Writes DIR/source_mutants.json (every mutant, its status, the check that killed it, times) and
DIR/source_mutants.md (the table and the score killed / (total − did not build − equivalent)).
Exit 0 when the score reaches --min-score (default 0.9), 4 below it, 2 bad input, 1 internal.
Only the standard library: runs under /usr/bin/python3.
"""

import argparse
import io
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tarfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mutant_sites import FEM_FILES, PHYSICS_FILES, generate, hand_mutants, is_fem  # noqa: E402

DEFAULT_SEED = 30  # issue 30
DEFAULT_COUNT = 160  # every lumped physics file gets two (79 files: 154), the rest by sites
DEFAULT_FEM_COUNT = 20
HERE = os.path.dirname(os.path.abspath(__file__))
JUDGED_FILE = os.path.join(HERE, "source_mutants_judged.json")

# --- running --------------------------------------------------------------------------------


def sh(cmd, cwd=None, timeout=None, log=None):
    start = time.monotonic()
    # Its own process group: on a timeout the whole group goes (bearing-verify's test programs
    # too), so a hung mutant leaves nothing running.
    p = subprocess.Popen(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, errors="replace", start_new_session=True)
    try:
        out, _ = p.communicate(timeout=timeout)
        rc = p.returncode
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        out, _ = p.communicate()
        rc = "timeout"
    if log:
        with open(log, "w", encoding="utf-8") as h:
            h.write(out)
    return rc, out, time.monotonic() - start


class FemUnavailable(Exception):
    """deal.II is absent: the fem/ mutants cannot be built."""


def prepare_scratch(repo, commit, scratch, say, fem=False):
    """The commit's files in scratch/src (git archive, once per commit) and its build folder,
    configured with the FE module on (fem) or off."""
    rev = subprocess.run(["git", "-C", repo, "rev-parse", commit], stdout=subprocess.PIPE,
                         text=True, check=True).stdout.strip()
    src = os.path.join(scratch, "src")
    stamp = os.path.join(scratch, "commit")
    if not (os.path.exists(stamp) and open(stamp).read().strip() == rev):
        say("scratch: copying %s to %s" % (rev[:10], src))
        shutil.rmtree(scratch, ignore_errors=True)
        os.makedirs(src)
        archive = subprocess.run(["git", "-C", repo, "archive", rev], stdout=subprocess.PIPE,
                                 check=True).stdout
        tarfile.open(fileobj=io.BytesIO(archive)).extractall(src)
        with open(stamp, "w") as h:
            h.write(rev + "\n")
    # The build folder inside the copy, as in a checkout: ccache (CCACHE_BASEDIR = the source
    # root) then sees the same relative paths as the developer's build and serves its objects.
    build = os.path.join(src, "build")
    if not os.path.exists(os.path.join(build, "build.ninja")):
        rc, out, _ = sh(["cmake", "-S", src, "-B", build, "-G", "Ninja",
                         "-DCMAKE_BUILD_TYPE=Release",
                         "-DBEARING_WITH_FEM=" + ("ON" if fem else "OFF")],
                        log=os.path.join(scratch, "configure.log"))
        if rc != 0:
            shutil.rmtree(build, ignore_errors=True)
            if fem and "deal.II" in out and "not found" in out:
                raise FemUnavailable("deal.II 9.4 was not found (Debian: libdeal.ii-dev)")
            raise RuntimeError("configuring the scratch copy failed: " + out[-2000:])
    return rev, src, build


def build(part, log, timeout):
    return sh(["cmake", "--build", part["build"], "-j2", "--target"] + part["targets"],
              timeout=timeout, log=log)


def run_checks(part, level, jobs, timeout, fail_fast=True):
    cmd = [os.path.join(part["build"], "verification", "bearing-verify"), "run", "--level",
           level, "--jobs", str(jobs), "--quiet", "--out", part["run"]]
    if part.get("only"):
        cmd += ["--only", part["only"], "--mpi", str(jobs)]
    if fail_fast:
        cmd.append("--fail-fast")
    return sh(cmd, timeout=timeout)


def fe_checks(report_file):
    """The ids of the checks that need bearing-fem: those an FE-off run reports as skipped."""
    with open(report_file, encoding="utf-8") as h:
        return [c["id"] for c in json.load(h)["checks"] if c["status"] == "skipped"]


def baseline(part, level, jobs, logs, say):
    """Builds the unmutated commit in this part's copy and runs its checks; sets the run timeout
    (5 times the baseline's run, at least 90 s)."""
    name = part["name"]
    say("baseline (%s): building %s" % (name, " and ".join(part["targets"])))
    rc, text, t_build = build(part, os.path.join(logs, "baseline-%s-build.log" % name), None)
    if rc != 0:
        raise RuntimeError("the unmutated commit does not build (%s): see "
                           "logs/baseline-%s-build.log" % (name, name))
    rc, text, t_run = run_checks(part, level, jobs, None, fail_fast=False)
    if rc != 0:
        raise RuntimeError("the unmutated commit fails its %s checks (%s):\n%s" % (level, name,
                                                                                   text))
    part["timeout"] = max(90.0, 5.0 * t_run)
    part["baseline"] = {"build_s": t_build, "run_s": t_run}
    say("baseline (%s): built in %.0f s, %s checks pass in %.1f s; run timeout %.0f s"
        % (name, t_build, level, t_run, part["timeout"]))


def classify(rc, out):
    if rc == 0:
        return "survived", "", ""
    if rc == "timeout":
        return "killed", "", "timed out (counted as killed)"
    if rc == 4:
        m = re.search(r"fail-fast: stopped after (\S+) failed", out)
        return "killed", m.group(1) if m else "", ""
    if rc < 0:
        return "killed", "", "crashed with signal %d (counted as killed)" % -rc
    tail = out.strip().splitlines()[-1] if out.strip() else ""
    return "killed", "", "exit %d (counted as killed): %s" % (rc, tail[:200])


def load_judgements():
    """{id: (judgement, argument)} of the survivors judged by hand."""
    if not os.path.exists(JUDGED_FILE):
        return {}
    with open(JUDGED_FILE, encoding="utf-8") as h:
        return {e["id"]: (e["judgement"], e["argument"]) for e in json.load(h)["survivors"]}


def score(mutants):
    counts = {s: sum(1 for m in mutants if m["status"] == s)
              for s in ("killed", "survived", "equivalent", "did not build")}
    judged = len(mutants) - counts["did not build"] - counts["equivalent"]
    counts["total"] = len(mutants)
    counts["score"] = counts["killed"] / judged if judged else 1.0
    return counts


def write_outputs(out, meta, mutants):
    result = dict(meta)
    result["score"] = score(mutants)
    result["mutants"] = mutants
    tmp = os.path.join(out, "source_mutants.json.tmp")
    with open(tmp, "w", encoding="utf-8") as h:
        json.dump(result, h, indent=1)
    os.replace(tmp, os.path.join(out, "source_mutants.json"))
    s = result["score"]
    lines = ["# Code mutants of the physics sources", "",
             "commit `%s`, seed %d, level %s, %d mutants drawn from %d sites in %d files; "
             "wall time %.0f s (%.1f s per mutant)." % (
                 meta["commit"][:10], meta["seed"], meta["level"], len(mutants),
                 meta["sites"], len(meta["files"]), meta.get("wall_time", 0.0),
                 meta.get("wall_time", 0.0) / max(1, len(mutants))), "",
             "**Score %d / %d = %.1f %%** (killed / (total − did not build − equivalent)); "
             "%d killed, %d survived, %d equivalent, %d did not build." % (
                 s["killed"], s["total"] - s["did not build"] - s["equivalent"],
                 100 * s["score"], s["killed"], s["survived"], s["equivalent"],
                 s["did not build"]), ""]
    for name, part in (("lumped (src/ and headers)", [m for m in mutants
                                                        if not is_fem(m["file"])]),
                       ("fem/", [m for m in mutants if is_fem(m["file"])])):
        p = score(part)
        if part:
            lines.append("- %s: %d / %d killed (%.1f %%), %d mutants" % (
                name, p["killed"], p["total"] - p["did not build"] - p["equivalent"],
                100 * p["score"], p["total"]))
    fem = meta.get("fem", {})
    if "skipped" in fem:
        lines.append("- " + fem["skipped"])
    elif fem:
        lines.append("- fem/ mutants judged in a build with deal.II by the %d checks that need "
                     "bearing-fem, their FE runs under `mpirun -np %d`" % (
                         len(fem["checks"]), fem["mpi_processes"]))
    lines += ["",
             "| id | file:line | operator | original → mutated | status | killed by |",
             "|---|---|---|---|---|---|"]
    for m in mutants:
        by = m.get("killed_by") or m.get("detail", "")
        lines.append("| %s | %s:%d | `%s` | `%s` → `%s` | %s | %s |" % (
            m["id"], m["file"].replace("lumped/src/", ""), m["line"], m["operator"],
            m["original"].strip().replace("|", "\\|"), m["mutated"].strip().replace("|", "\\|"),
            m["status"], by.replace("|", "\\|")))
    with open(os.path.join(out, "source_mutants.md"), "w", encoding="utf-8") as h:
        h.write("\n".join(lines) + "\n")


def selected(files, pattern):
    """The files whose path matches --files (all without it)."""
    return [f for f in files if pattern is None or re.search(pattern, f)]


def draw(src, args):
    """The mutants of this run: the lumped draw, the hand-written ones and the fem/ draw."""
    pattern = getattr(args, "files", None)
    lumped_files, fem_files = selected(PHYSICS_FILES, pattern), selected(FEM_FILES, pattern)
    mutants, total, stats = [], 0, {}
    if lumped_files:
        mutants, total, stats = generate(src, args.mutants, args.seed, lumped_files)
    if args.only_hand:
        mutants = []
    if not args.no_hand:
        mutants += [m for m in hand_mutants(src) if pattern is None or re.search(pattern, m["file"])]
    if args.fem_mutants > 0 and fem_files:
        fem, fem_total, fem_stats = generate(src, args.fem_mutants, args.seed, fem_files)
        mutants += fem
        total += fem_total
        stats.update(fem_stats)
    return mutants, total, stats


def prepare_fem(args, rev, scratch, lumped, mutants, meta, say):
    """The FE-on copy where the fem/ mutants are judged (configured now, built before its first
    mutant), or None when deal.II is absent: then the fem/ mutants are left out, said in meta."""
    if not any(is_fem(m["file"]) for m in mutants):
        return None
    try:
        _, src, build_dir = prepare_scratch(args.repo, rev, os.path.join(scratch, "fem"), say,
                                            fem=True)
    except FemUnavailable as e:
        meta["fem"] = {"skipped": "fem/ mutants not run: " + str(e)}
        say("source_mutants: the %d fem/ mutants are left out: %s" % (
            sum(1 for m in mutants if is_fem(m["file"])), e))
        mutants[:] = [m for m in mutants if not is_fem(m["file"])]
        return None
    checks = fe_checks(os.path.join(lumped["run"], "report.json"))
    if not checks:
        raise RuntimeError("the FE-off baseline skipped no check: no check needs bearing-fem?")
    meta["fem"] = {"files": FEM_FILES, "checks": checks, "mpi_processes": args.jobs}
    return {"name": "fem", "src": src, "build": build_dir,
            "run": os.path.join(scratch, "fem", "run"), "targets": ["bearing-fem", "bearing-verify"],
            "only": "^(" + "|".join(re.escape(c) for c in checks) + ")$"}


def judging_order(mutants, previous):
    """Round robin over the files (a run cut short has still reached every file), the fem/
    mutants after the others (one switch of build folder), the kept verdicts first."""
    by_file = {}
    for m in mutants:
        by_file.setdefault(m["file"], []).append(m)
    order = []
    while any(by_file.values()):
        for f in list(by_file):
            if by_file[f]:
                order.append(by_file[f].pop(0))
    order.sort(key=lambda m: (m["id"] not in previous, is_fem(m["file"])))  # stable
    return order


def run(args):
    say = (lambda s: None) if args.quiet else (lambda s: print(s, file=sys.stderr, flush=True))
    out = os.path.abspath(args.out)
    try:
        os.makedirs(out, exist_ok=True)
    except OSError as e:
        print("source_mutants: --out = \"%s\": cannot create it (%s); allowed: a folder"
              % (args.out, e.strerror), file=sys.stderr)
        return 2
    scratch = os.path.abspath(args.scratch or os.path.join(out, "scratch"))
    start = time.monotonic()
    rev, src, build_dir = prepare_scratch(args.repo, args.commit, scratch, say)
    lumped = {"name": "lumped", "src": src, "build": build_dir,
              "run": os.path.join(scratch, "run"), "targets": ["bearing-verify"]}
    mutants, total, stats = draw(src, args)
    logs = os.path.join(out, "logs")
    os.makedirs(logs, exist_ok=True)
    baseline(lumped, args.level, args.jobs, logs, say)
    meta = {"format": "bearing-verify source mutants 1", "commit": rev, "seed": args.seed,
            "level": args.level, "sites": total, "files": stats, "files_pattern": args.files,
            "baseline": lumped["baseline"], "run_timeout_s": lumped["timeout"]}
    fem = prepare_fem(args, rev, scratch, lumped, mutants, meta, say)
    judged = load_judgements()
    previous = {}
    done_file = os.path.join(out, "source_mutants.json")
    if args.resume and os.path.exists(done_file):
        keep = ("killed", "did not build") + (() if args.rerun_survivors else
                                              ("survived", "equivalent"))
        previous = {m["id"]: m for m in json.load(open(done_file))["mutants"]
                    if m.get("status") in keep}
    rank = {m["id"]: i for i, m in enumerate(mutants)}  # the outputs stay in file order
    earlier = 0.0
    if previous:
        earlier = json.load(open(done_file)).get("wall_time", 0.0)
    results = []
    for k, m in enumerate(judging_order(mutants, previous), start=1):
        if m["id"] in previous:
            r = previous[m["id"]]
        else:
            part = fem if is_fem(m["file"]) else lumped
            if "baseline" not in part:
                baseline(part, args.level, args.jobs, logs, say)
                meta["fem"].update(baseline=part["baseline"], run_timeout_s=part["timeout"])
            r = apply_and_judge(m, part, args, logs)
        if r["status"] == "equivalent":
            r["status"] = "survived"  # judged again below, from the current list
        if r["status"] == "survived" and r["id"] in judged:
            judgement, argument = judged[r["id"]]
            r["detail"] = judgement + ": " + argument
            if judgement == "equivalent":
                r["status"] = "equivalent"
        results.append(r)
        results.sort(key=lambda x: rank[x["id"]])
        say("[%d/%d] %-13s %s %s:%d %s (%.0f s)" % (
            k, len(mutants), r["status"], r["id"], r["file"], r["line"], r.get("killed_by", ""),
            r.get("build_s", 0) + r.get("run_s", 0)))
        meta["wall_time"] = earlier + time.monotonic() - start
        write_outputs(out, meta, results)
    s = score(results)
    print("source mutants: %d killed, %d survived, %d equivalent, %d did not build of %d; "
          "score %.1f %%; %s" % (s["killed"], s["survived"], s["equivalent"], s["did not build"],
                                 s["total"], 100 * s["score"],
                                 os.path.join(out, "source_mutants.md")))
    return 0 if s["score"] >= args.min_score else 4


def rescore(args):
    """The judgements of source_mutants_judged.json applied again to OUT/source_mutants.json
    (after judging the survivors by hand), without running anything."""
    path = os.path.join(args.out, "source_mutants.json")
    with open(path, encoding="utf-8") as h:
        doc = json.load(h)
    judged = load_judgements()
    for m in doc["mutants"]:
        if m["status"] in ("survived", "equivalent"):
            m["status"], m["detail"] = "survived", ""
            if m["id"] in judged:
                judgement, argument = judged[m["id"]]
                m["detail"] = judgement + ": " + argument
                if judgement == "equivalent":
                    m["status"] = "equivalent"
    meta = {k: v for k, v in doc.items() if k not in ("mutants", "score")}
    write_outputs(args.out, meta, doc["mutants"])
    s = score(doc["mutants"])
    print("score %.1f %% (%d killed, %d survived, %d equivalent, %d did not build of %d)" % (
        100 * s["score"], s["killed"], s["survived"], s["equivalent"], s["did not build"],
        s["total"]))
    return 0 if s["score"] >= args.min_score else 4


def apply_and_judge(m, part, args, logs):
    r = dict(m)
    path = os.path.join(part["src"], m["file"])
    with open(path, encoding="utf-8") as h:
        original = h.read()
    lines = original.split("\n")
    if lines[m["line"] - 1] != m["original"]:
        raise RuntimeError("%s: line %d is not the line the mutant was drawn from" % (
            m["file"], m["line"]))
    lines[m["line"] - 1] = m["mutated"]
    try:
        with open(path, "w", encoding="utf-8") as h:
            h.write("\n".join(lines))
        log = os.path.join(logs, re.sub(r"[^\w.+-]", "_", m["id"]) + ".build.log")
        rc, text, r["build_s"] = build(part, log, 900)
        if rc != 0:
            r["status"], r["killed_by"] = "did not build", ""
            err = [l for l in text.splitlines() if "error" in l]
            r["detail"] = (err[0] if err else "build failed (rc %s)" % rc)[-200:]
            r["run_s"] = 0.0
            return r
        rc, text, r["run_s"] = run_checks(part, args.level, args.jobs, part["timeout"])
        r["status"], r["killed_by"], r["detail"] = classify(rc, text)
        return r
    finally:
        with open(path, "w", encoding="utf-8") as h:
            h.write(original)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = p.add_subparsers(dest="command", required=True)
    for name in ("generate", "run"):
        s = sub.add_parser(name)
        s.add_argument("--repo", default=os.path.dirname(HERE), help="the source tree")
        s.add_argument("--mutants", type=int, default=DEFAULT_COUNT)
        s.add_argument("--fem-mutants", type=int, default=DEFAULT_FEM_COUNT,
                       help="mutants of fem/ (0: none; judged only where deal.II is found)")
        s.add_argument("--seed", type=int, default=DEFAULT_SEED)
        s.add_argument("--files", metavar="REGEX",
                       help="only the physics files whose path matches (e.g. a new source's)")
    g = sub.choices["generate"]
    g.add_argument("--json", help="write the drawn mutants here (default: stdout)")
    r = sub.choices["run"]
    r.add_argument("--out", required=True)
    r.add_argument("--commit", default="HEAD")
    r.add_argument("--scratch", help="scratch folder (default OUT/scratch), reused per commit")
    r.add_argument("--level", default="quick", choices=["quick", "standard", "full"])
    r.add_argument("--jobs", type=int, default=2)
    r.add_argument("--min-score", type=float, default=0.9)
    r.add_argument("--resume", action="store_true",
                   help="keep the verdicts of OUT/source_mutants.json, run the rest")
    r.add_argument("--rerun-survivors", action="store_true",
                   help="with --resume: run the survivors (and equivalents) again, e.g. after "
                        "new checks")
    r.add_argument("--no-hand", action="store_true",
                   help="leave out the hand-written mutants of source_mutants_hand.json")
    r.add_argument("--only-hand", action="store_true", help="only the hand-written mutants")
    r.add_argument("--quiet", action="store_true")
    sc = sub.add_parser("score", help="apply the hand judgements to OUT/source_mutants.json")
    sc.add_argument("--out", required=True)
    sc.add_argument("--min-score", type=float, default=0.9)
    a = p.parse_args()
    if a.command == "score":
        return rescore(a)
    if a.files is not None:
        try:
            re.compile(a.files)
        except re.error as e:
            print("source_mutants: --files = \"%s\": not a regular expression (%s)" % (a.files, e),
                  file=sys.stderr)
            return 2
        if not selected(PHYSICS_FILES + FEM_FILES, a.files):
            print("source_mutants: --files = \"%s\": matches no physics file; allowed: a pattern "
                  "of paths in mutant_sites.py's PHYSICS_FILES or FEM_FILES" % a.files,
                  file=sys.stderr)
            return 2
    lumped_files, fem_files = selected(PHYSICS_FILES, a.files), selected(FEM_FILES, a.files)
    if lumped_files and a.mutants < len(lumped_files):
        print("source_mutants: --mutants = %d: too few; allowed: at least %d (the number of "
              "physics files)" % (a.mutants, len(lumped_files)), file=sys.stderr)
        return 2
    if fem_files and a.fem_mutants != 0 and a.fem_mutants < len(fem_files):
        print("source_mutants: --fem-mutants = %d: too few; allowed: 0 or at least %d (the "
              "number of fem/ physics files)" % (a.fem_mutants, len(fem_files)), file=sys.stderr)
        return 2
    if a.command == "generate":
        mutants, total, stats = draw(a.repo, argparse.Namespace(
            mutants=a.mutants, fem_mutants=a.fem_mutants, seed=a.seed, files=a.files,
            only_hand=False, no_hand=True))
        doc = {"seed": a.seed, "sites": total, "files": stats, "mutants": mutants}
        text = json.dumps(doc, indent=1)
        if a.json:
            with open(a.json, "w", encoding="utf-8") as h:
                h.write(text)
        else:
            print(text)
        print("%d mutants from %d sites in %d files" % (len(mutants), total, len(stats)),
              file=sys.stderr)
        return 0
    return run(a)


if __name__ == "__main__":
    try:
        sys.exit(main())
    except RuntimeError as e:
        print("source_mutants: %s" % e, file=sys.stderr)
        sys.exit(1)
