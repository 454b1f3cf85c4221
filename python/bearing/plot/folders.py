"""Reading the folders bearing.plot draws: a run, a sweep, a bearing-fem contact output (a modes
folder: modes_figure.py)."""

import csv
import json
import os

import numpy as np

from .common import DISPLAY, FolderError
from .modes_figure import is_modes_folder


# --- reading ----------------------------------------------------------------------------------

class Table:
    """A table of named columns (a CSV with a header row, or an .npy with columns.json)."""

    def __init__(self, names, data, path):
        self.names = list(names)
        self.data = data
        self.path = path
        self._index = {n: i for i, n in enumerate(self.names)}

    def __contains__(self, name):
        return name in self._index

    def __getitem__(self, name):
        return self.data[:, self._index[name]]


def read_table(folder, stem):
    """FOLDER/stem.csv or FOLDER/stem.npy (+ columns.json) as a Table; None if neither exists."""
    path = os.path.join(folder, stem + ".csv")
    if os.path.exists(path):
        with open(path) as f:
            names = f.readline().strip().split(",")
        try:
            data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
        except ValueError as e:
            raise FolderError("%s: not a table of numbers (%s)" % (path, e)) from e
        return Table(names, data.reshape(-1, len(names)), path)
    path = os.path.join(folder, stem + ".npy")
    if os.path.exists(path):
        meta_path = os.path.join(folder, "columns.json")
        try:
            with open(meta_path) as f:
                names = json.load(f)["tables"][stem + ".npy"]["columns"]
        except (OSError, KeyError, ValueError) as e:
            raise FolderError("%s: no column names for %s.npy (%s)" % (meta_path, stem, e)) from e
        return Table(names, np.load(path), path)
    return None


def _read_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        raise FolderError("%s: %s" % (path, e)) from e


def _read_case_toml(path):
    """The resolved case.toml as a dict ({} if absent); tomllib (Python >= 3.11) or a fallback
    that reads `key = number` lines per table, which is all the figures need."""
    if not os.path.exists(path):
        return {}
    try:
        import tomllib
        with open(path, "rb") as f:
            return tomllib.load(f)
    except ImportError:
        pass
    case = {}
    current = case
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line.startswith("[["):
                current = None  # arrays of tables: not needed by the figures
            elif line.startswith("["):
                current = case
                for part in line.strip("[]").split("."):
                    current = current.setdefault(part.strip(), {})
            elif "=" in line and current is not None:
                key, value = (s.strip() for s in line.split("=", 1))
                try:
                    current[key] = float(value)
                except ValueError:
                    current[key] = value.strip('"')
    return case


class Run:
    """The files of one `bearing-sim run --out FOLDER` (tables are None when not written)."""

    def __init__(self, folder):
        self.folder = folder
        self.summary = _read_json(os.path.join(folder, "summary.json"))
        self.case = _read_case_toml(os.path.join(folder, "case.toml"))
        self.response = read_table(folder, "response")
        if self.response is None:
            raise FolderError("%s: no response.csv or response.npy" % folder)
        self.spectrum = read_table(folder, "spectrum")
        self.envelope = read_table(folder, "envelope")
        self.pressure = read_table(folder, "pressure")

    @property
    def name(self):
        return case_name(self.summary.get("case", {}).get("source", ""), self.folder)

    @property
    def clearance(self):
        """P_d [m], the diametral clearance (case.toml), or None."""
        value = self.case.get("bearing", {}).get("clearance")
        return float(value) if isinstance(value, (int, float)) else None

    @property
    def frequencies(self):
        return self.summary.get("frequencies", {})

    @property
    def transient(self):
        return float(self.summary.get("case", {}).get("transient", 0.0))

    @property
    def balls(self):
        z = self.case.get("bearing", {}).get("balls")
        if isinstance(z, (int, float)):
            return int(z)
        return sum(1 for n in self.response.names if n[:1] == "Q" and n[1:].isdigit())

    def title(self, what, extra=None):
        """'name — what', the case's parameters, and `extra` on a third line."""
        lines = ["%s — %s" % (self.name, what), case_parameters(self.summary, self.case)]
        return "\n".join(lines + ([extra] if extra else []))

    def frequency_line(self):
        fr = self.frequencies
        return "shaft %.4g Hz · FTF %.4g Hz · BPFO %.4g Hz · BPFI %.4g Hz · BSF %.4g Hz" % (
            fr.get("shaft", 0), fr.get("ftf", 0), fr.get("bpfo", 0), fr.get("bpfi", 0),
            fr.get("bsf", 0))


def case_name(source, folder):
    """A short name: the case file's stem, 'default case', or the run folder's name."""
    base = os.path.basename(os.path.normpath(folder))
    if source.endswith(".toml"):
        stem = os.path.splitext(os.path.basename(source))[0]
        if stem == "case":  # a rerun of a resolved case: the folder it came from says more
            stem = os.path.basename(os.path.dirname(os.path.abspath(source))) or stem
        return "%s (%s)" % (stem, base) if stem != base else stem
    if source.startswith("built-in"):
        return "default case (%s)" % base
    return base


def case_parameters(summary, case):
    """One line of the parameters an engineer looks for first."""
    c = summary.get("case", {})
    parts = []
    if c.get("bearing"):
        parts.append(str(c["bearing"]))
    if c.get("model"):
        parts.append("model %s" % c["model"])
    if "speed" in c:
        parts.append("%.0f rpm" % (c["speed"] * DISPLAY["rad/s"][1]))
    load = c.get("load")
    if load:
        parts.append("load (%s) N" % ", ".join("%.4g" % v for v in load))
    if c.get("axial_load"):
        parts.append("axial %.4g N" % c["axial_load"])
    clearance = case.get("bearing", {}).get("clearance")
    if isinstance(clearance, (int, float)):
        parts.append("P_d %.3g µm" % (clearance * 1e6))
    method = case.get("solver", {}).get("method")
    if c.get("model") == "quasistatic":
        method = "quasistatic"
    if "duration" in c:
        parts.append("%s%.3g s (transient %.3g s)" % (method + " " if method else "",
                                                      c["duration"], c.get("transient", 0.0)))
    if c.get("contact"):
        parts.append("contact %s" % c["contact"])
    return " · ".join(parts)


class Sweep:
    """sweep.csv: the varied keys, and per case its status and numbers (strings kept as text)."""

    def __init__(self, folder):
        self.folder = folder
        self.path = os.path.join(folder, "sweep.csv")
        with open(self.path, newline="") as f:
            rows = list(csv.reader(f))
        if not rows or "status" not in rows[0]:
            raise FolderError("%s: no header with a status column" % self.path)
        self.header = rows[0]
        self.keys = self.header[:self.header.index("status")]
        self.rows = [dict(zip(self.header, r)) for r in rows[1:] if r]
        self.ok = np.array([r.get("status") == "ok" for r in self.rows], dtype=bool)

    def column(self, name):
        """The column as floats (NaN where empty, not a number, or the case failed)."""
        out = np.full(len(self.rows), np.nan)
        for i, r in enumerate(self.rows):
            try:
                out[i] = float(r.get(name, ""))
            except ValueError:
                pass
        out[~self.ok] = np.nan
        return out

    def text(self, name):
        return [r.get(name, "") for r in self.rows]

    @property
    def varied(self):
        """The keys that take more than one value."""
        return [k for k in self.keys if len(np.unique(self.column_all(k))) > 1] or self.keys[:1]

    def column_all(self, name):
        """A key's column for every case, failed or not."""
        return np.array([float(r[name]) for r in self.rows])

    @property
    def channels(self):
        return [n[:-4] for n in self.header if n.endswith(".rms")]

    @property
    def microphones(self):
        return [n[:-10] for n in self.header if n.endswith(".spl_total")]

    @property
    def name(self):
        return os.path.basename(os.path.normpath(self.folder))


class Contact:
    """The files of one `bearing-fem contact --out FOLDER`."""

    def __init__(self, folder):
        self.folder = folder
        self.json = _read_json(os.path.join(folder, "contact.json"))
        self.curve = read_table(folder, "force_approach")
        if self.curve is None or "approach" not in self.curve or "force" not in self.curve:
            raise FolderError("%s: force_approach.csv has no approach and force columns" % folder)

    @property
    def name(self):
        source = self.json.get("case", "")
        stem = os.path.splitext(os.path.basename(source))[0] if source else ""
        base = os.path.basename(os.path.normpath(self.folder))
        return "%s (%s)" % (stem, base) if stem and stem != base else base


CALIBRATION_FORMAT = "bearing-fem calibration 1"


class Calibration:
    """A `bearing-fem calibrate CASE --out FILE.json` output: the file (both races' fitted
    Q = K delta^n) and, when present beside it, each race's contact folder (FILE's `details`:
    <stem>_inner/, <stem>_outer/ with force_approach.csv and contact.json)."""

    RACES = ("inner", "outer")

    def __init__(self, path):
        self.path = path
        self.json = _read_json(path)
        if self.json.get("format") != CALIBRATION_FORMAT:
            raise FolderError("%s: not a bearing-fem calibration (format %r, expected %r)"
                              % (path, self.json.get("format"), CALIBRATION_FORMAT))
        for race in self.RACES:
            law = self.json.get(race, {})
            for key in ("K", "exponent", "hertz_K"):
                if not isinstance(law.get(key), (int, float)) or not law[key] > 0:
                    raise FolderError("%s: %s.%s is %r, expected a positive number"
                                      % (path, race, key, law.get(key)))
        self.contacts = {}  # race -> Contact, for the races whose folder is there
        self.missing = {}  # race -> the folder looked for
        here = os.path.dirname(os.path.abspath(path))
        for race in self.RACES:
            details = self.json[race].get("details", "")
            folder = os.path.join(here, details) if details else ""
            if folder and os.path.isfile(os.path.join(folder, "force_approach.csv")):
                self.contacts[race] = Contact(folder)
            else:
                self.missing[race] = folder or "(no details folder named)"

    def law(self, race):
        """(K [N/m^n], n) of the race's calibrated law."""
        return self.json[race]["K"], self.json[race]["exponent"]

    @property
    def load_range(self):
        """[lowest, highest] ball load [N] the laws were fitted over."""
        return [float(v) for v in self.json.get("load_range", [])]

    @property
    def name(self):
        return os.path.splitext(os.path.basename(self.path))[0]


def calibration_file(path):
    """The calibration JSON a path names: the file itself, or the one such file in a folder
    (bearing-verify calibrate's DIR/calibration.json); None if there is none."""
    if os.path.isfile(path):
        return path if path.endswith(".json") and _is_calibration(path) else None
    found = [os.path.join(path, f) for f in sorted(os.listdir(path))
             if f.endswith(".json") and _is_calibration(os.path.join(path, f))]
    if len(found) > 1:
        raise FolderError("%s holds %d bearing-fem calibrations (%s): plot one of the files"
                          % (path, len(found), ", ".join(os.path.basename(f) for f in found)))
    return found[0] if found else None


def _is_calibration(path):
    try:
        with open(path) as f:
            return json.load(f).get("format") == CALIBRATION_FORMAT
    except (OSError, ValueError, AttributeError):
        return False


def detect(folder):
    """'run', 'analysis', 'stiffness', 'sweep', 'contact', 'calibration' or 'modes'; FolderError
    naming the folder and
    what was expected. A calibration may be named by its JSON file."""
    if os.path.isfile(folder):
        if calibration_file(folder):
            return "calibration"
        raise FolderError("%s is a file, and not a bearing-fem calibration (a JSON file with "
                          "\"format\": \"%s\"); the other outputs are plotted by their folder"
                          % (folder, CALIBRATION_FORMAT))
    if not os.path.isdir(folder):
        raise FolderError("%s: no such folder" % folder)
    has = lambda name: os.path.isfile(os.path.join(folder, name))  # noqa: E731
    if has("summary.json") and (has("response.csv") or has("response.npy")):
        return "run"
    if (has("summary.json") and (has("spectrum.csv") or has("spectrum.npy"))
            and "record" in _read_json(os.path.join(folder, "summary.json"))):
        return "analysis"
    if has("stiffness.csv"):
        return "stiffness"
    if has("sweep.csv"):
        return "sweep"
    if has("force_approach.csv") and has("contact.json"):
        return "contact"
    if calibration_file(folder):
        return "calibration"
    if is_modes_folder(folder):
        return "modes"
    inside = []
    for sub in sorted(os.listdir(folder)):
        path = os.path.join(folder, sub)
        if os.path.isdir(path) and any(os.path.isfile(os.path.join(path, f)) for f in (
                "summary.json", "sweep.csv", "stiffness.csv", "force_approach.csv",
                "modes.json")):
            inside.append(sub)
    raise FolderError(
        "%s is not a folder bearing-plot knows: expected a bearing-sim run (summary.json with "
        "response.csv or response.npy), an analysed record (summary.json with a record block "
        "and spectrum.csv or .npy), a bearing-sim sweep (sweep.csv), a bearing-sim stiffness "
        "output (stiffness.csv), a bearing-fem contact "
        "output (force_approach.csv with contact.json), a bearing-fem modes output (modes.json) "
        "or a bearing-fem calibration (its JSON file)%s" % (
            folder, "; its subfolders %s are: plot each of them" % ", ".join(inside[:6])
            + (", ..." if len(inside) > 6 else "") if inside else ""))


def load_run(folder):
    return Run(folder)


def load_sweep(folder):
    return Sweep(folder)


def load_contact(folder):
    return Contact(folder)


def load_calibration(path):
    """A Calibration from its JSON file, or from a folder holding exactly one."""
    found = calibration_file(path) if os.path.exists(path) else None
    if not found:
        raise FolderError("%s: no bearing-fem calibration JSON there" % path)
    return Calibration(found)
