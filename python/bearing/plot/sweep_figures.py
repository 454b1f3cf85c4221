"""The figures of a bearing-sim sweep: each statistic against the varied keys."""

import numpy as np
from matplotlib.figure import Figure

from .common import (
    DISPLAY, FolderError, QUANTITY, STATISTICS, STATISTIC_NAMES, _new_figure, _style,
    channel_unit, ring_channel)
from .panels import sweep_heatmap_axes, sweep_line_axes


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
