#!/usr/bin/python3
"""Force ripple of a sphere moved at constant velocity through the cells
(validation/forceRipple, see README.md).

    forceRipple.py run [--force] [--only NAME ...]
    forceRipple.py plot

A sphere (D = 1, nu = 1, rho_f = 1) in a triply periodic box L = 4 D moves
with the prescribed velocity U_b = (0.04, 0, 0) along x; the fluid's mean
velocity is held at (0.02, 0, 0) by meanVelocityForce, so the body moves at
0.02 relative to the mean flow: in its own frame the flow is a steady Stokes
flow at Re 0.02, and every change of the drag as it crosses the cells is the
grid's. The body starts at (0, 0.31 h, 0.17 h) (off the mesh lines), the
run is fixed in simulated time: 3 tau_box (tau_box = L^2/(4 pi^2 nu)) to set
the flow up, then the body crosses two cells; the ripple is the standard
deviation of the drag F_x over those two cells, divided by its mean.
run: the cases of the campaign (forcing surfaceCorrected and cutCellFraction,
     8 and 16 cells/D, lambda = nu dt/h^2 = 1) in run/<name>/ (git-ignored),
     each appended to results/runs.csv and skipped next time unless --force.
plot: results/table.md, results/metrics.json (ripple_pct_8, ripple_pct_16:
     the default forcing's; ripple_pct_8_cutCell, ripple_pct_16_cutCell) and
     results/forceRipple.png.
"""
import argparse
import math
import os
import subprocess
import sys
import json
from pathlib import Path

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "stokesDrag"))
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
import caseWriter  # noqa: E402
from runner import read_force  # noqa: E402
from validationTools import mesh_cells, provenance, read_csv, run_logged, write_csv, cpu_seconds  # noqa: E402

RESULTS = os.path.join(HERE, "results")
RUNS_CSV = os.path.join(RESULTS, "runs.csv")
BOX = 4.0
U_BODY = 0.04
U_MEAN = 0.02
LAMBDA = 1.0
CELLS_CROSSED = 2
FORCINGS = ("surfaceCorrected", "cutCellFraction")
FIELDS = ["name", "forcing", "cpd", "lambda", "dt", "cells", "steps", "t_start", "t_end",
          "mean_Fx", "std_Fx", "ripple_pct", "max_minus_min_pct", "cpu_s", "host", "date",
          "commit"]


def campaign():
    return [(f"sphere-c{cpd}-{forcing}", dict(cpd=cpd, forcing=forcing))
            for forcing in FORCINGS for cpd in (8, 16)]


def run_one(name, cpd, forcing):
    case = os.path.join(HERE, "run", name)
    if os.path.exists(case):
        subprocess.run(["rm", "-rf", case], check=True)
    h = 1.0 / cpd
    dt = LAMBDA * h * h
    tau = BOX ** 2 / (4 * math.pi ** 2)
    u_rel = U_BODY - U_MEAN
    t_start = 3 * tau
    n_start = int(math.ceil(t_start / dt))
    n_cross = int(round(CELLS_CROSSED * h / U_BODY / dt))
    t_end = (n_start + n_cross) * dt
    travel = U_BODY * t_end
    caseWriter.write_case(case, 1.0, "x", BOX, cpd, dt, t_end, u=u_rel,
                          margin=0.25 + travel + 2 * h, forcing=forcing,
                          write_interval=n_start + n_cross, ubar=(U_MEAN, 0.0, 0.0),
                          body_velocity=(U_BODY, 0.0, 0.0),
                          centre=(0.0, 0.31 * h, 0.17 * h))
    with open(os.path.join(case, "log.blockMesh"), "w") as out:
        subprocess.run(["blockMesh"], cwd=case, stdout=out, stderr=subprocess.STDOUT, check=True)
    print(f"{name}: {mesh_cells(case)} cells, dt {dt:.4g}, {n_start} + {n_cross} steps",
          flush=True)
    rc = run_logged(["nice", "-n", "10", "pimpleFoam"], case, "log.solver")
    if rc != 0:
        raise RuntimeError(f"pimpleFoam failed in {case} (see log.solver)")
    times, F = read_force(case)
    window = times > n_start * dt - 0.5 * dt
    fx = F[window, 0]
    mean, std = float(np.mean(fx)), float(np.std(fx))
    np.savetxt(os.path.join(RESULTS, f"{name}.dat"),
               np.column_stack([times[window] - n_start * dt, fx / mean]),
               header="t - t_start, F_x/mean", fmt="%.8g")
    return dict(name=name, forcing=forcing, cpd=cpd, **{"lambda": LAMBDA}, dt=f"{dt:.6g}",
                cells=mesh_cells(case), steps=n_start + n_cross, t_start=f"{n_start * dt:.6g}",
                t_end=f"{t_end:.6g}", mean_Fx=f"{mean:.8g}", std_Fx=f"{std:.6g}",
                ripple_pct=f"{100 * std / abs(mean):.5f}",
                max_minus_min_pct=f"{100 * (fx.max() - fx.min()) / abs(mean):.5f}",
                cpu_s=f"{cpu_seconds(case):.0f}", **provenance())


def do_run(args):
    os.makedirs(RESULTS, exist_ok=True)
    done = {r["name"] for r in read_csv(RUNS_CSV)} if not args.force else set()
    for name, kw in campaign():
        if (args.only and name not in args.only) or name in done:
            continue
        row = run_one(name, **kw)
        print(f"  -> ripple {row['ripple_pct']} % (max - min {row['max_minus_min_pct']} %)",
              flush=True)
        write_csv(RUNS_CSV, [r for r in read_csv(RUNS_CSV) if r["name"] != name] + [row], FIELDS)


def do_plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = read_csv(RUNS_CSV, missing_ok=False)
    md = ["# Force ripple of a sphere moved through the cells", "",
          "Produced by `validation/forceRipple/Allrun -plot` from results/runs.csv. Sphere, "
          f"L/D = {BOX:g}, lambda = {LAMBDA:g}, body crossing {CELLS_CROSSED} cells along x at "
          f"{U_BODY:g} (relative to the mean flow {U_BODY - U_MEAN:g}, Re "
          f"{U_BODY - U_MEAN:g}); ripple = std(F_x)/mean(F_x) over the crossing.", "",
          "| forcing | cells/D | cells | steps | mean F_x | ripple, second cell [%] | "
          "(max - min)/mean, second cell [%] | ripple, both cells [%] | CPU [s] |",
          "|---|---|---|---|---|---|---|---|---|"]
    metrics = {}
    for r in sorted(rows, key=lambda r: (r["forcing"] != "surfaceCorrected", int(r["cpd"]))):
        d = np.loadtxt(os.path.join(RESULTS, f"{r['name']}.dat"))
        h = 1.0 / int(r["cpd"])
        second = d[d[:, 0] * U_BODY >= h * (CELLS_CROSSED - 1) - 1e-12, 1]
        ripple = 100 * np.std(second) / abs(np.mean(second))
        spread = 100 * (second.max() - second.min()) / abs(np.mean(second))
        md.append(f"| {r['forcing']} | {r['cpd']} | {r['cells']} | {r['steps']} | "
                  f"{float(r['mean_Fx']):.5g} | {ripple:.4f} | {spread:.4f} | "
                  f"{float(r['ripple_pct']):.3f} | {r['cpu_s']} |")
        suffix = "" if r["forcing"] == "surfaceCorrected" else "_cutCell"
        metrics[f"ripple_pct_{r['cpd']}{suffix}"] = round(float(ripple), 5)
    with open(os.path.join(RESULTS, "table.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    with open(os.path.join(RESULTS, "metrics.json"), "w") as f:
        json.dump(metrics, f, indent=1, sort_keys=True)
        f.write("\n")
    print("\n".join(md))
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for r in rows:
        path = os.path.join(RESULTS, f"{r['name']}.dat")
        if not os.path.exists(path):
            continue
        d = np.loadtxt(path)
        h = 1.0 / int(r["cpd"])
        ax.plot(d[:, 0] * U_BODY / h, (d[:, 1] - 1) * 100,
                "-" if r["forcing"] == "surfaceCorrected" else "--",
                label=f"{r['forcing']}, {r['cpd']} cells/D")
    ax.set_xlabel("distance travelled [cells]")
    ax.set_ylabel("F_x / mean - 1  [%]")
    ax.set_title("Drag of a sphere moving through the cells (Stokes flow)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "forceRipple.png"), dpi=120)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("run")
    r.add_argument("--force", action="store_true")
    r.add_argument("--only", action="append", default=[])
    sub.add_parser("plot")
    args = ap.parse_args()
    do_run(args) if args.cmd == "run" else do_plot()


if __name__ == "__main__":
    main()
