"""Folders to figure files, and the command line (bearing-plot, python3 -m bearing.plot)."""

import argparse
import os
import sys

from matplotlib.figure import Figure

from .common import DPI, FORMATS, FolderError, STATISTICS
from .folders import detect, load_calibration, load_contact, load_run, load_sweep
from .run_figures import run_figures
from .record_figures import load_analysis, record_figures
from .sweep_figures import sweep_figures
from .stiffness_figure import load_stiffness, stiffness_figure
from .contact_figure import contact_figure
from .calibration_figure import calibration_figure
from .modes_figure import load_modes, modes_figure


# --- folders and the command line ------------------------------------------------------------

KNOWN_NAMES = ("time", "orbit", "spectrum", "envelope", "ball_loads", "ball_channels", "spl",
               "sensor", "force_approach", "calibration", "stiffness", "modes", "sweep_spl") + tuple("sweep_" + s
                                                                    for s in STATISTICS)


def figures_of(folder):
    """(kind, name -> Figure) of a run, sweep or contact folder or a calibration (file or
    folder)."""
    kind = detect(folder)
    if kind == "run":
        return kind, run_figures(load_run(folder))
    if kind == "analysis":
        return kind, record_figures(load_analysis(folder))
    if kind == "sweep":
        return kind, sweep_figures(load_sweep(folder))
    if kind == "stiffness":
        return kind, {"stiffness": stiffness_figure(load_stiffness(folder))}
    if kind == "calibration":
        return kind, {"calibration": calibration_figure(load_calibration(folder))}
    if kind == "modes":
        return kind, {"modes": modes_figure(load_modes(folder))}
    return kind, {"force_approach": contact_figure(load_contact(folder))}


def default_out(folder):
    """FOLDER/plots; for a calibration named by its file DIR/STEM.json, DIR/STEM_plots (beside
    the race folders DIR/STEM_inner, DIR/STEM_outer bearing-fem writes)."""
    if os.path.isfile(folder):
        return os.path.splitext(folder)[0] + "_plots"
    return os.path.join(folder, "plots")


def save(fig, path):
    """Writes the figure at DPI (its size in pixels is SIZES x DPI)."""
    fig.savefig(path, dpi=DPI, format=os.path.splitext(path)[1][1:])


def plot_folder(folder, out=None, fmt="png"):
    """Writes the folder's figures to `out` (default: default_out); returns the paths written."""
    if fmt not in FORMATS:
        raise FolderError("format %r: expected one of %s" % (fmt, ", ".join(FORMATS)))
    kind, figures = figures_of(folder)
    out = out or default_out(folder)
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
        description="Figures (PNG, SVG or PDF) of a bearing-sim run or sweep folder, of a "
                    "bearing-fem contact output or of a bearing-fem calibration; the kind is "
                    "recognised from the files.",
        epilog="Run: time, orbit, spectrum, and with their outputs envelope, ball_loads, "
               "ball_channels, spl (a 3-DOF run adds z and az to time and spectrum). Analysed "
               "record: spectrum, envelope (with the squared envelope spectrum's fault lines). "
               "Sweep: sweep_<statistic>, sweep_spl. Stiffness: stiffness. Contact: force_approach. "
               "Modes (bearing-fem modes): modes. Calibration: calibration. With [housing]: "
               "sensor.")
    parser.add_argument(
        "folder",
        metavar="RUN_DIR|ANALYSIS_DIR|SWEEP_DIR|STIFFNESS_DIR|CONTACT_DIR|MODES_DIR|CALIBRATION.json")
    parser.add_argument("--out", metavar="DIR", help="where the figures go (default FOLDER/plots; "
                        "for DIR/STEM.json, DIR/STEM_plots)")
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
