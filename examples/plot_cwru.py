"""The CWRU-like fault study's table and figure (examples/cwru_study.sh, examples/README.md §7).

Reads OUTDIR/{outer,inner,ball,healthy}/{summary.json,spectrum.csv,envelope.csv}; writes
OUTDIR/table.md (each run's diagnosis and its strongest fault line against the CWRU data set's
published defect frequency) and, with matplotlib, OUTDIR/cwru_spectra.png (the spectrum of ay and
its envelope spectrum per run, the expected fault lines marked). Run by Debian's /usr/bin/python3.
"""
import csv
import json
import sys
from pathlib import Path

# CWRU Bearing Data Center, drive-end 6205-2RS JEM SKF: defect frequencies in multiples of the
# running speed ("rolling element" is 2 x BSF).
CWRU = {"outer": ("BPFO", 3.5848), "inner": ("BPFI", 5.4152), "ball": ("2xBSF", 4.7135)}
RUNS = ["outer", "inner", "ball", "healthy"]


def columns(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    head, body = rows[0], rows[1:]
    return {name: [float(r[i]) for r in body] for i, name in enumerate(head)}


def table(out):
    lines = ["| spall | diagnosis | envelope band (ay) | SK | CWRU line | CWRU × f_r [Hz] | "
             "simulated line [Hz] | its amplitude |",
             "| --- | --- | --- | ---: | --- | ---: | ---: | ---: |"]
    for run in RUNS:
        s = json.loads((out / run / "summary.json").read_text())
        d, fr = s["diagnosis"], s["frequencies"]["shaft"]
        band = "%.0f–%.0f Hz" % tuple(s["envelope"]["ay"]["band"])
        sk = s["envelope"]["ay"]["spectral_kurtosis"]
        if run in CWRU:
            label, multiple = CWRU[run]
            peak = next((p for p in s["envelope"]["ay"]["peaks"] if p["label"] == label), None)
            line = "%.2f" % peak["frequency"] if peak else "not among the peaks"
            amp = "%.3g m/s²" % peak["amplitude"] if peak else ""
            lines.append("| %s | %s | %s | %.1f | %s | %.2f | %s | %s |" % (
                run, d["family"], band, sk, label, multiple * fr, line, amp))
        else:
            lines.append("| none (waviness) | %s | %s | %.1f | | | | |" % (d["family"], band, sk))
    text = "\n".join(lines) + "\n"
    (out / "table.md").write_text(text)
    print(text)


def figure(out):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("plot_cwru.py: no matplotlib for /usr/bin/python3: table only")
        return
    fig, axes = plt.subplots(len(RUNS), 2, figsize=(12, 10), constrained_layout=True)
    for row, run in enumerate(RUNS):
        s = json.loads((out / run / "summary.json").read_text())
        f = s["frequencies"]
        sp, env = columns(out / run / "spectrum.csv"), columns(out / run / "envelope.csv")
        ax = axes[row][0]
        ax.semilogy(sp["frequency"], sp["ay"], lw=0.6)
        lo, hi = s["envelope"]["ay"]["band"]
        ax.axvspan(lo, hi, color="tab:orange", alpha=0.15, label="envelope band")
        ax.set_xlim(0, 8000)
        ax.set_ylabel("|ay| [m/s²]")
        ax.set_title("%s: spectrum of ay" % run, fontsize=10)
        ax.legend(loc="upper right", fontsize=8)
        ax = axes[row][1]
        ax.plot(env["frequency"], env["env_ay"], lw=0.8)
        marks = {"outer": [(k * f["bpfo"], "k·BPFO") for k in range(1, 5)],
                 "inner": [(k * f["bpfi"], "k·BPFI") for k in range(1, 4)],
                 "ball": [(2 * k * f["bsf"], "2k·BSF") for k in range(1, 4)]}
        for x, name in marks.get(run, marks["outer"]):
            ax.axvline(x, color="tab:red", ls=":", lw=0.8)
        ax.set_xlim(0, 600)
        ax.set_ylabel("envelope [m/s²]")
        d = s["diagnosis"]
        ax.set_title("%s: envelope spectrum (%s, SK %.1f): diagnosis %s" % (
            run, "%.0f–%.0f Hz" % (lo, hi), s["envelope"]["ay"]["spectral_kurtosis"],
            d["family"]), fontsize=10)
    for ax in axes[-1]:
        ax.set_xlabel("frequency [Hz]")
    fig.suptitle("CWRU-like 6205, 1797 rpm, 500 N, 0.533 mm spall (red: the expected fault lines)")
    fig.savefig(out / "cwru_spectra.png", dpi=90)
    print("wrote", out / "cwru_spectra.png")


if __name__ == "__main__":
    out = Path(sys.argv[1] if len(sys.argv) > 1 else "out/studies/cwru")
    table(out)
    figure(out)
