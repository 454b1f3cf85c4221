"""The sensor figure of a run with a [housing]: the sensor's vertical acceleration (ay_housing on the
resonator; ay_<name> of the structure's sensors with [housing] modes: what an accelerometer on the
housing reads) beside the inner ring's ay, in time and in frequency, and where each channel's
energy lies."""

import numpy as np

from .common import (BALL_PASSES_ZOOMED, DISPLAY, _new_figure, _nice_ceiling, _style,
                     load_line_passes)
from .panels import spectrum_axes, trace_axes

RING, SENSOR = "ay", "ay_housing"


def sensor_channel(run):
    """The sensor channel the figure draws: ay_housing (the resonator), else the first sensor of
    the structure's modes (summary.json's housing.sensors), else None."""
    if SENSOR in run.response:
        return SENSOR
    for sensor in run.summary.get("housing", {}).get("sensors", []):
        name = "ay_" + sensor["name"]
        if name in run.response:
            return name
    return None


def has_sensor(run):
    """Whether the run wrote a sensor's acceleration (a case with [housing])."""
    return RING in run.response and sensor_channel(run) is not None


def energy_share(f, amplitude):
    """The cumulative share of the spectrum's energy (sum of squared amplitudes, the mean left
    out) below each frequency, and the band [f10, f90] holding its middle 80 %."""
    power = np.where(f > 0, amplitude ** 2, 0.0)
    total = power.sum()
    share = np.cumsum(power) / total if total > 0 else np.zeros_like(f)
    return share, (f[np.searchsorted(share, 0.1)], f[min(np.searchsorted(share, 0.9), f.size - 1)])


def sensor_figure(run):
    """Top: a_y of the ring and of the housing over the last ball passes. Bottom left: both
    amplitude spectra, the housing's own frequency f_h marked. Bottom right: each channel's
    cumulative energy share against frequency, with the band of its middle 80 %."""
    r, s = run.response, run.spectrum
    t = r["t"]
    bpfo = run.frequencies.get("bpfo", 0.0)
    span = BALL_PASSES_ZOOMED / bpfo if bpfo > 0 else 0.1 * (t[-1] - t[0])
    zoom = t >= t[-1] - span
    marks = load_line_passes(run.summary, t[zoom][0], t[-1])
    housing = run.summary.get("housing", {})
    f_h = housing.get("frequency")
    modes = housing.get("frequencies", [])  # the structure's, alone
    sensor = sensor_channel(run)
    unit, factor = DISPLAY["m/s^2"]
    names = {RING: "inner ring $a_y$",
             sensor: "sensor on the housing $a_{y,h}$" if sensor == SENSOR
             else "sensor %s $a_y$" % sensor[3:]}
    colours = {RING: "C1", sensor: "C2"}
    with _style():
        fig = _new_figure("sensor")
        (ring_ax, sensor_ax), (spectrum_ax, share_ax) = fig.subplots(2, 2)
        for ax, name in ((ring_ax, RING), (sensor_ax, sensor)):
            trace_axes(ax, t[zoom], r[name][zoom] * factor, label="%s [%s]" % (names[name], unit),
                       marks=marks, gid="sensor_time:" + name, color=colours[name])
            ax.set_xlabel("time t [s]")
            ax.set_title("%s, last %s" % (name, "%d ball passes" % BALL_PASSES_ZOOMED
                                          if bpfo > 0 else "10 % of the record"))
        if s is not None:
            f = s["frequency"]
            top = max(np.max(s[RING]), np.max(s[sensor])) * factor
            # Up to where both channels hold 99.9 % of their energy, and twice f_h at least.
            reach = max(f[min(np.searchsorted(energy_share(f, s[n])[0], 0.999), f.size - 1)]
                        for n in (RING, sensor))
            fmax = min(f[-1], _nice_ceiling(max(reach, 2 * (f_h or 0))))
            for name in (RING, sensor):
                spectrum_axes(spectrum_ax, f, s[name] * factor, (), fmax=fmax,
                              label="amplitude [%s]" % unit, gid="sensor_spectrum:" + name,
                              color=colours[name])
                spectrum_ax.lines[-1].set_label(names[name])
            spectrum_ax.set_ylim(top * 1e-5, top * 3)
            for name in (RING, sensor):
                share, (lo, hi) = energy_share(f, s[name])
                line, = share_ax.plot(f, share, color=colours[name], lw=1.2,
                                      label="%s: 80 %% in %.3g–%.3g kHz" % (names[name], lo / 1e3,
                                                                         hi / 1e3))
                line.set_gid("sensor_energy:" + name)
                share_ax.axvspan(lo, hi, color=colours[name], alpha=0.12, lw=0)
            share_ax.set_xlim(0, fmax)
            share_ax.set_ylim(0, 1.02)
            share_ax.set_xlabel("frequency [Hz]")
            share_ax.set_ylabel("share of the spectrum's energy below f")
            share_ax.set_title("where the energy lies (shaded: the middle 80 %)")
            if f_h:
                for ax in (spectrum_ax, share_ax):
                    ax.axvline(f_h, color="0.3", ls="--", lw=0.9,
                               label="f_h = %.4g Hz, the housing alone" % f_h)
            shown = [fk for fk in modes if fk <= fmax]
            for k, fk in enumerate(shown):  # the structure's modes, alone
                for ax in (spectrum_ax, share_ax):
                    ax.axvline(fk, color="0.55", ls=":", lw=0.8,
                               label="the structure's modes alone (%d up to %.3g kHz)"
                               % (len(shown), fmax / 1e3) if k == 0 else None)
            spectrum_ax.legend(loc="upper right", fontsize=8.5, framealpha=0.9)
            spectrum_ax.set_title("amplitude spectra (with the bearing the resonances lie "
                                  "above %s)" % ("the structure's own" if modes else "f_h"))
            share_ax.legend(loc="lower right", fontsize=8.5, framealpha=0.9)
        else:
            spectrum_ax.set_visible(False)
            share_ax.set_visible(False)
        if modes:
            fig.suptitle(run.title("the sensor %s on the structure's %d modes, %.4g to %.4g Hz "
                                   "alone" % (sensor[3:], len(modes), modes[0], modes[-1])))
        else:
            fig.suptitle(run.title("the sensor on the housing: m_h %s kg, f_h %s Hz, damping "
                                   "ratio %s" % tuple("%.4g" % housing.get(k, float("nan"))
                                                      for k in ("mass", "frequency",
                                                                "damping_ratio"))))
        fig.tight_layout()
    return fig
