"""Compare the body time series (postProcessing/immersedBodies/bodies.h5) of two runs.

    compareBodies.py CASE_A CASE_B [--rtol R] [--from-time T] [--min-rows N]
                     [--scale-floor QUANTITY=VALUE ...]

At every time both series have (to 1e-9 relative), the centres, orientations, velocities,
angular velocities and hydrodynamic forces of every body must agree:
|a - b| <= rtol * scale, with scale the largest magnitude of that quantity over run A
(the centre: the largest displacement from the first row; the orientation: 1), or the
floor given for it (for a quantity that is zero by symmetry and only round-off otherwise,
e.g. --scale-floor angularVelocity=1e-3).
Prints the largest differences; exit 1 on a mismatch or when fewer than --min-rows times
are shared, 2 on bad usage.
"""
import argparse
import os
import sys

import h5py
import numpy as np

QUANTITIES = ("centre", "orientation", "velocity", "angularVelocity", "hydroForce", "hydroTorque")


def read(case):
    path = os.path.join(case, "postProcessing", "immersedBodies", "bodies.h5")
    if not os.path.exists(path):
        sys.exit(f"compareBodies: {path}: no such file")
    with h5py.File(path, "r", locking=False) as f:
        names = [n.decode() if isinstance(n, bytes) else str(n) for n in f["bodyNames"][()]]
        data = {q: np.asarray(f[q][:], dtype=float) for q in QUANTITIES + ("time",)}
    return names, data


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--rtol", type=float, default=1e-6)
    ap.add_argument("--from-time", type=float, default=-np.inf)
    ap.add_argument("--min-rows", type=int, default=2)
    ap.add_argument("--scale-floor", action="append", default=[])
    args = ap.parse_args()
    floors = {}
    for item in args.scale_floor:
        name, _, value = item.partition("=")
        if name not in QUANTITIES or not value:
            ap.error(f"--scale-floor {item}: expected QUANTITY=VALUE, QUANTITY one of {QUANTITIES}")
        floors[name] = float(value)
    na, a = read(args.a)
    nb, b = read(args.b)
    if na != nb:
        print(f"FAIL: body names differ: {na} vs {nb}")
        return 1
    ta, tb = a["time"], b["time"]
    ia, ib = [], []
    for i, t in enumerate(ta):
        if t < args.from_time:
            continue
        j = np.flatnonzero(np.abs(tb - t) <= 1e-9 * max(abs(t), 1e-30))
        if len(j):
            ia.append(i)
            ib.append(j[-1])
    if len(ia) < args.min_rows:
        print(f"FAIL: only {len(ia)} shared times (need {args.min_rows})")
        return 1
    ok = True
    for q in QUANTITIES:
        va, vb = a[q][ia], b[q][ib]
        if q == "centre":
            scale = np.max(np.abs(a[q] - a[q][0]))
        elif q == "orientation":
            scale = 1.0
            # q and -q are the same attitude
            sign = np.sign(np.sum(va * vb, axis=-1, keepdims=True))
            vb = vb * np.where(sign == 0, 1, sign)
        else:
            scale = np.max(np.abs(a[q]))
        scale = max(scale, floors.get(q, 0.0))
        diff = np.max(np.abs(va - vb)) if va.size else 0.0
        rel = diff / scale if scale > 0 else diff
        good = rel <= args.rtol
        ok &= good
        print(f"{'PASS' if good else 'FAIL'}: {q}: max difference {diff:.3e} = {rel:.3e} x scale "
              f"{scale:.3e} (rtol {args.rtol:g}) over {len(ia)} times")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
