#!/usr/bin/python3
"""Where the code mutants of source_mutants.py come from: the physics files, the mutation sites on
their code lines (operators, literals, functions, dropped terms, swapped arguments), the fixed-seed
draw, and the hand-written physics mutants of source_mutants_hand.json. Only the standard library."""

import hashlib
import json
import os
import random
import re

HERE = os.path.dirname(os.path.abspath(__file__))


# The physics: what the verification checks are meant to cover. Left out: input parsing (case/),
# records/ (file formats), sweep/, output writing, presets.cc (the preset data is also the
# checks' reference geometry) and calibration.cc (the FE calibration, only with bearing-fem).
PHYSICS_FILES = [
    # contact / Hertz, kinematics, static load, excitation and defects, traction, material
    "lumped/src/core/contact.cc", "lumped/src/core/hertz_exact.cc",
    "lumped/src/core/hertz_hamrock_brewe.cc", "lumped/src/core/hertz_harris_table.cc",
    "lumped/src/core/kinematics.cc", "lumped/src/core/static_load.cc",
    "lumped/src/core/excitation.cc", "lumped/src/core/local_defect.cc",
    "lumped/src/core/traction.cc", "lumped/src/core/bearing.cc", "lumped/src/core/material.cc",
    "lumped/src/core/numerics/roots.cc", "lumped/src/core/numerics/line_search.cc",
    # the 5-DOF static solution and its stiffness (issue 32)
    "lumped/src/core/five_dof_static.cc", "lumped/src/core/ball_pass_stiffness.cc",
    # the models
    "lumped/src/models/two_dof.cc", "lumped/src/models/three_dof.cc",
    "lumped/src/models/ball_dofs.cc", "lumped/src/models/contact_kernels.cc",
    "lumped/src/models/contact_kernels.h", "lumped/src/models/housing.cc",
    "lumped/src/models/quasi_static.cc", "lumped/src/models/quasi_static_run.cc",
    "lumped/src/models/dynamic_run.cc", "lumped/src/models/response.cc",
    "lumped/src/models/ball_set.h", "lumped/src/models/ball_motion.h",
    "lumped/src/models/frame_force.h", "lumped/src/models/race_excitation.h",
    "lumped/src/models/race_stiffness.h", "lumped/src/models/groove_geometry.h",
    "lumped/src/models/defect_excitation.h", "lumped/src/models/phasor.h",
    "lumped/src/models/curvature_compliance_table.h", "lumped/src/models/static_rk4.h",
    # the transfer path and random slip (issue 40): the modes file, the housed model and its
    # support's kernels, the cage's slip
    "lumped/src/core/structure_modes.cc", "lumped/src/models/housed_model.h",
    "lumped/src/models/support_kernels.cc", "lumped/src/models/random_slip.cc",
    # the lubricant film (issue 43): the lubricant, the EHL film and the film law
    "lumped/src/core/lubricant.cc", "lumped/src/core/ehl_film.cc", "lumped/src/core/film_law.cc",
    # integrators
    "lumped/src/solvers/rk4.cc", "lumped/src/solvers/rk4_wide.cc",
    "lumped/include/solvers/bearing/solvers/rk4_loop.h",
    "lumped/include/solvers/bearing/solvers/fixed_step.h", "lumped/src/solvers/newmark.cc",
    "lumped/src/solvers/bdf.cc", "lumped/src/solvers/gsl_adaptive.cc",
    "lumped/src/solvers/event_adaptive.cc", "lumped/src/solvers/step_control.h",
    "lumped/src/solvers/integrator.cc",
    "lumped/src/solvers/integrator_detail.h", "lumped/src/solvers/mechanical_system.cc",
    # acoustics
    "lumped/src/acoustics/sources.cc", "lumped/src/acoustics/pressure.cc",
    "lumped/src/acoustics/microphones.cc",
    # signal analysis
    "lumped/src/signal/envelope.cc", "lumped/src/signal/fft.cc",
    "lumped/src/signal/fundamental_estimate.cc", "lumped/src/signal/harmonic_comb.cc",
    "lumped/src/signal/kurtogram.cc", "lumped/src/signal/line_floor.cc",
    "lumped/src/signal/line_names.cc", "lumped/src/signal/peaks.cc",
    "lumped/src/signal/prewhitening.cc", "lumped/src/signal/spectrum.cc",
    "lumped/src/signal/squared_envelope.cc", "lumped/src/signal/statistics.cc",
    # the analysis: a run's (pipeline), the diagnosis layer's, the run's line families and noise
    "lumped/src/pipeline/analysis.cc", "lumped/src/diagnosis/diagnosis.cc",
    # the coherence diagnosis of a record (issue 41)
    "lumped/src/diagnosis/coherence_bands.cc", "lumped/src/diagnosis/family_test.cc",
    "lumped/src/diagnosis/coherence_diagnosis.cc",
    "lumped/src/diagnosis/envelope_analysis.cc", "lumped/src/diagnosis/fault_lines.cc",
    "lumped/src/diagnosis/record_analysis.cc", "lumped/src/pipeline/excitation_families.cc",
    "lumped/src/pipeline/noise.cc",
]

# The FE library: the Hertz contact block and raceway segment, their gap and boundaries, the
# Helmholtz radiation solver, and the natural modes of a structure (its matrices and eigensolver,
# the seat's rigid fit, the direct harmonic response). Its mutants are judged in a build with
# deal.II, by the checks that run bearing-fem. Left out: fem/app/ (bearing-fem's command line, its
# input checks and output files, as case/ and the output writers are on the lumped side) and the
# readers of fem/mesh/ and fem/modes/structure_file.* (input parsing, as case/; fuzzed instead).
FEM_FILES = [
    "fem/contact/hertz_contact.cc", "fem/contact/raceway_segment.cc",
    "fem/contact/contact_geometry.h", "fem/radiation/helmholtz_radiation.cc",
    "fem/modes/elastic_problem.cc", "fem/modes/elastic_modes.cc",
    "fem/modes/harmonic_response.cc", "fem/modes/seat_fit.cc",
]


def is_fem(path):
    """Whether a mutant of this file is judged in the FE build."""
    return path.startswith("fem/")


# --- finding the code lines ------------------------------------------------------------------


def code_lines(text):
    """(line number, line, code mask) for each line: the mask is the line with comments blanked;
    lines that are no place for a mutant (preprocessor, strings, messages, templates, operator
    declarations, input guards) are left out."""
    lines = text.split("\n")
    out = []
    in_block = False
    in_throw = False
    for n, line in enumerate(lines, start=1):
        code = []
        i = 0
        while i < len(line):
            if in_block:
                end = line.find("*/", i)
                if end < 0:
                    code.append(" " * (len(line) - i))
                    i = len(line)
                else:
                    code.append(" " * (end + 2 - i))
                    i = end + 2
                    in_block = False
            elif line.startswith("//", i):
                code.append(" " * (len(line) - i))
                i = len(line)
            elif line.startswith("/*", i):
                in_block = True
            else:
                code.append(line[i])
                i += 1
        mask = "".join(code)
        stripped = mask.strip()
        starts_throw = "throw " in mask or "throw(" in mask
        skip = (not stripped or stripped.startswith("#") or '"' in mask or "'" in mask
                or in_throw or starts_throw or "operator" in mask or "template" in mask
                or "static_assert" in mask or "assert(" in mask or "namespace" in mask
                or "std::array<" in mask or "Matrix<" in mask or "Vector<" in mask)
        if starts_throw or in_throw:
            in_throw = not stripped.endswith(";") and not stripped.endswith("}")
        if not skip:
            out.append((n, line, mask))
    # An input guard (`if (...)` whose statement is a throw) checks bad input, not physics: the
    # verification checks never feed bad input, so its mutants would only say that.
    guarded = set()
    by_number = {n: m for n, _, m in out}
    for n, line in enumerate(lines, start=1):
        if "throw" in line and n not in by_number:
            k = n - 1
            while k >= 1 and (k in by_number) and k >= n - 3:
                guarded.add(k)
                if lines[k - 1].strip().startswith("if"):
                    break
                k -= 1
        if "throw" in line and line.strip().startswith("if"):
            guarded.add(n)
    return [(n, l, m) for n, l, m in out if n not in guarded]


# --- mutation operators ------------------------------------------------------------------------

BINARY = {
    " + ": [(" - ", "arith")], " - ": [(" + ", "arith")],
    " * ": [(" / ", "arith")], " / ": [(" * ", "arith")],
    " += ": [(" -= ", "arith")], " -= ": [(" += ", "arith")],
    " *= ": [(" /= ", "arith")], " /= ": [(" *= ", "arith")],
    " < ": [(" <= ", "compare"), (" > ", "compare")], " <= ": [(" < ", "compare")],
    " > ": [(" >= ", "compare"), (" < ", "compare")], " >= ": [(" > ", "compare")],
    " == ": [(" != ", "compare")], " != ": [(" == ", "compare")],
    " && ": [(" || ", "logic")], " || ": [(" && ", "logic")],
}
FUNCTIONS = {"std::cos(": "std::sin(", "std::sin(": "std::cos(", "std::min(": "std::max(",
             "std::max(": "std::min(", "std::floor(": "std::ceil(", "std::ceil(": "std::floor("}
SYMMETRIC = {"min", "max", "hypot", "swap", "push_back", "emplace_back", "resize", "assign",
             "insert", "emplace", "fill", "copy", "make_pair", "set", "reserve", "at", "find"}
NUMBER = re.compile(r"(?<![\w.])(\d+\.\d*(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?|\d+[eE][+-]?\d+"
                    r"|\d+)(?![\w.])")
STOP = re.compile(r" (?:[-+]|[<>]=?|==|!=|&&|\|\||[-+*/]?=|\?|:) ")


def mutated_literal(text):
    if re.fullmatch(r"\d+", text):
        n = int(text)
        return "1" if n == 0 else "0" if n == 1 else str(n + 1)
    value = float(text)
    if value == 0.0:
        return "1.0"
    new = "%.6g" % (value * 1.1)
    if not re.search(r"[.eE]", new):
        new += ".0"
    return new


def term_end(mask, start):
    """End of the additive term that starts at `start` (for a dropped term), or None when the
    term does not close on this line."""
    depth = 0
    i = start
    while i < len(mask):
        c = mask[i]
        if c in "([{":
            depth += 1
        elif c in ")]}":
            if depth == 0:
                return i
            depth -= 1
        elif depth == 0 and (c in ",;" or STOP.match(mask, i)):
            return i
        i += 1
    rest = mask[start:].rstrip()
    if depth != 0 or not rest or rest[-1] in "+-*/=<>&|,(":
        return None
    return len(mask.rstrip())


def call_arguments(mask, open_paren):
    """(start, end) of the two arguments of the call whose '(' is at open_paren, when it has two
    on this line; else None."""
    depth = 0
    commas = []
    for i in range(open_paren, len(mask)):
        c = mask[i]
        if c in "([{<" and not (c == "<" and mask[i - 1] == " "):
            depth += 1
        elif c in ")]}>" and not (c == ">" and (mask[i - 1] in " -")):
            depth -= 1
            if depth == 0:
                if len(commas) != 1:
                    return None
                a = (open_paren + 1, commas[0])
                b = (commas[0] + 1, i)
                return a, b
        elif c == "," and depth == 1:
            commas.append(i)
    return None


def sites(path, text):
    """Every mutant of one file: dicts file, line, column, operator, original, mutated."""
    out = []

    def add(n, line, col, op, new_line):
        if new_line != line:
            out.append({"file": path, "line": n, "column": col + 1, "operator": op,
                        "original": line, "mutated": new_line})

    for n, line, mask in code_lines(text):
        for token, replacements in BINARY.items():
            for m in re.finditer(re.escape(token), mask):
                col = m.start()
                for new, op in replacements:
                    add(n, line, col, op + ":" + token.strip() + "->" + new.strip(),
                        line[:col] + new + line[col + len(token):])
                if token in (" + ", " - "):
                    end = term_end(mask, col + len(token))
                    if end is not None and end > col + len(token):
                        add(n, line, col, "drop-term:" + token.strip(), line[:col] + line[end:])
        for m in NUMBER.finditer(mask):
            prev = mask[:m.start()].rstrip()
            if prev.endswith("[") or prev.endswith("<") or mask[m.end():].startswith(">"):
                continue  # an index or a template argument: not a physical constant
            add(n, line, m.start(), "literal:" + m.group(1),
                line[:m.start()] + mutated_literal(m.group(1)) + line[m.end():])
        for old, new in FUNCTIONS.items():
            for m in re.finditer(re.escape(old), mask):
                add(n, line, m.start(), "function:" + old[5:-1] + "->" + new[5:-1],
                    line[:m.start()] + new + line[m.end():])
        for m in re.finditer(r"([A-Za-z_][\w:]*)\(", mask):
            name = m.group(1).split("::")[-1]
            if name in SYMMETRIC or name in ("if", "for", "while", "switch", "return", "sizeof"):
                continue
            args = call_arguments(mask, m.end() - 1)
            if args is None:
                continue
            (a0, a1), (b0, b1) = args
            a, b = line[a0:a1].strip(), line[b0:b1].strip()
            if not a or not b or a == b:
                continue
            add(n, line, m.start(), "swap-args:" + name,
                line[:a0] + b + "," + (" " if line[b0] == " " else "") + a + line[b1:])
    return out


def mutant_id(m):
    key = "\0".join([m["file"], m["original"].strip(), str(m["column"]), m["mutated"].strip()])
    stem = os.path.splitext(os.path.basename(m["file"]))[0]
    return stem + "-" + hashlib.sha1(key.encode()).hexdigest()[:8]


def generate(repo, count, seed, files=PHYSICS_FILES):
    """A fixed-seed sample of `count` mutants covering every file: each file gets at least two
    (when it has them), the rest in proportion to its number of sites."""
    per_file = {}
    for f in files:
        with open(os.path.join(repo, f), encoding="utf-8") as h:
            per_file[f] = sites(f, h.read())
        for m in per_file[f]:
            m["id"] = mutant_id(m)
    total = sum(len(v) for v in per_file.values())
    rng = random.Random(seed)
    chosen = []
    for f in files:
        pool = sorted(per_file[f], key=lambda m: m["id"])
        rng.shuffle(pool)
        per_file[f] = pool
        take = min(len(pool), 2)
        chosen += pool[:take]
        per_file[f] = pool[take:]
    rest = [m for f in files for m in per_file[f]]
    rng.shuffle(rest)
    chosen += rest[:max(0, count - len(chosen))]
    chosen.sort(key=lambda m: (files.index(m["file"]), m["line"], m["column"], m["id"]))
    stats = {f: sum(1 for m in chosen if m["file"] == f) for f in files}
    return chosen, total, stats


HAND_FILE = os.path.join(HERE, "source_mutants_hand.json")


def hand_mutants(repo, path=HAND_FILE):
    """The hand-written physics mutants (source_mutants_hand.json), located in `repo`."""
    with open(path, encoding="utf-8") as h:
        table = json.load(h)["mutants"]
    out = []
    for e in table:
        with open(os.path.join(repo, e["file"]), encoding="utf-8") as h:
            lines = h.read().split("\n")
        at = [n for n, l in enumerate(lines, start=1) if e["find"] in l]
        if len(at) != 1:
            raise RuntimeError("hand mutant %s: \"%s\" is on %d lines of %s, not 1" % (
                e["name"], e["find"], len(at), e["file"]))
        line = lines[at[0] - 1]
        out.append({"file": e["file"], "line": at[0], "column": line.index(e["find"]) + 1,
                    "operator": "hand:" + e["what"], "original": line,
                    "mutated": line.replace(e["find"], e["replace"]), "id": "hand-" + e["name"]})
    return out
