#!/usr/bin/python3
"""Jeffery orbit of a neutrally buoyant prolate spheroid (r = 2.5) in simple
shear at Re = gamma a^2/nu = 0.1: the runs of validation/jefferyOrbit (see
README.md), their table and figures.

    jefferyOrbit.py run [--quick] [--group G ...] [--only NAME ...] [--force] [--collect]
    jefferyOrbit.py plot
    jefferyOrbit.py single CASE [--cpd N] [--dt DT] [--end-time T] [--box LX H LZ]
                               [--density-ratio R] [--virtual-mass CV]

run:  groups: orbit (the measured orbit, rho_p/rho_f = 1), stability (short
      runs that map where the explicit coupling is stable); one solver at a
      time (serial, nice) in run/<name>/ (git-ignored); each finished run's
      body time series is copied to results/<name>.h5 and its line to
      results/runs.csv, skipped next time unless --force.
      --quick: the smoke version (a short coarse run, run/quick/).
plot: results/table.md and results/*.png.
single: one run in the folder CASE (created; used by tests/foam/jefferyOrbitQuick);
      prints and writes CASE/rotation.csv (final angle, omega_z, Jeffery's rate
      there, the growth of the step-to-step oscillation).
"""
import argparse
import math
import os
import re
import shutil
import sys
from pathlib import Path

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
import jeffery  # noqa: E402
from validationTools import cpu_seconds, mesh_cells, provenance, read_csv, write_csv  # noqa: E402

RESULTS = os.path.join(HERE, "results")
RUNS_CSV = os.path.join(RESULTS, "runs.csv")
R = 2.5
MESH = dict(cpd=8, growth=1.2, max_ratio=8.0, box=(10.0, 10.0, 6.0))

FIELDS = ["name", "group", "density_ratio", "virtualMass", "dt", "penaltyRatio", "subSteps",
          "ddt", "nOuterCorrectors", "cpd", "cells", "lambda", "end_time", "steps", "wall_s",
          "cpu_s", "status", "growth_per_step", "alternation",
          "omega_end", "omega_jeffery_end", "omega_mean", "phi_mean", "phi0", "box", "T_half_pi", "T_pi", "T_2pi", "T_fit", "r_fit", "T_jeffery",
          "host", "date", "commit"]


def campaign(quick=False):
    runs = []
    if quick:
        runs.append(("quick", "quick", dict(MESH, dt=0.0007, end_time=0.07, virtual_mass=0.5)))
        return runs
    # the measured orbit with the library's defaults (virtualMass 0.5, penaltyRatio
    # 1e-3, forcing surfaceCorrected), over a full period, at two resolutions; the
    # step is the largest whose step-to-step alternation decays at that resolution
    # (300-step probes: 6 cells, gamma dt 1.5e-3 grows by 1.016 per step, 1e-3
    # decays by 0.995; 8 cells, 1.5e-3 decays by 0.996)
    runs.append(("orbit", "orbit-rho1-cv0.5-dt0.0015",
                 dict(MESH, dt=0.0015, end_time=19.5, write_interval=6.5, virtual_mass=0.5)))
    runs.append(("orbit", "orbit-rho1-cv0.5-c6-dt0.001",
                 dict(MESH, cpd=6, dt=0.001, end_time=19.5, write_interval=6.5,
                      virtual_mass=0.5)))
    # the stability map: 150 steps each
    for cv, rho, dt, extra in ((0, 1, 0.02, {}), (0, 1, 0.0025, {}), (0, 1, 0.001, {}),
                               (0, 1, 0.0007, {}),
                               (0, 1, 0.001, dict(penalty_ratio=1e-6)),
                               (0, 1, 0.001, dict(penalty_ratio=0.1)),
                               (0, 1, 0.001, dict(sub_steps=5)),
                               (0, 1, 0.001, dict(ddt="backward")),
                               (0, 1, 0.001, dict(n_outer=3)),
                               (0, 2, 0.0025, {}), (0, 2, 0.0015, {}),
                               (0, 4, 0.005, {}), (0, 4, 0.0025, {}),
                               (0.5, 1, 0.004, {}), (0.5, 1, 0.0025, {}), (0.5, 1, 0.0015, {}),
                               (0.5, 1, 0.001, {}), (1.0, 1, 0.0025, {})):
        tag = "".join(f"-{k}{v}" for k, v in extra.items())
        runs.append(("stability", f"stab-cv{cv:g}-rho{rho}-dt{dt:g}{tag}",
                     dict(MESH, dt=dt, density_ratio=rho, end_time=150 * dt, virtual_mass=cv,
                          **extra)))
    # the rotation rates at phi = 0 and phi = pi/2 from short runs (200 steps):
    # Jeffery's dphi/dt = A cos^2 phi + B sin^2 phi gives the period
    # T = 2 pi/sqrt(A B) and r = sqrt(A/B): cheap checks of the box size, the
    # resolution and the step against the orbit run
    for tag, extra in (("c8", {}), ("c8-box14", dict(box=(14.0, 14.0, 8.0))),
                       ("c8-dt0.00035", dict(dt=0.00035)), ("c12", dict(cpd=12, dt=0.0005)),
                       ("c8-cv0.5-dt0.0015", dict(dt=0.0015, virtual_mass=0.5))):
        for phi0 in (0, 90):
            kw = dict(MESH, dt=0.0007, virtual_mass=0, phi0=math.radians(phi0))
            kw.update(extra)
            kw["end_time"] = max(200 * kw["dt"], 0.14)
            runs.append(("rates", f"rates-{tag}-phi{phi0}", kw))
    # is the flow itself stable at these steps? the rotation prescribed at
    # Jeffery's rate at phi = 0, the torque watched
    for dt in (0.0025, 0.005):
        runs.append(("stability", f"stab-prescribed-dt{dt:g}",
                     dict(MESH, dt=dt, end_time=150 * dt, prescribed_omega=-R * R / (R * R + 1))))
    return runs


def oscillation_growth(omega):
    """(growth factor per step, final amplitude) of the period-2 (step-to-step
    alternating) part of omega_z, from its second differences
    |w[k+1] - 2 w[k] + w[k-1]| (4 x the amplitude of an alternation; a smooth
    variation gives ~ dt^2 w''): the mean of the last 5 against 5 in the middle
    of the run."""
    d2 = np.abs(omega[2:] - 2 * omega[1:-1] + omega[:-2])
    n = len(d2)
    if n < 20:
        return float("nan"), float(d2[-1] / 4) if n else float("nan")
    a0 = np.mean(d2[n // 2: n // 2 + 5]) + 1e-300
    a1 = np.mean(d2[-5:]) + 1e-300
    return float((a1 / a0) ** (1.0 / (n - 5 - n // 2))), float(a1 / 4)


def summarise(case, kw):
    """Analyse a finished (or diverged) run."""
    t, q, om, tq = jeffery.read_series(case)
    phi, pz = jeffery.phi_of(q)
    w = om[:, 2]
    if kw.get("prescribed_omega") is not None:
        w = tq[:, 2]          # the rotation is imposed: watch the torque instead
    g, amp = oscillation_growth(w)
    rate_j = -float(jeffery.jeffery_rate(phi[-1], R))
    # stable: close to Jeffery's rate and the alternation decays or is negligible
    if kw.get("prescribed_omega") is not None:
        bounded = np.all(np.isfinite(w)) and (g < 1.0 or amp < 1e-4 * abs(w[-1]))
    else:
        bounded = (np.all(np.isfinite(w)) and abs(w[-1] - rate_j) < 0.5 * abs(rate_j)
                   and (g < 1.0 or amp < 1e-4 * abs(rate_j)))
    k = max(1, len(t) // 4)          # the last quarter of the run
    out = dict(omega_mean=f"{np.mean(om[-k:, 2]):.6g}", phi_mean=f"{np.mean(phi[-k:]):.6g}")
    out.update(growth_per_step=f"{g:.4f}", alternation=f"{amp:.2e}", omega_end=f"{om[-1, 2]:.5g}",
               omega_jeffery_end=f"{rate_j:.5g}", status="stable" if bounded else "UNSTABLE",
               T_jeffery=f"{jeffery.jeffery_period(R):.5f}")
    res = jeffery.analyse(case, R)
    c = jeffery.crossings(t, phi, 0.5 * math.pi)
    if c:
        out["T_half_pi"] = f"{4 * c[0]:.5f}"      # phi = pi/2 at T/4
    c = jeffery.crossings(t, phi, math.pi)
    if c:
        out["T_pi"] = f"{2 * c[0]:.5f}"           # phi = pi at T/2
    c = jeffery.crossings(t, phi, 2 * math.pi)
    if c:
        out["T_2pi"] = f"{c[0]:.5f}"              # phi = 2 pi at T: one full period
    if "fit" in res and t[-1] > 2:
        out["T_fit"] = f"{res['fit']['T_fit']:.5f}"
        out["r_fit"] = f"{res['fit']['r_eff']:.4f}"
    return out


def do_run(args):
    csv_path = os.path.join(RESULTS, "quick.csv") if args.quick else RUNS_CSV
    os.makedirs(RESULTS, exist_ok=True)
    done = {r["name"] for r in read_csv(csv_path)} if not args.force else set()
    ok = True
    for group, name, kw in campaign(args.quick):
        if (args.group and group not in args.group) or (args.only and name not in args.only):
            continue
        if name in done and not args.quick:
            print(f"{name}: in {os.path.relpath(csv_path, HERE)}, skipped")
            continue
        case = os.path.join(HERE, "run", name)
        print(f"{name} ({group}):", flush=True)
        try:
            if args.collect:
                # an existing run (e.g. one started by hand with the same settings)
                cells = mesh_cells(case)
                with open(os.path.join(case, "log.solver")) as fh:
                    wall = float(re.findall(r"ClockTime = (\S+) s", fh.read())[-1])
            else:
                info, wall, cells = jeffery.run(case, **kw)
            failed = False
        except RuntimeError as e:
            # a diverged run ends with a floating-point exception: keep what it wrote
            print(f"  {e}")
            failed = True
            wall = float("nan")
            cells = mesh_cells(case)
        s = summarise(case, kw)
        if failed:
            s["status"] = "DIVERGED"
        h = 1.0 / kw["cpd"]
        nu = 1.25 ** 2 / 0.1
        row = dict(name=name, group=group, density_ratio=kw.get("density_ratio", 1.0),
                   virtualMass=kw.get("virtual_mass", 0.5),
                   dt=kw["dt"], penaltyRatio=kw.get("penalty_ratio", 1e-3),
                   subSteps=kw.get("sub_steps", 1), ddt=kw.get("ddt", "Euler"),
                   nOuterCorrectors=kw.get("n_outer", 1), cpd=kw["cpd"],
                   phi0=f"{math.degrees(kw.get('phi0', 0.0)):g}",
                   box="x".join(f"{v:g}" for v in kw["box"]),
                   cells=cells, end_time=kw["end_time"],
                   steps=len(jeffery.read_series(case)[0]) - 1,
                   wall_s=f"{wall:.0f}", cpu_s=f"{cpu_seconds(case):.0f}",
                   **provenance(), **s)
        row["lambda"] = f"{nu * kw['dt'] / h ** 2:.3g}"
        print("  " + ", ".join(f"{k} {row.get(k, '')}" for k in
                               ("status", "growth_per_step", "omega_end", "omega_jeffery_end",
                                "T_half_pi", "T_pi", "T_2pi", "T_fit", "wall_s")), flush=True)
        if args.quick:
            w, wj = float(row["omega_end"]), float(row["omega_jeffery_end"])
            good = row["status"] == "stable" and w < 0 and abs(w / wj - 1) < 0.1
            print("quick: " + ("passed" if good else "FAILED")
                  + f" (omega_z {w:.4f}, Jeffery {wj:.4f})")
            ok = ok and good
        else:
            shutil.copy(os.path.join(case, "postProcessing", "immersedBodies", "bodies.h5"),
                        os.path.join(RESULTS, f"{name}.h5"))
        write_csv(csv_path, [r for r in read_csv(csv_path) if r["name"] != name] + [row], FIELDS)
    if not ok:
        sys.exit(1)


def do_single(args):
    case = os.path.abspath(args.case)
    kw = dict(MESH, cpd=args.cpd, dt=args.dt, end_time=args.end_time, box=tuple(args.box),
              density_ratio=args.density_ratio, virtual_mass=args.virtual_mass)
    info, wall, cells = jeffery.run(case, **kw)
    t, q, om, tq = jeffery.read_series(case)
    phi, pz = jeffery.phi_of(q)
    row = dict(cells=cells, steps=len(t) - 1, t_end=f"{t[-1]:.6g}", phi_end=f"{phi[-1]:.6f}",
               phi_jeffery=f"{float(jeffery.jeffery_phi(t[-1], R)):.6f}",
               omega_z=f"{om[-1, 2]:.6f}",
               omega_jeffery=f"{-float(jeffery.jeffery_rate(phi[-1], R)):.6f}",
               growth_per_step=f"{oscillation_growth(om[:, 2])[0]:.5f}",
               alternation=f"{oscillation_growth(om[:, 2])[1]:.3g}",
               out_of_plane=f"{pz[-1]:.3g}", wall_s=f"{wall:.1f}",
               cpu_s=f"{cpu_seconds(case):.1f}")
    write_csv(os.path.join(case, "rotation.csv"), [row])
    print(", ".join(f"{k} {v}" for k, v in row.items()))


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    g = sub.add_parser("single")
    g.add_argument("case")
    g.add_argument("--cpd", type=int, default=6)
    g.add_argument("--dt", type=float, default=0.0007)
    g.add_argument("--end-time", type=float, default=0.07)
    g.add_argument("--box", type=float, nargs=3, default=[6.0, 6.0, 4.0])
    g.add_argument("--density-ratio", type=float, default=1.0)
    g.add_argument("--virtual-mass", type=float, default=0.5)
    r = sub.add_parser("run")
    r.add_argument("--quick", action="store_true")
    r.add_argument("--force", action="store_true")
    r.add_argument("--group", action="append", default=[])
    r.add_argument("--only", action="append", default=[], help="run only this NAME")
    r.add_argument("--collect", action="store_true",
                   help="only analyse existing run folders (no solver runs)")
    sub.add_parser("plot")
    args = ap.parse_args()
    if args.cmd == "run":
        do_run(args)
    elif args.cmd == "single":
        do_single(args)
    else:
        import plotJeffery
        plotJeffery.main(RESULTS)


if __name__ == "__main__":
    main()
