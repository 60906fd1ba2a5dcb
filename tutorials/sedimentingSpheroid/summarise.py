#!/usr/bin/python3
"""Summary of a sedimentingSpheroid run: results.md from the body time series.

    summarise.py [CASE]     (default: the current directory)

The case's parameters (nu, the body, the fluid density, g) are read from its dictionaries.
Settling speed and Reynolds number, the tilt of the symmetry axis from the vertical (90 deg =
broadside-on) against time, the mean settling speed broadside-on and the ripple of the
hydrodynamic force there (its standard deviation from step to step over its mean), the landing
on the bottom (the first collision force), the solver's wall and CPU time. Needs the project's environment (etc/bashrc, for the shared
helpers in applications/utilities/plotBodies/caseSummary.py) and Debian's python3-h5py and
python3-numpy (/usr/bin/python3).
"""
import math
import os
import sys

import h5py
import numpy as np

try:
    from caseSummary import read_entry, solver_time_row, write_results
except ImportError:  # applications/utilities/plotBodies is on PYTHONPATH through etc/bashrc
    sys.exit("summarise.py: caseSummary not found; source the project's etc/bashrc")


def case_parameters(case):
    """nu, the body's equal-volume diameter, density and the fluid density, g, from the case."""
    nu = float(read_entry(case, "constant/transportProperties", r"^nu\s+([0-9.eE+-]+)\s*;")[0])
    axes = [float(x) for x in read_entry(case, "constant/immersedBodiesProperties",
                                         r"semiAxes\s*\(\s*(\S+)\s+(\S+)\s+(\S+)\s*\)")]
    rho_p = float(read_entry(case, "constant/immersedBodiesProperties", r"^\s+density\s+([0-9.eE+-]+)\s*;")[0])
    rho_f = float(read_entry(case, "constant/immersedBodiesProperties", r"^fluidDensity\s+([0-9.eE+-]+)\s*;")[0])
    g = float(read_entry(case, "constant/g", r"^value\s*\(\s*\S+\s+\S+\s+(\S+)\s*\)")[0])
    d = 2 * (axes[0] * axes[1] * axes[2]) ** (1 / 3)
    return nu, d, rho_p, rho_f, abs(g)


def tilt_degrees(q):
    """Angle between the body x axis R(q) e_x and the vertical, folded into 0-90."""
    w, x, y, z = q[:, 0], q[:, 1], q[:, 2], q[:, 3]
    ez = 2 * (x * z - w * y)  # z component of R(q) e_x
    return np.degrees(np.arccos(np.clip(np.abs(ez), 0, 1)))


def main():
    case = sys.argv[1] if len(sys.argv) > 1 else "."
    nu, d, rho_p, rho_f, g = case_parameters(case)
    galileo = math.sqrt(abs(rho_p / rho_f - 1) * g * d ** 3) / nu
    with h5py.File(os.path.join(case, "postProcessing/immersedBodies/bodies.h5"), "r",
                   locking=False) as f:
        t = f["time"][()]
        c = f["centre"][:, 0, :]
        v = f["velocity"][:, 0, :]
        q = f["orientation"][:, 0, :]
        fc = f["collisionForce"][:, 0, :]
        fh = f["hydroForce"][:, 0, :]
    tilt = tilt_degrees(q)
    w = -v[:, 2]
    k = int(np.argmax(w))
    landed = np.flatnonzero(np.linalg.norm(fc, axis=1) > 0)
    broad = np.flatnonzero(tilt > 80)
    # broadside-on, from the turn to 0.1 s before the first contact
    steady = np.zeros(len(t), dtype=bool)
    if len(broad):
        steady = t >= t[broad[0]]
        if len(landed):
            steady &= t <= t[landed[0]] - 0.1
    if steady.sum() > 10:
        force = np.linalg.norm(fh[steady], axis=1)
        broadside = (f"{w[steady].mean() * 1e3:.1f} mm/s, force ripple "
                     f"{100 * force.std() / force.mean():.1f} % "
                     f"(t = {t[steady][0]:.2f}-{t[steady][-1]:.2f} s)")
    else:
        broadside = "not broadside-on for 10 steps before landing"
    rows = [("equal-volume diameter D, Galileo number sqrt((rho_p/rho_f - 1) g D^3)/nu",
             f"{d * 1e3:.2f} mm, {galileo:.1f}"),
            ("simulated time", f"{t[-1]:.3f} s ({len(t) - 1} steps)"),
            ("largest settling speed", f"{w[k] * 1e3:.1f} mm/s at t = {t[k]:.3f} s"),
            ("Reynolds number U D/nu there", f"{w[k] * d / nu:.1f}"),
            ("tilt from the vertical at the start", f"{tilt[0]:.1f} deg"),
            ("tilt at the largest speed", f"{tilt[k]:.1f} deg"),
            ("broadside-on (tilt > 80 deg) from", f"t = {t[broad[0]]:.3f} s" if len(broad) else "never"),
            ("broadside-on until 0.1 s before landing: mean settling speed, std/mean of the hydrodynamic force",
             broadside),
            ("lateral drift before landing",
             f"{np.hypot(*(c[landed[0] if len(landed) else -1, :2] - c[0, :2])) / d:.2f} D"),
            ("first contact with the bottom", f"t = {t[landed[0]]:.3f} s" if len(landed) else "none"),
            ("tilt at the end", f"{tilt[-1]:.1f} deg"),
            ("height of the centre at the end", f"{c[-1, 2] * 1e3:.2f} mm")]
    row = solver_time_row(case)
    if row:
        rows.append(row)
    write_results(case, rows)

if __name__ == "__main__":
    main()
