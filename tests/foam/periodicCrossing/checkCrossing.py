"""Checks of a sphere moving through a corner of a triply periodic box
(tests/foam/periodicSphereCase), run by tests/foam/periodicCrossing/run.

    checkCrossing.py CASE MIDDLE

- the centre stays in the box [0, L)^3 and is wrapped at the corner; the
  unwrapped centre is the prescribed path c0 + U t;
- the force and torque are those of the same motion in the middle of the box:
  MIDDLE is the case with the body 12 cells (0.024 m) further back along each
  axis, where it never reaches a face. A periodic box of uniform cells is the
  same seen from any cell, so the two runs must agree to the solver's
  tolerance (1e-6 of the force); a body losing its cells beyond a face, or a
  term of the wrong image, would change the force by tens of %;
- the momentum balance: the fluid's momentum changes by minus the impulse of the
  hydrodynamic force between two written times (within 2 %: the part of the
  force that is the internal fluid's momentum change is not in the fluid's);
- the surfaces are drawn on each side: 8 images at 0.3 s (straddling the
  corner), 1 at 0.1 s.
Exit 1 with a message on a failed check.
"""
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from foamFields import read_internal_field  # noqa: E402

L = 0.048            # box side [m]
H = 0.002            # cell size [m]
RHO = 1000.0         # fluid density
U = np.array([0.02, 0.02, 0.02])
C0 = np.array([0.038, 0.038, 0.038])
POINTS_PER_BODY = 642  # surfaceSubdivisions 3: 10 4^3 + 2


def fail(message):
    sys.exit(f"checkCrossing: {message}")


def series(case):
    with h5py.File(os.path.join(case, "postProcessing", "immersedBodies", "bodies.h5"), "r",
                   locking=False) as f:
        return {name: f[name][()] if name == "time" else f[name][:, 0, :]
                for name in ("time", "centre", "unwrappedCentre", "hydroForce", "hydroTorque")}


def main(case, middle):
    a, b = series(case), series(middle)
    t, centre, unwrapped, force = a["time"], a["centre"], a["unwrappedCentre"], a["hydroForce"]
    if len(t) < 55 or len(b["time"]) != len(t):
        fail(f"{len(t)} and {len(b['time'])} rows, expected 60 each")

    # wrapping
    if not ((centre >= 0) & (centre < L)).all():
        fail(f"a centre outside the box: {centre[(centre < 0) | (centre >= L)][:3]}")
    path = C0 + np.outer(t, U)
    err = np.abs(unwrapped - path).max()
    print(f"unwrapped centre against c0 + U t: {err:.3g} m")
    if err > 1e-12:
        fail(f"the unwrapped centre is off the prescribed path by {err:.3g} m")
    if not np.allclose(centre[-1], path[-1] - L, atol=1e-12):
        fail(f"the last centre {centre[-1]} is not the path {path[-1]} wrapped by {L}")

    # across the faces (from 0.25 s) as in the middle of the box
    if np.abs(b["unwrappedCentre"] - (path - 0.024)).max() > 1e-12:
        fail(f"{middle}: not the same path 0.024 m further back")
    scale = np.abs(force).max()
    dF = np.abs(force - b["hydroForce"]).max() / scale
    dT = np.abs(a["hydroTorque"] - b["hydroTorque"]).max() / (scale * 0.005)
    across = t >= 0.25
    print(f"force {np.abs(force[across]).mean():.4g} N per component across the faces; against "
          f"the run in the middle: force {dF:.3g}, torque {dT:.3g} of |F| R")
    if dF > 1e-6 or dT > 1e-6:
        fail(f"the force across the periodic faces differs from the same motion in the middle "
             f"of the box by {dF:.3g} (torque {dT:.3g}) of its scale")
    if (force[across] @ (-U)).min() <= 0:
        fail("the force is not against the motion")

    # momentum balance between the written times 0.2 and 0.6
    def momentum(time):
        u = read_internal_field(os.path.join(case, time, "U"), 24 ** 3)
        return RHO * H ** 3 * u.sum(axis=0)
    p2, p6 = momentum("0.2"), momentum("0.6")
    window = (t > 0.2 + 1e-9) & (t <= 0.6 + 1e-9)
    impulse = 0.01 * force[window].sum(axis=0)  # the force of each step acts over that step
    mismatch = np.linalg.norm((p6 - p2) + impulse) / np.linalg.norm(impulse)
    print(f"fluid momentum change {p6 - p2} against minus the impulse {-impulse}: "
          f"{100 * mismatch:.3f} %")
    if mismatch > 0.02:
        fail(f"momentum balance off by {100 * mismatch:.2f} %")

    # the surfaces on each side
    def images(time):
        series = os.path.join(case, "postProcessing", "immersedBodies", "surfaces")
        name = os.path.join(series, f"surfaces_{time}.vtk")
        with open(name, "rb") as f:
            for line in f:
                if line.startswith(b"POINTS"):
                    return int(line.split()[1]) // POINTS_PER_BODY
        fail(f"{name}: no POINTS line")
    n1, n3 = images("0.1"), images("0.3")
    print(f"surfaces: {n1} image(s) at 0.1 s, {n3} at 0.3 s")
    if (n1, n3) != (1, 8):
        fail(f"surfaces: {n1} and {n3} images at 0.1 and 0.3 s, expected 1 and 8")
    print("checkCrossing: all checks passed")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: checkCrossing.py CASE MIDDLE")
    main(sys.argv[1], sys.argv[2])
