#!/usr/bin/python3
"""report.html as a person sees it: headless Chromium loads the file, with no console error and no
failed load; its DOM has the title, the summary, a row per check and every figure report.json
names (embedded as data: URIs, so the page works when mailed); a screenshot is taken.

Usage: /usr/bin/python3 browser_check.py REPORT_DIR [--expect-fail]
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

BROWSER = shutil.which("chromium") or shutil.which("chromium-browser")


def chromium(args, profile):
    cmd = [BROWSER, "--headless", "--no-sandbox", "--disable-gpu", "--enable-logging=stderr",
           "--v=0", f"--user-data-dir={profile}"] + args
    return subprocess.run(cmd, capture_output=True, text=True, timeout=120)


def main():
    if BROWSER is None:
        sys.exit("chromium not found (Debian: apt install chromium; setup.sh installs it)")
    report_dir = os.path.abspath(sys.argv[1])
    page = "file://" + os.path.join(report_dir, "report.html")
    with open(os.path.join(report_dir, "report.json")) as f:
        report = json.load(f)
    with tempfile.TemporaryDirectory() as profile:
        dom = chromium(["--dump-dom", page], profile)
        shot = os.path.join(report_dir, "report_screenshot.png")
        chromium(["--window-size=412,915", f"--screenshot={shot}", page], profile)  # a phone
    if dom.returncode != 0:
        sys.exit(f"chromium failed ({dom.returncode}): {dom.stderr[-800:]}")
    html = dom.stdout
    problems = [line for line in dom.stderr.splitlines()
                if re.search(r"CONSOLE|Failed to load|net::ERR_|Uncaught", line)]
    if problems:
        sys.exit("the page logged errors:\n" + "\n".join(problems))
    assert "<h1>bearing-verify: verification report</h1>" in html, "no title"
    assert "<h2>Summary</h2>" in html, "no summary"
    for c in report["checks"]:
        assert f'id="{c["id"]}"' in html, f"no row for {c['id']}"
    figures = sum(len(c["figures"]) for c in report["checks"])
    embedded = len(re.findall(r'<img [^>]*src="data:image/png;base64,', html))
    assert embedded == figures, f"{embedded} embedded figures, report.json names {figures}"
    text = re.sub(r'data:image/png;base64,[^"]*', "", html)
    assert not re.search(r"\bNaN\b|\binf\b", text), "NaN or inf on the page"
    failed = len(re.findall(r'<tr class="fail" id=', html))
    assert failed == report["totals"]["failed"], "red rows != failed checks"
    if "--expect-fail" in sys.argv:
        assert failed > 0, "expected red rows"
    assert os.path.getsize(shot) > 10000, "screenshot missing or blank"
    print(f"report.html renders: {len(report['checks'])} rows, {embedded} figures, "
          f"{failed} red rows; screenshot {shot}")


if __name__ == "__main__":
    main()
