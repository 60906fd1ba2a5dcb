#!/usr/bin/python3
"""Stokes drag of a fixed spheroid in a triply periodic box: the runs of
validation/stokesDrag (see README.md), their table and figures.

    stokesDrag.py run [--quick] [--group G ...] [--force]
    stokesDrag.py plot
    stokesDrag.py single CASE [--ar AR] [--box L] [--cpd N] [--lam LAMBDA] [--tol TOL]

run:  runs the campaign (groups: box, resolution-BODY,
      lambda, fine24-BODY; BODY sphere, prolate2, oblate0.5),
      one pimpleFoam at a time (serial, nice), in run/<name>/ (git-ignored);
      each finished run is appended to results/runs.csv and skipped next time
      unless --force. --quick: the smoke version (two coarse runs in
      run/quick-*, results/quick.csv; not the committed table).
plot: results/table.md, results/boxFit.csv, results/resolution.csv and the
      figures results/*.png from results/runs.csv.
single: one run in the folder CASE (created; used by tests/foam/stokesDragQuick);
      prints and writes CASE/drag.csv (K along x = the axis, along y = across).

Units: D_eq = 1 (diameter of the sphere of the body's volume), nu = 1,
rho_f = 1, superficial velocity u = 0.02 per direction (Re = 0.02-0.03).
K = F/(6 pi mu r_eq u): the drag normalised by the equal-volume sphere.
"""
import argparse
import fcntl
import math
import os
import sys
import time
from pathlib import Path

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
from validationTools import provenance, read_csv, write_csv  # noqa: E402

RESULTS = os.path.join(HERE, "results")
RUNS_CSV = os.path.join(RESULTS, "runs.csv")

# the analytic drags, normalised by 6 pi mu r_eq U (physics-references.md 4)
BODIES = {"sphere": 1.0, "prolate2": 2.0, "oblate0.5": 0.5}
LAMBDA_BOX = 1.0          # the viscous number of the box-size series
LAMBDA = 1.0              # ... of the resolution series
LAMBDAS = (4.0, 1.0, 0.25, 0.0625)   # the viscous-number series (sphere, 12 cells/D)
LAMBDA_CUTCELL = 0.25     # the cutCellFraction comparison runs


def analytic_K(ar):
    """(K_axial, K_transverse): drag along / across the symmetry axis of the
    spheroid of aspect ratio ar = polar/equatorial, / (6 pi mu r_eq U)."""
    if abs(ar - 1) < 1e-12:
        return 1.0, 1.0
    r_eq = 0.5
    if ar > 1:                                   # prolate: a polar, b equatorial
        a = r_eq * ar ** (2 / 3)
        e = math.sqrt(1 - 1 / ar ** 2)
        L = math.log((1 + e) / (1 - e))
        Fa = 16 * math.pi * a * e ** 3 / ((1 + e * e) * L - 2 * e)
        Ft = 32 * math.pi * a * e ** 3 / (2 * e + (3 * e * e - 1) * L)
    else:                                        # oblate: a equatorial, c polar
        a = r_eq * ar ** (-1 / 3)
        e = math.sqrt(1 - ar ** 2)
        Fa = 8 * math.pi * a * e ** 3 / (e * math.sqrt(1 - e * e) - (1 - 2 * e * e) * math.asin(e))
        Ft = 16 * math.pi * a * e ** 3 / ((1 + 2 * e * e) * math.asin(e) - e * math.sqrt(1 - e * e))
    return Fa / (6 * math.pi * r_eq), Ft / (6 * math.pi * r_eq)


def hasimoto_K(phi):
    """Drag of a simple cubic array of spheres (Hasimoto 1959; the series of
    Sangani and Acrivos 1982, which agrees with Zick and Homsy's 1982 table to
    0.06 % up to phi 0.125, validation/periodicArray), K = F/(6 pi mu a U),
    U the superficial velocity, F the force per sphere balancing the mean
    pressure gradient over the cell; phi the solid fraction."""
    x = phi ** (1 / 3)
    return 1 / (1 - 1.7601 * x + phi - 1.5593 * phi ** 2 + 3.9799 * x ** 8 - 3.0734 * x ** 10)


HASIMOTO_B = -1.7601 * (math.pi / 6) ** (1 / 3)   # 1/K = 1 + b D/L + ...: -1.4187


def campaign(quick=False):
    """(group, name, kwargs) of every run."""
    runs = []
    if quick:
        for body, ar in (("sphere", 1.0), ("prolate2", 2.0)):
            runs.append(("quick", f"quick-{body}", dict(body=body, ar=ar, box=4, cpd=8, lam=1.0,
                                                          tol=1e-3)))
        return runs
    # in the order of importance: the box series (the extrapolation), the
    # resolution series, the viscous number, the finest sphere, and the
    # cut-cell forcing for comparison
    for body, ar in BODIES.items():
        # b is Hasimoto's (any body): two box sizes fix a and c; the sphere's
        # third size checks the fitted b against Hasimoto's
        for box in ((4, 6, 8) if body == "sphere" else (4, 6)):
            kw = dict(body=body, ar=ar, box=box, cpd=12, lam=LAMBDA_BOX)
            if box == 8:
                # its first stage (viscous number 1.44) is above the module's limit in a
                # period of 8 D at 12 cells/D (1.19, validation/viscousNumber): the run
                # converges, the limit is raised
                kw["max_viscous_number"] = 1.5
            runs.append(("box", f"{body}-L{box}-c12-lam{LAMBDA_BOX:g}", kw))
    for body, ar in BODIES.items():
        for cpd in (8, 12, 16):
            runs.append((f"resolution-{body}", f"{body}-L4-c{cpd}-lam{LAMBDA:g}",
                         dict(body=body, ar=ar, box=4, cpd=cpd, lam=LAMBDA)))
    for lam in LAMBDAS:
        # the series measures the steady drag's dependence on dt up to lambda 4, above the
        # module's limit for 12 cells/D (validation/viscousNumber): each stage runs about
        # 25 steps from the converged state of the stage before, too few for the period-two
        # oscillation to grow from roundoff (its growth there is about 1.03 per step)
        runs.append(("lambda", f"sphere-L4-c12-lam{lam:g}",
                     dict(body="sphere", ar=1.0, box=4, cpd=12, lam=lam,
                          max_viscous_number=max(LAMBDAS))))
    # its first stage (viscous number 1.44) is above the module's limit extrapolated to
    # 24 cells/D (1.2, validation/viscousNumber): the run converges, the limit is raised
    runs.append(("fine24-sphere", f"sphere-L4-c24-lam{LAMBDA:g}",
                 dict(body="sphere", ar=1.0, box=4, cpd=24, lam=LAMBDA, np=2,
                      max_viscous_number=1.5)))
    for cpd in (8, 12, 16):
        runs.append(("cutCell-sphere", f"sphere-L4-c{cpd}-lam{LAMBDA_CUTCELL:g}-cutCell",
                     dict(body="sphere", ar=1.0, box=4, cpd=cpd, lam=LAMBDA_CUTCELL,
                          forcing="cutCellFraction")))
    return runs


FIELDS = ["name", "body", "forcing", "AR", "L_over_D", "cpd", "lambda", "dt", "cells",
          "steps_stage1",
          "steps_stage2", "wall_s", "cpu_s", "Kx", "Ky", "Kx_gradP", "Ky_gradP", "Kx_last", "Ky_last",
          "Kx_analytic", "Ky_analytic", "host", "date", "commit"]


def do_run(args):
    import runner
    csv_path = os.path.join(RESULTS, "quick.csv") if args.quick else RUNS_CSV
    os.makedirs(RESULTS, exist_ok=True)
    done = {r["name"] for r in read_csv(csv_path)} if not args.force else set()
    for group, name, kw in campaign(args.quick):
        if args.group and group not in args.group:
            continue
        if name in done and not args.quick:
            print(f"{name}: in {os.path.relpath(csv_path, HERE)}, skipped")
            continue
        pause = os.path.join(HERE, "run", "PAUSE")
        if os.path.exists(pause):
            print(f"waiting while {pause} exists", flush=True)
            while os.path.exists(pause):
                time.sleep(10)
        case = os.path.join(HERE, "run", name)
        # another campaign running the same case (a run in two groups): skip it
        os.makedirs(os.path.dirname(case), exist_ok=True)
        case_lock = open(case + ".lock", "w")
        try:
            fcntl.flock(case_lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            print(f"{name}: being run by another campaign, skipped", flush=True)
            case_lock.close()
            continue
        if not args.quick and not args.force and name in {r["name"] for r in read_csv(csv_path)}:
            case_lock.close()
            continue
        print(f"{name} ({group}):", flush=True)
        kw = dict(kw)
        body = kw.pop("body")
        ar = kw.pop("ar")
        # stage 1: dt1 <= 0.01 D^2/nu (0.02 makes PISO with 2 correctors diverge at
        # L/D = 6: see README.md), viscous number <= 1.44
        dt1 = min(0.01, 1.44 / kw["cpd"] ** 2)
        for attempt in range(5):
            try:
                extra = {k: kw[k] for k in ("forcing", "max_viscous_number") if k in kw}
                res = runner.run_case(case, ar, "xy", kw["box"], kw["cpd"], lam=kw["lam"],
                                      dt1=dt1, tol=kw.get("tol", 2e-4), np_=kw.get("np", 1),
                                      **extra)
                break
            except RuntimeError:
                # the project's libraries being rebuilt when the solver started
                # (a shared checkout): wait and start the run again
                with open(os.path.join(case, "log.solver")) as fh:
                    text = fh.read()
                if attempt < 4 and ("error while loading shared libraries" in text
                                    or "Could not load" in text or "file too short" in text):
                    print("  (a library was being rebuilt: the run starts again in 60 s)",
                          flush=True)
                    time.sleep(60)
                    continue
                raise
        ka, kt = analytic_K(ar)
        row = dict(name=name, body=body, forcing=kw.get("forcing", "surfaceCorrected"), AR=ar, L_over_D=kw["box"], cpd=kw["cpd"],
                   **{"lambda": kw["lam"]}, dt=f"{res['dt']:.6g}", cells=res["cells"],
                   steps_stage1=res["steps1"], steps_stage2=res["steps2"],
                   wall_s=f"{res['wall']:.0f}", cpu_s=f"{res['cpu']:.0f}",
                   Kx=f"{res['Kx']:.6f}", Ky=f"{res['Ky']:.6f}",
                   Kx_gradP=f"{res['Fx_gradP'] / (6 * math.pi * 0.5 * 0.02):.6f}",
                   Ky_gradP=f"{res['Fy_gradP'] / (6 * math.pi * 0.5 * 0.02):.6f}",
                   Kx_last=f"{res['Fx_last'] / (6 * math.pi * 0.5 * 0.02):.6f}",
                   Ky_last=f"{res['Fy_last'] / (6 * math.pi * 0.5 * 0.02):.6f}",
                   Kx_analytic=f"{ka:.6f}", Ky_analytic=f"{kt:.6f}", **provenance())
        print(f"  -> K along the axis {row['Kx']}, across {row['Ky']} "
              f"(wall {row['wall_s']} s, CPU {row['cpu_s']} s)", flush=True)
        with open(csv_path + ".lock", "w") as lock:
            # two campaigns may run at once (different groups): one writer at a time
            fcntl.flock(lock, fcntl.LOCK_EX)
            write_csv(csv_path, [r for r in read_csv(csv_path) if r["name"] != name] + [row],
                      FIELDS)
        case_lock.close()
    if args.quick:
        check_quick(csv_path)


def check_quick(csv_path):
    """The smoke version passes if the coarse drags are within 25 % of the
    box-corrected... simply: finite, positive and ordered as the array theory
    says (K(L = 4) > the unbounded analytic value)."""
    ok = True
    for r in read_csv(csv_path):
        for d in "xy":
            k = float(r[f"K{d}"])
            if not (math.isfinite(k) and 0.8 * float(r[f"K{d}_analytic"]) < k < 2.5):
                print(f"quick: {r['name']} K{d} = {k}: outside (0.8 K_analytic, 2.5)")
                ok = False
    print("quick: " + ("passed" if ok else "FAILED"))
    if not ok:
        sys.exit(1)


def do_single(args):
    import runner
    dt1 = min(0.01, 1.44 / args.cpd ** 2)
    res = runner.run_case(os.path.abspath(args.case), args.ar, "xy", args.box, args.cpd,
                          lam=args.lam, dt1=dt1, tol=args.tol)
    ka, kt = analytic_K(args.ar)
    row = dict(AR=args.ar, L_over_D=args.box, cpd=args.cpd, lam=args.lam, cells=res["cells"],
               Kx=f"{res['Kx']:.10f}", Ky=f"{res['Ky']:.10f}", Kx_analytic=f"{ka:.6f}",
               Ky_analytic=f"{kt:.6f}", wall_s=f"{res['wall']:.1f}",
               cpu_s=f"{res['cpu']:.1f}")
    write_csv(os.path.join(args.case, "drag.csv"), [row])
    print(", ".join(f"{k} {v}" for k, v in row.items()))


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    g = sub.add_parser("single")
    g.add_argument("case")
    g.add_argument("--ar", type=float, default=2.0)
    g.add_argument("--box", type=float, default=4.0)
    g.add_argument("--cpd", type=int, default=8)
    g.add_argument("--lam", type=float, default=1.0)
    g.add_argument("--tol", type=float, default=1e-3)
    r = sub.add_parser("run")
    r.add_argument("--quick", action="store_true")
    r.add_argument("--force", action="store_true")
    r.add_argument("--group", action="append", default=[])
    sub.add_parser("plot")
    args = ap.parse_args()
    if args.cmd == "run":
        do_run(args)
    elif args.cmd == "single":
        do_single(args)
    else:
        import plotDrag
        plotDrag.main(RUNS_CSV, RESULTS)


if __name__ == "__main__":
    main()
