#!/usr/bin/env python3
"""Issue 42's measure of a hot-path change: does every output stay within the integrator's error?

    output_change.py finer RUN_DIR ARGS...            (called by tests/outputs/run_matrix.sh)
    output_change.py perturbed|perturbed-down RUN_DIR ARGS...   (likewise)
    output_change.py compare OLD NEW FINE PERTURBED... [--report FILE]

Run matrices (tests/outputs/run_matrix.sh) go in:
  OLD        the previous build, as the matrix writes it;
  NEW        this build, the same commands;
  FINE       the previous build with each run at its integrator's finer setting: dt/2 for the
             fixed-step methods (rk4, newmark), tolerance/10 for the adaptive ones (rkf45, rk8pd,
             rk8pd-events, bdf, whose dt is only the first step): |OLD − FINE| is the integrator's
             own error on that output;
  PERTURBED  the previous build with the shaft speed and the radial load moved by one unit in
             their last place, up and down (two matrices): what round-off alone does.

Each file is compared as text whose numbers are tokens: the text between numbers must be the same
(runs of blanks aside), and each number may move by at most
    max(|OLD − FINE|, 4 max|OLD − PERTURBED|, 16 ulp of OLD).
In a table (CSV, npy) the first two are each column's largest over its rows (sample by sample);
elsewhere (summary.json, the printed summary, a sweep's table: the statistics and named peaks)
each number has its own. The second term is what round-off alone moves: it covers what no
integrator touches (quasi-static equilibria), quantities made of round-off (x of a 3-DOF case
under a pure axial load is 1e-19 m), and the cases that amplify round-off: the adaptive methods,
whose step sizes a last-bit change moves, and balls leaving contact. Four: a code change puts
round-off into every evaluation, the perturbation into the inputs once. The third: the last 4
bits of any number (a geometric quantity computed in another order). A number printed with 12 or
fewer significant digits may also flip its last digit; such flips are counted. The solver's cost
(steps, evaluations) may change freely. Commands that failed in OLD (input errors), help texts
and `info` have no integrator: byte-identical or within the last bits.

The cases where round-off moves a time series by more than a tenth of the integrator's error are
named, with the column: there sample-by-sample agreement is only as good as round-off allows.

Exit status: 0 when every output is identical or within its bound, 1 otherwise, 2 on bad usage.
Run with /usr/bin/python3 (numpy).
"""
import argparse
import math
import os
import re
import sys
import tomllib

import numpy as np

FIXED_STEP = {"rk4", "newmark"}
SUMMARY_FILES = {"summary.json", "sweep.csv"}  # judged in every case, also the sensitive ones
NUMBER = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?|[-+]?(?:inf|nan)\b")
SENSITIVE_FRACTION = 0.1  # a round-off perturbation reaching a tenth of the integrator's error
ROUNDOFF_FACTOR = 4.0  # a change injects round-off at every step, the perturbation once: margin
# The solver's cost (steps, evaluations): what a hot-path change may change freely, not judged.
COST = re.compile(r"^(Solver:|solver\.(steps|rejected_steps|force_evaluations|jacobian_evaluations))")
AMPLIFY_FRACTION = 0.05  # round-off moving this share of a summary beyond the error: amplifying
LAST_BITS = 16  # a value may always move in its last 4 bits (16 units in the last place)
FLIP_UNITS = 1.5  # a printed number's last digit flipped (its difference read back is inexact)


# --- the extra settings of the FINE and PERTURBED matrices ----------------------------------------

def resolved_case(run_dir, args):
    """The [solver] and [operation] tables a run resolved: its own case.toml when it wrote one, else
    (a sweep) the defaults of bearing-sim overlaid by the case file and the --set arguments."""
    path = os.path.join(run_dir, "case.toml")
    if os.path.isfile(path):
        with open(path, "rb") as f:
            case = tomllib.load(f)
        return case.get("solver", {}), case.get("operation", {})
    solver = {"method": "rk4", "dt": 5e-6, "tolerance": 1e-6}
    for a in args:
        if a.endswith(".toml") and os.path.isfile(a):
            with open(a, "rb") as f:
                solver.update(tomllib.load(f).get("solver", {}))
    for i, a in enumerate(args[:-1]):
        if a == "--set" and args[i + 1].startswith("solver."):
            key, value = args[i + 1][len("solver."):].split("=", 1)
            solver[key] = value
    return solver, {}


def seconds(value):
    """A time as a case file or --set writes it: a number [s] or "5 us", "5us", "2 ms"."""
    if isinstance(value, (int, float)):
        return float(value)
    m = re.fullmatch(r"\s*([-+0-9.eE]+)\s*(s|ms|us|µs|ns)?\s*", str(value))
    if not m:
        raise ValueError(f"solver.dt = {value!r}: not a time")
    scale = {"s": 1.0, None: 1.0, "ms": 1e-3, "us": 1e-6, "µs": 1e-6, "ns": 1e-9}[m.group(2)]
    return float(m.group(1)) * scale


def rad_per_s(value):
    """A speed as a case file writes it: a number [rad/s] or "209.4 rad/s", "2000 rpm"."""
    if isinstance(value, (int, float)):
        return float(value)
    m = re.fullmatch(r"\s*([-+0-9.eE]+)\s*(rad/s|rpm|Hz)?\s*", str(value))
    if not m:
        raise ValueError(f"operation.speed = {value!r}: not a speed")
    scale = {"rad/s": 1.0, None: 1.0, "rpm": math.pi / 30, "Hz": 2 * math.pi}[m.group(2)]
    return float(m.group(1)) * scale


def failed(run_dir):
    try:
        with open(run_dir + ".rc") as f:
            return f.read().strip() != "0"
    except OSError:
        return True


def finer(run_dir, args):
    if failed(run_dir):
        return []
    solver, _ = resolved_case(run_dir, args)
    method = str(solver.get("method", "rk4"))
    if method in FIXED_STEP:
        return ["--set", f"solver.dt={seconds(solver.get('dt', 5e-6)) / 2!r}"]
    return ["--set", f"solver.tolerance={float(solver.get('tolerance', 1e-6)) / 10!r}"]


def perturbed(run_dir, args, sign):
    """The shaft speed and the radial load moved by about one unit in their last place (up for
    sign +1, down for −1): a perturbation of round-off size of the phase and of every force
    evaluation, as a reordered sum or a rotated phasor makes."""
    if failed(run_dir):
        return []
    _, operation = resolved_case(run_dir, args)
    factor = 1 + sign * 2.0**-52
    extra = []
    speed = rad_per_s(operation.get("speed", 0.0))
    if speed != 0:
        extra += ["--set", f"operation.speed={speed * factor!r} rad/s"]
    load = operation.get("load", [])
    if load and all(isinstance(f, (int, float)) for f in load) and any(load):
        moved = ", ".join(repr(f * factor) for f in load)
        extra += ["--set", f"operation.load=[{moved}]"]
    return extra


# --- reading an output as numbers and the text between them ---------------------------------------

class Parsed:
    """An output file: `skeleton` (its text with each number replaced), `values` (the numbers),
    `digits` (significant digits each was printed with; 17 for binary) and `column` (its column
    in a table, or its own index)."""

    def __init__(self, skeleton, values, digits, column, header=()):
        self.skeleton, self.values, self.digits, self.column = skeleton, values, digits, column
        self.header = header

    def column_name(self, k):
        """The name of number k's column (a table's header) or its index."""
        _, index = self.column[k]
        return self.header[index] if index < len(self.header) else f"#{index}"


def significant_digits(token):
    mantissa = re.split(r"[eE]", token.lstrip("+-"))[0].replace(".", "").lstrip("0")
    return max(len(mantissa), 1)


def writer_digits(path, token):
    """The significant digits the writer rounded this number to: JSON all (shortest round trip),
    CSV 12 (result_tables.h), the printed summary its own (%.4g and the like: at least 4)."""
    if path.endswith(".json"):
        return 17
    if path.endswith(".csv"):
        return 12
    return max(significant_digits(token), 4)


def parse_text(path):
    with open(path, "rb") as f:
        text = f.read().decode("utf-8", errors="replace")
    values, digits, column, parts, labels = [], [], [], [], []
    table = path.endswith(".csv")
    key, path_keys = "", []  # the JSON key a number belongs to, and the objects around it
    for line in text.splitlines(keepends=True):
        if path.endswith(".json"):  # pretty-printed: one key a line
            opened = re.match(r'\s*"([^"]+)"\s*:\s*[{\[]\s*$', line)
            if opened:
                path_keys.append(opened.group(1))
            elif re.match(r"\s*[}\]],?\s*$", line) and path_keys:
                path_keys.pop()
        last = 0
        first_word = line.split()[0] if line.split() else ""
        for m in NUMBER.finditer(line):
            before = line[last:m.start()]
            parts.append(before)
            parts.append("#")
            keys = re.findall(r'"([^"]+)"\s*:', before)
            key = keys[-1] if keys else key
            words = re.findall(r"[A-Za-z_][\w.]*", line[:m.start()])
            labels.append(".".join(path_keys[-2:] + [key] if keys else path_keys[-3:])
                          if path.endswith(".json") else
                          " ".join(w for w in (first_word, words[-1] if words else "") if w))
            values.append(float(m.group(0)))
            digits.append(writer_digits(path, m.group(0)))
            column.append(("c", line.count(",", 0, m.start())) if table else ("t", len(values) - 1))
            last = m.end()
        parts.append(line[last:])
    header = text.split("\n", 1)[0].strip().split(",") if table else labels
    # Runs of blanks collapsed: a printed column's padding follows its number's width.
    return Parsed(re.sub(r"[ \t]+", " ", "".join(parts)), np.array(values), np.array(digits), column, header)


def parse_npy(path):
    a = np.load(path, allow_pickle=False)
    flat = a.reshape(a.shape[0], -1) if a.ndim > 1 else a.reshape(-1, 1)
    cols = [("c", j) for _ in range(flat.shape[0]) for j in range(flat.shape[1])]
    skeleton = f"npy {a.dtype} {a.shape}"
    return Parsed(skeleton, flat.astype(float).ravel(), np.full(flat.size, 17), cols)


def parse(path):
    return parse_npy(path) if path.endswith(".npy") else parse_text(path)


def spread(old, other):
    """|OLD − other| per table column (its largest over the rows) or per number; None when the
    other run does not have the same shape."""
    if other is None or other.skeleton != old.skeleton:
        return None
    diff = np.abs(old.values - other.values)
    largest = {}
    for c, d in zip(old.column, diff):
        largest[c] = max(largest.get(c, 0.0), d)
    return np.array([largest[c] for c in old.column])


def last_digit_unit(value, digits):
    if value == 0 or digits >= 17:
        return 0.0
    return 10.0 ** (math.floor(math.log10(abs(value))) - digits + 1)


def parse_if(path):
    return parse(path) if os.path.isfile(path) else None


class Measures:
    """One output of the old build and what judges a change of it, per number: `error` (the
    integrator's, |OLD − FINE|), `roundoff` (|OLD − PERTURBED|), `unit` (one in the last printed
    digit). None where FINE or PERTURBED has another shape."""

    def __init__(self, old_root, fine_root, pert_roots, rel):
        self.old = parse(os.path.join(old_root, rel))
        self.error = spread(self.old, parse_if(os.path.join(fine_root, rel)))
        moved = [spread(self.old, parse_if(os.path.join(r, rel))) for r in pert_roots]
        moved = [m for m in moved if m is not None]
        self.roundoff = np.maximum.reduce(moved) if moved else None
        # Each perturbed run's own numbers, for amplifying_roundoff() and beyond_error().
        self.perturbed = [p for p in (parse_if(os.path.join(r, rel)) for r in pert_roots)
                          if p is not None and p.skeleton == self.old.skeleton]
        self.unit = np.array([last_digit_unit(v, d) for v, d in zip(self.old.values,
                                                                     self.old.digits)])

    def beyond_error(self, values):
        """How many numbers of `values` lie further from OLD than the integrator's error (of
        those the integrator moves at all)."""
        return int(np.sum((np.abs(values - self.old.values) > self.error) & (self.error > 0)))

    def amplifying_roundoff(self):
        """Whether round-off alone moves over AMPLIFY_FRACTION of this output's numbers further
        than the integrator's error: then it decides which steps an adaptive method takes, or
        which balls touch, and a number-by-number bound means nothing."""
        if self.error is None or not self.perturbed or not np.any(self.error > 0):
            return False
        worst = max(self.beyond_error(p.values) for p in self.perturbed)
        return worst > AMPLIFY_FRACTION * np.sum(self.error > 0)

    def bound(self):
        """The change allowed: the integrator's error, or ROUNDOFF_FACTOR times the round-off
        perturbation's effect where that is larger (a quantity the integrator does not touch, or
        one made of round-off); 0 where neither was measured."""
        e = self.error if self.error is not None else np.zeros_like(self.unit)
        r = self.roundoff if self.roundoff is not None else np.zeros_like(self.unit)
        last_bits = LAST_BITS * np.finfo(float).eps * np.abs(self.old.values)
        return np.maximum(np.maximum(e, ROUNDOFF_FACTOR * r), last_bits)

    def sensitive_column(self):
        """The first column in which a round-off perturbation moves the output by more than a
        tenth of the integrator's error (beyond a last-digit flip): the index of its first number,
        or None."""
        if self.error is None or self.roundoff is None:
            return None
        hit = (self.error > 0) & (self.roundoff > SENSITIVE_FRACTION * self.error) & (
            self.roundoff > FLIP_UNITS * self.unit)
        return int(np.argmax(hit)) if hit.any() else None


# --- the comparison ------------------------------------------------------------------------------

class Finding:
    def __init__(self, case, file, status, change=0.0, bound=0.0, flips=0, column=None):
        self.case, self.file, self.status = case, file, status
        self.change, self.bound, self.flips, self.column = change, bound, flips, column


def is_time_series(rel):
    name = os.path.basename(rel)
    return name.endswith(".npy") or (name.endswith(".csv") and name not in SUMMARY_FILES)


def compare_file(case, rel, roots, amplifying):
    old_root, new_root, fine_root, pert_roots = roots
    with open(os.path.join(old_root, rel), "rb") as f1, open(os.path.join(new_root, rel), "rb") as f2:
        if f1.read() == f2.read():
            return Finding(case, rel, "identical")
    m = Measures(old_root, fine_root, pert_roots, rel)
    new = parse(os.path.join(new_root, rel))
    if m.old.skeleton != new.skeleton or len(m.old.values) != len(new.values):
        return Finding(case, rel, "TEXT CHANGED")
    change = np.abs(new.values - m.old.values)
    cost = np.array([bool(COST.match(m.old.column_name(k))) for k in range(len(change))], dtype=bool)
    change = np.where(cost, 0.0, change)  # the solver's cost may change freely
    if amplifying and m.error is not None and m.perturbed:
        return judge_like_roundoff(case, rel, m, new)
    bound = m.bound()
    flip = (change > bound) & (change <= FLIP_UNITS * m.unit)
    exceed = (change > bound) & ~flip
    k = int(np.argmax(np.where(exceed, change / np.maximum(bound, 1e-300), -1.0))) \
        if exceed.any() else int(np.argmax(change))
    status = "EXCEEDS" if exceed.any() else "within bound"
    return Finding(case, rel, status, float(change[k]), float(bound[k]), int(flip.sum()),
                   m.old.column_name(k))


def judge_like_roundoff(case, rel, m, new):
    """In a case that amplifies round-off: its summary statistics and named peaks (not its time
    series, whose samples diverge from wherever the step sequences part) must have no more
    numbers beyond the integrator's error than round-off alone moved there (the larger
    perturbation's count, plus three times its Poisson spread)."""
    n_new = m.beyond_error(new.values)
    n_roundoff = max(m.beyond_error(p.values) for p in m.perturbed)
    allowed = n_roundoff + 3 * math.sqrt(n_roundoff) + 3
    if is_time_series(rel):
        status = "time series: not judged"
    else:
        status = "like round-off" if n_new <= allowed else "EXCEEDS round-off's spread"
    return Finding(case, rel, status, float(n_new), float(allowed), 0,
                   f"{n_new} of {len(new.values)} numbers beyond the error; round-off {n_roundoff}")


def amplifying_case(case, roots):
    """Whether the case's summary (summary.json, else its printed summary) amplifies round-off."""
    old_root, _, fine_root, pert_roots = roots
    for rel in (os.path.join(case, "summary.json"), case + ".stdout"):
        if os.path.isfile(os.path.join(old_root, rel)):
            return Measures(old_root, fine_root, pert_roots, rel).amplifying_roundoff()
    return False


def sensitive_file(case, roots):
    """Where a case's time series is dominated by round-off: "file column (its largest value,
    the integrator's error, the perturbation's effect)", or None."""
    old_root, _, fine_root, pert_roots = roots
    for dirpath, _, files in sorted(os.walk(os.path.join(old_root, case))):
        for name in sorted(files):
            rel = os.path.relpath(os.path.join(dirpath, name), old_root)
            if is_time_series(rel):
                m = Measures(old_root, fine_root, pert_roots, rel)
                k = m.sensitive_column()
                if k is not None:
                    scale = np.max(np.abs(m.old.values[[c == m.old.column[k] for c in m.old.column]]))
                    return (f"{os.path.basename(rel)} column {m.old.column_name(k)} (largest "
                            f"|value| {scale:.3g}, integrator's error {m.error[k]:.3g}, round-off "
                            f"perturbation's effect {m.roundoff[k]:.3g})")
    return None


def all_files(root):
    out = set()
    for dirpath, _, files in os.walk(root):
        for name in files:
            if name.endswith(".lock"):
                continue
            out.add(os.path.relpath(os.path.join(dirpath, name), root))
    return out


def case_of(rel):
    first = rel.split(os.sep)[0]
    return re.sub(r"\.(rc|stdout|stderr)$", "", first)


def compare(roots):
    old_files, new_files = all_files(roots[0]), all_files(roots[1])
    findings, sensitive, amplifying = [], {}, {}
    for rel in sorted(old_files | new_files):
        case = case_of(rel)
        if rel not in old_files or rel not in new_files:
            findings.append(Finding(case, rel, "MISSING IN NEW" if rel in old_files else "NEW FILE"))
            continue
        if case not in sensitive:
            sensitive[case] = sensitive_file(case, roots) if os.path.isdir(
                os.path.join(roots[0], case)) else None
            amplifying[case] = amplifying_case(case, roots)
        findings.append(compare_file(case, rel, roots, amplifying[case]))
    return findings, {c: why for c, why in sensitive.items() if why}, sorted(
        c for c, a in amplifying.items() if a)


def report(findings, sensitive, amplifying, out):
    changed = [f for f in findings if f.status != "identical"]
    bad = [f for f in changed if f.status.isupper() or f.status.startswith("EXCEEDS")]
    print(f"{len(findings)} outputs: {len(findings) - len(changed)} byte-identical, "
          f"{len(changed) - len(bad)} changed within their bound, {len(bad)} not", file=out)
    print(f"\n{len(amplifying)} cases amplify round-off (round-off alone moves over "
          f"{AMPLIFY_FRACTION:.0%} of their summary's numbers beyond the integrator's error): each "
          "output is judged by how many numbers the change moves that far, against round-off's "
          "own count: " + (", ".join(amplifying) if amplifying else "none"), file=out)
    print(f"\n{len(sensitive)} cases have a time series dominated by round-off, or made of it (a DOF "
          "at rest by symmetry): there a sample may move by four times the round-off's effect:",
          file=out)
    for case, why in sensitive.items():
        print(f"- {case}: {why}", file=out)
    if changed:
        print("\n| case | file | status | largest change | column | its bound | change / bound "
              "| last-digit flips |", file=out)
        print("| --- | --- | --- | ---: | ---: | ---: | ---: | ---: |", file=out)
        for f in changed:
            ratio = f"{f.change / f.bound:.2g}" if f.bound > 0 else ("0" if f.change == 0 else "–")
            print(f"| {f.case} | {f.file} | {f.status} | {f.change:.3g} | {f.column} | "
                  f"{f.bound:.3g} | {ratio} | {f.flips} |", file=out)
    return 1 if bad else 0


def main(argv):
    if len(argv) >= 2 and argv[0] in ("finer", "perturbed", "perturbed-down"):
        if argv[0] == "finer":
            extra = finer(argv[1], argv[2:])
        else:
            extra = perturbed(argv[1], argv[2:], +1 if argv[0] == "perturbed" else -1)
        if extra:
            print("\n".join(extra))
        return 0
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("mode", choices=["compare"])
    p.add_argument("old")
    p.add_argument("new")
    p.add_argument("fine")
    p.add_argument("perturbed", nargs="+")
    p.add_argument("--report", help="also write the table to this file")
    a = p.parse_args(argv)
    for name, path in [("old", a.old), ("new", a.new), ("fine", a.fine)] + [
            ("perturbed", p) for p in a.perturbed]:
        if not os.path.isdir(path):
            print(f"output_change.py: {name} = {path}: no such folder", file=sys.stderr)
            return 2
    findings, sensitive, amplifying = compare((a.old, a.new, a.fine, a.perturbed))
    status = report(findings, sensitive, amplifying, sys.stdout)
    if a.report:
        with open(a.report, "w") as f:
            report(findings, sensitive, amplifying, f)
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
