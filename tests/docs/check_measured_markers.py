#!/usr/bin/python3
"""Every section of a page whose numbers are measured, not regenerated, names its commit.

    check_measured_markers.py PAGE...

A section (a Markdown heading and the text to the next heading) holding a measured figure — a
decimal number or a percentage — must carry a line "*Measured at commit `abc1234`.*" (or
"commits `a`, `b` and `c`"), and each commit named must exist in the repository. Issue 30: a
number in the docs is produced by a test at HEAD or marked with the commit it comes from.
"""

import os
import re
import subprocess
import sys

MARK = re.compile(r"^\*Measured at commits? (.*)\.\*$", re.M)
FIGURE = re.compile(r"\d\.\d|\d ?%")
VERSION = re.compile(r"(deal\.II|version|C\+\+|Python|CMake) \d+(\.\d+)*")


def sections(text):
    parts = re.split(r"^(#+ .*)$", text, flags=re.M)
    # [preamble, heading, body, heading, body, ...]
    return [(parts[i], parts[i + 1]) for i in range(1, len(parts) - 1, 2)]


def main():
    repo = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    bad = 0
    shallow = subprocess.run(["git", "-C", repo, "rev-parse", "--is-shallow-repository"],
                             stdout=subprocess.PIPE, text=True).stdout.strip() != "false"
    if shallow:
        print("a shallow clone or no git: the commits named are not looked up")
    for page in sys.argv[1:]:
        text = open(page, encoding="utf-8").read()
        # Text in fenced blocks counts (tables of measured output), headings' own numbers do not.
        for heading, body in sections(text):
            if not FIGURE.search(VERSION.sub("", body)):
                continue
            m = MARK.search(body)
            if not m:
                print("%s: section \"%s\" has measured numbers but no \"*Measured at commit "
                      "`…`.*\" line" % (page, heading.strip("# ")))
                bad += 1
                continue
            for sha in [] if shallow else re.findall(r"`([0-9a-f]{7,40})`", m.group(1)):
                ok = subprocess.run(["git", "-C", repo, "cat-file", "-e", sha + "^{commit}"],
                                    stderr=subprocess.DEVNULL).returncode == 0
                if not ok:
                    print("%s: section \"%s\" names commit %s, which this repository lacks"
                          % (page, heading.strip("# "), sha))
                    bad += 1
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
