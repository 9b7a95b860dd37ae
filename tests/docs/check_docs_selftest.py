#!/usr/bin/env python3
"""Self-test of check_docs.py: on tests/docs/data (planted.md, planted_source.cpp) it must fail and report exactly
the lines marked [planted] -- each one, and no line that cites what exists."""
import os
import re
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.abspath(os.path.join(here, "..", ".."))
files = [os.path.join(here, "data", n) for n in ("planted.md", "planted_source.cpp")]
run = subprocess.run([sys.executable, os.path.join(here, "check_docs.py"), root, "--pages", files[0],
                      "--sources", files[1]], capture_output=True, text=True)
output = run.stdout + run.stderr
failures = []
if run.returncode == 0:
    failures.append("check_docs.py passed on the planted references")
for f in files:
    rel = os.path.relpath(f, root)
    marked = {i for i, line in enumerate(open(f, encoding="utf-8"), 1) if "[planted]" in line}
    reported = {int(n) for n in re.findall(r"^%s:(\d+): " % re.escape(rel), output, flags=re.M)}
    if marked - reported:
        failures.append(f"{rel}: planted lines not reported: {sorted(marked - reported)}")
    if reported - marked:
        failures.append(f"{rel}: lines reported that cite what exists: {sorted(reported - marked)}")
if failures:
    print("\n".join(failures) + "\n--- check_docs.py said:\n" + output)
    sys.exit(1)
print(f"check_docs.py reported every planted reference and nothing else:\n{output}")
