#!/usr/bin/python3
"""The ln(1/h0) coupling of normal and tangential motion from the gap's cubic terms: a
closed form against the Reynolds numerics of slidingFilm.py (validation/squeezeFilm, see
README.md, "The coupling from the gap's cubic terms").

    cubicCoupling.py [--out DIR]

Reads DIR/results/sliding.csv (slidingFilm.py run) and writes DIR/results/cubicCoupling.md
and the sliding_cubic_* keys of DIR/results/metrics.json (the other keys kept);
slidingFilm.py plot does the same.

Where the closest points are not vertices of the surfaces, the gap is
h = h0 + t.K t/2 + Gamma(t, t, t)/6 with Gamma = C1 + C2, C_k the third derivatives of the
surfaces (each for its own outward normal m_k: for the ellipsoid (y - c).A (y - c) = 1 at
the point y, g = A (y - c), b = P A m, C(t, t, t) = -3 (t.A t)(b.t)/|g|^2). To first order
in Gamma, a normal approach at the speed V (body 1 towards body 2) gives body 1 the
tangential force and the moment about its closest point, per ln(1/h0),

    F1 = pi mu R V [3/(k1 + k2) D:K^-1 + (S2 - S1) j/2],      D = C2 - C1,
    j_m = 36/(k1 + k2) M_mm [-(7 k_m + 2 k_o) Gamma_mmm/(6 k_m^2) - (k_m + 2 k_o) Gamma_moo/(2 k_m k_o)],
    T1 = -pi mu R V j x n - 12 pi mu R V/(k1 + k2) [(S1 K^-1)_21 - (S1 K^-1)_12] n,

in the principal axes of K (o the other axis, M_mm = 1/(3 k_m + 2 k_o)): the squeeze
pressure p0 on the cubic slopes of the surfaces, and the odd pressure the cubic terms add
to it (from the adjoint of the sliding problem, whose solution is the paraboloid law's
pressure) on the paraboloid's slopes; the twist is the squeeze pressure on surfaces whose
principal axes are not K's (not checked here: slidingFilm.py has no rotation about n).
By the symmetry of the film's resistance, a sliding or a
rotation of body 1 gives the normal force F.n = F1 . U + (T1 + (p1 - c1) x F1) . Omega.
"""
import argparse
import json
import math
import os

import numpy as np

from slidingFilm import SLIDING_CONFIGURATIONS, motion_frame
from squeezeFilm import CONFIGURATIONS, HERE, MU, NORMAL, Contact, Plane, md_header, md_row
from validationTools import read_csv  # noqa: E402 (on the path through squeezeFilm)


def third_derivatives(body, point, m):
    """C_ijk of the surface at point for its outward unit normal m (a plane: 0):
    C(t, t, t) = -3 (t.A t)(b.t)/|g|^2 on the tangent plane, b = P A m."""
    if isinstance(body, Plane):
        return np.zeros((3, 3, 3))
    A = body.A
    g = np.linalg.norm(A @ (point - body.centre))
    P = np.eye(3) - np.outer(m, m)
    At = P @ A @ P
    b = P @ A @ m
    return -(np.einsum("ij,k->ijk", At, b) + np.einsum("jk,i->ijk", At, b)
             + np.einsum("ik,j->ijk", At, b)) / g ** 2


def approach_loads(contact, mu=MU, speed=1.0):
    """(F1, T1 about p1, T1 about c1) per ln(1/h0) for body 1 approaching body 2 at speed."""
    n = NORMAL
    P = np.eye(3) - np.outer(n, n)
    S1 = P @ contact.body1.shape_operator(contact.p1) @ P
    S2 = P @ contact.body2.shape_operator(contact.p2) @ P
    K = S1 + S2
    k, vectors = np.linalg.eigh(K)
    order = np.argsort(k)[::-1][:2]          # the two tangent eigenvalues (n's is 0)
    k, E = k[order], vectors[:, order]
    R = 1.0 / math.sqrt(k[0] * k[1])
    C1 = third_derivatives(contact.body1, contact.p1, n)
    C2 = third_derivatives(contact.body2, contact.p2, -n)
    # in the principal axes of K
    frame = lambda T: np.einsum("ijk,ia,jb,kc->abc", T, E, E, E)  # noqa: E731
    Gamma, D = frame(C1 + C2), frame(C2 - C1)
    s1, s2 = E.T @ S1 @ E, E.T @ S2 @ E
    Kinv = np.diag(1.0 / k)
    trace = k[0] + k[1]
    j = np.zeros(2)
    for m in range(2):
        o = 1 - m
        M = 1.0 / (3.0 * k[m] + 2.0 * k[o])
        j[m] = 36.0 / trace * M * (-(7.0 * k[m] + 2.0 * k[o]) * Gamma[m, m, m] / (6.0 * k[m] ** 2)
                                   - (k[m] + 2.0 * k[o]) * Gamma[m, o, o] / (2.0 * k[m] * k[o]))
    scale = math.pi * mu * R * speed
    force2 = scale * (3.0 / trace * np.einsum("ijm,ij->m", D, Kinv) + 0.5 * (s2 - s1) @ j)
    force = E @ force2
    moment = -scale * np.cross(E @ j, n)
    s1K = s1 @ Kinv
    moment += -12.0 * scale / trace * (s1K[1, 0] - s1K[0, 1]) * np.cross(E[:, 0], E[:, 1])
    arm = contact.p1 - contact.body1.centre
    return force, moment, moment + np.cross(arm, force)


def rows_by(rows):
    return {(r["config"], r["motion"]): r for r in rows}


def compare(out):
    results = os.path.join(out, "results")
    rows = rows_by(read_csv(os.path.join(results, "sliding.csv"), missing_ok=False))
    configs = {c[0]: c for c in CONFIGURATIONS}
    table = []
    errors = []
    largest = 0.0
    for name in SLIDING_CONFIGURATIONS:
        if (name, "translation_e1") not in rows:
            continue
        _, label, body1, body2 = configs[name]
        contact = Contact(body1, body2, 1e-4)
        frame = motion_frame(contact)
        force, _, torque = approach_loads(contact)
        # predicted: the approach's tangential force; the normal force of each motion
        predicted = {"approach_Fe1": force @ frame[:, 0], "approach_Fe2": force @ frame[:, 1],
                     "translation_e1": force @ frame[:, 0], "translation_e2": force @ frame[:, 1],
                     "rotation_e1": torque @ frame[:, 0], "rotation_e2": torque @ frame[:, 1]}
        measured = {"approach_Fe1": float(rows[(name, "translation_e1")]["approach_Fe1_num"]),
                    "approach_Fe2": float(rows[(name, "translation_e1")]["approach_Fe2_num"])}
        for motion in ("translation_e1", "translation_e2", "rotation_e1", "rotation_e2"):
            measured[motion] = float(rows[(name, motion)]["Fn_num"])
        scale = max(abs(v) for v in measured.values())
        largest = max(largest, scale)
        for key in predicted:
            err = predicted[key] - measured[key]
            # relative where the coupling is there, absolute (against the paraboloid law's
            # scale, 2 pi mu R) where it vanishes
            if abs(measured[key]) > 1e-3:
                errors.append(100.0 * abs(err) / abs(measured[key]))
            table.append([label, key, f"{measured[key]:+.4f}", f"{predicted[key]:+.4f}",
                          f"{100.0 * err / measured[key]:+.2f} %" if abs(measured[key]) > 1e-3
                          else f"{err:+.1e} (abs)"])
    lines = ["# The coupling of normal and tangential motion from the gap's cubic terms", "",
             "Written by `cubicCoupling.py` from `sliding.csv` (`slidingFilm.py run`): the "
             "ln(1/h0) coefficients of the tangential force under a unit normal approach "
             "(approach_Fe1, approach_Fe2) and of the normal force F.n under each unit sliding "
             "and rolling motion of slidingFilm.py, measured (Reynolds, exact gap, slope "
             "1e-4 to 1e-5) and from the closed form of cubicCoupling.py.", "",
             *md_header(["configuration", "coefficient", "measured", "closed form", "error"])]
    lines += [md_row(r) for r in table]
    with open(os.path.join(results, "cubicCoupling.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    return {"sliding_cubic_coupling_max_abs_error_pct": round(max(errors), 4) if errors else None,
            "sliding_cubic_coupling_largest_coefficient": round(largest, 4)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default=HERE)
    out = parser.parse_args().out
    keys = compare(out)
    path = os.path.join(out, "results", "metrics.json")
    metrics = json.load(open(path)) if os.path.exists(path) else {}
    metrics.update(keys)
    with open(path, "w") as f:
        json.dump(metrics, f, indent=1, sort_keys=True)
        f.write("\n")
    for key, value in sorted(keys.items()):
        print(f"{key}: {value}")


if __name__ == "__main__":
    main()
