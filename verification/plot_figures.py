#!/usr/bin/python3
"""Draws the figures of a bearing-verify report: figures.json (written by bearing-verify) -> PNGs.

Usage: /usr/bin/python3 plot_figures.py FIGURES_JSON OUT_DIR

The drawing is bearing.plot's (python/bearing/plot/report_figures.py, with the panels bearing-plot
uses), imported from the source tree's python/ beside this folder: one plotting code for the
report and bearing-plot. The figure format is described there and in src/figure.h.
"""
import importlib
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "python"))


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    # import_module: no attribute lookup on the package `bearing`, whose compiled extension
    # need not be built (bearing.plot is NumPy and matplotlib only).
    plot = importlib.import_module("bearing.plot")
    plot.draw_report_figures(sys.argv[1], sys.argv[2])


if __name__ == "__main__":
    main()
