"""Body-fitted axisymmetric mesh of a sphere or a prolate spheroid in a uniform stream
along its axis (validation/finiteReynoldsDrag, the independent reference of
bodyFitted.py), written directly as an OpenFOAM polyMesh.

The meridian plane (X along the axis, R from it) is meshed with orthogonal conformal
coordinates zeta = xi + i eta, eta in [0, pi] (eta = 0 the downstream axis):
    prolate spheroid, focal distance c:  X + i R = c cosh(zeta),  body xi0 = atanh(b/a)
    sphere of radius r:                  X + i R = r exp(zeta),    body xi0 = 0
so the cells are squares in the meridian plane whose size grows with the distance
(d xi = d eta = pi/n_eta). The plane is turned into a wedge of WEDGE_DEG degrees about
the X axis; the cells next to the axis are prisms (their axis faces have no area and
are left out, as blockMesh does for a collapsed block).

Patches: body (wall), inlet (outer boundary upstream, eta > pi/2), outlet (outer
boundary downstream), front and back (wedge).
"""
import math
import os

import numpy as np

WEDGE_DEG = 5.0

HEADER = """FoamFile
{{
    version     2.0;
    format      ascii;
    class       {cls};
    location    "constant/polyMesh";
    object      {obj};
}}
"""


def meridian_nodes(ar, n_eta, outer_radius):
    """Node coordinates X[i, j], R[i, j] (i along xi from the body, j along eta) of
    the body of aspect ratio ar >= 1 with the equal-volume diameter 1."""
    b = 0.5 / ar ** (1.0 / 3.0)
    a = ar * b
    d = math.pi / n_eta
    eta = np.linspace(0.0, math.pi, n_eta + 1)
    if ar > 1.0:
        c = math.sqrt(a * a - b * b)
        xi0 = math.atanh(b / a)
        n_xi = int(math.ceil((math.acosh(outer_radius / c) - xi0) / d))
        xi = xi0 + d * np.arange(n_xi + 1)
        Z = xi[:, None] + 1j * eta[None, :]
        W = c * np.cosh(Z)
    elif ar == 1.0:
        n_xi = int(math.ceil(math.log(outer_radius / b) / d))
        xi = d * np.arange(n_xi + 1)
        W = b * np.exp(xi[:, None] + 1j * eta[None, :])
    else:
        raise ValueError(f"bodyFittedMesh: aspect ratio {ar} not handled (allowed: >= 1)")
    R = W.imag
    R[:, 0] = 0.0
    R[:, -1] = 0.0
    return W.real, R


def polygon(labels):
    """A face's point labels in order with the repeated ones (the axis) removed."""
    out = []
    for p in labels:
        if p not in out:
            out.append(int(p))
    return out


def oriented(points, face, towards):
    """The face with its points ordered so that its normal points along towards."""
    p = points[face]
    n = np.zeros(3)
    for k in range(len(face)):
        n += np.cross(p[k], p[(k + 1) % len(face)])
    return face if np.dot(n, towards) > 0 else face[::-1]


class _MeshBuilder:
    """Points, cells' faces and patches of the wedge built from the meridian nodes."""

    def __init__(self, X, R):
        self.ni, self.nj = X.shape[0] - 1, X.shape[1] - 1
        half = math.radians(WEDGE_DEG / 2)
        self.points = []
        self.index = {}
        for i in range(self.ni + 1):
            for j in range(self.nj + 1):
                if j in (0, self.nj):
                    self.index[(i, j, 0)] = self.index[(i, j, 1)] = len(self.points)
                    self.points.append((X[i, j], 0.0, 0.0))
                else:
                    for side, s in ((0, 1.0), (1, -1.0)):
                        self.index[(i, j, side)] = len(self.points)
                        self.points.append((X[i, j], R[i, j] * math.cos(half),
                                            s * R[i, j] * math.sin(half)))
        self.points = np.array(self.points)

    def cell(self, i, j):
        return i * self.nj + j

    def centre(self, i, j):
        ids = {self.index[(i + di, j + dj, s)] for di in (0, 1) for dj in (0, 1) for s in (0, 1)}
        return self.points[sorted(ids)].mean(axis=0)

    def polygon(self, nodes):
        """Point labels of a face through the (i, j, side) nodes in order, repeated
        labels (the axis) removed."""
        return polygon([self.index[n] for n in nodes])

    def oriented(self, face, towards):
        return oriented(self.points, face, towards)

    def build(self):
        internal, patches = [], {"body": [], "inlet": [], "outlet": [], "front": [], "back": []}
        for i in range(self.ni):
            for j in range(self.nj):
                own, c0 = self.cell(i, j), self.centre(i, j)
                if i + 1 < self.ni:
                    f = self.polygon([(i + 1, j, 0), (i + 1, j + 1, 0), (i + 1, j + 1, 1), (i + 1, j, 1)])
                    internal.append((own, self.cell(i + 1, j),
                                     self.oriented(f, self.centre(i + 1, j) - c0)))
                if j + 1 < self.nj:
                    f = self.polygon([(i, j + 1, 0), (i + 1, j + 1, 0), (i + 1, j + 1, 1), (i, j + 1, 1)])
                    internal.append((own, self.cell(i, j + 1),
                                     self.oriented(f, self.centre(i, j + 1) - c0)))
                if i == 0:
                    f = self.polygon([(0, j, 0), (0, j + 1, 0), (0, j + 1, 1), (0, j, 1)])
                    patches["body"].append((own, self.oriented(f, -c0 * [1, 1, 0])))
                if i + 1 == self.ni:
                    f = self.polygon([(i + 1, j, 0), (i + 1, j + 1, 0), (i + 1, j + 1, 1), (i + 1, j, 1)])
                    name = "outlet" if j < self.nj // 2 else "inlet"
                    patches[name].append((own, self.oriented(f, c0 * [1, 1, 0])))
                for side, name, s in ((0, "front", 1.0), (1, "back", -1.0)):
                    f = self.polygon([(i, j, side), (i + 1, j, side), (i + 1, j + 1, side), (i, j + 1, side)])
                    half = math.radians(WEDGE_DEG / 2)
                    normal = np.array([0.0, -s * math.sin(half), math.cos(half)]) * s
                    patches[name].append((own, self.oriented(f, normal)))
        internal.sort(key=lambda t: (t[0], t[1]))
        return internal, patches


def _write_list(path, cls, obj, items, fmt):
    with open(path, "w") as out:
        out.write(HEADER.format(cls=cls, obj=obj))
        out.write(f"\n{len(items)}\n(\n")
        for it in items:
            out.write(fmt(it) + "\n")
        out.write(")\n")


def write_poly_mesh(case, points, internal, patches, types):
    """Writes case/constant/polyMesh from the points, the internal faces [(owner,
    neighbour, face)] in upper-triangular order and the boundary faces {patch: [(owner,
    face)]}, the patches in the order of types {patch: OpenFOAM patch type}."""
    faces = [f for _, _, f in internal]
    owner = [o for o, _, _ in internal]
    neighbour = [n for _, n, _ in internal]
    starts = {}
    for name in types:
        starts[name] = len(faces)
        for o, f in patches[name]:
            faces.append(f)
            owner.append(o)
    d = os.path.join(case, "constant", "polyMesh")
    os.makedirs(d, exist_ok=True)
    _write_list(os.path.join(d, "points"), "vectorField", "points", points,
                lambda p: f"({p[0]:.15g} {p[1]:.15g} {p[2]:.15g})")
    _write_list(os.path.join(d, "faces"), "faceList", "faces", faces,
                lambda f: f"{len(f)}(" + " ".join(map(str, f)) + ")")
    _write_list(os.path.join(d, "owner"), "labelList", "owner", owner, str)
    _write_list(os.path.join(d, "neighbour"), "labelList", "neighbour", neighbour, str)
    with open(os.path.join(d, "boundary"), "w") as out:
        out.write(HEADER.format(cls="polyBoundaryMesh", obj="boundary"))
        out.write(f"\n{len(types)}\n(\n")
        for name, kind in types.items():
            out.write(f"    {name}\n    {{\n        type {kind};\n"
                      f"        nFaces {len(patches[name])};\n        startFace {starts[name]};\n    }}\n")
        out.write(")\n")


def write_mesh(case, ar, n_eta, outer_radius):
    """Writes case/constant/polyMesh; returns the number of cells."""
    if n_eta % 2:
        raise ValueError(f"bodyFittedMesh: n_eta {n_eta} must be even (allowed: even integers)")
    X, R = meridian_nodes(ar, n_eta, outer_radius)
    mb = _MeshBuilder(X, R)
    internal, patches = mb.build()
    write_poly_mesh(case, mb.points, internal, patches,
                    {"body": "wall", "inlet": "patch", "outlet": "patch", "front": "wedge",
                     "back": "wedge"})
    return mb.ni * mb.nj
