"""Read OpenFOAM ASCII volume fields (internalField) into numpy arrays.

Only what the tests need: uniform or nonuniform scalar/vector internal
fields of a case written with 'writeFormat ascii'. Use Debian's
/usr/bin/python3 (numpy from python3-numpy).
"""
import os
import re

import numpy as np

_UNIFORM = re.compile(r"internalField\s+uniform\s+(\([^)]*\)|[^;\s]+)\s*;")
_NONUNIFORM = re.compile(r"internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\(")


def time_dirs(case):
    """Time folders of a case (numeric names), sorted, without 0."""
    times = []
    for name in os.listdir(case):
        try:
            value = float(name)
        except ValueError:
            continue
        if os.path.isdir(os.path.join(case, name)) and value > 0:
            times.append((value, name))
    return [name for _, name in sorted(times)]


def read_internal_field(path, n_cells=None):
    """Return the internal field as an (n,) or (n, 3) float array.

    A uniform field needs n_cells to be expanded; without it a single value
    (shape (1,) or (1, 3)) is returned.
    """
    with open(path) as f:
        text = f.read()
    m = _NONUNIFORM.search(text)
    if m:
        kind, n = m.group(1), int(m.group(2))
        body = text[m.end():]
        if kind == "vector":
            values = re.findall(r"\(\s*([^()\s]+)\s+([^()\s]+)\s+([^()\s]+)\s*\)", body[: body.find("\n)")])
            arr = np.array(values, dtype=float)
        elif kind == "scalar":
            arr = np.array(body[: body.find(")")].split(), dtype=float)
        else:
            raise ValueError(f"{path}: unsupported field type List<{kind}>")
        if len(arr) != n:
            raise ValueError(f"{path}: expected {n} values, read {len(arr)}")
        return arr
    m = _UNIFORM.search(text)
    if m:
        value = np.array(m.group(1).strip("()").split(), dtype=float)
        count = n_cells if n_cells is not None else 1
        return np.tile(value, (count, 1)) if value.size == 3 else np.full(count, value[0])
    raise ValueError(f"{path}: no ASCII internalField found (writeFormat ascii?)")
