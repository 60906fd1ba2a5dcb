#!/usr/bin/python3
"""Unit test of validation/wetRebound/wetRebound.py's analysis (run by
tests/foam/wetReboundAnalysis/run) on a synthetic body time series with a known answer:
a sphere of the St 152 case approaching the wall at 1 m/s, in contact for 1 ms, leaving at
0.6 m/s and decelerating uniformly to a known top gap and back to 0.1 a; the collision force
is on from a gap of one radius on the way in to 0.2 a on the way out."""
import math
import os
import sys
import tempfile
import unittest
from pathlib import Path

import h5py
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "validation" / "wetRebound"))
import wetRebound as wr  # noqa: E402

NAME = "St152"
A = wr.CASES[NAME][4] / 2      # radius [m]
U_IN, U_OUT = 1.0, 0.6          # approach and leaving speeds [m/s]
TOP = 0.5                       # the rebound's height over the radius
DECEL = U_OUT ** 2 / (2 * TOP * A)
CONTACT = 1e-3                  # s
DT = 1e-5


def trajectory():
    """time, gap [m], vertical velocity, collision force of the synthetic bounce."""
    g0 = 1.5 * A
    t_touch = g0 / U_IN
    t_leave = t_touch + CONTACT
    delta = CONTACT / math.pi * U_IN        # overlap amplitude: the velocity is continuous at the touch
    # to the fall back through a gap of 0.1 a (a real series would meet the wall again there)
    fall = (U_OUT + math.sqrt(U_OUT ** 2 - 2 * DECEL * 0.1 * A)) / DECEL
    t = np.arange(0.0, t_leave + fall, DT)
    gap, w, fc = np.zeros_like(t), np.zeros_like(t), np.zeros_like(t)
    for k, tk in enumerate(t):
        if tk < t_touch:
            gap[k], w[k] = g0 - U_IN * tk, -U_IN
            fc[k] = 1.0 if gap[k] < A else 0.0
        elif tk < t_leave:
            s = math.pi * (tk - t_touch) / CONTACT
            gap[k], w[k], fc[k] = -delta * math.sin(s), -delta * math.pi / CONTACT * math.cos(s), 1.0
        else:
            tau = tk - t_leave
            gap[k], w[k] = U_OUT * tau - 0.5 * DECEL * tau ** 2, U_OUT - DECEL * tau
            fc[k] = 1.0 if (gap[k] < 0.2 * A and w[k] > 0) else 0.0
    return t, gap, w, fc


def with_second_touch(t, gap, w, fc):
    """The series continued through a second touch of the wall (the fall as in trajectory(),
    no collision force above the wall), after which the sphere leaves faster than from the
    first (a second bounce the analysis must not read)."""
    extra = np.arange(1, 800) * DT
    g2 = gap[-1] + w[-1] * extra - 0.5 * DECEL * extra ** 2
    w2 = w[-1] - DECEL * extra
    k = int(np.flatnonzero(g2 < -0.3 * A)[0])  # deeper than the first contact (0.21 a)
    up = np.arange(1, 60) * DT
    t = np.concatenate([t, t[-1] + extra[:k + 1], t[-1] + extra[k] + up])
    gap = np.concatenate([gap, g2[:k + 1], g2[k] + 2 * U_OUT * up])
    w = np.concatenate([w, w2[:k + 1], np.full(len(up), 2 * U_OUT)])
    fc = np.concatenate([fc, (g2[:k + 1] < 0).astype(float), np.ones(len(up))])
    return t, gap, w, fc


def write_h5(path, second_touch=False):
    t, gap, w, fc = trajectory()
    if second_touch:
        t, gap, w, fc = with_second_touch(t, gap, w, fc)
    n = len(t)
    vec = lambda z: np.stack([np.zeros(n), np.zeros(n), z], axis=1).reshape(n, 1, 3)  # noqa: E731
    with h5py.File(path, "w") as f:
        f["time"] = t
        f["centre"] = vec(gap + A)
        f["velocity"] = vec(w)
        f["collisionForce"] = vec(fc)
        f["hydroForce"] = vec(np.zeros(n))


def write_h5_from_the_touch(path):
    """The bounce from its first row with a collision force: no approach to measure."""
    t, gap, w, fc = trajectory()
    k = int(np.flatnonzero(fc != 0)[0])
    n = len(t) - k
    vec = lambda z: np.stack([np.zeros(n), np.zeros(n), z[k:]], axis=1).reshape(n, 1, 3)  # noqa: E731
    with h5py.File(path, "w") as f:
        f["time"] = t[k:]
        f["centre"] = vec(gap + A)
        f["velocity"] = vec(w)
        f["collisionForce"] = vec(fc)
        f["hydroForce"] = vec(np.zeros(len(t)))


def speed_out(h):
    """The exact leaving speed at the gap h (over the radius)."""
    return math.sqrt(U_OUT ** 2 - 2 * DECEL * h * A)


class WetReboundAnalysis(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(dir=os.environ.get("TMPDIR"))
        cls.h5 = os.path.join(cls.dir, "bounce.h5")
        write_h5(cls.h5)

    def test_rebound_speeds(self):
        r = wr.analyse(self.h5, NAME)
        self.assertAlmostEqual(r["U_in"], U_IN, places=9)
        self.assertAlmostEqual(r["e"], U_OUT / U_IN, delta=2 * DECEL * DT)
        # after the film: the first sample with no collision force on the way out, at 0.2 a
        self.assertAlmostEqual(r["e_after_film"], speed_out(0.2), delta=2 * DECEL * DT)

    def test_top_gap_is_the_rebound_height(self):
        # the collision force is on from a gap of one radius on the way in: the rebound's
        # height (0.5 a) must not be confused with that approach gap
        r = wr.analyse(self.h5, NAME)
        self.assertAlmostEqual(r["top_gap_a"], TOP, delta=1e-4)

    def test_same_gap_restitution(self):
        gaps = (0.05, 0.1, 0.2, 0.3, 0.6)
        values = wr.same_gap_restitution(self.h5, NAME, gaps=gaps)
        for h, v in zip(gaps[:-1], values[:-1]):
            self.assertAlmostEqual(v, speed_out(h) / U_IN / wr.E_DRY, delta=1e-4, msg=f"h = {h} a")
        self.assertEqual(values[-1], 0.0, "a gap above the rebound's height gives zero")


class WetReboundAnalysisSecondTouch(unittest.TestCase):
    def test_only_the_first_bounce_is_read(self):
        # a series that runs on into a second touch gives the first bounce's figures
        d = tempfile.mkdtemp(dir=os.environ.get("TMPDIR"))
        one, two = os.path.join(d, "one.h5"), os.path.join(d, "two.h5")
        write_h5(one)
        write_h5(two, second_touch=True)
        a, b = wr.analyse(one, NAME), wr.analyse(two, NAME)
        for key in ("U_in", "e", "e_spring", "e_after_film", "top_gap_a", "max_overlap_a",
                    "J_coll", "J_hydro", "J_gravity"):
            self.assertAlmostEqual(a[key], b[key], places=12, msg=key)
        self.assertAlmostEqual(b["e"], U_OUT / U_IN, delta=2 * DECEL * DT)
        # and the speeds at a common gap of the first bounce (not of the second touch's
        # deeper overlap)
        gaps = (0.05, 0.1, 0.2)
        self.assertEqual(wr.same_gap_restitution(one, NAME, gaps=gaps),
                         wr.same_gap_restitution(two, NAME, gaps=gaps))


class WetReboundWholeBounce(unittest.TestCase):
    """bounce_analysis: the contact, the rebound's top and the comparison with a measured
    trajectory (a file in the format of Gondret's digitised trajectories)."""

    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(dir=os.environ.get("TMPDIR"))
        cls.h5 = os.path.join(cls.dir, "bounce.h5")
        write_h5(cls.h5)
        cls.saved = wr.GONDRET_DATA

    @classmethod
    def tearDownClass(cls):
        wr.GONDRET_DATA = cls.saved

    def reference(self, scale):
        """A measured trajectory: the synthetic bounce sampled every 2 ms from the touch, its
        gaps times `scale`, in a directory of its own."""
        d = tempfile.mkdtemp(dir=self.dir)
        t, gap, _, _ = trajectory()
        t_touch = 1.5 * A / U_IN
        ts = np.arange(0.0, t[-1] - t_touch, 2e-3)
        np.savetxt(os.path.join(d, wr.GONDRET_TRAJECTORY[NAME]),
                   np.column_stack([ts, scale * np.interp(ts + t_touch, t, gap)]), delimiter=",")
        return d

    def test_contact_and_top(self):
        wr.GONDRET_DATA = tempfile.mkdtemp(dir=self.dir)    # no measured trajectory there
        b = wr.bounce_analysis(self.h5, NAME)
        self.assertAlmostEqual(b["contact_ms"], CONTACT * 1e3, delta=2e-3)
        self.assertAlmostEqual(b["depth_a"], CONTACT / math.pi * U_IN / A, delta=1e-4)
        self.assertAlmostEqual(b["top_a"], TOP, delta=1e-4)
        self.assertAlmostEqual(b["top_ms"], (CONTACT + U_OUT / DECEL) * 1e3, delta=DT * 1e3)
        self.assertFalse(b["falls_back"])
        self.assertNotIn("rms_speed", b)

    def test_against_a_measured_trajectory(self):
        # the same bounce measured: no speed difference, the same top
        wr.GONDRET_DATA = self.reference(1.0)
        b = wr.bounce_analysis(self.h5, NAME)
        self.assertLess(b["rms_speed"], 1e-9)
        # its top is its highest sample: at 4 ms from the touch, 0.5 ms past the top
        late = 4e-3 - CONTACT - U_OUT / DECEL
        self.assertAlmostEqual(b["ref_top_a"], TOP - 0.5 * DECEL * late ** 2 / A, delta=1e-9)
        # a rebound measured 20 % higher (every gap): its speeds are 20 % higher
        wr.GONDRET_DATA = self.reference(1.2)
        c = wr.bounce_analysis(self.h5, NAME)
        self.assertLess(c["mean_speed"], -0.01)
        self.assertGreater(c["rms_speed"], 0.01)
        self.assertAlmostEqual(c["ref_top_a"] / b["ref_top_a"], 1.2, places=9)


class QuasiSteadyBounce(unittest.TestCase):
    """quasi_steady_bounce against the closed forms of its two limits."""

    def test_in_vacuum_it_is_a_ballistic_bounce(self):
        a, u0, h0, g = 1.5e-3, 0.4, 2.0, 9.81
        b = wr.quasi_steady_bounce(a, 0.0, 0.0, u0, h0=h0, g=g)
        u_touch = math.sqrt(u0 ** 2 + 2 * g * h0 * a)
        self.assertAlmostEqual(b["u_touch"], u_touch, delta=1e-4 * u_touch)
        top = (wr.E_DRY * u_touch) ** 2 / (2 * g) / a
        self.assertAlmostEqual(b["top_a"], top, delta=1e-3 * top)

    def test_without_weight_and_inertia_of_the_fluid_the_film_takes_its_integral(self):
        # Stokes drag times Brenner's lambda only (no buoyancy, no added mass, Re = 0, g = 0):
        # m du = -6 pi mu a lambda(h/a) dh on the way in and out, lambda frozen below the
        # saturation gap
        a, mu, u0, h0, sat = 3e-3, 0.1, 0.5, 1.5, 1e-3
        b = wr.quasi_steady_bounce(a, 0.0, mu, u0, h0=h0, saturation=sat, g=0.0)
        mass = wr.RHO_P * 4 / 3 * math.pi * a ** 3
        x = np.logspace(math.log10(sat), 3.0, 4000)      # (the model tabulates to 1000 a)
        lam = np.array([wr.brenner(v) for v in x])
        # the integral of lambda over h/a from 0, cumulative
        cumulative = lam[0] * sat + np.concatenate(
            [[0.0], np.cumsum(0.5 * (lam[1:] + lam[:-1]) * np.diff(x))])
        k = 6 * math.pi * mu * a * a / mass
        u_touch = u0 - k * float(np.interp(h0, x, cumulative))
        self.assertAlmostEqual(b["u_touch"], u_touch, delta=5e-3 * u_touch)
        top = float(np.interp(wr.E_DRY * u_touch / k, cumulative, x))
        self.assertAlmostEqual(b["top_a"], top, delta=3e-3 * top)


class ForceRatio(unittest.TestCase):
    def test_in_and_out_against_the_quasi_steady_force(self):
        # the synthetic bounce with a resolved force equal to the quasi-steady one on the way
        # in and twice it on the way out (no collision force): ratios 1 and 2
        st, re_, rho_f, mu, d = wr.CASES[NAME]
        t, gap, w, _ = trajectory()
        stokes = 6 * math.pi * mu * (d / 2)
        below = np.flatnonzero(gap < 0)
        fh = np.zeros_like(t)
        for k in range(len(t)):
            if gap[k] <= 0:
                continue
            c = stokes * (wr.brenner(gap[k] / A) + 0.15 * (rho_f * abs(w[k]) * d / mu) ** 0.687)
            fh[k] = -c * w[k] * (1.0 if k < below[0] else 2.0)
        n = len(t)
        vec = lambda z: np.stack([np.zeros(n), np.zeros(n), z], axis=1).reshape(n, 1, 3)  # noqa: E731
        h5 = os.path.join(tempfile.mkdtemp(dir=os.environ.get("TMPDIR")), "forces.h5")
        with h5py.File(h5, "w") as f:
            f["time"] = t
            f["centre"] = vec(gap + A)
            f["velocity"] = vec(w)
            f["collisionForce"] = vec(np.zeros(n))
            f["hydroForce"] = vec(fh)
        self.assertAlmostEqual(wr.force_ratio(h5, NAME, "in"), 1.0, places=12)
        self.assertAlmostEqual(wr.force_ratio(h5, NAME, "out"), 2.0, places=12)


class WetReboundAnalysisWithoutApproach(unittest.TestCase):
    def test_a_series_starting_in_the_film_stops(self):
        # the approach speed is the sample before the first collision force: a series that
        # starts with one must stop with an error, not read the last row
        h5 = os.path.join(tempfile.mkdtemp(dir=os.environ.get("TMPDIR")), "fromTheTouch.h5")
        write_h5_from_the_touch(h5)
        with self.assertRaisesRegex(RuntimeError, "first row"):
            wr.analyse(h5, NAME)


if __name__ == "__main__":
    unittest.main(verbosity=2)
