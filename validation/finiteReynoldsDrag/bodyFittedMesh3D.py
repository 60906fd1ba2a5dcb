"""Body-fitted three-dimensional mesh of a sphere or a prolate spheroid in a uniform
stream at an incidence to its axis (validation/finiteReynoldsDrag, the reference of
bodyFitted.py away from the axis), written directly as an OpenFOAM polyMesh.

The meridian mesh of bodyFittedMesh (orthogonal conformal coordinates xi, eta of the
plane through the axis X) is swept about the axis through phi in [0, pi]: the point
(X, R) goes to (X, R cos phi, R sin phi). The prolate spheroidal coordinates
(xi, eta, phi) are orthogonal, so the cells are orthogonal hexahedra except those next
to the axis, which are prisms. The stream (cos(theta), sin(theta), 0) lies in the plane
z = 0, a plane of symmetry of the flow whatever the incidence theta: only z >= 0 is
meshed, the plane z = 0 (phi = 0 and phi = pi) a symmetryPlane patch.

Patches: body (wall), inlet (outer faces whose outward normal points against the
stream), outlet (the other outer faces), symmetry (symmetryPlane).
"""
import math

import numpy as np

import bodyFittedMesh
from bodyFittedMesh import oriented, polygon


def _points(X, R, n_phi):
    """The points and the label array P[i, j, k] (one label for every k on the axis)."""
    ni, nj = X.shape[0] - 1, X.shape[1] - 1
    phi = np.linspace(0.0, math.pi, n_phi + 1)
    cos_phi, sin_phi = np.cos(phi), np.sin(phi)
    cos_phi[-1], sin_phi[0], sin_phi[-1] = -1.0, 0.0, 0.0
    P = np.empty((ni + 1, nj + 1, n_phi + 1), dtype=np.int64)
    points = []
    for i in range(ni + 1):
        for j in range(nj + 1):
            if j in (0, nj):
                P[i, j, :] = len(points)
                points.append((X[i, j], 0.0, 0.0))
            else:
                P[i, j, :] = len(points) + np.arange(n_phi + 1)
                for k in range(n_phi + 1):
                    points.append((X[i, j], R[i, j] * cos_phi[k], R[i, j] * sin_phi[k]))
    return np.array(points), P


def write_mesh(case, ar, n_eta, n_phi, outer_radius, incidence_deg):
    """Writes case/constant/polyMesh; returns the number of cells."""
    if n_eta % 2:
        raise ValueError(f"bodyFittedMesh3D: n_eta {n_eta} must be even (allowed: even integers)")
    X, R = bodyFittedMesh.meridian_nodes(ar, n_eta, outer_radius)
    points, P = _points(X, R, n_phi)
    ni, nj, nk = X.shape[0] - 1, X.shape[1] - 1, n_phi
    stream = np.array([math.cos(math.radians(incidence_deg)),
                       math.sin(math.radians(incidence_deg)), 0.0])
    corner = points[P]
    centres = 0.125 * sum(corner[di:ni + di, dj:nj + dj, dk:nk + dk]
                          for di in (0, 1) for dj in (0, 1) for dk in (0, 1))

    def cell(i, j, k):
        return (i * nj + j) * nk + k

    internal = []
    patches = {"body": [], "inlet": [], "outlet": [], "symmetry": []}
    for i in range(ni):
        for j in range(nj):
            for k in range(nk):
                own, c0 = cell(i, j, k), centres[i, j, k]
                xi_face = polygon([P[i + 1, j, k], P[i + 1, j + 1, k],
                                    P[i + 1, j + 1, k + 1], P[i + 1, j, k + 1]])
                if i + 1 < ni:
                    internal.append((own, cell(i + 1, j, k),
                                     oriented(points, xi_face, centres[i + 1, j, k] - c0)))
                else:
                    f = oriented(points, xi_face, c0)
                    n = np.sum(np.cross(points[f], np.roll(points[f], -1, axis=0)), axis=0)
                    patches["inlet" if np.dot(n, stream) < 0 else "outlet"].append((own, f))
                if i == 0:
                    f = polygon([P[0, j, k], P[0, j + 1, k], P[0, j + 1, k + 1], P[0, j, k + 1]])
                    patches["body"].append((own, oriented(points, f, -c0)))
                if j + 1 < nj:
                    f = polygon([P[i, j + 1, k], P[i + 1, j + 1, k],
                                  P[i + 1, j + 1, k + 1], P[i, j + 1, k + 1]])
                    internal.append((own, cell(i, j + 1, k),
                                     oriented(points, f, centres[i, j + 1, k] - c0)))
                if k + 1 < nk:
                    f = polygon([P[i, j, k + 1], P[i + 1, j, k + 1],
                                  P[i + 1, j + 1, k + 1], P[i, j + 1, k + 1]])
                    internal.append((own, cell(i, j, k + 1),
                                     oriented(points, f, centres[i, j, k + 1] - c0)))
                for kk in {0, nk} & {k, k + 1}:
                    f = polygon([P[i, j, kk], P[i + 1, j, kk], P[i + 1, j + 1, kk], P[i, j + 1, kk]])
                    patches["symmetry"].append((own, oriented(points, f, [0.0, 0.0, -1.0])))
    internal.sort(key=lambda t: (t[0], t[1]))
    bodyFittedMesh.write_poly_mesh(case, points, internal, patches,
                                   {"body": "wall", "inlet": "patch", "outlet": "patch",
                                    "symmetry": "symmetryPlane"})
    return ni * nj * nk
