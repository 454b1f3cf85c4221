"""The figure of a bearing-fem calibrate output: each race's FE force against approach with the
fitted law Q = K delta^n and Hertz, and both laws' departure from Hertz over the loads."""

import math

import numpy as np

from .common import _new_figure, _style, _wrap
from .panels import force_approach_axes, plain_log_ticks


def calibration_figure(cal):
    """Top: per race, force against approach (the FE points of the race's contact folder when it
    is there) with the calibrated law and Hertz's (n = 1.5); bottom: Q / (K_Hertz delta^1.5) - 1
    of the FE points and of the calibrated law against the load."""
    load_lo, load_hi = (cal.load_range + [float("nan")] * 2)[:2]
    with _style():
        fig = _new_figure("calibration")
        grid = fig.add_gridspec(2, 2, height_ratios=[1.15, 1])
        bottom = fig.add_subplot(grid[1, :])
        for col, race in enumerate(cal.RACES):
            ax = fig.add_subplot(grid[0, col])
            law = cal.json[race]
            K, n = cal.law(race)
            contact = cal.contacts.get(race)
            approach = contact.curve["approach"] if contact else np.array([])
            force = contact.curve["force"] if contact else np.array([])
            span = None
            if not approach.size:  # the law alone over the calibrated loads
                span = ((load_lo / K) ** (1 / n) / 1.3, (load_hi / K) ** (1 / n) * 1.3)
            force_approach_axes(ax, approach, force, hertz_K=law["hertz_K"], hertz_n=1.5,
                                fit=(K, n), span=span, points_label="FE, %s race" % race,
                                law_label="Hertz", fit_label="calibrated",
                                gid="calibration:" + race)
            three_halves = law.get("K_three_halves")
            ax.set_title("%s race: K = %.5g N/m$^{%.5g}$, fit residual %.2g%s%s" % (
                race, K, n, law.get("fit_residual", float("nan")),
                "\nK at n = 1.5: %.5g N/m$^{1.5}$, %+.3g %% of Hertz"
                % (three_halves, 100 * (three_halves / law["hertz_K"] - 1))
                if three_halves else "",
                "" if contact else "\n(FE points: %s not found)" % cal.missing[race]),
                fontsize=10)
            _departure(bottom, race, "C%d" % col, law["hertz_K"], K, n, load_lo, load_hi,
                       approach, force)
        bottom.axhline(0, color="C3", lw=1.3, label="Hertz (n = 1.5)")
        if math.isfinite(load_lo) and math.isfinite(load_hi):
            for q in (load_lo, load_hi):
                bottom.axvline(q, color="0.4", lw=0.9, ls=":", zorder=0,
                               label="calibrated load range %.4g–%.4g N" % (load_lo, load_hi)
                               if q == load_lo else None)
        bottom.set_xscale("log")
        plain_log_ticks(bottom.xaxis)
        bottom.grid(True, which="both")
        bottom.set_xlabel("contact force Q [N]")
        bottom.set_ylabel("Q / (K$_{Hertz}$ δ$^{1.5}$) − 1 [%]")
        bottom.set_title("departure from Hertz at the same approach: FE points and the "
                         "calibrated laws (their gap is the fit's residual)")
        bottom.legend(loc="best", framealpha=0.9, ncol=2)
        j = cal.json
        b = j.get("bearing", {})
        fig.suptitle("%s — bearing-fem calibration of the %s, %s geometry (case %s, %s)\n%s" % (
            cal.name, b.get("designation", "?"), j.get("geometry", "?"), j.get("case", "?"),
            j.get("date", "?"), _wrap(j.get("mesh", ""), 150)))
        fig.tight_layout()
    return fig


def _departure(ax, race, color, hertz_K, K, n, load_lo, load_hi, approach, force):
    """One race on the departure panel: the FE points and the calibrated law over its loads."""
    if approach.size:
        points, = ax.semilogx(force, 100 * (force / (hertz_K * approach ** 1.5) - 1), "o",
                              color=color, ms=6, label="FE, %s race" % race)
        points.set_gid("calibration:departure:%s:fe" % race)
    if math.isfinite(load_lo) and math.isfinite(load_hi) and 0 < load_lo < load_hi:
        q = np.geomspace(load_lo, load_hi, 60)
        delta = (q / K) ** (1 / n)
        line, = ax.semilogx(q, 100 * (q / (hertz_K * delta ** 1.5) - 1), "--", color=color,
                            lw=1.3, label="calibrated law, %s race" % race)
        line.set_gid("calibration:departure:%s:fit" % race)
