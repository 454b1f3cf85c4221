"""The lumped model next to the CWRU test rig (examples/cwru/README.md; issues 29 and 40).

Runs the four cases of this folder (healthy, inner, ball, outer: the drive-end 6205 of the rig with
the records' 0.178 mm spalls) in three variants of what lies between the contacts and the sensor:

- ``resonator``: as written, the outer ring on one housing resonator (2 kg at 3.4 kHz), no slip —
  issue 29's comparison, kept as the reference the others change;
- ``resonator+slip``: the same with random slip of the cage, [slip] rms = 0.01 (Antoni & Randall's
  1-2 %, its lower end), the default correlation time (one ball pass), seed 1;
- ``shield+slip``: the outer ring in the example motor end shield's 20 FE modes
  (meshes/end_shield_6205.toml, computed by bearing-fem modes: end_shield_modes.json here), its
  sensor ``top`` at 12 o'clock on the hub (ay_top), every mode damped 5 %, with the same slip.

Each run's sensor channel is written as a record, and the twelve simulated and the four measured
records (tests/data/cwru/) are analysed by the same command, `bearing-sim analyse`, pre-whitened
(its default) and not. Writes OUT/table.md (numbers read from the summary.json files) and, with
matplotlib, one figure per condition OUT/cwru-<condition>.png. Run by Debian's /usr/bin/python3
(numpy, scipy; matplotlib for the figures):

    /usr/bin/python3 examples/cwru/compare.py [--sim build/lumped/bearing-sim] [--out out/cwru]
                                              [--modes examples/cwru/end_shield_modes.json]

The simulated record: the sensor channel after the run's transient, decimated from the run's 48 kHz
to the fault records' 12 kHz (scipy's zero-phase FIR anti-alias filter, as an acquisition filters
before it samples), plus white Gaussian noise at the healthy rig's broadband floor: the median
power spectral density of record 97 over 0-6 kHz (a median passes over the rig's lines). Without
it a noise-free simulation has no floor for the line-to-floor test to stand on. Nothing is fitted
to a record: every assumption is in the case files and the README, chosen before any simulated
record was analysed.
"""
import argparse
import json
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
from scipy import signal

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent
DATA = ROOT / "tests" / "data" / "cwru"
CASE_RATE = 48000.0   # the cases' solver.output_rate (checked against each run's summary.json)
SIM_RATE = 12000.0    # the rate the simulated records are written at: the fault records'
NOISE_BAND = 6000.0   # Hz: the fault records' band, where record 97's floor is measured

# condition: (record file, sampling rate [Hz], stored speed [rpm]) as tests/data/cwru/README.md
# gives them (the .npy files do not store them), and the fault family the condition is.
RECORDS = {
    "healthy": ("97_normal_0hp_DE.npy", 48000, 1796, None),
    "inner": ("105_IR007_0hp_DE.npy", 12000, 1797, "inner"),
    "ball": ("118_B007_0hp_DE.npy", 12000, 1796, "ball"),
    "outer": ("130_OR007at6_0hp_DE.npy", 12000, 1796, "outer"),
}
SLIP = ["--set", "slip.rms=0.01", "--set", "slip.seed=1"]
# variant: (the run's extra --set options, the FE housing or not, the sensor channel, what it is)
VARIANTS = {
    "resonator": ([], False, "ay_housing", "one resonator, no slip"),
    "resonator+slip": (SLIP, False, "ay_housing", "one resonator, slip 1 %"),
    "shield+slip": (SLIP, True, "ay_top", "end shield's FE modes, slip 1 %"),
}
G = 9.80665  # m/s^2 per g
# The first three harmonics' labels of each family (analyse's fault_lines[].lines[].label).
HARMONICS = {"outer": ["BPFO", "2xBPFO", "3xBPFO"], "inner": ["BPFI", "2xBPFI", "3xBPFI"],
             "ball": ["2xBSF", "4xBSF", "6xBSF"]}
GEOMETRY_RATIO = 0.3126 / 1.537  # D / d_m of the 6205 (tests/data/cwru/README.md), contact angle 0


def analyse(sim, record, rate, unit, rpm, out, prewhiten):
    """bearing-sim analyse of one record into out; returns its summary.json."""
    case = out.parent / "bearing.toml"
    case.parent.mkdir(parents=True, exist_ok=True)
    case.write_text('[bearing]\npreset = "6205"\n')
    cmd = [str(sim), "analyse", str(record), str(case), "--rate", str(rate), "--unit", unit,
           "--speed", "%drpm" % rpm, "--out", str(out), "--quiet"]
    if not prewhiten:
        cmd.append("--no-prewhiten")
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    return json.loads((out / "summary.json").read_text())


def rig_noise_floor():
    """Record 97's median PSD over 0 … NOISE_BAND [(m/s^2)^2/Hz]: the healthy rig's broadband floor."""
    x = np.load(DATA / RECORDS["healthy"][0]).astype(np.float64) * G
    f, p = signal.welch(x - x.mean(), fs=RECORDS["healthy"][1], nperseg=4096)
    return float(np.median(p[(f > 0) & (f < NOISE_BAND)]))


def shield_case(name, modes, out):
    """examples/cwru/<name>.toml with its [housing] resonator replaced by the end shield's modes."""
    text = (HERE / (name + ".toml")).read_text()
    table = ('[housing]\nmodes = "%s"\ndamping_ratio = 0.05\nsensors = ["top"]\n\n'
             % Path(modes).resolve())
    text, n = re.subn(r"\[housing\]\n(?:[^\[\n][^\n]*\n|\n)*", table, text)
    if n != 1:
        sys.exit("compare.py: %s.toml has no [housing] table to replace" % name)
    path = out / "cases" / ("%s-shield.toml" % name)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


def simulated_record(sim, name, variant, modes, out, noise_psd, seed):
    """Runs the condition's case in the variant; writes its sensor channel (+ noise) at SIM_RATE
    as out/records/<name>-<variant>.npy. Returns (path, the sensor's RMS without noise)."""
    sets, shield, channel, _ = VARIANTS[variant]
    case = shield_case(name, modes, out) if shield else HERE / (name + ".toml")
    run = out / "runs" / ("%s-%s" % (name, variant))
    subprocess.run([str(sim), "run", str(case), "--out", str(run), "--quiet", *sets],
                   check=True, stdout=subprocess.DEVNULL)
    summary = json.loads((run / "summary.json").read_text())
    if summary["case"]["output_rate"] != CASE_RATE:
        sys.exit("compare.py: %s.toml's output_rate is not %g Hz" % (name, CASE_RATE))
    columns = json.loads((run / "columns.json").read_text())["tables"]["response.npy"]["columns"]
    response = np.load(run / "response.npy")
    t, ay = response[:, 0], response[:, columns.index(channel)]
    ay = ay[t >= summary["case"]["transient"] - 0.5 / CASE_RATE]
    y = signal.decimate(ay, int(CASE_RATE / SIM_RATE), ftype="fir", zero_phase=True)
    sigma = np.sqrt(noise_psd * SIM_RATE / 2)  # white noise of that PSD up to Nyquist
    y = y + np.random.default_rng(seed).normal(0.0, sigma, y.size)
    path = out / "records" / ("%s-%s.npy" % (name, variant))
    path.parent.mkdir(parents=True, exist_ok=True)
    np.save(path, y)
    return path, float(np.std(ay))


def family_line(summary, family, harmonic=0):
    """The family's k-th harmonic line (frequency, SES amplitude) as analyse found it."""
    label = HARMONICS[family][harmonic]
    return next(l for l in summary["fault_lines"][family]["lines"] if l["label"] == label)


def _step(folder):
    freq = np.loadtxt(folder / "envelope.csv", delimiter=",", skiprows=1, usecols=0, max_rows=3)
    return float(freq[1] - freq[0])


def band(summary):
    lo, hi = next(iter(summary["envelope"].values()))["band"]
    return "%.2f–%.2f" % (lo / 1e3, hi / 1e3)


def diagnosis(summary):
    d = summary["diagnosis"]
    return d["family"] + ("" if d["family"] == "none" else " (+%.1f dB)" % d["margin"])


def harmonic_db(summary, family, k):
    """k-th over first harmonic of the family's SES lines [dB] (10 log10: the SES is a power)."""
    return 10 * np.log10(family_line(summary, family, k)["amplitude"] /
                         family_line(summary, family, 0)["amplitude"])


def line_cell(summary, family):
    lines = summary["fault_lines"][family]
    return "%.2f (%+.2f %%)%s" % (lines["carrier"], 100 * lines["offset"],
                                  "" if lines["detected"] else " not detected")


def tables(results, noise_psd, sigma, out):
    variants = list(VARIANTS)
    rows = ["Generated by examples/cwru/compare.py. Simulated: the sensor channel of "
            "examples/cwru/<condition>.toml in each variant (%s) at %.0f kHz plus white noise of "
            "%.3g (m/s²)²/Hz (record 97's median PSD over 0–%.0f kHz; %.3f m/s² RMS). Measured: "
            "tests/data/cwru/, in g × %.5f. Each analysed by `bearing-sim analyse` at the record's "
            "stored speed, pre-whitened (its default) unless a column says not." % (
                "; ".join("%s: %s" % (v, VARIANTS[v][3]) for v in variants), SIM_RATE / 1e3,
                noise_psd, NOISE_BAND / 1e3, sigma, G), ""]
    head = " | ".join(variants)
    rows += ["**Diagnosis** (pre-whitened; the margin over the threshold)", "",
             "| condition | measured | measured, not pre-whitened | %s | %s, not pre-whitened |"
             % (head, variants[0]), "| --- |" + " --- |" * (len(variants) + 3)]
    for name, r in results.items():
        rows.append("| %s | %s | %s | %s | %s |" % (
            name, diagnosis(r["measured"]["pw"]), diagnosis(r["measured"]["raw"]),
            " | ".join(diagnosis(r[v]["pw"]) for v in variants),
            diagnosis(r[variants[0]]["raw"])))
    rows += ["", "**Fault lines**: the rate at which analyse finds the condition's family in the "
             "squared envelope spectrum (pre-whitened; fault_lines.<family>.carrier, its comb fitted "
             "over 3 harmonics; offset from the kinematic rate). Contact angle: the one whose "
             "kinematics (D/d_m = 0.3126/1.537, Z = 9) give the measured rate", "",
             "| condition | line | kinematic [Hz] | measured [Hz] | %s | contact angle from the "
             "measured line |" % head, "| --- | --- | ---: | ---: |" + " ---: |" * len(variants) +
             " --- |"]
    for name, r in results.items():
        fam = RECORDS[name][3]
        if fam is None:
            rows.append("| %s | (none) | | |%s |" % (name, " |" * len(variants)))
            continue
        m = r["measured"]["pw"]["fault_lines"][fam]
        shaft = r["measured"]["pw"]["speed"]["shaft"]
        rows.append("| %s | %s | %.2f | %s | %s | %s |" % (
            name, HARMONICS[fam][0], m["nominal"], line_cell(r["measured"]["pw"], fam),
            " | ".join(line_cell(r[v]["pw"], fam) for v in variants),
            contact_angle(fam, m["carrier"] / shaft)))
    rows += ["", "**Harmonics** (the family's SES lines, pre-whitened: 10 log10 of 2×/1× and 3×/1×, "
             "dB; measured, then each variant)", "",
             "| condition | 2×/1×: measured | %s | 3×/1×: measured | %s |" % (head, head),
             "| --- |" + " ---: |" * (2 * len(variants) + 2)]
    for name, r in results.items():
        fam = RECORDS[name][3]
        if fam is None:
            continue
        cells = []
        for k in (1, 2):
            cells.append("%+.1f%s" % (harmonic_db(r["measured"]["pw"], fam, k),
                                      "" if r["measured"]["pw"]["fault_lines"][fam]["detected"]
                                      else " (not detected)"))
            cells += ["%+.1f" % harmonic_db(r[v]["pw"], fam, k) for v in variants]
        rows.append("| %s | %s |" % (name, " | ".join(cells)))
    rows += ["", "**Kurtogram band** (pre-whitened, kHz)", "",
             "| condition | measured | %s |" % head, "| --- |" + " --- |" * (len(variants) + 1)]
    for name, r in results.items():
        rows.append("| %s | %s | %s |" % (name, band(r["measured"]["pw"]),
                                          " | ".join(band(r[v]["pw"]) for v in variants)))
    rows += ["", "**Levels** (RMS over the analysed record, m/s²; simulated: the sensor without the "
             "added noise)", "", "| condition | measured | %s |" % head,
             "| --- |" + " ---: |" * (len(variants) + 1)]
    for name, r in results.items():
        rows.append("| %s | %.3g | %s |" % (
            name, r["measured"]["pw"]["channels"]["0"]["rms"],
            " | ".join("%.3g" % r[v]["sensor_rms"] for v in variants)))
    text = "\n".join(rows) + "\n"
    (out / "table.md").write_text(text)
    return text


def contact_angle(family, multiple):
    """The contact angle [deg] whose kinematics put the line at multiple x f_r (Z = 9)."""
    if family == "outer":
        ratio = 1 - multiple / 4.5
    elif family == "inner":
        ratio = multiple / 4.5 - 1
    else:
        return ""
    c = ratio / GEOMETRY_RATIO
    return "d cos α/d_m %.4f: α %.1f°" % (ratio, np.degrees(np.arccos(min(c, 1.0))))


def ses_db(folder, top):
    """(frequency, SES over its median floor in 5 Hz … top [dB]) of an analysis folder."""
    data = np.loadtxt(folder / "envelope.csv", delimiter=",", skiprows=1)
    f, ses = data[:, 0], data[:, 2]
    keep = f <= top
    floor = np.median(ses[(f > 5) & keep])
    return f[keep], 10 * np.log10(np.maximum(ses[keep], 1e-30) / floor)


def peak_hold(f, db, width):
    """The largest value in each run of `width` bins (a line of one bin stays visible when drawn)."""
    n = len(f) // width * width
    return f[:n].reshape(-1, width).mean(axis=1), db[:n].reshape(-1, width).max(axis=1)


# The figure's rows: who, the analysis, colour, title.
VIEWS = [("measured", "pw", "tab:blue", "measured"),
         ("resonator+slip", "pw", "tab:green", "model, one resonator, slip 1 %"),
         ("shield+slip", "pw", "tab:purple", "model, end shield's FE modes, slip 1 %")]


def figure(name, r, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fam = RECORDS[name][3]
    fams = [fam] if fam else ["outer", "inner", "ball"]
    top = 3.6 * max(family_line(r["measured"]["pw"], fm)["nominal"] for fm in fams)
    fig = plt.figure(figsize=(10, 9.5), constrained_layout=True)
    grid = fig.add_gridspec(len(VIEWS) + 1, 3)
    for row, (who, key, colour, title) in enumerate(VIEWS):
        ax = fig.add_subplot(grid[row, :])
        s, folder = r[who][key], r[who][key + "_dir"]
        f, db = peak_hold(*ses_db(folder, top), 5)
        ax.plot(f, db, lw=0.6, color=colour)
        for fm in fams:
            for k, label in enumerate(HARMONICS[fm]):
                x = family_line(s, fm, k)["frequency"]
                c = "tab:red" if s["fault_lines"][fm]["detected"] else "0.3"
                ax.axvline(x, color=c, ls=":", lw=0.8)
                ax.annotate(label, (x, 0.97), xycoords=("data", "axes fraction"), fontsize=7,
                            rotation=90, va="top", ha="right", color=c)
        fr = s["speed"]["shaft"]
        for k in range(1, int(top / fr) + 1):
            ax.axvline(k * fr, color="0.6", lw=0.4, alpha=0.5)
        record = RECORDS[name][0].split("_")[0] if who == "measured" else name + ".toml"
        ax.set_title("%s (%s, %.0f kHz, pre-whitened): band %s kHz (kurtogram); diagnosis %s" % (
            title, record, s["record"]["rate"] / 1e3, band(s), s["diagnosis"]["family"]),
            fontsize=9)
        ax.set_ylabel("SES / median [dB]")
        ax.set_xlim(0, top)
        ax.set_ylim(bottom=-5)
    ax.set_xlabel("frequency [Hz] (peak-held over 5 bins; grey: shaft harmonics f_r, 2 f_r, …; "
                  "dotted: the lines analyse found, red if their family is detected)", fontsize=8)
    # Zooms on the condition's 1x, 2x, 3x: every record at full resolution, the kinematic line.
    zoom_family = fam or "outer"
    for k in range(3):
        ax = fig.add_subplot(grid[len(VIEWS), k])
        nominal = family_line(r["measured"]["pw"], zoom_family, k)["nominal"]
        half = 0.012 * nominal
        for who, key, colour, _ in VIEWS:
            f, db = ses_db(r[who][key + "_dir"], top)
            sel = (f > nominal - half) & (f < nominal + half)
            ax.plot(f[sel] - nominal, db[sel], lw=0.8, color=colour, marker=".", ms=2, label=who)
        ax.axvline(0, color="k", ls="--", lw=0.8, label="kinematic (α = 0)")
        ax.set_title("%s = %.2f Hz" % (HARMONICS[zoom_family][k], nominal), fontsize=9)
        ax.set_xlabel("offset from the kinematic line [Hz]", fontsize=8)
        if k == 0:
            ax.set_ylabel("SES / median [dB]")
            ax.legend(fontsize=7, loc="upper left")
    fig.suptitle("CWRU %s: the rig's record and the model's, analysed by bearing-sim analyse "
                 "(squared envelope spectra, pre-whitened)" % name, fontsize=11)
    fig.savefig(out / ("cwru-%s.png" % name), dpi=80)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sim", default=str(ROOT / "build" / "lumped" / "bearing-sim"))
    parser.add_argument("--out", default=str(ROOT / "out" / "cwru"))
    parser.add_argument("--modes", default=str(HERE / "end_shield_modes.json"),
                        help="the end shield's modes.json (bearing-fem modes "
                             "meshes/end_shield_6205.toml)")
    args = parser.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    noise_psd = rig_noise_floor()
    sigma = float(np.sqrt(noise_psd * SIM_RATE / 2))
    results = {}
    for name, (file, rate, rpm, _) in RECORDS.items():
        number = int(file.split("_")[0])
        r = {"measured": {}}
        for key, pw in [("pw", True), ("raw", False)]:
            folder = out / "analyses" / ("%s-measured-%s" % (name, key))
            r["measured"][key] = analyse(args.sim, DATA / file, rate, "g", rpm, folder, pw)
            r["measured"][key + "_dir"] = folder
        for variant in VARIANTS:
            path, sensor_rms = simulated_record(args.sim, name, variant, args.modes, out,
                                                noise_psd, seed=number)
            r[variant] = {"sensor_rms": sensor_rms}
            for key, pw in [("pw", True), ("raw", False)]:
                folder = out / "analyses" / ("%s-%s-%s" % (name, variant, key))
                r[variant][key] = analyse(args.sim, path, int(SIM_RATE), "m/s^2", rpm, folder, pw)
                r[variant][key + "_dir"] = folder
        results[name] = r
    print(tables(results, noise_psd, sigma, out))
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        print("compare.py: no matplotlib for %s: table only" % sys.executable)
        return
    for name, r in results.items():
        figure(name, r, out)
    print("compare.py: wrote %s/table.md and cwru-{%s}.png" % (out, ",".join(results)))


if __name__ == "__main__":
    main()
