"""The figures of a bearing-verify report, drawn with the panels bearing-plot uses.

bearing-verify writes each check's figure as data to figures.json (verification/src/figure.h):
name, title, x_label, y_label (SI units in brackets), log_x, log_y, series [{label, x, y,
style}], markers [{x, label}] (labelled vertical lines), panel and laws [{label, K, exponent}].
`panel` says which panel draws it:

- "series" (the default): the named x-y series (series_axes);
- "spectrum": amplitude spectra (spectrum_axes), the markers the expected lines;
- "trace": time traces (trace_axes);
- "force_approach": series[0] the points (approach [m], force [N]), laws[0] the law drawn
  solid and laws[1], if any, dashed (force_approach_axes; approach shown in µm).

On the spectrum and trace panels a y unit DISPLAY knows is shown as bearing-plot shows it (m ->
µm, ...): the plotted values are the file's times the factor.
"""

import json
import os
import re

import numpy as np

from .cli import save
from .common import DISPLAY, FolderError, _new_figure, _style, _wrap
from .panels import force_approach_axes, mark_lines, series_axes, spectrum_axes, trace_axes

PANELS = ("series", "spectrum", "trace", "force_approach")


def display_label(label):
    """(label, factor): a label ending in '[SI unit]' with the unit as bearing-plot shows it and
    the factor from SI ('amplitude of y [m]' -> ('amplitude of y [µm]', 1e6))."""
    match = re.search(r"\[([^\[\]]+)\]\s*$", label)
    if not match or match.group(1) not in DISPLAY:
        return label, 1.0
    shown, factor = DISPLAY[match.group(1)]
    return label[:match.start(1)] + shown + label[match.end(1):], factor


def _arrays(s):
    return np.asarray(s["x"], dtype=float), np.asarray(s["y"], dtype=float)


def _spectrum(ax, spec):
    label, factor = display_label(spec["y_label"])
    tops = [np.max(_arrays(s)[1]) * factor for s in spec["series"] if len(s["y"])]
    for i, s in enumerate(spec["series"]):
        f, a = _arrays(s)
        line = spectrum_axes(ax, f, a * factor, label=label, fmax=f[-1], log=spec.get("log_y"),
                             gid="report:%d" % i, color="C%d" % (i % 10), top=max(tops))
        line.set_label(s.get("label") or None)
    ax.set_xlabel(spec["x_label"])
    mark_lines(ax, spec.get("markers", []), gid="report:line")
    if len(spec["series"]) > 1:
        ax.legend(loc="upper right", framealpha=0.9)


def _trace(ax, spec):
    label, factor = display_label(spec["y_label"])
    for i, s in enumerate(spec["series"]):
        t, y = _arrays(s)
        line = trace_axes(ax, t, y * factor, label=label, gid="report:%d" % i,
                          color="C%d" % (i % 10))
        line.set_label(s.get("label") or None)
        if i:  # an overlaid series dashed, so that equal curves stay distinguishable
            line.set_linestyle("--")
    ax.set_xlabel(spec["x_label"])
    mark_lines(ax, spec.get("markers", []), gid="report:line")
    if any(s.get("label") for s in spec["series"]):
        ax.legend(loc="best", framealpha=0.9)


def _force_approach(ax, spec):
    points, laws = spec["series"][0], spec.get("laws", [])
    if not laws:
        raise FolderError("figure %s: panel force_approach needs a law" % spec["name"])
    approach, force = _arrays(points)
    fit = (laws[1]["K"], laws[1]["exponent"]) if len(laws) > 1 else None
    force_approach_axes(ax, approach, force, hertz_K=laws[0]["K"], hertz_n=laws[0]["exponent"],
                        fit=fit, points_label=points["label"], law_label=laws[0]["label"],
                        fit_label=laws[1]["label"] if fit else None, gid="report")


def report_figure(spec):
    """One report figure (a figures.json entry) as a matplotlib Figure of SIZES['report']."""
    panel = spec.get("panel", "series")
    if panel not in PANELS:
        raise FolderError("figure %s: panel %r, expected one of %s"
                          % (spec.get("name"), panel, ", ".join(PANELS)))
    with _style():
        fig = _new_figure("report")
        ax = fig.subplots()
        if panel == "spectrum":
            _spectrum(ax, spec)
        elif panel == "trace":
            _trace(ax, spec)
        elif panel == "force_approach":
            _force_approach(ax, spec)
        else:
            series_axes(ax, spec["series"], xlabel=spec["x_label"], ylabel=spec["y_label"],
                        log_x=spec.get("log_x"), log_y=spec.get("log_y"),
                        lines=spec.get("markers", []), gid="report")
        ax.set_title(_wrap(spec["title"], 80), fontsize=10)
        fig.tight_layout()
    return fig


def draw_report_figures(figures_json, out_dir):
    """Draws every figure of a bearing-verify figures.json as OUT_DIR/NAME.png (written under a
    temporary name and renamed); returns the paths."""
    with open(figures_json) as f:
        specs = json.load(f)
    written = []
    for spec in specs:
        path = os.path.join(out_dir, spec["name"] + ".png")
        tmp = os.path.join(out_dir, "." + spec["name"] + ".tmp.png")
        save(report_figure(spec), tmp)
        os.replace(tmp, path)
        written.append(path)
    return written
