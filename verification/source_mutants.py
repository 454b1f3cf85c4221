#!/usr/bin/python3
"""Code mutants of the physics sources (issue 30): `bearing-verify mutate --source` runs this.

    source_mutants.py generate [--mutants N] [--seed S] [--repo DIR] [--json FILE]
    source_mutants.py run --out DIR [--mutants N] [--seed S] [--level quick] [--jobs J]
                          [--repo DIR] [--commit REV] [--scratch DIR] [--min-score F]

`generate` finds mutation sites on the code lines of PHYSICS_FILES (arithmetic and comparison
operators, numeric literals, cos/sin, min/max, floor/ceil, a dropped term, swapped arguments,
&&/||) and draws a fixed-seed sample covering every file. `run` copies the commit under test to a
scratch folder once (git archive), configures it once (Release, FE off), and for each mutant
writes the mutated line, rebuilds bearing-verify (only the mutated file recompiles; ccache serves
the rest), runs `bearing-verify run --level quick --fail-fast` and classifies it: killed (a check
failed, or bearing-verify crashed, exited with an error, or timed out — each said in `detail`),
survived, did not build; the file is restored after each. Survivors are judged by hand in
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
from mutant_sites import PHYSICS_FILES, generate, hand_mutants  # noqa: E402

DEFAULT_SEED = 30  # issue 30
DEFAULT_COUNT = 200
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


def prepare_scratch(repo, commit, scratch, say):
    """The commit's files in scratch/src (git archive, once per commit) and its build folder."""
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
                         "-DCMAKE_BUILD_TYPE=Release", "-DBEARING_WITH_FEM=OFF"],
                        log=os.path.join(scratch, "configure.log"))
        if rc != 0:
            raise RuntimeError("configuring the scratch copy failed: " + out[-2000:])
    return rev, src, build


def build(build_dir, log, timeout):
    return sh(["cmake", "--build", build_dir, "-j2", "--target", "bearing-verify"],
              timeout=timeout, log=log)


def run_checks(build_dir, level, jobs, out_dir, timeout, fail_fast=True):
    cmd = [os.path.join(build_dir, "verification", "bearing-verify"), "run", "--level", level,
           "--jobs", str(jobs), "--quiet", "--out", out_dir]
    if fail_fast:
        cmd.append("--fail-fast")
    return sh(cmd, timeout=timeout)


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
                 s["did not build"]), "",
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
    mutants, total, stats = generate(src, args.mutants, args.seed)
    if args.only_hand:
        mutants = []
    if not args.no_hand:
        mutants += hand_mutants(src)
    logs = os.path.join(out, "logs")
    os.makedirs(logs, exist_ok=True)
    say("baseline: building bearing-verify")
    rc, text, t_build = build(build_dir, os.path.join(logs, "baseline-build.log"), None)
    if rc != 0:
        raise RuntimeError("the unmutated commit does not build: see logs/baseline-build.log")
    rc, text, t_run = run_checks(build_dir, args.level, args.jobs,
                                 os.path.join(scratch, "run"), None, fail_fast=False)
    if rc != 0:
        raise RuntimeError("the unmutated commit fails its %s checks:\n%s" % (args.level, text))
    timeout = max(90.0, 5.0 * t_run)
    say("baseline: built in %.0f s, %s checks pass in %.1f s; run timeout %.0f s"
        % (t_build, args.level, t_run, timeout))
    judged = load_judgements()
    previous = {}
    done_file = os.path.join(out, "source_mutants.json")
    if args.resume and os.path.exists(done_file):
        keep = ("killed", "did not build") + (() if args.rerun_survivors else
                                              ("survived", "equivalent"))
        previous = {m["id"]: m for m in json.load(open(done_file))["mutants"]
                    if m.get("status") in keep}
    meta = {"format": "bearing-verify source mutants 1", "commit": rev, "seed": args.seed,
            "level": args.level, "sites": total, "files": stats,
            "baseline": {"build_s": t_build, "run_s": t_run}, "run_timeout_s": timeout}
    # Round robin over the files (a run cut short has still reached every file); the outputs
    # stay in file order.
    rank = {m["id"]: i for i, m in enumerate(mutants)}
    by_file = {}
    for m in mutants:
        by_file.setdefault(m["file"], []).append(m)
    order = []
    while any(by_file.values()):
        for f in list(by_file):
            if by_file[f]:
                order.append(by_file[f].pop(0))
    order.sort(key=lambda m: m["id"] not in previous)  # the kept verdicts first (stable)
    earlier = 0.0
    if previous:
        earlier = json.load(open(done_file)).get("wall_time", 0.0)
    results = []
    for k, m in enumerate(order, start=1):
        if m["id"] in previous:
            r = previous[m["id"]]
        else:
            r = apply_and_judge(m, src, build_dir, args, logs, scratch, timeout)
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


def apply_and_judge(m, src, build_dir, args, logs, scratch, timeout):
    r = dict(m)
    path = os.path.join(src, m["file"])
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
        rc, text, r["build_s"] = build(build_dir, log, 900)
        if rc != 0:
            r["status"], r["killed_by"] = "did not build", ""
            err = [l for l in text.splitlines() if "error" in l]
            r["detail"] = (err[0] if err else "build failed (rc %s)" % rc)[-200:]
            r["run_s"] = 0.0
            return r
        rc, text, r["run_s"] = run_checks(build_dir, args.level, args.jobs,
                                          os.path.join(scratch, "run"), timeout)
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
        s.add_argument("--seed", type=int, default=DEFAULT_SEED)
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
    if a.mutants < len(PHYSICS_FILES):
        print("source_mutants: --mutants = %d: too few; allowed: at least %d (the number of "
              "physics files)" % (a.mutants, len(PHYSICS_FILES)), file=sys.stderr)
        return 2
    if a.command == "generate":
        mutants, total, stats = generate(a.repo, a.mutants, a.seed)
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
