"""The figure of a bearing-fem contact output: force against approach with Hertz."""

import numpy as np

from .common import _new_figure, _style
from .panels import force_approach_axes, plain_log_ticks


# --- contact figure ---------------------------------------------------------------------------

def contact_figure(contact):
    """Force-approach on log axes with the Hertz law; the FE/Hertz deviation per step."""
    j = contact.json
    fe, hertz = j.get("fe", {}), j.get("hertz", {})
    curve = contact.curve
    with _style():
        fig = _new_figure("force_approach")
        left, right = fig.subplots(1, 2)
        fit = (fe["K_free_exponent"], fe["exponent"]) if "K_free_exponent" in fe else None
        force_approach_axes(left, curve["approach"], curve["force"], hertz_K=hertz["K"],
                            hertz_n=hertz.get("exponent", 1.5), fit=fit)
        left.set_title("force–approach: FE K at n = 1.5 is %.5g N/m$^{1.5}$ (%+.3g %% of Hertz)"
                       % (fe.get("K", float("nan")),
                          100 * j.get("relative_difference", {}).get("K", float("nan"))),
                       fontsize=10)
        steps = j.get("steps", [])
        if steps and all("hertz_force" in s for s in steps):
            load = np.array([s["force"] for s in steps])
            series = (("force", "hertz_force", "force at the same approach"),
                      ("semi_axis_a", "hertz_semi_axis_a", "semi-major axis a"),
                      ("semi_axis_b", "hertz_semi_axis_b", "semi-minor axis b"),
                      ("peak_pressure", "hertz_peak_pressure", "peak pressure p$_0$"))
            for key, ref, label in series:
                if all(key in s and ref in s for s in steps):
                    dev = np.array([100 * (s[key] / s[ref] - 1) for s in steps])
                    line, = right.semilogx(load, dev, "-o", ms=4, label=label)
                    line.set_gid("contact:dev:" + key)
            right.axhline(0, color="k", lw=0.7)
            plain_log_ticks(right.xaxis)
            right.set_xlabel("contact force Q [N]")
            right.set_ylabel("FE / Hertz − 1 [%]")
            right.set_title("FE against Hertz per approach step")
            right.legend(framealpha=0.9)
            right.grid(True, which="both")
        else:
            right.set_visible(False)
        mesh = j.get("mesh", {})
        fig.suptitle("%s — %s race, %s geometry: FE contact (bearing-fem)\n"
                     "%s cells, %s DOFs, %.3g cells per semi-minor axis, MPI processes: %s, "
                     "%.3g s wall time" % (
                         contact.name, j.get("race", "?"), j.get("geometry", "?"),
                         mesh.get("cells", "?"), mesh.get("dofs", "?"),
                         mesh.get("cells_per_semi_minor", float("nan")),
                         j.get("mpi_processes", "?"),
                         j.get("wall_time", float("nan"))))
        fig.tight_layout()
    return fig
