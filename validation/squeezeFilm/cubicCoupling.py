#!/usr/bin/python3
"""The ln(1/h0) coupling of normal and tangential motion from the gap's cubic terms: a
closed form against the Reynolds numerics of slidingFilm.py (validation/squeezeFilm, see
README.md, "The coupling from the gap's cubic terms").

    cubicCoupling.py [--out DIR]

Reads DIR/results/sliding.csv (slidingFilm.py run) and writes DIR/results/cubicCoupling.md,
DIR/results/cubicCoupling.png and the sliding_cubic_* keys of DIR/results/metrics.json (the
other keys kept); slidingFilm.py plot does the same.

Where the closest points are not vertices of the surfaces, the gap is
h = h0 + t.K t/2 + Gamma(t, t, t)/6 with Gamma = C1 + C2, C_k the third derivatives of the
surfaces (each for its own outward normal m_k: for the ellipsoid (y - c).A (y - c) = 1 at
the point y, g = A (y - c), b = P A m, C(t, t, t) = -3 (t.A t)(b.t)/|g|^2). To first order
in Gamma, a normal approach at the speed V (body 1 towards body 2) gives body 1 the
tangential force and the moment about its closest point, per ln(1/h0),

    F1 = pi mu R V [3/(k1 + k2) D:K^-1 + (S2 - S1) j/2],      D = C2 - C1,
    j_m = 36/(k1 + k2) M_mm [-(7 k_m + 2 k_o) Gamma_mmm/(6 k_m^2) - (k_m + 2 k_o) Gamma_moo/(2 k_m k_o)],
    T1 = -pi mu R V j x n - 12 pi mu R V/(k1 + k2) [(S1 K^-1)_21 - (S1 K^-1)_12] n,

in the principal axes of K (o the other axis, M_mm = 1/(3 k_m + 2 k_o), e1 x e2 = n for
the last term's components): the squeeze pressure p0 on the cubic slopes of the surfaces,
and the odd pressure the cubic terms add to it (from the adjoint of the sliding problem,
whose solution is the paraboloid law's pressure) on the paraboloid's slopes; the twist
(the moment about n) is the squeeze pressure on the slope of body 1, -S1 t, where the
principal axes of S1 are not K's. By the symmetry of the film's resistance, a motion of
body 1 that does not move p1 along n (velocity U of c1, angular velocity Omega) has the
normal force F.n = F1 . U + (T1 + (p1 - c1) x F1) . Omega.

Compared (compare()) with the Reynolds numerics of every configuration of slidingFilm.py:
the approach's tangential force and torque about p1, and the normal force of each of its
motions (translations along e1, e2, rotations about e1, e2 and n through c1: the last one
the twist's reciprocal).
"""
import argparse
import json
import math
import os

import numpy as np

from slidingFilm import MOTIONS, SLIDING_CASES, motion_frame, rigid_motion
from squeezeFilm import HERE, MU, NORMAL, Contact, Plane, md_header, md_row
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


# the closed form's unit pi mu R V: a coefficient below VANISHING of it, measured and in
# closed form, is compared in absolute terms (a coupling that vanishes by symmetry)
VANISHING = 1e-2
# the coefficients of the twist: the approach's moment about n (about p1) and, its
# reciprocal, the normal force of the rotation about n (through c1)
TWIST = ("approach_Tn", "rotation_n")
# the coefficients in the order of the table
ORDER = ("approach_Fe1", "approach_Fe2", "approach_Te1", "approach_Te2", "approach_Tn",
         *(m[0] for m in MOTIONS))


def closed_form_coefficients(contact, frame):
    """{coefficient: closed-form value}: the approach's tangential force and torque about p1,
    and the normal force of each motion of MOTIONS (the approach's loads through the
    symmetry of the film's resistance: F.v + T_c1.Omega, T_c1 the moment about c1 of the
    approach's tangential force and torque)."""
    force, moment, torque = approach_loads(contact)
    values = {"approach_Fe1": force @ frame[:, 0], "approach_Fe2": force @ frame[:, 1],
              "approach_Te1": moment @ frame[:, 0], "approach_Te2": moment @ frame[:, 1],
              "approach_Tn": moment @ frame[:, 2]}
    for motion in MOTIONS:
        velocity, omega = rigid_motion(contact, motion, frame)
        values[motion[0]] = force @ velocity + torque @ omega
    return values


def measured_coefficients(rows, name, suffix):
    """{coefficient: ln(1/h0) coefficient of sliding.csv} (suffix: "num" the slope on the
    base grid, "num_extrapolated" the fit on the grid x2): the approach's force and torque
    about p1, the normal force of each motion."""
    first = rows[(name, MOTIONS[0][0])]
    values = {f"approach_{c}": first[f"approach_{c}_{suffix}"]
              for c in ("Fe1", "Fe2", "Te1", "Te2", "Tn")}
    for motion in MOTIONS:
        values[motion[0]] = rows[(name, motion[0])][f"Fn_{suffix}"]
    return {k: None if v in ("", None) else float(v) for k, v in values.items()}


def compare(out):
    results = os.path.join(out, "results")
    rows = rows_by(read_csv(os.path.join(results, "sliding.csv"), missing_ok=False))
    table, points = [], []
    errors, errors_extrapolated, twist_errors, vanishing = [], [], [], []
    per_configuration = {}
    largest = 0.0
    for name, label, body1, body2 in SLIDING_CASES:
        if (name, MOTIONS[0][0]) not in rows:
            continue
        contact = Contact(body1, body2, 1e-4)
        frame = motion_frame(contact)
        unit = math.pi * MU * contact_radius(contact)
        predicted = closed_form_coefficients(contact, frame)
        measured = measured_coefficients(rows, name, "num")
        extrapolated = measured_coefficients(rows, name, "num_extrapolated")
        for key, value in predicted.items():
            num, extra = measured[key], extrapolated[key]
            largest = max(largest, abs(num))
            err = value - num
            if max(abs(num), abs(value)) > VANISHING * unit:
                pct = 100.0 * err / abs(num)
                errors.append(abs(pct))
                points.append((label, key, num, value, pct))
                per_configuration.setdefault(name, []).append(abs(pct))
                if key in TWIST:
                    twist_errors.append(abs(pct))
                error = f"{pct:+.3f} %"
                if extra is not None:
                    pct_extra = 100.0 * (value - extra) / abs(extra)
                    errors_extrapolated.append(abs(pct_extra))
                    error_extra = f"{pct_extra:+.3f} %"
            else:
                vanishing.append(abs(err))
                error = f"{err:+.1e} (abs)"
                if extra is not None:
                    error_extra = f"{value - extra:+.1e} (abs)"
            table.append([label, key, f"{num:+.4f}", "-" if extra is None else f"{extra:+.4f}",
                          f"{value:+.4f}", error, "-" if extra is None else error_extra])
    lines = ["# The coupling of normal and tangential motion from the gap's cubic terms", "",
             "Written by `cubicCoupling.py` from `sliding.csv` (`slidingFilm.py run`): the "
             "ln(1/h0) coefficients of the tangential force on body 1 and of its torque about "
             "p1 under a unit normal approach (approach_Fe1, approach_Fe2, approach_Te1, "
             "approach_Te2, approach_Tn) and of the normal force F.n under each unit motion of "
             "slidingFilm.py (translation along e1, e2, rotation about e1, e2, n through c1), "
             "measured (Reynolds, exact gap; num: the slope between h0 = 1e-4 and 1e-5; "
             "extrap.: A of A ln(1/h0) + B + C h0 ln(1/h0) through 1e-3, 1e-4, 1e-5 on the "
             "grid x2) and from the closed form of cubicCoupling.py. Errors relative to the "
             "measured value, absolute where both are below "
             f"{VANISHING:g} pi mu R (a coupling that vanishes by symmetry).", "",
             *md_header(["configuration", "coefficient", "num", "extrap.", "closed form",
                         "error vs num", "error vs extrap."])]
    lines += [md_row(r) for r in table]
    with open(os.path.join(results, "cubicCoupling.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    if points:
        plot_coupling(os.path.join(results, "cubicCoupling.png"), points)

    def worst(values):
        return round(max(values), 4) if values else None

    keys = {"sliding_cubic_coupling_max_abs_error_pct": worst(errors),
            "sliding_cubic_coupling_max_abs_error_pct_extrapolated": worst(errors_extrapolated),
            "sliding_cubic_twist_max_abs_error_pct": worst(twist_errors),
            "sliding_cubic_vanishing_max_abs_error": (float(f"{max(vanishing):.3g}")
                                                      if vanishing else None),
            "sliding_cubic_coupling_largest_coefficient": round(largest, 4)}
    for name, values in per_configuration.items():
        keys[f"sliding_cubic_coupling_max_abs_error_pct_{name}"] = worst(values)
    return {k: v for k, v in keys.items() if v is not None}


def plot_coupling(path, points):
    """Closed form against measured (num) for every coefficient that does not vanish, and
    the relative error; one marker per configuration, filled for the twist."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    labels = []
    for p in points:
        if p[0] not in labels:
            labels.append(p[0])
    markers = "osD^v<>ph"
    colours = plt.cm.tab10(np.arange(len(labels)) % 10)
    order = [k for k in ORDER if k not in TWIST] + list(TWIST)
    keys = [k for k in order if any(p[1] == k for p in points)]
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(13, 5.2))
    for i, label in enumerate(labels):
        mine = [p for p in points if p[0] == label]
        for twist in (False, True):
            sel = [p for p in mine if (p[1] in TWIST) == twist]
            if not sel:
                continue
            style = dict(marker=markers[i % len(markers)], color=colours[i], ls="none", ms=7,
                         mfc=colours[i] if twist else "none",
                         label=label + (" (twist)" if twist else ""))
            ax1.plot([p[2] for p in sel], [p[3] for p in sel], **style)
            ax2.plot([keys.index(p[1]) for p in sel], [p[4] for p in sel], **style)
    low = min(min(p[2], p[3]) for p in points)
    high = max(max(p[2], p[3]) for p in points)
    ax1.plot([low, high], [low, high], "k-", lw=0.8)
    ax1.set_xlabel("measured (Reynolds, exact gap): ln(1/h0) coefficient")
    ax1.set_ylabel("closed form")
    ax1.set_title("coupling of normal and tangential motion, per ln(1/h0)")
    for limit in (-0.5, 0.5):
        ax2.axhline(limit, color="k", lw=0.8, ls="--")
    ax2.axhline(0.0, color="k", lw=0.8)
    ax2.set_xticks(range(len(keys)))
    ax2.set_xticklabels(keys, rotation=45, ha="right", fontsize=8)
    ax2.set_ylabel("(closed form - measured)/|measured| [%]")
    ax2.set_title("relative error (dashed: 0.5 %)")
    ax2.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.02, 0.5))
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def contact_radius(contact):
    """R = 1/sqrt(k1 k2) of the gap's paraboloid."""
    return 1.0 / math.sqrt(contact.k[0] * contact.k[1])


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
