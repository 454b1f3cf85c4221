"""Figures of bearing-sim runs and sweeps and of bearing-fem contact outputs.

    bearing-plot FOLDER [--out DIR] [--format png|svg|pdf]
    /usr/bin/python3 -m bearing.plot FOLDER [...]        (with PYTHONPATH=build/python)

FOLDER is recognised by its files:

- a run (``bearing-sim run --out FOLDER``: ``summary.json`` and ``response.csv`` or
  ``response.npy``) gives ``time``: x, y, ax, ay over the whole record (transient shaded) and over
  the last four ball passes (dotted: a ball on the load line); ``orbit``: the inner-ring centre in
  the x-y plane with the clearance circle (radius P_d/2); ``spectrum``: the amplitude spectra of
  x, y, ax, ay with summary.json's labelled peaks; ``envelope`` (with ``output.envelope_band``):
  the envelope spectra, peaks, band, spectral kurtosis and diagnosis; ``ball_loads`` (with
  ``output.ball_loads``): Q_j against the ball's angle around the bearing (polar) and in time;
  ``spl`` (with ``[acoustics]``): the SPL per microphone (total, ring, balls) and p(t);
- a sweep (``bearing-sim sweep --out FOLDER``: ``sweep.csv``) gives ``sweep_<statistic>`` (rms,
  ptp, kurtosis, crest, peak_frequency; one panel per ring channel) and ``sweep_spl``: against the
  varied key as lines (one key), as heat maps (two keys), as points against each key (three and
  more);
- a contact output (``bearing-fem contact --out FOLDER``: ``force_approach.csv`` and
  ``contact.json``) gives ``force_approach``: the FE force against the approach on log axes with
  the Hertz law, and the FE/Hertz deviation of force, semi-axes and peak pressure per step.

The figures go to ``FOLDER/plots/`` unless ``--out`` says otherwise; a figure of the same name and
format an earlier call left there and this folder no longer gives (e.g. ``spl`` after a rerun
without acoustics) is removed. Exit status: 0 written, 2 the folder is none of the above.

Library use (the verification report draws with the same functions): ``load_run(folder)``,
``run_figures(run)`` (name -> matplotlib Figure), ``sweep_figures(load_sweep(folder))``,
``contact_figure(load_contact(folder))``, ``plot_folder(folder, out, fmt)``; and the panel
functions ``trace_axes``, ``orbit_axes``, ``spectrum_axes``, ``ball_load_axes``, ``spl_axes``,
``force_approach_axes``, ``sweep_line_axes``, ``sweep_heatmap_axes`` that draw plain NumPy arrays
on a given Axes. Only NumPy and matplotlib are used (no compiled extension). Every data artist
carries a gid (``"spectrum:ay"``, ``"orbit"``, ...) so a test can read the plotted values back.

Units: the data are the files' SI values times the display factor of ``DISPLAY`` (m -> um,
m/s -> mm/s, rad/s -> rpm, ...), written on every axis.
"""

import argparse
import csv
import json
import math
import os
import sys

import numpy as np

try:
    import matplotlib
    import matplotlib.ticker
    from matplotlib.figure import Figure
    from matplotlib.patches import Circle
except ImportError as _error:  # pragma: no cover - depends on the machine
    raise ImportError("bearing.plot needs matplotlib for %s (Debian: python3-matplotlib): %s"
                      % (sys.executable, _error)) from _error

DPI = 100
# Figure sizes in inches; the files are these times DPI pixels.
SIZES = {
    "time": (13.0, 9.0),
    "orbit": (13.0, 6.6),
    "spectrum": (13.0, 8.5),
    "envelope": (13.0, 7.0),
    "ball_loads": (13.0, 6.2),
    "spl": (13.0, 5.6),
    "sweep": (13.0, 8.5),
    "force_approach": (13.0, 5.8),
}
FORMATS = ("png", "svg", "pdf")
STYLE = {
    "font.size": 10.5,
    "axes.titlesize": 11,
    "axes.labelsize": 10.5,
    "xtick.labelsize": 9.5,
    "ytick.labelsize": 9.5,
    "legend.fontsize": 9.5,
    "figure.titlesize": 12,
    "axes.grid": True,
    "grid.linewidth": 0.5,
    "grid.alpha": 0.4,
    "lines.linewidth": 1.0,
    "axes.spines.top": False,
    "axes.spines.right": False,
    "savefig.dpi": DPI,
    "figure.dpi": DPI,
}
# SI unit -> (display unit, factor): the plotted value is the file's value times the factor.
DISPLAY = {
    "m": ("µm", 1e6),
    "m/s": ("mm/s", 1e3),
    "m/s^2": ("m/s²", 1.0),
    "N": ("N", 1.0),
    "Pa": ("Pa", 1.0),
    "Hz": ("Hz", 1.0),
    "s": ("s", 1.0),
    "rad/s": ("rpm", 60.0 / (2.0 * math.pi)),
    "rad": ("deg", 180.0 / math.pi),
    "dB": ("dB re 20 µPa", 1.0),
    "1": ("–", 1.0),
}
RING_UNITS = {0: "m", 1: "m/s", 2: "m/s^2"}
QUANTITY = {0: "displacement", 1: "velocity", 2: "acceleration"}
STATISTICS = ("rms", "ptp", "kurtosis", "crest", "peak_frequency")
STATISTIC_NAMES = {"rms": "RMS (about the mean)", "ptp": "peak to peak", "kurtosis": "kurtosis",
                   "crest": "crest factor", "peak_frequency": "largest spectral peak"}
BALL_PASSES_ZOOMED = 4


class FolderError(Exception):
    """The folder is not one bearing-plot knows, or a file in it cannot be read."""


# --- reading ----------------------------------------------------------------------------------

class Table:
    """A table of named columns (a CSV with a header row, or an .npy with columns.json)."""

    def __init__(self, names, data, path):
        self.names = list(names)
        self.data = data
        self.path = path
        self._index = {n: i for i, n in enumerate(self.names)}

    def __contains__(self, name):
        return name in self._index

    def __getitem__(self, name):
        return self.data[:, self._index[name]]


def read_table(folder, stem):
    """FOLDER/stem.csv or FOLDER/stem.npy (+ columns.json) as a Table; None if neither exists."""
    path = os.path.join(folder, stem + ".csv")
    if os.path.exists(path):
        with open(path) as f:
            names = f.readline().strip().split(",")
        try:
            data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
        except ValueError as e:
            raise FolderError("%s: not a table of numbers (%s)" % (path, e)) from e
        return Table(names, data.reshape(-1, len(names)), path)
    path = os.path.join(folder, stem + ".npy")
    if os.path.exists(path):
        meta_path = os.path.join(folder, "columns.json")
        try:
            with open(meta_path) as f:
                names = json.load(f)["tables"][stem + ".npy"]["columns"]
        except (OSError, KeyError, ValueError) as e:
            raise FolderError("%s: no column names for %s.npy (%s)" % (meta_path, stem, e)) from e
        return Table(names, np.load(path), path)
    return None


def _read_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        raise FolderError("%s: %s" % (path, e)) from e


def _read_case_toml(path):
    """The resolved case.toml as a dict ({} if absent); tomllib (Python >= 3.11) or a fallback
    that reads `key = number` lines per table, which is all the figures need."""
    if not os.path.exists(path):
        return {}
    try:
        import tomllib
        with open(path, "rb") as f:
            return tomllib.load(f)
    except ImportError:
        pass
    case = {}
    current = case
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line.startswith("[["):
                current = None  # arrays of tables: not needed by the figures
            elif line.startswith("["):
                current = case
                for part in line.strip("[]").split("."):
                    current = current.setdefault(part.strip(), {})
            elif "=" in line and current is not None:
                key, value = (s.strip() for s in line.split("=", 1))
                try:
                    current[key] = float(value)
                except ValueError:
                    current[key] = value.strip('"')
    return case


class Run:
    """The files of one `bearing-sim run --out FOLDER` (tables are None when not written)."""

    def __init__(self, folder):
        self.folder = folder
        self.summary = _read_json(os.path.join(folder, "summary.json"))
        self.case = _read_case_toml(os.path.join(folder, "case.toml"))
        self.response = read_table(folder, "response")
        if self.response is None:
            raise FolderError("%s: no response.csv or response.npy" % folder)
        self.spectrum = read_table(folder, "spectrum")
        self.envelope = read_table(folder, "envelope")
        self.pressure = read_table(folder, "pressure")

    @property
    def name(self):
        return case_name(self.summary.get("case", {}).get("source", ""), self.folder)

    @property
    def clearance(self):
        """P_d [m], the diametral clearance (case.toml), or None."""
        value = self.case.get("bearing", {}).get("clearance")
        return float(value) if isinstance(value, (int, float)) else None

    @property
    def frequencies(self):
        return self.summary.get("frequencies", {})

    @property
    def transient(self):
        return float(self.summary.get("case", {}).get("transient", 0.0))

    @property
    def balls(self):
        z = self.case.get("bearing", {}).get("balls")
        if isinstance(z, (int, float)):
            return int(z)
        return sum(1 for n in self.response.names if n[:1] == "Q" and n[1:].isdigit())

    def title(self, what, extra=None):
        """'name — what', the case's parameters, and `extra` on a third line."""
        lines = ["%s — %s" % (self.name, what), case_parameters(self.summary, self.case)]
        return "\n".join(lines + ([extra] if extra else []))

    def frequency_line(self):
        fr = self.frequencies
        return "shaft %.4g Hz · FTF %.4g Hz · BPFO %.4g Hz · BPFI %.4g Hz · BSF %.4g Hz" % (
            fr.get("shaft", 0), fr.get("ftf", 0), fr.get("bpfo", 0), fr.get("bpfi", 0),
            fr.get("bsf", 0))


def case_name(source, folder):
    """A short name: the case file's stem, 'default case', or the run folder's name."""
    base = os.path.basename(os.path.normpath(folder))
    if source.endswith(".toml"):
        stem = os.path.splitext(os.path.basename(source))[0]
        if stem == "case":  # a rerun of a resolved case: the folder it came from says more
            stem = os.path.basename(os.path.dirname(os.path.abspath(source))) or stem
        return "%s (%s)" % (stem, base) if stem != base else stem
    if source.startswith("built-in"):
        return "default case (%s)" % base
    return base


def case_parameters(summary, case):
    """One line of the parameters an engineer looks for first."""
    c = summary.get("case", {})
    parts = []
    if c.get("bearing"):
        parts.append(str(c["bearing"]))
    if c.get("model"):
        parts.append("model %s" % c["model"])
    if "speed" in c:
        parts.append("%.0f rpm" % (c["speed"] * DISPLAY["rad/s"][1]))
    load = c.get("load")
    if load:
        parts.append("load (%s) N" % ", ".join("%.4g" % v for v in load))
    if c.get("axial_load"):
        parts.append("axial %.4g N" % c["axial_load"])
    clearance = case.get("bearing", {}).get("clearance")
    if isinstance(clearance, (int, float)):
        parts.append("P_d %.3g µm" % (clearance * 1e6))
    method = case.get("solver", {}).get("method")
    if c.get("model") == "quasistatic":
        method = "quasistatic"
    if "duration" in c:
        parts.append("%s%.3g s (transient %.3g s)" % (method + " " if method else "",
                                                      c["duration"], c.get("transient", 0.0)))
    if c.get("contact"):
        parts.append("contact %s" % c["contact"])
    return " · ".join(parts)


class Sweep:
    """sweep.csv: the varied keys, and per case its status and numbers (strings kept as text)."""

    def __init__(self, folder):
        self.folder = folder
        self.path = os.path.join(folder, "sweep.csv")
        with open(self.path, newline="") as f:
            rows = list(csv.reader(f))
        if not rows or "status" not in rows[0]:
            raise FolderError("%s: no header with a status column" % self.path)
        self.header = rows[0]
        self.keys = self.header[:self.header.index("status")]
        self.rows = [dict(zip(self.header, r)) for r in rows[1:] if r]
        self.ok = np.array([r.get("status") == "ok" for r in self.rows], dtype=bool)

    def column(self, name):
        """The column as floats (NaN where empty, not a number, or the case failed)."""
        out = np.full(len(self.rows), np.nan)
        for i, r in enumerate(self.rows):
            try:
                out[i] = float(r.get(name, ""))
            except ValueError:
                pass
        out[~self.ok] = np.nan
        return out

    def text(self, name):
        return [r.get(name, "") for r in self.rows]

    @property
    def varied(self):
        """The keys that take more than one value."""
        return [k for k in self.keys if len(np.unique(self.column_all(k))) > 1] or self.keys[:1]

    def column_all(self, name):
        """A key's column for every case, failed or not."""
        return np.array([float(r[name]) for r in self.rows])

    @property
    def channels(self):
        return [n[:-4] for n in self.header if n.endswith(".rms")]

    @property
    def microphones(self):
        return [n[:-10] for n in self.header if n.endswith(".spl_total")]

    @property
    def name(self):
        return os.path.basename(os.path.normpath(self.folder))


class Contact:
    """The files of one `bearing-fem contact --out FOLDER`."""

    def __init__(self, folder):
        self.folder = folder
        self.json = _read_json(os.path.join(folder, "contact.json"))
        self.curve = read_table(folder, "force_approach")
        if self.curve is None or "approach" not in self.curve or "force" not in self.curve:
            raise FolderError("%s: force_approach.csv has no approach and force columns" % folder)

    @property
    def name(self):
        source = self.json.get("case", "")
        stem = os.path.splitext(os.path.basename(source))[0] if source else ""
        base = os.path.basename(os.path.normpath(self.folder))
        return "%s (%s)" % (stem, base) if stem and stem != base else base


def detect(folder):
    """'run', 'sweep' or 'contact'; FolderError naming the folder and what was expected."""
    if not os.path.isdir(folder):
        raise FolderError("%s: no such folder" % folder)
    has = lambda name: os.path.isfile(os.path.join(folder, name))  # noqa: E731
    if has("summary.json") and (has("response.csv") or has("response.npy")):
        return "run"
    if has("sweep.csv"):
        return "sweep"
    if has("force_approach.csv") and has("contact.json"):
        return "contact"
    inside = []
    for sub in sorted(os.listdir(folder)):
        path = os.path.join(folder, sub)
        if os.path.isdir(path) and any(os.path.isfile(os.path.join(path, f)) for f in (
                "summary.json", "sweep.csv", "force_approach.csv")):
            inside.append(sub)
    raise FolderError(
        "%s is not a folder bearing-plot knows: expected a bearing-sim run (summary.json with "
        "response.csv or response.npy), a bearing-sim sweep (sweep.csv) or a bearing-fem contact "
        "output (force_approach.csv with contact.json)%s" % (
            folder, "; its subfolders %s are: plot each of them" % ", ".join(inside[:6])
            + (", ..." if len(inside) > 6 else "") if inside else ""))


def load_run(folder):
    return Run(folder)


def load_sweep(folder):
    return Sweep(folder)


def load_contact(folder):
    return Contact(folder)


# --- helpers ----------------------------------------------------------------------------------

def ring_channel(name):
    """(dof letter, derivative) of a ring channel name ('ay' -> ('y', 2)), or None."""
    for prefix, derivative in (("a", 2), ("v", 1), ("", 0)):
        rest = name[len(prefix):]
        if name.startswith(prefix) and rest in ("x", "y", "z"):
            return rest, derivative
    return None


def channel_unit(name, summary=None):
    """The SI unit of a channel (summary.json's, else from its name)."""
    if summary:
        unit = summary.get("channels", {}).get(name, {}).get("unit")
        if unit:
            return unit
    ring = ring_channel(name)
    if ring:
        return RING_UNITS[ring[1]]
    return {"Q": "N", "d": "m", "r": "m"}.get(name[:1], "1")


def channel_label(name, summary=None):
    """'acceleration a_y [m/s²]' and its display factor."""
    unit, factor = DISPLAY.get(channel_unit(name, summary), (channel_unit(name, summary), 1.0))
    ring = ring_channel(name)
    if ring:
        dof, derivative = ring
        symbol = {0: "%s", 1: "v_%s", 2: "a_%s"}[derivative] % dof
        return "%s $%s$ [%s]" % (QUANTITY[derivative], symbol, unit), factor
    return "%s [%s]" % (name, unit), factor


def _nice_ceiling(value):
    """The smallest of 1, 2, 2.5, 5 x 10^k at or above value."""
    if value <= 0 or not np.isfinite(value):
        return 1.0
    exponent = math.floor(math.log10(value))
    for m in (1.0, 2.0, 2.5, 5.0, 10.0):
        if m * 10 ** exponent >= value * (1 - 1e-12):
            return m * 10 ** exponent
    return 10.0 ** (exponent + 1)


def _frequency_limit(f, amplitude, peaks, floor=1e-2):
    """Upper frequency of a spectrum panel: where the amplitude last exceeds floor x its largest
    value, or beyond the highest listed peak, rounded up; at most the last frequency."""
    a = np.asarray(amplitude)
    top = a.max() if a.size else 0.0
    upper = 0.0
    if top > 0:
        above = np.nonzero(a > floor * top)[0]
        upper = f[above[-1]] if above.size else 0.0
    if peaks:
        upper = max(upper, 1.15 * max(p["frequency"] for p in peaks))
    return min(_nice_ceiling(max(upper, f[min(len(f) - 1, 10)])), f[-1])


def load_line_passes(summary, t0, t1):
    """Times in [t0, t1] at which a ball is on the line of the applied radial load (none without
    a load or a turning cage): t = s (phi_L/2pi + m/Z) / f_c."""
    c = summary.get("case", {})
    load = c.get("load") or [0.0, 0.0]
    ftf = summary.get("frequencies", {}).get("ftf", 0.0)
    bpfo = summary.get("frequencies", {}).get("bpfo", 0.0)
    if math.hypot(*load[:2]) == 0 or ftf <= 0 or bpfo <= 0:
        return np.array([])
    balls = round(bpfo / ftf)
    sign = 1.0 if c.get("speed", 1.0) >= 0 else -1.0
    phase = math.atan2(load[1], load[0]) / (2 * math.pi)
    m0 = math.floor(min(sign * t0, sign * t1) * ftf * balls - phase * balls) - 1
    m1 = math.ceil(max(sign * t0, sign * t1) * ftf * balls - phase * balls) + 1
    times = sign * (phase + np.arange(m0, m1 + 1) / balls) / ftf
    return np.sort(times[(times >= t0) & (times <= t1)])


def _new_figure(kind):
    return Figure(figsize=SIZES[kind], dpi=DPI)


def _style():
    return matplotlib.rc_context(STYLE)


# --- panels (plain arrays on a given Axes; reused by the verification report) ----------------

def label_peaks(ax, peaks, fmax, spacing=0.028, y=0.985):
    """Names the peaks (dicts with frequency, amplitude, label) in a row of vertical labels along
    the top of the axes, spread to at least `spacing` (axes fraction) apart, each joined to its
    peak by a thin line: legible however close the peaks lie."""
    peaks = sorted(peaks, key=lambda p: p["frequency"])
    if not peaks:
        return
    want = [min(max(p["frequency"] / fmax, 0.0), 1.0) for p in peaks]
    spacing = min(spacing, 0.96 / len(peaks))
    xs = list(want)
    for i in range(1, len(xs)):  # push right
        xs[i] = max(xs[i], xs[i - 1] + spacing)
    xs[-1] = min(xs[-1], 0.99)
    for i in range(len(xs) - 2, -1, -1):  # and back left from the right edge
        xs[i] = min(xs[i], xs[i + 1] - spacing)
    for i, p in enumerate(peaks):
        ax.annotate(p["label"], xy=(p["frequency"], p["amplitude"]), xycoords="data",
                    xytext=(xs[i], y), textcoords="axes fraction", rotation=90, ha="center",
                    va="top", fontsize=8.5, color="C3",
                    arrowprops=dict(arrowstyle="-", color="C3", lw=0.5, alpha=0.6,
                                    shrinkA=1, shrinkB=4))


def plain_log_ticks(axis):
    """Log-axis ticks at 1, 2, 3, 5 x 10^k written as plain numbers (0.2, 0.3, 0.5, 1, 2, ...)."""
    axis.set_major_locator(matplotlib.ticker.LogLocator(base=10, subs=(1.0, 2.0, 3.0, 5.0)))
    axis.set_minor_locator(matplotlib.ticker.LogLocator(base=10, subs=np.arange(1, 10)))
    axis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: "%g" % v))
    axis.set_minor_formatter(matplotlib.ticker.NullFormatter())


def trace_axes(ax, t, values, *, label, transient=None, marks=None, gid=None, color="C0"):
    """A time trace; the transient (t < transient) shaded, dotted vertical lines at `marks`."""
    line, = ax.plot(t, values, color=color, lw=0.8)
    if gid:
        line.set_gid(gid)
    if transient and t.size and transient > t[0]:
        ax.axvspan(t[0], min(transient, t[-1]), color="0.85", lw=0, zorder=0)
    if marks is not None:
        for m in marks:
            ax.axvline(m, color="0.45", lw=0.7, ls=":", zorder=0)
    ax.set_xlim(t[0], t[-1])
    ax.set_ylabel(label)
    return line


def orbit_axes(ax, x, y, clearance=None, *, steady=None, unit="µm", gid="orbit", axes_lines=True):
    """The ring-centre orbit (x, y already in display units); the transient in grey, the steady
    part (mask `steady`) in colour, its mean as a cross; the clearance circle of radius
    clearance/2 (display units) about the centred position."""
    if steady is None:
        steady = np.ones_like(x, dtype=bool)
    if (~steady).any():
        ax.plot(x[~steady], y[~steady], color="0.7", lw=0.6, label="transient")
    line, = ax.plot(x[steady], y[steady], color="C0", lw=0.7, label="steady state")
    line.set_gid(gid)
    ax.plot([x[steady].mean()], [y[steady].mean()], "+", color="k", ms=12, mew=1.5,
            label="mean position (%.3g, %.3g) %s" % (x[steady].mean(), y[steady].mean(), unit))
    if clearance:
        circle = Circle((0.0, 0.0), clearance / 2, fill=False, ls="--", lw=1.2, color="C3",
                        label="clearance circle, radius P_d/2 = %.3g %s" % (clearance / 2, unit))
        circle.set_gid("clearance")
        ax.add_patch(circle)
    if axes_lines:
        ax.axhline(0, color="0.6", lw=0.5)
        ax.axvline(0, color="0.6", lw=0.5)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("inner-ring centre x [%s]" % unit)
    ax.set_ylabel("inner-ring centre y [%s] (up)" % unit)
    ax.legend(loc="best", framealpha=0.9)
    return line


def spectrum_axes(ax, f, amplitude, peaks=(), *, label, fmax=None, gid=None, log=True,
                  decades=5.0, color="C0"):
    """An amplitude spectrum (already in display units) with its listed peaks (dicts with
    frequency, amplitude in display units, label) marked and named."""
    line, = ax.plot(f, amplitude, color=color, lw=0.8)
    if gid:
        line.set_gid(gid)
    fmax = fmax or f[-1]
    inside = [p for p in peaks if p["frequency"] <= fmax]
    top = max([np.max(amplitude[(f <= fmax)])] + [p["amplitude"] for p in inside])
    if log:
        ax.set_yscale("log")
        ax.set_ylim(top * 10 ** -decades, top * 10 ** (decades * 0.42))
    else:
        ax.set_ylim(0, top * 1.75)
    if inside:
        px = [p["frequency"] for p in inside]
        py = [p["amplitude"] for p in inside]
        marker, = ax.plot(px, py, "v", color="C3", ms=5, ls="none")
        if gid:
            marker.set_gid(gid + ":peaks")
        label_peaks(ax, [p for p in inside if p.get("label")], fmax)
    ax.set_xlim(0, fmax)
    ax.set_xlabel("frequency [Hz]")
    ax.set_ylabel(label)
    return line


def ball_load_axes(ax, theta, loads, *, load_angle=None):
    """Polar: each ball's load Q_j [N] against its angle theta_j [rad] from +x (y up); `loads`
    and `theta` are lists, one array per ball. The applied load's direction as a dashed ray."""
    top = max([np.max(q) for q in loads if q.size] + [1e-30])
    for j, (th, q) in enumerate(zip(theta, loads)):
        line, = ax.plot(th, q, color="C0", lw=0.6, alpha=0.6)
        line.set_gid("ball_loads:Q%d" % (j + 1))
    if load_angle is not None:
        ax.plot([load_angle, load_angle], [0, top * 1.1], ls="--", color="k", lw=1.0,
                label="applied load")
    ax.set_ylim(0, top * 1.1)
    ax.set_rlabel_position(22.5)
    ax.yaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g N"))
    ax.set_title("every ball's load Q$_j$ against its position θ (from +x, y up)", pad=14)
    return ax


def spl_axes(ax, microphones):
    """Grouped bars: SPL of the total, ring and balls per microphone (summary.json acoustics
    microphones[]); None (a source left out) as no bar."""
    parts = (("spl_total", "total", "C0"), ("spl_ring", "ring", "C1"), ("spl_balls", "balls", "C2"))
    index = np.arange(len(microphones))
    width = 0.8 / len(parts)
    values = []
    for k, (key, label, color) in enumerate(parts):
        heights = np.array([m.get(key) if m.get(key) is not None else np.nan for m in microphones],
                           dtype=float)
        bars = ax.bar(index + (k - 1) * width, np.nan_to_num(heights, nan=0.0), width,
                      label=label, color=color)
        for i, (b, h) in enumerate(zip(bars, heights)):
            b.set_gid("spl:%s:%d" % (key, i + 1))
            if np.isfinite(h):
                ax.annotate("%.1f" % h, (b.get_x() + b.get_width() / 2, h),
                            xytext=(0, 2 if h >= 0 else -2), textcoords="offset points",
                            ha="center", va="bottom" if h >= 0 else "top", fontsize=8.5)
            else:
                b.set_visible(False)
        values.append(heights)
    ax.set_xticks(index)
    ax.set_xticklabels(["mic %d\nr = %.3g m, %.0f°"
                        % (i + 1, m["radius"], math.degrees(m["angle"]))
                        for i, m in enumerate(microphones)])
    finite = np.concatenate(values)
    finite = finite[np.isfinite(finite)]
    if finite.size:
        ax.set_ylim(min(0.0, finite.min() - 5), finite.max() + 14)
    ax.set_ylabel("sound pressure level [dB re 20 µPa]")
    ax.legend(loc="upper right", ncol=3, framealpha=0.9)
    ax.grid(axis="x", visible=False)


def force_approach_axes(ax, approach, force, *, hertz_K, hertz_n=1.5, fit=None, unit="µm",
                        factor=1e6):
    """FE force [N] against approach [m] (plotted in `unit`, x factor) on log axes, with the Hertz
    law Q = K delta^n and an optional FE fit (K, n)."""
    points, = ax.loglog(approach * factor, force, "o", color="C0", ms=6, label="FE (bearing-fem)")
    points.set_gid("contact:fe")
    lo, hi = approach.min() / 1.3, approach.max() * 1.3
    d = np.geomspace(lo, hi, 100)
    law, = ax.loglog(d * factor, hertz_K * d ** hertz_n, "-", color="C3", lw=1.3,
                     label="Hertz: Q = K δ$^{%.4g}$, K = %.5g N/m$^{%.4g}$"
                     % (hertz_n, hertz_K, hertz_n))
    law.set_gid("contact:hertz")
    if fit:
        K, n = fit
        ax.loglog(d * factor, K * d ** n, "--", color="0.3", lw=1.0,
                  label="FE fit: K = %.5g N/m$^{%.5g}$, n = %.5g" % (K, n, n))
    ax.set_xlabel("approach δ [%s]" % unit)
    ax.set_ylabel("contact force Q [N]")
    plain_log_ticks(ax.xaxis)
    plain_log_ticks(ax.yaxis)
    ax.grid(True, which="both")
    ax.legend(loc="upper left", framealpha=0.9)


def sweep_line_axes(ax, x, y, *, xlabel, ylabel, labels=None, gid=None):
    """One statistic against one key: points joined in key order; text labels at the points."""
    order = np.argsort(x, kind="stable")
    line, = ax.plot(x[order], y[order], "-o", ms=4)
    if gid:
        line.set_gid(gid)
    if labels is not None:
        for xi, yi, text in zip(x, y, labels):
            if text and np.isfinite(yi):
                ax.annotate(text, (xi, yi), xytext=(3, 4), textcoords="offset points", fontsize=8)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    return line


def sweep_heatmap_axes(ax, x, y, values, *, xlabel, ylabel, zlabel, labels=None, gid=None,
                       annotate=True):
    """One statistic over two keys: values[i_y, i_x] on the grid of the sorted distinct x and y
    (one equal cell per value, ticks naming the values), as a heat map (NaN: a failed case, blank)
    with a colour bar; the values written in the cells of a grid of at most 10 x 10."""
    ax.grid(False)
    mesh = ax.pcolormesh(np.arange(len(x) + 1) - 0.5, np.arange(len(y) + 1) - 0.5,
                         np.ma.masked_invalid(values), shading="flat", cmap="viridis")
    if gid:
        mesh.set_gid(gid)
    ax.figure.colorbar(mesh, ax=ax, label=zlabel)
    for axis, ticks in ((ax.xaxis, x), (ax.yaxis, y)):
        step = max(1, int(math.ceil(len(ticks) / 10)))
        axis.set_ticks(np.arange(0, len(ticks), step))
        axis.set_ticklabels(["%.4g" % v for v in ticks[::step]])
    if annotate and values.size <= 100:
        finite = values[np.isfinite(values)]
        middle = (finite.min() + finite.max()) / 2 if finite.size else 0.0
        for i in range(len(y)):
            for k in range(len(x)):
                v = values[i, k]
                text = "failed" if not np.isfinite(v) else "%.3g" % v
                if labels is not None and labels[i][k]:
                    text += "\n" + labels[i][k]
                color = "0.3" if not np.isfinite(v) else "k" if v > middle else "w"
                ax.text(k, i, text, ha="center", va="center", fontsize=9, color=color)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    return mesh


# --- run figures ------------------------------------------------------------------------------

def time_figure(run):
    """x, y, ax, ay: the whole record (transient shaded) and the last few ball passes."""
    r = run.response
    t = r["t"]
    bpfo = run.frequencies.get("bpfo", 0.0)
    span = BALL_PASSES_ZOOMED / bpfo if bpfo > 0 else 0.1 * (t[-1] - t[0])
    zoom = t >= t[-1] - span
    marks = load_line_passes(run.summary, t[zoom][0], t[-1])
    channels = [c for c in ("x", "y", "ax", "ay") if c in r]
    with _style():
        fig = _new_figure("time")
        axes = fig.subplots(len(channels), 2, sharex="col", squeeze=False,
                            gridspec_kw={"width_ratios": [1.35, 1]})
        for row, name in enumerate(channels):
            label, factor = channel_label(name, run.summary)
            color = "C0" if ring_channel(name)[1] == 0 else "C1"
            trace_axes(axes[row][0], t, r[name] * factor, label=label, transient=run.transient,
                       gid="time:%s" % name, color=color)
            trace_axes(axes[row][1], t[zoom], r[name][zoom] * factor, label=label, marks=marks,
                       gid="time_zoom:%s" % name, color=color)
        axes[0][0].set_title("whole record (grey: transient %.3g s, left out of statistics)"
                             % run.transient)
        axes[0][1].set_title("last %s%s" % (
            "%d ball passes (1/BPFO = %.3g ms)" % (BALL_PASSES_ZOOMED, 1e3 / bpfo) if bpfo > 0
            else "10 % of the record", "; dotted: a ball on the load line" if marks.size else ""))
        axes[-1][0].set_xlabel("time t [s]")
        axes[-1][1].set_xlabel("time t [s]")
        fig.suptitle(run.title("ring displacement and acceleration"))
        fig.align_ylabels(axes[:, 0])
        fig.tight_layout()
    return fig


def orbit_figure(run):
    """The inner-ring centre in the x-y plane: with the clearance circle, and the steady orbit
    enlarged."""
    r = run.response
    factor = DISPLAY["m"][1]
    steady = r["t"] >= run.transient
    if not steady.any():
        steady = np.ones_like(steady)
    x, y = r["x"] * factor, r["y"] * factor
    with _style():
        fig = _new_figure("orbit")
        whole, zoom = fig.subplots(1, 2)
        clearance = run.clearance * factor if run.clearance else None
        orbit_axes(whole, x, y, clearance, steady=steady, unit=DISPLAY["m"][0])
        whole.set_title("in the clearance (dashed: where a rigid ring would touch)")
        orbit_axes(zoom, x[steady], y[steady], None, unit=DISPLAY["m"][0], gid="orbit_steady",
                   axes_lines=False)
        ptp = [run.summary.get("channels", {}).get(c, {}).get("ptp") for c in ("x", "y")]
        extra = ""
        if all(v is not None for v in ptp):
            extra = ": p-p x %.3g µm, y %.3g µm" % (ptp[0] * 1e6, ptp[1] * 1e6)
        zoom.set_title("steady orbit enlarged%s" % extra)
        fig.suptitle(run.title("inner-ring orbit"))
        fig.tight_layout()
    return fig


def _peaks_display(peaks, factor):
    return [dict(p, amplitude=p["amplitude"] * factor) for p in peaks]


def spectrum_figure(run):
    """Amplitude spectra of x, y, ax, ay with the labelled peaks of summary.json."""
    s = run.spectrum
    f = s["frequency"]
    channels = [c for c in ("x", "y", "ax", "ay") if c in s]
    window = run.case.get("output", {}).get("window", "hann")
    with _style():
        fig = _new_figure("spectrum")
        axes = fig.subplots(2, 2, squeeze=False).ravel()
        for ax, name in zip(axes, channels):
            label, factor = channel_label(name, run.summary)
            peaks = _peaks_display(run.summary.get("peaks", {}).get(name, []), factor)
            amplitude = s[name] * factor
            spectrum_axes(ax, f, amplitude, peaks, label="amplitude of " + label,
                          fmax=_frequency_limit(f, amplitude, peaks), gid="spectrum:%s" % name,
                          color="C0" if ring_channel(name)[1] == 0 else "C1")
            ax.set_title("%s: %d largest peaks (▼), named by bearing frequency"
                         % (name, len(peaks)))
        for ax in axes[len(channels):]:
            ax.set_visible(False)
        fig.suptitle(run.title("amplitude spectra (window %s, from t = %.3g s)"
                               % (window, run.transient), run.frequency_line()))
        fig.tight_layout()
    return fig


def envelope_figure(run):
    """The envelope spectrum of each ring acceleration: band, SK, peaks and the diagnosis."""
    e = run.envelope
    f = e["frequency"]
    channels = [n[4:] for n in e.names if n.startswith("env_")]
    info = run.summary.get("envelope", {})
    fr = run.frequencies
    fault = max(fr.get("bpfo", 0), fr.get("bpfi", 0), 2 * fr.get("bsf", 0))
    with _style():
        fig = _new_figure("envelope")
        axes = fig.subplots(len(channels), 1, squeeze=False).ravel()
        for ax, name in zip(axes, channels):
            label, factor = channel_label(name, run.summary)
            ch = info.get(name, {})
            peaks = _peaks_display(ch.get("peaks", []), factor)
            amplitude = e["env_" + name] * factor
            upper = max([5 * fault] + [1.15 * p["frequency"] for p in peaks])
            spectrum_axes(ax, f, amplitude, peaks, label="envelope amplitude\n" + label,
                          fmax=min(_nice_ceiling(upper), f[-1]), gid="envelope:%s" % name,
                          log=False, color="C1")
            band = ch.get("band", [float("nan")] * 2)
            ax.set_title("%s: band %.4g–%.4g kHz (%s), spectral kurtosis %.3g" % (
                name, band[0] / 1e3, band[1] / 1e3, ch.get("band_source", "?"),
                ch.get("spectral_kurtosis", float("nan"))))
        diagnosis = run.summary.get("diagnosis", {})
        if diagnosis:
            axes[-1].text(0.995, 0.97, "diagnosis: %s\n%s" % (diagnosis.get("family", "?"),
                          _wrap(diagnosis.get("reason", ""), 70)),
                          transform=axes[-1].transAxes, ha="right", va="top", fontsize=9,
                          bbox=dict(boxstyle="round", fc="white", ec="0.6", alpha=0.9))
        fig.suptitle(run.title("envelope spectra of the accelerations", run.frequency_line()))
        fig.tight_layout()
    return fig


def _wrap(text, width):
    words, lines, line = text.split(), [], ""
    for w in words:
        if line and len(line) + 1 + len(w) > width:
            lines.append(line)
            line = w
        else:
            line = (line + " " + w).strip()
    return "\n".join(lines + [line])


def ball_angles(run, t):
    """theta_j(t) = 2 pi j / Z + s 2 pi f_c t [rad] per ball j (s the sign of the shaft speed)."""
    z = run.balls
    sign = 1.0 if run.summary.get("case", {}).get("speed", 1.0) >= 0 else -1.0
    wc = sign * 2 * math.pi * run.frequencies.get("ftf", 0.0)
    return [2 * math.pi * j / z + wc * t for j in range(z)]


def ball_load_figure(run):
    """Q_j around the bearing (polar, over the analysis window) and in time (last ball passes)."""
    r = run.response
    t = r["t"]
    steady = t >= run.transient
    z = run.balls
    theta = [a[steady] for a in ball_angles(run, t)]
    loads = [r["Q%d" % (j + 1)][steady] for j in range(z)]
    load = run.summary.get("case", {}).get("load") or [0.0, 0.0]
    load_angle = math.atan2(load[1], load[0]) if math.hypot(*load[:2]) > 0 else None
    bpfo = run.frequencies.get("bpfo", 0.0)
    span = BALL_PASSES_ZOOMED * 2 / bpfo if bpfo > 0 else 0.1 * (t[-1] - t[0])
    zoom = t >= t[-1] - span
    with _style():
        fig = _new_figure("ball_loads")
        polar = fig.add_subplot(1, 2, 1, projection="polar")
        ball_load_axes(polar, theta, loads, load_angle=load_angle)
        ax = fig.add_subplot(1, 2, 2)
        for j in range(z):
            line, = ax.plot(t[zoom], r["Q%d" % (j + 1)][zoom], color="C%d" % (j % 10), lw=0.9,
                            label="Q%d" % (j + 1))
            line.set_gid("ball_loads_time:Q%d" % (j + 1))
        ax.set_xlim(t[zoom][0], t[-1])
        ax.set_xlabel("time t [s]")
        ax.set_ylabel("ball load Q$_j$ [N]")
        ax.set_title("last %d ball passes" % (2 * BALL_PASSES_ZOOMED) if bpfo > 0 else
                     "last 10 % of the record")
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8.5,
                  ncol=1 if z <= 14 else 2)
        fig.suptitle(run.title("ball loads (from t = %.3g s)" % run.transient))
        fig.tight_layout()
    return fig


def spl_figure(run):
    """SPL per microphone (total, ring, balls) and the pressure over the last ball passes."""
    acoustics = run.summary.get("acoustics", {})
    mics = acoustics.get("microphones", [])
    p = run.pressure
    with _style():
        fig = _new_figure("spl")
        left, right = fig.subplots(1, 2, gridspec_kw={"width_ratios": [1, 1.2]})
        spl_axes(left, mics)
        left.set_title("SPL over the analysis window (band %.3g–%.4g Hz)"
                       % tuple(acoustics.get("band", [float("nan")] * 2)))
        if p is not None:
            t = p["t"]
            bpfo = run.frequencies.get("bpfo", 0.0)
            span = BALL_PASSES_ZOOMED / bpfo if bpfo > 0 else 0.1 * (t[-1] - t[0])
            zoom = t >= t[-1] - span
            for i, name in enumerate(n for n in p.names if n != "t"):
                line, = right.plot(t[zoom], p[name][zoom], lw=0.9,
                                   label="%s (mic %d)" % (name, i + 1))
                line.set_gid("pressure:%s" % name)
            right.set_xlim(t[zoom][0], t[-1])
            right.legend(loc="upper right", fontsize=8.5, framealpha=0.9)
        right.set_xlabel("time t [s]")
        right.set_ylabel("sound pressure p [Pa]")
        right.set_title("p(t), last %d ball passes (%s summation)"
                        % (BALL_PASSES_ZOOMED, acoustics.get("summation", "?")))
        fig.suptitle(run.title("sound at the microphones: ring %s, balls %s" % (
            acoustics.get("ring_source", "?"), acoustics.get("ball_source", "?"))))
        fig.tight_layout()
    return fig


def run_figures(run):
    """name -> Figure for every figure the run's files allow."""
    figures = {"time": time_figure(run)}
    if "x" in run.response and "y" in run.response:
        figures["orbit"] = orbit_figure(run)
    if run.spectrum is not None:
        figures["spectrum"] = spectrum_figure(run)
    if run.envelope is not None:
        figures["envelope"] = envelope_figure(run)
    if "Q1" in run.response and run.balls > 0:
        figures["ball_loads"] = ball_load_figure(run)
    if run.summary.get("acoustics", {}).get("microphones"):
        figures["spl"] = spl_figure(run)
    return figures


# --- sweep figures ----------------------------------------------------------------------------

def key_display(key):
    """(axis label, factor) of a varied key; sweep.csv holds SI values."""
    leaf = [p for p in key.split(".") if not p.isdigit()][-1]
    units = {"speed": "rad/s", "clearance": "m", "amplitude": "m", "band": "m", "values": "m",
             "ball_diameter": "m", "pitch_diameter": "m", "ring_radius": "m", "width": "m",
             "depth": "m", "load": "N", "axial_load": "N", "contact_angle": "rad", "phase": "rad",
             "position": "rad", "duration": "s", "transient": "s", "dt": "s", "young": "Pa",
             "mass": "kg", "damping": "N s/m", "output_rate": "Hz", "unbalance": "kg m"}
    unit = units.get(leaf)
    if unit in ("m",) and leaf in ("ball_diameter", "pitch_diameter", "ring_radius", "width",
                                   "depth"):
        return "%s [mm]" % key, 1e3
    if unit == "Pa":
        return "%s [GPa]" % key, 1e-9
    if unit in DISPLAY:
        shown, factor = DISPLAY[unit]
        return "%s [%s]" % (key, shown), factor
    return ("%s [%s]" % (key, unit) if unit else "%s [SI]" % key), 1.0


STATISTIC_SHORT = {"rms": "RMS", "ptp": "peak to peak", "kurtosis": "kurtosis",
                   "crest": "crest factor",
                   "peak_frequency": "largest peak"}


def statistic_display(channel, statistic):
    """(axis label, factor) of a sweep column `<channel>.<statistic>`: 'RMS [µm]'."""
    if statistic in ("kurtosis", "crest"):
        return "%s [–]" % STATISTIC_SHORT[statistic], 1.0
    if statistic == "peak_frequency":
        return "%s [Hz]" % STATISTIC_SHORT[statistic], 1.0
    unit, factor = DISPLAY.get(channel_unit(channel), ("SI", 1.0))
    return "%s [%s]" % (STATISTIC_SHORT[statistic], unit), factor


def channel_title(channel):
    """'a_y: acceleration' for a ring channel."""
    ring = ring_channel(channel)
    if not ring:
        return channel
    return "%s: %s %s" % (channel, ring[0], QUANTITY[ring[1]])


def _grid_layout(sweep):
    """Rows: displacement, velocity, acceleration; columns: x, y (z)."""
    rings = [c for c in sweep.channels if ring_channel(c)]
    dofs = [d for d in ("x", "y", "z") if any(ring_channel(c)[0] == d for c in rings)]
    rows = sorted({ring_channel(c)[1] for c in rings})
    cells = {}
    for c in rings:
        d, k = ring_channel(c)
        cells[(rows.index(k), dofs.index(d))] = c
    return len(rows), len(dofs), cells


def _sweep_panel(ax, sweep, keys, column, label, factor, labels=None, gid=None):
    ok = sweep.ok
    if len(keys) == 1:
        kl, kf = key_display(keys[0])
        x = sweep.column_all(keys[0])
        return sweep_line_axes(ax, x[ok] * kf, sweep.column(column)[ok] * factor, xlabel=kl,
                               ylabel=label, labels=[l for l, o in zip(labels, ok) if o]
                               if labels else None, gid=gid)
    kx, ky = keys
    (xl, xf), (yl, yf) = key_display(kx), key_display(ky)
    xs, ys = sweep.column_all(kx), sweep.column_all(ky)
    ux, uy = np.unique(xs), np.unique(ys)
    grid = np.full((uy.size, ux.size), np.nan)
    text = [["" for _ in ux] for _ in uy]
    values = sweep.column(column) * factor
    for n in range(len(sweep.rows)):
        i, k = np.searchsorted(uy, ys[n]), np.searchsorted(ux, xs[n])
        grid[i, k] = values[n]
        if labels:
            text[i][k] = labels[n]
    unit = label[label.rfind("["):] if "[" in label else ""
    return sweep_heatmap_axes(ax, ux * xf, uy * yf, grid, xlabel=xl, ylabel=yl, zlabel=unit,
                              labels=text if labels else None, gid=gid)


def sweep_figures(sweep):
    """name -> Figure: per statistic a panel per ring channel, and the SPL per microphone."""
    keys = sweep.varied
    figures = {}
    failed = int((~sweep.ok).sum())
    if not sweep.ok.any():
        raise FolderError("%s: no case succeeded, nothing to plot (case 1: %s)" % (
            sweep.path, sweep.rows[0].get("error", "?") if sweep.rows else "no rows"))
    subtitle = "%d cases%s; varied: %s" % (
        len(sweep.rows), " (%d failed)" % failed if failed else "", ", ".join(keys))
    if len(keys) > 2:
        return _sweep_scatter_figures(sweep, keys, subtitle)
    nrows, ncols, cells = _grid_layout(sweep)
    with _style():
        for statistic in STATISTICS:
            fig = _new_figure("sweep")
            axes = fig.subplots(nrows, ncols, squeeze=False)
            for (i, k), channel in sorted(cells.items()):
                label, factor = statistic_display(channel, statistic)
                column = "%s.%s" % (channel, statistic)
                labels = sweep.text("%s.peak_label" % channel) if statistic == "peak_frequency" \
                    else None
                drawn = _sweep_panel(axes[i][k], sweep, keys, column, label, factor,
                                     labels=labels, gid="sweep:" + column)
                if statistic == "peak_frequency" and len(keys) == 1:
                    drawn.set_linestyle("none")  # the largest peak jumps between lines
                axes[i][k].set_title(channel_title(channel))
            for i in range(nrows):
                for k in range(ncols):
                    if (i, k) not in cells:
                        axes[i][k].set_visible(False)
            fig.suptitle("%s — %s against %s\n%s" % (sweep.name, STATISTIC_NAMES[statistic],
                                                     " and ".join(keys), subtitle))
            fig.tight_layout()
            figures["sweep_" + statistic] = fig
        mics = sweep.microphones
        if mics:
            fig = _new_figure("sweep")
            parts = ("spl_total", "spl_ring", "spl_balls")
            if len(keys) == 1:
                axes = fig.subplots(1, len(mics), squeeze=False)[0]
                for ax, mic in zip(axes, mics):
                    for part, style in zip(parts, (dict(color="k", lw=2.2, alpha=0.45),
                                                   dict(color="C1", ls="--"), dict(color="C2"))):
                        column = "%s.%s" % (mic, part)
                        line = _sweep_panel(ax, sweep, keys, column, "SPL [dB re 20 µPa]", 1.0,
                                            gid="sweep:" + column)
                        line.set_label(part[4:])
                        line.set(**style)
                    ax.set_title(mic)
                    ax.legend()
            else:
                axes = fig.subplots(1, len(mics), squeeze=False)[0]
                for ax, mic in zip(axes, mics):
                    column = "%s.spl_total" % mic
                    _sweep_panel(ax, sweep, keys, column, "SPL [dB re 20 µPa]", 1.0,
                                 gid="sweep:" + column)
                    ax.set_title("%s, total" % mic)
            fig.suptitle("%s — sound pressure level against %s\n%s"
                         % (sweep.name, " and ".join(keys), subtitle))
            fig.tight_layout()
            figures["sweep_spl"] = fig
    return figures


def _sweep_scatter_figures(sweep, keys, subtitle):
    """Three or more varied keys: each statistic's cases as points against each key."""
    figures = {}
    nrows, ncols, cells = _grid_layout(sweep)
    with _style():
        for statistic in STATISTICS:
            for key in keys:
                fig = _new_figure("sweep")
                axes = fig.subplots(nrows, ncols, squeeze=False)
                kl, kf = key_display(key)
                for (i, k), channel in sorted(cells.items()):
                    label, factor = statistic_display(channel, statistic)
                    column = "%s.%s" % (channel, statistic)
                    pts, = axes[i][k].plot(sweep.column_all(key)[sweep.ok] * kf,
                                           sweep.column(column)[sweep.ok] * factor, "o", ms=4)
                    pts.set_gid("sweep:" + column)
                    axes[i][k].set_xlabel(kl)
                    axes[i][k].set_ylabel(label)
                    axes[i][k].set_title(channel_title(channel))
                fig.suptitle("%s — %s against %s (all cases)\n%s" % (
                    sweep.name, STATISTIC_NAMES[statistic], key, subtitle))
                fig.tight_layout()
                figures["sweep_%s_vs_%s" % (statistic, key.replace(".", "_"))] = fig
    return figures


# --- contact figure ---------------------------------------------------------------------------

def contact_figure(contact):
    """Force-approach on log axes with the Hertz law; the FE/Hertz deviation per step."""
    j = contact.json
    fe, hertz = j.get("fe", {}), j.get("hertz", {})
    curve = contact.curve
    with _style():
        fig = _new_figure("force_approach")
        left, right = fig.subplots(1, 2)
        fit = (fe["K_free_exponent"], fe["exponent"]) if "K_free_exponent" in fe else None
        force_approach_axes(left, curve["approach"], curve["force"], hertz_K=hertz["K"],
                            hertz_n=hertz.get("exponent", 1.5), fit=fit)
        left.set_title("force–approach: FE K at n = 1.5 is %.5g N/m$^{1.5}$ (%+.3g %% of Hertz)"
                       % (fe.get("K", float("nan")),
                          100 * j.get("relative_difference", {}).get("K", float("nan"))),
                       fontsize=10)
        steps = j.get("steps", [])
        if steps and all("hertz_force" in s for s in steps):
            load = np.array([s["force"] for s in steps])
            series = (("force", "hertz_force", "force at the same approach"),
                      ("semi_axis_a", "hertz_semi_axis_a", "semi-major axis a"),
                      ("semi_axis_b", "hertz_semi_axis_b", "semi-minor axis b"),
                      ("peak_pressure", "hertz_peak_pressure", "peak pressure p$_0$"))
            for key, ref, label in series:
                if all(key in s and ref in s for s in steps):
                    dev = np.array([100 * (s[key] / s[ref] - 1) for s in steps])
                    line, = right.semilogx(load, dev, "-o", ms=4, label=label)
                    line.set_gid("contact:dev:" + key)
            right.axhline(0, color="k", lw=0.7)
            plain_log_ticks(right.xaxis)
            right.set_xlabel("contact force Q [N]")
            right.set_ylabel("FE / Hertz − 1 [%]")
            right.set_title("FE against Hertz per approach step")
            right.legend(framealpha=0.9)
            right.grid(True, which="both")
        else:
            right.set_visible(False)
        mesh = j.get("mesh", {})
        fig.suptitle("%s — %s race, %s geometry: FE contact (bearing-fem)\n"
                     "%s cells, %s DOFs, %.3g cells per semi-minor axis, MPI processes: %s, "
                     "%.3g s wall time" % (
                         contact.name, j.get("race", "?"), j.get("geometry", "?"),
                         mesh.get("cells", "?"), mesh.get("dofs", "?"),
                         mesh.get("cells_per_semi_minor", float("nan")),
                         j.get("mpi_processes", "?"),
                         j.get("wall_time", float("nan"))))
        fig.tight_layout()
    return fig


# --- folders and the command line ------------------------------------------------------------

KNOWN_NAMES = ("time", "orbit", "spectrum", "envelope", "ball_loads", "spl", "force_approach",
               "sweep_spl") + tuple("sweep_" + s for s in STATISTICS)


def figures_of(folder):
    """(kind, name -> Figure) of a run, sweep or contact folder."""
    kind = detect(folder)
    if kind == "run":
        return kind, run_figures(load_run(folder))
    if kind == "sweep":
        return kind, sweep_figures(load_sweep(folder))
    return kind, {"force_approach": contact_figure(load_contact(folder))}


def save(fig, path):
    """Writes the figure at DPI (its size in pixels is SIZES x DPI)."""
    fig.savefig(path, dpi=DPI, format=os.path.splitext(path)[1][1:])


def plot_folder(folder, out=None, fmt="png"):
    """Writes the folder's figures to `out` (default FOLDER/plots); returns the paths written."""
    if fmt not in FORMATS:
        raise FolderError("format %r: expected one of %s" % (fmt, ", ".join(FORMATS)))
    kind, figures = figures_of(folder)
    out = out or os.path.join(folder, "plots")
    os.makedirs(out, exist_ok=True)
    written = []
    for name, fig in figures.items():
        path = os.path.join(out, "%s.%s" % (name, fmt))
        tmp = os.path.join(out, ".%s.tmp.%s" % (name, fmt))
        save(fig, tmp)
        os.replace(tmp, path)
        written.append(path)
    for entry in os.listdir(out):  # figures an earlier call wrote that this folder no longer gives
        name, ext = os.path.splitext(entry)
        ours = name in KNOWN_NAMES or (name.startswith("sweep_") and "_vs_" in name)
        if ext == "." + fmt and ours and name not in figures:
            os.remove(os.path.join(out, entry))
    return written


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="bearing-plot",
        description="Figures (PNG, SVG or PDF) of a bearing-sim run or sweep folder or of a "
                    "bearing-fem contact output; the kind is recognised from the files.",
        epilog="Run: time, orbit, spectrum, and with their outputs envelope, ball_loads, spl. "
               "Sweep: sweep_<statistic>, sweep_spl. Contact: force_approach.")
    parser.add_argument("folder", metavar="RUN_DIR|SWEEP_DIR|CONTACT_DIR")
    parser.add_argument("--out", metavar="DIR", help="where the figures go (default FOLDER/plots)")
    parser.add_argument("--format", choices=FORMATS, default="png", help="file format (png)")
    parser.add_argument("--quiet", action="store_true", help="print nothing on success")
    args = parser.parse_args(argv)
    try:
        written = plot_folder(args.folder, args.out, args.format)
    except FolderError as e:
        print("bearing-plot: error: %s" % e, file=sys.stderr)
        return 2
    if not args.quiet:
        for path in written:
            print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
