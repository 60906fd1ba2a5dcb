#!/usr/bin/python3
"""Drag (and lift) of a fixed sphere and a fixed prolate spheroid (AR 2.5) in a
uniform stream at Re 10-100 (validation/finiteReynoldsDrag, see README.md).

    finiteReynoldsDrag.py run [--force] [--only NAME ...]
    finiteReynoldsDrag.py plot
    finiteReynoldsDrag.py single CASE [--ar AR] [--incidence DEG] [--re RE] [--cpd N]
                                      [--end-time T]

run: the cases of the campaign in run/<name>/ (git-ignored), one solver at a
     time; each is a fixed number of Euler steps (dt = h/U) to t = END_TIME
     D_eq/U, so two identical runs give the same figures. Every finished case is
     appended to results/runs.csv with its force history in results/<name>.dat,
     and skipped next time unless --force.
plot: results/table.md, results/metrics.json and results/finiteReynoldsDrag.png.
single: one case in the folder CASE (used by tests/foam/finiteReynoldsDragQuick);
     writes CASE/drag.csv (C_D, C_L at the end, cells, steps).

C_D = F_x / (rho U^2/2 pi D_eq^2/4), C_L = |F_y| / (same), D_eq the diameter of
the equal-volume sphere (the normalisation of Zastawny et al. 2012); the pitching
torque C_T = T_z / (rho U^2/2 pi D_eq^2/4 D_eq/2), T the hydrodynamic torque about the
body's centre (bodies.h5 hydroTorque), positive when it turns the symmetry axis away
from the stream (towards broadside): the axis (cos phi, sin phi, 0) at incidence phi.
"""
import argparse
import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np

import caseWriter

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
from validationTools import (cpu_seconds, locked, provenance, read_csv,  # noqa: E402
                             run_logged, write_csv)

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "results")
RUNS_CSV = os.path.join(RESULTS, "runs.csv")
END_TIME = 40.0
SETTLE_WINDOW = 10.0   # the convergence figure: change of C_D over the last window
AREA = math.pi / 4
ARM = 0.5              # the torque's reference length D_eq/2 (Zastawny et al.'s C_T)
FIELDS = ["name", "shape", "ar", "incidence", "Re", "cpd", "cells", "dt", "steps",
          "C_D", "C_L", "C_D_change_pct", "cpu_s", "host", "date", "commit", "C_T"]


def campaign():
    # (the folder names and the Re 50 resolution series are read by plotDrag.py)
    runs = [(f"sphere-Re{re}-c16", dict(ar=1.0, incidence=0, re=re, cpd=16))
            for re in (20, 50, 100)]
    runs += [(f"sphere-Re50-c{cpd}", dict(ar=1.0, incidence=0, re=50, cpd=cpd))
             for cpd in (8, 12)]
    runs += [(f"prolate-Re{re}-i{inc}-c16", dict(ar=2.5, incidence=inc, re=re, cpd=16))
             for re in (100, 20) for inc in (0, 45, 90)]
    runs += [(f"prolate-Re100-i45-c{cpd}", dict(ar=2.5, incidence=45, re=100, cpd=cpd))
             for cpd in (8, 12)]
    runs += [(f"prolate-Re100-i90-c{cpd}", dict(ar=2.5, incidence=90, re=100, cpd=cpd))
             for cpd in (12, 24)]
    return runs


def read_force(case):
    """time[N], hydroForce[N, 3], hydroTorque[N, 3] (about the centre) of the body from
    its HDF5 series."""
    import h5py
    path = os.path.join(case, "postProcessing", "immersedBodies", "bodies.h5")
    with h5py.File(path, "r", locking=False) as f:
        n = min(f[k].shape[0] for k in ("time", "hydroForce", "hydroTorque"))
        return f["time"][:n], f["hydroForce"][:n, 0, :], f["hydroTorque"][:n, 0, :]


def run_case(case, ar, incidence, re, cpd, end_time=END_TIME, domain=caseWriter.DOMAIN):
    """Write, mesh and run one case in the folder case (replaced); returns its figures
    and the history (t, C_D, C_L, C_T)."""
    if os.path.exists(case):
        subprocess.run(["rm", "-rf", case], check=True)
    dt, steps, cells = caseWriter.write_case(case, ar, incidence, re, cpd, end_time,
                                             domain=domain)
    print(f"{os.path.basename(case)}: {cells} cells, dt {dt:.4g}, {steps} steps", flush=True)
    rc = run_logged(["nice", "-n", "10", "pimpleFoam"], case, "log.solver")
    if rc != 0:
        raise RuntimeError(f"pimpleFoam failed in {case} (see log.solver)")
    t, F, T = read_force(case)
    cd, cl = F[:, 0] / (0.5 * AREA), np.abs(F[:, 1]) / (0.5 * AREA)
    # T_z turns the axis (cos phi, sin phi, 0) towards larger phi, away from the stream x
    ct = T[:, 2] / (0.5 * AREA * ARM)
    if not np.all(np.isfinite(cd)) or t[-1] < steps * dt - 1e-6:
        raise RuntimeError(f"{case}: the force history is incomplete or not finite")
    before = np.interp(t[-1] - min(SETTLE_WINDOW, 0.5 * t[-1]), t, cd)
    row = dict(shape="sphere" if ar == 1 else "prolate", ar=ar, incidence=incidence, Re=re,
               cpd=cpd, cells=cells, dt=f"{dt:.6g}", steps=steps, C_D=f"{cd[-1]:.6f}",
               C_L=f"{cl[-1]:.6f}", C_D_change_pct=f"{100 * (cd[-1] - before) / cd[-1]:.4f}",
               cpu_s=f"{cpu_seconds(case):.0f}", C_T=f"{ct[-1]:.6f}")
    return row, (t, cd, cl, ct)


def run_one(name, **kw):
    row, history = run_case(os.path.join(HERE, "run", name), **kw)
    np.savetxt(os.path.join(RESULTS, f"{name}.dat"), np.column_stack(history),
               header="t [D_eq/U], C_D, |C_L|, C_T (pitching, positive towards broadside)",
               fmt="%.8g")
    return dict(name=name, **row, **provenance())


def do_single(args):
    row, _ = run_case(os.path.abspath(args.case), args.ar, args.incidence, args.re, args.cpd,
                      args.end_time)
    write_csv(os.path.join(args.case, "drag.csv"), [row])
    print(", ".join(f"{k} {v}" for k, v in row.items()))


def do_run(args):
    os.makedirs(RESULTS, exist_ok=True)
    done = {r["name"] for r in read_csv(RUNS_CSV)} if not args.force else set()
    for name, kw in campaign():
        if (args.only and name not in args.only) or name in done:
            continue
        row = run_one(name, **kw)
        print(f"  -> C_D {row['C_D']}, C_L {row['C_L']}, C_T {row['C_T']} (change over the last "
              f"{SETTLE_WINDOW:g} D/U: {row['C_D_change_pct']} %)", flush=True)
        with locked(RUNS_CSV):
            old = read_csv(RUNS_CSV)    # a rerun keeps its row's place
            rows = [row if r["name"] == name else r for r in old]
            write_csv(RUNS_CSV, rows if any(r["name"] == name for r in old) else old + [row],
                      FIELDS)


def do_plot():
    import plotDrag
    rows = read_csv(RUNS_CSV, missing_ok=False)
    for r in rows:
        for k in ("ar", "Re", "C_D", "C_L", "C_D_change_pct"):
            r[k] = float(r[k])
        r["cpd"], r["incidence"] = int(r["cpd"]), int(r["incidence"])
    metrics = {}
    md = plotDrag.tables(rows, metrics)
    body_fitted, body_fitted_torque = {}, {}
    csv_body_fitted = os.path.join(RESULTS, "bodyFitted.csv")
    if os.path.exists(csv_body_fitted):
        import bodyFittedTable
        lines, more = bodyFittedTable.tables(csv_body_fitted)
        md += [""] + lines
        metrics.update(more)
        body_fitted = bodyFittedTable.extrapolated(csv_body_fitted)
        body_fitted_torque = bodyFittedTable.torque(csv_body_fitted)
    md += plotDrag.torque_table(rows, metrics, RESULTS, body_fitted_torque)
    with open(os.path.join(RESULTS, "table.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    with open(os.path.join(RESULTS, "metrics.json"), "w") as f:
        json.dump(metrics, f, indent=1, sort_keys=True)
        f.write("\n")
    plotDrag.figure(rows, os.path.join(RESULTS, "finiteReynoldsDrag.png"), body_fitted)
    print("\n".join(md))


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("run")
    r.add_argument("--force", action="store_true")
    r.add_argument("--only", action="append", default=[])
    sub.add_parser("plot")
    g = sub.add_parser("single")
    g.add_argument("case")
    g.add_argument("--ar", type=float, default=1.0)
    g.add_argument("--incidence", type=float, default=0.0)
    g.add_argument("--re", type=float, default=20.0)
    g.add_argument("--cpd", type=int, default=8)
    g.add_argument("--end-time", type=float, default=4.0)
    args = ap.parse_args()
    {"run": do_run, "single": do_single, "plot": lambda a: do_plot()}[args.cmd](args)


if __name__ == "__main__":
    main()
