"""Helpers shared by the tutorials' summarise.py scripts: read a case entry, the solver's time
from its log, and write the results.md table.

etc/bashrc puts applications/utilities/plotBodies on PYTHONPATH, so `from caseSummary import ...`
works in the project's environment. Standard library only.
"""
import os
import re
import sys


def read_entry(case, path, pattern):
    """The groups of the first match of pattern (multi-line) in the case file path; exits with
    a message naming the file and the pattern when there is none."""
    with open(os.path.join(case, path)) as f:
        m = re.search(pattern, f.read(), re.M)
    if not m:
        sys.exit(f"summarise.py: no match for '{pattern}' in {path}")
    return m.groups()


def solver_time_row(case, log="log.immersedSpheroidFoam"):
    """('solver time', 'W s wall, C s CPU, N rank(s)') from the last ExecutionTime line of the
    solver's log, or None without a log or such a line."""
    path = os.path.join(case, log)
    if not os.path.exists(path):
        return None
    with open(path) as f:
        text = f.read()
    times = re.findall(r"ExecutionTime = (\S+) s\s+ClockTime = (\S+) s", text)
    nprocs = re.findall(r"nProcs\s*:\s*(\d+)", text)
    if not times:
        return None
    return ("solver time", f"{float(times[-1][1]):.0f} s wall, {float(times[-1][0]):.0f} s CPU, "
                           f"{nprocs[0] if nprocs else 1} rank(s)")


def write_results(case, rows):
    """results.md: a two-column Markdown table of (quantity, value) rows; also printed."""
    lines = ["| quantity | value |", "|---|---|"] + [f"| {a} | {b} |" for a, b in rows]
    with open(os.path.join(case, "results.md"), "w") as out:
        out.write("\n".join(lines) + "\n")
    print("\n".join(lines))
