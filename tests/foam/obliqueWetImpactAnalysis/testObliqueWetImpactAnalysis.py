#!/usr/bin/python3
"""Unit test of validation/obliqueWetImpact/obliqueWetImpact.py's analysis (run by
tests/foam/obliqueWetImpactAnalysis/run) on a synthetic oblique bounce with a known answer:
the sphere of the case approaches the wall at U_z = -1 m/s with U_x = 0.5 m/s and no spin,
is in contact for 1 ms, and leaves at U_z = 0.6 m/s with U_x = 0.3 m/s and a spin omega_y,
then decelerates uniformly; the collision force is on from a gap of one radius on the way in
to 0.2 a on the way out, with a tangential part of -0.2 times it (a contact sliding with
mu 0.2), and a constant tangential fluid force acts throughout."""
import math
import os
import sys
import tempfile
import unittest
from pathlib import Path

import h5py
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "validation" / "obliqueWetImpact"))
import obliqueWetImpact as ow  # noqa: E402

A = ow.D / 2
U_IN, U_OUT = 1.0, 0.6          # normal approach and leaving speeds [m/s]
UX_IN, UX_OUT = 0.5, 0.3        # tangential speeds [m/s]
OMEGA_OUT = 80.0                # spin about y after the contact [1/s]
DECEL = U_OUT ** 2 / (2 * 0.5 * A)
CONTACT = 1e-3
DT = 1e-5
MU_CONTACT = 0.2
FLUID_X = -1e-3                 # N


def write_h5(path):
    g0 = 1.5 * A
    t_touch = g0 / U_IN
    t_leave = t_touch + CONTACT
    delta = CONTACT / math.pi * U_IN
    t = np.arange(0.0, t_leave + U_OUT / DECEL, DT)
    n = len(t)
    gap, w, u, oy, fc = (np.zeros(n) for _ in range(5))
    for k, tk in enumerate(t):
        if tk < t_touch:
            gap[k], w[k], u[k] = g0 - U_IN * tk, -U_IN, UX_IN
            fc[k] = 1.0 if gap[k] < A else 0.0
        elif tk < t_leave:
            s = math.pi * (tk - t_touch) / CONTACT
            gap[k], w[k], fc[k] = -delta * math.sin(s), -delta * math.pi / CONTACT * math.cos(s), 1.0
            u[k], oy[k] = 0.5 * (UX_IN + UX_OUT), 0.5 * OMEGA_OUT
        else:
            tau = tk - t_leave
            gap[k], w[k] = U_OUT * tau - 0.5 * DECEL * tau ** 2, U_OUT - DECEL * tau
            u[k], oy[k] = UX_OUT, OMEGA_OUT
            fc[k] = 1.0 if (gap[k] < 0.2 * A and w[k] > 0) else 0.0
    vec = lambda x, y, z: np.stack([x, y, z], axis=1).reshape(n, 1, 3)  # noqa: E731
    zero = np.zeros(n)
    with h5py.File(path, "w") as f:
        f["time"] = t
        f["centre"] = vec(zero, zero, gap + A)
        f["velocity"] = vec(u, zero, w)
        f["angularVelocity"] = vec(zero, oy, zero)
        f["collisionForce"] = vec(-MU_CONTACT * fc, zero, fc)
        f["hydroForce"] = vec(FLUID_X + zero, zero, zero)


class ObliqueWetImpactAnalysis(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(dir=os.environ.get("TMPDIR"))
        cls.h5 = os.path.join(cls.dir, "bounce.h5")
        write_h5(cls.h5)

    def test_in_and_out_states(self):
        r = ow.analyse(self.h5)
        self.assertAlmostEqual(r["Un_in"], U_IN, places=12)
        self.assertAlmostEqual(r["psi_in"], UX_IN / U_IN, places=12)
        # the out state is the sample of the largest rebound speed: the first after the contact
        self.assertAlmostEqual(r["e_n"], U_OUT / U_IN, delta=DECEL * DT)
        self.assertAlmostEqual(r["psi_out"], (UX_OUT - A * OMEGA_OUT) / U_IN, places=12)
        self.assertAlmostEqual(r["mu_eff"], (UX_IN - UX_OUT) / ((1 + U_OUT / U_IN) * U_IN),
                               delta=1e-3)
        self.assertAlmostEqual(r["tan_out"], UX_OUT / U_OUT, delta=1e-3)
        self.assertAlmostEqual(r["omega_out_a_over_Un"], A * OMEGA_OUT / U_IN, places=12)

    def test_impulses(self):
        r = ow.analyse(self.h5)
        self.assertAlmostEqual(r["contact_ratio"], MU_CONTACT, places=12)
        self.assertAlmostEqual(r["J_fluid_n"], 0.0, places=12)
        # a constant fluid force: its impulse over the window equals the drag before it held
        # over the window, and is positive (it slows the sphere along +x)
        self.assertGreater(r["mu_fluid"], 0.0)
        self.assertAlmostEqual(r["mu_fluid"], r["mu_drag"], places=12)

    def test_impact_theory(self):
        mu, e_n, beta0 = 0.1, 0.8, 0.97
        psi_c = 3.5 * mu * (1 + e_n) / (1 + beta0)
        # sliding throughout: the tangential impulse is mu times the normal one
        self.assertAlmostEqual(float(ow.psi_theory(1.0, mu, e_n, beta0)), 1.0 - 3.5 * mu * 1.8)
        self.assertAlmostEqual(float(ow.mu_eff_theory(1.0, mu, e_n, beta0)), mu)
        # sticking: the contact point's tangential speed reverses with beta0
        self.assertAlmostEqual(float(ow.psi_theory(0.5 * psi_c, mu, e_n, beta0)),
                               -beta0 * 0.5 * psi_c)
        # continuous at the corner
        self.assertAlmostEqual(float(ow.psi_theory(psi_c * (1 + 1e-12), mu, e_n, beta0)),
                               float(ow.psi_theory(psi_c, mu, e_n, beta0)), places=9)


if __name__ == "__main__":
    unittest.main(verbosity=2)
