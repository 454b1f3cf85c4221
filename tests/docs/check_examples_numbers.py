#!/usr/bin/python3
"""The numbers of examples/README.md against HEAD (issue 30: docs tied to HEAD).

    check_examples_numbers.py REPO BEARING_SIM OUTDIR

Runs examples/run_studies.sh with BEARING_SIM into OUTDIR (~3 min on 2 cores), then checks every
row of the README's output blocks (fenced blocks without a language; command blocks are skipped):
its numbers, in order, must be found in one line of OUTDIR/tables.txt, or in two lines that start
with the same number (the README sets an inner-race and an outer-race row side by side), each
equal to the table's value rounded to the digits the README prints. Two kinds of README numbers are
not the toolkit's and are left out: the columns headed "paper" (the papers' values) and the rows
marked "(chaotic)" (their values change with any floating-point change, as the README says).

Fails, listing each stale row, when a committed number is no longer what HEAD prints.
"""

import os
import re
import subprocess
import sys

NUMBER = re.compile(r"[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?")


def numbers(text):
    """[(value, printed decimals, in e-notation)] of the numbers in text, in order."""
    out = []
    for m in NUMBER.finditer(text):
        mantissa = m.group(0).split("e")[0]
        decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
        out.append((float(m.group(0)), decimals, "e" in m.group(0)))
    return out


def rounds_to(printed, value):
    """Whether the table's value, rounded to the README's digits, is the README's number."""
    v, decimals, scientific = printed
    half = 0.5 * 10.0 ** (-decimals) * (abs(v) if scientific else 1.0)
    return abs(v - value) <= half * (1 + 1e-9) + 1e-300


def in_order(readme_row, table_values):
    i = 0
    for x in table_values:
        if i < len(readme_row) and rounds_to(readme_row[i], x):
            i += 1
    return i == len(readme_row)


def paper_columns(block_lines):
    """Character spans of the columns a header line names "paper …" (one word after it)."""
    spans = []
    for line in block_lines:
        for m in re.finditer(r"paper\s+\S+", line):
            spans.append((m.start(), m.end()))
    return spans


def output_rows(readme):
    """(line number, row text with the paper columns blanked) of every numeric output row."""
    rows = []
    for m in re.finditer(r"^```([a-z]*)\n(.*?)^```", readme, re.S | re.M):
        if m.group(1):  # ```sh, ```toml, ```python: commands and inputs, not output
            continue
        first = readme.count("\n", 0, m.start(2)) + 1
        lines = m.group(2).splitlines()
        spans = paper_columns(lines)
        for k, line in enumerate(lines):
            if not re.search(r"\d\.\d", line) or "(chaotic)" in line:
                continue
            if line.lstrip().startswith(("examples/", "build/", "bearing", "mpirun", "--")):
                continue
            # Blank every token that overlaps a paper column (values may overhang the header).
            kept = "".join(" " * len(t.group(0)) if any(t.start() < b and t.end() > a
                                                         for a, b in spans) else t.group(0)
                           for t in re.finditer(r"\s+|\S+", line))
            rows.append((first + k, kept))
    return rows


def main():
    if len(sys.argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    repo, sim, out = sys.argv[1:]
    env = dict(os.environ, BEARING_SIM=sim)
    run = subprocess.run(["bash", os.path.join(repo, "examples", "run_studies.sh"), out],
                         env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if run.returncode != 0:
        print("run_studies.sh failed (exit %d):\n%s" % (run.returncode, run.stderr[-3000:]))
        return 1
    with open(os.path.join(out, "tables.txt"), encoding="utf-8") as h:
        table = [numbers(line) for line in h.read().splitlines()]
    table = [t for t in table if t]
    by_lead = {}
    for t in table:
        by_lead.setdefault(t[0][0], []).append(t)
    with open(os.path.join(repo, "examples", "README.md"), encoding="utf-8") as h:
        readme = h.read()
    rows = output_rows(readme)
    stale = []
    for line_no, row in rows:
        want = numbers(row)
        if any(in_order(want, [x[0] for x in t]) for t in table):
            continue
        pairs = by_lead.get(want[0][0], [])
        if any(in_order(want, [x[0] for x in a] + [x[0] for x in b[1:]])
               for a in pairs for b in pairs if a is not b):
            continue
        stale.append((line_no, row.strip()))
    for line_no, row in stale:
        print("examples/README.md:%d: not what HEAD prints in tables.txt: %s" % (line_no, row))
    print("%d of %d output rows of examples/README.md agree with HEAD's tables.txt (%s)"
          % (len(rows) - len(stale), len(rows), os.path.join(out, "tables.txt")))
    if not rows:
        print("no output rows found: the README's blocks changed shape")
        return 1
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main())
