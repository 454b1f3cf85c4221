"""Panels: plain arrays drawn on a given matplotlib Axes (reused by the verification report)."""

import math

import numpy as np
import matplotlib.ticker
from matplotlib.patches import Circle


# --- panels (plain arrays on a given Axes; reused by the verification report) ----------------

def _spread(want, spacing, right=0.99):
    """Positions (axes fractions, ascending) at least `spacing` apart, each as near its wanted
    place as that allows: pushed right, then back left from the right edge."""
    xs = list(want)
    for i in range(1, len(xs)):
        xs[i] = max(xs[i], xs[i - 1] + spacing)
    if xs:
        xs[-1] = min(xs[-1], right)
    for i in range(len(xs) - 2, -1, -1):
        xs[i] = min(xs[i], xs[i + 1] - spacing)
    return xs


def label_peaks(ax, peaks, fmax, spacing=0.028, y=0.985):
    """Names the peaks (dicts with frequency, amplitude, label) in a row of vertical labels along
    the top of the axes, spread to at least `spacing` (axes fraction) apart, each joined to its
    peak by a thin line: legible however close the peaks lie."""
    peaks = sorted(peaks, key=lambda p: p["frequency"])
    if not peaks:
        return
    spacing = min(spacing, 0.96 / len(peaks))
    xs = _spread([min(max(p["frequency"] / fmax, 0.0), 1.0) for p in peaks], spacing)
    for i, p in enumerate(peaks):
        ax.annotate(p["label"], xy=(p["frequency"], p["amplitude"]), xycoords="data",
                    xytext=(xs[i], y), textcoords="axes fraction", rotation=90, ha="center",
                    va="top", fontsize=8.5, color="C3",
                    arrowprops=dict(arrowstyle="-", color="C3", lw=0.5, alpha=0.6,
                                    shrinkA=1, shrinkB=4))


def mark_lines(ax, lines, spacing=0.03, gid=None):
    """Labelled vertical lines at given x (dicts with x and label: an expected spectral line, a
    limit): dashed grey, each label written upwards along the top of the axes just right of its
    line, spread apart as label_peaks does. Call after the axes' x limits are set."""
    lines = sorted(lines, key=lambda m: m["x"])
    if not lines:
        return
    for m in lines:
        drawn = ax.axvline(m["x"], color="0.35", lw=0.9, ls="--", zorder=1)
        if gid:
            drawn.set_gid("%s:%s" % (gid, m["label"]))
    lo, hi = ax.get_xlim()
    to_axes = (lambda v: (math.log10(v) - math.log10(lo)) / (math.log10(hi) - math.log10(lo))) \
        if ax.get_xscale() == "log" else (lambda v: (v - lo) / (hi - lo))
    spacing = min(spacing, 0.96 / len(lines))
    xs = _spread([min(max(to_axes(m["x"]) + 0.012, 0.0), 1.0) for m in lines], spacing)
    for x, m in zip(xs, lines):
        ax.text(x, 0.985, m["label"], transform=ax.transAxes, rotation=90, ha="center",
                va="top", fontsize=8.5, color="0.2",
                bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.8))


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
                  decades=5.0, color="C0", top=None):
    """An amplitude spectrum (already in display units) with its listed peaks (dicts with
    frequency, amplitude in display units, label) marked and named; the y range from `top` (the
    largest amplitude of overlaid spectra) or from this one's."""
    line, = ax.plot(f, amplitude, color=color, lw=0.8)
    if gid:
        line.set_gid(gid)
    fmax = fmax or f[-1]
    inside = [p for p in peaks if p["frequency"] <= fmax]
    top = top or max([np.max(amplitude[(f <= fmax)])] + [p["amplitude"] for p in inside])
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
                        factor=1e6, span=None, points_label="FE (bearing-fem)", law_label="Hertz",
                        fit_label="FE fit", gid="contact"):
    """Force [N] against approach [m] (plotted in `unit`, x factor) on log axes: the points, the
    law Q = K delta^n (hertz_K, hertz_n; named law_label) as a solid line and an optional second
    law `fit` = (K, n) dashed, both over `span` = (lowest, highest) approach [m] (default: the
    points' range widened by 1.3 each way). Gids: GID:fe, GID:hertz, GID:fit."""
    approach, force = np.asarray(approach, dtype=float), np.asarray(force, dtype=float)
    if approach.size:
        points, = ax.loglog(approach * factor, force, "o", color="C0", ms=6, label=points_label)
        points.set_gid(gid + ":fe")
    lo, hi = span if span else (approach.min() / 1.3, approach.max() * 1.3)
    d = np.geomspace(lo, hi, 100)
    law, = ax.loglog(d * factor, hertz_K * d ** hertz_n, "-", color="C3", lw=1.3,
                     label="%s: Q = K δ$^{%.4g}$, K = %.5g N/m$^{%.4g}$"
                     % (law_label, hertz_n, hertz_K, hertz_n))
    law.set_gid(gid + ":hertz")
    if fit:
        K, n = fit
        fitted, = ax.loglog(d * factor, K * d ** n, "--", color="0.3", lw=1.0,
                            label="%s: K = %.5g N/m$^{%.5g}$, n = %.5g" % (fit_label, K, n, n))
        fitted.set_gid(gid + ":fit")
    ax.set_xlabel("approach δ [%s]" % unit)
    ax.set_ylabel("contact force Q [N]")
    plain_log_ticks(ax.xaxis)
    plain_log_ticks(ax.yaxis)
    ax.grid(True, which="both")
    ax.legend(loc="upper left", framealpha=0.9)


def series_axes(ax, series, *, xlabel, ylabel, log_x=False, log_y=False, lines=(), gid=None):
    """Named x-y series (dicts with label, x, y and style "line", "marker" or "line+marker"), each
    in its own colour, on linear or log axes, with labelled vertical `lines` (mark_lines). The
    series' gids are GID:0, GID:1, ... in the order given."""
    drawn = []
    for i, s in enumerate(series):
        style = s.get("style", "line")
        fmt, extra = {"marker": ("o", dict(ms=4.5)), "line+marker": ("-o", dict(ms=4, lw=1.2))
                      }.get(style, ("-", dict(lw=1.2)))
        line, = ax.plot(np.asarray(s["x"], dtype=float), np.asarray(s["y"], dtype=float), fmt,
                        color="C%d" % (i % 10), label=s.get("label") or None, **extra)
        if gid:
            line.set_gid("%s:%d" % (gid, i))
        drawn.append(line)
    if log_x:
        ax.set_xscale("log")
    if log_y:
        ax.set_yscale("log")
    ax.grid(True, which="both")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    mark_lines(ax, lines, gid=gid and gid + ":line")
    if any(s.get("label") for s in series):
        ax.legend(loc="best", framealpha=0.9)
    return drawn


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
