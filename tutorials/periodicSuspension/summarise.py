#!/usr/bin/python3
"""Summary of a periodicSuspension run: results.md, settling.png, orientation.png and
clustering.png from the body time series and the solver log.

    summarise.py [CASE]     (default: the current directory)

Everything is read from the case: nu (constant/transportProperties), g (constant/g), the fluid
density (constant/immersedBodiesProperties), the box (L in equal-volume diameters and the scale
D of system/blockMeshDict), the bodies and their time series
(postProcessing/immersedBodies/bodies.h5) and, from log.immersedSpheroidFoam, the meanFlow
lines (the mean pressure gradient and the mean velocity over the box), the largest overlap of
the collision lines and the solver's time.

"Second half": the rows with t >= t_end/2. Averages over time are weighted by the time step.
The settling speed is -<v_z>, <.> the mean over the bodies, in the frame of zero volume flux
(the box's mean velocity is held at zero): the frame of batch sedimentation, where
Richardson-Zaki gives u = u_t (1 - phi)^n, here with Rowe's (1987) n(Re_t) and u_t the
terminal velocity of the equal-volume sphere from the Schiller-Naumann drag law (an estimate:
a prolate spheroid broadside-on has more drag). The orientation is the angle between each
body's symmetry axis (its body x axis, R(q) e_x) and gravity, folded into 0-90 degrees (90:
broadside-on; for random orientations its density is sin(theta), mean 57.3 degrees). The pair
distribution g(r) comes from the minimum-image distances of the centres (r < L/2), split
into pairs within 60 degrees of the vertical and the others (equal solid angles); beside it, a
side view of the bodies in a slab through the middle of the box at the last time. The largest
hydrodynamic force on a body is given against the body's net weight (about 1 when it settles
steadily).

Needs the project's environment (etc/bashrc: caseSummary) and Debian's python3-h5py,
python3-numpy and python3-matplotlib (/usr/bin/python3). Exit status 0, or 1 with a message.
"""
import math
import os
import re
import sys

try:
    import h5py
    import numpy as np
except ImportError as e:
    sys.exit(f"summarise.py: {e}; run it with Debian's /usr/bin/python3")

try:
    from caseSummary import read_entry, solver_time_row, write_results
except ImportError:  # applications/utilities/plotBodies is on PYTHONPATH through etc/bashrc
    sys.exit("summarise.py: caseSummary not found; source the project's etc/bashrc")

NUMBER = r"([-+0-9.eE]+)"
MEAN_FLOW = re.compile(r"meanFlow zeroFlux: mean pressure gradient \(([^)]*)\) Pa/m \(net weight "
                       r"\(([^)]*)\), flux hold \(([^)]*)\)\), mean velocity of the last solve "
                       r"\(([^)]*)\)")
OVERLAP = re.compile(r"^collisions: .*max overlap " + NUMBER + r" a_min")
SERIES = ("time", "centre", "unwrappedCentre", "velocity", "orientation", "hydroForce")


def fail(message):
    sys.exit(f"summarise.py: {message}")


def vector(text):
    return np.array([float(x) for x in text.split()])


def read_series(case):
    path = os.path.join(case, "postProcessing", "immersedBodies", "bodies.h5")
    if not os.path.exists(path):
        fail(f"{path}: no such file (did the run finish?)")
    try:
        with h5py.File(path, "r", locking=False) as f:
            missing = [k for k in SERIES + ("semiAxes", "density") if k not in f]
            if missing:
                fail(f"{path}: no dataset {', '.join(missing)} (a periodic-domain series has "
                     f"unwrappedCentre)")
            rows = min(f[k].shape[0] for k in SERIES)
            data = {k: np.asarray(f[k][:rows], float) for k in SERIES}
            data["semiAxes"] = np.asarray(f["semiAxes"][()], float)
            data["density"] = np.asarray(f["density"][()], float)
    except OSError as e:
        fail(f"{path}: not readable ({e})")
    if rows < 4:
        fail(f"{path}: {rows} rows; too few to summarise")
    return data


def read_log(case):
    """(net-weight gradients, mean velocities, largest overlap) from the solver log, or None."""
    path = os.path.join(case, "log.immersedSpheroidFoam")
    if not os.path.exists(path):
        return None
    weights, means, overlap = [], [], 0.0
    with open(path, errors="replace") as f:
        for line in f:
            m = MEAN_FLOW.search(line)
            if m:
                weights.append(vector(m.group(2)))
                means.append(vector(m.group(4)))
                continue
            m = OVERLAP.search(line)
            if m:
                overlap = max(overlap, float(m.group(1)))
    return np.array(weights), np.array(means), overlap


def rotation_axis_z(q):
    """z component of the symmetry axis R(q) e_x of quaternions q[..., (w, x, y, z)]."""
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    return 2 * (x * z - w * y)


def time_mean(t, y):
    """Mean and standard deviation of y(t) weighted by the time step (trapezoidal rule)."""
    if len(t) < 2 or t[-1] <= t[0]:
        return float(np.mean(y)), float(np.std(y))
    span = t[-1] - t[0]
    mean = np.trapz(y, t) / span
    return float(mean), float(math.sqrt(max(np.trapz((y - mean) ** 2, t) / span, 0.0)))


def schiller_naumann_terminal(galileo):
    """Re_t of a sphere settling at Galileo number Ga: Ga^2 = (3/4) C_D(Re) Re^2 with
    C_D = 24/Re (1 + 0.15 Re^0.687), by bisection (Re < 800, the law's range)."""
    lo, hi = 1e-8, 800.0
    for _ in range(200):
        re_ = math.sqrt(lo * hi)
        if 18 * re_ * (1 + 0.15 * re_ ** 0.687) < galileo ** 2:
            lo = re_
        else:
            hi = re_
    return math.sqrt(lo * hi)


def rowe(re_t):
    return (4.7 + 0.41 * re_t ** 0.75) / (1 + 0.175 * re_t ** 0.75)


def pair_distribution(c, L, edges):
    """g(r) of the centres c (rows x B x 3) in the periodic cube of side L from the
    minimum-image distances: all pairs, pairs within 60 degrees of the vertical, the others."""
    B = c.shape[1]
    i, j = np.triu_indices(B, 1)
    counts = np.zeros((3, len(edges) - 1))
    for row in c:
        d = row[j] - row[i]
        d -= L * np.round(d / L)
        r = np.linalg.norm(d, axis=1)
        vertical = np.abs(d[:, 2]) > 0.5 * r
        counts[0] += np.histogram(r, edges)[0]
        counts[1] += np.histogram(r[vertical], edges)[0]
        counts[2] += np.histogram(r[~vertical], edges)[0]
    shell = 4 / 3 * math.pi * (edges[1:] ** 3 - edges[:-1] ** 3)
    ideal = len(c) * len(i) * shell / L ** 3          # uniform pairs per bin over the rows
    return counts[0] / ideal, counts[1] / (0.5 * ideal), counts[2] / (0.5 * ideal)


def title_line(n_bodies, ar, phi, galileo, ratio, cells):
    return (f"periodicSuspension: {n_bodies} prolate spheroids (Ar {ar:.3g}) settling in a "
            f"triply periodic box\nsolid fraction {phi:.3f}, Ga {galileo:.1f}, "
            f"rho_p/rho_f {ratio:.3g}, {cells:.3g} cells per D")


def main(argv):
    if len(argv) > 2 or (len(argv) == 2 and argv[1].startswith("-")):
        sys.exit("usage: summarise.py [CASE]")
    case = argv[1] if len(argv) == 2 else "."
    if not os.path.isdir(case):
        fail(f"{case}: no such folder")
    for path in ("constant/transportProperties", "constant/g", "constant/immersedBodiesProperties",
                 "system/blockMeshDict"):
        if not os.path.exists(os.path.join(case, path)):
            fail(f"{os.path.join(case, path)}: no such file (not a periodicSuspension case?)")
    nu = float(read_entry(case, "constant/transportProperties", r"^nu\s+" + NUMBER + r"\s*;")[0])
    rho_f = float(read_entry(case, "constant/immersedBodiesProperties",
                             r"^fluidDensity\s+" + NUMBER + r"\s*;")[0])
    gvec = vector(read_entry(case, "constant/g", r"^value\s*\(([^)]*)\)")[0])
    g = float(np.linalg.norm(gvec))
    scale = float(read_entry(case, "system/blockMeshDict", r"^scale\s+" + NUMBER + r"\s*;")[0])
    L_D = float(read_entry(case, "system/blockMeshDict", r"^L\s+" + NUMBER + r"\s*;")[0])
    n_cells = int(read_entry(case, "system/blockMeshDict", r"^n\s+([0-9]+)\s*;")[0])
    if g <= 0 or abs(gvec[2]) < (1 - 1e-12) * g:
        fail(f"constant/g: gravity {gvec} is not along z")
    L = L_D * scale

    s = read_series(case)
    t, c, v = s["time"], s["centre"], s["velocity"]
    axes, density = s["semiAxes"], s["density"]
    if not (np.all(np.isfinite(c)) and np.all(np.isfinite(v))):
        fail("non-finite body states in bodies.h5")
    packing = os.path.join(case, "constant", "suspension.csv")
    if os.path.exists(packing):
        with open(packing) as f:
            m = re.search(r"^# boxLength\s+" + NUMBER, f.read(), re.M)
        if m and abs(float(m.group(1)) - L) > 1e-9 * L:
            fail(f"{packing}: box {float(m.group(1)):g} m, system/blockMeshDict {L:g} m "
                 f"(the packing is not of this mesh: run Allrun again)")
    if c.min() < 0 or c.max() > L * (1 + 1e-12):
        fail(f"body centres {c.min():g} .. {c.max():g} m outside the box [0, {L:g}) m of "
             f"system/blockMeshDict")
    n_bodies = c.shape[1]
    volume = 4 / 3 * math.pi * np.prod(axes, axis=1)
    D = (6 * volume[0] / math.pi) ** (1 / 3)
    ar = axes[0, 0] / axes[0, 1]
    phi = volume.sum() / L ** 3
    ratio = float(density[0] / rho_f)
    if ratio <= 1:
        fail(f"density ratio {ratio:g}: the bodies do not settle")
    galileo = math.sqrt((ratio - 1) * g * D ** 3) / nu
    re_t = schiller_naumann_terminal(galileo)
    u_t = re_t * nu / D
    n_rz = rowe(re_t)
    u_rz = u_t * (1 - phi) ** n_rz

    late = t >= t[-1] / 2
    if late.sum() < 2:
        fail(f"{late.sum()} rows in the second half of the run (t {t[-1]:.3g} s)")
    tl = t[late]
    down = -np.sign(gvec[2])                        # +1: gravity along -z
    w = down * -v[:, :, 2].mean(axis=1)            # settling speed, positive along g
    w_mean, w_sd = time_mean(tl, w[late])
    rms_z = np.sqrt(((v[:, :, 2] - v[:, :, 2].mean(axis=1, keepdims=True)) ** 2).mean(axis=1))
    vh = v[:, :, :2] - v[:, :, :2].mean(axis=1, keepdims=True)
    rms_h = np.sqrt((vh ** 2).sum(axis=2).mean(axis=1) / 2)
    rz_mean, rh_mean = time_mean(tl, rms_z[late])[0], time_mean(tl, rms_h[late])[0]
    settled = down * -(s["unwrappedCentre"][-1, :, 2] - s["unwrappedCentre"][0, :, 2]).mean()
    speed = np.linalg.norm(v, axis=2)
    # the hydrodynamic force over the net weight: about 1 for a body settling steadily, a few
    # in a close encounter
    force = np.linalg.norm(s["hydroForce"], axis=2) / ((density - rho_f) * volume * g)
    force_row = int(np.argmax(force.max(axis=1)))
    strong = int(np.sum(force.max(axis=1) > 5))

    theta = np.degrees(np.arccos(np.clip(np.abs(rotation_axis_z(s["orientation"][late])), 0, 1)))

    # g(r) over at most 200 rows of the second half (evenly spaced), and of the packing
    rows = np.flatnonzero(late)
    rows = rows[np.linspace(0, len(rows) - 1, min(len(rows), 200)).round().astype(int)]
    edges = np.linspace(0, L / 2, max(int(L / 2 / (0.1 * D)), 5) + 1)
    g_all, g_vert, g_hor = pair_distribution(c[rows], L, edges)
    g_start = pair_distribution(c[:1], L, edges)[0]
    near = (edges[:-1] >= D - 1e-12) & (edges[1:] <= 2 * D + 1e-12)
    shell = edges[1:] ** 3 - edges[:-1] ** 3

    def near_mean(gr):
        return float(np.sum(gr[near] * shell[near]) / np.sum(shell[near])) if near.any() else math.nan

    results = [
        ("bodies", f"{n_bodies} prolate spheroids, Ar {ar:.3g}, semi-axes {axes[0, 0] * 1e3:.4g} x "
                   f"{axes[0, 1] * 1e3:.4g} mm, equal-volume D {D * 1e3:.4g} mm"),
        ("solid fraction", f"{phi:.4f}"),
        ("box", f"{L_D:g} D = {L * 1e3:.4g} mm a side, periodic along x, y and z; {n_cells}^3 "
                f"cells, {n_cells / L_D:.3g} per D"),
        ("density ratio", f"{ratio:.4g}"),
        ("Galileo number sqrt((rho_p/rho_f - 1) g D^3)/nu", f"{galileo:.2f}"),
        ("single-body terminal velocity u_t, estimate (equal-volume sphere, Schiller-Naumann drag)",
         f"{u_t * 1e3:.1f} mm/s, Re_t = {re_t:.1f}"),
        ("Richardson-Zaki u_t (1 - phi)^n, n from Rowe (1987)",
         f"{u_rz * 1e3:.1f} mm/s, n = {n_rz:.3f}"),
        ("simulated time, steps", f"{t[-1]:.4g} s, {len(t) - 1} steps; second half from "
                                  f"{t[-1] / 2:.4g} s"),
        ("mean settling speed over the second half (mean +- sd over time), Re",
         f"{w_mean * 1e3:.2f} +- {w_sd * 1e3:.2f} mm/s, Re = {w_mean * D / nu:.2f}"),
        ("mean settling speed against u_t and against Richardson-Zaki",
         f"{w_mean / u_t:.3f} u_t; {100 * (w_mean / u_rz - 1):+.1f} % against Richardson-Zaki"),
        ("velocity fluctuation over the bodies, second half (rms vertical, horizontal)",
         f"{rz_mean * 1e3:.2f}, {rh_mean * 1e3:.2f} mm/s"),
        ("mean distance settled (unwrapped centres)", f"{settled / D:.2f} D"),
        ("angle of the symmetry axis to gravity, second half (mean; share above 60 deg)",
         f"{theta.mean():.1f} deg; {np.mean(theta > 60):.2f} (random orientations: 57.3 deg; "
         f"0.50)"),
        ("pair distribution g(r) over 1-2 D, second half (all, vertical, horizontal pairs)",
         f"{near_mean(g_all):.2f}, {near_mean(g_vert):.2f}, {near_mean(g_hor):.2f} (packing at "
         f"the start: {near_mean(g_start):.2f})"),
        ("largest body speed", f"{speed.max() * 1e3:.1f} mm/s = {speed.max() / u_t:.2f} u_t"),
        ("largest hydrodynamic force on a body, against its net weight (rho_p - rho_f) V_p g",
         f"{force.max():.2f} at t = {t[force_row]:.4g} s; {strong} of {len(t)} rows above 5"),
    ]

    expected = (density - rho_f) @ volume * gvec / L ** 3    # (rho_p - rho_f) sum V_p g / V_box
    log = read_log(case)
    if log is None or len(log[0]) == 0:
        why = ("no solver log" if log is None
               else "no meanFlow zeroFlux lines in log.immersedSpheroidFoam")
        results += [("mean pressure gradient: logged net weight against (rho_p - rho_f) sum V_p g "
                     "/ V_box", f"{why}; expected {expected[2]:.6g} Pa/m along z"),
                    ("largest magnitude of the mean velocity over the box (solver log)", why),
                    ("largest overlap between bodies (solver log)",
                     "no solver log" if log is None else f"{log[2]:.3g} of the smallest semi-axis")]
    else:
        weights, means, overlap = log
        logged = weights[-1]
        error = np.abs(weights - expected).max() / abs(expected[2])
        worst = np.linalg.norm(means, axis=1).max()
        results += [("mean pressure gradient: logged net weight against (rho_p - rho_f) sum V_p g "
                     "/ V_box", f"{logged[2]:.6g} against {expected[2]:.6g} Pa/m along z "
                                f"(largest difference over {len(weights)} steps: {error:.1e} of it)"),
                    ("largest magnitude of the mean velocity over the box (solver log)",
                     f"{worst * 1e3:.3g} mm/s = {worst / w_mean:.2g} of the mean settling speed"),
                    ("largest overlap between bodies (solver log)",
                     f"{overlap:.3g} of the smallest semi-axis")]
    row = solver_time_row(case)
    results.append(row if row else ("solver time", "no solver log"))
    write_results(case, results)

    title = title_line(n_bodies, ar, phi, galileo, ratio, n_cells / L_D)
    plot_settling(case, t, w, rms_z, rms_h, u_t, u_rz, w_mean, title)
    plot_orientation(case, theta, tl, title)
    plot_clustering(case, edges / D, g_all, g_vert, g_hor, g_start, c[-1], s["orientation"][-1],
                    axes, L, D, t, rows, title)


def figure(*args, **kwargs):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt.subplots(*args, **kwargs)


def plot_settling(case, t, w, rms_z, rms_h, u_t, u_rz, w_mean, title):
    fig, ax = figure(2, 1, figsize=(7.5, 6.5), sharex=True)
    ax[0].plot(t, w * 1e3, "C0-", label="mean settling speed -<v_z> over the bodies")
    ax[0].axhline(u_t * 1e3, color="k", ls="--", lw=1,
                  label=f"single body u_t, estimate (sphere): {u_t * 1e3:.1f} mm/s")
    ax[0].axhline(u_rz * 1e3, color="C3", ls=":", lw=1.5,
                  label=f"Richardson-Zaki (Rowe): {u_rz * 1e3:.1f} mm/s")
    ax[0].hlines(w_mean * 1e3, t[-1] / 2, t[-1], colors="C0", lw=3, alpha=0.6,
                 label=f"mean over the second half: {w_mean * 1e3:.1f} mm/s")
    ax[0].set_ylabel("settling speed (mm/s)")
    ax[0].legend(fontsize="small", loc="lower right")
    ax[1].plot(t, rms_z * 1e3, "C1-", label="vertical: rms over the bodies of v_z - <v_z>")
    ax[1].plot(t, rms_h * 1e3, "C2-", label="horizontal: rms of one horizontal component")
    ax[1].set_ylabel("velocity fluctuation (mm/s)")
    ax[1].set_xlabel("time t (s)")
    ax[1].legend(fontsize="small", loc="upper left")
    for a in ax:
        a.grid(alpha=0.3)
        a.axvspan(t[-1] / 2, t[-1], color="0.9", zorder=0)
    ax[0].set_title(title, fontsize="medium")
    fig.tight_layout()
    fig.savefig(os.path.join(case, "settling.png"), dpi=110)


def plot_orientation(case, theta, tl, title):
    fig, ax = figure(figsize=(6.5, 4.5))
    ax.hist(theta.ravel(), bins=np.linspace(0, 90, 19), density=True, color="C0", alpha=0.7,
            label=f"bodies, t = {tl[0]:.3g}-{tl[-1]:.3g} s (mean {theta.mean():.1f} deg)")
    x = np.linspace(0, 90, 200)
    ax.plot(x, np.sin(np.radians(x)) * math.pi / 180, "k--",
            label="random orientations: sin(theta) (mean 57.3 deg)")
    ax.set_xlabel("angle theta between the symmetry axis and gravity (deg; 90: broadside-on)")
    ax.set_ylabel("probability density (1/deg)")
    ax.set_xlim(0, 90)
    ax.grid(alpha=0.3)
    ax.legend(fontsize="small", loc="upper left")
    ax.set_title(title + "\norientation over the second half", fontsize="medium")
    fig.tight_layout()
    fig.savefig(os.path.join(case, "orientation.png"), dpi=110)


def side_view(ax, centres, orientations, semi_axes, L, D):
    """The outlines (exact silhouettes, plotBodies.outline) of the bodies whose centres lie in
    the slab |y - L/2| < D, seen along +y in the periodic box with their images across the x
    and z faces, coloured by depth; lengths in D. A slab, not the whole depth: at a solid
    fraction of 0.1 the bodies of a box deeper than a few D cover the whole view."""
    import matplotlib
    try:
        from plotBodies import outline
    except ImportError:  # applications/utilities/plotBodies is on PYTHONPATH through etc/bashrc
        fail("plotBodies not found; source the project's etc/bashrc")
    colour = matplotlib.colormaps["viridis"]
    depth = (centres[:, 1] - L / 2) / D
    slab = np.flatnonzero(np.abs(depth) < 1)
    for b in slab[np.argsort(-depth[slab])]:            # the nearest (smallest y) drawn last
        p = outline(centres[b], orientations[b], semi_axes[b], 0, 2)
        for sx in (-L, 0, L):
            for sz in (-L, 0, L):
                x, z = p[0] + sx, p[1] + sz
                if x.max() > 0 and x.min() < L and z.max() > 0 and z.min() < L:
                    ax.fill(x / D, z / D, facecolor=colour((depth[b] + 1) / 2), edgecolor="k",
                            lw=0.4)
    ax.set_xlim(0, L / D)
    ax.set_ylim(0, L / D)
    ax.set_aspect("equal")
    ax.set_xlabel("x / D")
    ax.set_ylabel("z / D (up; gravity along -z)")
    return len(slab)


def plot_clustering(case, r, g_all, g_vert, g_hor, g_start, centres, orientations, semi_axes, L,
                    D, t, rows, title):
    fig, ax = figure(1, 2, figsize=(11, 4.8), gridspec_kw={"width_ratios": [1.5, 1]})
    mid = 0.5 * (r[1:] + r[:-1])
    ax[0].plot(mid, g_start, color="0.6", lw=1, label="random packing at t = 0")
    ax[0].plot(mid, g_all, "k-", lw=1.5, label="all pairs")
    ax[0].plot(mid, g_vert, "C3-", lw=1, label="pairs within 60 deg of the vertical")
    ax[0].plot(mid, g_hor, "C0-", lw=1, label="the other pairs (nearer the horizontal)")
    ax[0].axhline(1, color="k", ls=":", lw=1)
    ax[0].set_xlabel("centre distance r / D (minimum image)")
    ax[0].set_ylabel("pair distribution function g(r)")
    ax[0].set_xlim(0, r[-1])
    ax[0].grid(alpha=0.3)
    ax[0].legend(fontsize="small")
    ax[0].set_title(f"g(r) over {len(rows)} rows of t = {t[rows[0]]:.3g}-{t[rows[-1]]:.3g} s",
                    fontsize="medium")
    shown = side_view(ax[1], centres, orientations, semi_axes, L, D)
    ax[1].set_title(f"side view at t = {t[-1]:.3g} s: the {shown} bodies with |y - L/2| < D\n"
                    f"(colour: depth, dark nearest)", fontsize="medium")
    fig.suptitle(title, fontsize="medium")
    fig.tight_layout()
    fig.savefig(os.path.join(case, "clustering.png"), dpi=110)


if __name__ == "__main__":
    main(sys.argv)
