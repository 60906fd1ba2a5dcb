#!/usr/bin/python3
"""Summary of a sedimentingSpheroid run: results.md from the body time series.

    summarise.py [CASE]     (default: the current directory)

Settling speed and Reynolds number, the tilt of the symmetry axis from the vertical (90 deg =
broadside-on) against time, the landing on the bottom (the first collision force), the solver's
wall and CPU time. Needs Debian's python3-h5py and python3-numpy (/usr/bin/python3).
"""
import os
import re
import sys

import h5py
import numpy as np

D, NU = 6e-3, 1e-5  # the case's equal-volume diameter and viscosity


def tilt_degrees(q):
    """Angle between the body x axis R(q) e_x and the vertical, folded into 0-90."""
    w, x, y, z = q[:, 0], q[:, 1], q[:, 2], q[:, 3]
    ez = 2 * (x * z - w * y)  # z component of R(q) e_x
    return np.degrees(np.arccos(np.clip(np.abs(ez), 0, 1)))


def main():
    case = sys.argv[1] if len(sys.argv) > 1 else "."
    with h5py.File(os.path.join(case, "postProcessing/immersedBodies/bodies.h5"), "r",
                   locking=False) as f:
        t = f["time"][()]
        c = f["centre"][:, 0, :]
        v = f["velocity"][:, 0, :]
        q = f["orientation"][:, 0, :]
        fc = f["collisionForce"][:, 0, :]
    tilt = tilt_degrees(q)
    w = -v[:, 2]
    k = int(np.argmax(w))
    landed = np.flatnonzero(np.linalg.norm(fc, axis=1) > 0)
    broad = np.flatnonzero(tilt > 80)
    rows = [("simulated time", f"{t[-1]:.3f} s ({len(t) - 1} steps)"),
            ("largest settling speed", f"{w[k] * 1e3:.1f} mm/s at t = {t[k]:.3f} s"),
            ("Reynolds number U D/nu there", f"{w[k] * D / NU:.1f}"),
            ("tilt from the vertical at the start", f"{tilt[0]:.1f} deg"),
            ("tilt at the largest speed", f"{tilt[k]:.1f} deg"),
            ("broadside-on (tilt > 80 deg) from", f"t = {t[broad[0]]:.3f} s" if len(broad) else "never"),
            ("lateral drift before landing",
             f"{np.hypot(*(c[landed[0] if len(landed) else -1, :2] - c[0, :2])) / D:.2f} D"),
            ("first contact with the bottom", f"t = {t[landed[0]]:.3f} s" if len(landed) else "none"),
            ("tilt at the end", f"{tilt[-1]:.1f} deg"),
            ("height of the centre at the end", f"{c[-1, 2] * 1e3:.2f} mm")]
    log = os.path.join(case, "log.immersedSpheroidFoam")
    if os.path.exists(log):
        times = re.findall(r"ExecutionTime = (\S+) s\s+ClockTime = (\S+) s", open(log).read())
        nprocs = re.findall(r"nProcs\s*:\s*(\d+)", open(log).read())
        if times:
            rows.append(("solver time", f"{float(times[-1][1]):.0f} s wall, {float(times[-1][0]):.0f} s CPU, "
                                        f"{nprocs[0] if nprocs else 1} rank(s)"))
    lines = ["| quantity | value |", "|---|---|"] + [f"| {a} | {b} |" for a, b in rows]
    with open(os.path.join(case, "results.md"), "w") as out:
        out.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
