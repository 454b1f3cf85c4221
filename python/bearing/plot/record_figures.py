"""The figures of an analysed record (``bearing-sim analyse``, ``bearing.analyse(...).write``):
its spectrum with the named peaks, its envelope spectrum, its squared envelope spectrum with
each fault family's comb of lines, and the coherence diagnosis's map and lines
(coherence_figure.py)."""

import os

import numpy as np

from .coherence_figure import coherence_figure
from .common import (DISPLAY, FolderError, _frequency_limit, _nice_ceiling, _new_figure, _style,
                     channel_label)
from .folders import _read_json, read_table
from .panels import spectrum_axes

FAMILY_COLORS = {"outer": "C3", "inner": "C2", "ball": "C4"}


class Analysis:
    """The files of one analysed record (tables are None when not written)."""

    def __init__(self, folder):
        self.folder = folder
        self.summary = _read_json(os.path.join(folder, "summary.json"))
        if "record" not in self.summary:
            raise FolderError("%s: summary.json has no record block" % folder)
        self.spectrum = read_table(folder, "spectrum")
        if self.spectrum is None:
            raise FolderError("%s: no spectrum.csv or spectrum.npy" % folder)
        self.envelope = read_table(folder, "envelope")

    @property
    def channel(self):
        return self.summary["record"]["channel"]

    @property
    def frequencies(self):
        return self.summary.get("frequencies", {})

    @property
    def name(self):
        record = self.summary["record"].get("file", "")
        base = os.path.basename(os.path.normpath(self.folder))
        return os.path.basename(record) + " (%s)" % base if record else base

    def title(self, what, extra=None):
        r = self.summary["record"]
        sp = self.summary.get("speed", {})
        parts = ["%s, channel %s" % (self.summary.get("case", {}).get("bearing", "?"),
                                     self.channel),
                 "%.6g Hz, %.4g s" % (r.get("rate", 0), r.get("duration", 0)),
                 "%.5g rpm (%s)" % (sp.get("rpm", 0), sp.get("source", "?"))]
        if r.get("prewhitened"):
            parts.append("pre-whitened")
        lines = ["%s — %s" % (self.name, what), " · ".join(parts)]
        return "\n".join(lines + ([extra] if extra else []))

    def frequency_line(self):
        fr = self.frequencies
        return "shaft %.4g Hz · FTF %.4g Hz · BPFO %.4g Hz · BPFI %.4g Hz · BSF %.4g Hz" % (
            fr.get("shaft", 0), fr.get("ftf", 0), fr.get("bpfo", 0), fr.get("bpfi", 0),
            fr.get("bsf", 0))


def load_analysis(folder):
    return Analysis(folder)


def _display(peaks, factor):
    return [dict(p, amplitude=p["amplitude"] * factor) for p in peaks]


def spectrum_figure(a):
    """The record's amplitude spectrum with summary.json's named peaks."""
    name = a.channel
    f = a.spectrum["frequency"]
    label, factor = channel_label(name, a.summary)
    peaks = _display(a.summary.get("peaks", {}).get(name, []), factor)
    amplitude = a.spectrum[name] * factor
    with _style():
        fig = _new_figure("record_spectrum")
        ax = fig.subplots(1, 1)
        spectrum_axes(ax, f, amplitude, peaks, label="amplitude of " + label,
                      fmax=_frequency_limit(f, amplitude, peaks), gid="spectrum:%s" % name)
        ax.set_title("%s: %d largest peaks (▼), named by %s" % (
            name, len(peaks), ", ".join(a.summary.get("peak_families", []))))
        fig.suptitle(a.title("amplitude spectrum", a.frequency_line()))
        fig.tight_layout()
    return fig


def _comb_axes(ax, f, ses, families, fmax):
    """The squared envelope spectrum [display unit²] with each family's rated lines marked."""
    line, = ax.plot(f, ses, color="C1", lw=0.8)
    line.set_gid("ses")
    top = np.max(ses[(f > 0) & (f <= fmax)]) if np.any((f > 0) & (f <= fmax)) else 1.0
    for family, info in families.items():
        lines = [l for l in info.get("lines", []) if l.get("rated") and not l.get("excluded")]
        if not lines:
            continue
        marker, = ax.plot([l["frequency"] for l in lines],
                          [l["amplitude"] for l in lines], "o", ms=5, mfc="none",
                          color=FAMILY_COLORS.get(family, "k"),
                          label="%s %.1f dB (threshold %.1f)%s" % (
                              family, info["evidence"], info["threshold"],
                              ", detected" if info.get("detected") else ""))
        marker.set_gid("ses:%s" % family)
    ax.set_xlim(0, fmax)
    ax.set_ylim(0, 1.25 * top)
    ax.set_xlabel("frequency [Hz]")
    ax.legend(loc="upper center", fontsize=8.5, framealpha=0.9, ncol=3)


def envelope_figure(a):
    """The envelope spectrum with its named peaks and band; the squared envelope spectrum with
    the fault families' lines and the diagnosis."""
    name = a.channel
    e = a.envelope
    f = e["frequency"]
    label, factor = channel_label(name, a.summary)
    unit = DISPLAY.get(a.summary["record"].get("unit", ""), ("", 1.0))[0]
    info = a.summary.get("envelope", {}).get(name, {})
    fr = a.frequencies
    fault = max(fr.get("bpfo", 0), fr.get("bpfi", 0), 2 * fr.get("bsf", 0))
    peaks = _display(info.get("peaks", []), factor)
    fmax = min(_nice_ceiling(max([4.5 * fault] + [1.15 * p["frequency"] for p in peaks])), f[-1])
    with _style():
        fig = _new_figure("record_envelope")
        top, bottom = fig.subplots(2, 1)
        spectrum_axes(top, f, e["env_" + name] * factor, peaks,
                      label="envelope amplitude\n" + label, fmax=fmax,
                      gid="envelope:%s" % name, log=False, color="C1")
        band = info.get("band", [float("nan")] * 2)
        top.set_title("%s: band %.4g–%.4g kHz (%s), spectral kurtosis %.3g" % (
            name, band[0] / 1e3, band[1] / 1e3, info.get("band_source", "?"),
            info.get("spectral_kurtosis", float("nan"))))
        if "ses_" + name in e:
            _comb_axes(bottom, f, e["ses_" + name] * factor ** 2,
                       a.summary.get("fault_lines", {}), fmax)
            bottom.set_ylabel("squared envelope\n[(%s)²]" % unit)
            settings = a.summary.get("fault_lines", {}).get("settings", {})
            bottom.set_title("squared envelope spectrum: each family's lines at its best slip "
                             "(○; ±%.3g %%, %d harmonics, false-alarm rate %.3g per family)" % (
                                 100 * settings.get("slip", 0), settings.get("harmonics", 0),
                                 settings.get("false_alarm", 0)))
        diagnosis = a.summary.get("diagnosis", {})
        if diagnosis:
            bottom.text(0.995, 0.80, "diagnosis: %s\n%s" % (
                diagnosis.get("family", "?"), _wrap(diagnosis.get("reason", ""), 80)),
                transform=bottom.transAxes, ha="right", va="top", fontsize=8.5,
                bbox=dict(boxstyle="round", fc="white", ec="0.6", alpha=0.9))
        fig.suptitle(a.title("envelope and squared envelope spectra", a.frequency_line()))
        fig.tight_layout()
    return fig


def _wrap(text, width):
    words, lines, line = text.split(), [], ""
    for w in words:
        if line and len(line) + 1 + len(w) > width:
            lines.append(line)
            line = w
        else:
            line = (line + " " + w).strip()
    return "\n".join(lines + [line])


def record_figures(a):
    """name -> Figure for every figure the analysis's files allow."""
    figures = {"spectrum": spectrum_figure(a)}
    if a.envelope is not None:
        figures["envelope"] = envelope_figure(a)
    if "coherence" in a.summary:
        figures["coherence"] = coherence_figure(a)
    return figures
