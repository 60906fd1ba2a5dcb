#!/usr/bin/python3
"""Quasi-steady Stokes force on a rigid sphere translating near an infinite plane wall: an
exact-series reference for validation/lubricationResolution.

What it computes
----------------
A sphere of radius a in fluid of viscosity mu translates with velocity U, without rotating,
at the gap h (closest distance surface to wall) above a no-slip plane wall; the fluid is at
rest at infinity. Two motions:

  f_perp = -F_z / (6 pi mu a U)     translation along the wall normal (Brenner's problem)
  f_par  = -F_x / (6 pi mu a U)     translation parallel to the wall ("sliding", O'Neill's)
  g_par  =  T_y / (8 pi mu a^2 U)   torque about the sphere centre on the sliding sphere,

with the wall the plane z = 0 below the sphere and the sliding velocity along +x. f_perp and
f_par are drags (positive). g_par > 0 is the sense of rolling along the motion (angular velocity
+y, the bottom of the sphere turning backwards against the wall); this is the sign of Goldman,
Cox & Brenner's near-contact torque -(1/10) ln(h/a) - 0.1895, positive at small gaps.

Method
------
The exact solution in bispherical coordinates (xi, eta, phi): the wall is xi = 0, the sphere
xi = alpha with cosh(alpha) = 1 + h/a, the foci at z = +-c, c = a sinh(alpha). The velocity is
written v = (1/2) x p/mu + w with p and the three Cartesian components of w harmonic (this makes
v a Stokes flow; continuity is a further condition), and each harmonic function is expanded in
the separable bispherical harmonics

    (cosh xi - cos eta)^(1/2) exp(+-(n + 1/2) xi) P_n^m(cos eta) {cos, sin}(m phi).

For the normal motion (m = 0; Brenner 1961 solved it with Stimson & Jeffery's 1926 stream
function) p and w_z are axisymmetric and w_x + i w_y = e^(i phi) U_1; for the parallel motion
(m = 1; O'Neill 1964, Goldman, Cox & Brenner 1967, Part I) p and w_z go as cos(phi) and
w_x + i w_y = U_0 + U_2 e^(2 i phi). The no-slip conditions on the wall and on the sphere,
multiplied by (cosh xi - cos eta)^(1/2), and the continuity condition (div v is itself
harmonic, so it vanishes if it vanishes on both boundaries), multiplied by
(cosh xi - cos eta)^(-1/2), become Legendre series in which each coefficient involves only a
few neighbouring unknowns (the sphere's velocity aside); they are projected on P_k^m by
Gauss-Legendre quadrature (exact for the polynomial parts), a Galerkin form of the
recurrences these papers derive by hand, and solved as one linear system of 6 N (normal) or
8 N (parallel) coefficients, N = max(24, ceil(16/alpha)).
Force and torque are the integrals of the traction over the sphere (the pressure cancels from
sigma = mu [x (x) grad p' + grad p' (x) x]/2 + mu [grad w + grad w^T], p' = p/mu), by
Gauss-Legendre in cos(eta) and the trapezoidal rule in phi. No asymptote is used: every row
of the table is the exact series (column `source` = bispherical).

Sources: H. Brenner, Chem. Eng. Sci. 16 (1961) 242; M. Stimson & G. B. Jeffery, Proc. R. Soc.
A 111 (1926) 110; M. E. O'Neill, Mathematika 11 (1964) 67; A. J. Goldman, R. G. Cox &
H. Brenner, Chem. Eng. Sci. 22 (1967) 637 (Part I, near-contact asymptotes and the far-field
torque, and Faxen's far-field expansion for the parallel motion as they quote it).

Verified accuracy (`check`, the figures it prints)
--------------------------------------------------
  1. f_perp of the series against Brenner's closed form at the eleven gaps: largest relative
     difference 4e-12 (tolerance 0.3 %).
  2. f_par against Faxen's expansion: -8e-9, -3.5e-7, -1.2e-5 (relative) at h/a = 16, 8, 4
     (tolerance 0.3 %); -0.023 % at h/a = 2, -0.243 % at h/a = 1. g_par against the far-field
     torque (3/32) s^4 (1 - 3s/8): -0.06 %, -0.15 %, -0.18 % at h/a = 16, 8, 4 (tolerance
     0.3 %); +0.7 % at 2, +5.5 % at 1.
  3. f_par against Goldman, Cox & Brenner's -(8/15) ln(h/a) + 0.9588: +3.54 %, +1.29 %,
     +0.57 %, +0.22 % at h/a = 0.1, 0.04, 0.02, 0.01 (shrinking, as checked), +0.025 % and
     -0.036 % at 0.004 and 0.002. A fit of C + A eps ln eps + B eps to f_par + (8/15) ln eps
     (eps = h/a = 0.02 ... 0.002) gives C = 0.9543, not GCB's 0.9588: hence the change of sign
     below h/a ~ 0.003. g_par minus -(1/10) ln(h/a) - 0.1895: +0.0480, +0.0231, +0.0121,
     +0.0055, +0.0008, -0.0011 at h/a = 0.1, 0.04, 0.02, 0.01, 0.004, 0.002 (the same fit:
     C = -0.1929).
  4. Internal: 1.5 N terms and 1.5 times the quadrature points change f_perp, f_par, g_par by
     at most 2.3e-9 (relative) at the eleven gaps. The no-slip conditions hold at random points
     of wall and sphere (off the quadrature nodes) to 4.5e-6 U with N terms, 2.4e-9 U with
     1.5 N (the truncated tail of the series, largest at the top of the sphere; the forces
     are converged far beyond it, as the 2.3e-9 shows). Fourth-order finite differences of
     the velocity field at random points of the fluid give |div v| <= 3e-8 |grad v| and
     |lap v - grad p'| <= 7e-7 |grad p'|. Force and torque integrated over the sphere
     xi = alpha/2, which encloses the particle, equal those on its surface to 1.5e-12. The
     log-log cubic interpolation of the table (sliding_force) is within 0.033 % of the series
     at the geometric means of neighbouring tabulated gaps.

Usage
-----
  /usr/bin/python3 sphereWallStokes.py table   reference/sphereWall.csv (gap_over_d, f_perp,
                                                f_par, g_par, source) for h/d = 2 ... 0.001,
                                                printed too
  /usr/bin/python3 sphereWallStokes.py check   the checks above; exit status 1 on a failure
  from sphereWallStokes import sliding_force   f_par at h/d from the table, cubic in
                                                log-log between its gaps (ValueError outside)
  parallel_translation(h/a) -> (f_par, g_par), normal_translation(h/a) -> f_perp compute the
  series at any gap h/a > 0 (about 8 s of one core for both at h/a = 0.002; N grows like
  1/alpha, the cost like 1/alpha^3). Run times: `table` 10 s, `check` 50 s of one core.
"""
import csv
import math
import os
import sys
import time

import numpy as np

try:
    from scipy.special import roots_legendre as _gauss
except ImportError:              # numpy's companion-matrix rule: slower, the same nodes
    from numpy.polynomial.legendre import leggauss as _gauss

HERE = os.path.dirname(os.path.abspath(__file__))
CSV_PATH = os.path.join(HERE, "reference", "sphereWall.csv")
COLUMNS = ["gap_over_d", "f_perp", "f_par", "g_par", "source"]
GAPS_OVER_D = (2.0, 1.0, 0.5, 0.2, 0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001)
TOLERANCE = 0.003            # the reference checks (items 1 and 2): 0.3 %
PHI_NODES = 8                # trapezoidal rule in phi, exact for cos(k phi), k < 8: the
                             # traction and torque integrands have k <= 5


# --------------------------------------------------------------------------------------------
# Closed forms and asymptotes the series is checked against (h = gap over the radius a)
# --------------------------------------------------------------------------------------------

def brenner_series(alpha, ratio, what):
    """(4/3) sinh(alpha) sum_n n (n + 1)/((2n - 1)(2n + 3)) (ratio(n, alpha) - 1), the form of
    Brenner's (1961) series, summed until a term is below 1e-16 of the sum (an error naming
    what after a million terms)."""
    total = 0.0
    for n in range(1, 1000001):
        term = n * (n + 1) / ((2 * n - 1) * (2 * n + 3)) * (ratio(n, alpha) - 1.0)
        total += term
        if abs(term) < 1e-16 * abs(total):
            return 4.0 / 3.0 * math.sinh(alpha) * total
    raise RuntimeError(f"{what}: the series has not converged in {n} terms (last term "
                       f"{term:.3e}, sum {total:.6e})")


def brenner(h):
    """Brenner's (1961) exact f_perp of a sphere approaching a wall at h = gap/a."""
    def wall(n, alpha):
        k = 2 * n + 1
        return ((2.0 * math.sinh(k * alpha) + k * math.sinh(2.0 * alpha))
                / (4.0 * math.sinh((n + 0.5) * alpha) ** 2 - (k * math.sinh(alpha)) ** 2))
    return brenner_series(math.acosh(1.0 + h), wall, f"brenner at h/a = {h}")


def two_spheres_approaching(xi):
    """The force on each of two equal spheres moving towards each other along their line of
    centres at U (relative speed 2U), over 6 pi mu a U, at the gap xi = h/a between them:
    Brenner's (1961) series for a sphere approaching a free surface at h/(2a), the plane of
    symmetry of the pair (Stimson & Jeffery's problem with the velocities opposed)."""
    def free_surface(n, alpha):
        k = 2 * n + 1
        return ((4.0 * math.cosh((n + 0.5) * alpha) ** 2 + (k * math.sinh(alpha)) ** 2)
                / (2.0 * math.sinh(k * alpha) - k * math.sinh(2.0 * alpha)))
    return brenner_series(math.acosh(1.0 + 0.5 * xi), free_surface,
                          f"two_spheres_approaching at h/a = {xi}")


def faxen_parallel(h):
    """Faxen's far-field f_par, s = a/(h + a)."""
    s = 1.0 / (1.0 + h)
    return 1.0 / (1.0 - 9.0 / 16.0 * s + s ** 3 / 8.0 - 45.0 / 256.0 * s ** 4 - s ** 5 / 16.0)


def gcb_force(h):
    """Goldman, Cox & Brenner's (1967) near-contact f_par."""
    return -8.0 / 15.0 * math.log(h) + 0.9588


def gcb_torque(h):
    """Goldman, Cox & Brenner's (1967) near-contact g_par (rolling sense positive)."""
    return -0.1 * math.log(h) - 0.1895


def far_torque(h):
    """The far-field torque on the sliding sphere, (3/32) s^4 (1 - (3/8) s), s = a/(h + a)
    (Goldman, Cox & Brenner 1967, method of reflections)."""
    s = 1.0 / (1.0 + h)
    return 3.0 / 32.0 * s ** 4 * (1.0 - 3.0 / 8.0 * s)


# --------------------------------------------------------------------------------------------
# Bispherical harmonics
# --------------------------------------------------------------------------------------------

def truncation(alpha):
    """Terms N of the series and Gauss points M: the coefficients decay like exp(-n alpha)
    or faster, so N ~ 16/alpha leaves them below 1e-7; M > N + 2 makes the projections of the
    polynomial parts exact, the rest resolves the (cosh xi - cos eta)^(1/2) weight."""
    n = max(24, int(math.ceil(16.0 / alpha)))
    return n, 3 * n + 24


def legendre(m, nmax, mu):
    """Orthonormal associated Legendre functions sqrt((2n+1)/2 (n-m)!/(n+m)!) P_n^m(mu)
    (no Condon-Shortley phase), n = 0..nmax (zero below m), and their derivatives along
    eta = arccos(mu), at |mu| < 1; arrays (nmax + 1, len(mu))."""
    sin_eta = np.sqrt(1.0 - mu * mu)
    p = np.zeros((nmax + 2,) + mu.shape)
    p[m] = np.prod(np.arange(1, 2 * m, 2)) * sin_eta ** m     # (2m-1)!! sin^m
    p[m + 1] = (2 * m + 1) * mu * p[m]
    for n in range(m + 1, nmax + 1):            # the upward recurrence in n, stable for fixed m
        p[n + 1] = ((2 * n + 1) * mu * p[n] - (n + m) * p[n - 1]) / (n - m + 1)
    dp = np.zeros((nmax + 1,) + mu.shape)
    for n in range(m, nmax + 1):                # (1 - mu^2) dP/dmu = (n+m) P_{n-1} - n mu P_n
        below = p[n - 1] if n > m else 0.0
        dp[n] = -((n + m) * below - n * mu * p[n]) / sin_eta
    scale = np.zeros(nmax + 1)
    for n in range(m, nmax + 1):
        scale[n] = math.sqrt((2 * n + 1) / 2.0 / np.prod(np.arange(n - m + 1, n + m + 1.0)))
    return p[:nmax + 1] * scale[:, None], dp * scale[:, None]


class Points:
    """Points of the meridian plane, (xi, mu = cos eta), of the geometry with gap h/a, and the
    bispherical harmonics there."""

    def __init__(self, h, xi, mu, nmax):
        self.alpha = math.acosh(1.0 + h)
        self.c = math.sinh(self.alpha)
        self.nmax = nmax
        self.mu = np.asarray(mu, dtype=float)
        self.xi = np.broadcast_to(np.asarray(xi, dtype=float), self.mu.shape)
        self.sm = np.cosh(self.xi) - self.mu                  # cosh xi - cos eta
        self.sinh_xi = np.sinh(self.xi)
        self.sin_eta = np.sqrt(1.0 - self.mu ** 2)
        self.rho = self.c * self.sin_eta / self.sm
        self.z = self.c * self.sinh_xi / self.sm
        # rho + i z = i c coth((xi + i eta)/2) is conformal: its derivative gives the chain rule
        d = -0.5j * self.c / np.sinh(0.5 * (self.xi + 1j * np.arccos(self.mu))) ** 2
        self.dre, self.dim, self.jac = d.real, d.imag, np.abs(d) ** 2
        self._legendre = {}

    def legendre(self, m):
        if m not in self._legendre:
            self._legendre[m] = legendre(m, self.nmax, self.mu)
        return self._legendre[m]

    def harmonics(self, m, scale=1.0):
        """The harmonics scale (cosh xi - mu)^(1/2) g_n(xi) Pbar_n^m(mu), g_n one of
        exp((n+1/2)(xi - alpha)) (order one on the sphere) and exp(-(n+1/2) xi) (order one on
        the wall), and their derivatives along rho and z: three arrays (points, nmax+1, 2)."""
        k = np.arange(self.nmax + 1) + 0.5
        xi = self.xi[:, None]
        g = np.stack([np.exp(k * (xi - self.alpha)), np.exp(-k * xi)], axis=2)
        dg = g * np.stack([k, -k], axis=1)[None, :, :]
        p, dp = self.legendre(m)
        p, dp = p.T[:, :, None], dp.T[:, :, None]
        root = np.sqrt(self.sm)[:, None, None]
        f = scale * root * p * g
        f_xi = scale * (0.5 * self.sinh_xi[:, None, None] / root * g + root * dg) * p
        f_eta = scale * (0.5 * self.sin_eta[:, None, None] / root * p + root * dp) * g
        a, b, j = (q[:, None, None] for q in (self.dre, self.dim, self.jac))
        return f, (a * f_xi - b * f_eta) / j, (b * f_xi + a * f_eta) / j


def to_bispherical(h, x, y, z):
    """(xi, mu, phi) of Cartesian points (z > 0) for the gap h/a."""
    c = math.sinh(math.acosh(1.0 + h))
    zeta = (z - 1j * np.hypot(x, y)) / c
    w = np.log((zeta + 1.0) / (zeta - 1.0))       # xi + i eta
    return w.real, np.cos(np.abs(w.imag)), np.arctan2(y, x)


# --------------------------------------------------------------------------------------------
# The two problems
# --------------------------------------------------------------------------------------------
# A problem names its harmonic families (name, m, lowest n, times 1/c), the boundary
# conditions as Galerkin equations, and how p' and w are built from the families:
# terms (family, m of phi, "cos"/"sin").

class Normal:
    """Translation along the wall normal (+z): p' = Q, w_x + i w_y = e^(i phi) U, w_z = W."""
    families = [("Q", 0, 0, True), ("U", 1, 1, False), ("W", 0, 0, False)]
    p_terms = [("Q", 0, "cos")]
    w_terms = ([("U", 1, "cos")], [("U", 1, "sin")], [("W", 0, "cos")])
    axis = 2

    @staticmethod
    def equations(pts, fam):
        """(m of the projection, lowest k, power of cosh xi - mu, blocks, right side per
        unit boundary velocity): v_rho = 0, v_z = V, div v = 0."""
        (q, q_r, q_z), (u, u_r, _), (w, _, w_z) = fam["Q"], fam["U"], fam["W"]
        rho, z = pts.rho[:, None, None], pts.z[:, None, None]
        return [
            (1, 1, 0.5, {"Q": 0.5 * rho * q, "U": u}, None),
            (0, 0, 0.5, {"Q": 0.5 * z * q, "W": w}, 1.0),
            (0, 0, -0.5, {"Q": 0.5 * (3 * q + rho * q_r + z * q_z), "U": u_r + u / rho,
                          "W": w_z}, None)]


class Parallel:
    """Translation along the wall (+x): p' = Q cos(phi), w_x + i w_y = U0 + U2 e^(2 i phi),
    w_z = W cos(phi)."""
    families = [("U0", 0, 0, False), ("U2", 2, 2, False), ("Q", 1, 1, True),
                ("W", 1, 1, False)]
    p_terms = [("Q", 1, "cos")]
    w_terms = ([("U0", 0, "cos"), ("U2", 2, "cos")], [("U2", 2, "sin")], [("W", 1, "cos")])
    axis = 0

    @staticmethod
    def equations(pts, fam):
        """v_x = V (its m = 0 part), v_x and v_y = 0 (m = 2), v_z = 0, div v = 0."""
        (u0, u0_r, _), (u2, u2_r, _) = fam["U0"], fam["U2"]
        (q, q_r, q_z), (w, _, w_z) = fam["Q"], fam["W"]
        rho, z = pts.rho[:, None, None], pts.z[:, None, None]
        return [
            (0, 0, 0.5, {"U0": u0, "Q": 0.25 * rho * q}, 1.0),
            (2, 2, 0.5, {"U2": u2, "Q": 0.25 * rho * q}, None),
            (1, 1, 0.5, {"W": w, "Q": 0.5 * z * q}, None),
            (1, 1, -0.5, {"U0": u0_r, "U2": u2_r + 2 * u2 / rho,
                          "Q": 0.5 * (3 * q + rho * q_r + z * q_z), "W": w_z}, None)]


class Solution:
    """The series of one problem at gap h/a, solved with nmax terms and m_gauss points."""

    def __init__(self, problem, h, nmax=None, m_gauss=None):
        self.problem, self.h = problem, h
        self.alpha = math.acosh(1.0 + h)
        self.c = math.sinh(self.alpha)
        n_default, m_default = truncation(self.alpha)
        self.nmax = nmax or n_default
        self.m_gauss = m_gauss or m_default
        self.mu, self.weights = _gauss(self.m_gauss)
        self._solve()

    def families_at(self, pts):
        return {name: pts.harmonics(m, 1.0 / self.c if over_c else 1.0)
                for name, m, _, over_c in self.problem.families}

    def _solve(self):
        rows, rhs = [], []
        for xi, speed in ((0.0, 0.0), (self.alpha, 1.0)):      # wall at rest, sphere moving
            pts = Points(self.h, xi, self.mu, self.nmax)
            fam = self.families_at(pts)
            for m, kmin, power, blocks, right in self.problem.equations(pts, fam):
                proj = pts.legendre(m)[0][kmin:] * (self.weights * pts.sm ** power)
                row = []
                for name, _, nmin, _ in self.problem.families:
                    if name in blocks:
                        block = np.tensordot(proj, blocks[name][:, nmin:, :], axes=(1, 0))
                        row.append(block.reshape(block.shape[0], -1))
                    else:
                        row.append(np.zeros((proj.shape[0], 2 * (self.nmax + 1 - nmin))))
                rows.append(np.hstack(row))
                rhs.append(proj @ np.full(self.mu.shape, speed * right) if right
                           else np.zeros(proj.shape[0]))
        matrix, rhs = np.vstack(rows), np.concatenate(rhs)
        scale = 1.0 / np.abs(matrix).max(axis=1)          # rows of equal weight for pivoting
        x = np.linalg.solve(matrix * scale[:, None], rhs * scale)
        self.coef, offset = {}, 0
        for name, _, nmin, _ in self.problem.families:
            size = 2 * (self.nmax + 1 - nmin)
            full = np.zeros((self.nmax + 1, 2))
            full[nmin:] = x[offset:offset + size].reshape(-1, 2)
            self.coef[name] = full
            offset += size

    def fields(self, xi, mu):
        """Each family's value, d/drho, d/dz at the points (xi, mu)."""
        pts = Points(self.h, xi, mu, self.nmax)
        out = {}
        for name, arrays in self.families_at(pts).items():
            out[name] = [np.tensordot(f, self.coef[name], axes=([1, 2], [0, 1])) for f in arrays]
        return pts, out

    def _cartesian(self, pts, fields, phi):
        """p' and the components of w, each (value, Cartesian gradient as 3 arrays), and the
        position x, at the points and angles phi: phi of shape (1, K) gives the grid
        (points, K), phi of shape (points, 1) one angle per point."""
        cphi, sphi = np.cos(phi), np.sin(phi)
        rho = pts.rho[:, None]

        def assemble(terms):
            val, grad = 0.0, [0.0, 0.0, 0.0]
            for name, m, trig in terms:
                f, f_r, f_z = (a[:, None] for a in fields[name])
                if trig == "cos":
                    t, t_phi = np.cos(m * phi), -m * np.sin(m * phi)
                else:
                    t, t_phi = np.sin(m * phi), m * np.cos(m * phi)
                val = val + f * t
                grad[0] = grad[0] + cphi * f_r * t - sphi / rho * f * t_phi
                grad[1] = grad[1] + sphi * f_r * t + cphi / rho * f * t_phi
                grad[2] = grad[2] + f_z * t
            return val, grad

        p = assemble(self.problem.p_terms)
        w = [assemble(terms) for terms in self.problem.w_terms]
        x = [rho * cphi, rho * sphi, pts.z[:, None] + 0.0 * phi]
        return p, w, x

    def velocity(self, x, y, z):
        """Velocity (3, points) and p' (points) at Cartesian points of the fluid (z >= 0),
        per unit U, a = 1."""
        xi, mu, phi = to_bispherical(self.h, np.asarray(x, float), np.asarray(y, float),
                                     np.asarray(z, float))
        pts, fields = self.fields(xi, mu)
        (p, _), w, xx = self._cartesian(pts, fields, phi[:, None])
        v = np.array([(0.5 * xx[j] * p + w[j][0])[:, 0] for j in range(3)])
        return v, p[:, 0]

    def force_torque(self, xi_surface=None):
        """Force and torque (about the particle's centre) over the sphere xi = xi_surface
        (default the particle), per mu U a and mu U a^2: the traction of the fluid outside."""
        xi_s = self.alpha if xi_surface is None else xi_surface
        pts, fields = self.fields(np.full(self.mu.shape, xi_s), self.mu)
        phi = 2.0 * np.pi * np.arange(PHI_NODES)[None, :] / PHI_NODES
        (p, gp), w, x = self._cartesian(pts, fields, phi)
        centre, radius = self.c / math.tanh(xi_s), self.c / math.sinh(xi_s)
        normal = [x[0] / radius, x[1] / radius, (x[2] - centre) / radius]
        # sigma/mu = (x_j d_i p' + x_i d_j p')/2 + d_i w_j + d_j w_i (the pressure cancels)
        traction = [sum((0.5 * (x[j] * gp[i] + x[i] * gp[j]) + w[j][1][i] + w[i][1][j])
                        * normal[j] for j in range(3)) for i in range(3)]
        area = (self.c ** 2 * self.weights / pts.sm ** 2)[:, None] * (2.0 * np.pi / PHI_NODES)
        arm = [x[0], x[1], x[2] - math.cosh(self.alpha)]
        force = np.array([np.sum(t * area) for t in traction])
        torque = np.array([np.sum((arm[(i + 1) % 3] * traction[(i + 2) % 3]
                                   - arm[(i + 2) % 3] * traction[(i + 1) % 3]) * area)
                           for i in range(3)])
        return force, torque


def normal_translation(h, **kw):
    """f_perp at the gap h/a (the sphere moving along the normal; the sign of the motion does
    not matter in Stokes flow)."""
    force, _ = Solution(Normal, h, **kw).force_torque()
    return -force[2] / (6.0 * math.pi)


def parallel_translation(h, **kw):
    """(f_par, g_par) at the gap h/a, the sphere sliding along +x without rotation."""
    force, torque = Solution(Parallel, h, **kw).force_torque()
    return -force[0] / (6.0 * math.pi), torque[1] / (8.0 * math.pi)


# --------------------------------------------------------------------------------------------
# The table and its interpolation
# --------------------------------------------------------------------------------------------

def compute_table(gaps_over_d=GAPS_OVER_D):
    rows = []
    for g in gaps_over_d:
        h = 2.0 * g                                  # h/a
        f_par, g_par = parallel_translation(h)
        rows.append({"gap_over_d": g, "f_perp": normal_translation(h), "f_par": f_par,
                     "g_par": g_par, "source": "bispherical"})
    return rows


def format_row(r):
    return {"gap_over_d": f"{r['gap_over_d']:g}", "f_perp": f"{r['f_perp']:.10g}",
            "f_par": f"{r['f_par']:.10g}", "g_par": f"{r['g_par']:.10g}", "source": r["source"]}


_TABLE = None


def read_table():
    """The table of reference/sphereWall.csv, or computed when that file is missing."""
    global _TABLE
    if _TABLE is None:
        if os.path.exists(CSV_PATH):
            with open(CSV_PATH, newline="") as f:
                _TABLE = [{k: (v if k == "source" else float(v)) for k, v in r.items()}
                          for r in csv.DictReader(f)]
        else:
            _TABLE = compute_table()
        _TABLE.sort(key=lambda r: r["gap_over_d"])
    return _TABLE


def interpolate(gap_over_d, column, table=None):
    """A column of the table at h/d = gap_over_d: the tabulated value at a tabulated gap, else
    a cubic spline (not-a-knot) of log(value) in log(gap) through all tabulated gaps (linear
    in log-log without scipy). ValueError outside the tabulated range."""
    rows = sorted(table or read_table(), key=lambda r: r["gap_over_d"])
    gaps = np.array([r["gap_over_d"] for r in rows])
    values = np.array([r[column] for r in rows])
    g = float(gap_over_d)
    if not (gaps[0] * (1 - 1e-12) <= g <= gaps[-1] * (1 + 1e-12)):
        raise ValueError(f"sphereWallStokes: h/d = {g:g} is outside the table "
                         f"({gaps[0]:g} to {gaps[-1]:g})")
    hit = np.nonzero(np.abs(gaps / g - 1.0) < 1e-9)[0]
    if hit.size:
        return float(values[hit[0]])
    try:
        from scipy.interpolate import CubicSpline
        return float(np.exp(CubicSpline(np.log(gaps), np.log(values))(math.log(g))))
    except ImportError:
        return float(np.exp(np.interp(math.log(g), np.log(gaps), np.log(values))))


def sliding_force(gap_over_d):
    """f_par = F_x/(6 pi mu a U) of the non-rotating sliding sphere at h/d = gap_over_d."""
    return interpolate(gap_over_d, "f_par")


def sliding_torque(gap_over_d):
    """g_par = T_y/(8 pi mu a^2 U) (rolling sense positive) at h/d = gap_over_d."""
    return interpolate(gap_over_d, "g_par")


def table():
    rows = compute_table()
    os.makedirs(os.path.dirname(CSV_PATH), exist_ok=True)
    with open(CSV_PATH, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        for r in rows:
            writer.writerow(format_row(r))
    with open(CSV_PATH) as f:
        sys.stdout.write(f.read())
    print(f"written {os.path.relpath(CSV_PATH)}")


# --------------------------------------------------------------------------------------------
# The checks
# --------------------------------------------------------------------------------------------

def check():
    failures = []

    def verdict(ok, what):
        if not ok:
            failures.append(what)
        return "ok" if ok else "FAIL"

    rows = compute_table()
    print("The series at the table's gaps (eps = h/a; differences relative, in %):")
    print(f"{'h/d':>6} {'h/a':>6} {'f_perp':>12} {'Brenner':>12} {'diff':>9} {'f_par':>10} "
          f"{'Faxen':>8} {'diff':>8} {'GCB':>8} {'diff':>8} {'g_par':>9} {'GCB':>8} "
          f"{'g-GCB':>8}")
    worst_brenner = 0.0
    for r in rows:
        h = 2.0 * r["gap_over_d"]
        b = brenner(h)
        d_b = r["f_perp"] / b - 1.0
        worst_brenner = max(worst_brenner, abs(d_b))
        fx = faxen_parallel(h)
        gf, gt = gcb_force(h), gcb_torque(h)
        print(f"{r['gap_over_d']:6g} {h:6g} {r['f_perp']:12.7f} {b:12.7f} {100 * d_b:+9.1e} "
              f"{r['f_par']:10.6f} {fx:8.4f} {100 * (r['f_par'] / fx - 1):+8.3f} "
              f"{gf:8.4f} {100 * (r['f_par'] / gf - 1):+8.3f} {r['g_par']:9.6f} {gt:8.4f} "
              f"{r['g_par'] - gt:+8.4f}")
    print(f"\n1. f_perp against Brenner (1961), all eleven gaps: largest |difference| "
          f"{worst_brenner:.1e} (tolerance {TOLERANCE:.1%}): "
          f"{verdict(worst_brenner < TOLERANCE, 'f_perp against Brenner')}")

    print("\n2. f_par against Faxen's far-field expansion, g_par against (3/32) s^4 (1 - 3s/8), "
          f"s = a/(h + a) (tolerance {TOLERANCE:.1%} at h/a >= 4):")
    print(f"{'h/a':>6} {'f_par':>12} {'Faxen':>12} {'diff %':>10} {'g_par':>12} "
          f"{'(3/32)s^4(1-3s/8)':>18} {'ratio-1 %':>10}")
    for h in (16.0, 8.0, 4.0, 2.0, 1.0):
        f, g = parallel_translation(h)
        fx, ft = faxen_parallel(h), far_torque(h)
        d = f / fx - 1.0
        dt = g / ft - 1.0
        status = (verdict(abs(d) < TOLERANCE and abs(dt) < TOLERANCE, f"far field at h/a = {h:g}")
                  if h >= 4 else "reported")
        print(f"{h:6g} {f:12.8f} {fx:12.8f} {100 * d:+10.5f} {g:12.4e} {ft:18.4e} "
              f"{100 * dt:+10.3f}  {status}")

    print("\n3. Near contact, against Goldman, Cox & Brenner (1967): f_par = -(8/15) ln eps + "
          "0.9588, g_par = -(1/10) ln eps - 0.1895")
    print(f"{'h/a':>6} {'f_par':>12} {'GCB':>10} {'diff %':>9} {'g_par':>10} {'GCB':>10} "
          f"{'diff':>9} {'diff %':>8}")
    near = [0.1, 0.04, 0.02, 0.01, 0.004, 0.002]
    series = {}
    for h in near:
        series[h] = parallel_translation(h)
        f, g = series[h]
        print(f"{h:6g} {f:12.8f} {gcb_force(h):10.6f} {100 * (f / gcb_force(h) - 1):+9.4f} "
              f"{g:10.7f} {gcb_torque(h):10.6f} {g - gcb_torque(h):+9.5f} "
              f"{100 * (g / gcb_torque(h) - 1):+8.3f}")
    d_f = [abs(series[h][0] / gcb_force(h) - 1) for h in near[:4]]
    d_t = [abs(series[h][1] - gcb_torque(h)) for h in near[:4]]
    print(f"   f_par: |difference| shrinks over h/a = 0.1, 0.04, 0.02, 0.01: "
          f"{verdict(all(a > b for a, b in zip(d_f, d_f[1:])), 'GCB force shrinking')}")
    print(f"   g_par: |difference| shrinks over h/a = 0.1, 0.04, 0.02, 0.01: "
          f"{verdict(all(a > b for a, b in zip(d_t, d_t[1:])), 'GCB torque shrinking')}")
    small = max(abs(series[h][0] / gcb_force(h) - 1) for h in near[3:])
    print(f"   f_par within 0.5 % of the asymptote at h/a <= 0.01 (largest {100 * small:.3f} %): "
          f"{verdict(small < 0.005, 'GCB force within 0.5 % at h/a <= 0.01')}")
    # the constants the series tends to: C + A eps ln eps + B eps fitted to the remainders
    eps = np.array(near[2:])
    basis = np.vstack([np.ones_like(eps), eps * np.log(eps), eps]).T
    c_force = np.linalg.lstsq(basis, [series[h][0] + 8.0 / 15.0 * math.log(h) for h in near[2:]],
                              rcond=None)[0][0]
    c_torque = np.linalg.lstsq(basis, [series[h][1] + 0.1 * math.log(h) for h in near[2:]],
                               rcond=None)[0][0]
    print(f"   constants the series extrapolates to (fit over h/a = 0.02...0.002): "
          f"force {c_force:.4f} (GCB 0.9588), torque {c_torque:.4f} (GCB -0.1895)")

    print("\n4. Internal consistency of the series:")
    worst = 0.0
    for r in rows:
        h = 2.0 * r["gap_over_d"]
        n, m = truncation(math.acosh(1.0 + h))
        n2, m2 = int(1.5 * n), int(1.5 * m)
        f_perp = normal_translation(h, nmax=n2, m_gauss=m2)
        f_par, g_par = parallel_translation(h, nmax=n2, m_gauss=m2)
        worst = max(worst, abs(f_perp / r["f_perp"] - 1), abs(f_par / r["f_par"] - 1),
                    abs(g_par / r["g_par"] - 1))
    print(f"   1.5 N terms and 1.5 M points: largest relative change of f_perp, f_par, g_par "
          f"{worst:.1e} (tolerance 1e-6): {verdict(worst < 1e-6, 'truncation')}")

    rng = np.random.default_rng(1)
    bc, bc_fine, div, mom, surf = 0.0, 0.0, 0.0, 0.0, 0.0
    for h in (2.0, 0.2, 0.02, 0.002):
        n, m = truncation(math.acosh(1.0 + h))
        for problem in (Normal, Parallel):
            sol = Solution(problem, h)
            fine = Solution(problem, h, nmax=int(1.5 * n), m_gauss=int(1.5 * m))
            alpha, c = sol.alpha, sol.c
            # no-slip at random points of the sphere and of the wall (within 20 a of the axis)
            eta = np.arccos(rng.uniform(-1, 1, 40))
            phi = rng.uniform(0, 2 * np.pi, 40)
            for xi, speed in ((alpha, 1.0), (0.0, 0.0)):
                rho = c * np.sin(eta) / (np.cosh(xi) - np.cos(eta))
                z = c * np.sinh(xi) / (np.cosh(xi) - np.cos(eta))
                keep = rho < 20.0
                where = (rho[keep] * np.cos(phi[keep]), rho[keep] * np.sin(phi[keep]), z[keep])
                v, _ = sol.velocity(*where)
                v[problem.axis] -= speed
                bc = max(bc, np.abs(v).max())
                v, _ = fine.velocity(*where)
                v[problem.axis] -= speed
                bc_fine = max(bc_fine, np.abs(v).max())
            # finite differences (fourth order) at random points of the fluid: div v and
            # lap v - grad p' (zero by construction: p' and w are harmonic)
            xi = alpha * rng.uniform(0.15, 0.85, 12)
            eta = np.arccos(rng.uniform(-1, 1, 12))
            phi = rng.uniform(0, 2 * np.pi, 12)
            rho = c * np.sin(eta) / (np.cosh(xi) - np.cos(eta))
            z = c * np.sinh(xi) / (np.cosh(xi) - np.cos(eta))
            x0 = np.array([rho * np.cos(phi), rho * np.sin(phi), z])
            step = 1e-2 * np.minimum(z, 1.0)
            offsets = (-2, -1, 1, 2)
            pts = [x0]
            for i in range(3):
                for o in offsets:
                    d = np.zeros_like(x0)
                    d[i] = o * step
                    pts.append(x0 + d)
            v, p = sol.velocity(*np.concatenate(pts, axis=1))
            k = x0.shape[1]
            v, p = v.reshape(3, 13, k), p.reshape(13, k)

            def at(f, i, o):              # f at x0 + o step e_i
                return f[..., 1 + 4 * i + offsets.index(o), :]

            def d1(f, i):
                return (at(f, i, -2) - 8 * at(f, i, -1) + 8 * at(f, i, 1)
                        - at(f, i, 2)) / (12 * step)

            def d2(f, i):
                return (-at(f, i, -2) + 16 * at(f, i, -1) - 30 * f[..., 0, :] + 16 * at(f, i, 1)
                        - at(f, i, 2)) / (12 * step ** 2)

            grad_v = np.array([d1(v, i) for i in range(3)])
            grad_p = np.array([d1(p, i) for i in range(3)])
            lap_v = sum(d2(v, i) for i in range(3))
            div_v = np.trace(grad_v, axis1=0, axis2=1)
            div = max(div, (np.abs(div_v) / np.abs(grad_v).max(axis=(0, 1))).max())
            mom = max(mom, (np.abs(lap_v - grad_p).max(axis=0) / np.abs(grad_p).max(axis=0)).max())
            # force and torque over the sphere xi = alpha/2, which encloses the particle
            f1, t1 = sol.force_torque()
            f2, t2 = sol.force_torque(0.5 * alpha)
            surf = max(surf, np.abs(f2 - f1).max() / np.abs(f1).max(),
                       np.abs(t2 - t1).max() / max(np.abs(t1).max(), np.abs(f1).max()))
    print(f"   no-slip at random points of sphere and wall (h/a = 2, 0.2, 0.02, 0.002): largest "
          f"|v - V| = {bc:.1e} U with N terms, {bc_fine:.1e} U with 1.5 N (the truncated tail, "
          f"largest at the top of the sphere; tolerance 1e-4 and 1e-6): "
          f"{verdict(bc < 1e-4 and bc_fine < 1e-6, 'no-slip')}")
    print(f"   finite differences at random points of the fluid (each point against its own "
          f"scale): |div v|/|grad v| <= {div:.1e}, |lap v - grad p'|/|grad p'| <= {mom:.1e} "
          f"(tolerance 1e-5): {verdict(div < 1e-5 and mom < 1e-5, 'Stokes equations')}")
    print(f"   force and torque over the sphere xi = alpha/2 against the particle's surface: "
          f"{surf:.1e} (tolerance 1e-8): {verdict(surf < 1e-8, 'traction balance')}")

    # two equal spheres approaching: near contact Jeffrey & Onishi's (1984) singular terms
    # X11 - X12 = 1/(2 xi) + (9/20) ln(1/xi) + const, the constant the same from xi = 1e-3 to
    # 1e-5; far apart the reflections 1 + (3/2) s + (9/4) s^2, s = a/r (r = (2 + xi) a)
    near = [two_spheres_approaching(x) - 1 / (2 * x) - 0.45 * math.log(1 / x)
            for x in (1e-3, 1e-4, 1e-5)]
    spread = max(near) - min(near)
    far = [(x, two_spheres_approaching(x), 1 + 1.5 / (2 + x) + 2.25 / (2 + x) ** 2)
           for x in (100.0, 1000.0)]
    far_err = max(abs(v / r - 1) * (2 + x) ** 3 for x, v, r in far)
    print("   two spheres approaching: lambda - 1/(2 xi) - (9/20) ln(1/xi) = "
          + ", ".join(f"{v:.5f}" for v in near) + f" at xi = 1e-3, 1e-4, 1e-5 (spread "
          f"{spread:.1e}, tolerance 2e-3): {verdict(spread < 2e-3, 'two spheres, contact')}")
    print(f"   two spheres far apart against 1 + 3s/2 + 9s^2/4: largest |difference|/s^3 "
          f"{far_err:.2f} at xi = 100, 1000 (tolerance 5): "
          f"{verdict(far_err < 5, 'two spheres, far field')}")

    # interpolation of the table between its gaps against the series there
    gaps = sorted(r["gap_over_d"] for r in rows)
    worst_i = 0.0
    for lo, hi in zip(gaps, gaps[1:]):
        g = math.sqrt(lo * hi)
        exact = parallel_translation(2.0 * g)[0]
        worst_i = max(worst_i, abs(interpolate(g, "f_par", rows) / exact - 1))
    print(f"   sliding_force between the tabulated gaps (geometric means) against the series: "
          f"largest {100 * worst_i:.4f} % (tolerance 0.05 %): "
          f"{verdict(worst_i < 5e-4, 'interpolation')}")
    try:
        interpolate(0.5 * gaps[0], "f_par", rows)
        ok = False
    except ValueError:
        ok = True
    print(f"   sliding_force below the table raises ValueError: {verdict(ok, 'range')}")

    if os.path.exists(CSV_PATH):
        with open(CSV_PATH, newline="") as f:
            stored = {float(r["gap_over_d"]): r for r in csv.DictReader(f)}
        worst_csv = max((abs(float(stored[r["gap_over_d"]][k]) / r[k] - 1)
                         for r in rows for k in ("f_perp", "f_par", "g_par")
                         if r["gap_over_d"] in stored), default=float("inf"))
        print(f"   {os.path.relpath(CSV_PATH)} against the series: largest relative difference "
              f"{worst_csv:.1e} (tolerance 1e-8; `table` rewrites it): "
              f"{verdict(worst_csv < 1e-8 and len(stored) == len(rows), 'stored table')}")

    if failures:
        print("\nFAILED: " + "; ".join(failures))
        return 1
    print("\nall checks passed")
    return 0


def main(argv):
    if len(argv) != 2 or argv[1] not in ("table", "check"):
        sys.exit(f"usage: {argv[0]} table|check")
    start = time.process_time()
    status = table() if argv[1] == "table" else check()
    print(f"cpu {time.process_time() - start:.1f} s")
    return status or 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
