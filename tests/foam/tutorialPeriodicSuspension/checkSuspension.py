"""Checks of a periodicSuspension quick run (run by tests/foam/tutorialPeriodicSuspension/run).

    checkSuspension.py CASE                   the run in CASE (below)
    checkSuspension.py --compare A B UNTIL RTOL
                                              two runs of the same case (serial, 2 ranks): the
                                              centres, velocities and orientations of every body
                                              agree to RTOL of their scale up to t = UNTIL s

CASE: every centre stays in the box [0, L)^3 and the unwrapped centre differs from it by whole
periods, at least half the bodies crossed the lower face; the suspension settles (mean vertical
velocity over the bodies and the second half below -10 mm/s); one meanFlow line per step, its
net-weight gradient (rho_p - rho_f) sum V_p g / V_box to 1e-9, the mean velocity over the box
below 1 % of the mean settling speed; no body faster than 0.2 m/s and no hydrodynamic force above
5 times the body's net weight; the largest overlap of the collision lines below the model's cap
(0.1 of the smallest semi-axis).
Exit 0 when every check passes, 1 with a message otherwise, 2 on bad usage.
"""
import math
import os
import re
import sys

import h5py
import numpy as np

MEAN_FLOW = re.compile(r"^immersedBodies: meanFlow zeroFlux: mean pressure gradient \([^)]*\) "
                       r"Pa/m \(net weight \(([^)]*)\), flux hold \([^)]*\)\), mean velocity of "
                       r"the last solve \(([^)]*)\)")
OVERLAP = re.compile(r"^collisions: .*max overlap ([-+0-9.eE]+) a_min")


def fail(message):
    print(f"checkSuspension: {message}")
    sys.exit(1)


def entry(case, path, pattern):
    if not os.path.exists(os.path.join(case, path)):
        fail(f"{os.path.join(case, path)}: no such file")
    with open(os.path.join(case, path)) as f:
        m = re.search(pattern, f.read(), re.M)
    if not m:
        fail(f"no match for {pattern!r} in {path}")
    return m.group(1)


def series(case, names=("time", "centre", "unwrappedCentre", "velocity", "orientation",
                        "hydroForce")):
    path = os.path.join(case, "postProcessing", "immersedBodies", "bodies.h5")
    if not os.path.exists(path):
        fail(f"{path}: no such file")
    try:
        f = h5py.File(path, "r", locking=False)
    except OSError as e:
        fail(f"{path}: not readable ({e})")
    with f:
        missing = [k for k in names + ("semiAxes", "density") if k not in f]
        if missing:
            fail(f"{path}: no dataset {', '.join(missing)}")
        rows = min(f[k].shape[0] for k in names)
        data = {k: np.asarray(f[k][:rows], float) for k in names}
        data["semiAxes"] = np.asarray(f["semiAxes"][()], float)
        data["density"] = np.asarray(f["density"][()], float)
    return data


def check(case):
    L = float(entry(case, "system/blockMeshDict", r"^L\s+(\S+);")) \
        * float(entry(case, "system/blockMeshDict", r"^scale\s+(\S+);"))
    end = float(entry(case, "system/controlDict", r"^endTime\s+(\S+);"))
    rho_f = float(entry(case, "constant/immersedBodiesProperties", r"^fluidDensity\s+(\S+);"))
    g = np.array([float(x) for x in entry(case, "constant/g", r"^value\s*\(([^)]*)\)").split()])
    s = series(case)
    t, c, u, v = s["time"], s["centre"], s["unwrappedCentre"], s["velocity"]
    for k in ("centre", "unwrappedCentre", "velocity", "orientation"):
        if not np.all(np.isfinite(s[k])):
            fail(f"non-finite {k}")
    if t[-1] < end * (1 - 1e-9):
        fail(f"the series ends at t = {t[-1]} s, before endTime {end} s")

    # inside the box, wrapped by whole periods
    if c.min() < 0 or c.max() >= L:
        fail(f"a centre left the box [0, {L}): {c.min():.6g} .. {c.max():.6g} m")
    shift = (u - c) / L
    if np.abs(shift - np.round(shift)).max() > 1e-9:
        fail(f"unwrappedCentre - centre is not whole periods: {np.abs(shift - np.round(shift)).max():.3g} L")
    crossed = np.mean(np.round(shift[-1, :, 2]) <= -1)
    if crossed < 0.5:
        fail(f"only {crossed:.2f} of the bodies crossed the lower periodic face")

    # settling
    late = t >= t[-1] / 2
    vz = v[late, :, 2].mean()
    if not vz < -0.01:
        fail(f"mean vertical velocity over the second half {vz:.4g} m/s: the bodies do not settle")
    top = np.linalg.norm(v, axis=2).max()
    if top > 0.2:
        fail(f"a body moves at {top:.3g} m/s (bound 0.2 m/s, twice the single sphere's u_t)")

    # a hydrodynamic force far above the net weight: the step-to-step alternating force of a
    # pair in a long contact (README, "Close pairs")
    volume = 4 / 3 * math.pi * np.prod(s["semiAxes"], axis=1)
    force = (np.linalg.norm(s["hydroForce"], axis=2)
             / ((s["density"] - rho_f) * volume * np.linalg.norm(g))).max()
    if force > 5:
        fail(f"a hydrodynamic force of {force:.3g} times the body's net weight (bound 5)")

    # meanFlow zeroFlux
    log = os.path.join(case, "log.immersedSpheroidFoam")
    if not os.path.exists(log):
        fail(f"{log}: no such file")
    weights, means, overlap = [], [], 0.0
    with open(log, errors="replace") as f:
        for line in f:
            m = MEAN_FLOW.search(line)
            if m:
                weights.append([float(x) for x in m.group(1).split()])
                means.append([float(x) for x in m.group(2).split()])
            m = OVERLAP.search(line)
            if m:
                overlap = max(overlap, float(m.group(1)))
    steps = len(t) - 1
    if len(weights) != steps:
        fail(f"{len(weights)} meanFlow lines in {log} for {steps} steps")
    expected = (s["density"] - rho_f) @ volume * g / L ** 3
    error = np.abs(np.array(weights) - expected).max() / np.linalg.norm(expected)
    if error > 1e-9:
        fail(f"the logged net-weight gradient differs from (rho_p - rho_f) sum V_p g / V_box "
             f"{expected} Pa/m by {error:.3g} of it")
    worst = np.linalg.norm(np.array(means), axis=1).max()
    if worst > 0.01 * abs(vz):
        fail(f"mean velocity over the box up to {worst:.3g} m/s, {worst / abs(vz):.3g} of the "
             f"settling speed (bound 0.01)")
    if overlap >= 0.1:
        fail(f"bodies overlapped by {overlap:.3g} of the smallest semi-axis (cap 0.1)")
    print(f"checkSuspension: {c.shape[1]} bodies inside the box, {crossed:.2f} crossed the lower "
          f"face; settling at {-vz * 1e3:.1f} mm/s; largest speed {top * 1e3:.1f} mm/s; mean "
          f"velocity over the box <= {worst / abs(vz):.2g} of the settling speed; net weight to "
          f"{error:.1g}; largest overlap {overlap:.3g} a_min; largest hydrodynamic force "
          f"{force:.3g} net weights")


def compare(a, b, until, rtol):
    sa, sb = series(a), series(b)
    ta, tb = sa["time"], sb["time"]
    ia = np.flatnonzero(ta <= until * (1 + 1e-9))
    ib = np.searchsorted(tb, ta[ia])
    ok = (ib < len(tb))
    ok[ok] = np.abs(tb[ib[ok]] - ta[ia[ok]]) <= 1e-9 * np.maximum(ta[ia[ok]], 1e-30)
    if ok.sum() < 10:
        fail(f"only {ok.sum()} shared times up to t = {until} s")
    ia, ib = ia[ok], ib[ok]
    worst = {}
    for k in ("centre", "velocity", "orientation"):
        x, y = sa[k][ia], sb[k][ib]
        scale = 1.0 if k == "orientation" else np.abs(sa[k][ia] - (sa[k][0] if k == "centre" else 0)).max()
        worst[k] = np.abs(x - y).max() / scale
    print("checkSuspension: up to t = {:g} s ({} rows), largest differences: {}".format(
        until, len(ia), ", ".join(f"{k} {w:.2g}" for k, w in worst.items())))
    bad = {k: w for k, w in worst.items() if not w <= rtol}
    if bad:
        fail(f"the runs differ by more than {rtol:g} of the scale: {bad}")


def main(argv):
    if len(argv) == 2 and not argv[1].startswith("-"):
        check(argv[1])
    elif len(argv) == 6 and argv[1] == "--compare":
        compare(argv[2], argv[3], float(argv[4]), float(argv[5]))
    else:
        print(__doc__.split("\n\n")[1])
        sys.exit(2)


if __name__ == "__main__":
    main(sys.argv)
