#!/usr/bin/python3
"""bearing-plot end to end: each kind of figure made from a small run, sweep or contact output;
the files exist, are images of the expected size, and the plotted data are the files' values
(read back from the figures' artists by their gid, not from pixels). Skipped (exit 77) when
/usr/bin/python3 has no matplotlib or numpy.

    test_plot.py CASE --sim BEARING_SIM --python BUILD/python --work DIR [--fem BEARING_FEM]
                 [--source SOURCE_DIR]

CASE: run (default case: time, orbit, spectrum), run_outputs (envelope, ball loads, acoustics,
output.format = "npy"), run_3dof (the 3-DOF model with an axial load: z, az in time,
spectrum and envelope), run_balls (seed 004's ball-DOF model with an axial load and every
per-ball output: z, az and the ball_channels figure), run_housing (the sensor figure of a case
with [housing]), run_modes (a bearing-fem modes folder's figure, and a run on its modes: the
sensor figure, the orbit relative to the seat), sweep2 (2 x 2: heat maps), sweep1 (one key
with acoustics: lines), contact_example (examples/seed003_6308_calibration_inner, a committed
bearing-fem output), contact_fem (a fresh bearing-fem contact run; needs --fem),
calibration_example (examples/seed003_6308_calibration.json and its race folders),
calibration_fem (a fresh bearing-fem calibrate; needs --fem), analysis (an analysed record
written by the compiled module's bearing.analyse: spectrum, envelope), report (the bearing-verify report's
figures: verification/plot_figures.py on a figures.json with every panel kind), cli (formats,
default --out, errors, import without the compiled extension), stiffness (bearing-sim
stiffness: a --vary grid's terms against the key, one point's as bars).
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


def check_files(plot, out, names, fmt="png", sizes=None):
    """Every expected figure file, non-empty, of its size in pixels (SIZES of its name, or
    `sizes` {name: inches}); nothing else of ours."""
    for name in names:
        path = os.path.join(out, "%s.%s" % (name, fmt))
        exists = os.path.isfile(path) and os.path.getsize(path) > 0
        check(exists, "%s written and not empty" % path)
        if not exists:
            continue
        kind = "sweep" if name.startswith("sweep_") else name
        inches = (sizes or {}).get(name) or plot.SIZES[kind]
        want = tuple(int(round(v * plot.DPI)) for v in inches)
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

def check_run_data(plot, folder, figures, csv_format=True,
                   channels=("x", "y", "ax", "ay")):
    """The time and spectrum figures draw exactly `channels` (the ring channels the model
    writes: x, y, ax, ay; 3-DOF also z, az), each equal to its file's column."""
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
    factor = {c: plot.DISPLAY[summary["channels"][c]["unit"]][1] for c in channels}

    fig = figures["time"]
    drawn = sorted(a.get_gid()[5:] for a in fig.findobj(
        lambda a: (a.get_gid() or "").startswith("time:")))
    check(drawn == sorted(channels), "time: draws %s (draws %s)" % (sorted(channels), drawn))
    for c in channels:
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
    drawn = sorted(a.get_gid()[9:] for a in fig.findobj(
        lambda a: (a.get_gid() or "").startswith("spectrum:")
        and not a.get_gid().endswith(":peaks")))
    check(drawn == sorted(channels), "spectrum: draws %s (draws %s)" % (sorted(channels), drawn))
    for c in channels:
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
    # The acoustics' ball source makes run write the ball motion r_j, vr_j: ball_channels.
    check_files(plot, out, ["time", "orbit", "spectrum", "envelope", "ball_loads", "ball_channels",
                            "spl"], sizes={"ball_channels": plot.ball_channels_size(1)})
    figures = plot.run_figures(plot.load_run(folder))
    summary, response = check_run_data(plot, folder, figures)
    for name, factor in [("r%d" % j, 1e6) for j in range(1, 9)] + [("vr%d" % j, 1e3)
                                                                   for j in range(1, 9)]:
        line = artist(figures["ball_channels"], "ball_channels:" + name).get_xydata()
        n = len(line)
        check(n > 10 and same(line, np.column_stack([response["t"][-n:],
                                                     response[name][-n:] * factor])),
              "ball_channels: %s is the end of response.csv's column x %g" % (name, factor))
    drawn = figures["ball_channels"].findobj(lambda a: (a.get_gid() or "").startswith("ball_"))
    check(len(drawn) == 16, "ball_channels: r1..r8 and vr1..vr8 and nothing else (%d lines)"
          % len(drawn))

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


def check_axial(plot, folder, figures, envelope=False):
    """z and az: their panels name the axial DOF and its unit; the envelope of az equals
    envelope.csv."""
    summary = json.load(open(os.path.join(folder, "summary.json")))
    for c, unit in (("z", "µm"), ("az", "m/s²")):
        trace = artist(figures["time"], "time:" + c).axes
        check(trace.get_ylabel().endswith("$%s$ [%s]" % ("a_z" if c == "az" else "z", unit)),
              "time: the %s panel's label names it and its unit (%r)" % (c, trace.get_ylabel()))
        spectrum = artist(figures["spectrum"], "spectrum:" + c).axes
        check(spectrum.get_title().startswith(c + ":") and unit in spectrum.get_ylabel(),
              "spectrum: the %s panel is titled %r, label %r"
              % (c, spectrum.get_title(), spectrum.get_ylabel()))
    check("axial z" in figures["time"]._suptitle.get_text(), "time: the title names the axial z")
    check("axial %.4g N" % summary["case"]["axial_load"] in figures["time"]._suptitle.get_text(),
          "time: the title gives the axial load")
    if envelope:
        data = csv_columns(os.path.join(folder, "envelope.csv"))
        check(same(artist(figures["envelope"], "envelope:az").get_xydata(),
                   np.column_stack([data["frequency"], data["env_az"]])),
              "envelope: env_az equals envelope.csv")


def case_run_3dof(args, plot):
    folder = os.path.join(args.work, "run_3dof")
    # The default 6308 under 20 N radial and 10 N axial (seed 001's 3-DOF case under its 10 N
    # preload hardly moves in 0.15 s: its y spectrum has no peak to check).
    run_sim(args, "run", "--out", folder, *SHORT, "--set", "model.kind=3dof",
            "--set", "operation.axial_load=10N", "--set", "output.envelope_band=auto")
    result = plot_cli(args, folder)
    check(result.returncode == 0, "bearing-plot 3-DOF RUN_DIR exits 0 (%s)"
          % result.stderr.strip())
    out = os.path.join(folder, "plots")
    check_files(plot, out, ["time", "orbit", "spectrum", "envelope"],
                sizes={"time": plot.SIZES["time_axial"],
                       "spectrum": plot.SIZES["spectrum_axial"]})
    figures = plot.run_figures(plot.load_run(folder))
    check_run_data(plot, folder, figures, channels=("x", "y", "z", "ax", "ay", "az"))
    check_axial(plot, folder, figures, envelope=True)


def case_run_balls(args, plot):
    folder = os.path.join(args.work, "run_balls")
    run_sim(args, "run", os.path.join(args.source, "examples", "seed004_6304.toml"),
            "--out", folder, *SHORT, "--set", "operation.axial_load=200N",
            "--set", "output.ball_loads=true", "--set", "output.ball_approach=true",
            "--set", "output.ball_motion=true", "--set", "output.ball_dynamics=true")
    result = plot_cli(args, folder)
    check(result.returncode == 0, "bearing-plot balls RUN_DIR exits 0 (%s)"
          % result.stderr.strip())
    response = csv_columns(os.path.join(folder, "response.csv"))
    summary = json.load(open(os.path.join(folder, "summary.json")))
    z = 7  # the 6304
    families = ["d", "r", "vr", "wb", "Qo", "Fi", "Fo"]
    check(all("%s%d" % (p, j) in response for p in families + ["Q"] for j in range(1, z + 1)),
          "the balls run wrote Q, %s for its %d balls" % (", ".join(families), z))
    out = os.path.join(folder, "plots")
    check_files(plot, out, ["time", "orbit", "spectrum", "ball_loads", "ball_channels"],
                sizes={"time": plot.SIZES["time_axial"],
                       "spectrum": plot.SIZES["spectrum_axial"],
                       "ball_channels": plot.ball_channels_size(4)})  # 7 panels, 2 a row
    figures = plot.run_figures(plot.load_run(folder))
    check_run_data(plot, folder, figures, channels=("x", "y", "z", "ax", "ay", "az"))
    check_axial(plot, folder, figures)
    fig = figures["ball_channels"]
    t = response["t"]
    # independent of bearing.plot: the SI unit of each family, shown as DISPLAY says
    units = {"d": "m", "r": "m", "vr": "m/s", "wb": "rad/s", "Qo": "N", "Fi": "N", "Fo": "N"}
    for p in families:
        unit = summary["channels"].get(p + "1", {}).get("unit", units[p])
        check(unit == units[p], "summary.json's unit of %s1 is %s" % (p, units[p]))
        shown, factor = plot.DISPLAY[unit]
        for j in range(1, z + 1):
            line = artist(fig, "ball_channels:%s%d" % (p, j)).get_xydata()
            n = len(line)
            check(n > 10 and same(line, np.column_stack([t[-n:], response["%s%d" % (p, j)][-n:]
                                                         * factor])),
                  "ball_channels: %s%d is the end of response.csv's column x %g" % (p, j, factor))
        ax = artist(fig, "ball_channels:%s1" % p).axes
        check(ax.get_ylabel().endswith("[%s]" % shown) and ax.get_title(),
              "ball_channels: the %s panel has a title and the unit %s (%r)"
              % (p, shown, ax.get_ylabel()))
    span = line[-1, 0] - line[0, 0]
    want = 2 * plot.BALL_PASSES_ZOOMED / summary["frequencies"]["bpfo"]
    check(abs(span - want) < 2 / 20000.0, "ball_channels: spans %d ball passes (%.4g s)"
          % (2 * plot.BALL_PASSES_ZOOMED, span))


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


MODES = {"format": "bearing-fem modes", "version": 1, "structure": "plate.toml",
         "boundary": {"free": False, "fixed": ["edge"]},
         "frequencies": [1800.0, 3100.0, 5200.0],
         "seat": {"x": [0.3, -0.2, 0.1], "y": [0.25, 0.4, -0.15], "z": [0.0, 0.01, 0.0],
                  "tilt_x": [0.0, 1.5, 0.0], "tilt_y": [2.0, 0.0, -1.0]},
         "sensors": [{"name": "top", "point": [0.0, 0.06, 0.0], "x": [0.1, 0.2, 0.3],
                      "y": [0.3, 0.2, 0.1], "z": [0.0, 0.0, 0.05]}],
         "mesh": {"elements": 1234, "dofs": 5678, "fe_degree": 2}}


def case_run_modes(args, plot):
    """A modes folder (bearing-fem modes' modes.json): the modes figure's bars are the file's
    seat translations, tilts and sensor shapes; a run on those modes ([housing] modes): the sensor
    figure draws ay and the sensor's ay_top with the structure's frequencies marked, the orbit is
    the ring relative to the seat (x - x_seat)."""
    modes_dir = os.path.join(args.work, "modes")
    os.makedirs(modes_dir)
    with open(os.path.join(modes_dir, "modes.json"), "w") as f:
        json.dump(MODES, f)
    result = plot_cli(args, modes_dir)
    check(result.returncode == 0, "bearing-plot exits 0 on a modes folder (%s)" % result.stderr)
    check_files(plot, os.path.join(modes_dir, "plots"), ["modes"],
                sizes={"modes": (13.0, 2.9 + 2.6 * 3)})
    fig = plot.modes_figure(plot.load_modes(modes_dir))
    for gid, values in (("modes_seat:x", MODES["seat"]["x"]), ("modes_seat:z", MODES["seat"]["z"]),
                        ("modes_tilt:tilt_y", MODES["seat"]["tilt_y"]),
                        ("modes_sensor_top:y", MODES["sensors"][0]["y"])):
        heights = [a.get_height() for a in fig.findobj(lambda a: a.get_gid() == gid)]
        check(heights == values, "modes: the bars %s are the file's %s" % (gid, values))

    folder = os.path.join(args.work, "run_modes")
    run_sim(args, "run", "--out", folder, *SHORT, "--set", "operation.load=[0, -500]",
            "--set", "housing.modes=" + os.path.join(modes_dir, "modes.json"))
    result = plot_cli(args, folder)
    check(result.returncode == 0, "bearing-plot exits 0 (%s)" % result.stderr.strip())
    check_files(plot, os.path.join(folder, "plots"), ["time", "orbit", "spectrum", "sensor"])
    figures = plot.run_figures(plot.load_run(folder))
    summary = json.load(open(os.path.join(folder, "summary.json")))
    response = csv_columns(os.path.join(folder, "response.csv"))
    t = response["t"]
    for c in ("ay", "ay_top"):
        zoom = artist(figures["sensor"], "sensor_time:" + c).get_xydata()
        n = len(zoom)
        check(n > 10 and same(zoom, np.column_stack([t[-n:], response[c][-n:]])),
              "sensor: %s over the last ball passes equals response.csv" % c)
    marked = sorted({round(line.get_xdata()[0], 6) for line in figures["sensor"].axes[2].lines
                     if line.get_linestyle() == ":"})
    fmax = figures["sensor"].axes[2].get_xlim()[1]
    check(marked == [f for f in MODES["frequencies"] if f <= fmax],
          "sensor: the structure's frequencies up to %.4g Hz are marked (%s)" % (fmax, marked))
    steady = t >= summary["case"]["transient"]
    um = plot.DISPLAY["m"][1]
    check(same(artist(figures["orbit"], "orbit").get_xydata(),
               np.column_stack([(response["x"] - response["x_seat"])[steady] * um,
                                (response["y"] - response["y_seat"])[steady] * um])),
          "orbit: on the structure's modes, the ring relative to the seat")


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


def case_stiffness(args, plot):
    """bearing-sim stiffness: a grid (lines against the varied key) and one point (bars)."""
    folder = os.path.join(args.work, "grid")
    run_sim(args, "stiffness", "--vary", "operation.axial_load=0:200:5", "--quiet", "--out", folder)
    result = plot_cli(args, folder)
    check(result.returncode == 0, "bearing-plot STIFFNESS_DIR exits 0 (%s)" % result.stderr.strip())
    check_files(plot, os.path.join(folder, "plots"), ["stiffness"])
    data = csv_columns(os.path.join(folder, "stiffness.csv"))
    fig = plot.stiffness_figure(plot.load_stiffness(folder))
    x = data["operation.axial_load [N]"]
    for name, unit in (("k_xx", "N/m"), ("k_yy", "N/m"), ("k_zz", "N/m"), ("k_gx_gx", "N*m/rad"),
                       ("k_gy_gy", "N*m/rad")):
        line = artist(fig, "stiffness:" + name)
        check(same(line.get_xydata(), np.column_stack([x, data["%s [%s]" % (name, unit)]])),
              "stiffness: %s against operation.axial_load equals stiffness.csv" % name)
    drawn = {a.get_gid()[len("stiffness:"):] for a in fig.findobj(
        lambda a: (a.get_gid() or "").startswith("stiffness:"))}
    couplings = sorted(n for n in drawn if n not in ("k_xx", "k_yy", "k_zz", "k_gx_gx", "k_gy_gy"))
    check(bool(couplings),
          "stiffness: the largest couplings drawn too (%s)" % ", ".join(couplings))
    check("k_xy" not in drawn, "stiffness: a coupling at round-off (k_xy) is not drawn")
    # The diagonal's range over one ball pass: a band from stiffness.json's min to its max.
    with open(os.path.join(folder, "stiffness.json")) as f:
        points = json.load(f)["points"]
    passes = [p["ball_pass"] for p in points]
    for i, name in enumerate(("k_xx", "k_yy", "k_zz", "k_gx_gx", "k_gy_gy")):
        # Its mean over the pass, the rotor's K: a dotted line through stiffness.json's values.
        mean = artist(fig, "rotor:" + name)
        check(same(mean.get_xydata(),
                   np.column_stack([x, [p["rotor"]["stiffness"][i][i] for p in points]])),
              "stiffness: %s's ball-pass mean is stiffness.json's rotor.stiffness" % name)
        lo = np.array([b["min"][i][i] for b in passes])
        hi = np.array([b["max"][i][i] for b in passes])
        band = artist(fig, "ball_pass:" + name)
        outline = band.get_paths()[0].vertices
        check(all(any(np.array_equal(v, [xi, y]) for v in outline)
                  for xi, a, b in zip(x, lo, hi) for y in (a, b)),
              "stiffness: %s's ball-pass band runs from stiffness.json's min to its max" % name)
        check(np.all(lo <= data["%s [%s]" % (name, plot.term_unit(i, i))]) and
              np.all(data["%s [%s]" % (name, plot.term_unit(i, i))] <= hi),
              "stiffness: %s lies in its ball-pass band" % name)
    check(passes[0]["max"][1][1] > passes[0]["min"][1][1],
          "stiffness: without a preload the band has a width")
    bare = os.path.join(args.work, "bare")
    run_sim(args, "stiffness", "--vary", "operation.axial_load=0:200:3", "--ball-pass", "0",
            "--quiet", "--out", bare)
    bare_fig = plot.stiffness_figure(plot.load_stiffness(bare))
    check(not bare_fig.findobj(lambda a: (a.get_gid() or "").startswith(("ball_pass:", "rotor:"))),
          "stiffness: --ball-pass 0, no band and no mean")
    one = os.path.join(args.work, "one")
    run_sim(args, "stiffness", "--set", "operation.axial_load=100", "--quiet", "--out", one)
    check(plot_cli(args, one).returncode == 0, "bearing-plot of one point exits 0")
    check_files(plot, os.path.join(one, "plots"), ["stiffness"])
    one_fig = plot.stiffness_figure(plot.load_stiffness(one))
    bar = artist(one_fig, "stiffness:k_zz")
    check(bar.get_height() == csv_columns(os.path.join(one, "stiffness.csv"))["k_zz [N/m]"][0],
          "stiffness (one point): the k_zz bar is stiffness.csv's value")
    with open(os.path.join(one, "stiffness.json")) as f:
        one_pass = json.load(f)["points"][0]["ball_pass"]
    segment = artist(one_fig, "ball_pass:k_zz").get_segments()[0]
    check(same(segment[:, 1], [one_pass["min"][2][2], one_pass["max"][2][2]]),
          "stiffness (one point): k_zz's ball-pass bar spans stiffness.json's min to max")
    check(same(artist(one_fig, "rotor:k_zz").get_ydata(), [one_pass["mean"][2][2]]),
          "stiffness (one point): k_zz's diamond is its ball-pass mean")
    # With [lubricant]: the damping's row, C at the cage angle and its mean, the rotor's C.
    oil = os.path.join(args.work, "oil")
    run_sim(args, "stiffness", "--vary", "operation.speed=1000rpm:3000rpm:3",
            "--set", "lubricant.viscosity=0.02 Pa s", "--set", "lubricant.pressure_viscosity=2e-8 1/Pa",
            "--set", "lubricant.roughness=0.1 um", "--quiet", "--out", oil)
    oil_fig = plot.stiffness_figure(plot.load_stiffness(oil))
    oil_data = csv_columns(os.path.join(oil, "stiffness.csv"))
    with open(os.path.join(oil, "stiffness.json")) as f:
        oil_points = json.load(f)["points"]
    line = artist(oil_fig, "damping:c_yy")
    check(same(np.sort(line.get_ydata()), np.sort(oil_data["c_yy [N*s/m]"])),
          "stiffness with [lubricant]: c_yy is stiffness.csv's")
    check(same(np.sort(artist(oil_fig, "rotor:c_yy").get_ydata()),
               np.sort([p["rotor"]["damping"][1][1] for p in oil_points])),
          "stiffness with [lubricant]: c_yy's dotted mean is stiffness.json's rotor.damping")


# --- contact ----------------------------------------------------------------------------------

def outer_fault_record(rate=12000.0, seconds=3.0):
    """Outer-race impacts of the 6205 at 1797 rpm (BPFO, 1 % jitter) ringing 3 kHz, in noise."""
    rng = np.random.default_rng(3)
    bpfo = 3.5848 * 1797 / 60
    t = np.arange(int(seconds * rate)) / rate
    x = 0.5 * rng.standard_normal(t.size) + 0.4 * np.sin(2 * np.pi * 1797 / 60 * t)
    for j in range(int(seconds * bpfo)):
        d = t - (j + 0.01 * rng.standard_normal()) / bpfo
        ring = d >= 0
        x[ring] += np.exp(-565 * d[ring]) * np.sin(2 * np.pi * 3000 * d[ring])
    return x


def case_analysis(args, plot):
    """An analysed record (bearing.analyse(...).write, as bearing-sim analyse writes it), CSV and
    .npy: spectrum and envelope figures, their data the files' (the squared envelope spectrum and
    each family's rated lines included)."""
    try:
        import bearing
        if bearing._bearing is None:
            raise ImportError(bearing._import_error)
    except ImportError as e:
        print("SKIP: the compiled module bearing is needed to write an analysis (%s)" % e)
        sys.exit(77)
    case = bearing.Case.from_toml('[bearing]\npreset = "6205"\n[operation]\nspeed = "1797 rpm"\n')
    analysis = bearing.analyse(outer_fault_record(), 12000, case, channel="DE", file="rig.mat")
    sizes = {"spectrum": plot.SIZES["record_spectrum"], "envelope": plot.SIZES["record_envelope"],
             "coherence": plot.SIZES["record_coherence"]}
    for fmt in ("csv", "npy"):
        folder = os.path.join(args.work, "analysis_" + fmt)
        analysis.write(folder, fmt)
        check(plot.detect(folder) == "analysis", "%s is recognised as an analysed record" % folder)
        result = plot_cli(args, folder)
        check(result.returncode == 0, "bearing-plot ANALYSIS_DIR exits 0 (%s)"
              % result.stderr.strip()[-300:])
        check_files(plot, os.path.join(folder, "plots"), ["spectrum", "envelope", "coherence"],
                    sizes=sizes)
        figures = plot.record_figures(plot.load_analysis(folder))
        spectrum = plot.read_table(folder, "spectrum")
        envelope = plot.read_table(folder, "envelope")
        check(same(artist(figures["spectrum"], "spectrum:DE").get_ydata(), spectrum["DE"]),
              "%s: the spectrum drawn is spectrum.%s's DE" % (fmt, fmt))
        check(same(artist(figures["envelope"], "envelope:DE").get_ydata(), envelope["env_DE"]),
              "%s: the envelope spectrum drawn is env_DE" % fmt)
        check(same(artist(figures["envelope"], "ses").get_ydata(), envelope["ses_DE"]),
              "%s: the squared envelope spectrum drawn is ses_DE" % fmt)
        summary = json.load(open(os.path.join(folder, "summary.json")))
        outer = [l for l in summary["fault_lines"]["outer"]["lines"]
                 if l["rated"] and not l["excluded"]]
        check(same(artist(figures["envelope"], "ses:outer").get_xdata(),
                   [l["frequency"] for l in outer]), "%s: the outer race's lines marked" % fmt)
        check(summary["diagnosis"]["family"] == "outer", "the synthetic outer fault is named")
        # The coherence figure: each band of the map coloured by summary.json's margin, each
        # family's three harmonic bars its excess.
        coherence = summary["coherence"]
        fig = figures["coherence"]
        for family in ("outer", "inner", "ball"):
            bars = [p.get_height() for p in fig.findobj(lambda o: o.get_gid() == "lines:" + family)]
            check(same(bars, [h["excess"] for h in coherence["families"][family]["harmonics"]]),
                  "%s: %s's bars are its harmonics' excess in its best band" % (fmt, family))
            cells = fig.findobj(lambda o: (o.get_gid() or "").startswith("map:%s:" % family))
            check(len(cells) == len(coherence["bands"]),
                  "%s: one cell a band in %s's map" % (fmt, family))


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


# --- calibration ------------------------------------------------------------------------------

def check_calibration(args, plot, path, out=None, races_present=("inner", "outer")):
    """bearing-plot on a calibration (its JSON file, or a folder holding it): the figure's data
    are the JSON's laws and the race folders' force_approach.csv, read here independently."""
    result = plot_cli(args, path, *(["--out", out] if out else []))
    check(result.returncode == 0, "bearing-plot %s exits 0 (%s)" % (path, result.stderr.strip()))
    out = out or (os.path.splitext(path)[0] + "_plots" if os.path.isfile(path)
                  else os.path.join(path, "plots"))
    check_files(plot, out, ["calibration"])
    file = path if os.path.isfile(path) else os.path.join(
        path, next(f for f in os.listdir(path) if f.endswith(".json")))
    cal = json.load(open(file))
    fig = plot.calibration_figure(plot.load_calibration(path))
    lo, hi = cal["load_range"]
    for race in ("inner", "outer"):
        K, n, KH = cal[race]["K"], cal[race]["exponent"], cal[race]["hertz_K"]
        fit = artist(fig, "calibration:%s:fit" % race)
        x = fit.get_xdata() / 1e6
        check(np.allclose(fit.get_ydata(), K * x ** n, rtol=1e-12, atol=0),
              "calibration %s: the dashed law is the JSON's Q = %.5g delta^%.5g" % (race, K, n))
        hertz = artist(fig, "calibration:%s:hertz" % race)
        check(np.allclose(hertz.get_ydata(), KH * (hertz.get_xdata() / 1e6) ** 1.5, rtol=1e-12,
                          atol=0), "calibration %s: the solid law is Hertz's K_H delta^1.5" % race)
        ax = fit.axes
        check(ax.get_xscale() == "log" and ax.get_yscale() == "log"
              and "[µm]" in ax.get_xlabel() and "[N]" in ax.get_ylabel(),
              "calibration %s: log axes, approach in µm, force in N" % race)
        check(ax.get_title().startswith(race + " race: K = %.5g" % K),
              "calibration %s: the title gives K (%r)" % (race, ax.get_title()))
        law = artist(fig, "calibration:departure:%s:fit" % race).get_xydata()
        delta = (law[:, 0] / K) ** (1 / n)
        check(math.isclose(law[0, 0], lo) and math.isclose(law[-1, 0], hi)
              and np.allclose(law[:, 1], 100 * (law[:, 0] / (KH * delta ** 1.5) - 1),
                              rtol=1e-9, atol=1e-12),
              "calibration %s: the departure of the law from Hertz over %.4g-%.4g N" % (race, lo,
                                                                                       hi))
        found = fig.findobj(lambda a: a.get_gid() == "calibration:%s:fe" % race)
        if race not in races_present:
            check(not found and "not found" in ax.get_title(),
                  "calibration %s: no FE points, and the title says the folder is missing" % race)
            continue
        curve = csv_columns(os.path.join(os.path.dirname(file), cal[race]["details"],
                                         "force_approach.csv"))
        check(len(found) == 1 and same(found[0].get_xydata(), np.column_stack(
            [curve["approach"] * 1e6, curve["force"]])),
              "calibration %s: the FE points equal %s/force_approach.csv" % (race,
                                                                            cal[race]["details"]))
        points = artist(fig, "calibration:departure:%s:fe" % race).get_xydata()
        check(same(points[:, 0], curve["force"]) and np.allclose(
            points[:, 1], 100 * (curve["force"] / (KH * curve["approach"] ** 1.5) - 1),
            rtol=1e-12, atol=1e-12), "calibration %s: the FE points' departure from Hertz" % race)
    return fig


def copy_calibration(source_json, folder, stem):
    """The calibration file and its race folders copied into `folder` as STEM.json, STEM_inner,
    STEM_outer (the details names rewritten): a calibrate output in a scratch place."""
    os.makedirs(folder, exist_ok=True)
    cal = json.load(open(source_json))
    for race in ("inner", "outer"):
        shutil.copytree(os.path.join(os.path.dirname(source_json), cal[race]["details"]),
                        os.path.join(folder, "%s_%s" % (stem, race)))
        cal[race]["details"] = "%s_%s" % (stem, race)
    path = os.path.join(folder, stem + ".json")
    json.dump(cal, open(path, "w"), indent=1)
    return path


def case_calibration_example(args, plot):
    example = os.path.join(args.source, "examples", "seed003_6308_calibration.json")
    check_calibration(args, plot, example, os.path.join(args.work, "example_plots"))
    # The default --out of a file DIR/STEM.json is DIR/STEM_plots, beside DIR/STEM_inner, _outer.
    copy = copy_calibration(example, os.path.join(args.work, "copy"), "cal")
    check_calibration(args, plot, copy)
    # A folder holding one calibration (as bearing-verify calibrate writes) is one too.
    check_calibration(args, plot, os.path.join(args.work, "copy"))
    # Without a race's folder: the laws alone, and the title says which folder is missing.
    shutil.rmtree(os.path.join(args.work, "copy", "cal_outer"))
    check_calibration(args, plot, copy, os.path.join(args.work, "no_outer"),
                      races_present=("inner",))
    # A JSON that is not a calibration, and a calibration with a bad K: exit 2, the file named.
    other = os.path.join(args.source, "examples", "seed003_6308_calibration_inner", "contact.json")
    result = plot_cli(args, other, "--out", os.path.join(args.work, "bad"))
    check(result.returncode == 2 and other in result.stderr and "calibration" in result.stderr,
          "bearing-plot contact.json (not a calibration): exit 2 (%s)" % result.stderr.strip())
    cal = json.load(open(copy))
    cal["outer"]["K"] = -1.0
    json.dump(cal, open(copy, "w"))
    result = plot_cli(args, copy, "--out", os.path.join(args.work, "bad"))
    check(result.returncode == 2 and "outer.K" in result.stderr and "-1" in result.stderr,
          "a calibration with outer.K = -1: exit 2 naming the field (%s)" % result.stderr.strip())


def case_calibration_fem(args, plot):
    if not args.fem:
        print("SKIP: bearing-fem is not built (BEARING_WITH_FEM=OFF)")
        sys.exit(77)
    path = os.path.join(args.work, "cal", "6308.json")
    subprocess.run([args.fem, "calibrate", os.path.join(args.source, "examples",
                                                        "seed003_6308.toml"),
                    "--out", path, "--cells", "4", "--grading", "3", "--quiet"], check=True,
                   stdout=subprocess.DEVNULL)
    check_calibration(args, plot, path)


# --- the bearing-verify report ----------------------------------------------------------------

REPORT_FIGURES = [  # one per panel kind, in SI as bearing-verify writes them
    {"name": "series-log", "title": "Energy drift of an undamped run (RK4) against the step",
     "x_label": "dt [s]", "y_label": "max|E - E0| / max kinetic energy [-]", "log_x": True,
     "log_y": True, "panel": "series", "laws": [],
     "series": [{"label": "measured drift", "x": [2e-5, 1e-5, 5e-6], "y": [1e-6, 6e-8, 4e-9],
                 "style": "line+marker"},
                {"label": "RK4 bound", "x": [2e-5, 1e-5, 5e-6], "y": [2e-6, 1.2e-7, 8e-9],
                 "style": "line"},
                {"label": "", "x": [1e-5], "y": [3e-7], "style": "marker"}],
     "markers": [{"x": 1e-5, "label": "dt = 10 us"}]},
    {"name": "spectrum", "title": "y spectrum: largest line against the reference and the paper",
     "x_label": "frequency [Hz]", "y_label": "y amplitude [m]", "log_x": False, "log_y": True,
     "panel": "spectrum", "laws": [],
     "series": [{"label": "y amplitude", "x": list(range(1, 41)),
                 "y": [1e-9 if k in (10, 30) else 1e-12 for k in range(1, 41)],
                 "style": "line"}],
     "markers": [{"x": 10.0, "label": "reference"}, {"x": 10.4, "label": "paper"}]},
    {"name": "trace", "title": "Free decay of the 6308 at rest, 300 N, 1 nm release",
     "x_label": "t [s]", "y_label": "y - y_eq [m]", "log_x": False, "log_y": False,
     "panel": "trace", "laws": [], "markers": [],
     "series": [{"label": "closed form", "x": [0.0, 1e-4, 2e-4, 3e-4],
                 "y": [1e-9, -6e-10, 3e-10, -1e-10], "style": "line"},
                {"label": "model", "x": [0.0, 1e-4, 2e-4, 3e-4],
                 "y": [1e-9, -5.9e-10, 3e-10, -1.1e-10], "style": "line"}]},
    {"name": "force-approach", "title": "6308 inner race: FE block against the lumped law",
     "x_label": "approach delta [m]", "y_label": "force F [N]", "log_x": True, "log_y": True,
     "panel": "force_approach", "markers": [],
     "series": [{"label": "FE Hertz-reduced block", "x": [1.5e-7, 3.7e-7, 6.9e-7],
                 "y": [2.0, 8.0, 20.1], "style": "marker"}],
     "laws": [{"label": "lumped exact Hertz", "K": 3.5e10, "exponent": 1.5},
              {"label": "a second law", "K": 3.6e10, "exponent": 1.502}]},
]


def case_report(args, plot):
    figures_json = os.path.join(args.work, "figures.json")
    json.dump(REPORT_FIGURES, open(figures_json, "w"))
    script = os.path.join(args.source, "verification", "plot_figures.py")
    # As bearing-verify runs it: Debian's python, no PYTHONPATH (it finds python/ itself).
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    result = subprocess.run(["/usr/bin/python3", script, figures_json, args.work], env=env,
                            capture_output=True, text=True)
    check(result.returncode == 0, "plot_figures.py exits 0 (%s)" % result.stderr.strip()[-400:])
    want = tuple(int(round(v * plot.DPI)) for v in plot.SIZES["report"])
    for spec in REPORT_FIGURES:
        path = os.path.join(args.work, spec["name"] + ".png")
        check(png_size(path) == want, "%s is bearing.plot's report size %s px (is %s)"
              % (path, want, png_size(path)))
    for spec in REPORT_FIGURES:
        fig = plot.report_figure(spec)
        ax = fig.axes[0]
        name, panel = spec["name"], spec["panel"]
        check(ax.get_title() == spec["title"], "%s: titled %r" % (name, spec["title"]))
        if panel == "force_approach":
            law = spec["laws"]
            points = artist(fig, "report:fe").get_xydata()
            check(same(points, np.column_stack([np.array(spec["series"][0]["x"]) * 1e6,
                                                spec["series"][0]["y"]])),
                  "%s: the points are the series (approach in µm)" % name)
            for gid, (K, n) in (("report:hertz", (law[0]["K"], law[0]["exponent"])),
                                ("report:fit", (law[1]["K"], law[1]["exponent"]))):
                line = artist(fig, gid)
                check(np.allclose(line.get_ydata(), K * (line.get_xdata() / 1e6) ** n,
                                  rtol=1e-12, atol=0), "%s: %s is Q = %g delta^%g" % (name, gid,
                                                                                     K, n))
            legend = [t.get_text() for t in ax.get_legend().get_texts()]
            check(legend[0] == "FE Hertz-reduced block" and legend[1].startswith(
                "lumped exact Hertz") and legend[2].startswith("a second law"),
                  "%s: the legend names the points and the laws (%s)" % (name, legend))
            check("[µm]" in ax.get_xlabel() and "[N]" in ax.get_ylabel(),
                  "%s: approach in µm, force in N" % name)
            continue
        # series, spectrum, trace: every series' data (y in display units for the vibration
        # panels: m -> µm), in order
        factor = 1e6 if panel in ("spectrum", "trace") else 1.0
        for i, s in enumerate(spec["series"]):
            check(same(artist(fig, "report:%d" % i).get_xydata(),
                       np.column_stack([s["x"], np.array(s["y"]) * factor])),
                  "%s: series %d (%s) is the spec's x, y x %g" % (name, i, s["label"], factor))
        check(ax.get_xlabel() == spec["x_label"], "%s: x label %r" % (name, spec["x_label"]))
        ylabel = spec["y_label"].replace("[m]", "[µm]")
        check(ax.get_ylabel() == ylabel, "%s: y label %r (is %r)" % (name, ylabel,
                                                                    ax.get_ylabel()))
        check(ax.get_xscale() == ("log" if spec["log_x"] else "linear")
              and ax.get_yscale() == ("log" if spec["log_y"] else "linear"),
              "%s: the axes' scales are the spec's" % name)
        for m in spec["markers"]:
            line = artist(fig, "report:line:" + m["label"])
            check(same(line.get_xdata(), [m["x"], m["x"]])
                  and m["label"] in [t.get_text() for t in ax.texts],
                  "%s: a vertical line at %g named %r" % (name, m["x"], m["label"]))
        labelled = [s["label"] for s in spec["series"] if s["label"]]
        if panel == "spectrum" and len(spec["series"]) == 1:
            labelled = []  # one spectrum: its y label names it
        legend = [t.get_text() for t in ax.get_legend().get_texts()] if ax.get_legend() else []
        check(legend == labelled, "%s: the legend is %s (is %s)" % (name, labelled, legend))
    try:
        plot.report_figure(dict(REPORT_FIGURES[0], panel="pie"))
        check(False, "an unknown panel is refused")
    except plot.FolderError as e:
        check("pie" in str(e) and "series" in str(e), "an unknown panel is refused: %s" % e)


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
