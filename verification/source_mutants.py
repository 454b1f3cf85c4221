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
import hashlib
import json
import os
import random
import re
import shutil
import subprocess
import sys
import tarfile
import io
import time

# The physics: what the verification checks are meant to cover. Left out: input parsing (case/),
# records/ (file formats), sweep/, output writing, presets.cc (the preset data is also the
# checks' reference geometry), calibration.cc (the FE calibration, only with bearing-fem) and
# fem/ (its checks are FE-level and are skipped in a build without deal.II).
PHYSICS_FILES = [
    # contact / Hertz, kinematics, static load, excitation and defects, traction, material
    "lumped/src/core/contact.cc", "lumped/src/core/hertz_exact.cc",
    "lumped/src/core/hertz_hamrock_brewe.cc", "lumped/src/core/hertz_harris_table.cc",
    "lumped/src/core/kinematics.cc", "lumped/src/core/static_load.cc",
    "lumped/src/core/excitation.cc", "lumped/src/core/local_defect.cc",
    "lumped/src/core/traction.cc", "lumped/src/core/bearing.cc", "lumped/src/core/material.cc",
    "lumped/src/core/numerics/roots.cc", "lumped/src/core/numerics/line_search.cc",
    # the models
    "lumped/src/models/two_dof.cc", "lumped/src/models/three_dof.cc",
    "lumped/src/models/ball_dofs.cc", "lumped/src/models/contact_kernels.cc",
    "lumped/src/models/contact_kernels.h", "lumped/src/models/housing.cc",
    "lumped/src/models/quasi_static.cc", "lumped/src/models/quasi_static_run.cc",
    "lumped/src/models/dynamic_run.cc", "lumped/src/models/response.cc",
    "lumped/src/models/ball_set.h", "lumped/src/models/ball_motion.h",
    "lumped/src/models/frame_force.h", "lumped/src/models/race_excitation.h",
    "lumped/src/models/race_stiffness.h", "lumped/src/models/groove_geometry.h",
    "lumped/src/models/defect_excitation.h", "lumped/src/models/phasor.h",
    "lumped/src/models/curvature_compliance_table.h",
    # integrators
    "lumped/src/solvers/rk4.cc", "lumped/src/solvers/rk4_wide.cc",
    "lumped/src/solvers/rk4_stages.h", "lumped/src/solvers/newmark.cc",
    "lumped/src/solvers/bdf.cc", "lumped/src/solvers/gsl_adaptive.cc",
    "lumped/src/solvers/event_adaptive.cc", "lumped/src/solvers/integrator.cc",
    "lumped/src/solvers/integrator_detail.h", "lumped/src/solvers/mechanical_system.cc",
    # acoustics
    "lumped/src/acoustics/sources.cc", "lumped/src/acoustics/pressure.cc",
    "lumped/src/acoustics/microphones.cc",
    # signal analysis
    "lumped/src/signal/envelope.cc", "lumped/src/signal/fft.cc",
    "lumped/src/signal/fundamental_estimate.cc", "lumped/src/signal/harmonic_comb.cc",
    "lumped/src/signal/kurtogram.cc", "lumped/src/signal/line_floor.cc",
    "lumped/src/signal/line_names.cc", "lumped/src/signal/peaks.cc",
    "lumped/src/signal/prewhitening.cc", "lumped/src/signal/spectrum.cc",
    "lumped/src/signal/squared_envelope.cc", "lumped/src/signal/statistics.cc",
    # the run pipeline's analysis parts
    "lumped/src/pipeline/analysis.cc", "lumped/src/pipeline/diagnosis.cc",
    "lumped/src/pipeline/envelope_analysis.cc", "lumped/src/pipeline/fault_lines.cc",
    "lumped/src/pipeline/record_analysis.cc", "lumped/src/pipeline/excitation_families.cc",
    "lumped/src/pipeline/noise.cc",
]

DEFAULT_SEED = 30  # issue 30
DEFAULT_COUNT = 200
HERE = os.path.dirname(os.path.abspath(__file__))
JUDGED_FILE = os.path.join(HERE, "source_mutants_judged.json")


# --- finding the code lines ------------------------------------------------------------------


def code_lines(text):
    """(line number, line, code mask) for each line: the mask is the line with comments blanked;
    lines that are no place for a mutant (preprocessor, strings, messages, templates, operator
    declarations, input guards) are left out."""
    lines = text.split("\n")
    out = []
    in_block = False
    in_throw = False
    for n, line in enumerate(lines, start=1):
        code = []
        i = 0
        while i < len(line):
            if in_block:
                end = line.find("*/", i)
                if end < 0:
                    code.append(" " * (len(line) - i))
                    i = len(line)
                else:
                    code.append(" " * (end + 2 - i))
                    i = end + 2
                    in_block = False
            elif line.startswith("//", i):
                code.append(" " * (len(line) - i))
                i = len(line)
            elif line.startswith("/*", i):
                in_block = True
            else:
                code.append(line[i])
                i += 1
        mask = "".join(code)
        stripped = mask.strip()
        starts_throw = "throw " in mask or "throw(" in mask
        skip = (not stripped or stripped.startswith("#") or '"' in mask or "'" in mask
                or in_throw or starts_throw or "operator" in mask or "template" in mask
                or "static_assert" in mask or "assert(" in mask or "namespace" in mask
                or "std::array<" in mask or "Matrix<" in mask or "Vector<" in mask)
        if starts_throw or in_throw:
            in_throw = not stripped.endswith(";") and not stripped.endswith("}")
        if not skip:
            out.append((n, line, mask))
    # An input guard (`if (...)` whose statement is a throw) checks bad input, not physics: the
    # verification checks never feed bad input, so its mutants would only say that.
    guarded = set()
    by_number = {n: m for n, _, m in out}
    for n, line in enumerate(lines, start=1):
        if "throw" in line and n not in by_number:
            k = n - 1
            while k >= 1 and (k in by_number) and k >= n - 3:
                guarded.add(k)
                if lines[k - 1].strip().startswith("if"):
                    break
                k -= 1
        if "throw" in line and line.strip().startswith("if"):
            guarded.add(n)
    return [(n, l, m) for n, l, m in out if n not in guarded]


# --- mutation operators ------------------------------------------------------------------------

BINARY = {
    " + ": [(" - ", "arith")], " - ": [(" + ", "arith")],
    " * ": [(" / ", "arith")], " / ": [(" * ", "arith")],
    " += ": [(" -= ", "arith")], " -= ": [(" += ", "arith")],
    " *= ": [(" /= ", "arith")], " /= ": [(" *= ", "arith")],
    " < ": [(" <= ", "compare"), (" > ", "compare")], " <= ": [(" < ", "compare")],
    " > ": [(" >= ", "compare"), (" < ", "compare")], " >= ": [(" > ", "compare")],
    " == ": [(" != ", "compare")], " != ": [(" == ", "compare")],
    " && ": [(" || ", "logic")], " || ": [(" && ", "logic")],
}
FUNCTIONS = {"std::cos(": "std::sin(", "std::sin(": "std::cos(", "std::min(": "std::max(",
             "std::max(": "std::min(", "std::floor(": "std::ceil(", "std::ceil(": "std::floor("}
SYMMETRIC = {"min", "max", "hypot", "swap", "push_back", "emplace_back", "resize", "assign",
             "insert", "emplace", "fill", "copy", "make_pair", "set", "reserve", "at", "find"}
NUMBER = re.compile(r"(?<![\w.])(\d+\.\d*(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?|\d+[eE][+-]?\d+"
                    r"|\d+)(?![\w.])")
STOP = re.compile(r" (?:[-+]|[<>]=?|==|!=|&&|\|\||[-+*/]?=|\?|:) ")


def mutated_literal(text):
    if re.fullmatch(r"\d+", text):
        n = int(text)
        return "1" if n == 0 else "0" if n == 1 else str(n + 1)
    value = float(text)
    if value == 0.0:
        return "1.0"
    new = "%.6g" % (value * 1.1)
    if not re.search(r"[.eE]", new):
        new += ".0"
    return new


def term_end(mask, start):
    """End of the additive term that starts at `start` (for a dropped term), or None when the
    term does not close on this line."""
    depth = 0
    i = start
    while i < len(mask):
        c = mask[i]
        if c in "([{":
            depth += 1
        elif c in ")]}":
            if depth == 0:
                return i
            depth -= 1
        elif depth == 0 and (c in ",;" or STOP.match(mask, i)):
            return i
        i += 1
    rest = mask[start:].rstrip()
    if depth != 0 or not rest or rest[-1] in "+-*/=<>&|,(":
        return None
    return len(mask.rstrip())


def call_arguments(mask, open_paren):
    """(start, end) of the two arguments of the call whose '(' is at open_paren, when it has two
    on this line; else None."""
    depth = 0
    commas = []
    for i in range(open_paren, len(mask)):
        c = mask[i]
        if c in "([{<" and not (c == "<" and mask[i - 1] == " "):
            depth += 1
        elif c in ")]}>" and not (c == ">" and (mask[i - 1] in " -")):
            depth -= 1
            if depth == 0:
                if len(commas) != 1:
                    return None
                a = (open_paren + 1, commas[0])
                b = (commas[0] + 1, i)
                return a, b
        elif c == "," and depth == 1:
            commas.append(i)
    return None


def sites(path, text):
    """Every mutant of one file: dicts file, line, column, operator, original, mutated."""
    out = []

    def add(n, line, col, op, new_line):
        if new_line != line:
            out.append({"file": path, "line": n, "column": col + 1, "operator": op,
                        "original": line, "mutated": new_line})

    for n, line, mask in code_lines(text):
        for token, replacements in BINARY.items():
            for m in re.finditer(re.escape(token), mask):
                col = m.start()
                for new, op in replacements:
                    add(n, line, col, op + ":" + token.strip() + "->" + new.strip(),
                        line[:col] + new + line[col + len(token):])
                if token in (" + ", " - "):
                    end = term_end(mask, col + len(token))
                    if end is not None and end > col + len(token):
                        add(n, line, col, "drop-term:" + token.strip(), line[:col] + line[end:])
        for m in NUMBER.finditer(mask):
            prev = mask[:m.start()].rstrip()
            if prev.endswith("[") or prev.endswith("<") or mask[m.end():].startswith(">"):
                continue  # an index or a template argument: not a physical constant
            add(n, line, m.start(), "literal:" + m.group(1),
                line[:m.start()] + mutated_literal(m.group(1)) + line[m.end():])
        for old, new in FUNCTIONS.items():
            for m in re.finditer(re.escape(old), mask):
                add(n, line, m.start(), "function:" + old[5:-1] + "->" + new[5:-1],
                    line[:m.start()] + new + line[m.end():])
        for m in re.finditer(r"([A-Za-z_][\w:]*)\(", mask):
            name = m.group(1).split("::")[-1]
            if name in SYMMETRIC or name in ("if", "for", "while", "switch", "return", "sizeof"):
                continue
            args = call_arguments(mask, m.end() - 1)
            if args is None:
                continue
            (a0, a1), (b0, b1) = args
            a, b = line[a0:a1].strip(), line[b0:b1].strip()
            if not a or not b or a == b:
                continue
            add(n, line, m.start(), "swap-args:" + name,
                line[:a0] + b + "," + (" " if line[b0] == " " else "") + a + line[b1:])
    return out


def mutant_id(m):
    key = "\0".join([m["file"], m["original"].strip(), str(m["column"]), m["mutated"].strip()])
    stem = os.path.splitext(os.path.basename(m["file"]))[0]
    return stem + "-" + hashlib.sha1(key.encode()).hexdigest()[:8]


def generate(repo, count, seed, files=PHYSICS_FILES):
    """A fixed-seed sample of `count` mutants covering every file: each file gets at least two
    (when it has them), the rest in proportion to its number of sites."""
    per_file = {}
    for f in files:
        with open(os.path.join(repo, f), encoding="utf-8") as h:
            per_file[f] = sites(f, h.read())
        for m in per_file[f]:
            m["id"] = mutant_id(m)
    total = sum(len(v) for v in per_file.values())
    rng = random.Random(seed)
    chosen = []
    for f in files:
        pool = sorted(per_file[f], key=lambda m: m["id"])
        rng.shuffle(pool)
        per_file[f] = pool
        take = min(len(pool), 2)
        chosen += pool[:take]
        per_file[f] = pool[take:]
    rest = [m for f in files for m in per_file[f]]
    rng.shuffle(rest)
    chosen += rest[:max(0, count - len(chosen))]
    chosen.sort(key=lambda m: (files.index(m["file"]), m["line"], m["column"], m["id"]))
    stats = {f: sum(1 for m in chosen if m["file"] == f) for f in files}
    return chosen, total, stats


HAND_FILE = os.path.join(HERE, "source_mutants_hand.json")


def hand_mutants(repo, path=HAND_FILE):
    """The hand-written physics mutants (source_mutants_hand.json), located in `repo`."""
    with open(path, encoding="utf-8") as h:
        table = json.load(h)["mutants"]
    out = []
    for e in table:
        with open(os.path.join(repo, e["file"]), encoding="utf-8") as h:
            lines = h.read().split("\n")
        at = [n for n, l in enumerate(lines, start=1) if e["find"] in l]
        if len(at) != 1:
            raise RuntimeError("hand mutant %s: \"%s\" is on %d lines of %s, not 1" % (
                e["name"], e["find"], len(at), e["file"]))
        line = lines[at[0] - 1]
        out.append({"file": e["file"], "line": at[0], "column": line.index(e["find"]) + 1,
                    "operator": "hand:" + e["what"], "original": line,
                    "mutated": line.replace(e["find"], e["replace"]), "id": "hand-" + e["name"]})
    return out


# --- running --------------------------------------------------------------------------------


def sh(cmd, cwd=None, timeout=None, log=None):
    start = time.monotonic()
    try:
        p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           timeout=timeout, text=True, errors="replace")
        rc, out = p.returncode, p.stdout
    except subprocess.TimeoutExpired as e:
        rc, out = "timeout", (e.stdout or b"").decode(errors="replace") if isinstance(
            e.stdout, bytes) else (e.stdout or "")
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
