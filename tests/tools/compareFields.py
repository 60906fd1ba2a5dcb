#!/usr/bin/python3
"""Compare the fields of two runs of the same case, time by time.

    compareFields.py caseA caseB --fields U p --rtol 1e-8 --atol 1e-10

For each time folder of caseA (except 0) and each field: passes if the
largest difference is <= rtol * (largest magnitude in caseA) + atol (atol
covers fields that are zero up to round-off, e.g. the pressure of a fully
developed channel). Exits 1 if a time or field is missing in caseB or any
difference exceeds its bound.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from foamFields import read_internal_field, time_dirs  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    parser.add_argument("caseA")
    parser.add_argument("caseB")
    parser.add_argument("--fields", nargs="+", required=True)
    parser.add_argument("--rtol", type=float, required=True)
    parser.add_argument("--atol", type=float, default=0.0)
    args = parser.parse_args()

    times = time_dirs(args.caseA)
    if not times:
        print(f"FAIL: no time folders in {args.caseA}")
        return 1
    worst = 0.0
    failed = False
    for t in times:
        for field in args.fields:
            pa = os.path.join(args.caseA, t, field)
            pb = os.path.join(args.caseB, t, field)
            if not os.path.isfile(pb):
                print(f"FAIL: {pb} missing")
                failed = True
                continue
            a = read_internal_field(pa)
            b = read_internal_field(pb, n_cells=len(a))
            if a.shape != b.shape:
                print(f"FAIL: {field} at t = {t}: shapes {a.shape} and {b.shape} differ")
                failed = True
                continue
            scale = np.abs(a).max()
            diff = np.abs(a - b).max()
            bound = args.rtol * scale + args.atol
            worst = max(worst, diff / bound if bound > 0 else np.inf * diff)
            status = "ok" if diff <= bound else "FAIL"
            failed |= not diff <= bound
            print(f"{status}: {field} t = {t}: max |A - B| = {diff:.3e}, max |A| = {scale:.3e},"
                  f" bound {bound:.3e}")
    print(f"largest difference / bound: {worst:.3e}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
