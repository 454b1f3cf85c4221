"""The figures of a bearing-sim run: time, orbit, spectrum, envelope, ball loads, the other
per-ball channels, SPL."""

import math

import numpy as np
from matplotlib.figure import Figure

from .common import (
    BALL_PASSES_ZOOMED, DISPLAY, DPI, _frequency_limit, _new_figure, _nice_ceiling, _style,
    _wrap, ball_channels_size, channel_label, channel_unit, load_line_passes, ring_channel)
from .panels import ball_load_axes, orbit_axes, spectrum_axes, spl_axes, trace_axes
from .sensor_figure import has_sensor, sensor_figure

# The ring channels the time and spectrum figures draw, in this order (z, az: 3-DOF, or balls with
# an axial load); the velocities are in the files and summary.json, not drawn.
RING_DRAWN = ("x", "y", "z", "ax", "ay", "az")


# --- run figures ------------------------------------------------------------------------------

def time_figure(run):
    """x, y, ax, ay: the whole record (transient shaded) and the last few ball passes."""
    r = run.response
    t = r["t"]
    bpfo = run.frequencies.get("bpfo", 0.0)
    span = BALL_PASSES_ZOOMED / bpfo if bpfo > 0 else 0.1 * (t[-1] - t[0])
    zoom = t >= t[-1] - span
    marks = load_line_passes(run.summary, t[zoom][0], t[-1])
    channels = [c for c in RING_DRAWN if c in r]
    with _style():
        fig = _new_figure("time_axial" if "z" in r else "time")
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
        fig.suptitle(run.title("ring displacement and acceleration"
                               + (" (radial x, y; axial z)" if "z" in r else "")))
        fig.align_ylabels(axes[:, 0])
        fig.tight_layout()
    return fig


def orbit_figure(run):
    """The inner-ring centre in the x-y plane: with the clearance circle, and the steady orbit
    enlarged. With a [housing] the ring relative to the outer ring (x - x_housing, y - y_housing;
    on the structure's modes x - x_seat, y - y_seat), the position the clearance is about."""
    r = run.response
    factor = DISPLAY["m"][1]
    steady = r["t"] >= run.transient
    if not steady.any():
        steady = np.ones_like(steady)
    x, y = r["x"], r["y"]
    for seat in ("housing", "seat"):
        if "x_" + seat in r and "y_" + seat in r:
            x, y = x - r["x_" + seat], y - r["y_" + seat]
    x, y = x * factor, y * factor
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
    axial = "z" in s or "az" in s
    dofs = ("x", "y", "z") if axial else ("x", "y")
    window = run.case.get("output", {}).get("window", "hann")
    with _style():
        fig = _new_figure("spectrum_axial" if axial else "spectrum")
        # rows: displacement, acceleration; columns: the ring's DOFs
        grid = fig.subplots(2, len(dofs), squeeze=False)
        cells = [(grid[row][col], prefix + dof) for row, prefix in enumerate(("", "a"))
                 for col, dof in enumerate(dofs)]
        for ax, name in cells:
            if name not in s:
                ax.set_visible(False)
                continue
            label, factor = channel_label(name, run.summary)
            peaks = _peaks_display(run.summary.get("peaks", {}).get(name, []), factor)
            amplitude = s[name] * factor
            spectrum_axes(ax, f, amplitude, peaks, label="amplitude of " + label,
                          fmax=_frequency_limit(f, amplitude, peaks), gid="spectrum:%s" % name,
                          color="C0" if ring_channel(name)[1] == 0 else "C1")
            families = run.summary.get("peak_families")
            ax.set_title("%s: %d largest peaks (▼), named by %s"
                         % (name, len(peaks), ", ".join(families) if families is not None
                            else "bearing frequency"))
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


# Per-ball channels besides Q (ball_loads): the prefix, what it is, its symbol.
BALL_CHANNELS = (
    ("d", "approach", "d_j"),
    ("r", "radial displacement", "r_j"),
    ("vr", "radial velocity", "v_{r,j}"),
    ("wb", "spin (relative to the cage)", "\\omega_{b,j}"),
    ("Qo", "outer contact load", "Q_{o,j}"),
    ("Fi", "friction force, inner contact", "F_{i,j}"),
    ("Fo", "friction force, outer contact", "F_{o,j}"),
)


def ball_channel_families(run):
    """The BALL_CHANNELS prefixes the response has (Z columns each: prefix1 ... prefixZ)."""
    return [p for p, _, _ in BALL_CHANNELS if "%s1" % p in run.response]


def ball_channel_figure(run):
    """Each per-ball channel besides Q (ball approach, ball motion, ball dynamics), every ball
    over the last ball passes: one panel per channel kind."""
    r = run.response
    t = r["t"]
    families = ball_channel_families(run)
    z = run.balls
    bpfo = run.frequencies.get("bpfo", 0.0)
    span = BALL_PASSES_ZOOMED * 2 / bpfo if bpfo > 0 else 0.1 * (t[-1] - t[0])
    zoom = t >= t[-1] - span
    columns = 1 if len(families) == 1 else 2
    rows = (len(families) + columns - 1) // columns
    with _style():
        fig = Figure(figsize=ball_channels_size(rows), dpi=DPI)
        axes = fig.subplots(rows, columns, squeeze=False, sharex=True)
        for ax, prefix in zip(axes.ravel(), families):
            what, symbol = next((w, y) for p, w, y in BALL_CHANNELS if p == prefix)
            unit = channel_unit("%s1" % prefix, run.summary)
            shown, factor = DISPLAY.get(unit, (unit, 1.0))
            for j in range(z):
                name = "%s%d" % (prefix, j + 1)
                line, = ax.plot(t[zoom], r[name][zoom] * factor, color="C%d" % (j % 10), lw=0.9,
                                label="ball %d" % (j + 1))
                line.set_gid("ball_channels:" + name)
            ax.set_xlim(t[zoom][0], t[-1])
            ax.set_ylabel("$%s$ [%s]" % (symbol, shown))
            ax.set_title("%s: %s%s…%s%d" % (what, prefix, 1, prefix, z))
        for ax in axes.ravel()[len(families):]:
            ax.set_visible(False)
        for col in range(columns):  # the time axis under the lowest panel of each column
            lowest = axes[(len(families) - 1 - col) // columns][col]
            lowest.xaxis.set_tick_params(labelbottom=True)
            lowest.set_xlabel("time t [s]")
        axes[0][-1].legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8.5,
                           ncol=1 if z <= 14 else 2)
        fig.suptitle(run.title("per-ball channels, last %s" % (
            "%d ball passes" % (2 * BALL_PASSES_ZOOMED) if bpfo > 0 else "10 % of the record")))
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
    if has_sensor(run):
        figures["sensor"] = sensor_figure(run)
    if "Q1" in run.response and run.balls > 0:
        figures["ball_loads"] = ball_load_figure(run)
    if ball_channel_families(run) and run.balls > 0:
        figures["ball_channels"] = ball_channel_figure(run)
    if run.summary.get("acoustics", {}).get("microphones"):
        figures["spl"] = spl_figure(run)
    return figures
