#!/usr/bin/python3
"""Helpers shared by the validation scripts (validation/*): the provenance of a run, CSV
tables, the CPU time and mesh size of a finished run from its logs, and writing or editing
OpenFOAM case files.

Case files are edited with substitute(), substitute_re() and set_entry(); each raises
SubstitutionError, naming the file and the pattern, when the pattern is not found the
expected number of times, so a template that has changed stops the run instead of running
unedited. Standard library only (Debian's /usr/bin/python3). A script in validation/<name>/
imports it with

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
    from validationTools import provenance, read_csv, set_entry

Shell scripts (Allrun) use the command line; each OLD (a literal string) and each KEY (an
entry, as set_entry) must be found exactly once:

    validationTools.py substitute FILE OLD NEW [OLD NEW ...]
    validationTools.py set FILE KEY VALUE [KEY VALUE ...]
"""
import contextlib
import csv
import fcntl
import os
import re
import socket
import subprocess
import sys
import time
from pathlib import Path

# the repository's root (this file is validation/tools/validationTools.py)
TOP = Path(__file__).resolve().parents[2]
REFINED_BOX_MESH = TOP / "applications" / "utilities" / "refinedBoxMesh" / "refinedBoxMesh.py"


FOAM_PROGRESS = TOP / "bin" / "foamProgress"


# ---------------------------------------------------------------------------
# running a case


def run_logged(cmd, case, log_name):
    """Run cmd (a list) in the folder case with its output in case/log_name,
    while bin/foamProgress shows one progress line on stderr: simulated time of
    endTime, steps, wall time, time left (rewritten in place on a terminal, a
    line every 30 s otherwise). It follows the newest solver log below case:
    log_name itself for a solver run directly, the solver's log for a script
    such as ./Allrun. Returns cmd's exit status."""
    case = os.path.abspath(case)
    with open(os.path.join(case, log_name), "w") as out:
        proc = subprocess.Popen(cmd, cwd=case, stdout=out, stderr=subprocess.STDOUT)
    watcher = subprocess.Popen([str(FOAM_PROGRESS), "-watch", str(proc.pid), case])
    try:
        return proc.wait()
    finally:
        if proc.poll() is None:   # interrupted: do not leave the solver running
            proc.terminate()
            proc.wait()
        watcher.wait()            # ends within a second of the run


# ---------------------------------------------------------------------------
# provenance

def commit(top=TOP):
    """The commit of the library a run used: the short HEAD, with '+src' appended if src/
    differs from it; 'unknown' outside a git checkout."""
    try:
        head = subprocess.run(["git", "-C", str(top), "rev-parse", "--short", "HEAD"],
                              check=True, capture_output=True, text=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", str(top), "diff", "--quiet", "HEAD", "--",
                                "src"]).returncode
        return head + ("+src" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def provenance(top=TOP):
    """The columns host, date and commit of a results row (the date to the minute)."""
    return dict(host=socket.gethostname(), date=time.strftime("%Y-%m-%d %H:%M"),
                commit=commit(top))


# ---------------------------------------------------------------------------
# CSV tables

def read_csv(path, missing_ok=True):
    """The rows of a CSV file as dicts (column name: string); [] for a missing file if
    missing_ok, else FileNotFoundError."""
    if missing_ok and not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


@contextlib.contextmanager
def locked(path):
    """An exclusive lock (path.lock) held over a read, merge and write of the file path, so
    that runs of one campaign side by side do not lose each other's rows."""
    with open(f"{path}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        yield


def merge_row(path, row, key, fields=None, ignore_extra=False):
    """Under locked(path): the rows of the CSV file path whose column key differs from row's,
    then row, written back (write_csv's fields and ignore_extra)."""
    with locked(path):
        write_csv(path, [r for r in read_csv(path) if r[key] != row[key]] + [row], fields,
                  ignore_extra)


def write_csv(path, rows, fields=None, ignore_extra=False):
    """Write rows (dicts) to the CSV file path, creating its folder. fields: the columns in
    order (default: the keys of the first row); ignore_extra: drop keys of a row that are not
    columns (else ValueError). The file is written beside path and renamed onto it, so that a
    reader never sees it half written."""
    rows = list(rows)
    if fields is None:
        fields = list(rows[0])
    folder = os.path.dirname(str(path))
    if folder:
        os.makedirs(folder, exist_ok=True)
    partial = f"{path}.{os.getpid()}.partial"
    try:
        with open(partial, "w", newline="") as f:
            wr = csv.DictWriter(f, fieldnames=fields,
                                extrasaction="ignore" if ignore_extra else "raise")
            wr.writeheader()
            wr.writerows(rows)
        os.replace(partial, path)
    finally:
        if os.path.exists(partial):
            os.remove(partial)


# ---------------------------------------------------------------------------
# logs of a finished run

def execution_times(log):
    """The cumulative CPU times (ExecutionTime, s) an OpenFOAM solver printed in the log
    file, one per time step; [] if there are none."""
    with open(log) as f:
        return [float(t) for t in re.findall(r"ExecutionTime = (\S+) s", f.read())]


def cpu_seconds(case, log="log.solver"):
    """The CPU time (s) of the solver run in the folder case: its last ExecutionTime in
    case/log; nan if the log is missing or has none."""
    try:
        t = execution_times(os.path.join(case, log))
    except OSError:
        return float("nan")
    return t[-1] if t else float("nan")


def mesh_cells(case, log="log.blockMesh"):
    """The number of cells blockMesh reported in case/log."""
    path = os.path.join(case, log)
    with open(path) as f:
        m = re.search(r"nCells:\s*(\d+)", f.read())
    if m is None:
        raise RuntimeError(f"{path}: no nCells")
    return int(m.group(1))


# ---------------------------------------------------------------------------
# writing case files

FOAM_HEADER = """/*--------------------------------*- C++ -*----------------------------------*\\
  {title}
\\*---------------------------------------------------------------------------*/
FoamFile
{{
    version     2.0;
    format      ascii;
    class       {cls};
    location    "{loc}";
    object      {obj};
}}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

"""

FOAM_FOOTER = "\n// ************************************************************************* //\n"


def write_dict(path, cls, location, obj, body, title):
    """Write an OpenFOAM file: the banner with the line title, the FoamFile header (class
    cls, location, object obj), body and the closing line; creates the folder."""
    os.makedirs(os.path.dirname(str(path)), exist_ok=True)
    with open(path, "w") as f:
        f.write(FOAM_HEADER.format(title=title, cls=cls, loc=location, obj=obj) + body
                + FOAM_FOOTER)


def refined_box_mesh(case, args):
    """Write case/system/blockMeshDict with applications/utilities/refinedBoxMesh (args: its
    options without -o); the command and its output go to case/log.refinedBoxMesh."""
    os.makedirs(os.path.join(case, "system"), exist_ok=True)
    cmd = [sys.executable or "/usr/bin/python3", str(REFINED_BOX_MESH), *args,
           "-o", os.path.join(case, "system", "blockMeshDict")]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    with open(os.path.join(case, "log.refinedBoxMesh"), "w") as f:
        f.write(" ".join(cmd) + "\n" + out)
    return out


# ---------------------------------------------------------------------------
# editing case files

class SubstitutionError(ValueError):
    """A pattern to replace was not found the expected number of times."""


def _source(path_or_text):
    """(text, path): a pathlib.Path, or a str without a line break naming an existing file,
    is read (path set); any other str is the text itself (path None)."""
    if isinstance(path_or_text, Path) or (
            "\n" not in path_or_text and os.path.isfile(path_or_text)):
        with open(path_or_text) as f:
            return f.read(), str(path_or_text)
    return path_or_text, None


def _where(text, path):
    """The file's path, or the start of the text, for an error message."""
    if path is not None:
        return path
    head = text[:60] + ("..." if len(text) > 60 else "")
    return f"the text {head!r}"


def _check(found, count, what, text, path, caller):
    """Raise SubstitutionError unless found matches count (None: at least one)."""
    if found == 0 or (count is not None and found != count):
        expected = "at least once" if count is None else f"{count} time(s)"
        raise SubstitutionError(f"{caller}: {what} found {found} time(s) in "
                                f"{_where(text, path)}, expected {expected}")


def _finish(new_text, path):
    """Write the edited text back to the file it came from; return it."""
    if path is not None:
        with open(path, "w") as f:
            f.write(new_text)
    return new_text


def substitute(path_or_text, old, new, count=1):
    """Replace the literal string old by new, in a file (edited in place) or a text; returns
    the new text. count: how many times old must occur (every occurrence is replaced);
    None: at least once. Otherwise SubstitutionError naming the file and old."""
    if not old:
        raise ValueError("substitute: empty pattern")
    text, path = _source(path_or_text)
    _check(text.count(old), count, f"{old!r}", text, path, "substitute")
    return _finish(text.replace(old, new), path)


def substitute_re(path_or_text, pattern, repl, count=1, flags=re.MULTILINE):
    """re.sub(pattern, repl) in a file (edited in place) or a text; returns the new text.
    repl: a replacement string (backreferences \\1, \\g<name>) or a function of the match.
    count: how many matches there must be (all are replaced); None: at least one.
    Otherwise SubstitutionError naming the file and the pattern. ^ and $ match at the
    line ends (re.MULTILINE) unless flags says otherwise."""
    text, path = _source(path_or_text)
    new_text, found = re.subn(pattern, repl, text, flags=flags)
    _check(found, count, f"the pattern {pattern!r}", text, path, "substitute_re")
    return _finish(new_text, path)


def set_entry(path_or_text, key, value, count=1):
    """Set the value of the dictionary entry 'key value;', a line that starts with key after
    its indentation (so a // comment never matches): the text between the key's spacing and
    the ';' is replaced, the rest of the line (a trailing comment) kept. count: how many such
    entries there must be (all are set); None: at least one. Otherwise SubstitutionError
    naming the file and the key."""
    pattern = rf"^([ \t]*{re.escape(key)}[ \t]+)[^;\n]*;"
    text, path = _source(path_or_text)
    new_text, found = re.subn(pattern, lambda m: f"{m.group(1)}{value};", text,
                              flags=re.MULTILINE)
    _check(found, count, f"the entry {key!r} ({pattern!r})", text, path, "set_entry")
    return _finish(new_text, path)


def main(argv):
    usage = ("usage: validationTools.py substitute FILE OLD NEW [OLD NEW ...]\n"
             "       validationTools.py set FILE KEY VALUE [KEY VALUE ...]")
    if len(argv) < 5 or argv[1] not in ("substitute", "set") or (len(argv) - 3) % 2:
        sys.exit(usage)
    edit = substitute if argv[1] == "substitute" else set_entry
    path = Path(argv[2])
    try:
        for old, new in zip(argv[3::2], argv[4::2]):
            edit(path, old, new)
    except (SubstitutionError, OSError) as e:
        sys.exit(f"validationTools.py: {e}")


if __name__ == "__main__":
    main(sys.argv)
