#!/usr/bin/python3
"""Analysis of the fluidisedBed tutorial, in two steps (Allfunctions calls both):

    summarise.py terminal CASE U_IN   the single-body run in CASE (terminalVelocity/): its
                                      terminal velocity u_t = U_IN - v_z, averaged over the
                                      second half of the run, written to CASE/terminalVelocity
    summarise.py bed CASE             the bed: fluidisedBed.png, expansion.png, results.md
    summarise.py speeds CASE [UNTIL [ABOVE]]
                                      rows of the time series (up to t = UNTIL s) with a body
                                      faster than ABOVE m/s (default 0.15, about 2 u_t), and
                                      the largest body speed: the oscillation of bodies in
                                      near-contact (README, "Time step")

The bed height is H = 2 <z> (z of the body centres above the inlet; a uniform bed of height H
has <z> = H/2), the voidage eps = 1 - N V_p / (A H) with A the column's cross-section. Per
inflow stage the mean and standard deviation over the stage's second half are compared with
Richardson-Zaki, U/u_t = eps^n, the exponent from Rowe (1987) with Re_t = u_t D/nu and from
Khan & Richardson (1989) with the Archimedes number g D^3 (rho_p/rho_f - 1)/nu^2 (the wall
term d/D is left out: the side walls are free-slip); D is the equal-volume diameter. The
measured exponent is the least-squares slope of log(U/u_t) against log(eps) through the
origin (u_t measured), and with a free intercept (u_i/u_t).

Everything is read from the case (nu, the bodies, the inflow stages in constant/fluidisation,
the column from system/blockMeshDict). Needs the project's environment (etc/bashrc) and Debian's
python3-h5py, python3-numpy and python3-matplotlib (/usr/bin/python3).
"""
import math
import os
import re
import sys

import h5py
import numpy as np


try:
    from caseSummary import read_entry, solver_time_row, write_results
except ImportError:  # applications/utilities/plotBodies is on PYTHONPATH through etc/bashrc
    sys.exit("summarise.py: caseSummary not found; source the project's etc/bashrc")

NUMBER = r"([-+0-9.eE]+)"
G = 9.81


def read_bodies(case):
    """time, centres (N x B x 3), velocities, semi-axes (B x 3), densities (B)."""
    path = os.path.join(case, "postProcessing", "immersedBodies", "bodies.h5")
    if not os.path.exists(path):
        sys.exit(f"summarise.py: {path}: no such file (did the run finish?)")
    with h5py.File(path, "r", locking=False) as f:
        t = np.asarray(f["time"][()], float)
        rows = min(len(t), f["centre"].shape[0], f["velocity"].shape[0])
        return (t[:rows], np.asarray(f["centre"][:rows], float),
                np.asarray(f["velocity"][:rows], float), np.asarray(f["semiAxes"][()], float),
                np.asarray(f["density"][()], float))


def column(case):
    """(width x, width y, height) of the column from the vertices of system/blockMeshDict."""
    scale, = read_entry(case, "system/blockMeshDict", r"^scale\s+" + NUMBER + r"\s*;")
    x, y, z = read_entry(case, "system/blockMeshDict",
                         r"\(0 0 0\)\s*\(" + NUMBER + r" 0 0\)\s*\(\S+ " + NUMBER
                         + r" 0\)\s*\(0 \S+ 0\)\s*\(0 0 " + NUMBER + r"\)")
    return tuple(float(scale) * float(v) for v in (x, y, z))


def terminal(case, inflow):
    t, c, v, axes, _ = read_bodies(case)
    height = column(case)[2]
    D = 2 * float(np.prod(axes[0])) ** (1 / 3)
    late = t >= t[-1] / 2
    if late.sum() < 10:
        sys.exit(f"summarise.py: only {late.sum()} rows in the second half of the run "
                 f"(t {t[-1]:.3g} s): too short to measure a terminal velocity")
    z = c[late, 0, 2]
    if z.min() < 1.5 * D or z.max() > height - 1.5 * D:
        sys.exit(f"summarise.py: the body came within 1.5 D of the inlet or the outlet (z "
                 f"{z.min() / D:.2f} to {z.max() / D:.2f} D in a column of {height / D:.1f} D): "
                 f"set terminalVelocityGuess in constant/fluidisation nearer u_t "
                 f"(U_in {inflow} m/s, body velocity v_z {v[-1, 0, 2]:.3g} m/s)")
    vz = v[late, 0, 2]
    ut = inflow - vz.mean()
    spread = vz.max() - vz.min()
    # 4 digits: what the measurement resolves (serial and parallel runs agree to ~1e-6), and
    # the same inflow stages from both
    with open(os.path.join(case, "terminalVelocity"), "w") as out:
        out.write(f"{ut:.4g}\n")
    print(f"terminal velocity u_t = {ut:.5g} m/s = U_in {inflow:g} - v_z {vz.mean():.4g} m/s "
          f"(v_z varied by {spread:.2g} m/s over t {t[-1] / 2:.3g}-{t[-1]:.3g} s); "
          f"D {D * 1e3:.3g} mm")


def fast_rows(t, v, until=math.inf, above=0.15):
    """(rows up to t = until, of which rows with a body faster than `above`, largest speed)."""
    speed = np.linalg.norm(v[t <= until], axis=-1)
    return len(speed), int(np.sum(speed.max(axis=1) > above)), float(speed.max())


def speeds(case, until, above):
    t, _, v, _, _ = read_bodies(case)
    rows, fast, top = fast_rows(t, v, until, above)
    print(f"{case}: up to t = {min(until, t[-1]):.3g} s, {fast} of {rows} rows with a body faster "
          f"than {above:g} m/s; largest body speed {top:.3g} m/s")


def stage_list(case):
    text, = read_entry(case, "constant/fluidisation", r"^stages\s*\(([^)]*)\)")
    T, = read_entry(case, "constant/fluidisation", r"^stageTime\s+" + NUMBER)
    return [float(s) for s in text.split()], float(T)


def contacts_per_stage(case, stages, T):
    """Mean of the log's 'in contact now N' (body pairs and body-wall pairs) over the second
    half of each stage; None without the solver log (e.g. a reconstructed copy)."""
    log = os.path.join(case, "log.immersedSpheroidFoam")
    if not os.path.exists(log):
        return None
    sums, counts, time = [0] * len(stages), [0] * len(stages), 0.0
    with open(log) as f:
        for line in f:
            if line.startswith("Time = "):
                time = float(line.split()[2])
                continue
            m = re.search(r"in contact now (\d+)", line)
            if m:
                i = int(time // T)
                if 0 <= i < len(stages) and time >= (i + 0.5) * T:
                    sums[i] += int(m.group(1))
                    counts[i] += 1
    return [sums[i] / counts[i] if counts[i] else None for i in range(len(stages))]


def collision_work(case):
    """From the log's 'collisions:' lines over the whole run: the mean and the largest number
    of collision sub-steps per fluid step, and the largest 'max overlap' (of the smallest
    semi-axis); None without the solver log."""
    log = os.path.join(case, "log.immersedSpheroidFoam")
    if not os.path.exists(log):
        return None
    steps, overlap = [], 0.0
    with open(log) as f:
        for line in f:
            if not line.startswith("collisions: "):
                continue
            steps.append(int(line.split()[1]))
            m = re.search(r"max overlap (" + NUMBER[1:-1] + r") a_min", line)
            if m:
                overlap = max(overlap, float(m.group(1)))
    return (sum(steps) / len(steps), max(steps), overlap) if steps else None


def rowe(re_t):
    return (4.7 + 0.41 * re_t ** 0.75) / (1 + 0.175 * re_t ** 0.75)


def khan_richardson(archimedes):
    x = 0.043 * archimedes ** 0.57
    return (4.8 + 2.4 * x) / (1 + x)


def bed(case):
    t, c, v, axes, density = read_bodies(case)
    wx, wy, height = column(case)
    nu = float(read_entry(case, "constant/transportProperties", r"^nu\s+" + NUMBER)[0])
    rho_f = float(read_entry(case, "constant/immersedBodiesProperties",
                             r"^fluidDensity\s+" + NUMBER)[0])
    with open(os.path.join(case, "terminalVelocity", "terminalVelocity")) as f:
        ut = float(f.read())
    stages, T = stage_list(case)
    n_bodies = c.shape[1]
    volume = 4 / 3 * math.pi * np.prod(axes, axis=1)
    D = (6 * volume[0] / math.pi) ** (1 / 3)
    H = 2 * c[:, :, 2].mean(axis=1)
    eps = 1 - volume.sum() / (wx * wy * H)
    re_t = ut * D / nu
    archimedes = G * D ** 3 * (density[0] / rho_f - 1) / nu ** 2
    n_rowe, n_kr = rowe(re_t), khan_richardson(archimedes)

    rows = []
    means = []
    for i, s in enumerate(stages):
        window = (t >= (i + 0.5) * T) & (t <= (i + 1) * T)
        if window.sum() < 2:
            break
        means.append((s, eps[window].mean(), eps[window].std(), H[window].mean()))
    measured = np.array(means)
    fit = {}
    if len(measured) >= 2:
        x, y = np.log(measured[:, 1]), np.log(measured[:, 0])
        fit["origin"] = float(np.sum(x * y) / np.sum(x * x))
        slope, intercept = np.polyfit(x, y, 1)
        fit["free"] = (float(slope), float(math.exp(intercept)))

    rows += [("bodies", f"{n_bodies} spheroids, semi-axes {axes[0, 0] * 1e3:.3g} x "
                        f"{axes[0, 1] * 1e3:.3g} mm, D_eq {D * 1e3:.3g} mm, density ratio "
                        f"{density[0] / rho_f:.3g}"),
             ("column", f"{wx / D:.2f} x {wy / D:.2f} x {height / D:.1f} D, free-slip sides"),
             ("terminal velocity u_t (single body, measured)", f"{ut * 1e3:.2f} mm/s"),
             ("Re_t = u_t D/nu", f"{re_t:.2f}"),
             ("Archimedes number g D^3 (rho_p/rho_f - 1)/nu^2", f"{archimedes:.1f}"),
             ("n (Rowe 1987)", f"{n_rowe:.3f}"),
             ("n (Khan & Richardson 1989, no wall term)", f"{n_kr:.3f}")]
    if fit:
        rows += [("n measured (slope through u_t), against Rowe",
                  f"{fit['origin']:.3f}, {100 * (fit['origin'] / n_rowe - 1):+.1f} %"),
                 ("n measured (free fit), u_i/u_t", f"{fit['free'][0]:.3f}, "
                                                    f"{fit['free'][1]:.3f}")]
    contacts = contacts_per_stage(case, stages, T)
    for i, (s, e, sd, h) in enumerate(means):
        rows.append((f"stage U/u_t = {s:g}: voidage (mean +- sd), bed height",
                     f"{e:.4f} +- {sd:.4f} (RZ Rowe {s ** (1 / n_rowe):.4f}, "
                     f"{100 * (e / s ** (1 / n_rowe) - 1):+.1f} %; KR "
                     f"{s ** (1 / n_kr):.4f}), H = {h / D:.2f} D"))
        if contacts and contacts[i] is not None:
            rows.append((f"stage U/u_t = {s:g}: contacts (pairs and walls, mean)",
                         f"{contacts[i]:.1f}"))
    work = collision_work(case)
    if work:
        rows.append(("collision sub-steps per fluid step (mean, largest); largest overlap / a_min",
                     f"{work[0]:.2f}, {work[1]}; {work[2]:.4f}"))
    rows_all, fast, top = fast_rows(t, v)
    rows.append(("rows with a body faster than 0.15 m/s (about 2 u_t); largest body speed",
                 f"{fast} of {rows_all}; {top * 1e3:.0f} mm/s"))
    for name, sub in (("single body", "terminalVelocity"), ("bed", ".")):
        row = solver_time_row(os.path.join(case, sub))
        if row:
            rows.append((f"solver time, {name}", row[1]))
    write_results(case, rows)
    plot_history(case, t, H / D, eps, ut, stages, T, measured)
    plot_expansion(case, measured, n_rowe, n_kr, fit)


def plot_history(case, t, H, eps, ut, stages, T, measured):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(3, 1, figsize=(7, 8), sharex=True)
    inflow = np.array([stages[min(int(x // T), len(stages) - 1)] for x in t])
    ax[0].plot(t, inflow, "k-")
    ax[0].set_ylabel("inflow U / u_t")
    ax[1].plot(t, H, "C0-")
    ax[1].set_ylabel("bed height H = 2<z> (D)")
    ax[2].plot(t, eps, "C1-", lw=1)
    for i, (s, e, sd, _) in enumerate(measured):
        ax[2].hlines(e, (i + 0.5) * T, (i + 1) * T, colors="k", lw=2)
    ax[2].set_ylabel("voidage eps")
    ax[2].set_xlabel("t (s)")
    for a in ax:
        a.grid(alpha=0.3)
    ax[0].set_title(f"fluidised bed: stages of inflow, u_t = {ut * 1e3:.1f} mm/s "
                    "(black bars: stage means)")
    fig.tight_layout()
    fig.savefig(os.path.join(case, "fluidisedBed.png"), dpi=110)


def plot_expansion(case, measured, n_rowe, n_kr, fit):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4.5))
    e = np.linspace(0.45, 1, 100)
    ax.plot(e, e ** n_rowe, "C0-", label=f"Richardson-Zaki, n = {n_rowe:.2f} (Rowe)")
    ax.plot(e, e ** n_kr, "C2--", label=f"Richardson-Zaki, n = {n_kr:.2f} (Khan-Richardson)")
    if "origin" in fit:
        ax.plot(e, e ** fit["origin"], "C3:", label=f"fit, n = {fit['origin']:.2f}")
    if len(measured):
        ax.errorbar(measured[:, 1], measured[:, 0], xerr=measured[:, 2], fmt="ko",
                    label="this code (stage means +- sd)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("voidage eps")
    ax.set_ylabel("U / u_t")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(os.path.join(case, "expansion.png"), dpi=110)


def main(argv):
    if len(argv) == 4 and argv[1] == "terminal":
        terminal(argv[2], float(argv[3]))
    elif len(argv) == 3 and argv[1] == "bed":
        bed(argv[2])
    elif 3 <= len(argv) <= 5 and argv[1] == "speeds":
        speeds(argv[2], float(argv[3]) if len(argv) > 3 else math.inf,
               float(argv[4]) if len(argv) > 4 else 0.15)
    else:
        sys.exit("usage: summarise.py terminal CASE U_IN | summarise.py bed CASE | "
                 "summarise.py speeds CASE [UNTIL [ABOVE]]")


if __name__ == "__main__":
    main(sys.argv)
