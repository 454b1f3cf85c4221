#!/usr/bin/python3
"""Draws the figures of a bearing-verify report: figures.json (written by bearing-verify) -> PNGs.

Usage: /usr/bin/python3 plot_figures.py FIGURES_JSON OUT_DIR
Each figure: name, title, x_label, y_label, log_x, log_y, series [{label, x, y, style}],
markers [{x, label}] (labelled vertical lines).
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def draw(fig_spec, out_dir):
    fig, ax = plt.subplots(figsize=(6.4, 4.0), dpi=110)
    for s in fig_spec["series"]:
        style = s.get("style", "line")
        kwargs = {"label": s["label"]} if s["label"] else {}
        if style == "marker":
            ax.plot(s["x"], s["y"], "o", ms=4, **kwargs)
        elif style == "line+marker":
            ax.plot(s["x"], s["y"], "-o", ms=4, lw=1.2, **kwargs)
        else:
            ax.plot(s["x"], s["y"], "-", lw=1.2, **kwargs)
    if fig_spec.get("log_x"):
        ax.set_xscale("log")
    if fig_spec.get("log_y"):
        ax.set_yscale("log")
    for i, m in enumerate(fig_spec.get("markers", [])):
        ax.axvline(m["x"], color="0.45", lw=0.8, ls="--")
        ax.annotate(m["label"], (m["x"], 1.0), xycoords=("data", "axes fraction"),
                    xytext=(3, -12 - 11 * (i % 3)), textcoords="offset points", fontsize=7,
                    color="0.25")
    ax.set_title(fig_spec["title"], fontsize=10)
    ax.set_xlabel(fig_spec["x_label"])
    ax.set_ylabel(fig_spec["y_label"])
    ax.grid(True, which="both", lw=0.3, alpha=0.5)
    if any(s["label"] for s in fig_spec["series"]):
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(f"{out_dir}/{fig_spec['name']}.png")
    plt.close(fig)


def main():
    with open(sys.argv[1]) as f:
        figures = json.load(f)
    for spec in figures:
        draw(spec, sys.argv[2])


if __name__ == "__main__":
    main()
