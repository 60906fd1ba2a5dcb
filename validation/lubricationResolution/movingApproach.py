#!/usr/bin/python3
"""A sphere approaching a wall, or two spheres approaching each other, at constant speed
through the mesh: resolved flow plus the lubrication correction against the exact Stokes
force along the whole path (validation/lubricationResolution).

The runs of lubricationResolution.py hold the body at one gap per run (a frozen body, the
velocity imposed on the fluid). Here the body moves (`motion { type prescribed; frozen no; }`)
from START_GAP down to END_GAP: its surface crosses the cells, the cells of the gap turn solid
one after another and the film closes as in a free run. The gap closes by CELLS_PER_STEP cells
per time step (nu dt/h^2 = 1 as in the frozen runs), so the sphere's speed is U = 0.0025 N in
d = 1, nu = 1 units at N cells/d (Re = U d/nu 0.02 at 8 cells/d, 0.04 at 16; each sphere of the
pair moves at half of it): the film is quasi-steady (its viscous time a h/nu over the time h/U
in which the gap closes is Re/2), and the flow has forgotten the start by 0.5 d (2.5 d^2/nu at
8 cells/d, 1.25 at 16).

Each step's force along the motion, hydrodynamic plus collision (the correction as it runs in
production), over 6 pi mu a U, is compared with the exact force averaged over the gap path of
that step: the collision model gives the film's impulse integrated over the path (docs/
collisions.md, step 6), so a step's force is the path's mean (at 1e-3 d and 8 cells/d a step
closes a third of the gap, 3.1e-4 d, and the film force varies as 1/h over it). The exact forces are Brenner
(1961) for the wall and Brenner's free-surface series for the pair (sphereWallStokes.py).

    movingApproach.py run --cpd N [--shape sphere|spherePair] [--force]
    movingApproach.py plot        results/movingTable.md, moving.png (lubricationResolution.py
                                  plot calls it and adds its metrics)

Per run: results/moving-<shape>-c<N>.csv (every step from 0.5 d to 1e-3 d) and a row of
results/movingRuns.csv (the largest error, CPU time, host, commit).
"""
import argparse
import math
import os
import shutil
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import lubricationResolution as lr  # noqa: E402
from validationTools import (cpu_seconds, locked, mesh_cells, provenance,  # noqa: E402
                             read_csv, run_logged, write_csv)

START_GAP, FIRST_GAP, LAST_GAP, END_GAP = 0.6, 0.5, 1e-3, 5e-4   # h/d
CELLS_PER_STEP = 0.0025   # the gap closes by this many cells per time step
TABLE_GAPS = (0.5, 0.2, 0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001)
SHAPES = ("sphere", "spherePair")
RUNS_CSV = os.path.join(lr.RESULTS, "movingRuns.csv")
RUN_FIELDS = ["name", "shape", "cpd", "U", "cells", "dt", "steps", "samples",
              "max_abs_error_pct", "worst_gap", "cpu_s", "host", "date", "commit"]
SERIES_FIELDS = ["gap", "F_hydro", "F_collision", "F_total", "reference_path_mean", "error_pct"]


def closing_speed(cpd):
    """The speed at which the gap closes: CELLS_PER_STEP cells per step of nu dt/h^2 = LAMBDA."""
    h = 1.0 / cpd
    return CELLS_PER_STEP * h / (lr.LAMBDA * h * h)


def body_speed(cpd, shape):
    """Each body's speed: the closing speed, shared by the two spheres of a pair."""
    return closing_speed(cpd) / (2 if shape == "spherePair" else 1)


def reference(shape):
    """The exact force over 6 pi mu a U as a function of h/d (each sphere at U for the pair),
    interpolated in log-log from 400 gaps over the runs' range (the series are slow)."""
    exact = lr.two_spheres_approaching if shape == "spherePair" else lr.brenner
    grid = np.logspace(math.log10(0.5 * END_GAP), math.log10(1.2 * START_GAP), 400)
    values = np.log([exact(g / lr.A) for g in grid])
    return lambda g: np.exp(np.interp(np.log(g), np.log(grid), values))


def write_case(case, cpd, shape):
    """The frozen harness's case with the body set moving from START_GAP to END_GAP."""
    u = body_speed(cpd, shape)
    saved = lr.U, lr.MOTIONS["approach"]
    lr.U, lr.MOTIONS["approach"] = u, ((0.0, 0.0, -u), 2)
    try:
        info = lr.write_case(case, cpd, START_GAP, (START_GAP - END_GAP) / closing_speed(cpd),
                             "approach", lr.BOX_HALF, shape)
    finally:
        lr.U, lr.MOTIONS["approach"] = saved
    path = os.path.join(case, "constant", "immersedBodiesProperties")
    text = open(path).read()
    moving = text.replace("frozen          yes;", "frozen          no;")
    bodies = 2 if shape == "spherePair" else 1
    if (moving.count("frozen          no;") != bodies
            or moving.count(f"velocity        constant (0 0 {-u:.12g});") != 1):
        sys.exit(f"movingApproach: the frozen entry or the velocity {-u:g} of {path} was not found")
    with open(path, "w") as f:
        f.write(moving)
    return {**info, "U": u}


def analyse(h5, shape, cpd):
    """Per step from FIRST_GAP to LAST_GAP: the gap at its end, the forces over 6 pi mu a U
    (against the motion) and the error against the exact force's mean over the step's path."""
    import h5py
    u = body_speed(cpd, shape)
    exact = reference(shape)
    with h5py.File(h5, "r", locking=False) as f:
        names = [n.decode() if isinstance(n, bytes) else str(n) for n in f["bodyNames"][:]]
        b = names.index("upper" if shape == "spherePair" else "sphere")
        z = f["centre"][:, b, 2]
        fh = f["hydroForce"][:, b, 2]
        fc = f["collisionForce"][:, b, 2]
    gap = z - lr.A - (lr.PAIR_MID if shape == "spherePair" else 0.0)
    if shape == "spherePair":
        gap = 2 * gap          # the upper sphere's lowest point is half the gap above PAIR_MID
    scale = 6 * math.pi * lr.A * u
    rows = []
    for i in range(1, len(gap)):
        if not LAST_GAP * (1 - 1e-9) <= gap[i] <= FIRST_GAP:
            continue
        path = np.geomspace(gap[i], gap[i - 1], 65)
        mean = np.trapz(exact(path), path) / (gap[i - 1] - gap[i])
        total = (fh[i] + fc[i]) / scale
        rows.append({"gap": gap[i], "F_hydro": fh[i] / scale, "F_collision": fc[i] / scale,
                     "F_total": total, "reference_path_mean": mean,
                     "error_pct": 100 * (total / mean - 1)})
    return rows


def run(cpd, shape, force):
    name = f"moving-{shape}-c{cpd}"
    case = os.path.join(lr.RUNS, name)
    h5 = os.path.join(case, "postProcessing", "immersedBodies", "bodies.h5")
    if os.path.isdir(case) and (force or not os.path.isfile(h5)):
        shutil.rmtree(case)
    if not os.path.isdir(case):
        os.makedirs(case)
        write_case(case, cpd, shape)
        if run_logged(["blockMesh"], case, "log.blockMesh") != 0:
            sys.exit(f"movingApproach: blockMesh failed in {case}")
        if run_logged(["immersedSpheroidFoam"], case, "log.solver") != 0:
            sys.exit(f"movingApproach: the solver failed in {case} (log.solver)")
    rows = analyse(h5, shape, cpd)
    if not rows or rows[-1]["gap"] > 1.5 * LAST_GAP:
        sys.exit(f"movingApproach: {case} did not reach the gap {LAST_GAP:g} d (rerun with --force)")
    os.makedirs(lr.RESULTS, exist_ok=True)
    write_csv(os.path.join(lr.RESULTS, f"{name}.csv"),
              [{k: f"{v:.6g}" for k, v in r.items()} for r in rows], SERIES_FIELDS)
    worst = max(rows, key=lambda r: abs(r["error_pct"]))
    dt = lr.LAMBDA / cpd ** 2
    row = {"name": name, "shape": shape, "cpd": cpd, "U": f"{body_speed(cpd, shape):g}",
           "cells": mesh_cells(case), "dt": f"{dt:.6g}",
           "steps": int(round((START_GAP - END_GAP) / closing_speed(cpd) / dt)),
           "samples": len(rows), "max_abs_error_pct": f"{abs(worst['error_pct']):.3f}",
           "worst_gap": f"{worst['gap']:.4g}",
           "cpu_s": f"{cpu_seconds(case, 'log.solver'):.0f}", **provenance()}
    with locked(RUNS_CSV):
        rows_csv = [r for r in read_csv(RUNS_CSV) if r["name"] != name] + [row]
        write_csv(RUNS_CSV, sorted(rows_csv, key=lambda r: (r["shape"], int(r["cpd"]))),
                  RUN_FIELDS, ignore_extra=True)
    print(f"{name}: {len(rows)} steps from {FIRST_GAP:g} d to {LAST_GAP:g} d, largest error "
          f"{worst['error_pct']:+.2f} % at {worst['gap']:.4g} d", flush=True)


def series(name):
    return [{k: float(v) for k, v in r.items()}
            for r in read_csv(os.path.join(lr.RESULTS, f"{name}.csv"), missing_ok=False)]


def plot():
    """results/movingTable.md (returned) and moving.png; returns (markdown, metrics)."""
    runs = read_csv(RUNS_CSV)
    if not runs:
        return "", {}
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axs = plt.subplots(1, 2, figsize=(11, 4))
    metrics = {}
    lines = ["Bodies moving at constant speed through the mesh (`movingApproach.py`): the force "
             "of the step ending at the gap h, resolved + correction, against the exact force "
             "averaged over the step's gap path (every step from 0.5 d to 1e-3 d counted in the "
             "largest error; the table shows the step nearest each gap).", "",
             "| run | U | cells | steps | " + " | ".join(f"{g:g} d" for g in TABLE_GAPS)
             + " | largest \\|error\\| (at h/d) | CPU [s] |",
             "|---|---|---|---|" + "---|" * len(TABLE_GAPS) + "---|---|"]
    for k, r in enumerate(runs):
        s = series(r["name"])
        gaps = np.array([x["gap"] for x in s])
        cells = [f"{s[int(np.argmin(abs(np.log(gaps / g))))]['error_pct']:+.1f} %"
                 for g in TABLE_GAPS]
        lines.append(f"| {r['name']} | {r['U']} | {r['cells']} | {r['steps']} | "
                     + " | ".join(cells) + f" | {float(r['max_abs_error_pct']):.2f} % "
                     f"({float(r['worst_gap']):.3g}) | {r['cpu_s']} |")
        label = f"{'two spheres' if r['shape'] == 'spherePair' else 'sphere-wall'}, {r['cpd']} cells/d"
        style = "--" if r["shape"] == "spherePair" else "-"
        axs[0].loglog(gaps, [x["F_total"] for x in s], style, color=f"C{k}", label=label)
        axs[0].loglog(gaps, [x["F_hydro"] for x in s], ":", color=f"C{k}")
        axs[1].semilogx(gaps, [x["error_pct"] for x in s], style, color=f"C{k}", label=label)
        kind = "moving_pair" if r["shape"] == "spherePair" else "moving"
        metrics[f"max_abs_{kind}_force_error_pct_{r['cpd']}"] = round(
            float(r["max_abs_error_pct"]), 3)
    for shape in SHAPES:
        sel = [float(r["max_abs_error_pct"]) for r in runs if r["shape"] == shape]
        if sel:
            kind = "moving_pair" if shape == "spherePair" else "moving"
            metrics[f"max_abs_{kind}_force_error_pct"] = round(max(sel), 3)
    axs[0].set_ylabel("F / (6 pi mu a U)  (dotted: resolved alone)")
    axs[1].set_ylabel("against the exact force's path mean [%]")
    axs[1].axhspan(-10, 10, color="0.9")
    for ax in axs:
        ax.set_xlabel("gap h / d")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle("Moving through the mesh at constant speed: resolved force plus correction")
    fig.tight_layout()
    fig.savefig(os.path.join(lr.RESULTS, "moving.png"), dpi=120)
    plt.close(fig)
    text = "\n".join(lines)
    with open(os.path.join(lr.RESULTS, "movingTable.md"), "w") as f:
        f.write(text + "\n")
    return text, metrics


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("run")
    r.add_argument("--cpd", type=int, required=True, choices=[8, 12, 16])
    r.add_argument("--shape", choices=SHAPES, default="sphere")
    r.add_argument("--force", action="store_true")
    sub.add_parser("plot")
    a = ap.parse_args()
    if a.cmd == "run":
        run(a.cpd, a.shape, a.force)
    else:
        print(plot()[0])


if __name__ == "__main__":
    main()
