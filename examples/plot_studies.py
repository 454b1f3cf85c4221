#!/usr/bin/python3
"""Plots of the reproduction studies written by examples/run_studies.sh.

    /usr/bin/python3 examples/plot_studies.py OUTDIR

Reads OUTDIR/<study>/.../sweep.csv and run folders, writes OUTDIR/plots/*.png. Needs matplotlib
(Debian: python3-matplotlib); run_studies.sh calls it only when /usr/bin/python3 has it.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def sweep(path, key, *cols):
    rows = [r for r in csv.DictReader(open(os.path.join(path, "sweep.csv"))) if r["status"] == "ok"]
    return [float(r[key]) for r in rows], [[float(r[c]) for r in rows] for c in cols]


def spectrum(path, ch):
    f, a = [], []
    for r in csv.DictReader(open(os.path.join(path, "spectrum.csv"))):
        f.append(float(r["frequency"]))
        a.append(float(r[ch]))
    return f, a


def seed001(out, plots):
    d = os.path.join(out, "seed001")
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    for sub, label, style in (("balls_P10", "P_l = 10 N", "o-"), ("balls_P0", "P_l = 0", "s--")):
        z, (y, x) = sweep(os.path.join(d, sub), "bearing.balls", "y.rms", "x.ptp")
        ax[0].semilogy(z, [max(v, 1e-22) for v in y], style, label=f"y RMS, {label}")
        ax[0].semilogy(z, [max(v, 1e-22) for v in x], style, alpha=0.5, label=f"x ptp, {label}")
    ax[0].set(xlabel="number of balls Z", ylabel="displacement [m]",
              title="Seed 001 Fig. 3: varying-compliance vibration vs Z")
    ax[0].legend(fontsize=8)
    pts = []
    for sub in ("preload_Z8", "preload_Z8_fine", "preload_Z8_heavy"):
        p, (y, x) = sweep(os.path.join(d, sub), "operation.axial_load", "y.rms", "x.ptp")
        pts += list(zip(p, y, x))
    pts.sort()
    ax[1].semilogy([p[0] for p in pts], [max(p[1], 1e-22) for p in pts], "o-", label="y RMS")
    ax[1].semilogy([p[0] for p in pts], [max(p[2], 1e-22) for p in pts], "s--", label="x ptp")
    ax[1].set(xlabel="axial preload P_l [N]", ylabel="displacement [m]",
              title="Seed 001 Fig. 4: preload, Z = 8 (values < 1e-22 m clipped)")
    ax[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(plots, "seed001_balls_preload.png"), dpi=110)
    plt.close(fig)


def seed002(out, plots):
    d = os.path.join(out, "seed002")
    fig, ax = plt.subplots(2, 2, figsize=(12, 8), sharex=True)
    for i, race in enumerate(("inner", "outer")):
        for j, amp in enumerate(("8um", "0.5um")):
            a = ax[j][i]
            key = f"waviness.{race}.0.order"
            for suffix, label, style in (("tvd", "TVD", "o-"), ("tvds", "TVDS", "x--"),
                                         ("tvd_psi", "TVD, psi + 1e-6 rad", ":")):
                n, (ay,) = sweep(os.path.join(d, f"{race}_{amp}_{suffix}"), key, "ay.rms")
                a.plot(n, ay, style, label=label)
                if suffix == "tvd":
                    t1 = [(o, v) for o, v in zip(n, ay) if int(o) % 8 in (0, 1, 7)]
                    a.plot([o for o, _ in t1], [v for _, v in t1], "ks", mfc="none", ms=9,
                           label="Table 1 orders")
            for k in (8, 16, 24):
                a.axvline(k, color="grey", lw=0.6)
            a.set(title=f"Seed 002 Fig. 4{'a' if race == 'inner' else 'b'}: {race} race, "
                        f"A = {amp.replace('um', ' um')}", ylabel="ay RMS [m/s^2]")
            if j == 1:
                a.set_xlabel("waviness order N (grey: multiples of Z = 8)")
            a.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(plots, "seed002_tvds.png"), dpi=110)
    plt.close(fig)


def seed002_scan(out, plots):
    d = os.path.join(out, "seed002")
    fig, ax = plt.subplots(1, 2, figsize=(12, 4.5), sharey=True)
    for a, race in zip(ax, ("inner", "outer")):
        path = os.path.join(d, f"{race}_amplitude_scan", "sweep.csv")
        rows = [r for r in csv.DictReader(open(path)) if r["status"] == "ok"]
        amps = sorted({float(r[f"waviness.{race}.0.amplitude"]) for r in rows})
        for amp in amps:
            sel = [r for r in rows if float(r[f"waviness.{race}.0.amplitude"]) == amp]
            a.semilogy([int(r[f"waviness.{race}.0.order"]) for r in sel],
                       [float(r["ay.rms"]) for r in sel], "o-", ms=3, label=f"A = {amp * 1e6:g} um")
        for k in (8, 16, 24):
            a.axvline(k, color="grey", lw=0.6)
        a.set(title=f"Seed 002, {race} race, TVD: amplitude scan (gap 7 um per ball)",
              xlabel="waviness order N (grey: multiples of Z = 8)")
        a.legend(fontsize=7, ncol=2)
    ax[0].set_ylabel("ay RMS [m/s^2]")
    fig.tight_layout()
    fig.savefig(os.path.join(plots, "seed002_amplitude_scan.png"), dpi=110)
    plt.close(fig)


def seed003_amplitude(out, plots):
    d = os.path.join(out, "seed003_amplitude")
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    for race, style in (("inner", "o-"), ("outer", "s--")):
        a, (ptp, rms) = sweep(os.path.join(d, race), f"waviness.{race}.0.amplitude", "y.ptp", "ay.rms")
        ax[0].plot([v * 1e6 for v in a], [v * 1e6 for v in ptp], style, label=race)
        ax[1].plot([v * 1e6 for v in a], rms, style, label=race)
    ax[0].plot([0, 1.2], [0, 2.4], "k:", lw=0.8, label="2 A")
    ax[0].set(xlabel="waviness amplitude A [um] (order 7)", ylabel="y peak-to-peak [um]",
              title="Seed 003 Figs. 10, 13")
    ax[1].set(xlabel="waviness amplitude A [um] (order 7)", ylabel="ay RMS [m/s^2]",
              title="Seed 003 Figs. 11, 14")
    for a in ax:
        a.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(plots, "seed003_amplitude.png"), dpi=110)
    plt.close(fig)


def seed003_measured(out, plots):
    d = os.path.join(out, "seed003_measured")
    fig, ax = plt.subplots(2, 1, figsize=(11, 7))
    for run, label in (("Pd2um", "measured, P_d = 2 um"), ("perfect_Pd2um", "perfect, P_d = 2 um"),
                       ("Pd14um", "measured, P_d = 14 um")):
        path = os.path.join(d, run)
        if not os.path.exists(os.path.join(path, "spectrum.csv")):
            continue
        for a, ch, scale, unit in ((ax[0], "y", 1e6, "um"), (ax[1], "ay", 1.0, "m/s^2")):
            f, amp = spectrum(path, ch)
            keep = [k for k, v in enumerate(f) if v <= 2000]
            a.semilogy([f[k] for k in keep], [max(amp[k] * scale, 1e-9) for k in keep], lw=0.7,
                       label=label)
            a.set(ylabel=f"{ch} amplitude [{unit}]")
    ax[0].set_title("Seed 003 Table 3 waviness (inner race, orders 4-100): spectra, 20 N, 2000 rpm")
    ax[1].set_xlabel("frequency [Hz]")
    for a in ax:
        a.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(plots, "seed003_measured.png"), dpi=110)
    plt.close(fig)


def seed000(out, plots):
    """SPL at point A against each swept parameter (examples/seed000_noise.sh), paper trend noted."""
    d = os.path.join(out, "seed000")
    if not os.path.isdir(d):
        return
    studies = (("order", "wave number N_w (both races)", "irregular"),
               ("amplitude", "waviness amplitude A [um] (both races)", "rising"),
               ("speed", "speed [rpm]", "rising"),
               ("load", "radial load [N]", "rising"),
               ("band", "ball-size error band [um]", "rising"),
               ("band_only", "error band [um], no waviness", "rising"))
    fig, ax = plt.subplots(2, 3, figsize=(14, 7.5))
    for a, (name, label, claim) in zip(ax.flat, studies):
        rows = list(csv.DictReader(open(os.path.join(d, name + ".csv"))))
        x = [float(r["value"]) for r in rows]
        for col, style in (("spl_total", "o-"), ("spl_ring", "s--"), ("spl_balls", "^:")):
            a.plot(x, [float(r[col]) for r in rows], style, label=col.replace("spl_", ""))
        jumps = [(xv, float(r["spl_total"])) for xv, r in zip(x, rows) if int(r["jumps"]) > 0]
        if jumps:
            a.plot(*zip(*jumps), "rx", ms=10, label="orbit jumps")
        if name == "speed":
            a.set_xscale("log")
        a.set(xlabel=label, ylabel="SPL at point A [dB re 20 uPa]",
              title=f"{name}: seed 000 claims {claim}")
        a.grid(alpha=0.3)
    ax[0][0].axhline(29.8, color="k", lw=0.8, ls="-.", label="seed 000: 29.8 dB")
    ax[0][0].legend(fontsize=7)
    fig.suptitle("Seed 000 608 at 720 rpm, 50 N: SPL 10 mm below the centre (quasi-static model)")
    fig.tight_layout()
    fig.savefig(os.path.join(plots, "seed000_spl.png"), dpi=110)
    plt.close(fig)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "out/studies"
    plots = os.path.join(out, "plots")
    os.makedirs(plots, exist_ok=True)
    for f in (seed000, seed001, seed002, seed002_scan, seed003_amplitude, seed003_measured):
        f(out, plots)


if __name__ == "__main__":
    main()
