#!/usr/bin/python3
"""Summary of a sedimentingSpheroids run: results.md and pair.png from the body time series.

    summarise.py [CASE]     (default: the current directory)

Everything is read from the case: nu and g from constant/, the bodies (names, semi-axes,
densities) and the time series from postProcessing/immersedBodies/bodies.h5, the fluid density
from constant/immersedBodiesProperties. The surface gap between the two bodies at every stored
time comes from the project's `ellipsoidDistance` (dual method, 1e-6 of the equal-volume radius),
so the script needs the project's environment (etc/bashrc). Reported: the largest settling speed
of each body, the closest approach (gap and time), when the trailing body passes the leading
one while both fall (drafting-kissing-tumbling), when each body first touches the bottom, the wall and CPU time
of the solver. Needs Debian's python3-h5py, python3-numpy and python3-matplotlib
(/usr/bin/python3).
"""
import io
import math
import os
import subprocess
import sys

import h5py
import numpy as np

try:
    from caseSummary import read_entry, solver_time_row, write_results
except ImportError:  # applications/utilities/plotBodies is on PYTHONPATH through etc/bashrc
    sys.exit("summarise.py: caseSummary not found; source the project's etc/bashrc")


def rotation(q):
    """Rotation matrices R(q) (body to world) of quaternions q[..., (w, x, y, z)]."""
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
        np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
        np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1)], -2)


def tilt_degrees(q):
    """Angle between the symmetry axis R(q) e_x and the vertical, folded into 0-90."""
    ez = rotation(q)[..., 2, 0]
    return np.degrees(np.arccos(np.clip(np.abs(ez), 0, 1)))


def bottom_gap(c, q, axes):
    """Height of each body's lowest point: z - sqrt(sum_i a_i^2 R_zi^2)."""
    rz = rotation(q)[..., 2, :]
    return c[..., 2] - np.sqrt(np.sum((axes * rz) ** 2, axis=-1))


def pair_gaps(c, q, axes, eps):
    """Signed surface distance of bodies 0 and 1 at every row (ellipsoidDistance, dual)."""
    rows = ["a1,b1,c1,x1,y1,z1,qw1,qx1,qy1,qz1,a2,b2,c2,x2,y2,z2,qw2,qx2,qy2,qz2"]
    for k in range(len(c)):
        v = list(axes[0]) + list(c[k, 0]) + list(q[k, 0]) + list(axes[1]) + list(c[k, 1]) + list(q[k, 1])
        rows.append(",".join(repr(float(x)) for x in v))
    try:
        out = subprocess.run(["ellipsoidDistance", "-method", "dual", "-eps", repr(eps), "-"],
                             input="\n".join(rows) + "\n", capture_output=True, text=True, check=True)
    except (OSError, subprocess.CalledProcessError) as e:
        sys.exit(f"summarise.py: ellipsoidDistance failed ({e}); source the project's etc/bashrc")
    data = np.genfromtxt(io.StringIO(out.stdout), delimiter=",", names=True, dtype=None, encoding=None)
    return np.atleast_1d(data["distance"]).astype(float)


def first_time(t, mask):
    k = np.flatnonzero(mask)
    return f"t = {t[k[0]]:.3f} s" if len(k) else "not in this run"


def main():
    case = sys.argv[1] if len(sys.argv) > 1 else "."
    nu = float(read_entry(case, "constant/transportProperties", r"^nu\s+([0-9.eE+-]+)\s*;")[0])
    rho_f = float(read_entry(case, "constant/immersedBodiesProperties",
                             r"^fluidDensity\s+([0-9.eE+-]+)\s*;")[0])
    g = abs(float(read_entry(case, "constant/g", r"^value\s*\(\s*\S+\s+\S+\s+(\S+)\s*\)")[0]))
    with h5py.File(os.path.join(case, "postProcessing/immersedBodies/bodies.h5"), "r",
                   locking=False) as f:
        n = min(len(f[k]) for k in ("time", "centre", "velocity", "orientation", "collisionForce"))
        t = f["time"][:n]
        c = f["centre"][:n]
        v = f["velocity"][:n]
        q = f["orientation"][:n]
        fc = f["collisionForce"][:n]
        names = [x.decode() if isinstance(x, bytes) else str(x) for x in f["bodyNames"][()]]
        axes = f["semiAxes"][()]
        rho_p = f["density"][()]
    if len(names) != 2:
        sys.exit(f"summarise.py: the case has {len(names)} bodies, this summary is for two")
    d = 2 * np.prod(axes, axis=1) ** (1 / 3)  # equal-volume diameters
    D = float(d.min())
    galileo = math.sqrt(abs(rho_p[0] / rho_f - 1) * g * d[0] ** 3) / nu
    gap = pair_gaps(c, q, axes, 1e-6 * D / 2)
    dz = c[:, 1, 2] - c[:, 0, 2]           # trailing above leading: > 0
    above = bottom_gap(c, q, axes)           # N x 2
    w = -v[:, :, 2]
    kmin = int(np.argmin(gap))
    rows = [("equal-volume diameter D, Galileo number sqrt((rho_p/rho_f - 1) g D^3)/nu",
             f"{D * 1e3:.2f} mm, {galileo:.1f}"),
            ("simulated time", f"{t[-1]:.3f} s ({len(t) - 1} steps)")]
    for b, name in enumerate(names):
        k = int(np.argmax(w[:, b]))
        rows.append((f"{name}: largest settling speed (Re = U D/nu)",
                     f"{w[k, b] * 1e3:.1f} mm/s ({w[k, b] * d[b] / nu:.1f}) at t = {t[k]:.3f} s"))
    rows += [("gap between the bodies at the start", f"{gap[0] / D:.2f} D"),
             ("closest approach (gap)", f"{gap[kmin] / D:.4f} D at t = {t[kmin]:.3f} s"),
             ("gap below 0.1 D (kissing) from", first_time(t, gap < 0.1 * D)),
             # while both are still off the bottom: bodies resting side by side
             # on it are at the same height (their centres may cross by a hair)
             (f"{names[1]} passes {names[0]} (tumbling) at",
              first_time(t, (dz < 0) & np.all(above > 0, axis=1))),
             ("tilt from the vertical at the closest approach",
              f"{tilt_degrees(q[kmin, 0]):.0f} / {tilt_degrees(q[kmin, 1]):.0f} deg")]
    for b, name in enumerate(names):
        rows.append((f"{name}: first contact with the bottom", first_time(t, above[:, b] <= 0)))
    rows.append(("horizontal distance of the centres at the end",
                 f"{np.hypot(*(c[-1, 1, :2] - c[-1, 0, :2])) / D:.2f} D"))
    row = solver_time_row(case)
    if row:
        rows.append(row)
    write_results(case, rows)
    plot_pair(os.path.join(case, "pair.png"), t, gap / D, dz / D, fc, names)


def plot_pair(path, t, gap, dz, fc, names):
    """pair.png: gap and height difference in D, collision force of each body."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(3, 1, figsize=(7, 8), sharex=True)
    ax[0].plot(t, gap)
    ax[0].set_ylabel("gap between the bodies / D")
    ax[0].set_ylim(bottom=min(0.0, float(np.min(gap))) - 0.05)
    ax[1].plot(t, dz)
    ax[1].axhline(0, color="0.6", lw=0.8)
    ax[1].set_ylabel(f"z({names[1]}) - z({names[0]}) / D")
    for b, name in enumerate(names):
        ax[2].plot(t, np.linalg.norm(fc[:, b], axis=1), label=name)
    ax[2].set_ylabel("|collision force| (N)")
    ax[2].set_xlabel("t (s)")
    ax[2].legend()
    for a in ax:
        a.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


if __name__ == "__main__":
    main()
