#!/usr/bin/python3
"""Unit test of validation/drafting/drafting.py's analysis (run by
tests/foam/draftingAnalysis/run) on synthetic series with known answers: two spheres, the
trailing one closing the gap at a constant rate until they touch, then rolling over the
leading one until it is below it (kissing time, collision speed, pair force onset, tumbling
time, the analysed window); the signed surface gap of two spheroids in configurations whose
closest points are known; and the largest overlap read from a solver log."""
import math
import os
import sys
import tempfile
import unittest
from pathlib import Path

import h5py
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "validation" / "drafting"))
import drafting as dr  # noqa: E402

D = dr.D
R = D / 2
U_LEAD = 0.05           # m/s, the leading sphere's constant fall speed
CLOSING = 5.0           # 1/s, the gap over d closes at this rate
GAP0 = 1.5              # the gap over d at t = 0
T_TOUCH = (GAP0 + 0.01) / CLOSING   # the gap stops at -0.01 d (the contact's overlap)
T_KISS = (GAP0 - dr.KISS_GAP) / CLOSING
ROLL = 10.0             # rad/s: the trailing sphere rolls over the leading one after the touch
T_TUMBLE = T_TOUCH + (math.pi / 2) / ROLL
DT = 1e-3
Z0 = 0.0316             # the leading centre at t = 0
T_END = 0.62


def series():
    """time, centres (N, 2, 3), velocities, collision forces of (leading, trailing)."""
    t = np.arange(0.0, T_END, DT)
    n = len(t)
    c, u, fc = np.zeros((n, 2, 3)), np.zeros((n, 2, 3)), np.zeros((n, 2, 3))
    c[:, :, 0] = c[:, :, 1] = 0.005
    c[:, 0, 2] = Z0 - U_LEAD * t
    u[:, 0, 2] = -U_LEAD
    for k, tk in enumerate(t):
        if tk < T_TOUCH:
            dist, theta, ddist, dtheta = D * (1 + GAP0 - CLOSING * tk), 0.0, -CLOSING * D, 0.0
        else:
            dist, theta, ddist, dtheta = D * 0.99, ROLL * (tk - T_TOUCH), 0.0, ROLL
        c[k, 1] = c[k, 0] + dist * np.array([math.sin(theta), 0.0, math.cos(theta)])
        u[k, 1] = u[k, 0] + ddist * np.array([math.sin(theta), 0.0, math.cos(theta)]) \
            + dist * dtheta * np.array([math.cos(theta), 0.0, -math.sin(theta)])
        if dist / D - 1 < 0.44:
            fc[k, 1] = (0.0, 0.0, 1e-6)
            fc[k, 0] = (0.0, 0.0, -1e-6)
    return t, c, u, fc


def write_h5(path):
    t, c, u, fc = series()
    n = len(t)
    order = [1, 0]  # the file lists (trailing, leading): load() must sort them by name
    with h5py.File(path, "w") as f:
        f["time"] = t
        f["bodyNames"] = np.array([b"trailing", b"leading"])
        f["centre"] = c[:, order]
        f["velocity"] = u[:, order]
        f["collisionForce"] = fc[:, order]
        q = np.zeros((n, 2, 4))
        q[:, :, 0] = 1.0
        f["orientation"] = q
        f["semiAxes"] = np.full((2, 3), R)


class DraftingAnalysis(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.h5 = os.path.join(tempfile.mkdtemp(dir=os.environ.get("TMPDIR")), "bodies.h5")
        write_h5(cls.h5)
        cls.r = dr.analyse(cls.h5)

    def test_the_bodies_are_ordered_by_name(self):
        # the leading sphere starts below the trailing one
        self.assertAlmostEqual(self.r["centre"][0, 0, 2], Z0, places=12)

    def test_kissing_time(self):
        # the gap is linear in time: the interpolation between rows is exact
        self.assertAlmostEqual(self.r["kiss_time"], T_KISS, delta=1e-9)

    def test_collision_speed(self):
        # the trailing sphere's largest downward speed before the kissing
        self.assertAlmostEqual(self.r["collision_speed"], U_LEAD + CLOSING * D, delta=1e-9)

    def test_pair_force_onset(self):
        t, c, _, _ = series()
        first = t[np.flatnonzero((np.linalg.norm(c[:, 1] - c[:, 0], axis=1) - D) / D < 0.44)[0]]
        self.assertAlmostEqual(self.r["pair_onset_time"], first, delta=1e-12)

    def test_tumbling_time(self):
        # the trailing centre passes below the leading one at a quarter turn; the crossing is
        # interpolated between rows (cos is not linear: within a small part of a row)
        self.assertAlmostEqual(self.r["tumbling_time"], T_TUMBLE, delta=0.05 * DT)

    def test_window_ends_half_a_diameter_above_the_floor(self):
        t, c, _, _ = series()
        lowest = np.min(c[:, :, 2], axis=1) - R
        n = np.flatnonzero(lowest < dr.FLOOR_GAP * D)
        self.assertGreater(len(n), 0, "the series reaches the floor's half diameter")
        self.assertAlmostEqual(self.r["window_end"], t[n[0] - 1], delta=1e-12)
        self.assertLess(self.r["window_end"], t[-1])

    def test_smallest_gap(self):
        self.assertAlmostEqual(self.r["min_gap_d"], -0.01, delta=1e-9)


class SurfaceGap(unittest.TestCase):
    """Prolate spheroids (a = 2 b) with their closest points known, through the geometry
    core's ellipsoidDistance."""
    b = R / 2 ** (1 / 3)
    a = 2 * b
    axes = (a, b, b)
    same = (1.0, 0.0, 0.0, 0.0)
    turned = (math.cos(math.pi / 4), 0.0, 0.0, math.sin(math.pi / 4))  # axis along y

    def gap(self, offset, q2):
        return dr.surface_gaps(self.axes, np.zeros((1, 3)), np.array([self.same]),
                               np.array([offset], float), np.array([q2]))[0]

    def test_tip_to_tip(self):
        self.assertAlmostEqual(self.gap((2 * self.a + 0.1 * D, 0, 0), self.same), 0.1 * D,
                               delta=1e-7 * D)

    def test_side_by_side(self):
        self.assertAlmostEqual(self.gap((0, 2 * self.b + 0.05 * D, 0), self.same), 0.05 * D,
                               delta=1e-7 * D)

    def test_tip_to_side(self):
        self.assertAlmostEqual(self.gap((self.a + self.b + 0.02 * D, 0, 0), self.turned),
                               0.02 * D, delta=1e-7 * D)

    def test_overlapping_bodies_give_minus_the_penetration_depth(self):
        self.assertAlmostEqual(self.gap((2 * self.a - 0.2 * D, 0, 0), self.same), -0.2 * D,
                               delta=1e-7 * D)

    def test_every_row_in_one_call(self):
        offsets = np.array([[2 * self.a + h * D, 0, 0] for h in (0.3, 0.1, -0.05)])
        gaps = dr.surface_gaps(self.axes, np.zeros((3, 3)), np.tile(self.same, (3, 1)), offsets,
                               np.tile(self.same, (3, 1)))
        np.testing.assert_allclose(gaps, [0.3 * D, 0.1 * D, -0.05 * D], atol=1e-7 * D)


class LogMaxOverlap(unittest.TestCase):
    def test_up_to_the_window_and_over_the_run(self):
        log = os.path.join(tempfile.mkdtemp(dir=os.environ.get("TMPDIR")), "log.solver")
        with open(log, "w") as f:
            for t, x in ((0.1, 0.01), (0.2, 0.03), (0.3, 0.2), (0.4, 0.05)):
                f.write(f"Time = {t}\n\ncollisions: 2 bodies, max overlap {x} a_min\n")
        self.assertEqual(dr.log_max_overlap(log, 0.25), (0.03, 0.2))
        self.assertEqual(dr.log_max_overlap(log + ".missing", 0.25), (None, None))


if __name__ == "__main__":
    unittest.main(verbosity=2)
