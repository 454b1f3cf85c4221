#!/usr/bin/python3
"""report.json of bearing-verify against its documented schema (verification/report.schema.json),
plus what a schema cannot say: the totals add up, every figure it names exists, every mutation
run lists a score.

Usage: /usr/bin/python3 validate_report.py SCHEMA REPORT_DIR [--expect-mutations]
"""
import json
import os
import sys

import jsonschema


def main():
    schema_path, report_dir = sys.argv[1], sys.argv[2]
    with open(schema_path) as f:
        schema = json.load(f)
    with open(os.path.join(report_dir, "report.json")) as f:
        text = f.read()
    if "NaN" in text or "Infinity" in text:
        sys.exit("report.json contains NaN or Infinity")
    report = json.loads(text)
    jsonschema.Draft202012Validator.check_schema(schema)
    jsonschema.validate(report, schema, cls=jsonschema.Draft202012Validator)
    checks = report["checks"]
    totals = report["totals"]
    assert totals["checks"] == len(checks), "totals.checks != number of checks"
    assert totals["passed"] == sum(c["status"] == "pass" for c in checks)
    assert totals["failed"] == sum(c["status"] == "fail" for c in checks)
    assert totals["skipped"] == sum(c["status"] == "skipped" for c in checks)
    assert sum(s["passed"] + s["failed"] + s["skipped"] for s in report["summary"]) == len(checks)
    for c in checks:
        for fig in c["figures"]:
            assert os.path.isfile(os.path.join(report_dir, fig)), f"{c['id']}: missing {fig}"
        if c["status"] != "skipped":
            assert c["value"] is not None and c["reference"] is not None, f"{c['id']}: null value"
    if "--expect-mutations" in sys.argv:
        assert "mutations" in report and "mutation_score" in report, "no mutation score"
        assert report["mutation_score"]["total"] == len(report["mutations"])
    print(f"report.json valid: {len(checks)} checks, {totals['passed']} passed, "
          f"{totals['failed']} failed, {totals['skipped']} skipped")


if __name__ == "__main__":
    main()
