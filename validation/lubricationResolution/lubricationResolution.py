#!/usr/bin/python3
"""The film force of a sphere approaching a wall: resolved flow plus the lubrication
correction, against Brenner's exact Stokes force (validation/lubricationResolution).

A sphere of diameter d = 1 (nu = 1, rho_f = 1, mu = 1) moves towards the bottom wall with a
prescribed velocity that keeps the gap on h(t) = h0 exp(-t/tau): U = -h/tau, so every decade
of gap takes the same number of steps, and the Reynolds number U d/nu stays below h0/tau. The
force the module puts on the body, hydrodynamic plus collision (the lubrication correction
of `lubricationContact` and the film correction), divided by 6 pi mu a |U|, is compared at
every step with Brenner (1961):

    lambda(alpha) = (4/3) sinh(alpha) sum_n n (n+1)/((2n-1)(2n+3))
                    [(2 sinh((2n+1) alpha) + (2n+1) sinh(2 alpha))
                     / (4 sinh^2((n+1/2) alpha) - (2n+1)^2 sinh^2(alpha)) - 1],
    cosh(alpha) = 1 + h/a.

    lubricationResolution.py run [--cpd N] [--quick] [--force]   one resolution
    lubricationResolution.py plot        results/table.md, metrics.json, force.png

Each finished run appends a row to results/runs.csv (CPU time, host, commit) and keeps its
force history as results/c<N>.csv (gap/d, U, F_hydro, F_collision, F_total, Brenner).
"""
import argparse
import json
import math
import os
import shutil
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
from validationTools import (cpu_seconds, provenance, read_csv, refined_box_mesh,  # noqa: E402
                             run_logged, write_csv, write_dict)

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "results")
RUNS = os.path.join(HERE, "run")
RUNS_CSV = os.path.join(RESULTS, "runs.csv")
TITLE = "spheroidFoam validation: a sphere approaching a wall (validation/lubricationResolution)"

A = 0.5                 # sphere radius (d = 1)
H0 = 2.5                # start gap / d; the comparison starts at GAP_MAX
GAP_MAX, GAP_MIN = 2.0, 1e-3
TAU = 50.0              # e-folding time of the gap, in d^2/nu
LAMBDA = 1.0            # nu dt/h^2
TABLE_DT = 0.25         # spacing of the velocity table (linear interpolation: 3e-6 of U)
BOX_HALF, BOX_TOP = 6.0, 12.0
FIELDS = ["name", "cpd", "cells", "dt", "steps", "tau", "max_abs_error_pct",
          "max_abs_error_pct_hydro_only", "wall_s", "cpu_s", "host", "date", "commit"]


def brenner(gap):
    """Brenner's (1961) F/(6 pi mu a U) of a sphere approaching a plane at the gap (units of
    the radius a = 1 here: gap/a), the series summed until its terms fall below 1e-14."""
    alpha = math.acosh(1 + gap)
    s = 0.0
    n = 1
    while True:
        k = 2 * n + 1
        num = 2 * math.sinh(k * alpha) + k * math.sinh(2 * alpha)
        den = 4 * math.sinh((n + 0.5) * alpha) ** 2 - k * k * math.sinh(alpha) ** 2
        term = n * (n + 1) / ((2 * n - 1) * (2 * n + 3)) * (num / den - 1)
        s += term
        if abs(term) < 1e-14 * abs(s) or n > 100000:
            break
        n += 1
    return 4.0 / 3.0 * math.sinh(alpha) * s


def velocity_table(end_time):
    """The prescribed velocity as a Function1 table: U_z = -h(t)/tau every TABLE_DT."""
    rows = []
    n = int(math.ceil(end_time / TABLE_DT)) + 2
    for i in range(n):
        t = i * TABLE_DT
        rows.append(f"        ({t:.12g} (0 0 {-H0 * math.exp(-t / TAU) / TAU:.12g}))")
    return "\n".join(rows)


def write_case(case, cpd, quick):
    h = 1.0 / cpd
    top_fine = math.ceil((H0 + 1.0 + 0.25) / h) * h
    fine = math.ceil((A + 0.25) / h) * h
    refined_box_mesh(case, [
        "--box", *map(str, (-BOX_HALF, BOX_HALF, -BOX_HALF, BOX_HALF, 0.0, BOX_TOP)),
        "--fine", *(f"{v:.12g}" for v in (-fine, fine, -fine, fine, 0.0, top_fine)),
        "--h", f"{h:.12g}", "--growth", "1.15", "--max-ratio", "16",
        "--patch", "xMin:wall", "--patch", "xMax:wall", "--patch", "yMin:wall",
        "--patch", "yMax:wall", "--patch", "zMin:wall", "--patch", "zMax:patch"])
    dt = LAMBDA * h * h
    end_time = TAU * math.log(H0 / (0.5 * GAP_MIN)) if not quick else 0.5 * TAU
    w = lambda rel, cls, obj, body: write_dict(  # noqa: E731
        os.path.join(case, *rel.split("/")), cls, rel.split("/")[0], obj, body, TITLE)
    w("system/controlDict", "dictionary", "controlDict", f"""\
application     immersedSpheroidFoam;

startFrom       latestTime;
startTime       0;
stopAt          endTime;
endTime         {end_time:.12g};
deltaT          {dt:.12g};

writeControl    timeStep;
writeInterval   100000000;
purgeWrite      0;
writeFormat     binary;
writePrecision  12;
writeCompression off;
timeFormat      general;
timePrecision   12;
runTimeModifiable false;
""")
    w("system/fvSchemes", "dictionary", "fvSchemes", """\
ddtSchemes           { default Euler; }
gradSchemes          { default Gauss linear; }
divSchemes
{
    default         none;
    div(phi,U)      Gauss linear;
    div((nuEff*dev2(T(grad(U))))) Gauss linear;
}
laplacianSchemes     { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes        { default corrected; }
""")
    w("system/fvSolution", "dictionary", "fvSolution", """\
solvers
{
    p     { solver GAMG; smoother DIC; tolerance 1e-9; relTol 0; }
    pFinal { $p; }
    "(U|UFinal)" { solver PBiCGStab; preconditioner DILU; tolerance 1e-10; relTol 0; }
}

PIMPLE
{
    momentumPredictor yes;
    nOuterCorrectors 1;
    nCorrectors     2;
    nNonOrthogonalCorrectors 0;
}
""")
    w("constant/transportProperties", "dictionary", "transportProperties",
      "transportModel  Newtonian;\n\nnu              1;\n")
    w("constant/turbulenceProperties", "dictionary", "turbulenceProperties",
      "simulationType  laminar;\n")
    w("constant/g", "uniformDimensionedVectorField", "g",
      "dimensions      [0 1 -2 0 0 0 0];\nvalue           (0 0 0);\n")
    w("constant/immersedBodiesProperties", "dictionary", "immersedBodiesProperties", f"""\
fluidDensity    1;

bodies
{{
    sphere
    {{
        semiAxes        ({A} {A} {A});
        density         1;
        centre          (0 0 {A + H0:.12g});
        motion
        {{
            type            prescribed;
            velocity        table
            (
{velocity_table(end_time)}
            );
            angularVelocity constant (0 0 0);
        }}
    }}
}}

collision
{{
    type            lubricationContact;
    walls           (zMin);
}}

output
{{
    timeSeries      yes;
    surfaces        no;
}}
""")
    w("0/U", "volVectorField", "U", """\
dimensions      [0 1 -1 0 0 0 0];
internalField   uniform (0 0 0);
boundaryField
{
    zMax            { type pressureInletOutletVelocity; value uniform (0 0 0); }
    ".*"            { type noSlip; }
}
""")
    w("0/p", "volScalarField", "p", """\
dimensions      [0 2 -2 0 0 0 0];
internalField   uniform 0;
boundaryField
{
    zMax            { type fixedValue; value uniform 0; }
    ".*"            { type zeroGradient; }
}
""")
    return {"dt": dt, "end_time": end_time}


def analyse(h5):
    """Per step: gap/d, U_z, the hydrodynamic, collision and total force along z over
    6 pi mu a |U|, and Brenner's value."""
    import h5py
    with h5py.File(h5, "r", locking=False) as f:
        centre = f["centre"][:, 0, :]
        vel = f["velocity"][:, 0, :]
        fh = f["hydroForce"][:, 0, :]
        fc = f["collisionForce"][:, 0, :]
    gap = centre[:, 2] - A
    u = vel[:, 2]
    scale = 6 * math.pi * A * np.abs(u)
    out = {"gap": gap, "u": u, "hydro": fh[:, 2] / scale, "collision": fc[:, 2] / scale}
    out["total"] = out["hydro"] + out["collision"]
    out["brenner"] = np.array([brenner(x / A) for x in gap])
    return out


def run_one(cpd, force, quick):
    name = f"c{cpd}" + ("-quick" if quick else "")
    case = os.path.join(RUNS, name)
    if os.path.isdir(case) and force:
        shutil.rmtree(case)
    if not os.path.isdir(case):
        os.makedirs(case)
        info = write_case(case, cpd, quick)
        with open(os.path.join(case, "info.json"), "w") as f:
            json.dump(info, f)
    if run_logged(["blockMesh"], case, "log.blockMesh") != 0:
        sys.exit(f"lubricationResolution: blockMesh failed in {case}")
    if run_logged(["immersedSpheroidFoam"], case, "log.solver") != 0:
        sys.exit(f"lubricationResolution: the solver failed in {case} (log.solver)")
    h5 = os.path.join(case, "postProcessing", "immersedBodies", "bodies.h5")
    x = analyse(h5)
    sel = (x["gap"] <= GAP_MAX) & (x["gap"] >= GAP_MIN) & (np.abs(x["u"]) > 0)
    err = 100 * (x["total"][sel] / x["brenner"][sel] - 1)
    err_h = 100 * (x["hydro"][sel] / x["brenner"][sel] - 1)
    print(f"{name}: {sel.sum()} steps with gap/d in [{GAP_MIN}, {GAP_MAX}], "
          f"largest |error| {np.abs(err).max():.1f} % (hydrodynamic force alone "
          f"{np.abs(err_h).max():.1f} %)")
    if quick:
        return
    os.makedirs(RESULTS, exist_ok=True)
    np.savetxt(os.path.join(RESULTS, f"{name}.csv"),
               np.column_stack([x["gap"], x["u"], x["hydro"], x["collision"], x["total"],
                                x["brenner"]]),
               delimiter=",", header="gap_over_d,U,F_hydro,F_collision,F_total,Brenner "
               "(forces over 6 pi mu a |U|)", fmt="%.8g")
    info = json.load(open(os.path.join(case, "info.json")))
    row = {"name": name, "cpd": cpd, "cells": "", "dt": info["dt"], "steps": len(x["gap"]),
           "tau": TAU, "max_abs_error_pct": f"{np.abs(err).max():.2f}",
           "max_abs_error_pct_hydro_only": f"{np.abs(err_h).max():.2f}",
           "cpu_s": f"{cpu_seconds(case, 'log.solver'):.0f}", "wall_s": "", **provenance()}
    rows = [r for r in read_csv(RUNS_CSV) if r["name"] != name] + [row]
    write_csv(RUNS_CSV, rows, FIELDS, ignore_extra=True)


def do_plot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = sorted(read_csv(RUNS_CSV, missing_ok=False), key=lambda r: int(r["cpd"]))
    lines = ["| cells/d | steps | largest error, resolved + correction | resolved alone | CPU |",
             "|---|---|---|---|---|"]
    fig, axs = plt.subplots(1, 2, figsize=(11, 4))
    g = np.logspace(math.log10(GAP_MIN), math.log10(GAP_MAX), 200)
    axs[0].loglog(g, [brenner(x / A) for x in g], "k-", label="Brenner (1961), exact")
    for r in rows:
        d = np.loadtxt(os.path.join(RESULTS, f"{r['name']}.csv"), delimiter=",")
        sel = (d[:, 0] <= GAP_MAX) & (d[:, 0] >= GAP_MIN)
        axs[0].loglog(d[sel, 0], d[sel, 4], "-", label=f"{r['cpd']} cells/d: resolved + correction")
        axs[0].loglog(d[sel, 0], d[sel, 2], ":", label=f"{r['cpd']} cells/d: resolved alone")
        axs[1].semilogx(d[sel, 0], 100 * (d[sel, 4] / d[sel, 5] - 1), label=f"{r['cpd']} cells/d")
        lines.append(f"| {r['cpd']} | {r['steps']} | {float(r['max_abs_error_pct']):.1f} % | "
                     f"{float(r['max_abs_error_pct_hydro_only']):.1f} % | {r['cpu_s']} s |")
    axs[0].set_xlabel("gap h / d")
    axs[0].set_ylabel("F / (6 pi mu a U)")
    axs[1].set_xlabel("gap h / d")
    axs[1].set_ylabel("error against Brenner [%]")
    axs[1].axhspan(-10, 10, color="0.9")
    for ax in axs:
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle("Sphere approaching a wall in Stokes flow: resolved force plus lubrication "
                 "correction")
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "force.png"), dpi=120)
    with open(os.path.join(RESULTS, "table.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    metrics = {"max_abs_force_error_pct": max(float(r["max_abs_error_pct"]) for r in rows),
               "resolutions": len(rows)}
    for r in rows:
        metrics[f"max_abs_force_error_pct_{r['cpd']}"] = float(r["max_abs_error_pct"])
    with open(os.path.join(RESULTS, "metrics.json"), "w") as f:
        json.dump(metrics, f, indent=1, sort_keys=True)
        f.write("\n")
    print("\n".join(lines))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sp = ap.add_subparsers(dest="cmd", required=True)
    r = sp.add_parser("run")
    r.add_argument("--cpd", type=int, default=8, choices=[4, 8, 12, 16])
    r.add_argument("--quick", action="store_true")
    r.add_argument("--force", action="store_true")
    sp.add_parser("plot")
    a = ap.parse_args()
    if a.cmd == "run":
        run_one(a.cpd, a.force, a.quick)
    else:
        do_plot()


if __name__ == "__main__":
    main()
