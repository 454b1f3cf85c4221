"""The figure of a `bearing-sim stiffness` folder: the bearing's stiffness terms at the case's cage
angle against the varied key, one panel per unit, with each diagonal term's range over one ball
pass as a band and its mean over it (what a rotor model takes) as a dotted line when stiffness.json
has them (docs/rotordynamics.md); with [lubricant] (stiffness.csv's c_* columns) the squeeze-film
damping C = dF/d(dq/dt) in a second row of panels beside it."""

import csv
import json
import os
import re

import numpy as np

from .common import FolderError, _new_figure, _style
from .sweep_figures import key_display

DOFS = ("x", "y", "z", "gx", "gy")
# The panels: the unit of K_ij (i <= j) in stiffness.csv's header, and the panel's title.
PANELS = (("N/m", "forces by displacements [N/m]"),
          ("N/rad", "forces by tilts [N/rad] = moments by displacements [N]"),
          ("N*m/rad", "moments by tilts [N·m/rad]"))
SHOWN_UNIT = {"N/m": "N/m", "N/rad": "N/rad", "N*m/rad": "N·m/rad"}
# The damping's panels, by the stiffness unit of the same block: C_ij's unit is K_ij's times s.
DAMPING_SHOWN_UNIT = {"N/m": "N·s/m", "N/rad": "N·s/rad", "N*m/rad": "N·m·s/rad"}
DAMPING_TITLE = {"N/m": "damping, forces by velocities [N·s/m]",
                 "N/rad": "damping, forces by tilt rates [N·s/rad] = moments by velocities [N·s]",
                 "N*m/rad": "damping, moments by tilt rates [N·m·s/rad]"}
OFF_DIAGONAL_SHOWN = 3  # the largest off-diagonal terms per panel
_COLUMN = re.compile(r"^(?P<name>.+?) \[(?P<unit>[^\]]*)\]$")


def term_name(i, j, prefix="k"):
    """stiffness.csv's name of K_ij: "k_xx", "k_x_gx", "k_gx_gy" (as bearing/stiffness.h); with
    prefix "c" C_ij's ("c_xx", as bearing/stiffness_output.h)."""
    a, b = DOFS[i], DOFS[j]
    return prefix + "_" + a + ("" if len(a) == 1 and len(b) == 1 else "_") + b


def term_unit(i, j):
    """The unit of K_ij for i <= j: N/m, N/rad or N*m/rad."""
    return "N*m/rad" if i >= 3 else ("N/rad" if j >= 3 else "N/m")


class Stiffness:
    """stiffness.csv (and the case named in stiffness.json): the varied keys, then the terms."""

    def __init__(self, folder):
        self.folder = folder
        self.path = os.path.join(folder, "stiffness.csv")
        with open(self.path, newline="") as f:
            rows = [r for r in csv.reader(f) if r]
        if not rows or "k_xx [N/m]" not in rows[0]:
            raise FolderError("%s: no header with a k_xx [N/m] column" % self.path)
        header = rows[0]
        try:
            values = np.array([[float(c) for c in r] for r in rows[1:]], ndmin=2)
        except ValueError as e:
            raise FolderError("%s: not a table of numbers (%s)" % (self.path, e)) from e
        self.columns = {}  # name (without unit) -> (unit, values)
        for k, text in enumerate(header):
            m = _COLUMN.match(text)
            name, unit = (m.group("name"), m.group("unit")) if m else (text, "")
            self.columns[name] = (unit, values[:, k] if values.size else np.array([]))
        self.keys = [_COLUMN.match(h).group("name") if _COLUMN.match(h) else h
                     for h in header[:header.index("k_xx [N/m]")]]
        self.source = ""
        # The diagonal terms' range over one ball pass: {name: (min, max)}, one value per row
        # (stiffness.json's points[].ball_pass, in stiffness.csv's row order); {} without it.
        self.ball_pass = {}
        # Their mean over it, the rotor's K: {name: values} (points[].rotor.stiffness); {}
        # without it.
        self.rotor = {}
        self.ball_pass_samples = 0
        meta = os.path.join(folder, "stiffness.json")
        if os.path.exists(meta):
            try:
                with open(meta) as f:
                    doc = json.load(f)
                case = doc.get("case", {})
                self.source = "%s (%s)" % (case.get("source", ""), case.get("bearing", ""))
                self._read_ball_pass(doc.get("points", []), len(rows) - 1)
            except (OSError, ValueError, KeyError, TypeError, IndexError):
                self.ball_pass = {}
                self.rotor = {}

    def _read_ball_pass(self, points, rows):
        passes = [p.get("ball_pass") for p in points]
        if not passes or len(passes) != rows or any(b is None for b in passes):
            return
        for i in range(5):
            lo = np.array([float(b["min"][i][i]) for b in passes])
            hi = np.array([float(b["max"][i][i]) for b in passes])
            self.ball_pass[term_name(i, i)] = (lo, hi)
        self.ball_pass_samples = int(passes[0]["samples"])
        rotors = [p.get("rotor") for p in points]
        if all(r is not None for r in rotors):
            for i in range(5):
                self.rotor[term_name(i, i)] = np.array([float(r["stiffness"][i][i])
                                                        for r in rotors])
                if all("damping" in r for r in rotors):  # with [lubricant]: the rotor's C
                    self.rotor[term_name(i, i, "c")] = np.array(
                        [float(r["damping"][i][i]) for r in rotors])

    def __getitem__(self, name):
        return self.columns[name][1]

    @property
    def has_damping(self):
        """Whether stiffness.csv has the damping's columns (the case had [lubricant])."""
        return "c_xx" in self.columns

    @property
    def points(self):
        return len(self["k_xx"])

    @property
    def varied(self):
        """The keys that take more than one value."""
        return [k for k in self.keys if len(np.unique(self[k])) > 1]

    @property
    def name(self):
        return os.path.basename(os.path.normpath(self.folder))


def load_stiffness(folder):
    return Stiffness(folder)


def panel_terms(s, unit, prefix="k"):
    """(diagonal, off-diagonal) term names of one unit's panel: every diagonal term, and the
    largest off-diagonal terms that are not round-off (|K_ij| above 1e-6 sqrt(|K_ii| |K_jj|));
    `unit` the stiffness block's, `prefix` "k" (K) or "c" (C, the same blocks)."""
    peak = {name: float(np.max(np.abs(s[name]))) if s.points else 0.0
            for name in (term_name(i, j, prefix) for i in range(5) for j in range(i, 5))}
    diagonal = [term_name(i, i, prefix) for i in range(5) if term_unit(i, i) == unit]
    off = []
    for i in range(5):
        for j in range(i + 1, 5):
            if term_unit(i, j) != unit:
                continue
            scale = np.sqrt(peak[term_name(i, i, prefix)] * peak[term_name(j, j, prefix)])
            if peak[term_name(i, j, prefix)] > 1e-6 * scale:
                off.append(term_name(i, j, prefix))
    off.sort(key=lambda n: -peak[n])
    return diagonal, off[:OFF_DIAGONAL_SHOWN]


def _draw_ball_pass(ax, s, name, x, color, joined):
    """A diagonal term's range over one ball pass: a band along a joined curve, a vertical bar at
    each unjoined point or on one point's bar (gid "ball_pass:<name>")."""
    if name not in s.ball_pass:
        return
    lo, hi = s.ball_pass[name]
    if x is None:
        band = ax.vlines([name], lo, hi, color="k", lw=3, alpha=0.6)
    elif joined:
        order = np.argsort(x, kind="stable")
        band = ax.fill_between(x[order], lo[order], hi[order], color=color, alpha=0.25, lw=0)
    else:
        band = ax.vlines(x, lo, hi, color=color, alpha=0.5)
    band.set_gid("ball_pass:" + name)


def _draw_rotor(ax, s, name, x, color, joined):
    """A diagonal term's mean over one ball pass, the rotor's K: a dotted curve along a joined
    one, dots at unjoined points, a diamond on one point's bar (gid "rotor:<name>")."""
    if name not in s.rotor:
        return
    mean = s.rotor[name]
    if x is None:
        mark, = ax.plot([name], mean, "D", color="k", ms=6)
    else:
        order = np.argsort(x, kind="stable")
        mark, = ax.plot(x[order], mean[order], ":" if joined else ".", color=color, lw=1.5)
    mark.set_gid("rotor:" + name)


def _draw_panel(ax, s, unit, x, xlabel, joined=True, prefix="k"):
    diagonal, off = panel_terms(s, unit, prefix)
    gid = "stiffness:" if prefix == "k" else "damping:"
    for name in diagonal + off:
        style = ("-o" if name in diagonal else "--s") if joined else \
            ("o" if name in diagonal else "s")
        if x is None:  # one point: its terms as bars
            bars = ax.bar([name], s[name], color="C0" if name in diagonal else "C1")
            bars.patches[0].set_gid(gid + name)
            if name in diagonal:
                _draw_ball_pass(ax, s, name, None, None, joined)
                _draw_rotor(ax, s, name, None, None, joined)
            continue
        order = np.argsort(x, kind="stable")
        line, = ax.plot(x[order], s[name][order], style, ms=4, label=name)
        line.set_gid(gid + name)
        if name in diagonal:
            _draw_ball_pass(ax, s, name, x, line.get_color(), joined)
            _draw_rotor(ax, s, name, x, line.get_color(), joined)
    ax.set_ylabel("K [%s]" % SHOWN_UNIT[unit] if prefix == "k" else
                  "C [%s]" % DAMPING_SHOWN_UNIT[unit])
    ax.ticklabel_format(axis="y", style="sci", scilimits=(-3, 4))
    if x is not None:
        ax.set_xlabel(xlabel)
        if diagonal or off:
            ax.legend()
    if not diagonal and not off:
        ax.text(0.5, 0.5, "no coupling above round-off", transform=ax.transAxes, ha="center")


def stiffness_figure(s):
    """The stiffness terms against the first varied key (one point: as bars), one panel per unit;
    with more varied keys, all points against the first. With the damping's columns
    (Stiffness.has_damping) a second row: C's terms, the same way."""
    if s.points == 0:
        raise FolderError("%s: no operating point" % s.path)
    varied = s.varied
    key = varied[0] if varied else None
    xlabel, factor = key_display(key) if key else ("", 1.0)
    x = s[key] * factor if key else None
    with _style():
        fig = _new_figure("stiffness")
        rows = 2 if s.has_damping else 1
        grid = fig.subplots(rows, len(PANELS), squeeze=False)
        if rows == 2:
            width, height = fig.get_size_inches()
            fig.set_size_inches(width, 1.8 * height)
        for ax, (unit, what) in zip(grid[0], PANELS):
            _draw_panel(ax, s, unit, x, xlabel, joined=len(varied) <= 1)
            ax.set_title(what, fontsize=10)
        if rows == 2:
            for ax, (unit, _) in zip(grid[1], PANELS):
                _draw_panel(ax, s, unit, x, xlabel, joined=len(varied) <= 1, prefix="c")
                ax.set_title(DAMPING_TITLE[unit], fontsize=10)
        against = "against %s" % key if key else "at the operating point"
        extra = "; also varied: %s (every point, unjoined)" % ", ".join(varied[1:]) \
            if len(varied) > 1 else ""
        legend = ("blue: diagonal, orange: largest couplings" if key is None else
                  "solid: diagonal, dashed: largest couplings" if len(varied) == 1 else
                  "circles: diagonal, squares: largest couplings")
        if s.ball_pass:
            legend += ("; %s: the diagonal's range over one ball pass (%d cage angles)"
                       % ("black bars" if key is None else "bands" if len(varied) <= 1
                          else "vertical bars", s.ball_pass_samples))
        if s.rotor:
            legend += ("; %s: its mean, the rotor's K%s"
                       % ("diamonds" if key is None else "dotted" if len(varied) <= 1
                          else "dots", " and C" if s.has_damping else ""))
        films = ("the EHL films in series, their squeeze damping C = dF/d(dq/dt) below"
                 if s.has_damping else "no damping")
        fig.suptitle("%s — bearing stiffness K = dF/dq %s, at the case's cage angle\n(%s)\n"
                     "%s · 5-DOF static solution: rigid rings, centrifugal ball load at speed, "
                     "%s%s"
                     % (s.name, against, legend, s.source, films, extra))
        fig.tight_layout()
    return fig
