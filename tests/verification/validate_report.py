#!/usr/bin/python3
"""report.json of bearing-verify against its documented schema (verification/report.schema.json),
plus what a schema cannot say: the totals add up, every figure it names exists, every mutation
run lists a score; and the figures are bearing.plot's: each PNG has the size of bearing.plot's
report figure, and each figure redrawn by bearing.plot.report_figure from figures.json shows that
file's data (every series, every law, every labelled line) with the axes and title it names.

Usage: /usr/bin/python3 validate_report.py SCHEMA REPORT_DIR [--expect-mutations]
"""
import importlib
import json
import os
import struct
import sys

import jsonschema
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "..", "python"))


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    assert head[:8] == b"\x89PNG\r\n\x1a\n", f"{path}: not a PNG"
    return struct.unpack(">II", head[16:24])


def artist(fig, gid):
    found = fig.findobj(lambda a: a.get_gid() == gid)
    assert len(found) == 1, f"{len(found)} artists with gid {gid}"
    return found[0]


def check_figure(plot, spec, png):
    """The PNG is bearing.plot's report size; bearing.plot draws the spec's data."""
    want = tuple(int(round(v * plot.DPI)) for v in plot.SIZES["report"])
    assert png_size(png) == want, f"{png}: {png_size(png)} px, bearing.plot's report is {want}"
    name = spec["name"]
    fig = plot.report_figure(spec)
    ax = fig.axes[0]
    assert ax.get_title().replace("\n", " ") == spec["title"], f"{name}: title {ax.get_title()!r}"
    if spec["panel"] == "force_approach":
        s = spec["series"][0]
        xy = artist(fig, "report:fe").get_xydata()
        assert np.array_equal(xy, np.column_stack([np.array(s["x"]) * 1e6, s["y"]])), name
        for gid, law in zip(("report:hertz", "report:fit"), spec["laws"]):
            line = artist(fig, gid)
            assert np.allclose(line.get_ydata(),
                               law["K"] * (line.get_xdata() / 1e6) ** law["exponent"],
                               rtol=1e-12, atol=0), f"{name}: {gid} is not {law}"
        return
    label, factor = plot.display_label(spec["y_label"]) if spec["panel"] != "series" \
        else (spec["y_label"], 1.0)
    assert ax.get_ylabel() == label and ax.get_xlabel() == spec["x_label"], f"{name}: labels"
    for i, s in enumerate(spec["series"]):
        xy = artist(fig, f"report:{i}").get_xydata()
        assert np.array_equal(xy, np.column_stack([s["x"], np.array(s["y"]) * factor])), \
            f"{name}: series {i} ({s['label']}) is not the file's data"
    for m in spec["markers"]:
        assert artist(fig, f"report:line:{m['label']}").get_xdata()[0] == m["x"], name
        assert m["label"] in [t.get_text() for t in ax.texts], f"{name}: no label {m['label']}"


def check_figures(report, report_dir):
    """Every figure report.json names is in figures/figures.json and drawn by bearing.plot."""
    plot = importlib.import_module("bearing.plot")
    with open(os.path.join(report_dir, "figures", "figures.json")) as f:
        specs = {s["name"]: s for s in json.load(f)}
    named = [fig for c in report["checks"] for fig in c["figures"]]
    kinds = set()
    for path in named:
        stem = os.path.splitext(os.path.basename(path))[0]
        assert stem in specs, f"{path}: not in figures.json"
        assert specs[stem]["panel"] in plot.PANELS, f"{stem}: panel {specs[stem]['panel']}"
        check_figure(plot, specs[stem], os.path.join(report_dir, path))
        kinds.add(specs[stem]["panel"])
    return len(named), sorted(kinds)


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
    pinned = [c["tolerance"]["basis"] == "pin" for c in checks]
    assert totals["passed"] == sum(c["status"] == "pass" and not p for c, p in zip(checks, pinned))
    assert totals["pinned"] == sum(c["status"] == "pass" and p for c, p in zip(checks, pinned))
    assert totals["failed"] == sum(c["status"] == "fail" for c in checks)
    assert totals["skipped"] == sum(c["status"] == "skipped" for c in checks)
    assert totals["reported"] == sum(c["status"] == "reported" for c in checks)
    assert sum(s["passed"] + s["pinned"] + s["failed"] + s["skipped"] + s["reported"]
               for s in report["summary"]) == len(checks)
    for c in checks:
        # Only a reported (not judged) check or a unit-test suite (reached by code mutants only)
        # names no mutation it must catch.
        assert c["catches"] or c["status"] == "reported" or c["reference_kind"] == "unit-test", \
            f"{c['id']}: names no mutation"
        for fig in c["figures"]:
            assert os.path.isfile(os.path.join(report_dir, fig)), f"{c['id']}: missing {fig}"
        if c["status"] != "skipped":
            assert c["value"] is not None and c["reference"] is not None, f"{c['id']}: null value"
    figures, panels = check_figures(report, report_dir)
    if "--expect-mutations" in sys.argv:
        assert "mutations" in report and "mutation_score" in report, "no mutation score"
        assert report["mutation_score"]["total"] == len(report["mutations"])
    print(f"report.json valid: {len(checks)} checks, {totals['passed']} passed, "
          f"{totals['failed']} failed, {totals['skipped']} skipped, {totals['reported']} reported; "
          f"{figures} figures drawn by "
          f"bearing.plot with their data (panels: {', '.join(panels)})")


if __name__ == "__main__":
    main()
