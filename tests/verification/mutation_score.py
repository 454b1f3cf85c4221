#!/usr/bin/python3
"""After `bearing-verify mutate`: every mutation caught, every claimed catch real.

Usage: /usr/bin/python3 mutation_score.py REPORT_DIR
"""
import json
import os
import sys

with open(os.path.join(sys.argv[1], "report.json")) as f:
    report = json.load(f)
score = report["mutation_score"]
gaps = [m["id"] for m in report["mutations"] if not m["caught"]]
false_claims = {m["id"]: m["claimed_not_caught"] for m in report["mutations"] if m["claimed_not_caught"]}
print(f"mutation score {score['caught']}/{score['total']}")
if gaps:
    sys.exit(f"mutations no check catches: {gaps}")
if false_claims:
    sys.exit(f"checks that name a mutation they do not catch: {false_claims}")
if score["total"] == 0 or report["totals"]["failed"] != 0:
    sys.exit("no mutations run, or the baseline failed")
