#!/usr/bin/python3
"""Stokes drag of a simple cubic array of fixed spheres: the runs of
validation/periodicArray (see README.md), their table and figures.

    periodicArray.py run [--group G ...] [--force] [--quick] [--out DIR]
    periodicArray.py plot [--out DIR]
    periodicArray.py mesh --phi PHI --cpd N [--position centre|corner]

run:  the runs of the named groups (default: all but the straddle groups),
      one pimpleFoam at a time (serial), in DIR/run/<name>/, each appended to
      DIR/results/runs.csv and skipped by later calls unless --force; then
      `plot`. Groups:
        core      phi 0.027, 0.064, 0.125, 0.216, 0.343 at 8 and 12 cells/D,
                  phi 0.125 and 0.216 at 16 (Zick and Homsy's fractions)
        c8, c12, c16   every fraction of the campaign (0.001 ... 0.4) at
                  8, 12, 16 cells/D
        straddle  phi 0.064 and 0.216 at 12 cells/D on a uniform mesh, the
                  sphere centred (straddle-centre) and centred on a box corner
                  (straddle-corner: it straddles the three periodic
                  boundaries); run only when named: the corner runs need
                  bodies across cyclic patches (README.md)
      --quick: the smoke version, one coarse run (phi 0.216, 6 cells/D) in
      DIR (default validation/periodicArray/run-quick, git-ignored); exits 1
      if K is not within QUICK_BOUND_PCT of Zick and Homsy's.
plot: DIR/results/table.md, metrics.json and the figures from runs.csv
      (plotPeriodicArray.py).
mesh: the mesh a run would use (kind, cells, cells per D), without running it.

DIR defaults to validation/periodicArray (the committed results/).

Units: sphere diameter D = 1, nu = 1, rho_f = 1; superficial velocity
U = 0.02 along x (Re = 0.02) held by OpenFOAM's meanVelocityForce (the mean
of U over the whole box, sphere included). K = F/(6 pi mu a U), a = D/2,
F the sphere's hydrodynamic force along x.
"""
import argparse
import fcntl
import math
import os
import re
import sys
import tempfile
import time
from pathlib import Path

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "stokesDrag"))
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
import caseWriter  # noqa: E402  (validation/stokesDrag)
from validationTools import provenance, read_csv, write_csv  # noqa: E402

if __name__ == "__main__":
    # one module, whether run or imported (plotPeriodicArray imports it): one UserError
    sys.modules.setdefault("periodicArray", sys.modules["__main__"])

U = 0.02                  # the superficial velocity held (Re = U D/nu = 0.02)
LAMBDA = 1.0              # viscous number nu dt/h^2 of the converged stage
TOL = 2e-4                # relative stopping tolerance (Aitken-extrapolated)
QUICK = dict(phi=0.216, cpd=6, tol=1e-3)
QUICK_BOUND_PCT = 6.0     # the smoke run's K within this of Zick and Homsy's
# a box of side L >= REFINED_MIN_L D gets stokesDrag's refined mesh (uniform
# cells of D/n within 0.25 D of the sphere, graded outside); smaller boxes are
# uniform (see mesh_plan)
REFINED_MIN_L = 2.0

# Zick and Homsy (1982), table for the simple cubic array: phi -> K
ZICK_HOMSY = {0.027: 2.008, 0.064: 2.810, 0.125: 4.292, 0.216: 7.442, 0.343: 15.4,
              0.45: 28.1, 0.5236: 42.1}
PHIS_CORE = (0.027, 0.064, 0.125, 0.216, 0.343)
PHIS_ALL = (0.001, 0.008, 0.027, 0.064, 0.125, 0.216, 0.343, 0.4)
CPDS = (8, 12, 16)
PHI_TARGET = 0.2          # the accuracy target covers phi <= 0.2

FIELDS = ["name", "group", "phi", "position", "mesh", "L_over_D", "cpd", "cpd_eff", "cells",
          "lambda", "dt", "steps_stage1", "steps_stage2", "segments", "wall_s", "cpu_s",
          "K", "K_last", "K_gradP", "K_ref", "ref_source", "error_pct", "host", "date",
          "commit"]


class UserError(Exception):
    """Bad input: reported as one line and exit status 1, without a traceback."""


# ---------------------------------------------------------------------------
# references

def expansion_K(phi):
    """Dilute expansion for a simple cubic array (Hasimoto 1959; Sangani and
    Acrivos 1982): 1/K = 1 - 1.7601 phi^(1/3) + phi - 1.5593 phi^2
    + 3.9799 phi^(8/3) - 3.0734 phi^(10/3); K = F/(6 pi mu a U), U the
    superficial velocity."""
    x = phi ** (1 / 3)
    return 1 / (1 - 1.7601 * x + phi - 1.5593 * phi ** 2 + 3.9799 * x ** 8
                - 3.0734 * x ** 10)


def _zick_homsy_interpolant(phi):
    """ln K as a quadratic in ln phi through the three tabulated fractions of
    Zick and Homsy nearest phi: (value, d ln K/d ln phi)."""
    ps = sorted(ZICK_HOMSY, key=lambda p: abs(p - phi))[:3]
    x = math.log(phi)
    xs = [math.log(p) for p in ps]
    val = slope = 0.0
    for i, p in enumerate(ps):
        others = [xs[j] for j in range(3) if j != i]
        den = (xs[i] - others[0]) * (xs[i] - others[1])
        y = math.log(ZICK_HOMSY[p])
        val += y * (x - others[0]) * (x - others[1]) / den
        slope += y * ((x - others[0]) + (x - others[1])) / den
    return math.exp(val), slope


def reference_K(phi):
    """(K_ref, source) at the solid fraction phi: Zick and Homsy's value where
    tabulated; else the dilute expansion for phi <= 0.2 (within 0.06 % of
    Zick and Homsy at their fractions up to 0.125); else ln K interpolated
    quadratically in ln phi through the three nearest tabulated fractions."""
    for p, k in ZICK_HOMSY.items():
        if abs(p - phi) < 1e-9:
            return k, "Zick-Homsy"
    if phi <= PHI_TARGET:
        return expansion_K(phi), "expansion"
    return _zick_homsy_interpolant(phi)[0], "Zick-Homsy interpolated"


def radius_sensitivity(phi):
    """d ln K/d ln a at a fixed box: K = F/(6 pi mu a U) of a sphere of radius
    a(1 + e) is K_ref(phi (1 + e)^3) (1 + e), so a relative error e of the
    sphere's effective radius is an error (1 + 3 d ln K_ref/d ln phi) e of K.
    The slope is the expansion's for phi <= 0.2, the Zick and Homsy
    interpolant's above."""
    if phi <= PHI_TARGET:
        d = 1e-4
        slope = (math.log(expansion_K(phi * (1 + d))) - math.log(expansion_K(phi * (1 - d)))) \
            / (math.log(1 + d) - math.log(1 - d))
    else:
        slope = _zick_homsy_interpolant(phi)[1]
    return 1 + 3 * slope


def box_side(phi):
    """L/D of the cubic cell holding one sphere of diameter D at solid fraction phi."""
    return (math.pi / (6 * phi)) ** (1 / 3)


def tag(phi):
    """0.125 -> '0p125' (for names and JSON keys)."""
    return f"{phi:g}".replace(".", "p")


# ---------------------------------------------------------------------------
# meshes

def mesh_plan(phi, cpd, position="centre", uniform=None):
    """How a run is meshed, as keyword arguments of runner.run_case /
    caseWriter.write_case: dict(kind, box, cpd_eff, kw, n). A box with
    L/D >= REFINED_MIN_L (and a centred sphere) gets caseWriter's refined mesh
    at exactly cpd cells per D. Smaller boxes, and every straddle run, are
    uniform: N = the even number nearest cpd L/D cells per side, h = L/N (the
    sphere's centre and the box corners are mesh points, so the centred and
    the corner sphere see the same grid). caseWriter keeps its fine region
    inside the box; with h = L/N and the fine half-width (N/2 - 1) h (margin
    chosen below), the one graded cell it leaves on each side is of size h:
    the mesh is N^3 uniform cells."""
    box = box_side(phi)
    if uniform is None:
        uniform = position != "centre" or box < REFINED_MIN_L
    kw = {}
    if position == "corner":
        kw["centre"] = (0.5 * box,) * 3
    if not uniform:
        return dict(kind="refined", box=box, cpd_eff=float(cpd), kw=kw, n=None)
    n = 2 * max(2, round(cpd * box / 2))
    cpd_eff = n / box
    # fine half-width ceil((0.5 + margin) cpd_eff) h = ceil(N/2 - 1.5) h = (N/2 - 1) h
    kw["margin"] = (n / 2 - 1.5) / cpd_eff - 0.5
    return dict(kind="uniform", box=box, cpd_eff=cpd_eff, kw=kw, n=n)


def mesh_counts(plan, case=None):
    """(nx, ny, nz) of the mesh caseWriter writes for plan (into case, or a
    temporary folder), from refinedBoxMesh's report."""
    def counts(folder):
        caseWriter.write_case(folder, 1.0, "x", plan["box"], plan["cpd_eff"], 0.01, 1.0,
                              **plan["kw"])
        with open(os.path.join(folder, "log.refinedBoxMesh")) as f:
            m = re.search(r"(\d+) x (\d+) x (\d+) = \d+ cells", f.read())
        return tuple(int(g) for g in m.groups())
    if case is not None:
        return counts(case)
    with tempfile.TemporaryDirectory() as tmp:
        return counts(os.path.join(tmp, "case"))


# ---------------------------------------------------------------------------
# the campaign

def run_name(phi, cpd, position="centre", straddle=False):
    return (("straddle-" if straddle else "") + f"phi{tag(phi)}-c{cpd}"
            + (f"-{position}" if straddle else ""))


def campaign(quick=False):
    """(group, name, settings) of every run."""
    if quick:
        return [("quick", run_name(QUICK["phi"], QUICK["cpd"]), dict(
            phi=QUICK["phi"], cpd=QUICK["cpd"], position="centre", uniform=None,
            tol=QUICK["tol"]))]
    runs = []
    for cpd in CPDS:
        for phi in PHIS_CORE:
            if cpd < 16 or phi in (0.125, 0.216):
                runs.append(("core", run_name(phi, cpd), dict(phi=phi, cpd=cpd)))
    for cpd in CPDS:
        for phi in PHIS_ALL:
            runs.append((f"c{cpd}", run_name(phi, cpd), dict(phi=phi, cpd=cpd)))
    for phi in (0.064, 0.216):
        for position in ("centre", "corner"):
            runs.append((f"straddle-{position}", run_name(phi, 12, position, True),
                         dict(phi=phi, cpd=12, position=position, uniform=True)))
    for _, _, s in runs:
        s.setdefault("position", "centre")
        s.setdefault("uniform", None)
        s.setdefault("tol", TOL)
    return runs


GROUPS = ("core", "c8", "c12", "c16", "straddle", "straddle-centre", "straddle-corner")


def in_groups(group, wanted):
    """A run of the group is selected by its name or by its prefix before '-'
    (straddle selects straddle-centre and straddle-corner)."""
    return any(group == g or group.startswith(g + "-") for g in wanted)


def run_with_retry(case, plan, settings, attempts=5):
    """runner.run_case for one sphere; a solver that cannot load a library
    (the project's libraries being rebuilt in a shared checkout) is started
    again after 60 s."""
    import runner
    cpd = plan["cpd_eff"]
    dt1 = min(0.01, 1.44 / cpd ** 2)   # stage 1 as validation/stokesDrag
    kw = dict(plan["kw"])
    if plan["box"] >= 8 and cpd >= 12:
        # stage 1 (viscous number 1.44) is above the module's limit in a period of 8 D at 12
        # cells/D (1.19, validation/viscousNumber): the phi 0.001 run converges, the limit is
        # raised
        kw["max_viscous_number"] = 1.5
    for attempt in range(attempts):
        try:
            return runner.run_case(case, 1.0, "x", plan["box"], cpd, lam=LAMBDA, u=U, dt1=dt1,
                                   tol=settings["tol"], **kw)
        except RuntimeError:
            log = os.path.join(case, "log.solver")
            text = open(log).read() if os.path.exists(log) else ""
            if attempt + 1 < attempts and ("error while loading shared libraries" in text
                                           or "Could not load" in text
                                           or "file too short" in text):
                print("  (a library is being rebuilt: the run starts again in 60 s)",
                      flush=True)
                time.sleep(60)
                continue
            raise


def do_run(out, groups, force, quick, phis=()):
    results = os.path.join(out, "results")
    csv_path = os.path.join(results, "runs.csv")
    os.makedirs(results, exist_ok=True)
    wanted = groups or [g for g in GROUPS if not g.startswith("straddle")]
    for group, name, s in campaign(quick):
        if not quick and not in_groups(group, wanted):
            continue
        if phis and not any(abs(s["phi"] - p) <= 1e-9 for p in phis):
            continue
        done = {r["name"] for r in read_csv(csv_path)}
        if name in done and not force:
            print(f"{name}: in {os.path.relpath(csv_path)}, skipped", flush=True)
            continue
        case = os.path.join(out, "run", name)
        os.makedirs(os.path.dirname(case), exist_ok=True)
        plan = mesh_plan(s["phi"], s["cpd"], s["position"], s["uniform"])
        print(f"{name} ({group}): phi {s['phi']:g}, L/D {plan['box']:.4f}, {plan['kind']} mesh, "
              f"{plan['cpd_eff']:.3f} cells/D, sphere at the box "
              f"{'corner' if s['position'] == 'corner' else 'centre'}", flush=True)
        res = run_with_retry(case, plan, s)
        if plan["n"] is not None and res["cells"] != plan["n"] ** 3:
            raise RuntimeError(f"{case}: {res['cells']} cells, the uniform mesh has "
                               f"{plan['n']}^3 (caseWriter's fine region changed?)")
        norm = 6 * math.pi * 0.5 * U           # 6 pi mu a U
        k_ref, source = reference_K(s["phi"])
        row = dict(name=name, group=group, phi=f"{s['phi']:g}", position=s["position"],
                   mesh=plan["kind"], L_over_D=f"{plan['box']:.6f}", cpd=s["cpd"],
                   cpd_eff=f"{plan['cpd_eff']:.4f}", cells=res["cells"],
                   **{"lambda": LAMBDA}, dt=f"{res['dt']:.6g}", steps_stage1=res["steps1"],
                   steps_stage2=res["steps2"], segments=res["segments"],
                   wall_s=f"{res['wall']:.0f}", cpu_s=f"{res['cpu']:.0f}",
                   K=f"{res['Kx']:.6f}", K_last=f"{res['Fx_last'] / norm:.6f}",
                   K_gradP=f"{res['Fx_gradP'] / norm:.6f}", K_ref=f"{k_ref:.6g}",
                   ref_source=source, error_pct=f"{100 * (res['Kx'] / k_ref - 1):.4f}",
                   **provenance())
        print(f"  -> K {row['K']} (reference {row['K_ref']}, {row['ref_source']}: "
              f"{float(row['error_pct']):+.3f} %; wall {row['wall_s']} s, CPU {row['cpu_s']} s)",
              flush=True)
        with open(csv_path + ".lock", "w") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)      # one writer at a time
            write_csv(csv_path, [r for r in read_csv(csv_path) if r["name"] != name] + [row],
                      FIELDS)
    return csv_path


def check_quick(csv_path):
    """The smoke run passes if K is finite and within QUICK_BOUND_PCT of Zick
    and Homsy's."""
    ok = True
    for r in read_csv(csv_path):
        k, e = float(r["K"]), float(r["error_pct"])
        if not (math.isfinite(k) and abs(e) < QUICK_BOUND_PCT):
            print(f"quick: {r['name']}: K = {k} ({e:+.2f} % from {r['K_ref']}), outside "
                  f"{QUICK_BOUND_PCT:g} %")
            ok = False
    print("quick: " + ("passed" if ok else "FAILED"))
    if not ok:
        sys.exit(1)


def do_mesh(phi, cpd, position):
    plan = mesh_plan(phi, cpd, position)
    nx, ny, nz = mesh_counts(plan)
    print(f"phi {phi:g}: L/D {plan['box']:.4f}, {plan['kind']} mesh {nx} x {ny} x {nz} = "
          f"{nx * ny * nz} cells, {plan['cpd_eff']:.4f} cells/D near the sphere")


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("run")
    r.add_argument("--group", action="append", default=[])
    r.add_argument("--force", action="store_true")
    r.add_argument("--quick", action="store_true")
    r.add_argument("--phi", type=float, action="append", default=[],
                   help="only the runs of this solid fraction (repeatable)")
    r.add_argument("--out")
    p = sub.add_parser("plot")
    p.add_argument("--out")
    m = sub.add_parser("mesh")
    m.add_argument("--phi", type=float, required=True)
    m.add_argument("--cpd", type=float, required=True)
    m.add_argument("--position", choices=("centre", "corner"), default="centre")
    args = ap.parse_args()
    try:
        if args.cmd == "mesh":
            if not 0 < args.phi <= math.pi / 6:
                raise UserError(f"--phi {args.phi}: a simple cubic array needs "
                                f"0 < phi <= pi/6 = {math.pi / 6:.4f}")
            if args.cpd < 3:
                raise UserError(f"--cpd {args.cpd}: at least 3 cells per diameter")
            do_mesh(args.phi, args.cpd, args.position)
            return
        out = os.path.abspath(args.out) if args.out else (
            os.path.join(HERE, "run-quick") if getattr(args, "quick", False) else HERE)
        if args.cmd == "run":
            bad = [g for g in args.group if g not in GROUPS]
            if bad:
                raise UserError(f"unknown group(s) {', '.join(bad)} (groups: {', '.join(GROUPS)})")
            if args.quick and args.group:
                raise UserError("--quick runs its own case: no --group with it")
            csv_path = do_run(out, args.group, args.force, args.quick, args.phi)
        import plotPeriodicArray
        plotPeriodicArray.main(out)
        if args.cmd == "run" and args.quick:
            check_quick(csv_path)
    except UserError as e:
        sys.exit(f"periodicArray.py: {e}")
    except RuntimeError as e:        # a run that failed: the runner names the case and log
        sys.exit(f"periodicArray.py: {e}")


if __name__ == "__main__":
    main()
