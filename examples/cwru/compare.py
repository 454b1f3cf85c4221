"""The lumped model next to the CWRU test rig (examples/cwru/README.md; issue 29).

Runs the four cases of this folder (healthy, inner, ball, outer: the drive-end 6205 of the rig with
the records' 0.178 mm spalls, on a housing resonator), writes each run's sensor channel ay_housing
as a record, and analyses the four simulated and the four measured records (tests/data/cwru/) with
the same command, `bearing-sim analyse`. Writes OUT/table.md (numbers read from the summary.json
files) and, with matplotlib, one figure per condition OUT/cwru-<condition>.png. Run by Debian's
/usr/bin/python3 (numpy, scipy; matplotlib for the figures):

    /usr/bin/python3 examples/cwru/compare.py [--sim build/lumped/bearing-sim] [--out out/cwru]

The simulated record: ay_housing after the run's transient, decimated from the run's 48 kHz to the
fault records' 12 kHz (scipy's zero-phase FIR anti-alias filter, as an acquisition filters before
it samples), plus white Gaussian noise at the healthy rig's broadband floor: the median power
spectral density of record 97 over 0-6 kHz (a median passes over the rig's lines). Without it a
noise-free simulation has no floor for the line-to-floor test to stand on.

Each record is analysed twice: pre-whitened (analyse's default, the benchmark's first step) and
not (--no-prewhiten). The model's impacts are exactly periodic (no random slip), so pre-whitening
takes them away with the other discrete lines; see the README.
"""
import argparse
import json
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


def simulated_record(sim, name, out, noise_psd, seed):
    """Runs examples/cwru/<name>.toml; writes ay_housing (+ noise) at SIM_RATE as out/<name>.npy."""
    run = out / "runs" / name
    subprocess.run([str(sim), "run", str(HERE / (name + ".toml")), "--out", str(run), "--quiet"],
                   check=True, stdout=subprocess.DEVNULL)
    summary = json.loads((run / "summary.json").read_text())
    if summary["case"]["output_rate"] != CASE_RATE:
        sys.exit("compare.py: %s.toml's output_rate is not %g Hz" % (name, CASE_RATE))
    columns = json.loads((run / "columns.json").read_text())["tables"]["response.npy"]["columns"]
    response = np.load(run / "response.npy")
    t, ay = response[:, 0], response[:, columns.index("ay_housing")]
    ay = ay[t >= summary["case"]["transient"] - 0.5 / CASE_RATE]
    y = signal.decimate(ay, int(CASE_RATE / SIM_RATE), ftype="fir", zero_phase=True)
    sigma = np.sqrt(noise_psd * SIM_RATE / 2)  # white noise of that PSD up to Nyquist
    y = y + np.random.default_rng(seed).normal(0.0, sigma, y.size)
    path = out / "records" / (name + ".npy")
    path.parent.mkdir(parents=True, exist_ok=True)
    np.save(path, y)
    return path, summary, float(np.std(ay))


def family_line(summary, family, harmonic=0):
    """The family's k-th harmonic line (frequency, SES amplitude) as analyse found it."""
    label = HARMONICS[family][harmonic]
    return next(l for l in summary["fault_lines"][family]["lines"] if l["label"] == label)


def _step(folder):
    freq = np.loadtxt(folder / "envelope.csv", delimiter=",", skiprows=1, usecols=0, max_rows=3)
    return float(freq[1] - freq[0])


def band(summary):
    lo, hi = next(iter(summary["envelope"].values()))["band"]
    return "%.2f–%.2f kHz" % (lo / 1e3, hi / 1e3)


def diagnosis(summary):
    d = summary["diagnosis"]
    return d["family"] + ("" if d["family"] == "none" else " (+%.1f dB)" % d["margin"])


def harmonic_db(summary, family, k):
    """k-th over first harmonic of the family's SES lines [dB] (10 log10: the SES is a power)."""
    return 10 * np.log10(family_line(summary, family, k)["amplitude"] /
                         family_line(summary, family, 0)["amplitude"])


def tables(results, noise_psd, sigma, out):
    rows = ["Generated by examples/cwru/compare.py. Simulated: ay_housing of examples/cwru/<condition>.toml "
            "at %.0f kHz plus white noise of %.3g (m/s²)²/Hz (record 97's median PSD over 0–%.0f kHz; "
            "%.3f m/s² RMS). Measured: tests/data/cwru/, in g × %.5f. Each analysed by `bearing-sim "
            "analyse` at the record's stored speed." % (SIM_RATE / 1e3, noise_psd, NOISE_BAND / 1e3,
                                                          sigma, G), ""]
    rows += ["**Fault lines**: the rate at which analyse finds the condition's family in the squared "
             "envelope spectrum (fault_lines.<family>.carrier, its comb fitted over 3 harmonics; "
             "offset from the kinematic rate), pre-whitened for the measured record, not for the "
             "simulated one; bin = the measured record's SES bin. Contact angle: the one whose "
             "kinematics (D/d_m = 0.3126/1.537, Z = 9) give the measured rate", "",
             "| condition | record | line | kinematic [Hz] | measured [Hz] (offset) | simulated [Hz] "
             "(offset) | measured − simulated | contact angle from the measured line |",
             "| --- | --- | --- | ---: | ---: | ---: | ---: | ---: |"]
    for name, r in results.items():
        fam = RECORDS[name][3]
        if fam is None:
            rows.append("| %s | %s | (none) | | | | | |" % (name, RECORDS[name][0].split("_")[0]))
            continue
        m, s = r["measured"]["pw"]["fault_lines"][fam], r["simulated"]["raw"]["fault_lines"][fam]
        step = r["measured"]["bin"]
        gap = m["carrier"] - s["carrier"]
        shaft = r["measured"]["pw"]["speed"]["shaft"]
        rows.append("| %s | %s | %s | %.2f | %.2f (%+.2f %%)%s | %.2f (%+.2f %%)%s | %+.2f Hz = %+.1f "
                    "bins of %.4f Hz | %s |" % (
                        name, RECORDS[name][0].split("_")[0], HARMONICS[fam][0], m["nominal"],
                        m["carrier"], 100 * m["offset"], "" if m["detected"] else " not detected",
                        s["carrier"], 100 * s["offset"], "" if s["detected"] else " not detected",
                        gap, gap / step, step, contact_angle(fam, m["carrier"] / shaft)))
    rows += ["", "**Diagnosis, harmonics, band** (measured / simulated; pre-whitened = analyse's "
             "default; 2×/1×, 3×/1×: the family's SES lines, 10 log10 of the amplitude ratio)", "",
             "| condition | measured: pre-whitened | measured: not | simulated: not pre-whitened | "
             "simulated: pre-whitened | 2×/1× [dB] meas / sim | 3×/1× [dB] meas / sim | "
             "kurtogram band: measured (pre-whitened) | simulated (not pre-whitened) |",
             "| --- | --- | --- | --- | --- | ---: | ---: | --- | --- |"]
    for name, r in results.items():
        fam = RECORDS[name][3]
        m, s = r["measured"], r["simulated"]
        h2 = h3 = ""
        if fam is not None:
            nd = "" if m["pw"]["fault_lines"][fam]["detected"] else " (measured: not detected)"
            h2 = "%+.1f / %+.1f%s" % (harmonic_db(m["pw"], fam, 1), harmonic_db(s["raw"], fam, 1), nd)
            h3 = "%+.1f / %+.1f" % (harmonic_db(m["pw"], fam, 2), harmonic_db(s["raw"], fam, 2))
        rows.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            name, diagnosis(m["pw"]), diagnosis(m["raw"]), diagnosis(s["raw"]), diagnosis(s["pw"]),
            h2, h3, band(m["pw"]), band(s["raw"])))
    rows += ["", "**Levels** (RMS over the analysed record, m/s²)", "",
             "| condition | measured | simulated ay_housing (no noise) | simulated record (with noise) |",
             "| --- | ---: | ---: | ---: |"]
    for name, r in results.items():
        rows.append("| %s | %.3g | %.3g | %.3g |" % (
            name, r["measured"]["pw"]["channels"]["0"]["rms"], r["sim_rms"],
            r["simulated"]["raw"]["channels"]["0"]["rms"]))
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


def figure(name, r, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fam = RECORDS[name][3]
    fams = [fam] if fam else ["outer", "inner", "ball"]
    views = [("measured", "pw", "tab:blue"), ("simulated", "raw", "tab:green")]
    top = 3.6 * max(family_line(r["measured"]["pw"], fm)["nominal"] for fm in fams)
    fig = plt.figure(figsize=(10, 7.5), constrained_layout=True)
    grid = fig.add_gridspec(3, 3)
    for row, (who, key, colour) in enumerate(views):
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
        ax.set_title("%s (%s, %s, %s): band %s (kurtogram); diagnosis %s" % (
            who, record, "%.0f kHz" % (s["record"]["rate"] / 1e3),
            "pre-whitened" if key == "pw" else "not pre-whitened", band(s),
            s["diagnosis"]["family"]), fontsize=9)
        ax.set_ylabel("SES / median [dB]")
        ax.set_xlim(0, top)
        ax.set_ylim(bottom=-5)
    ax.set_xlabel("frequency [Hz] (peak-held over 5 bins; grey: shaft harmonics f_r, 2 f_r, …; "
                  "dotted: the lines analyse found, red if their family is detected)", fontsize=8)
    # Zooms on the condition's 1x, 2x, 3x: both records at full resolution, the kinematic line.
    zoom_family = fam or "outer"
    for k in range(3):
        ax = fig.add_subplot(grid[2, k])
        nominal = family_line(r["measured"]["pw"], zoom_family, k)["nominal"]
        half = 0.012 * nominal
        for who, key, colour in views:
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
                 "(squared envelope spectra)" % name, fontsize=11)
    fig.savefig(out / ("cwru-%s.png" % name), dpi=80)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sim", default=str(ROOT / "build" / "lumped" / "bearing-sim"))
    parser.add_argument("--out", default=str(ROOT / "out" / "cwru"))
    args = parser.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    noise_psd = rig_noise_floor()
    sigma = float(np.sqrt(noise_psd * SIM_RATE / 2))
    results = {}
    for name, (file, rate, rpm, _) in RECORDS.items():
        number = int(file.split("_")[0])
        path, _, sim_rms = simulated_record(args.sim, name, out, noise_psd, seed=number)
        r = {"sim_rms": sim_rms}
        for who, record, rec_rate, unit in [("measured", DATA / file, rate, "g"),
                                            ("simulated", path, int(SIM_RATE), "m/s^2")]:
            r[who] = {}
            for key, pw in [("pw", True), ("raw", False)]:
                folder = out / "analyses" / ("%s-%s-%s" % (name, who, key))
                r[who][key] = analyse(args.sim, record, rec_rate, unit, rpm, folder, pw)
                r[who][key + "_dir"] = folder
            r[who]["bin"] = _step(r[who]["pw_dir"])
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
