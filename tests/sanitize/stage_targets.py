#!/usr/bin/env python3
"""The build targets a sanitizer stage runs, so that it builds only those (issue 42).

    stage_targets.py BUILD CTEST_ARGS...

Reads the tests that `ctest CTEST_ARGS` selects in BUILD (ctest --show-only=json-v1: it lists the
commands without building anything) and prints, one a line, each executable target of BUILD that a
selected command runs or names (a test's program, an executable passed as an argument or as
-DNAME=path). Ninja builds what those link and depend on. GoogleTest programs not yet built have
no tests to list (they are discovered after the build): the stage builds them by the target
`lumped_test_programs` (tests/CMakeLists.txt). Exit 1 when ctest or ninja cannot list.
"""
import json
import os
import re
import subprocess
import sys


def main(argv):
    if len(argv) < 2:
        print("usage: stage_targets.py BUILD CTEST_ARGS...", file=sys.stderr)
        return 2
    build = os.path.realpath(argv[0])
    listing = subprocess.run(["ctest", "--test-dir", build, "--show-only=json-v1", *argv[1:]],
                             check=True, capture_output=True, text=True).stdout
    ninja_targets = subprocess.run(["ninja", "-C", build, "-t", "targets", "all"], check=True,
                                   capture_output=True, text=True).stdout
    # An executable's ninja rule names its output path relative to BUILD.
    executables = {}
    for line in ninja_targets.splitlines():
        path, _, rule = line.partition(": ")
        if rule.startswith("CXX_EXECUTABLE_LINKER") or rule.startswith("C_EXECUTABLE_LINKER"):
            executables[os.path.join(build, path)] = os.path.basename(path)
    wanted = set()
    for test in json.loads(listing).get("tests", []):
        for arg in test.get("command", []):
            for token in re.split(r"[=;]", arg):
                name = executables.get(os.path.realpath(token)) if token.startswith("/") else None
                if name:
                    wanted.add(name)
    if wanted:
        print("\n".join(sorted(wanted)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
