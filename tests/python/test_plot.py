#!/usr/bin/python3
"""bearing-plot end to end: each kind of figure made from a small run, sweep or contact output;
the files exist, are images of the expected size, and the plotted data are the files' values
(read back from the figures' artists by their gid, not from pixels). Skipped (exit 77) when
/usr/bin/python3 has no matplotlib or numpy.

    test_plot.py CASE --sim BEARING_SIM --python BUILD/python --work DIR [--fem BEARING_FEM]
                 [--source SOURCE_DIR]

CASE: run (default case: time, orbit, spectrum), run_outputs (envelope, ball loads, acoustics,
output.format = "npy"), run_housing (the sensor figure of a case with [housing]), sweep2 (2 x 2:
heat maps), sweep1 (one key with acoustics: lines), contact_example
(examples/seed003_6308_calibration_inner, a committed bearing-fem output), contact_fem (a fresh
bearing-fem contact run; needs --fem), cli (formats, default --out, errors, import without the
compiled extension).
"""
import argparse
import csv
import importlib
import json
import math
import os
import shutil
import struct
import subprocess
import sys

try:
    import numpy as np
    import matplotlib  # noqa: F401
except ImportError as e:
    print("SKIP: %s cannot import numpy and matplotlib (%s); install python3-matplotlib and "
          "python3-numpy to test bearing-plot" % (sys.executable, e))
    sys.exit(77)

SHORT = ["--quiet", "--set", "solver.duration=0.15", "--set", "solver.transient=0.05"]
FAILURES = []


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what)
    if not ok:
        FAILURES.append(what)


def csv_columns(path):
    """The CSV's numeric columns as {name: float array}, read with the csv module (independently
    of bearing.plot); text columns (a sweep's status, error, peak labels) are left out."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    columns = {}
    for i, name in enumerate(rows[0]):
        try:
            columns[name] = np.array([float(r[i]) for r in rows[1:]])
        except ValueError:
            pass
    return columns


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n":
        return None
    return struct.unpack(">II", head[16:24])


def artist(fig, gid):
    found = fig.findobj(lambda a: a.get_gid() == gid)
    if len(found) != 1:
        raise AssertionError("%d artists with gid %s" % (len(found), gid))
    return found[0]


def same(a, b):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and np.array_equal(a, b)


def check_files(plot, out, names, fmt="png"):
    """Every expected figure file, non-empty, of its size in pixels; nothing else of ours."""
    for name in names:
        path = os.path.join(out, "%s.%s" % (name, fmt))
        exists = os.path.isfile(path) and os.path.getsize(path) > 0
        check(exists, "%s written and not empty" % path)
        if not exists:
            continue
        kind = "sweep" if name.startswith("sweep_") else name
        want = tuple(int(round(v * plot.DPI)) for v in plot.SIZES[kind])
        if fmt == "png":
            check(png_size(path) == want, "%s is %s px (want %s)" % (path, png_size(path), want))
        elif fmt == "svg":
            with open(path) as f:
                text = f.read(2000)
            check("<svg" in text and 'width="%gpt"' % (plot.SIZES[kind][0] * 72) in text,
                  "%s is an SVG %g in wide" % (path, plot.SIZES[kind][0]))
        else:
            with open(path, "rb") as f:
                check(f.read(5) == b"%PDF-", "%s is a PDF" % path)
    ours = sorted(f for f in os.listdir(out) if f.endswith("." + fmt))
    check(ours == sorted("%s.%s" % (n, fmt) for n in names),
          "%s holds exactly %s (has %s)" % (out, sorted(names), ours))


def run_sim(args, *cmd):
    subprocess.run([args.sim, *cmd], check=True, stdout=subprocess.DEVNULL)


def plot_cli(args, folder, *extra):
    return subprocess.run([os.path.join(args.python, "bearing-plot"), folder, *extra],
                          capture_output=True, text=True)


# --- runs -------------------------------------------------------------------------------------

def check_run_data(plot, folder, figures, csv_format=True):
    summary = json.load(open(os.path.join(folder, "summary.json")))
    if csv_format:
        response = csv_columns(os.path.join(folder, "response.csv"))
        spectrum = csv_columns(os.path.join(folder, "spectrum.csv"))
    else:
        meta = json.load(open(os.path.join(folder, "columns.json")))["tables"]
        table = lambda stem: dict(zip(meta[stem + ".npy"]["columns"],  # noqa: E731
                                      np.load(os.path.join(folder, stem + ".npy")).T))
        response, spectrum = table("response"), table("spectrum")
    t = response["t"]
    factor = {c: plot.DISPLAY[summary["channels"][c]["unit"]][1] for c in ("x", "y", "ax", "ay")}

    fig = figures["time"]
    for c in ("x", "y", "ax", "ay"):
        line = artist(fig, "time:" + c)
        check(same(line.get_xydata(), np.column_stack([t, response[c] * factor[c]])),
              "time: %s over the whole record equals the response file" % c)
        zoom = artist(fig, "time_zoom:" + c).get_xydata()
        n = len(zoom)
        check(n > 10 and same(zoom, np.column_stack([t[-n:], response[c][-n:] * factor[c]])),
              "time: %s zoom (%d samples) equals the end of the record" % (c, n))
    span = zoom[-1, 0] - zoom[0, 0]
    check(abs(span - plot.BALL_PASSES_ZOOMED / summary["frequencies"]["bpfo"]) < 2 / 20000.0,
          "time: the zoom spans %d ball passes (%.4g s)" % (plot.BALL_PASSES_ZOOMED, span))

    fig = figures["orbit"]
    steady = t >= summary["case"]["transient"]
    um = plot.DISPLAY["m"][1]
    check(same(artist(fig, "orbit").get_xydata(),
               np.column_stack([response["x"][steady] * um, response["y"][steady] * um])),
          "orbit: the steady x-y equals the response file")
    case_toml = open(os.path.join(folder, "case.toml")).read()
    clearance = float(next(line.split("=")[1] for line in case_toml.splitlines()
                           if line.startswith("clearance")))
    check(math.isclose(artist(fig, "clearance").get_radius(), clearance / 2 * um, rel_tol=1e-15),
          "orbit: the clearance circle's radius is P_d/2 = %.4g µm" % (clearance / 2 * um))

    fig = figures["spectrum"]
    for c in ("x", "y", "ax", "ay"):
        line = artist(fig, "spectrum:" + c)
        check(same(line.get_xydata(), np.column_stack([spectrum["frequency"],
                                                       spectrum[c] * factor[c]])),
              "spectrum: %s equals the spectrum file" % c)
        ax = line.axes
        fmax = ax.get_xlim()[1]
        peaks = [p for p in summary["peaks"][c] if p["frequency"] <= fmax]
        marks = artist(fig, "spectrum:%s:peaks" % c).get_xydata()
        check(len(peaks) >= 1 and same(marks, [[p["frequency"], p["amplitude"] * factor[c]]
                                               for p in peaks]),
              "spectrum: %s marks summary.json's %d peaks in its band" % (c, len(peaks)))
        texts = sorted(a.get_text() for a in ax.texts)
        check(texts == sorted(p["label"] for p in peaks if p["label"]),
              "spectrum: %s names them %s" % (c, texts))
    return summary, response


def case_run(args, plot):
    folder = os.path.join(args.work, "run")
    run_sim(args, "run", "--out", folder, *SHORT)
    result = plot_cli(args, folder)
    check(result.returncode == 0, "bearing-plot RUN_DIR exits 0 (%s)" % result.stderr.strip())
    out = os.path.join(folder, "plots")
    check_files(plot, out, ["time", "orbit", "spectrum"])
    check(sorted(result.stdout.split()) == sorted(os.path.join(out, n + ".png")
                                                  for n in ("time", "orbit", "spectrum")),
          "bearing-plot prints the files it wrote")
    check_run_data(plot, folder, plot.run_figures(plot.load_run(folder)))


def case_run_outputs(args, plot):
    folder = os.path.join(args.work, "run_outputs")
    run_sim(args, "run", "--out", folder, *SHORT,
            "--set", 'acoustics.microphones=[["0.1 m", "0 deg"], ["0.3 m", "-90 deg"]]',
            "--set", "output.envelope_band=auto", "--set", "output.ball_loads=true")
    out = os.path.join(args.work, "run_outputs_plots")
    result = plot_cli(args, folder, "--out", out)
    check(result.returncode == 0, "bearing-plot exits 0 (%s)" % result.stderr.strip())
    check_files(plot, out, ["time", "orbit", "spectrum", "envelope", "ball_loads", "spl"])
    figures = plot.run_figures(plot.load_run(folder))
    summary, response = check_run_data(plot, folder, figures)

    envelope = csv_columns(os.path.join(folder, "envelope.csv"))
    for c in ("ax", "ay"):
        check(same(artist(figures["envelope"], "envelope:" + c).get_xydata(),
                   np.column_stack([envelope["frequency"], envelope["env_" + c]])),
              "envelope: env_%s equals envelope.csv" % c)

    t = response["t"]
    steady = t >= summary["case"]["transient"]
    z = 8
    wc = 2 * math.pi * summary["frequencies"]["ftf"]
    for j in range(z):
        line = artist(figures["ball_loads"], "ball_loads:Q%d" % (j + 1))
        theta = 2 * math.pi * j / z + wc * t[steady]
        check(np.allclose(line.get_xdata(), theta, rtol=1e-14, atol=0)
              and same(line.get_ydata(), response["Q%d" % (j + 1)][steady]),
              "ball loads: Q%d against theta_j = 2 pi j/Z + w_c t equals response.csv" % (j + 1))

    pressure = csv_columns(os.path.join(folder, "pressure.csv"))
    for i, mic in enumerate(summary["acoustics"]["microphones"]):
        for key in ("spl_total", "spl_ring", "spl_balls"):
            bar = artist(figures["spl"], "spl:%s:%d" % (key, i + 1))
            check(bar.get_height() == mic[key], "spl: mic %d %s bar = summary.json's %.4g dB"
                  % (i + 1, key, mic[key]))
        line = artist(figures["spl"], "pressure:p%d" % (i + 1)).get_xydata()
        n = len(line)
        check(n > 10 and same(line, np.column_stack([pressure["t"][-n:],
                                                     pressure["p%d" % (i + 1)][-n:]])),
              "spl: p%d(t) equals the end of pressure.csv" % (i + 1))

    # The same run written as .npy: the same figures from the NumPy tables.
    npy = os.path.join(args.work, "run_npy")
    run_sim(args, "run", "--out", npy, *SHORT, "--set", "output.format=npy")
    check_run_data(plot, npy, plot.run_figures(plot.load_run(npy)), csv_format=False)
    # A rerun without the optional outputs into the same plots folder leaves no stale figures.
    run_sim(args, "run", "--out", folder, *SHORT)
    result = plot_cli(args, folder, "--out", out)
    check_files(plot, out, ["time", "orbit", "spectrum"])


def case_run_housing(args, plot):
    """A run with [housing]: the sensor figure draws response.csv's ay and ay_housing and
    spectrum.csv's, their energy shares are the spectra's own, and the orbit is the ring relative
    to the housing; the other figures as for any run."""
    folder = os.path.join(args.work, "run_housing")
    run_sim(args, "run", "--out", folder, *SHORT, "--set", "operation.load=[0, -500]",
            "--set", "housing.mass=1kg", "--set", "housing.frequency=3kHz")
    result = plot_cli(args, folder)
    check(result.returncode == 0, "bearing-plot exits 0 (%s)" % result.stderr.strip())
    check_files(plot, os.path.join(folder, "plots"), ["time", "orbit", "spectrum", "sensor"])
    figures = plot.run_figures(plot.load_run(folder))
    summary = json.load(open(os.path.join(folder, "summary.json")))
    response = csv_columns(os.path.join(folder, "response.csv"))
    spectrum = csv_columns(os.path.join(folder, "spectrum.csv"))
    factor = plot.DISPLAY["m/s^2"][1]
    t = response["t"]
    for c in ("ay", "ay_housing"):
        zoom = artist(figures["sensor"], "sensor_time:" + c).get_xydata()
        n = len(zoom)
        check(n > 10 and same(zoom, np.column_stack([t[-n:], response[c][-n:] * factor])),
              "sensor: %s over the last ball passes equals response.csv" % c)
        check(same(artist(figures["sensor"], "sensor_spectrum:" + c).get_xydata(),
                   np.column_stack([spectrum["frequency"], spectrum[c] * factor])),
              "sensor: the spectrum of %s equals spectrum.csv" % c)
        f, amplitude = spectrum["frequency"], spectrum[c]
        power = np.where(f > 0, amplitude ** 2, 0.0)
        share = artist(figures["sensor"], "sensor_energy:" + c).get_ydata()
        check(np.allclose(share, np.cumsum(power) / power.sum(), rtol=1e-12, atol=0),
              "sensor: the energy share of %s is the cumulative squared spectrum" % c)
    steady = t >= summary["case"]["transient"]
    um = plot.DISPLAY["m"][1]
    check(same(artist(figures["orbit"], "orbit").get_xydata(),
               np.column_stack([(response["x"] - response["x_housing"])[steady] * um,
                                (response["y"] - response["y_housing"])[steady] * um])),
          "orbit: with a housing, the ring relative to it")


# --- sweeps -----------------------------------------------------------------------------------

def case_sweep2(args, plot):
    folder = os.path.join(args.work, "sweep2")
    run_sim(args, "sweep", "--vary", "operation.speed=1000rpm:3000rpm:2",
            "--vary", "bearing.clearance=4um:14um:2", "--out", folder, *SHORT)
    result = plot_cli(args, folder)
    check(result.returncode == 0, "bearing-plot SWEEP_DIR exits 0 (%s)" % result.stderr.strip())
    check_files(plot, os.path.join(folder, "plots"), ["sweep_" + s for s in plot.STATISTICS])
    data = csv_columns_text(os.path.join(folder, "sweep.csv"))
    figures = plot.sweep_figures(plot.load_sweep(folder))
    speeds = sorted(set(data["operation.speed"]))
    clearances = sorted(set(data["bearing.clearance"]))
    for statistic in plot.STATISTICS:
        for c in ("x", "y", "vx", "vy", "ax", "ay"):
            column = "%s.%s" % (c, statistic)
            factor = plot.statistic_display(c, statistic)[1]
            grid = np.full((2, 2), np.nan)
            for s, p, v in zip(data["operation.speed"], data["bearing.clearance"], data[column]):
                grid[clearances.index(p), speeds.index(s)] = float(v) * factor
            mesh = artist(figures["sweep_" + statistic], "sweep:" + column)
            check(same(np.ma.filled(mesh.get_array(), np.nan).reshape(2, 2), grid),
                  "sweep (2 keys): heat map of %s equals sweep.csv" % column)
    ax = artist(figures["sweep_rms"], "sweep:ay.rms").axes
    rpm = 60 / (2 * math.pi)
    check([t.get_text() for t in ax.get_xticklabels()] == ["%.4g" % (s * rpm) for s in speeds],
          "sweep (2 keys): the x ticks name the speeds in rpm")


def csv_columns_text(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return {name: [float(r[i]) if name in ("operation.speed", "bearing.clearance") else r[i]
                   for r in rows[1:]] for i, name in enumerate(rows[0])}


def case_sweep1(args, plot):
    folder = os.path.join(args.work, "sweep1")
    run_sim(args, "sweep", "--vary", "operation.speed=1000rpm:3000rpm:3", "--out", folder,
            "--set", 'acoustics.microphones=[["0.1 m", "0 deg"]]', *SHORT)
    result = plot_cli(args, folder)
    check(result.returncode == 0, "bearing-plot SWEEP_DIR exits 0 (%s)" % result.stderr.strip())
    check_files(plot, os.path.join(folder, "plots"),
                ["sweep_" + s for s in plot.STATISTICS] + ["sweep_spl"])
    data = csv_columns(os.path.join(folder, "sweep.csv"))
    figures = plot.sweep_figures(plot.load_sweep(folder))
    x = data["operation.speed"] * plot.DISPLAY["rad/s"][1]
    for statistic in plot.STATISTICS:
        for c in ("x", "y", "vx", "vy", "ax", "ay"):
            column = "%s.%s" % (c, statistic)
            factor = plot.statistic_display(c, statistic)[1]
            line = artist(figures["sweep_" + statistic], "sweep:" + column)
            check(same(line.get_xydata(), np.column_stack([x, data[column] * factor])),
                  "sweep (1 key): %s against the speed in rpm equals sweep.csv" % column)
    for key in ("spl_total", "spl_ring", "spl_balls"):
        line = artist(figures["sweep_spl"], "sweep:mic1." + key)
        check(same(line.get_xydata(), np.column_stack([x, data["mic1." + key]])),
              "sweep (1 key): mic1.%s equals sweep.csv" % key)


# --- contact ----------------------------------------------------------------------------------

def check_contact(args, plot, folder, out):
    result = plot_cli(args, folder, "--out", out)
    check(result.returncode == 0, "bearing-plot CONTACT_DIR exits 0 (%s)" % result.stderr.strip())
    check_files(plot, out, ["force_approach"])
    data = csv_columns(os.path.join(folder, "force_approach.csv"))
    contact = json.load(open(os.path.join(folder, "contact.json")))
    fig = plot.contact_figure(plot.load_contact(folder))
    fe = artist(fig, "contact:fe")
    check(same(fe.get_xydata(), np.column_stack([data["approach"] * 1e6, data["force"]])),
          "contact: the FE points equal force_approach.csv (approach in µm)")
    check(fe.axes.get_xscale() == "log" and fe.axes.get_yscale() == "log", "contact: log axes")
    hertz = artist(fig, "contact:hertz").get_xydata()
    K = contact["hertz"]["K"]
    check(np.allclose(hertz[:, 1], K * (hertz[:, 0] / 1e6) ** 1.5, rtol=1e-12, atol=0)
          and hertz[0, 0] < data["approach"].min() * 1e6 < data["approach"].max() * 1e6
          < hertz[-1, 0], "contact: the Hertz line is Q = K delta^1.5 over the FE approaches")


def case_contact_example(args, plot):
    folder = os.path.join(args.source, "examples", "seed003_6308_calibration_inner")
    check_contact(args, plot, folder, os.path.join(args.work, "contact_example_plots"))


def case_contact_fem(args, plot):
    if not args.fem:
        print("SKIP: bearing-fem is not built (BEARING_WITH_FEM=OFF)")
        sys.exit(77)
    folder = os.path.join(args.work, "contact_fem")
    subprocess.run([args.fem, "contact", os.path.join(args.source, "examples", "seed003_6308.toml"),
                    "--race", "inner", "--out", folder, "--no-vtu", "--steps", "3",
                    "--cells", "4", "--grading", "3", "--quiet"], check=True,
                   stdout=subprocess.DEVNULL)
    check_contact(args, plot, folder, os.path.join(folder, "plots"))


# --- command line -----------------------------------------------------------------------------

def case_cli(args, plot):
    folder = os.path.join(args.work, "cli_run")
    run_sim(args, "run", "--out", folder, *SHORT)
    env = dict(os.environ, PYTHONPATH=args.python)
    for fmt in ("svg", "pdf"):
        out = os.path.join(args.work, "cli_" + fmt)
        result = subprocess.run([sys.executable, "-m", "bearing.plot", folder, "--out", out,
                                 "--format", fmt, "--quiet"], env=env, capture_output=True,
                                text=True)
        check(result.returncode == 0 and result.stdout == "",
              "python3 -m bearing.plot --format %s --quiet exits 0 silently (%s)"
              % (fmt, result.stderr.strip()))
        check_files(plot, out, ["time", "orbit", "spectrum"], fmt)
    # Not a folder it knows, and no folder at all: exit 2, the folder and what was expected named.
    empty = os.path.join(args.work, "cli_empty")
    os.makedirs(empty, exist_ok=True)
    for bad in (empty, os.path.join(args.work, "no_such_folder")):
        result = plot_cli(args, bad)
        check(result.returncode == 2 and bad in result.stderr and result.stdout == "",
              "bearing-plot %s: exit 2 naming the folder (%s)" % (bad, result.stderr.strip()))
    result = plot_cli(args, empty)
    check("summary.json" in result.stderr and "sweep.csv" in result.stderr
          and "force_approach.csv" in result.stderr, "the error says what a folder must hold")
    result = plot_cli(args, folder, "--format", "jpg")
    check(result.returncode == 2 and "png" in result.stderr, "--format jpg: exit 2, png named")
    # bearing.plot without the compiled extension (importing bearing._bearing fails here), by
    # both spellings a user writes; and the script beside a package without the extension.
    for statement in ("import bearing.plot", "from bearing import plot"):
        code = ("import sys; sys.modules['bearing._bearing'] = None\n%s\n"
                "assert 'matplotlib.pyplot' not in sys.modules, 'pyplot imported'\n"
                "print('imported')" % statement)
        result = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                                text=True)
        check(result.returncode == 0 and "imported" in result.stdout,
              "'%s' works without the compiled extension, and without pyplot (%s)"
              % (statement, result.stderr.strip()[-300:]))
    bare = os.path.join(args.work, "no_extension")
    shutil.copytree(args.python, bare, ignore=shutil.ignore_patterns("_bearing*", "CMakeFiles"))
    result = subprocess.run([os.path.join(bare, "bearing-plot"), folder, "--out",
                             os.path.join(args.work, "no_extension_plots")],
                            capture_output=True, text=True)
    check(result.returncode == 0, "bearing-plot runs without the compiled extension (%s)"
          % result.stderr.strip()[-300:])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("case")
    parser.add_argument("--sim", required=True)
    parser.add_argument("--python", required=True, help="build/python (the package and script)")
    parser.add_argument("--work", required=True)
    parser.add_argument("--source", default=os.path.join(os.path.dirname(__file__), "..", ".."))
    parser.add_argument("--fem", default="")
    args = parser.parse_args()
    sys.path.insert(0, args.python)
    plot = importlib.import_module("bearing.plot")
    args.work = os.path.join(args.work, args.case)
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    globals()["case_" + args.case](args, plot)
    if FAILURES:
        print("%d check(s) failed" % len(FAILURES))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
