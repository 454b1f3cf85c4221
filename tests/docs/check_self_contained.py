#!/usr/bin/python3
"""The repository is self-contained: nothing it tracks points at a file outside it.

The physics lives in docs/model.md (issue 30). Before, the code and the pages cited a spec and the
source papers in a folder beside the clone, which a clone does not have. This check fails, naming
file:line, for any tracked file that
  - names the sibling folder (a relative path up one level into "shared"), or
  - cites the old spec, i.e. "model.md" spelled in any case other than the lowercase docs page
    (docs/model.md, or model.md from inside docs/),
and fails if docs/model.md lacks one of its section headings 1-9 ("## N. Title"), which the code
cites as "docs/model.md §N".

Usage: check_self_contained.py [SOURCE_ROOT]   (default: two folders up from this file)
Exit 0 pass, 1 fail, 77 skipped (no git checkout: e.g. a source tarball, or no git).
"""

import os
import re
import subprocess
import sys

SKIP = 77

# Built from parts so that this file does not match its own patterns.
OUTSIDE = re.compile(re.escape(".." + "/" + "shared"))
SPEC = re.compile(r"model\.md", re.IGNORECASE)
ALLOWED_SPEC = "model" + ".md"  # the lowercase page, as docs/model.md or a link from docs/
HEADING = r"^##\s+§?{n}\.\s+\S"


def tracked_files(root):
    """The files git tracks under root, or None when root is not a git checkout."""
    if not os.path.exists(os.path.join(root, ".git")):
        return None
    try:
        out = subprocess.run(["git", "-C", root, "ls-files", "-z"], check=True,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE).stdout
    except (OSError, subprocess.CalledProcessError):
        return None
    return [p for p in out.decode("utf-8", "surrogateescape").split("\0") if p]


def text_lines(path):
    """The lines of a text file; [] for a binary one (a NUL byte) or one that cannot be read."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError:
        return []
    if b"\0" in data:
        return []
    return data.decode("utf-8", "replace").splitlines()


def outside_pointers(root, files):
    problems = []
    for rel in files:
        for number, line in enumerate(text_lines(os.path.join(root, rel)), 1):
            if OUTSIDE.search(line):
                problems.append(f"{rel}:{number}: points outside the repository: {line.strip()}")
            for m in SPEC.finditer(line):
                if m.group(0) != ALLOWED_SPEC:
                    problems.append(f"{rel}:{number}: cites {m.group(0)} (the physics is "
                                    f"docs/{ALLOWED_SPEC}): {line.strip()}")
    return problems


def missing_sections(root):
    path = os.path.join(root, "docs", ALLOWED_SPEC)
    lines = text_lines(path)
    if not lines:
        return [f"docs/{ALLOWED_SPEC}: missing or empty"]
    problems = []
    for n in range(1, 10):
        heading = re.compile(HEADING.format(n=n))
        if not any(heading.match(line) for line in lines):
            problems.append(f"docs/{ALLOWED_SPEC}: no section heading '## {n}. …' "
                            f"(the code cites docs/{ALLOWED_SPEC} §{n})")
    return problems


def main(argv):
    root = os.path.abspath(argv[1] if len(argv) > 1 else
                           os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    files = tracked_files(root)
    if files is None:
        print(f"skipped: {root} is not a git checkout (or git is missing), so the tracked files "
              "are not known")
        return SKIP
    problems = outside_pointers(root, files) + missing_sections(root)
    for p in problems:
        print(p)
    if problems:
        print(f"FAIL: {len(problems)} problem(s) in {len(files)} tracked files")
        return 1
    print(f"ok: {len(files)} tracked files point at nothing outside the repository; "
          f"docs/{ALLOWED_SPEC} has §1-§9")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
