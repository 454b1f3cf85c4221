"""bearing: the rolling-bearing vibration toolkit (bearing-sim) from Python.

``bearing.plot`` (figures of runs, sweeps and FE contact outputs; also the ``bearing-plot``
program) is pure Python (NumPy, matplotlib) and works without the compiled extension.

A thin layer (pybind11) over the C++ library the command line uses: the same case files and
overrides, the same simulation and analysis, the same numbers to the last bit. Nothing physical is
computed in Python.

Units are SI everywhere (m, N, s, rad, rad/s, Pa, Hz); a value given as a string may carry a unit
as in a case file: ``"3000 rpm"``, ``"2 um"``, ``"0.05 kN"``.

Example::

    import bearing
    case = bearing.Case.default().set("operation.speed", "3000 rpm")
    result = bearing.run(case)                     # GIL released while it runs
    result.t, result["ay"]                         # s, m/s^2 (NumPy views, no copies)
    result.summary["channels"]["ay"]["rms"]        # m/s^2, as summary.json
    rows = bearing.sweep(case, vary={"waviness.inner.0.amplitude": "0um:1um:5"}, jobs=2)
    a = bearing.analyse(samples, 12000, case, speed="estimate")   # a measured record [m/s^2]
    a.summary["diagnosis"]["family"]                # "outer", "inner", "ball" or "none"

API
---
``Case``      a case: ``Case.from_file(path)``, ``Case.default()``, ``Case.from_toml(text)``;
              ``case.set(key, value)`` (as ``--set``), ``case.to_toml()``
``info``      ``bearing-sim info --json`` as a dict
``stiffness`` the bearing's 5x5 stiffness at the case's operating point averaged over one ball
              pass: the matrix a rotor model takes (``bearing-sim stiffness --format ross``)
``stiffness_at_cage_angle`` the same at the case's cage angle alone (depends on where the balls
              stand: one ball under a light load gives no sideways stiffness)
``damping`` the 5x5 squeeze-film damping of the EHL contacts (with ``[lubricant]``), averaged over
              one ball pass as ``stiffness``; ``damping_at_cage_angle`` at the cage angle alone
``ball_pass_stiffness`` that stiffness over one ball pass: its samples, mean, range and BPFO
              harmonics (the parametric excitation)
``SingularStiffnessWarning`` (a RuntimeWarning): ``stiffness`` is singular or near it, and why
``modes``     a structure's natural modes (``bearing-fem modes``): frequencies, seat and sensor
              shapes, as ``[housing] modes`` reads them
``run``       ``bearing-sim run``: a ``Result`` (``.t``, channels, ``.spectrum``, ``.summary``)
``sweep``     ``bearing-sim sweep``: the rows of sweep.csv (list of dicts or pandas DataFrame)
``analyse``   a measured record (NumPy array, SI) analysed: an ``Analysis`` (``.summary``, spectra)
``presets``   the bearing catalogue;  ``keys``, ``keys_help`` every case-file key
``InputError`` (a ValueError) and ``SolverError`` (a RuntimeError): the C++ library's messages,
              exactly as bearing-sim prints them after ``error:``.

Built by the project's CMake (``BEARING_WITH_PYTHON``, on when pybind11-dev and python3-dev are
installed) into ``build/python/bearing``: ``PYTHONPATH=build/python /usr/bin/python3``.
"""

import importlib as _importlib
import operator as _operator
import os as _os
import warnings as _warnings

__version__ = "0.1.0"

try:
    _bearing = _importlib.import_module(__name__ + "._bearing")
except ImportError as _error:  # the .py files are there but the extension was not built
    _bearing = None
    _import_error = _error

    def __getattr__(name):
        if name not in __all__:  # e.g. the submodule bearing.plot, which needs no extension
            raise AttributeError(f"module 'bearing' has no attribute {name!r}")
        raise ImportError(
            f"bearing.{name}: the compiled extension bearing._bearing is not available "
            f"({_import_error}). Build it with the project's CMake (BEARING_WITH_PYTHON=ON; "
            "Debian packages pybind11-dev python3-dev) for this interpreter (Debian's "
            "/usr/bin/python3) and put build/python on PYTHONPATH.")
else:
    Case = _bearing.Case
    Result = _bearing.Result
    Analysis = _bearing.Analysis
    InputError = _bearing.InputError
    SolverError = _bearing.SolverError
    InputError.__doc__ = (
        "Bad input: an unknown key, a wrong type or unit, a value outside its range. The message "
        "names the key, the value and what is allowed (bearing-sim exits with status 2).")
    SolverError.__doc__ = (
        "A numerical procedure that did not reach its answer, e.g. a blow-up; the message says "
        "why and what to change (bearing-sim exits with status 3).")

__all__ = ["Case", "Result", "Analysis", "InputError", "SolverError", "SingularStiffnessWarning",
           "info", "stiffness", "stiffness_at_cage_angle", "damping", "damping_at_cage_angle",
           "ball_pass_stiffness", "modes", "run", "sweep", "analyse", "presets", "keys",
           "keys_help"]


class SingularStiffnessWarning(RuntimeWarning):
    """:func:`stiffness` (K averaged over one ball pass) is singular or near it: no ball is loaded
    at any cage angle (the load sits in the clearance, K = 0), or the translations (x, y, z) or
    the tilts (gx, gy) have their smallest eigenvalue below 1e-9 times their largest (a direction
    the bearing supports at no cage angle). The message says which, and what to change; a rotor
    model on this bearing alone has a free rigid-body mode there. As the ``rotor.warnings`` of
    ``bearing-sim stiffness``'s stiffness.json (bearing/rotor_coefficients.h)."""


def _case(case):
    """A Case from a Case, or from a case file's path (str or os.PathLike)."""
    if isinstance(case, (str, _os.PathLike)):
        return _bearing.Case.from_file(_os.fspath(case))
    return case


def info(case):
    """Geometry-derived numbers of a case: ``bearing-sim info --json`` as a dict.

    ``case``: a :class:`Case`, or the path of a case file.

    Keys (SI): ``kinematics.{shaft,ftf,bpfo,bpfi,bsf}`` [Hz];
    ``contact.{inner,outer}.{sum_rho [1/m], f_rho [-], ellipticity [-], delta_star [-],
    K [N/m^n], exponent n [-]}``, ``contact.K`` [N/m^n] and ``contact.exponent`` of the ball
    between both races, ``contact.method``; ``static.deflection`` ([x, y] of the inner-ring centre,
    m), ``static.ball_angles`` [rad], ``static.ball_loads`` [N], ``static.q_max`` [N];
    ``case.{source,bearing,speed [rad/s],load [N]}``, ``units``; ``defects[]`` with
    ``[[defects]]``. Raises InputError or SolverError.

    >>> bearing.info(bearing.Case.default())["kinematics"]["bpfo"]   # Hz
    """
    return _bearing.info(_case(case))


def stiffness(case, samples=32):
    """The bearing's stiffness for a rotor model: K at the case's operating point AVERAGED OVER
    ONE BALL PASS, a 5x5 NumPy array (float64).

    K at one cage angle depends on where the balls stand: under a light radial load in the
    clearance one ball may sit right under the load, and the ring has no sideways stiffness there
    at all; as the cage turns on, two balls share the load. A linear rotor model holds the
    bearing's stiffness constant, so it takes the mean over one ball pitch,
    ``ball_pass_stiffness(case, samples)["mean"]``: the numbers of ``bearing-sim stiffness
    --format ross`` (its kxx, kxy, kyx, kyy are ``K[:2, :2]``) and of stiffness.json's
    ``rotor.stiffness``. ``samples``: the cage angles through one pitch, each its own equilibrium
    under the load (an integer from 4 to 4096; default 32, as ``bearing-sim stiffness``). K at
    the case's cage angle alone: :func:`stiffness_at_cage_angle`. Where the mean is singular or
    near it, a :class:`SingularStiffnessWarning` says why (the ``warnings`` module: printed on
    stderr once by default; ``warnings.simplefilter("error", bearing.SingularStiffnessWarning)``
    makes it an exception).

    ``case``: a :class:`Case`, or the path of a case file. K = dF/dq of the 5-DOF static solution
    of the inner ring (as ``bearing-sim stiffness`` and ``info`` compute it): q = (x, y, z, gx, gy)
    its displacement [m] and tilts about +x, +y [rad], F = (Fx, Fy, Fz, Mx, My) the load on it
    [N, N*m]: ``operation.load`` (with the rotor weight when ``operation.gravity``),
    ``operation.axial_load`` and ``operation.moment``, whatever ``model.kind``. Units: K[:3, :3]
    N/m, K[:3, 3:] N/rad, K[3:, :3] N (= N*m/m), K[3:, 3:] N*m/rad; symmetric. Assumed: rigid
    rings, each ball's centrifugal load at ``operation.speed`` (``ball.centrifugal``, on by
    default), the gyroscopic moment neglected. With ``[lubricant]`` (and a speed: the film needs
    entrainment) each contact's EHL film is in series with Hertz (its damping: :func:`damping`);
    without it the contacts are dry. With no ball loaded (no load, the ring in the clearance) K
    is 0. Raises TypeError (``samples`` not an integer), InputError (``samples`` out of range,
    the case) or SolverError (an equilibrium not reached at a cage angle).

    >>> k = bearing.stiffness(bearing.Case.default().set("operation.axial_load", "100 N"))
    >>> k[1, 1]                                   # k_yy [N/m], averaged over one ball pass
    """
    k, warnings = _bearing.stiffness(_case(case), _operator.index(samples))
    for w in warnings:
        _warnings.warn(w, SingularStiffnessWarning, stacklevel=2)
    return k


def stiffness_at_cage_angle(case):
    """The bearing's stiffness at the case's operating point AND CAGE ANGLE: a 5x5 NumPy array.

    K = dF/dq as :func:`stiffness`, but at the one equilibrium with ball 0 at the case's cage
    angle (the cage phase a run starts at) instead of averaged over one ball pass. It depends on
    where the balls stand, so it is not what a rotor model takes: the 6308 of
    examples/seed003_6308.toml has one ball right under its 20 N, and k_xx = 0 there. It is
    stiffness.json's ``stiffness_at_cage_angle``, stiffness.csv's k_ij and
    ``bearing.info(case)["stiffness"]["matrix"]``; the displacement, ball loads and contact
    angles there: ``bearing.info(case)["stiffness"]``. Units as :func:`stiffness`'s. Raises
    InputError or SolverError.
    """
    return _bearing.stiffness_at_cage_angle(_case(case))


def damping(case, samples=32):
    """The bearing's damping for a rotor model: C at the case's operating point AVERAGED OVER ONE
    BALL PASS (as :func:`stiffness`), a 5x5 NumPy array (float64); ROSS's cxx, cxy, cyx, cyy of
    ``bearing-sim stiffness --format ross`` are ``C[:2, :2]``, stiffness.json's
    ``rotor.damping`` the whole. At the case's cage angle alone: :func:`damping_at_cage_angle`.

    ``case``: a :class:`Case`, or the path of a case file. C = dF/d(dq/dt) of the same 5-DOF
    static solution as :func:`stiffness` (q, F as there), at each cage angle: the squeeze films of the EHL contacts
    (Reynolds' isoviscous squeeze at the central film, a lower estimate; the two contacts of a
    ball in series), when the case has ``[lubricant]``; 0 without it (dry contacts) or at rest
    (no entrainment, no film). Units: C[:3, :3] N*s/m, C[:3, 3:] N*s/rad, C[3:, :3] N*s,
    C[3:, 3:] N*m*s/rad; symmetric. Raises InputError or SolverError.

    >>> c = bearing.damping(bearing.Case.default().update({"lubricant.viscosity": "0.02 Pa s",
    ...     "lubricant.pressure_viscosity": "2e-8 1/Pa", "lubricant.roughness": "0.1 um"}))
    >>> c[1, 1]                                   # c_yy [N*s/m]
    """
    return _bearing.damping(_case(case), _operator.index(samples))


def damping_at_cage_angle(case):
    """The damping C of :func:`damping` at the case's operating point AND CAGE ANGLE alone (ball 0
    at the case's cage phase): a 5x5 NumPy array, stiffness.json's ``damping_at_cage_angle``.
    Units as :func:`damping`'s. Raises InputError or SolverError."""
    return _bearing.damping_at_cage_angle(_case(case))


def ball_pass_stiffness(case, samples=32):
    """The bearing's stiffness over one ball pass: a dict of NumPy arrays (float64, SI).

    ``case``: a :class:`Case`, or the path of a case file. As the cage turns, the balls pass the
    load zone and K (the matrix of :func:`stiffness`) varies with the cage angle; the ball set
    repeats after one pitch 2*pi/Z, so K is periodic at the ball-pass frequency over the outer
    race (BPFO): the parametric excitation the dynamic models feel. K is solved at ``samples``
    cage angles (an integer from 4 to 4096; as ``bearing-sim stiffness --ball-pass N``) through
    one pitch from the case's cage phase, each its own equilibrium under the same load, at the
    case's speed (each ball's centrifugal load). Keys:

    - ``cage_angles`` [N]: the cage angles phi_k = phi_0 + k (2*pi/Z)/N [rad];
    - ``samples`` [N, 5, 5]: K at each (``samples[0]`` is ``stiffness_at_cage_angle(case)``);
    - ``mean``, ``min``, ``max`` [5, 5]: over the pitch, entry by entry (``mean`` is
      ``stiffness(case, samples)``, the matrix a rotor model takes);
    - ``harmonics`` [(N - 1) // 2, 5, 5]: ``harmonics[m - 1]`` each entry's amplitude at m x BPFO,
      (2/N) |sum_k K_k exp(-2*pi*i*m*k/N)|, every m < N/2 (m = 1 ... N/2 - 1 for an even N);
    - ``damping_samples`` [N, 5, 5], ``damping_mean`` [5, 5]: the damping C (:func:`damping`;
      0 without ``[lubricant]``) at each cage angle and its mean over the pitch, units K's times s;
    - ``bpfo``: the BPFO at ``operation.speed`` [Hz] (outer ring fixed, pure rolling), so
      harmonic m lies at m * bpfo.

    Units of every matrix as :func:`stiffness`'s: [:3, :3] N/m, [:3, 3:] N/rad, [3:, :3] N,
    [3:, 3:] N*m/rad. Raises TypeError (``samples`` not an integer), InputError (``samples`` out
    of range, the case) or SolverError (an equilibrium not reached at a cage angle).

    >>> bp = bearing.ball_pass_stiffness(bearing.Case.default(), samples=32)
    >>> bp["max"][1, 1] - bp["min"][1, 1], bp["harmonics"][0, 1, 1]   # k_yy ripple [N/m]
    """
    return _bearing.ball_pass_stiffness(_case(case), _operator.index(samples))


def modes(path):
    """A structure's natural modes as ``bearing-fem modes`` wrote them: a dict (float64, SI).

    ``path``: the folder of ``bearing-fem modes ... --out DIR``, or its ``modes.json``. Read and
    checked by the C++ reader that ``[housing] modes = "..."`` uses (InputError naming the key,
    as bearing-sim would). Shapes are mass-normalised (phi^T M phi = 1 kg), so a shape value is a
    displacement per unit modal coordinate [kg^-1/2]; the frame is the bearing's (z the shaft's
    axis, y up). Keys:

    - ``frequencies`` [M]: the elastic modes [Hz], ascending (rigid-body modes are never there);
    - ``seat`` [M, 3]: the seat's rigid translation x, y, z per mode [kg^-1/2], what drives and
      moves the bearing's outer ring;
    - ``sensors``: name -> {``point`` [3] (m, the surface point used), ``shape`` [M, 3]};
    - ``free``: whether no surface is held (free-free; such a structure cannot carry a bearing);
    - ``file``: the modes.json read;
    - ``document``: the whole file as a dict (tilts, fit residuals, effective masses, mesh, solver,
      orthogonality: fem/README.md, "Structure modes").

    >>> m = bearing.modes("out/shield")
    >>> m["frequencies"][:3], m["seat"][0], m["sensors"]["top"]["shape"][0]
    """
    import json as _json
    file = _os.path.join(path, "modes.json") if _os.path.isdir(path) else path
    out = _bearing.read_modes(file)
    with open(file, encoding="utf-8") as f:
        out["document"] = _json.load(f)
    return out


def run(case):
    """Simulates and analyses a case as ``bearing-sim run`` does; returns a :class:`Result`.

    ``case``: a :class:`Case`, or the path of a case file. The GIL is released during the run, so
    other Python threads go on. Raises InputError (bad settings) or SolverError (blow-up, no
    convergence) with bearing-sim's messages.

    The result (arrays are read-only NumPy float64 views of the C++ result, no copies):

    - ``result.t`` [s]: output times from 0 at ``solver.output_rate``;
    - ``result["ay"]`` or ``result.ay``: a channel (``x, y`` m; ``vx, vy`` m/s; ``ax, ay`` m/s^2;
      3-DOF ``z, vz, az``; ``Q1…`` N, ``d1…`` m, ``r1…`` m, ``vr1…`` m/s when asked for in
      [output]); ``result.channels``: {name: SI unit} in response.csv's order;
      ``result.response``: {"t": …, name: …} (``pandas.DataFrame(result.response)`` is
      response.csv);
    - ``result.spectrum``: {"frequency" [Hz], ring channel: one-sided amplitude [channel unit]}
      over [transient, duration) (spectrum.csv);
    - ``result.envelope`` (with ``output.envelope_band``, else None): {"frequency" [Hz],
      "env_ax" … [m/s^2]}; ``result.pressure`` (with [acoustics], else None): {"t" [s],
      "p1" … [Pa]};
    - ``result.summary``: summary.json's content as a dict (equal to ``json.load`` of the CLI's
      file); ``str(result)``: the readable summary; ``result.case_toml``: case.toml;
      ``result.write(dir)``: the CLI's result files.

    >>> r = bearing.run(bearing.Case.default().set("solver.duration", "0.5 s"))
    >>> r.summary["channels"]["ay"]["rms"]        # m/s^2
    """
    return _bearing.run(_case(case))


def sweep(case, vary, jobs=0, as_dataframe=None):
    """Runs a case for every combination of ``vary`` as ``bearing-sim sweep`` does.

    ``vary``: {key: spec}, a spec being ``"FROM:TO:N"`` as ``--vary`` takes it (units allowed:
    ``"1000rpm:3000rpm:5"``), or a list of values (numbers in SI, or strings with units). The
    Cartesian product of the keys in order, the first slowest. ``jobs``: parallel cases, the C++
    sweep's threads (0: all cores); the GIL is released meanwhile.

    Returns one row per case in case order, the columns of sweep.csv: the varied values (SI),
    ``status`` ("ok"/"failed"), ``error`` (the message of a failed case), then per ring channel
    ``<ch>.rms``, ``<ch>.ptp`` [channel unit], ``<ch>.kurtosis``, ``<ch>.crest`` [-],
    ``<ch>.peak_frequency`` [Hz], ``<ch>.peak_label``, with [acoustics] per microphone
    ``mic<i>.spl_total``, ``mic<i>.spl_ring``, ``mic<i>.spl_balls`` [dB re 20 uPa], and with
    ``output.envelope_band`` per ring acceleration ``env_<ch>.band_low``, ``env_<ch>.band_high``
    [Hz], ``env_<ch>.spectral_kurtosis``, ``env_<ch>.energy_fraction`` [-],
    ``env_<ch>.peak_frequency`` [Hz], ``env_<ch>.peak_amplitude`` [m/s^2], ``env_<ch>.peak_label``,
    then ``diagnosis.family`` ("outer", "inner", "ball", "none"), ``diagnosis.channel``,
    ``diagnosis.spectral_kurtosis``, ``diagnosis.family_share`` [-],
    ``diagnosis.evidence_labels``, ``diagnosis.evidence_frequencies``,
    ``diagnosis.evidence_amplitudes`` (texts: lists joined by ";") and ``diagnosis.reason``
    (docs/bearing-sim.md, sweep); fields sweep.csv leaves empty are None. A pandas DataFrame if pandas can be imported (``as_dataframe=None``),
    else a list of dicts; ``as_dataframe=False`` always gives the list, ``True`` requires pandas.
    A failed case does not stop the others; a bad key or spec raises InputError.

    >>> rows = bearing.sweep(bearing.Case.default(),
    ...                      vary={"operation.speed": "1000rpm:3000rpm:5"}, jobs=2)
    >>> [r["ay.rms"] for r in rows]               # m/s^2
    """
    rows = _bearing.sweep(_case(case), dict(vary), int(jobs))
    if as_dataframe is False:
        return rows
    try:
        import pandas
    except ImportError:
        if as_dataframe:
            raise
        return rows
    return pandas.DataFrame(rows)


def analyse(samples, rate, case, speed=None, *, speed_source="option", channel="record",
            unit="m/s^2", prewhiten=True, band="auto", rule="coherence", false_alarm=1e-3,
            slip=0.02, harmonics=3, speed_refinement=0.03, file="", speed_origin=""):
    """Analyses a measured record as ``bearing-sim analyse`` does; returns an :class:`Analysis`.

    ``samples``: a 1-D array of one channel in SI (``unit``: "m/s^2", "m/s" or "m"; convert g
    with 9.80665 first); ``rate``: its sampling rate [Hz]; ``case``: a :class:`Case` or a case
    file's path, giving the bearing (``bearing.preset = "6205"`` suffices), the nominal speed
    and the spectrum's window and peak count. ``speed``: None (the case's ``operation.speed``),
    ``"estimate"`` (the shaft frequency found from the record's shaft harmonics within ±10 % of
    the case's speed), or the speed itself: a number [rad/s] or a string with a unit
    (``"1797 rpm"``), whose source is ``speed_source`` ("option", or "record" for a speed the
    file stored); a given speed is refined from the record's shaft harmonics within
    ±``speed_refinement`` where they stand out (0: used as given). ``prewhiten``: cepstral
    pre-whitening before the envelope analysis (default on). ``band``: "auto" (the kurtogram's),
    "none", or (low, high) [Hz, or strings with units]. ``rule``: "coherence" (default: each
    family in its band of the pre-whitened record's cyclic-coherence map, 2 of 3 harmonics within
    ±``slip`` over a threshold from ``false_alarm`` per family and record, the record's own
    decoys, each family's sidebands; two race families clearly present give "several"),
    "line_to_floor" (the kurtogram band's fault lines over their floor, ``harmonics`` harmonics)
    or "envelope_peaks" (run's rule). ``channel`` names the channel in
    the outputs; ``file`` and ``speed_origin`` are recorded in the summary. The GIL is released
    meanwhile. Raises InputError naming what is wrong (a NaN sample, a rate <= 0, a record too
    short, no shaft line found by the estimate, ...).

    The result: ``.summary`` (summary.json's content as a dict: record, speed and its source,
    frequencies [Hz], channels, peaks, envelope, fault_lines, coherence, diagnosis, units),
    ``.family`` (the diagnosis: "outer", "inner", "ball", "several" or "none"), ``.margin``
    (its margin [dB]), ``.coherence`` (the map and each family's evidence), ``.spectrum`` ({"frequency" [Hz], channel: amplitude}), ``.envelope``
    ({"frequency", "env_<channel>" [unit], "ses_<channel>" [unit^2]} or None), ``str(a)`` (the
    readable summary) and ``.write(dir, format="csv")`` (spectrum, envelope, summary.json, all or
    nothing; ``bearing-plot dir`` draws it).

    >>> a = bearing.analyse(x, 12000, bearing.Case.from_toml('[bearing]\npreset = "6205"\n'
    ...                     '[operation]\nspeed = "1797 rpm"'))
    >>> a.family, a.margin                                 # "inner", 16.4 (dB)
    >>> a.coherence["families"]["inner"]["harmonics"]     # each harmonic's excess [dB]
    """
    return _bearing.analyse(samples, float(rate), _case(case), speed, speed_source, channel, unit,
                            bool(prewhiten), band, rule, float(false_alarm), float(slip),
                            int(harmonics), float(speed_refinement), file, speed_origin)


def presets():
    """The bearing catalogue: {designation: where its numbers come from} (``bearing-sim presets``).

    A designation is a case's ``bearing.preset`` (e.g. ``case.set("bearing.preset", "6205")``);
    its dimensions are in SI in ``Case.from_toml('[bearing]\\npreset = "6205"').to_toml()``.
    """
    return _bearing.presets()


def keys():
    """Every case-file key ``Case.set`` and ``sweep`` accept, as "table.key" (a numeric part such
    as ``waviness.inner.0.amplitude`` indexes an array of tables); ``print(bearing.keys_help())``
    gives each key's meaning and units."""
    return _bearing.keys()


def keys_help():
    """One line per case-file key: its name, what it is and the units it accepts (as ``bearing-sim
    run --help`` lists them); plain numbers are SI."""
    return _bearing.keys_help()
