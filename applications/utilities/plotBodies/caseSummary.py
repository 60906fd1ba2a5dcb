"""Helpers shared by the tutorials' summarise.py scripts: read a case entry, the solver's time
from its log, and write the results.md table (write_results, the only writer of that file).

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
    """results.md: a two-column Markdown table of (quantity, value) rows; also printed.

    The one writer of results.md. Each quantity is one row: a list that names one twice, or a
    cell that would break the table (a '|' or a line break), ends the script with a message
    instead. The table goes to a temporary file that then replaces results.md, so results.md
    is always one whole table from one call: two runs finishing in the same case, or a write
    cut short, cannot leave parts of two tables in it."""
    labels = [a for a, _ in rows]
    repeated = sorted({a for a in labels if labels.count(a) > 1})
    if repeated:
        sys.exit(f"summarise.py: results.md would list these rows more than once: "
                 f"{'; '.join(repeated)}")
    broken = [f"{a}: {b}" for a, b in rows if re.search(r"[|\n]", f"{a}{b}")]
    if broken:
        sys.exit(f"summarise.py: results.md cells with '|' or a line break: {'; '.join(broken)}")
    lines = ["| quantity | value |", "|---|---|"] + [f"| {a} | {b} |" for a, b in rows]
    path = os.path.join(case, "results.md")
    partial = f"{path}.{os.getpid()}.tmp"
    try:
        with open(partial, "w") as out:
            out.write("\n".join(lines) + "\n")
        os.replace(partial, path)
    finally:
        if os.path.exists(partial):
            os.remove(partial)
    print("\n".join(lines))
