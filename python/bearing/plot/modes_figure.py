"""The figure of a structure's natural modes (``bearing-fem modes STRUCTURE.toml --out FOLDER``:
modes.json): per mode, its frequency, how it moves the seat (the rigid translation x, y, z and
the tilts about x and y of the seat's least-squares fit, in the mass-normalised shapes' units)
and how it moves each sensor. What the lumped model's ``[housing] modes`` takes from it: the
seat's x and y, and the sensors."""

import json
import os

import numpy as np

from .common import FolderError, _new_figure, _style

MODES_FORMAT = "bearing-fem modes"


class Modes:
    """modes.json of a bearing-fem modes folder, as plain dicts and NumPy arrays (SI)."""

    def __init__(self, folder):
        self.folder = folder
        path = os.path.join(folder, "modes.json")
        try:
            with open(path, encoding="utf-8") as f:
                self.json = json.load(f)
        except (OSError, ValueError) as e:
            raise FolderError("%s: cannot read a modes file: %s" % (path, e)) from e
        if self.json.get("format") != MODES_FORMAT:
            raise FolderError("%s: \"format\" is %r, not %r" % (path, self.json.get("format"),
                                                                MODES_FORMAT))
        self.frequencies = np.asarray(self.json["frequencies"], dtype=float)
        seat = self.json.get("seat", {})
        self.seat = {k: np.asarray(seat[k], dtype=float)
                     for k in ("x", "y", "z", "tilt_x", "tilt_y") if k in seat}
        self.sensors = {s["name"]: {a: np.asarray(s[a], dtype=float) for a in ("x", "y", "z")}
                        for s in self.json.get("sensors", [])}

    @property
    def name(self):
        structure = self.json.get("structure") or self.folder
        return os.path.splitext(os.path.basename(os.path.normpath(structure)))[0]


def is_modes_folder(folder):
    path = os.path.join(folder, "modes.json")
    if not os.path.isfile(path):
        return False
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f).get("format") == MODES_FORMAT
    except (OSError, ValueError, AttributeError):
        return False


def load_modes(folder):
    return Modes(folder)


def _bars(ax, modes, series, unit, gid):
    """Grouped bars per mode (x = mode number), one colour per series."""
    n = modes.frequencies.size
    k = np.arange(1, n + 1)
    width = 0.8 / max(len(series), 1)
    for i, (label, values) in enumerate(series):
        bars = ax.bar(k + (i - (len(series) - 1) / 2) * width, values, width, label=label,
                      color="C%d" % i)
        for bar in bars:  # each bar's height is the value, readable back by its gid
            bar.set_gid("%s:%s" % (gid, label))
    ax.axhline(0.0, color="0.3", lw=0.6)
    ax.set_xlim(0.4, n + 0.6)
    ax.set_xticks(k)
    ax.set_xticklabels(["%d\n%.3g" % (i, f / 1e3) for i, f in zip(k, modes.frequencies)],
                       fontsize=8 if n <= 20 else 6)
    ax.set_xlabel("mode\nfrequency [kHz]")
    ax.set_ylabel(unit)
    ax.legend(loc="upper right", fontsize=8.5, framealpha=0.9, ncol=len(series))


def modes_figure(modes):
    """Top: the seat's rigid translation per mode (x, y, z); middle: its tilts (when the file has
    them); bottom: each sensor's displacement per mode (x, y, z; one panel per sensor, up to
    three). Shapes mass-normalised (phi^T M phi = 1 kg): kg^-1/2, tilts rad kg^-1/2 m^-1."""
    sensors = list(modes.sensors.items())[:3]
    tilts = [(a, modes.seat[a]) for a in ("tilt_x", "tilt_y") if a in modes.seat]
    rows = 1 + (1 if tilts else 0) + len(sensors)
    with _style():
        fig = _new_figure("modes")
        fig.set_size_inches(13.0, 2.9 + 2.6 * rows)
        axes = np.atleast_1d(fig.subplots(rows, 1))
        _bars(axes[0], modes, [(a, modes.seat[a]) for a in ("x", "y", "z") if a in modes.seat],
              "seat translation [kg$^{-1/2}$]", "modes_seat")
        axes[0].set_title("the seat's rigid motion per mode (what drives and moves the bearing's "
                          "outer ring: x and y)")
        row = 1
        if tilts:
            _bars(axes[row], modes, tilts, "seat tilt [rad kg$^{-1/2}$ m$^{-1}$]", "modes_tilt")
            axes[row].set_title("the seat's tilts per mode (not taken by the 2-DOF and 3-DOF "
                                "rings)")
            row += 1
        for name, shape in sensors:
            _bars(axes[row], modes, [(a, shape[a]) for a in ("x", "y", "z")],
                  "displacement [kg$^{-1/2}$]", "modes_sensor_" + name)
            axes[row].set_title("sensor %s per mode" % name)
            row += 1
        mesh = modes.json.get("mesh", {})
        detail = ""
        if mesh:
            detail = ": %s elements, %s DOFs, degree %s" % (mesh.get("elements", "?"),
                                                            mesh.get("dofs", "?"),
                                                            mesh.get("fe_degree", "?"))
        free = modes.json.get("boundary", {}).get("free")
        fig.suptitle("%s — %d natural modes, %.4g to %.4g Hz%s%s" % (
            modes.name, modes.frequencies.size, modes.frequencies[0], modes.frequencies[-1],
            detail, " (free-free: the 6 rigid-body modes left out)" if free else ""))
        fig.tight_layout()
    return fig
