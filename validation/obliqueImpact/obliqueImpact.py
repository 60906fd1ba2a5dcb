#!/usr/bin/python3
"""Oblique impact of a prolate spheroid (aspect ratio 2) on a wall in a viscous fluid:
trajectory and rebound, without and with Coulomb friction (see README.md).

    obliqueImpact.py run [--cpd N] [--force] [--quick]
    obliqueImpact.py plot
    obliqueImpact.py collect     (re-analyse results/<name>.h5 into results/runs.csv)

The spheroid (D_eq = 4 mm, steel 7800 kg/m^3) starts at gap 1.5 D_eq with 0.6 m/s
at 30 degrees from the wall normal, its axis in the plane of motion and tilted 45
degrees from the normal, in oil (rho_f 935, mu 0.01 Pa s; St = rho_p U D_eq/(9 mu)
~ 200). Box 6 x 4 x 4 D_eq, bottom the collision wall; lubricationContact, e_dry 0.97,
friction 0 and 0.3. The case is caseTemplate/ with the mesh, the time step, the end time and
the friction set per run. Results: results/runs.csv (rebound quantities), results/<name>.h5,
results/table.md, results/trajectory.png.
"""
import argparse
import json
import math
import os
import shutil
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
from validationTools import (locked, merge_row, provenance, read_csv, run_logged,  # noqa: E402
                             set_entry, substitute_re, write_csv)

HERE = os.path.dirname(os.path.abspath(__file__))

RESULTS = os.path.join(HERE, "results")
RUNS_CSV = os.path.join(RESULTS, "runs.csv")
# D_eq, the release speed and its angle from the wall normal in caseTemplate/ (they set the
# time step and the end time)
D_EQ, U0, IMPACT_DEG = 4e-3, 0.6, 30.0
FIELDS = ["name", "friction", "cpd", "cells", "dt", "steps", "impacts", "u_n_in", "u_t_in", "u_n_out",
          "u_t_out", "omega_y_out", "rebound_angle_deg", "tilt_in_deg", "tilt_out_deg",
          "max_overlap_amin", "max_omega_y", "max_tilt_deg", "impact_interval_ms", "u_z_after_first",
          "wall_s", "host", "date", "commit"]


def write_case(case, friction, cpd, quick):
    """case/: a copy of caseTemplate/ (the body, the fluid, the 6 x 4 x 4 D_eq box) with the
    mesh, the time step, the end time and the friction of this run."""
    h = D_EQ / cpd
    dt = 0.4 * h / U0
    nx, ny, nz = round(6 * cpd), round(4 * cpd), round(4 * cpd)
    # the template's start: gap 1.5 D_eq, velocity at IMPACT_DEG from the wall normal
    uz = -U0 * math.cos(math.radians(IMPACT_DEG))
    t_end = (1.5 * D_EQ / -uz) * (0.5 if quick else 2.6)
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(os.path.join(HERE, "caseTemplate"), case)
    bm = f"{case}/system/blockMeshDict"
    substitute_re(bm, r"^// .*cells per D_eq$", f"// 6 x 4 x 4 D_eq, D_eq = 4 mm, {cpd} cells per D_eq")
    substitute_re(bm, r"^(\s*hex \(0 1 2 3 4 5 6 7\) )\(\d+ \d+ \d+\)", rf"\g<1>({nx} {ny} {nz})")
    cd = f"{case}/system/controlDict"
    set_entry(cd, "endTime", f"{t_end:.6g}")
    set_entry(cd, "deltaT", f"{dt:.6g}")
    set_entry(cd, "maxDeltaT", f"{dt:.6g}")
    set_entry(f"{case}/constant/immersedBodiesProperties", "friction", f"{friction:g}")
    return dict(dt=dt, cells=nx * ny * nz)


def analyse(h5):
    import h5py
    with h5py.File(h5, "r", locking=False) as f:
        t = f["time"][()]
        c = f["centre"][:, 0, :]
        u = f["velocity"][:, 0, :]
        w = f["angularVelocity"][:, 0, :]
        q = f["orientation"][:, 0, :]
        fc = f["collisionForce"][:, 0, :]
        semi = f["semiAxes"][()].reshape(-1)[:3]
    for arr in (c, u, w, q):
        if not np.all(np.isfinite(arr)):
            raise RuntimeError(f"{h5}: non-finite body state")
    # body x axis in the world: first column of R(q), q = (w x y z)
    qw, qx, qy, qz = q.T
    axis = np.stack([1 - 2 * (qy ** 2 + qz ** 2), 2 * (qx * qy + qw * qz), 2 * (qx * qz - qw * qy)], 1)
    tilt = np.degrees(np.arccos(np.clip(np.abs(axis[:, 2]), 0, 1)))
    a, b = semi[0], semi[1]
    # lowest point height: centre z - sqrt(e_z^T P e_z), P = R diag(a^2 b^2 b^2) R^T
    nz2 = axis[:, 2] ** 2
    gap = c[:, 2] - np.sqrt(a ** 2 * nz2 + b ** 2 * (1 - nz2))
    touched = np.flatnonzero(np.linalg.norm(fc, axis=1) > 0)
    out = dict(t=t, x=c[:, 0], gap=gap, tilt=tilt, u=u, w=w)
    if len(touched) == 0:
        out.update(touched=False)
        return out
    i0 = touched[0]
    # impacts: runs of rows in contact (gap < 0; a tilted prolate body hits
    # with one end, turns, and may hit again with the other). Not the rows
    # with a collision force: the lubrication and the film correction act
    # between the impacts too
    contact = np.flatnonzero(gap < 0)
    if len(contact) == 0:
        contact = touched
    breaks = np.flatnonzero(np.diff(contact) > 1)
    impacts = 1 + len(breaks)
    starts = contact[np.r_[0, breaks + 1]]
    i1 = min(touched[-1] + 1, len(t) - 1)
    # the approach: before the first collision force; the rebound state: after
    # the last one (lubrication and film correction included)
    out.update(touched=True, i0=i0, i1=i1, impacts=impacts, u_in=u[i0 - 1], u_out=u[i1],
               w_out=w[i1], tilt_in=tilt[i0 - 1], tilt_out=tilt[i1],
               max_overlap=max(-gap.min(), 0) / b,
               max_omega=np.abs(w[:, 1]).max(), max_tilt=tilt.max(),
               impact_gap=(t[starts[-1]] - t[starts[0]]) if impacts > 1 else 0.0,
               # the centre's vertical velocity when the first impact has ended
               u_z_after_first=u[contact[breaks[0]] + 1, 2] if impacts > 1 else float("nan"))
    return out


def measured(r):
    """The measured columns of runs.csv from analyse()."""
    return dict(impacts=r["impacts"], u_n_in=f"{-r['u_in'][2]:.4f}", u_t_in=f"{r['u_in'][0]:.4f}",
                u_n_out=f"{r['u_out'][2]:.4f}", u_t_out=f"{r['u_out'][0]:.4f}",
                omega_y_out=f"{r['w_out'][1]:.2f}",
                rebound_angle_deg=f"{math.degrees(math.atan2(r['u_out'][0], r['u_out'][2])):.1f}",
                tilt_in_deg=f"{r['tilt_in']:.1f}", tilt_out_deg=f"{r['tilt_out']:.1f}",
                max_overlap_amin=f"{r['max_overlap']:.4f}", max_omega_y=f"{r['max_omega']:.1f}",
                max_tilt_deg=f"{r['max_tilt']:.1f}",
                impact_interval_ms=f"{1e3 * r['impact_gap']:.2f}",
                u_z_after_first=f"{r['u_z_after_first']:.4f}")


def run_one(friction, cpd, force, quick):
    tag = f"{'quick-' if quick else ''}mu{friction:g}-c{cpd}"
    out_csv = os.path.join(RESULTS, "quick.csv" if quick else "runs.csv")
    if not force and not quick and any(r["name"] == tag for r in read_csv(out_csv)):
        print(f"{tag}: in results/runs.csv, skipped")
        return
    case = os.path.join(HERE, "run", tag)
    info = write_case(case, friction, cpd, quick)
    print(f"{tag}: {info['cells']} cells, dt {info['dt']:.3g} s", flush=True)
    start = time.time()
    rc = run_logged(["nice", "-n", "5", "./Allrun"], case, "log.Allrun")
    wall = time.time() - start
    if rc != 0:
        sys.exit(f"obliqueImpact: {tag} failed (see {case}/log.*)")
    h5 = os.path.join(case, "postProcessing", "immersedBodies", "bodies.h5")
    r = analyse(h5)
    if not r["touched"]:
        if quick:
            print(f"  quick run: finite, {len(r['t'])} rows, no contact yet (as expected)")
            return
        sys.exit(f"obliqueImpact: {tag}: the spheroid never reached the wall")
    row = dict(name=tag, friction=friction, cpd=cpd, cells=info["cells"], dt=f"{info['dt']:.6g}",
               steps=len(r["t"]) - 1, wall_s=round(wall), **provenance(), **measured(r))
    print("  " + ", ".join(f"{k} {row[k]}" for k in FIELDS[6:15]), flush=True)
    if not quick:
        shutil.copy(h5, os.path.join(RESULTS, f"{tag}.h5"))
    merge_row(out_csv, row, "name", FIELDS, ignore_extra=True)


def write_metrics(rows):
    """results/metrics.json, per run (friction 0 -> mu0, 0.3 -> mu0.3): the normal and tangential
    rebound ratios u_n out/u_n in and u_t out/u_t in, the rebound angle, the spin after the
    rebound, the impacts and the largest overlap over the small semi-axis (cap 0.1)."""
    metrics = {}
    for r in rows:
        key = f"mu{float(r['friction']):g}_c{r['cpd']}"
        metrics[f"{key}_normal_rebound_ratio"] = round(float(r["u_n_out"]) / float(r["u_n_in"]), 4)
        metrics[f"{key}_tangential_rebound_ratio"] = round(
            float(r["u_t_out"]) / float(r["u_t_in"]), 4)
        metrics[f"{key}_rebound_angle_deg"] = float(r["rebound_angle_deg"])
        metrics[f"{key}_omega_y_out"] = float(r["omega_y_out"])
        metrics[f"{key}_impacts"] = int(r["impacts"])
        metrics[f"{key}_max_overlap_b"] = float(r["max_overlap_amin"])
    with open(os.path.join(RESULTS, "metrics.json"), "w") as f:
        json.dump(metrics, f, indent=1, sort_keys=True)
        f.write("\n")


def do_plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = read_csv(RUNS_CSV)
    if not rows:
        sys.exit("obliqueImpact: no runs in results/runs.csv")
    lines = ["| run | impacts | u_n in | u_t in | u_n out | u_t out | omega_y out [1/s] | rebound angle | "
             "tilt in -> out | max overlap/b | max omega_y | max tilt | between impacts | "
             "u_z after the first | wall |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| friction {r['friction']}, {r['cpd']} cells/D_eq | {r['impacts']} | {r['u_n_in']} | "
                     f"{r['u_t_in']} | {r['u_n_out']} | {r['u_t_out']} | {r['omega_y_out']} | "
                     f"{r['rebound_angle_deg']} deg | {r['tilt_in_deg']} -> {r['tilt_out_deg']} deg | "
                     f"{r['max_overlap_amin']} | {r['max_omega_y']} | {r['max_tilt_deg']} deg | "
                     f"{r['impact_interval_ms']} ms | {r['u_z_after_first']} | {r['wall_s']} s |")
    with open(os.path.join(RESULTS, "table.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    write_metrics(rows)
    fig, axs = plt.subplots(1, 3, figsize=(12, 3.6))
    for r in rows:
        x = analyse(os.path.join(RESULTS, f"{r['name']}.h5"))
        lab = f"friction {r['friction']}"
        axs[0].plot(x["x"] / D_EQ, x["gap"] / D_EQ, label=lab)
        axs[1].plot(x["t"] * 1e3, x["tilt"], label=lab)
        axs[2].plot(x["t"] * 1e3, x["w"][:, 1], label=lab)
    axs[0].set_xlabel("x / D_eq")
    axs[0].set_ylabel("lowest point above the wall / D_eq")
    axs[1].set_xlabel("t [ms]")
    axs[1].set_ylabel("axis tilt from the wall normal [deg]")
    axs[2].set_xlabel("t [ms]")
    axs[2].set_ylabel("omega_y [1/s]")
    for ax in axs:
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Prolate spheroid (Ar 2) hitting a wall at 30 deg in oil, St ~ 200")
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "trajectory.png"), dpi=120)


def do_collect():
    # under the file's lock: a run beside this one may add its row meanwhile
    with locked(RUNS_CSV):
        rows = read_csv(RUNS_CSV)
        for row in rows:
            row.update(measured(analyse(os.path.join(RESULTS, f"{row['name']}.h5"))))
        write_csv(RUNS_CSV, rows, FIELDS, ignore_extra=True)
    print(f"obliqueImpact: {len(rows)} runs re-analysed")


def main():
    ap = argparse.ArgumentParser()
    sp = ap.add_subparsers(dest="cmd", required=True)
    r = sp.add_parser("run")
    r.add_argument("--cpd", type=int, default=10)
    r.add_argument("--force", action="store_true")
    r.add_argument("--quick", action="store_true")
    sp.add_parser("plot")
    sp.add_parser("collect")
    args = ap.parse_args()
    os.makedirs(RESULTS, exist_ok=True)
    if args.cmd == "plot":
        do_plot()
        return
    if args.cmd == "collect":
        do_collect()
        return
    if args.cpd < 4 or args.cpd > 64:
        sys.exit(f"obliqueImpact: --cpd {args.cpd}: allowed 4 to 64")
    if args.quick:
        run_one(0.3, 5, True, True)
        return
    for friction in (0.0, 0.3):
        run_one(friction, args.cpd, args.force, False)


if __name__ == "__main__":
    main()
