"""Figures of bearing-sim runs and sweeps, of bearing-fem contact and calibrate outputs, and of
the bearing-verify report.

    bearing-plot FOLDER|CALIBRATION.json [--out DIR] [--format png|svg|pdf]
    /usr/bin/python3 -m bearing.plot FOLDER [...]        (with PYTHONPATH=build/python)

FOLDER is recognised by its files:

- a run (``bearing-sim run --out FOLDER``: ``summary.json`` and ``response.csv`` or
  ``response.npy``) gives ``time``: x, y, ax, ay (3-DOF, and balls with an axial load: also the
  axial z, az) over the whole record (transient shaded) and over the last four ball passes
  (dotted: a ball on the load line); ``orbit``: the inner-ring centre in the x-y plane with the
  clearance circle (radius P_d/2); ``spectrum``: the amplitude spectra of x, y, ax, ay (and z,
  az) with summary.json's labelled peaks; ``envelope`` (with ``output.envelope_band``): the
  envelope spectra (env_ax, env_ay, env_az), peaks, band, spectral kurtosis and diagnosis;
  ``ball_loads`` (with ``output.ball_loads``): Q_j against the ball's angle around the bearing
  (polar) and in time; ``ball_channels`` (with ``output.ball_approach``, ``output.ball_motion``
  or an ``[acoustics]`` ball source, and for ``balls`` ``output.ball_dynamics``): each per-ball
  channel d_j, r_j, vr_j, wb_j, Qo_j, Fi_j, Fo_j of every ball in time; ``spl`` (with
  ``[acoustics]``): the SPL per microphone (total, ring, balls) and p(t);
  ``sensor`` (with ``[housing]``): the housing's ay_housing (with ``[housing] modes``: the first
  sensor's ay_<name>) beside the ring's ay over the last ball passes, both spectra with f_h (the
  structure's modes) marked, and each one's cumulative energy share against frequency (the orbit
  is then the ring relative to the housing, or to the seat);
- an analysed record (``bearing-sim analyse RECORD --out FOLDER``, ``bearing.analyse(...).write``:
  ``summary.json`` with a ``record`` block and ``spectrum.csv`` or ``.npy``) gives ``spectrum``:
  the record's amplitude spectrum with its named peaks; ``envelope`` (with an envelope band): the
  envelope spectrum with its peaks, band and spectral kurtosis, and the squared envelope spectrum
  with each fault family's lines at its best slip, its evidence and threshold [dB], and the
  diagnosis;
- a sweep (``bearing-sim sweep --out FOLDER``: ``sweep.csv``) gives ``sweep_<statistic>`` (rms,
  ptp, kurtosis, crest, peak_frequency; one panel per ring channel) and ``sweep_spl``: against the
  varied key as lines (one key), as heat maps (two keys), as points against each key (three and
  more);
- a stiffness output (``bearing-sim stiffness --out FOLDER``: ``stiffness.csv``) gives
  ``stiffness``: the bearing's stiffness terms at the case's cage angle against the first varied
  key, one panel per unit (N/m: forces by displacements, N/rad: forces by tilts, N·m/rad: moments
  by tilts), each diagonal term solid and the largest couplings above round-off dashed; a single
  point as bars; with ``ball_pass`` in ``stiffness.json``, each diagonal term's range over one
  ball pass as a band around its curve (a black bar on a single point's bar) and its mean over
  it, the rotor's K (``rotor``), dotted (a black diamond on a single point's bar);
- a contact output (``bearing-fem contact --out FOLDER``: ``force_approach.csv`` and
  ``contact.json``) gives ``force_approach``: the FE force against the approach on log axes with
  the Hertz law, and the FE/Hertz deviation of force, semi-axes and peak pressure per step;
- a modes output (``bearing-fem modes STRUCTURE.toml --out FOLDER``: ``modes.json``) gives
  ``modes``: per mode, the seat's rigid translation (x, y, z), its tilts, and each sensor's
  displacement (x, y, z), in the mass-normalised shapes' units, against the mode's number and
  frequency;
- a calibration (``bearing-fem calibrate CASE --out DIR/STEM.json``: the JSON file, or a folder
  holding one, e.g. ``bearing-verify calibrate``'s) gives ``calibration``: per race the FE force
  against approach (from the race folder DIR/STEM_inner, _outer when it is there) with the
  calibrated Q = K delta^n and Hertz's law, and below both laws' and the FE points' departure
  from Hertz against the load.

The figures go to ``FOLDER/plots/`` (for ``DIR/STEM.json``: ``DIR/STEM_plots/``) unless
``--out`` says otherwise; a figure of the same name and format an earlier call left there and
this folder no longer gives (e.g. ``spl`` after a rerun without acoustics) is removed. Exit
status: 0 written, 2 the folder (or file) is none of the above.

Library use: ``load_run(folder)``, ``run_figures(run)`` (name -> matplotlib Figure),
``record_figures(load_analysis(folder))``,
``sweep_figures(load_sweep(folder))``, ``stiffness_figure(load_stiffness(folder))``,
``contact_figure(load_contact(folder))``,
``calibration_figure(load_calibration(path))``, ``modes_figure(load_modes(folder))``,
``plot_folder(folder, out, fmt)``; and the panel
functions ``trace_axes``, ``orbit_axes``, ``spectrum_axes``, ``ball_load_axes``, ``spl_axes``,
``force_approach_axes``, ``series_axes``, ``mark_lines``, ``sweep_line_axes``,
``sweep_heatmap_axes`` that draw plain NumPy arrays on a given Axes. The bearing-verify report
draws its figures with these panels too: ``report_figure(spec)`` for one entry of its
figures.json, ``draw_report_figures(figures_json, out_dir)`` (called by
verification/plot_figures.py). Only NumPy and matplotlib are used (no compiled extension).
Every data artist carries a gid (``"spectrum:ay"``, ``"orbit"``, ...) so a test can read the
plotted values back.

Units: the data are the files' SI values times the display factor of ``DISPLAY`` (m -> um,
m/s -> mm/s, rad/s -> rpm, ...), written on every axis.
"""

import sys

try:
    import matplotlib  # noqa: F401
except ImportError as _error:  # pragma: no cover - depends on the machine
    raise ImportError("bearing.plot needs matplotlib for %s (Debian: python3-matplotlib): %s"
                      % (sys.executable, _error)) from _error

from .common import (  # noqa: F401
    BALL_PASSES_ZOOMED, DISPLAY, DPI, FORMATS, FolderError, QUANTITY, RING_UNITS, SIZES,
    STATISTICS, STATISTIC_NAMES, STYLE, ball_channels_size, channel_label, channel_unit,
    load_line_passes, ring_channel)
from .folders import (  # noqa: F401
    CALIBRATION_FORMAT, Calibration, Contact, Run, Sweep, Table, calibration_file, case_name,
    case_parameters, detect, load_calibration, load_contact, load_run, load_sweep, read_table)
from .panels import (  # noqa: F401
    ball_load_axes, force_approach_axes, label_peaks, mark_lines, orbit_axes, plain_log_ticks,
    series_axes, spectrum_axes, spl_axes, sweep_heatmap_axes, sweep_line_axes, trace_axes)
from .run_figures import (  # noqa: F401
    BALL_CHANNELS, RING_DRAWN, ball_angles, ball_channel_families, ball_channel_figure,
    ball_load_figure, envelope_figure, orbit_figure, run_figures, spectrum_figure, spl_figure,
    time_figure)
from .sweep_figures import (  # noqa: F401
    STATISTIC_SHORT, channel_title, key_display, statistic_display, sweep_figures)
from .stiffness_figure import (  # noqa: F401
    Stiffness, load_stiffness, panel_terms, stiffness_figure, term_name, term_unit)
from .contact_figure import contact_figure  # noqa: F401
from .calibration_figure import calibration_figure  # noqa: F401
from .modes_figure import Modes, load_modes, modes_figure  # noqa: F401
from .record_figures import Analysis, load_analysis, record_figures  # noqa: F401
from .cli import KNOWN_NAMES, default_out, figures_of, main, plot_folder, save  # noqa: F401
from .report_figures import (  # noqa: F401
    PANELS, display_label, draw_report_figures, report_figure)
