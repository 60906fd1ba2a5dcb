#!/usr/bin/python3
"""Check a body-force-driven periodic channel against Poiseuille's profile.

    checkPoiseuille.py CASE --time T --acceleration A --nu NU --height H --rtol R

Walls at y = 0 and y = H, force per unit mass A along x: at steady state
u(y) = A/(2 nu) y (H - y), v = w = 0. Reads U and the cell centres C
(postProcess -func writeCellCentres) at time T. Fails (exit 1) if
max |u - u_exact| > R * u_centre or the cross-flow exceeds 1e-6 u_centre.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from foamFields import read_internal_field  # noqa: E402


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    p.add_argument("case")
    p.add_argument("--time", required=True)
    p.add_argument("--acceleration", type=float, required=True)
    p.add_argument("--nu", type=float, required=True)
    p.add_argument("--height", type=float, required=True)
    p.add_argument("--rtol", type=float, required=True)
    a = p.parse_args()

    U = read_internal_field(os.path.join(a.case, a.time, "U"))
    C = read_internal_field(os.path.join(a.case, a.time, "C"), n_cells=len(U))
    y = C[:, 1]
    exact = a.acceleration / (2 * a.nu) * y * (a.height - y)
    u_centre = a.acceleration * a.height**2 / (8 * a.nu)
    err = np.abs(U[:, 0] - exact).max() / u_centre
    cross = np.abs(U[:, 1:]).max() / u_centre
    # bulk velocity: exact 2/3 u_centre; midpoint rule on the cell centres
    bulk = U[:, 0].mean() / u_centre
    print(f"u_centre exact {u_centre:.6g} m/s; max |u - u_exact| / u_centre = {err:.3e} (rtol {a.rtol:g})")
    print(f"bulk / u_centre = {bulk:.6f} (exact 2/3); max cross-flow / u_centre = {cross:.3e}")
    ok = err <= a.rtol and cross <= 1e-6
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
