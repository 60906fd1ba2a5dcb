"""Checks of a sphere settling in a triply periodic box with meanFlow zeroFlux
(run by tests/foam/periodicSettling/run).

    checkSettling.py CASE
"""
import math
import os
import re
import sys

import h5py
import numpy as np

RHO_F, RHO_P, R, L, G = 1000.0, 1010.0, 0.005, 0.048, 9.81


def fail(message):
    sys.exit(f"checkSettling: {message}")


def main(case):
    with h5py.File(os.path.join(case, "postProcessing", "immersedBodies", "bodies.h5"), "r",
                   locking=False) as f:
        t = f["time"][()]
        u = f["velocity"][:, 0, :]
        centre = f["centre"][:, 0, :]
        unwrapped = f["unwrappedCentre"][:, 0, :]
    w = u[:, 2]
    late = t >= t[-1] - 0.3 - 1e-9
    change = abs(w[late][-1] - w[late][0]) / abs(w[-1])
    print(f"settling speed {-w[-1]:.5g} m/s at {t[-1]:g} s; change over the last 0.3 s "
          f"{100 * change:.3f} %")
    if not w[-1] < 0 or change > 0.01:
        fail(f"the sphere does not settle steadily: w = {w[late][0]:.5g} .. {w[-1]:.5g} m/s")
    # it starts 1 mm above the lower face: its centre crosses it and is wrapped to the top
    if not (unwrapped[-1, 2] < 0 and centre[-1, 2] > L / 2 and (centre[:, 2] >= 0).all()
            and abs(centre[-1, 2] - (unwrapped[-1, 2] + L)) < 1e-12):
        fail(f"the centre did not cross the lower periodic face and wrap: centre "
             f"{centre[-1, 2]:.6g}, unwrapped {unwrapped[-1, 2]:.6g}")

    log = open(os.path.join(case, "log.immersedSpheroidFoam")).read()
    lines = re.findall(r"meanFlow zeroFlux: mean pressure gradient \(([^)]*)\) Pa/m "
                       r"\(net weight \(([^)]*)\), flux hold \(([^)]*)\)\), mean velocity of "
                       r"the last solve \(([^)]*)\)", log)
    if len(lines) < 100:
        fail(f"{len(lines)} meanFlow lines in the log, expected one a step")
    weight = np.array([float(v) for v in lines[-1][1].split()])
    expected = -(RHO_P - RHO_F) * 4 / 3 * math.pi * R ** 3 * G / L ** 3  # (rho_p - rho_f) V_p g_z / V_box
    print(f"net-weight gradient {weight} Pa/m, expected (0 0 {expected:.6g})")
    if abs(weight[2] - expected) > 1e-6 * abs(expected) or abs(weight[:2]).max() > 0:
        fail(f"the net-weight term {weight} is not (0 0 {expected:.6g}) Pa/m")
    mean = np.array([[float(v) for v in line[3].split()] for line in lines[10:]])
    worst = np.abs(mean).max() / abs(w[-1])
    print(f"largest mean velocity over the box after the first 10 steps: {worst:.3g} of the "
          f"settling speed")
    if worst > 1e-4:
        fail(f"the volume flux is not held at zero: mean velocity {worst:.3g} of the speed")
    print("checkSettling: all checks passed")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: checkSettling.py CASE")
    main(sys.argv[1])
