#!/usr/bin/python3
"""Squeeze film between two smooth convex surfaces: the Reynolds equation solved with the
exact gap against the closed-form force of the gap's local paraboloid
(validation/squeezeFilm, see README.md).

    squeezeFilm.py run [--quick] [--out DIR]
    squeezeFilm.py plot [--out DIR]

run:  every configuration (two bodies, each an ellipsoid or a plane) at the gaps h0 of the
      campaign: the Reynolds force F_num on the exact gap, its check on a grid refined x2
      and on a domain halved, the closed form F_par of the gap's paraboloid, and the
      paraboloid gap itself on the solver against F_par. Writes DIR/results/results.csv and
      DIR/results/paraboloid.csv (DIR: this folder, or run-quick/ with --quick).
      --quick: three configurations, two gaps, a coarse grid (a few seconds).
plot: DIR/results/table.md, metrics.json and the figures from those two files (the
      sliding_* keys that slidingFilm.py plot writes into metrics.json are kept).

Units: viscosity mu = 1, approach speed U = 1, lengths in the smallest semi-axis.
"""
import argparse
import json
import math
import os
import sys
import time
from pathlib import Path

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from scipy.integrate import quad

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
from validationTools import provenance, read_csv, write_csv  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
MU = 1.0
U = 1.0
# the campaign's gaps 1e-3 to 1e-1, and two smaller ones that show the limit h0 -> 0
GAPS = (1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 1e-1)
QUICK_GAPS = (1e-3, 1e-2)
HEADLINE_GAPS = (1e-3, 1e-2)
# the smallest gaps, on which the deviation F_num/F_par - 1 is fitted
FIT_GAPS = (1e-4, 3e-4, 1e-3)

NORMAL = np.array([0.0, 0.0, 1.0])        # the common normal n, from body 1 to body 2
TANGENT_BASIS = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]).T   # columns span n's plane


# ---------------------------------------------------------------------------
# grid parameters

class GridSpec:
    """A tensor-product grid graded geometrically away from the contact: the first cell
    is first_cell contact lengths sqrt(2 h0/k) wide (k the principal curvature of the
    gap along that axis), each next cell growth times the previous, at most max_cell
    of the film's extent along that half-axis."""

    def __init__(self, first_cell, growth, max_cell):
        self.first_cell = first_cell
        self.growth = growth
        self.max_cell = max_cell


FULL_GRID = GridSpec(first_cell=0.1, growth=1.08, max_cell=1 / 40)
QUICK_GRID = GridSpec(first_cell=0.25, growth=1.2, max_cell=1 / 15)
# the paraboloid check: the film reaches PARABOLOID_EXTENT contact lengths, where the
# closed-form pressure has fallen to 1/PARABOLOID_EXTENT^4 of its central value
PARABOLOID_EXTENT = 200.0


# ---------------------------------------------------------------------------
# geometry: ellipsoids and planes

def unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


def frame_with_first_axis(axis):
    """A rotation matrix whose first column is the unit vector along axis."""
    u = unit(axis)
    helper = np.array([1.0, 0.0, 0.0]) if abs(u[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    v = unit(helper - helper.dot(u) * u)
    return np.column_stack([u, v, np.cross(u, v)])


def ellipsoid_matrix(semi_axes, axis):
    """A of (y - c)^T A (y - c) = 1: A = R diag(1/a^2, 1/b^2, 1/c^2) R^T, the body's first
    axis (semi-axis a) along axis (for a spheroid (a, b, b) its symmetry axis)."""
    R = frame_with_first_axis(axis)
    return R @ np.diag(1.0 / np.square(np.asarray(semi_axes, dtype=float))) @ R.T


def stable_quadratic_roots(a, b, c):
    """The two roots (low, high) of a s^2 + 2 b s + c = 0 (a > 0), NaN where there is
    none; written so that a root near zero keeps its digits (no cancellation)."""
    disc = b * b - a * c
    with np.errstate(invalid="ignore", divide="ignore"):
        q = -(b + np.copysign(np.sqrt(disc), b))
        r1 = q / a
        r2 = np.where(q != 0, c / q, r1)
    return np.minimum(r1, r2), np.maximum(r1, r2)


class Ellipsoid:
    """The body (y - c)^T A (y - c) <= 1."""

    def __init__(self, A, centre):
        self.A = np.asarray(A, dtype=float)
        self.centre = np.asarray(centre, dtype=float)

    @classmethod
    def touching(cls, A, point, outward_normal):
        """The ellipsoid of matrix A placed so that its surface point with the outward
        normal outward_normal is point (the support point y = c + A^-1 m/sqrt(m^T A^-1 m))."""
        m = unit(outward_normal)
        Ainv_m = np.linalg.solve(A, m)
        return cls(A, np.asarray(point, dtype=float) - Ainv_m / math.sqrt(m.dot(Ainv_m)))

    def line_roots(self, points, direction):
        """(s_low, s_high): the line points + s direction meets the surface at both; NaN
        where it misses. points: array (..., 3)."""
        d = points - self.centre
        a = direction @ self.A @ direction
        b = d @ (self.A @ direction)
        c = np.einsum("...i,ij,...j->...", d, self.A, d) - 1.0
        return stable_quadratic_roots(a, b, c)

    def reach(self, origin, tangent, direction):
        """The largest t >= 0 for which the line origin + t tangent + s direction still
        meets the body (origin's line meets it): the root of the discriminant, a
        quadratic in t."""
        A, d0, e, n = self.A, origin - self.centre, tangent, direction
        an = n @ A @ n
        alpha = (n @ A @ e) ** 2 - an * (e @ A @ e)
        beta = 2.0 * ((n @ A @ d0) * (n @ A @ e) - an * (e @ A @ d0))
        gamma = (n @ A @ d0) ** 2 - an * (d0 @ A @ d0 - 1.0)
        # alpha < 0 (Cauchy-Schwarz in the A inner product), gamma >= 0: one root >= 0
        return (-beta - math.sqrt(beta * beta - 4.0 * alpha * gamma)) / (2.0 * alpha)

    def shape_operator(self, point):
        """S = P A P/|g|, g = A (y - c), P = I - m m^T, m = g/|g|: the curvature tensor of
        the surface at point (on the tangent plane its eigenvalues are the principal
        curvatures, positive for this convex body)."""
        g = self.A @ (point - self.centre)
        gnorm = np.linalg.norm(g)
        m = g / gnorm
        P = np.eye(3) - np.outer(m, m)
        return P @ self.A @ P / gnorm

    def gaussian_radius(self, point):
        """1/sqrt(k1 k2) at a surface point."""
        k = np.linalg.eigvalsh(self.shape_operator(point))[1:]
        return 1.0 / math.sqrt(k[0] * k[1])


class Plane:
    """The half-space behind the plane through point with the outward normal normal."""

    def __init__(self, point, normal):
        self.point = np.asarray(point, dtype=float)
        self.normal = unit(normal)

    def line_roots(self, points, direction):
        s = ((self.point - points) @ self.normal) / (direction @ self.normal)
        return s, s

    def reach(self, origin, tangent, direction):
        return math.inf

    def shape_operator(self, point):
        return np.zeros((3, 3))

    def gaussian_radius(self, point):
        return math.inf


# ---------------------------------------------------------------------------
# configurations

SPHERE = (1.0, 1.0, 1.0)
SPHERE2 = (2.0, 2.0, 2.0)
PROLATE = (2.0, 1.0, 1.0)      # aspect ratio 2, symmetry axis along the first body axis
OBLATE = (1.0, 2.0, 2.0)       # aspect ratio 1/2
X, Y, Z = np.eye(3)
DIAGONAL_XZ = unit(X + Z)     # 45 degrees between the symmetry axis and the normal
DIAGONAL_XY = unit(X + Y)     # in the tangent plane, 45 degrees from x

# name, label, body 1 (semi-axes, axis), body 2 (semi-axes, axis; None: a plane)
CONFIGURATIONS = [
    ("spherePlane", "sphere / plane", (SPHERE, Z), None),
    ("sphereSphere", "sphere / sphere (equal)", (SPHERE, Z), (SPHERE, Z)),
    ("sphere1Sphere2", "sphere a=1 / sphere a=2", (SPHERE, Z), (SPHERE2, Z)),
    ("prolateBroadside", "prolate broadside / plane", (PROLATE, X), None),
    ("prolateTip", "prolate tip-on / plane", (PROLATE, Z), None),
    ("prolateTilted", "prolate 45 deg / plane", (PROLATE, DIAGONAL_XZ), None),
    ("oblateFace", "oblate face-on / plane", (OBLATE, Z), None),
    ("oblateEdge", "oblate edge-on / plane", (OBLATE, X), None),
    ("oblateTilted", "oblate 45 deg / plane", (OBLATE, DIAGONAL_XZ), None),
    ("prolatesParallel", "prolates side by side, parallel", (PROLATE, X), (PROLATE, X)),
    ("prolatesCrossed", "prolates side by side, crossed 90 deg", (PROLATE, X), (PROLATE, Y)),
    ("prolates45", "prolates side by side, 45 deg", (PROLATE, X), (PROLATE, DIAGONAL_XY)),
    ("prolateTipSide", "prolate tip / prolate side", (PROLATE, Z), (PROLATE, X)),
]
QUICK_CONFIGURATIONS = ("spherePlane", "prolateTilted", "prolatesCrossed")


def is_axisymmetric_about_normal(body):
    """A plane, a sphere, or a spheroid whose symmetry axis is the normal."""
    if body is None:
        return True
    semi, axis = body
    if semi[0] == semi[1] == semi[2]:
        return True
    return semi[1] == semi[2] and abs(abs(unit(axis) @ NORMAL) - 1.0) < 1e-12


class Contact:
    """Two bodies at the gap h0: body 1 below the tangent plane z = 0 touching it at the
    origin p1 with outward normal n = z, body 2 above z = h0 touching it at p2 = h0 n
    with outward normal -n. Each body lies in its tangent half-space, so p1, p2 are the
    closest points and h0 the gap. K = S1(p1) + S2(p2) on the tangent plane; its
    eigenvectors e1, e2 (k1 >= k2) are the axes of the grid."""

    def __init__(self, body1, body2, h0):
        self.h0 = h0
        self.p1 = np.zeros(3)
        self.p2 = h0 * NORMAL
        semi1, axis1 = body1
        self.body1 = Ellipsoid.touching(ellipsoid_matrix(semi1, axis1), self.p1, NORMAL)
        if body2 is None:
            self.body2 = Plane(self.p2, -NORMAL)
        else:
            semi2, axis2 = body2
            self.body2 = Ellipsoid.touching(ellipsoid_matrix(semi2, axis2), self.p2, -NORMAL)
        K3 = self.body1.shape_operator(self.p1) + self.body2.shape_operator(self.p2)
        K2 = TANGENT_BASIS.T @ K3 @ TANGENT_BASIS
        k, vectors = np.linalg.eigh(K2)
        order = np.argsort(k)[::-1]
        self.k = k[order]
        self.axes = TANGENT_BASIS @ vectors[:, order]      # columns e1, e2

    def gap(self, u, v):
        """The exact gap h = s2 - s1 along n at the tangent-plane points p1 + u e1 + v e2
        (u, v broadcastable): s1 the largest root of body 1 (its face towards body 2),
        s2 the smallest of body 2; NaN where the line misses either body."""
        u, v = np.broadcast_arrays(np.asarray(u, float), np.asarray(v, float))
        points = self.p1 + u[..., None] * self.axes[:, 0] + v[..., None] * self.axes[:, 1]
        s1 = self.body1.line_roots(points, NORMAL)[1]
        s2 = self.body2.line_roots(points, NORMAL)[0]
        return s2 - s1

    def film_extent(self, tangent):
        """How far the film reaches from p1 along tangent: where the first line misses a
        body."""
        return min(self.body1.reach(self.p1, tangent, NORMAL),
                   self.body2.reach(self.p1, tangent, NORMAL))

    def half_axis_extents(self):
        """((-e1 side, +e1 side), (-e2 side, +e2 side)) extents of the film."""
        return tuple((self.film_extent(-e), self.film_extent(e)) for e in self.axes.T)

    def paraboloid_gap_on_film(self, u, v):
        """The paraboloid h0 + (k1 u^2 + k2 v^2)/2 on the exact gap's film (NaN where the
        exact gap is): the force it gives separates the film's finite extent from the
        gap's departure from the paraboloid."""
        u, v = np.broadcast_arrays(np.asarray(u, float), np.asarray(v, float))
        h = self.h0 + 0.5 * (self.k[0] * u * u + self.k[1] * v * v)
        return np.where(np.isfinite(self.gap(u, v)), h, np.nan)

    def gaussian_squeeze_radius(self):
        """The combination R1 R2/(R1 + R2) of the two Gaussian radii 1/sqrt(k1 k2) at the
        closest points (the sphere-equivalent a model of Gaussian radii would use)."""
        r1 = self.body1.gaussian_radius(self.p1)
        r2 = self.body2.gaussian_radius(self.p2)
        return r1 if math.isinf(r2) else r1 * r2 / (r1 + r2)


def squeeze_radius(k1, k2):
    """R* of the paraboloid gap h0 + (k1 x^2 + k2 y^2)/2: R*^2 = 2/(sqrt(k1 k2)(k1 + k2))."""
    return math.sqrt(2.0 / (math.sqrt(k1 * k2) * (k1 + k2)))


def paraboloid_force(h0, k1, k2):
    """F_par = 6 pi mu U R*^2/h0."""
    return 6.0 * math.pi * MU * U * squeeze_radius(k1, k2) ** 2 / h0


# ---------------------------------------------------------------------------
# grid

def half_axis_edges(first_cell, growth, max_cell, length):
    """Cell edges from 0 to length: the first cell first_cell wide, each next growth
    times the previous up to max_cell; the last edge moved onto length (a last cell
    under half its neighbour is merged into it)."""
    edges = [0.0]
    size = first_cell
    while edges[-1] < length:
        edges.append(edges[-1] + size)
        size = min(size * growth, max_cell)
    edges[-1] = length
    if len(edges) > 2 and edges[-1] - edges[-2] < 0.5 * (edges[-2] - edges[-3]):
        del edges[-2]
    return np.array(edges)


def axis_edges(spec, contact_length, extents, fraction=1.0):
    """The edges along one axis, from -fraction*extents[0] to +fraction*extents[1]; the
    cells near the contact do not depend on fraction (same grid, smaller domain)."""
    sides = []
    for extent in extents:
        sides.append(half_axis_edges(spec.first_cell * contact_length, spec.growth,
                                     spec.max_cell * extent, fraction * extent))
    return np.concatenate([-sides[0][::-1], sides[1][1:]])


def bisected(edges):
    """Every cell cut in two: the grid refined x2."""
    mid = 0.5 * (edges[1:] + edges[:-1])
    out = np.empty(2 * len(edges) - 1)
    out[0::2] = edges
    out[1::2] = mid
    return out


# ---------------------------------------------------------------------------
# the Reynolds equation

def face_gaps(h_face, h_left, h_right):
    """The gap on the faces; where the face's gap is undefined (a film edge) the gap of the
    cell beside it that is in the film."""
    return np.where(np.isfinite(h_face), h_face, np.fmin(h_left, h_right))


def face_conductances(h_face, h_left, h_right, length, distance):
    """h^3 length/distance on the faces (face_gaps)."""
    return face_gaps(h_face, h_left, h_right) ** 3 * length / distance


def centre_distances(edges, centres):
    """Distances across the faces: between neighbouring centres, and half a cell at the
    two ends (where p = 0 is set on the face)."""
    return np.concatenate([[centres[0] - edges[0]], np.diff(centres),
                           [edges[-1] - centres[-1]]])


def add_faces(rows, cols, vals, diag, index_left, index_right, conductance):
    """Add the fluxes T (p_neighbour - p) of a set of faces: coupling between two cells in
    the film, p = 0 beside a cell whose neighbour is out of the film or the boundary."""
    left_in = index_left >= 0
    right_in = index_right >= 0
    np.add.at(diag, index_left[left_in], conductance[left_in])
    np.add.at(diag, index_right[right_in], conductance[right_in])
    both = left_in & right_in
    for a, b in ((index_left, index_right), (index_right, index_left)):
        rows.append(a[both])
        cols.append(b[both])
        vals.append(-conductance[both])


class ReynoldsFilm:
    """Cell-centred finite volumes for -div(h^3 grad p) on the tensor-product grid, p = 0
    on the outer boundary and in the cells whose centre is out of the film (gap
    undefined): the matrix, assembled once, and its solution for any right-hand side.
    Cells (i, j): x between x_edges[i] and x_edges[i + 1], y between y_edges[j] and
    y_edges[j + 1]; the film's cells are numbered in the order of in_film's True entries.
    index: (nx + 2, ny + 2), the cells' numbers padded by a ring of -1 (out of the film);
    the faces normal to x are (nx + 1, ny), face i between padded cells i and i + 1 (rows
    j + 1), those normal to y (nx, ny + 1) likewise; h_x_face, h_y_face: the exact gap at
    the face centres (NaN out of the film)."""

    def __init__(self, x_edges, y_edges, gap):
        self.x_edges, self.y_edges = x_edges, y_edges
        self.xc = xc = 0.5 * (x_edges[1:] + x_edges[:-1])
        self.yc = yc = 0.5 * (y_edges[1:] + y_edges[:-1])
        self.dx, self.dy = dx, dy = np.diff(x_edges), np.diff(y_edges)
        nx, ny = len(xc), len(yc)
        self.h_centre = h_centre = gap(xc[:, None], yc[None, :])
        self.in_film = in_film = np.isfinite(h_centre)
        self.index = index = np.full((nx + 2, ny + 2), -1)
        index[1:-1, 1:-1][in_film] = np.arange(in_film.sum())
        self.h_pad = h_pad = np.full((nx + 2, ny + 2), np.nan)
        h_pad[1:-1, 1:-1] = h_centre
        self.cells = n = int(in_film.sum())
        diag = np.zeros(n)
        rows, cols, vals = [], [], []
        self.x_distance = centre_distances(x_edges, xc)[:, None]
        self.y_distance = centre_distances(y_edges, yc)[None, :]
        self.h_x_face = gap(x_edges[:, None], yc[None, :])
        tx = face_conductances(self.h_x_face, h_pad[:-1, 1:-1], h_pad[1:, 1:-1], dy[None, :],
                               self.x_distance)
        add_faces(rows, cols, vals, diag, index[:-1, 1:-1].ravel(), index[1:, 1:-1].ravel(),
                  tx.ravel())
        self.h_y_face = gap(xc[:, None], y_edges[None, :])
        ty = face_conductances(self.h_y_face, h_pad[1:-1, :-1], h_pad[1:-1, 1:], dx[:, None],
                               self.y_distance)
        add_faces(rows, cols, vals, diag, index[1:-1, :-1].ravel(), index[1:-1, 1:].ravel(),
                  ty.ravel())
        rows.append(np.arange(n))
        cols.append(np.arange(n))
        vals.append(diag)
        self.matrix = sp.csc_matrix((np.concatenate(vals), (np.concatenate(rows),
                                                             np.concatenate(cols))),
                                    shape=(n, n))
        self.area = (dx[:, None] * dy[None, :])[in_film]

    def solve(self, rhs):
        """The pressure in the film's cells for the right-hand side rhs (the source
        integrated over each cell; (cells,) or (cells, k) for k at once)."""
        return spla.spsolve(self.matrix, rhs)

    def padded(self, pressure):
        """One solution (cells,) as an (nx + 2, ny + 2) array, 0 out of the film and on the
        padding ring."""
        out = np.zeros(self.index.shape)
        out[1:-1, 1:-1][self.in_film] = pressure
        return out


def solve_reynolds(x_edges, y_edges, gap):
    """ReynoldsFilm for div(h^3 grad p) = -12 mu U (the surfaces approach at U, p > 0).
    Returns the force F = sum p dA and the number of cells in the film."""
    film = ReynoldsFilm(x_edges, y_edges, gap)
    pressure = film.solve(12.0 * MU * U * film.area)
    return float(pressure @ film.area), film.cells


def contact_grid(contact, spec, fraction=1.0):
    """The grid edges (x along e1, y along e2) of a contact, reaching fraction of the
    film's extent along each half-axis."""
    extents = contact.half_axis_extents()
    lengths = [math.sqrt(2.0 * contact.h0 / k) for k in contact.k]
    return [axis_edges(spec, lengths[i], extents[i], fraction) for i in range(2)]


def axisymmetric_force(h0, body1, body2):
    """The Reynolds force of an axisymmetric film, p = 0 at its edge r_f:
    F = 6 pi mu U int_0^r_f r^3/h^3 dr (from r h^3 dp/dr = -6 mu U r^2), h = h0 + the
    depths of the two surfaces below their tips, a_n (1 - sqrt(1 - r^2/b^2)) for a
    spheroid of semi-axis a_n along n and b across it (a plane: 0). An independent
    reference for the axisymmetric configurations (is_axisymmetric_about_normal: the
    first semi-axis is the one along n): written from the profiles, not from the line
    intersections."""
    profiles = [(body[0][0], body[0][1]) for body in (body1, body2) if body is not None]
    r_film = min(across for _, across in profiles)

    def gap(r):
        return h0 + sum(along * (1.0 - math.sqrt(max(0.0, 1.0 - (r / across) ** 2)))
                        for along, across in profiles)

    k = sum(along / across ** 2 for along, across in profiles)
    contact_length = math.sqrt(2.0 * h0 / k)
    breaks = [0.0] + [contact_length * 4.0 ** i for i in range(12)
                      if contact_length * 4.0 ** i < r_film] + [r_film]
    total = sum(quad(lambda r: r ** 3 / gap(r) ** 3, a, b, limit=200, epsabs=0,
                     epsrel=1e-12)[0] for a, b in zip(breaks[:-1], breaks[1:]))
    return 6.0 * math.pi * MU * U * total


# ---------------------------------------------------------------------------
# the campaign

def run_configuration(name, label, body1, body2, h0, spec):
    """One configuration at one gap: F_num, its grid and domain checks, F_par."""
    start = time.process_time()
    contact = Contact(body1, body2, h0)
    k1, k2 = contact.k
    f_par = paraboloid_force(h0, k1, k2)
    x_edges, y_edges = contact_grid(contact, spec)
    f_num, cells = solve_reynolds(x_edges, y_edges, contact.gap)
    f_fine, cells_fine = solve_reynolds(bisected(x_edges), bisected(y_edges), contact.gap)
    f_half, _ = solve_reynolds(*contact_grid(contact, spec, fraction=0.5), contact.gap)
    f_par_film, _ = solve_reynolds(x_edges, y_edges, contact.paraboloid_gap_on_film)
    row = dict(config=name, label=label, h0=h0, k1=k1, k2=k2,
               R_star=squeeze_radius(k1, k2), F_par=f_par, F_num=f_num, ratio=f_num / f_par,
               F_grid2=f_fine, grid_change_pct=100.0 * (f_fine / f_num - 1.0),
               ratio_richardson=(4.0 * f_fine - f_num) / (3.0 * f_par),
               F_domain_half=f_half, domain_change_pct=100.0 * (f_half / f_num - 1.0),
               F_par_film=f_par_film, ratio_edge=f_par_film / f_par,
               ratio_shape=f_num / f_par_film, R_gauss=contact.gaussian_squeeze_radius(),
               cells=cells, cells_grid2=cells_fine)
    row["ratio_gauss"] = f_num / (6.0 * math.pi * MU * U * row["R_gauss"] ** 2 / h0)
    if is_axisymmetric_about_normal(body1) and is_axisymmetric_about_normal(body2):
        row["F_axisym"] = axisymmetric_force(h0, body1, body2)
        row["axisym_diff_pct"] = 100.0 * (f_num / row["F_axisym"] - 1.0)
    row["cpu_s"] = time.process_time() - start
    return row


def paraboloid_check(h0, k1, k2, angle_deg, spec, refine=False):
    """The solver on the paraboloid gap h0 + x^T K x/2 (principal curvatures k1, k2 along
    axes turned angle_deg from the grid's) against F_par. Aligned axes: the grid of the
    campaign in the principal directions, reaching PARABOLOID_EXTENT contact lengths
    sqrt(2 h0/k) along each; turned axes: the first cells of the more curved direction's
    contact length along both grid axes, reaching PARABOLOID_EXTENT of the flatter's.
    Returns a row."""
    start = time.process_time()
    c, s = math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg))
    R = np.array([[c, -s], [s, c]])
    K = R @ np.diag([k1, k2]) @ R.T

    def gap(x, y):
        return h0 + 0.5 * (K[0, 0] * x * x + 2.0 * K[0, 1] * x * y + K[1, 1] * y * y)

    lengths = [math.sqrt(2.0 * h0 / k) for k in (k1, k2)]
    if angle_deg == 0:
        cells = lengths
        reach = [PARABOLOID_EXTENT * length for length in lengths]
    else:
        cells = [min(lengths)] * 2
        reach = [PARABOLOID_EXTENT * max(lengths)] * 2
    edges = [axis_edges(spec, cells[i], (reach[i], reach[i])) for i in range(2)]
    if refine:
        edges = [bisected(e) for e in edges]
    force, n = solve_reynolds(edges[0], edges[1], gap)
    f_par = paraboloid_force(h0, k1, k2)
    return dict(h0=h0, k1=k1, k2=k2, angle_deg=angle_deg, refined=int(refine), cells=n,
                F_num=force, F_par=f_par, error_pct=100.0 * (force / f_par - 1.0),
                cpu_s=time.process_time() - start)


# (h0, k1, k2, angle of the principal axes from the grid's in degrees)
PARABOLOID_CASES = [(1e-3, 2.0, 0.25, 0.0), (1e-3, 2.0, 0.25, 30.0)]
RESULT_FIELDS = ["config", "label", "h0", "k1", "k2", "R_star", "F_par", "F_num", "ratio",
                 "F_grid2", "grid_change_pct", "ratio_richardson", "F_domain_half",
                 "domain_change_pct", "F_par_film", "ratio_edge", "ratio_shape", "F_axisym",
                 "axisym_diff_pct", "R_gauss", "ratio_gauss", "cells", "cells_grid2", "cpu_s",
                 "host", "date", "commit"]


def results_dir(out):
    return os.path.join(out, "results")


def run_configurations(configs, gaps, spec, stamp):
    """The rows of results.csv: every configuration at every gap."""
    rows = []
    for name, label, body1, body2 in configs:
        for h0 in gaps:
            row = run_configuration(name, label, body1, body2, h0, spec)
            row.update(stamp)
            rows.append(row)
            print(f"{name:18s} h0 {h0:7.0e}  R* {row['R_star']:.4f}  F_num/F_par "
                  f"{row['ratio']:.5f}  grid x2 {row['grid_change_pct']:+.3f} %  domain/2 "
                  f"{row['domain_change_pct']:+.3f} %  cells {row['cells']}  "
                  f"{row['cpu_s']:.1f} s", flush=True)
    return rows


def run_paraboloid_checks(cases, spec, stamp):
    """The rows of paraboloid.csv: each case on its grid and on the grid refined x2."""
    checks = []
    for h0, k1, k2, angle in cases:
        for refine in (False, True):
            row = paraboloid_check(h0, k1, k2, angle, spec, refine)
            row.update(stamp)
            checks.append(row)
            print(f"paraboloid k {k1}/{k2} at {angle} deg{' x2' if refine else ''}: "
                  f"F_num/F_par - 1 = {row['error_pct']:+.4f} %  cells {row['cells']}  "
                  f"{row['cpu_s']:.1f} s", flush=True)
    return checks


def run(args):
    quick = args.quick
    out = args.out or os.path.join(HERE, "run-quick" if quick else "")
    start = time.process_time()
    stamp = provenance()
    spec = QUICK_GRID if quick else FULL_GRID
    configs = [c for c in CONFIGURATIONS if not quick or c[0] in QUICK_CONFIGURATIONS]
    rows = run_configurations(configs, QUICK_GAPS if quick else GAPS, spec, stamp)
    checks = run_paraboloid_checks(PARABOLOID_CASES[:1] if quick else PARABOLOID_CASES,
                                   spec, stamp)
    write_csv(os.path.join(results_dir(out), "results.csv"), rows, RESULT_FIELDS)
    write_csv(os.path.join(results_dir(out), "paraboloid.csv"), checks)
    print(f"total CPU {time.process_time() - start:.1f} s; results in {results_dir(out)}")
    return quick_verdict(rows, checks) if quick else 0


def quick_verdict(rows, checks):
    """The smoke check: the paraboloid reproduced to 1 %, the ratio within 5 % of 1 at the
    smallest gap."""
    bad = [c for c in checks if abs(c["error_pct"]) > 1.0]
    smallest = min(r["h0"] for r in rows)
    bad += [r for r in rows if r["h0"] == smallest and abs(r["ratio"] - 1.0) > 0.05]
    for b in bad:
        print("FAILED:", b, file=sys.stderr)
    return 1 if bad else 0


# ---------------------------------------------------------------------------
# table, metrics and figures

def load_rows(out):
    """The rows of results.csv and paraboloid.csv, numbers as floats (None if empty)."""
    rows = read_csv(os.path.join(results_dir(out), "results.csv"), missing_ok=False)
    text = {"config", "label", "host", "date", "commit"}
    for r in rows:
        for key, value in r.items():
            if key not in text:
                r[key] = float(value) if value not in ("", None) else None
    checks = read_csv(os.path.join(results_dir(out), "paraboloid.csv"), missing_ok=False)
    for c in checks:
        for key in ("h0", "k1", "k2", "angle_deg", "refined", "cells", "F_num", "F_par",
                    "error_pct", "cpu_s"):
            c[key] = float(c[key])
    return rows, checks


def gap_key(h0):
    """'h1e-3' for 1e-3."""
    mantissa, exponent = f"{h0:.0e}".split("e")
    return f"h{mantissa}e{int(exponent)}"


def deviation_fit(rows):
    """For one configuration: the least-squares fit of F/F_par - 1 = h0 (a ln h0 + b) on
    FIT_GAPS, F the Richardson extrapolation (4 F_grid2 - F_num)/3 of the grid pair (the
    discretisation is second order; its error, about 1e-4 of F and nearly the same at
    every gap, would otherwise bias a fit of deviations of a few 1e-3); the local slope
    d ln|dev|/d ln h0 between the two smallest gaps; with three gaps or more, the fit
    c0 + h0 (a ln h0 + b) too, whose c0 is the ratio's limit minus 1 (zero if F_par is
    the limit)."""
    pts = sorted((r["h0"], r["ratio_richardson"] - 1.0) for r in rows if r["h0"] in FIT_GAPS)
    if len(pts) < 2:
        return None
    h = np.array([p[0] for p in pts])
    dev = np.array([p[1] for p in pts])
    (a, b), *_ = np.linalg.lstsq(np.column_stack([h * np.log(h), h]), dev, rcond=None)
    slope = math.log(abs(dev[1] / dev[0])) / math.log(h[1] / h[0])
    fit = dict(a=a, b=b, slope=slope, limit=None)
    if len(pts) >= 3:
        (c0, _, _), *_ = np.linalg.lstsq(np.column_stack([np.ones_like(h), h * np.log(h), h]),
                                         dev, rcond=None)
        fit["limit"] = 1.0 + c0
    return fit


def configurations_in(rows):
    names = []
    for r in rows:
        if r["config"] not in names:
            names.append(r["config"])
    return names


def metrics_of(rows, checks):
    m = {}
    gaps = sorted({r["h0"] for r in rows})
    for h0 in gaps:
        at = [r for r in rows if r["h0"] == h0]
        key = gap_key(h0)
        m[f"max_abs_ratio_error_pct_{key}"] = max(100 * abs(r["ratio"] - 1) for r in at)
        m[f"grid_change_pct_{key}"] = max(abs(r["grid_change_pct"]) for r in at)
        m[f"domain_change_pct_{key}"] = max(abs(r["domain_change_pct"]) for r in at)
    headline = [r for r in rows if r["h0"] in HEADLINE_GAPS]
    m["grid_change_pct"] = max(abs(r["grid_change_pct"]) for r in headline)
    m["domain_change_pct"] = max(abs(r["domain_change_pct"]) for r in headline)
    axi = [abs(r["axisym_diff_pct"]) for r in rows if r["axisym_diff_pct"] is not None]
    if axi:
        m["axisymmetric_check_max_pct"] = max(axi)
    for c in checks:
        suffix = ("" if c["angle_deg"] == 0 else "_rotated") + ("_grid2" if c["refined"] else "")
        m[f"paraboloid_check_error_pct{suffix}"] = abs(c["error_pct"])
    slopes, limits = [], []
    for name in configurations_in(rows):
        mine = [r for r in rows if r["config"] == name]
        fit = deviation_fit(mine)
        if fit:
            slopes.append(fit["slope"])
            m[f"deviation_slope_{name}"] = fit["slope"]
            m[f"deviation_log_coefficient_{name}"] = fit["a"]
            if fit["limit"] is not None:
                limits.append(abs(fit["limit"] - 1.0))
        for r in mine:
            if r["h0"] in HEADLINE_GAPS:
                m[f"ratio_{name}_{gap_key(r['h0'])}"] = r["ratio"]
    if slopes:
        m["deviation_slope_min"] = min(slopes)
        m["deviation_slope_max"] = max(slopes)
    if limits:
        m["extrapolated_limit_error_pct"] = 100.0 * max(limits)
    m["cpu_s_total"] = sum(r["cpu_s"] for r in rows) + sum(c["cpu_s"] for c in checks)
    return {k: round(float(v), 6) for k, v in m.items()}


def md_row(cells):
    """One line of a markdown table."""
    return "| " + " | ".join(str(c) for c in cells) + " |"


def md_header(cells):
    return [md_row(cells), md_row(["---"] * len(cells))]


def signed(x, digits):
    return "-" if x is None else f"{x:+.{digits}f}"


def write_table(path, rows, checks):
    lines = ["# Squeeze film: Reynolds force on the exact gap against the paraboloid's",
             "",
             "Produced by `validation/squeezeFilm/squeezeFilm.py plot` from results/results.csv "
             "and results/paraboloid.csv. mu = U = 1, lengths in the smallest semi-axis. "
             "F_par = 6 pi R*^2/h0, R*^2 = 2/(sqrt(k1 k2)(k1 + k2)), k1, k2 the principal "
             "curvatures of K = S1 + S2. F_num: the Reynolds equation on the exact gap over "
             "the whole film. grid x2: F on the grid refined x2, relative to F_num; "
             "domain/2: F on the film's half-extent (the same cells near the contact), "
             "relative to F_num. edge: the paraboloid gap on the same film (p = 0 at the "
             "film's edge) over F_par; shape: F_num over that, the share of the gap's "
             "departure from the paraboloid (edge x shape = F_num/F_par). axisym.: F_num "
             "against the 1D quadrature of the axisymmetric films. F_num/F_G: against "
             "6 pi R_G*^2/h0, the Gaussian radii 1/sqrt(k1 k2) of the two surfaces combined "
             "as two spheres.",
             ""]
    lines += md_header(["configuration", "h0", "k1", "k2", "R*", "F_par", "F_num",
                        "F_num/F_par", "grid x2 [%]", "domain/2 [%]", "edge", "shape",
                        "axisym. [%]", "F_num/F_G", "cells"])
    for r in rows:
        lines.append(md_row([
            r["label"], f"{r['h0']:.0e}", f"{r['k1']:.4f}", f"{r['k2']:.4f}",
            f"{r['R_star']:.4f}", f"{r['F_par']:.6g}", f"{r['F_num']:.6g}",
            f"{r['ratio']:.5f}", signed(r["grid_change_pct"], 4),
            signed(r["domain_change_pct"], 3), f"{r['ratio_edge']:.5f}",
            f"{r['ratio_shape']:.5f}", signed(r["axisym_diff_pct"], 4),
            f"{r['ratio_gauss']:.4f}", int(r["cells"])]))
    lines += ["", "## Deviation from the paraboloid's force",
              "",
              f"Fit of F/F_par - 1 = h0 (a ln h0 + b), F = (4 F_grid2 - F_num)/3 the "
              "Richardson extrapolation of the grid pair, on h0 = "
              f"{', '.join(f'{g:g}' for g in FIT_GAPS)}; slope: d ln|F/F_par - 1|/d ln h0 "
              "between the two smallest gaps (1 for a deviation proportional to h0, below 1 "
              "with a logarithm: 0.88 for h0 ln h0 alone between 1e-4 and 3e-4). limit: the "
              "ratio at h0 = 0 from the fit c0 + h0 (a ln h0 + b) through the same gaps, minus 1.",
              ""]
    lines += md_header(["configuration", "a", "b", "slope", "limit - 1"])
    for name in configurations_in(rows):
        mine = [r for r in rows if r["config"] == name]
        fit = deviation_fit(mine)
        if fit:
            limit = "-" if fit["limit"] is None else f"{fit['limit'] - 1.0:+.1e}"
            lines.append(md_row([mine[0]["label"], f"{fit['a']:+.3f}", f"{fit['b']:+.3f}",
                                 f"{fit['slope']:.3f}", limit]))
    lines += ["", "## The paraboloid gap on the solver",
              "",
              f"h = h0 + x^T K x/2, the film reaching {PARABOLOID_EXTENT:g} contact lengths "
              "sqrt(2 h0/k) of the flatter direction, p = 0 there; the principal axes along "
              "the grid's (0 deg) or turned by 30 deg.",
              ""]
    lines += md_header(["h0", "k1", "k2", "axes", "grid", "cells", "F_num", "F_par",
                        "F_num/F_par - 1 [%]"])
    for c in checks:
        lines.append(md_row([f"{c['h0']:.0e}", f"{c['k1']:g}", f"{c['k2']:g}",
                             f"{c['angle_deg']:g} deg", "x2" if c["refined"] else "base",
                             int(c["cells"]), f"{c['F_num']:.7g}", f"{c['F_par']:.7g}",
                             f"{c['error_pct']:+.5f}"]))
    first = rows[0]
    lines += ["", f"Run on {first['host']}, {first['date']}, commit {first['commit']}; "
              f"CPU {sum(r['cpu_s'] for r in rows) + sum(c['cpu_s'] for c in checks):.0f} s "
              "in all.", ""]
    with open(path, "w") as f:
        f.write("\n".join(lines))


def plot_ratios(path, rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    names = configurations_in(rows)
    colours = plt.cm.tab20(np.linspace(0, 1, 20))
    markers = "os^vD<>ph*XP8"
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(13, 5.2))
    for i, name in enumerate(names):
        mine = sorted((r for r in rows if r["config"] == name), key=lambda r: r["h0"])
        h = np.array([r["h0"] for r in mine])
        ratio = np.array([r["ratio"] for r in mine])
        style = dict(color=colours[i % 20], marker=markers[i % len(markers)], ms=5,
                     label=mine[0]["label"])
        ax1.semilogx(h, ratio, **style)
        ax2.loglog(h, np.abs(ratio - 1.0), **style)
    h = np.geomspace(min(r["h0"] for r in rows), max(r["h0"] for r in rows), 50)
    ax1.axhline(1.0, color="k", lw=0.8)
    ax1.set_xlabel("gap $h_0$ / smallest semi-axis")
    ax1.set_ylabel(r"$F_{num}/F_{par}$")
    ax1.set_title("Reynolds force on the exact gap / paraboloid's closed form")
    ax2.loglog(h, h * np.log(1 / h), "k--", lw=1, label=r"$h_0 \ln(1/h_0)$")
    ax2.loglog(h, h, "k:", lw=1, label=r"$h_0$")
    ax2.set_xlabel("gap $h_0$ / smallest semi-axis")
    ax2.set_ylabel(r"$|F_{num}/F_{par} - 1|$")
    ax2.set_title("deviation")
    ax2.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.02, 0.5))
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def plot_gaussian(path, rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    names = configurations_in(rows)
    colours = plt.cm.tab20(np.linspace(0, 1, 20))
    markers = "os^vD<>ph*XP8"
    fig, ax = plt.subplots(figsize=(9, 5))
    for i, name in enumerate(names):
        mine = sorted((r for r in rows if r["config"] == name), key=lambda r: r["h0"])
        ax.semilogx([r["h0"] for r in mine], [r["ratio_gauss"] for r in mine],
                    color=colours[i % 20], marker=markers[i % len(markers)], ms=5,
                    label=mine[0]["label"])
        # as h0 -> 0, F_num -> F_par, so F_num/F_G -> (R*/R_G*)^2
        ax.plot(0.5 * mine[0]["h0"], (mine[0]["R_star"] / mine[0]["R_gauss"]) ** 2, "_",
                color=colours[i % 20], ms=14, mew=2)
    ax.axhline(1.0, color="k", lw=0.8)
    ax.set_xlabel("gap $h_0$ / smallest semi-axis")
    ax.set_ylabel(r"$F_{num}/F_G$, $F_G = 6\pi\mu U R_G^{*2}/h_0$")
    ax.set_title("against the sphere of the Gaussian radii (bars: the limit $(R^*/R_G^*)^2$)")
    ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.02, 0.5))
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def plot(args):
    out = args.out or HERE
    rows, checks = load_rows(out)
    folder = results_dir(out)
    write_table(os.path.join(folder, "table.md"), rows, checks)
    metrics = metrics_of(rows, checks)
    path = os.path.join(folder, "metrics.json")
    # the sliding_* keys are slidingFilm.py plot's
    kept = {}
    if os.path.exists(path):
        with open(path) as f:
            kept = {k: v for k, v in json.load(f).items() if k.startswith("sliding_")}
    with open(path, "w") as f:
        json.dump({**kept, **metrics}, f, indent=1, sort_keys=True)
        f.write("\n")
    plot_ratios(os.path.join(folder, "forceRatio.png"), rows)
    plot_gaussian(os.path.join(folder, "gaussianRadius.png"), rows)
    per_configuration = ("ratio_", "deviation_slope_", "deviation_log_")
    for key in sorted(metrics):
        if not key.startswith(per_configuration) or key.endswith(("min", "max")):
            print(f"{key}: {metrics[key]}")
    return 0


def run_or_plot(doc, run_step, plot_step):
    """The command line of this folder's scripts: `run [--quick] [--out DIR]` or
    `plot [--out DIR]`, dispatched to run_step or plot_step; their exit status."""
    ap = argparse.ArgumentParser(description=doc,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="command", required=True)
    r = sub.add_parser("run")
    r.add_argument("--quick", action="store_true")
    r.add_argument("--out")
    p = sub.add_parser("plot")
    p.add_argument("--out")
    args = ap.parse_args()
    return run_step(args) if args.command == "run" else plot_step(args)


def main():
    return run_or_plot(__doc__, run, plot)


if __name__ == "__main__":
    sys.exit(main())
