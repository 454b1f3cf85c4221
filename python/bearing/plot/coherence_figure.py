"""The coherence diagnosis of an analysed record (summary.json's ``coherence``): for each fault
family, its margin in every band of the cyclic-coherence map (the IESFOgram: the bands of the
pre-whitened record by level, coloured by how far the family's 2-of-3 test stands over what it
needs), its best band outlined; and each family's three harmonics in that band, each one's excess
over its threshold, with the family's margin and whether it is named."""

import matplotlib.colors as mcolors
import matplotlib.patches as mpatches
import numpy as np

from .common import _new_figure, _style

FAMILIES = ("outer", "inner", "ball")
# The colour scale's ends [dB]: below −10 a family is nowhere near; above +20 it is plain.
LOW, HIGH = -10.0, 20.0


def _map_axes(ax, coherence, family, norm, cmap):
    """One family's margin per band: x the band, y its level (shifted bands half a row up)."""
    bands = coherence["bands"]
    levels = coherence["levels"]
    shifted = coherence.get("shifted", [False] * len(bands))
    margins = coherence["map"][family]
    info = coherence["families"][family]
    top = max(b[1] for b in bands)
    for i, ((lo, hi), level, shift, m) in enumerate(zip(bands, levels, shifted, margins)):
        y = level + (0.5 if shift else 0.0)
        rated = m > -99
        patch = mpatches.Rectangle((lo, y), hi - lo, 0.5,
                                   facecolor=cmap(norm(m)) if rated else "0.92",
                                   edgecolor="white", lw=0.6)
        patch.set_gid("map:%s:%d" % (family, i))
        ax.add_patch(patch)
    best = info.get("band_index", 0)
    lo, hi = bands[best]
    y = levels[best] + (0.5 if shifted[best] else 0.0)
    ax.add_patch(mpatches.Rectangle((lo, y), hi - lo, 0.5, fill=False, edgecolor="k", lw=1.6))
    ax.set_xlim(0, top)
    ax.set_ylim(max(levels) + 1.0, 0)
    ax.set_yticks([l + 0.25 for l in range(max(levels) + 1)])
    ax.set_yticklabels(["%d" % l for l in range(max(levels) + 1)])
    ax.set_ylabel("%s\nlevel" % family)
    ax.set_title("%s: best band %.0f–%.0f Hz, margin %+.1f dB%s" % (
        family, lo, hi, info.get("margin", float("nan")), ", named" if info.get("named") else ""),
        fontsize=9.5, loc="left")


def _lines_axes(ax, coherence):
    """Each family's three harmonics in its best band: excess over the threshold [dB]."""
    width = 0.26
    for k, family in enumerate(FAMILIES):
        info = coherence["families"][family]
        harmonics = info.get("harmonics", [])
        x = np.arange(len(harmonics)) + (k - 1) * width
        excess = [h["excess"] for h in harmonics]
        bars = ax.bar(x, excess, width, color={"outer": "C3", "inner": "C2", "ball": "C4"}[family],
                      label="%s: %d of 3 (%d needed), margin %+.1f dB%s" % (
                          family, info.get("standing_out", 0), info.get("needed", 2),
                          info.get("margin", float("nan")), ", named" if info.get("named") else ""))
        for b in bars:
            b.set_gid("lines:%s" % family)
        for xi, h in zip(x, harmonics):
            ax.text(xi, 0, h["label"], rotation=90, ha="center", va="bottom", fontsize=7.5)
    ax.axhline(0, color="k", lw=0.8)
    ax.set_xticks([0, 1, 2])
    ax.set_xticklabels(["1st harmonic", "2nd", "3rd"])
    ax.set_ylabel("excess over threshold [dB]")
    ax.legend(loc="upper right", fontsize=8.5, framealpha=0.9)
    ax.set_title("lines in each family's best band (> 0: over threshold)", fontsize=9.5,
                 loc="left")


def coherence_figure(a):
    """The map of each family's margin over the bands and its lines in its best band."""
    coherence = a.summary["coherence"]
    diagnosis = a.summary.get("diagnosis", {})
    norm = mcolors.Normalize(vmin=LOW, vmax=HIGH, clip=True)
    cmap = mcolors.LinearSegmentedColormap.from_list(
        "margin", [(0.0, "#f7f7f7"), (-LOW / (HIGH - LOW), "#fde0a0"), (1.0, "#b2182b")])
    with _style():
        fig = _new_figure("record_coherence")
        grid = fig.add_gridspec(3, 3, width_ratios=[1.6, 0.04, 1.0], hspace=0.55, wspace=0.55,
                                left=0.08, right=0.98, top=0.86, bottom=0.08)
        axes = [fig.add_subplot(grid[i, 0]) for i in range(3)]
        for ax, family in zip(axes, FAMILIES):
            _map_axes(ax, coherence, family, norm, cmap)
        axes[-1].set_xlabel("frequency band [Hz]")
        lines = fig.add_subplot(grid[:, 2])
        _lines_axes(lines, coherence)
        bar = fig.colorbar(_scalar_mappable(norm, cmap), cax=fig.add_subplot(grid[:, 1]))
        bar.set_label("margin per band [dB]\n(before any lines are explained)")
        fig.suptitle(a.title(
            "cyclic coherence by band (%d bands, false-alarm rate %.3g per family)" % (
                len(coherence["bands"]), coherence["settings"].get("false_alarm", 0)),
            "diagnosis: %s, margin %+.1f dB" % (diagnosis.get("family", "?"),
                                                 diagnosis.get("margin", float("nan")))))
    return fig


def _scalar_mappable(norm, cmap):
    import matplotlib.cm as cm
    mappable = cm.ScalarMappable(norm=norm, cmap=cmap)
    mappable.set_array([])
    return mappable
