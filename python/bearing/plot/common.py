"""Constants, sizes, units and small helpers shared by the figures of bearing.plot."""

import math

import numpy as np
import matplotlib
from matplotlib.figure import Figure


DPI = 100
# Figure sizes in inches; the files are these times DPI pixels.
SIZES = {
    "time": (13.0, 9.0),
    "time_axial": (13.0, 12.5),  # 3-DOF (and balls with an axial load): z and az added
    "orbit": (13.0, 6.6),
    "spectrum": (13.0, 8.5),
    "spectrum_axial": (15.0, 8.5),
    "sensor": (13.0, 8.5),
    "envelope": (13.0, 7.0),
    "ball_loads": (13.0, 6.2),
    "spl": (13.0, 5.6),
    "sweep": (13.0, 8.5),
    "force_approach": (13.0, 5.8),
    "record_spectrum": (13.0, 6.0),
    "record_envelope": (13.0, 8.5),
    "record_coherence": (13.0, 8.0),
    "calibration": (13.0, 10.0),
    "stiffness": (15.0, 5.4),
    "modes": (13.0, 8.0),  # its height follows the panels (modes_figure)
    "report": (7.0, 4.4),  # one panel of the verification report (bearing-verify)
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
    prefix = name.rstrip("0123456789")
    return {"Q": "N", "Qo": "N", "Fi": "N", "Fo": "N", "d": "m", "r": "m", "vr": "m/s",
            "wb": "rad/s"}.get(prefix, "1")


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


def ball_channels_size(rows):
    """The ball_channels figure's size in inches: its rows of panels (two per row)."""
    return (13.0, 1.6 + 2.7 * rows)


def _wrap(text, width):
    words, lines, line = text.split(), [], ""
    for w in words:
        if line and len(line) + 1 + len(w) > width:
            lines.append(line)
            line = w
        else:
            line = (line + " " + w).strip()
    return "\n".join(lines + [line])


def _new_figure(kind):
    return Figure(figsize=SIZES[kind], dpi=DPI)


def _style():
    return matplotlib.rc_context(STYLE)
