#!/usr/bin/python3
"""verification/README.md's numbers against the program that produces them, so that a stale
number fails a test instead of misleading a reader:

- "N checks: Q at `quick`, S more at `standard`, F more at `full`" against `bearing-verify list`;
- the mutation table's "caught at `quick` by (count; ...)" column against the counts of the
  `mutate --level quick` report (ctest verify.mutate_quick writes it), and every mutation of the
  report has a row.

    check_readme_numbers.py README.md BEARING_VERIFY MUTATE_REPORT_DIR
"""
import json
import os
import re
import subprocess
import sys


def main():
    readme, verify, mutate_dir = sys.argv[1], sys.argv[2], sys.argv[3]
    text = open(readme, encoding="utf-8").read()
    failures = []

    listing = subprocess.run([verify, "list"], check=True, capture_output=True, text=True).stdout
    levels = {"quick": 0, "standard": 0, "full": 0}
    for line in listing.splitlines():
        fields = line.split()
        if len(fields) > 3 and fields[3] in levels:
            levels[fields[3]] += 1
    m = re.search(r"(\d+)\s+checks:\s+(\d+)\s+at\s+`quick`,\s+(\d+)\s+more\s+at\s+`standard`,"
                  r"\s+(\d+)\s+more\s+at\s+`full`", text)
    if not m:
        failures.append("README: no sentence 'N checks: Q at `quick`, S more at `standard`, ...'")
    else:
        stated = tuple(int(g) for g in m.groups())
        actual = (sum(levels.values()), levels["quick"], levels["standard"], levels["full"])
        if stated != actual:
            failures.append(f"README says {stated} checks (all, quick, standard, full); "
                            f"bearing-verify list has {actual}")

    report = json.load(open(os.path.join(mutate_dir, "report.json"), encoding="utf-8"))
    if report["run"]["level"] != "quick" or report["run"]["only"]:
        sys.exit(f"{mutate_dir}: not a whole mutate --level quick report")
    rows = dict(re.findall(r"^\| `([a-z0-9.+-]+)` \| [^|]+ \| (\d+):", text, re.MULTILINE))
    for mutation in report["mutations"]:
        caught = len(mutation["caught_by"])
        if mutation["id"] not in rows:
            failures.append(f"README: no row for mutation {mutation['id']} (caught by {caught})")
        elif int(rows[mutation["id"]]) != caught:
            failures.append(f"README: {mutation['id']} caught by {rows[mutation['id']]}; the "
                            f"report: {caught}")

    for f in failures:
        print("STALE:", f)
    if not failures:
        print(f"verification/README.md's numbers hold: {sum(levels.values())} checks, "
              f"{len(report['mutations'])} mutations")
    sys.exit(1 if failures else 0)


main()
