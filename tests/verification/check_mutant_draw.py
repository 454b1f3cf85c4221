#!/usr/bin/python3
"""ctest verify.mutant_draw: the code mutants' draw (source_mutants.py generate) in seconds, so that
a change of the physics sources that breaks the draw is seen without the hour-long run.

    check_mutant_draw.py VERIFICATION_DIR

Checks: two draws with the same seed are identical; the lumped and fem/ counts are the defaults
(160 and 20); every physics file with two sites or more gets at least two mutants; every mutated
line differs from its original and is the file's line; every hand-written mutant's text is on
exactly one line of its file (hand_mutants raises otherwise); the judgements name known fates."""

import json
import os
import subprocess
import sys
import tempfile


def draw(script, repo, out):
    subprocess.run(["/usr/bin/python3", script, "generate", "--repo", repo, "--json", out],
                   check=True, stderr=subprocess.DEVNULL)
    with open(out, encoding="utf-8") as h:
        return json.load(h)


def main():
    here = os.path.abspath(sys.argv[1])
    repo = os.path.dirname(here)
    sys.path.insert(0, here)
    import mutant_sites as ms  # noqa: E402
    import source_mutants as sm  # noqa: E402
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        a = draw(os.path.join(here, "source_mutants.py"), repo, os.path.join(tmp, "a.json"))
        b = draw(os.path.join(here, "source_mutants.py"), repo, os.path.join(tmp, "b.json"))
    if a != b:
        failures.append("two draws with seed %d differ" % a["seed"])
    mutants = a["mutants"]
    fem = [m for m in mutants if ms.is_fem(m["file"])]
    if (len(mutants) - len(fem), len(fem)) != (sm.DEFAULT_COUNT, sm.DEFAULT_FEM_COUNT):
        failures.append("drew %d lumped and %d fem/ mutants, not %d and %d" % (
            len(mutants) - len(fem), len(fem), sm.DEFAULT_COUNT, sm.DEFAULT_FEM_COUNT))
    for f in ms.PHYSICS_FILES + ms.FEM_FILES:
        with open(os.path.join(repo, f), encoding="utf-8") as h:
            text = h.read()
        n_sites = len(ms.sites(f, text))
        drawn = [m for m in mutants if m["file"] == f]
        if len(drawn) < min(2, n_sites):
            failures.append("%s: %d sites but %d mutants drawn" % (f, n_sites, len(drawn)))
        lines = text.split("\n")
        for m in drawn:
            if lines[m["line"] - 1] != m["original"] or m["mutated"] == m["original"]:
                failures.append("%s: mutant %s does not match line %d" % (f, m["id"], m["line"]))
    hand = ms.hand_mutants(repo)
    if len(hand) != 26:
        failures.append("%d hand-written mutants, not 26" % len(hand))
    with open(os.path.join(here, "source_mutants_judged.json"), encoding="utf-8") as h:
        fates = {e["judgement"] for e in json.load(h)["survivors"]}
    if not fates <= {"equivalent", "new check", "gap", "limit"}:
        failures.append("unknown judgements: %s" % sorted(fates))
    for f in failures:
        print("FAIL:", f)
    print("%d mutants (%d of fem/), %d hand-written: %s" % (
        len(mutants), len(fem), len(hand), "ok" if not failures else "%d failures" % len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
