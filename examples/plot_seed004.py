#!/usr/bin/python3
"""Plots of the seed 004 studies written by examples/seed004_studies.sh.

    /usr/bin/python3 examples/plot_seed004.py OUTDIR [PLOTDIR]

OUTDIR is seed004_studies.sh's output folder (fig8/, fig9.csv, fig10.csv, fig12/, fig13/); PNGs go
to PLOTDIR (default OUTDIR/plots): seed004_friction_angle.png (Fig. 8 analogue),
seed004_friction_slip.png (Fig. 9), seed004_friction_speed.png (Fig. 10), seed004_ax_slip.png
(Fig. 12) and seed004_ax_speed.png (Fig. 13). Needs matplotlib (Debian: python3-matplotlib);
seed004_studies.sh and run_studies.sh call it only when /usr/bin/python3 has it.
"""
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

TRANSIENT = 0.2  # s, the friction runs' transient (seed004_studies.sh)


def save(fig, plots, name):
    """Lays out, writes PLOTDIR/name and closes the figure."""
    fig.tight_layout()
    fig.savefig(os.path.join(plots, name), dpi=110)
    plt.close(fig)


def rows(path):
    return list(csv.DictReader(open(path)))


def sweep(path, key, *cols):
    r = [x for x in rows(os.path.join(path, "sweep.csv")) if x["status"] == "ok"]
    return [float(x[key]) for x in r], [[float(x[c]) for x in r] for c in cols]


def friction_angle(out, plots):
    d = os.path.join(out, "fig8")
    w = json.load(open(os.path.join(d, "summary.json")))["cage"]["speed"]
    pts = []
    for r in csv.DictReader(open(os.path.join(d, "response.csv"))):
        t = float(r["t"])
        if t < TRANSIENT:
            continue
        th = math.degrees(math.remainder(w * t, 2 * math.pi))
        pts.append((th, float(r["Fi1"]), float(r["Fo1"]), float(r["Q1"]), float(r["Qo1"])))
    pts.sort()
    th = [p[0] for p in pts]
    fig, ax = plt.subplots(figsize=(9, 4.5))
    ax.plot(th, [p[1] for p in pts], "-", label="Fi1: inner contact")
    ax.plot(th, [p[2] for p in pts], "--", label="Fo1: outer contact")
    ax.set(xlabel="angular position of ball 1, theta [deg] (load along theta = 0)",
           ylabel="friction force on ball 1 [N] (+: direction of rotation)", xlim=(-180, 180),
           title="Seed 004 Fig. 8: s_c = 2 %, mu_m = 0.05, 2000 rpm, 2000 N")
    ax.set_xticks(range(-180, 181, 30))
    ax.grid(alpha=0.3)
    ax2 = ax.twinx()
    ax2.plot(th, [p[3] for p in pts], "k:", lw=1, label="Q1: inner load")
    ax2.plot(th, [p[4] for p in pts], "C3:", lw=1, label="Qo1: outer load")
    ax2.set_ylabel("contact load [N]")
    h1, l1 = ax.get_legend_handles_labels()
    h2, l2 = ax2.get_legend_handles_labels()
    ax.legend(h1 + h2, l1 + l2, fontsize=8, loc="upper right")
    save(fig, plots, "seed004_friction_angle.png")


def friction_peaks(out, plots, csv, group, x_key, x_scale, label, xlabel, prediction, title, png):
    """Peak friction on ball 1 (and its prediction, dotted) against x_key, one line per group."""
    r = rows(os.path.join(out, csv))
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for k, g in enumerate(sorted({x[group] for x in r}, key=float)):
        sel = [x for x in r if x[group] == g]
        xs = [x_scale * float(x[x_key]) for x in sel]
        ax.plot(xs, [float(x["Fi1_peak"]) for x in sel], "o-", color=f"C{k}", label=label.format(g))
        ax.plot(xs, [float(x["predicted"]) for x in sel], ":", color=f"C{k}")
    ax.plot([], [], "k:", label=prediction)
    ax.set(xlabel=xlabel, ylabel="peak friction on ball 1, Fi1 [N]", title=title)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, plots, png)


def friction_slip(out, plots):
    friction_peaks(out, plots, "fig9.csv", "mu_m", "slip", 100, "mu_m = {}", "cage slip s_c [%]",
                   "mu_m Q_max min(1, s w_i r_i / 2 Dv_m)", "Seed 004 Fig. 9: 2000 rpm, 2000 N",
                   "seed004_friction_slip.png")


def friction_speed(out, plots):
    friction_peaks(out, plots, "fig10.csv", "load", "speed_rpm", 1, "W = {} N",
                   "inner-ring speed [rpm]", "mu_m Q_max s w_i r_i / 2 Dv_m",
                   "Seed 004 Fig. 10: s_c = 2 %, mu_m = 0.01", "seed004_friction_speed.png")


STATS = (("ax.ptp", "PTP [m/s^2]"), ("ax.rms", "RMS [m/s^2]"), ("ax.kurtosis", "kurtosis [-]"))


def ax_slip(out, plots):
    d = os.path.join(out, "fig12")
    fig, ax = plt.subplots(1, 3, figsize=(14, 4.2))
    s0, v0 = sweep(os.path.join(d, "mu0"), "cage.slip", *(c for c, _ in STATS))
    r = [x for x in rows(os.path.join(d, "mu", "sweep.csv")) if x["status"] == "ok"]
    for a, (col, label), v in zip(ax, STATS, v0):
        a.plot([100 * s for s in s0], v, "k--", label="mu_m = 0 (control)")
        for k, mu in enumerate(sorted({float(x["cage.friction"]) for x in r})):
            sel = [x for x in r if float(x["cage.friction"]) == mu]
            a.plot([100 * float(x["cage.slip"]) for x in sel], [float(x[col]) for x in sel], "o-",
                   color=f"C{k}", label=f"mu_m = {mu:g}")
        a.set(xlabel="cage slip s_c [%]", ylabel=f"ax {label}")
        a.grid(alpha=0.3)
    ax[0].legend(fontsize=8)
    fig.suptitle("Seed 004 Fig. 12: inner-ring x acceleration vs cage slip, 2000 rpm, 2000 N")
    save(fig, plots, "seed004_ax_slip.png")


def ax_speed(out, plots):
    d = os.path.join(out, "fig13")
    fig, ax = plt.subplots(1, 3, figsize=(14, 4.2))
    for k, w in enumerate((1000, 2000, 3000)):
        n, v = sweep(os.path.join(d, f"W{w}"), "operation.speed", *(c for c, _ in STATS))
        rpm = [x * 30 / math.pi for x in n]
        _, (r0,) = sweep(os.path.join(d, f"W{w}_mu0"), "operation.speed", "ax.rms")
        for i, (a, (_, label)) in enumerate(zip(ax, STATS)):
            a.plot(rpm, v[i], "o-", color=f"C{k}", label=f"W = {w} N")
            if i == 1:
                a.plot(rpm, r0, ":", color=f"C{k}", label=f"W = {w} N, mu_m = 0")
            a.set(xlabel="inner-ring speed [rpm]", ylabel=f"ax {label}")
            a.grid(alpha=0.3)
    ax[1].legend(fontsize=8)
    fig.suptitle("Seed 004 Fig. 13: inner-ring x acceleration vs speed, s_c = 2 %, mu_m = 0.01")
    save(fig, plots, "seed004_ax_speed.png")


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "out/studies/seed004"
    plots = sys.argv[2] if len(sys.argv) > 2 else os.path.join(out, "plots")
    os.makedirs(plots, exist_ok=True)
    for f in (friction_angle, friction_slip, friction_speed, ax_slip, ax_speed):
        f(out, plots)


if __name__ == "__main__":
    main()
