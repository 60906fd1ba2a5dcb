#!/usr/bin/python3
"""Hindered settling of free spheres in a triply periodic box against Richardson-Zaki
(validation/hinderedSettling, see README.md).

    hinderedSettling.py reference [--cpd N] [--domain-scale S] [--out DIR]
    hinderedSettling.py run [--only NAME ...] [--force | --analyse] [--out DIR]
    hinderedSettling.py array [--out DIR]
    hinderedSettling.py held [--out DIR]
    hinderedSettling.py plot [--out DIR]
    hinderedSettling.py quick [--out DIR]
    (every command also takes --ga GA: the Galileo number of a new DIR, default 20, and
    --ddt Euler|backward: the time scheme of a new DIR, default the tutorial's; the
    reference, a steady fixed sphere, keeps its own; and --collision
    lubricationContact|contact: the collision model of a new DIR, default the tutorial's
    lubricationContact, contact being the same contact without the lubrication correction)

reference: the single sphere's terminal velocity on the mesh of the suspensions (cpd
     cells per D): the sphere held fixed in a uniform stream (validation/finiteReynoldsDrag's
     case, the frame of a sphere settling steadily) at the Reynolds number where its measured
     drag equals its net weight, (3/4) C_D Re^2 = Ga^2. Each call runs the sphere at the
     Reynolds number predicted from the runs already made at that cpd (the Schiller-Naumann
     curve for the first), until the balance is met to 1e-3 (at most three runs); rows in
     results/reference.csv.
run: the suspensions of the campaign in run/<name>/, one solver at a time (serial); each
     ends at a fixed simulated time, so two identical runs give the same figures. A finished
     run is appended to results/runs.csv with its settling history (results/<name>.dat) and
     skipped next time unless --force; an interrupted one, or one whose end time the
     campaign has raised, continues from its last written time. --analyse: the finished
     runs' rows and histories again from their cases, nothing run.
array: the check of the zero-flux frame, a simple cubic array of spheres settling in Stokes
     flow against the fixed array of ../periodicArray on the same mesh (results/array.csv;
     about 20 s).
held: the moving sphere against the fixed one at Re_t: the free sphere of single-c8-L4 and
     single-c12-L4 against the same sphere held fixed in the same box and mesh with its
     settling speed held as the superficial velocity (results/held.csv; about 3 and 10 min).
plot: results/table.md, results/metrics.json, hindrance.png and settling.png.
quick: the smoke version (12 spheres in a 4 D box at 4 cells per D, 4 D/V_g, about 20 s;
     the Schiller-Naumann terminal velocity stands in for the reference run) into DIR
     (default run-quick/), then plot into DIR/results.

Units: D = 1, rho_f = 1, |g| = 1, rho_p/rho_f = RATIO, nu = sqrt((RATIO - 1) g D^3)/GA, so the
gravitational velocity V_g = sqrt((RATIO - 1) g D) = 1 and times are in D/V_g. DIR/results/
parameters.json records the Galileo number of DIR and its time scheme and collision model if
not the tutorial's
(its other values are fixed here); at a Galileo number other than 20 the campaign is the three
core runs.
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np

if __name__ == "__main__":
    # one module, whether run or imported (plotHinderedSettling imports it): one GA
    sys.modules.setdefault("hinderedSettling", sys.modules["__main__"])

HERE = Path(__file__).resolve().parent
TOP = HERE.parents[1]
TUTORIAL = TOP / "tutorials" / "periodicSuspension"
sys.path.insert(0, str(HERE.parent / "tools"))
sys.path.insert(0, str(HERE.parent / "finiteReynoldsDrag"))
sys.path.insert(0, str(TUTORIAL))
from validationTools import (cpu_seconds, execution_times, locked,  # noqa: E402
                             merge_row, mesh_cells, provenance, read_csv, run_logged,
                             set_entry, write_csv, write_dict)

DEFAULT_GA = 20.0         # Galileo number sqrt((rho_p/rho_f - 1) g D^3)/nu
RATIO = 2.0               # rho_p/rho_f
GA = DEFAULT_GA           # of the results folder in use (set_galileo)
NU = math.sqrt(RATIO - 1.0) / GA
DDT = None                # time scheme of the results folder in use (None: the tutorial's)
DDT_SCHEMES = ("Euler", "backward")
COLLISION = "lubricationContact"   # collision model of the results folder in use
COLLISION_MODELS = ("lubricationContact", "contact")   # the tutorial's; without lubrication
PARAMETERS = "parameters.json"   # the Galileo number of a results folder
END_TIME = 100.0          # D/V_g, of the side runs
CORE_END_TIME = 200.0     # D/V_g, of the core runs and the second packing
WRITE_INTERVAL = 25.0     # D/V_g, of the fields (restart points)
AVERAGE_FROM = 30.0       # the statistics are taken from here to the run's end
BATCHES = 5               # for the standard error of the mean settling speed
BALANCE_TOLERANCE = 1e-3  # the reference's |(3/4) C_D Re^2/Ga^2 - 1|
SOLVER_LOG = "log.immersedSpheroidFoam"   # the name summarise.read_log reads
TITLE = "spheroidFoam validation: hindered settling (validation/hinderedSettling)"

RUN_FIELDS = ["name", "phi_nominal", "phi", "bodies", "L", "cpd", "seed", "cells", "steps",
              "average_from", "end_time", "w", "w_se", "w_first_half", "w_second_half",
              "g_near_vertical", "g_near_horizontal", "g_near_start", "rms_w", "rms_h",
              "flux_residue", "max_force_over_weight", "max_overlap", "cpu_s", "host", "date",
              "commit"]
ARRAY_FIELDS = ["name", "phi", "L", "cells", "cpd_eff", "dt", "steps", "w", "w_change",
                "K_settling", "K_fixed", "K_ref", "ref_source", "difference_pct", "error_pct",
                "flux_residue", "cpu_s", "host", "date", "commit"]
# the settling array: Stokes flow (Re = W D/nu <= 0.02), one sphere per periodic box
ARRAY_NU = 1.0
ARRAY_STOKES_SPEED = 0.02  # (rho_p - rho_f) g D^2/(18 mu) of the sphere alone
ARRAY_END = 3.0            # D^2/nu: about 20 relaxation times of the sphere and the box
ARRAY_RUNS = [(phi, cpd) for phi in (0.125, 0.216) for cpd in (8, 12)]
# the moving sphere against the fixed one at Re_t (do_held)
HELD_FREE = ("single-c8-L4", "single-c12-L4")
HELD_FIELDS = ["name", "free", "W", "Re", "force_over_weight", "force_change", "difference_pct",
               "slope", "velocity_equivalent_pct", "cells", "steps", "cpu_s", "host", "date",
               "commit"]
REF_FIELDS = ["name", "cpd", "domain_scale", "Re", "C_D", "balance", "cells", "steps",
              "C_D_change_pct", "cpu_s", "host", "date", "commit"]


def campaign():
    """(name, parameters) of the suspensions: the three solid fractions at 8 cells per D in a
    6 D box, at phi 0.1 12 cells per D, and one sphere per 4 D box (the free sphere of the
    held check); at the default Galileo number also, at phi 0.1, a second packing and a
    larger box, and one sphere per box of 6 D and at 12 cells per D."""
    runs = [(f"phi{phi:g}-c8-L6-s1", dict(phi=phi, cpd=8, L=6, seed=1, end_time=CORE_END_TIME))
            for phi in (0.05, 0.1, 0.2)]
    single = [(f"single-c{cpd}-L{L}", dict(phi=round(math.pi / (6 * L ** 3), 8), cpd=cpd, L=L,
                                            seed=1))
              for cpd, L in ((8, 4), (8, 6), (12, 4))]
    # the resolution check over the core runs' window
    fine = [("phi0.1-c12-L6-s1", dict(phi=0.1, cpd=12, L=6, seed=1, end_time=CORE_END_TIME))]
    if GA != DEFAULT_GA:
        return runs + fine + single[:1]
    runs += [("phi0.1-c8-L6-s2", dict(phi=0.1, cpd=8, L=6, seed=2, end_time=CORE_END_TIME)),
             ("phi0.1-c8-L8-s1", dict(phi=0.1, cpd=8, L=8, seed=1))] + fine
    # one sphere per box (a simple cubic array settling): how much its own images hinder it
    return runs + single


def set_galileo(results, ga):
    """The Galileo number of the results folder: ga (None: the folder's own, else the
    default), recorded in results/parameters.json; a folder keeps the Ga it was made with."""
    global GA, NU
    import json
    path = os.path.join(results, PARAMETERS)
    if ga is not None and not (math.isfinite(ga) and ga > 0):
        sys.exit(f"hinderedSettling: --ga {ga:g}: the Galileo number must be finite and > 0")
    recorded = json.load(open(path))["Ga"] if os.path.exists(path) else None
    if ga is not None and recorded is not None and ga != recorded:
        sys.exit(f"hinderedSettling: {path} holds Ga {recorded:g}, not --ga {ga:g}; use another "
                 f"--out for another Galileo number")
    GA = float(ga if ga is not None else recorded if recorded is not None else DEFAULT_GA)
    NU = math.sqrt(RATIO - 1.0) / GA
    if recorded is None:
        os.makedirs(results, exist_ok=True)
        with open(path, "w") as f:
            json.dump({"Ga": GA, "density_ratio": RATIO}, f)
            f.write("\n")


def set_folder_choice(results, key, flag, value, default):
    """The setting key of the results folder: value (None: the folder's own, else default),
    recorded in results/parameters.json when it is not the default; a folder keeps the one
    it was made with, so that its runs share it."""
    import json
    path = os.path.join(results, PARAMETERS)
    params = json.load(open(path)) if os.path.exists(path) else {}
    recorded = params.get(key)
    if value is not None and value != (recorded or default) and os.path.exists(
            os.path.join(results, "runs.csv")):
        made = recorded or default or "of the tutorial"
        sys.exit(f"hinderedSettling: {results} has runs made with {key} {made}; "
                 f"use another --out for {flag} {value}")
    chosen = value if value is not None else recorded
    if chosen is not None and chosen != default and recorded is None:
        params[key] = chosen
        with open(path, "w") as f:
            json.dump(params, f)
            f.write("\n")
    return None if chosen == default else chosen


def rowe(re_t):
    """Richardson-Zaki exponent of Rowe (1987)."""
    return (4.7 + 0.41 * re_t ** 0.75) / (1 + 0.175 * re_t ** 0.75)


def schiller_naumann_cd(re):
    return 24.0 / re * (1 + 0.15 * re ** 0.687)


def balance(re, cd):
    """(3/4) C_D Re^2/Ga^2: 1 at the terminal velocity."""
    return 0.75 * cd * re * re / (GA * GA)


def predicted_re(rows):
    """The terminal Reynolds number from the reference runs rows (dicts with Re, C_D): the
    two runs nearest to balance interpolated linearly in ln(C_D Re^2) against ln Re; one run:
    its C_D scaled along the Schiller-Naumann curve; none: Schiller-Naumann alone."""
    pts = sorted(((abs(math.log(balance(r["Re"], r["C_D"]))), r["Re"], r["C_D"]) for r in rows))
    if len(pts) >= 2 and pts[0][1] != pts[1][1]:
        (_, r1, c1), (_, r2, c2) = pts[:2]
        y1, y2 = math.log(balance(r1, c1)), math.log(balance(r2, c2))
        return math.exp(math.log(r1) - y1 * (math.log(r2) - math.log(r1)) / (y2 - y1))
    scale = pts[0][2] / schiller_naumann_cd(pts[0][1]) if pts else 1.0
    lo, hi = 1e-6, 1e4
    for _ in range(200):
        mid = math.sqrt(lo * hi)
        lo, hi = (mid, hi) if balance(mid, scale * schiller_naumann_cd(mid)) < 1 else (lo, mid)
    return math.sqrt(lo * hi)


# ---------------------------------------------------------------------------
# the single sphere

def reference_rows(results, cpd, domain_scale=1.0):
    rows = [r for r in read_csv(os.path.join(results, "reference.csv"))
            if int(r["cpd"]) == cpd and float(r["domain_scale"]) == domain_scale]
    for r in rows:
        r["Re"], r["C_D"] = float(r["Re"]), float(r["C_D"])
    return rows


def terminal_re(results, cpd, domain_scale=1.0):
    """The measured terminal Reynolds number at cpd (None without reference runs)."""
    rows = reference_rows(results, cpd, domain_scale)
    return predicted_re(rows) if rows else None


def do_reference(args):
    import finiteReynoldsDrag as frd
    import caseWriter
    results = os.path.join(args.out, "results")
    os.makedirs(results, exist_ok=True)
    domain = caseWriter.scaled_domain(args.domain_scale)
    for _ in range(3):
        rows = reference_rows(results, args.cpd, args.domain_scale)
        if len(rows) >= 2 and min(abs(balance(r["Re"], r["C_D"]) - 1) for r in rows) \
                < BALANCE_TOLERANCE:
            break
        if not rows:   # start from the other domain's runs at this cpd, if any
            rows = reference_rows(results, args.cpd, 1.0 if args.domain_scale != 1.0 else 2.0)
        reynolds = round(predicted_re(rows), 4)
        name = f"sphere-c{args.cpd}-x{args.domain_scale:g}-Re{reynolds:g}"
        row, _ = frd.run_case(os.path.join(args.out, "run", name), 1.0, 0, reynolds, args.cpd,
                              domain=domain)
        cd = float(row["C_D"])
        out = dict(name=name, cpd=args.cpd, domain_scale=args.domain_scale, Re=reynolds,
                   C_D=row["C_D"], balance=f"{balance(reynolds, cd):.6f}", cells=row["cells"],
                   steps=row["steps"], C_D_change_pct=row["C_D_change_pct"],
                   cpu_s=row["cpu_s"], **provenance())
        print(f"{name}: C_D {cd:.5f}, (3/4) C_D Re^2/Ga^2 = {balance(reynolds, cd):.5f}",
              flush=True)
        path = os.path.join(results, "reference.csv")
        with locked(path):
            write_csv(path, read_csv(path) + [out], REF_FIELDS)
    rows = reference_rows(results, args.cpd, args.domain_scale)
    miss = min(abs(balance(r["Re"], r["C_D"]) - 1) for r in rows)
    re_t = terminal_re(results, args.cpd, args.domain_scale)
    print(f"terminal Re at {args.cpd} cells/D (domain x{args.domain_scale:g}): {re_t:.5f}, "
          f"V_t = {re_t * NU:.5f} V_g")
    if miss >= BALANCE_TOLERANCE:
        sys.exit(f"hinderedSettling reference: not converged after {len(rows)} runs at "
                 f"{args.cpd} cells/D (domain x{args.domain_scale:g}): the nearest run's "
                 f"(3/4) C_D Re^2/Ga^2 is {miss:.2e} from 1, tolerance {BALANCE_TOLERANCE:g}; "
                 f"the terminal Re above is interpolated (call reference again for another "
                 f"three runs)")


# ---------------------------------------------------------------------------
# the suspensions

def write(path, cls, loc, obj, body):
    write_dict(path, cls, loc, obj, body, TITLE)


def write_case(case, phi, cpd, L, seed, end_time, write_interval=WRITE_INTERVAL, single=None):
    """The periodicSuspension tutorial's numerics (fvSchemes, fvSolution, the cyclic box
    of blockMeshDict, 0/) with spheres of diameter 1 at the units of this validation; the
    fields written every write_interval (the steps are adjusted to land on the writes, so
    a run whose end time is a multiple of it ends there exactly, and whatever the end time,
    a run takes the same steps; an interrupted or extended run resumes from the last
    write). single: None, or dict(n, nu, g, dt, motion, ubar) for one sphere at the centre
    of a box of n^3 cells, viscosity nu, gravity g, fixed steps dt (None: the suspensions'
    Courant-limited steps), motion free or fixed, and ubar: None (meanFlow zeroFlux) or the
    superficial velocity along z held by OpenFOAM's meanVelocityForce."""
    os.makedirs(case)
    shutil.copytree(TUTORIAL / "system", os.path.join(case, "system"))
    shutil.copytree(TUTORIAL / "0.orig", os.path.join(case, "0"))
    if DDT is not None:
        schemes = os.path.join(case, "system", "fvSchemes")
        text, n = re.subn(r"(ddtSchemes\s*\{\s*default\s+)\w+;", rf"\g<1>{DDT};",
                          open(schemes).read())
        if n != 1:
            sys.exit(f"hinderedSettling: no ddtSchemes default in {schemes}")
        open(schemes, "w").write(text)
    os.makedirs(os.path.join(case, "constant"))
    single = dict(dict(dt=None, motion="free", ubar=None), **single) if single else None
    n = single["n"] if single else cpd * L
    if n != int(n):
        sys.exit(f"hinderedSettling: cells per side {n} is not an integer (cpd {cpd}, L {L})")
    nu, g = (single["nu"], single["g"]) if single else (NU, 1.0)
    steps = (f"deltaT          {single['dt']:.12g};\nadjustTimeStep  no;\n"
             if single and single["dt"] else
             "deltaT          0.01;\nadjustTimeStep  yes;\nmaxCo           0.5;\n"
             "maxDeltaT       0.1;\n")
    held = single["ubar"] if single else None
    block = os.path.join(case, "system", "blockMeshDict")
    for key, value in (("scale", "1"), ("L", f"{L:.12g}"), ("n", f"{int(n)}")):
        set_entry(block, key, value)
    write(os.path.join(case, "system", "controlDict"), "dictionary", "system", "controlDict", f"""\
application     immersedSpheroidFoam;

startFrom       latestTime;
startTime       0;
stopAt          endTime;
endTime         {end_time:.12g};

{steps}
writeControl    adjustableRunTime;
writeInterval   {write_interval:.12g};
purgeWrite      2;
writeFormat     binary;
writePrecision  12;
writeCompression off;
timeFormat      general;
timePrecision   8;
runTimeModifiable false;
""")
    write(os.path.join(case, "constant", "g"), "uniformDimensionedVectorField", "constant", "g",
          f"dimensions      [0 1 -2 0 0 0 0];\nvalue           (0 0 {-g:.12g});\n")
    write(os.path.join(case, "constant", "transportProperties"), "dictionary", "constant",
          "transportProperties", f"transportModel  Newtonian;\nnu              {nu:.12g};\n")
    write(os.path.join(case, "constant", "turbulenceProperties"), "dictionary", "constant",
          "turbulenceProperties", "simulationType  laminar;\n")
    bodies_comment = ("one sphere of diameter 1 at the centre of the box, starting at rest"
                      if single else
                      f"spheres of diameter 1 at random positions (packSpheroids -Ar 1 -l {L:g}"
                      f" -alpha {phi:g}\n// -D 1 -seed {seed}), starting at rest")
    write(os.path.join(case, "constant", "immersedBodiesProperties"), "dictionary", "constant",
          "immersedBodiesProperties", f"""\
fluidDensity    1;

// {bodies_comment}
packing
{{
    file        "constant/suspension.csv";
    density     {RATIO:g};
    offset      (0 0 0);
    motion      {{ type {single["motion"] if single else "free"}; }}
}}

meanFlow        {"none" if held is not None else "zeroFlux"};

collision
{{
    type            {COLLISION};
    restitution     0.9;
}}

output
{{
    timeSeries      yes;
    surfaces        no;
}}
""")
    if held is not None:
        write(os.path.join(case, "system", "fvOptions"), "dictionary", "system", "fvOptions",
              f"""\
// holds the superficial velocity (the mean of U over the whole box, sphere included)
// at {held:.12g} along z with a uniform pressure gradient, printed in the log
meanFlowZ
{{
    type            meanVelocityForce;
    selectionMode   all;
    fields          (U);
    Ubar            (0 0 {held:.12g});
}}
""")
    if single:
        with open(os.path.join(case, "constant", "suspension.csv"), "w") as f:
            f.write(f"# formatVersion 1\n# boxLength {L!r}\n# aspectRatio 1\n"
                    f"# equivalentDiameter 1\n# volumeFraction {math.pi / 6 / L ** 3!r}\n"
                    f"# seed 0\n# bodies 1\na,b,c,x,y,z,qw,qx,qy,qz\n"
                    f"0.5,0.5,0.5,{L / 2!r},{L / 2!r},{L / 2!r},1,0,0,0\n")
    else:
        with open(os.path.join(case, "log.packSpheroids"), "w") as out:
            subprocess.run(["packSpheroids", "-Ar", "1", "-l", f"{L:g}", "-alpha", f"{phi:g}",
                            "-D", "1", "-seed", str(seed), "-o", "constant/suspension.csv"],
                           cwd=case, stdout=out, stderr=subprocess.STDOUT, check=True)
    with open(os.path.join(case, "log.blockMesh"), "w") as out:
        subprocess.run(["blockMesh"], cwd=case, stdout=out, stderr=subprocess.STDOUT, check=True)


def finished(case, end_time):
    """True when the solver log ends with End and the last step reached end_time."""
    log = os.path.join(case, SOLVER_LOG)
    if not os.path.exists(log):
        return False
    with open(log, errors="replace") as f:
        text = f.read()
    times = [float(x) for x in re.findall(r"^Time = (\S+)", text, flags=re.MULTILINE)]
    return text.rstrip().endswith("End") and bool(times) and times[-1] >= end_time * (1 - 1e-6)


def batch_standard_error(t, y, batches=BATCHES):
    """Standard error of the time mean of y(t): the spread of the means of equal spans."""
    edges = np.linspace(t[0], t[-1], batches + 1)
    means = []
    for a, b in zip(edges[:-1], edges[1:]):
        m = (t >= a) & (t <= b)
        means.append(np.trapz(y[m], t[m]) / (t[m][-1] - t[m][0]))
    return float(np.std(means, ddof=1) / math.sqrt(batches))


def analyse(case, L, average_from):
    """The figures of a finished suspension run (a dict) and its settling history (t, w)."""
    import summarise
    s = summarise.read_series(case)
    t, v = s["time"], s["velocity"]
    if not np.all(np.isfinite(v)):
        raise RuntimeError(f"{case}: non-finite body velocities in bodies.h5")
    axes, density = s["semiAxes"], s["density"]
    bodies = v.shape[1]
    w = -v[:, :, 2].mean(axis=1)
    late = t >= average_from
    if late.sum() < 2 * BATCHES:
        raise RuntimeError(f"{case}: {late.sum()} rows after t = {average_from}: too few")
    tl = t[late]
    w_mean = float(np.trapz(w[late], tl) / (tl[-1] - tl[0]))
    middle = 0.5 * (tl[0] + tl[-1])
    halves = [float(np.trapz(w[late][m], tl[m]) / (tl[m][-1] - tl[m][0]))
              for m in (tl <= middle, tl >= middle)]
    rms_w = float(np.sqrt(np.trapz(((-v[late, :, 2] - w[late, None]) ** 2).mean(axis=1), tl)
                          / (tl[-1] - tl[0])))
    vh = v[late, :, 0] - v[late, :, 0].mean(axis=1, keepdims=True)
    rms_h = float(np.sqrt(np.trapz((vh ** 2).mean(axis=1), tl) / (tl[-1] - tl[0])))
    volume = 4.0 / 3.0 * math.pi * np.prod(axes, axis=-1)
    weight = (density - 1.0) * volume * 1.0
    force = np.linalg.norm(s["hydroForce"][late], axis=2) / weight
    # the microstructure near contact: g(r) over r = 1-1.5 D for pairs within 60 degrees of
    # the vertical and the others, over the window (rows about 1 D/V_g apart) and at t = 0
    near = np.array([1.0, 1.5])
    stride = max(1, int(round(len(tl) / max(tl[-1] - tl[0], 1.0))))
    centres = s["centre"][late][::stride]
    g_vertical = g_horizontal = g_start = float("nan")
    if bodies > 1:
        _, g_vertical, g_horizontal = (float(x[0]) for x in
                                       summarise.pair_distribution(centres, L, near))
        g_start = float(summarise.pair_distribution(s["centre"][:1], L, near)[0][0])
    logged = summarise.read_log(case)
    residue = float("nan")
    overlap = float("nan")
    if logged is not None and len(logged[1]):
        means, overlap = logged[1], logged[2]
        residue = float(np.max(np.linalg.norm(means, axis=1)) / w_mean)
    row = dict(phi=f"{float(volume.sum()) / L ** 3:.6f}", bodies=bodies, L=f"{L:g}",
               cells=mesh_cells(case), steps=len(t), average_from=f"{average_from:g}",
               end_time=f"{t[-1]:.6g}",
               w=f"{w_mean:.6f}", w_se=f"{batch_standard_error(tl, w[late]):.6f}",
               w_first_half=f"{halves[0]:.6f}", w_second_half=f"{halves[1]:.6f}",
               g_near_vertical=f"{g_vertical:.4f}", g_near_horizontal=f"{g_horizontal:.4f}",
               g_near_start=f"{g_start:.4f}",
               rms_w=f"{rms_w:.6f}", rms_h=f"{rms_h:.6f}", flux_residue=f"{residue:.3g}",
               max_force_over_weight=f"{float(force.max()):.4g}", max_overlap=f"{overlap:.3g}",
               cpu_s=f"{solver_cpu(case):.0f}")
    return row, (t, w)


def solver_cpu(case):
    """The solver's CPU time over all the parts of a run (each continuation restarts the
    ExecutionTime count)."""
    times = execution_times(os.path.join(case, SOLVER_LOG))
    return sum(a for a, b in zip(times, times[1:] + [-1.0]) if b < a)


def run_case(case, name, phi, cpd, L, seed, end_time=END_TIME, average_from=AVERAGE_FROM,
             fresh=False, write_interval=WRITE_INTERVAL):
    """Write (unless resuming), run and analyse one suspension; returns its runs.csv row
    and saves its settling history beside runs.csv."""
    if fresh and os.path.exists(case):
        shutil.rmtree(case)
    if not os.path.exists(os.path.join(case, "constant", "polyMesh")):
        if os.path.exists(case):
            shutil.rmtree(case)
        write_case(case, phi, cpd, L, seed, end_time, write_interval)
    if not finished(case, end_time):
        # a longer end time than the case was written with continues it from its last write
        set_entry(os.path.join(case, "system", "controlDict"), "endTime", f"{end_time:.12g}")
        print(f"{name}: phi {phi:g}, {cpd} cells/D, box {L:g} D, seed {seed}", flush=True)
        log = os.path.join(case, SOLVER_LOG)
        earlier = open(log, errors="replace").read() if os.path.exists(log) else ""
        rc = run_logged(["nice", "-n", "10", "immersedSpheroidFoam"], case, SOLVER_LOG)
        if earlier:   # one log for the whole run: the earlier parts first
            text = open(log, errors="replace").read()
            with open(log, "w") as f:
                f.write(earlier + text)
        if rc != 0 or not finished(case, end_time):
            raise RuntimeError(f"immersedSpheroidFoam failed in {case} (see {SOLVER_LOG})")
    row, history = analyse(case, L, average_from)
    return dict(name=name, phi_nominal=phi, cpd=cpd, seed=seed, **row, **provenance()), history


def save_history(results, name, history):
    t, w = history
    np.savetxt(os.path.join(results, f"{name}.dat"), np.column_stack([t, w]),
               header="t [D/V_g], mean settling speed -<v_z> [V_g]", fmt="%.8g")


def do_run(args):
    names = [name for name, _ in campaign()]
    unknown = [name for name in args.only if name not in names]
    if unknown:
        sys.exit(f"hinderedSettling run --only: no run {', '.join(unknown)} at Ga {GA:g} "
                 f"(allowed: {', '.join(names)})")
    results = os.path.join(args.out, "results")
    os.makedirs(results, exist_ok=True)
    path = os.path.join(results, "runs.csv")
    done = {r["name"]: float(r["end_time"]) for r in read_csv(path)} if not args.force else {}
    for name, kw in campaign():
        case = os.path.join(args.out, "run", name)
        if args.only and name not in args.only:
            continue
        if args.analyse:
            if not finished(case, kw.get("end_time", END_TIME)):
                continue
            row, history = analyse(case, kw["L"], AVERAGE_FROM)
            prior = next((r for r in read_csv(path) if r["name"] == name), None)
            made = ({k: prior[k] for k in ("host", "date", "commit")} if prior
                    else provenance())   # the run's own provenance, not the analysis's
            row = dict(name=name, phi_nominal=kw["phi"], cpd=kw["cpd"], seed=kw["seed"],
                       **row, **made)
        elif done.get(name, -1) >= kw.get("end_time", END_TIME) * (1 - 1e-6):
            continue
        else:
            row, history = run_case(case, name, **kw, fresh=args.force)
        save_history(results, name, history)
        merge_row(path, row, "name", RUN_FIELDS)
        print(f"  -> -<v_z> {row['w']} +- {row['w_se']} V_g ({row['bodies']} spheres, "
              f"phi {row['phi']})", flush=True)


def do_array(args):
    """A simple cubic array settling in Stokes flow with meanFlow zeroFlux (one sphere in a
    triply periodic box, on the uniform mesh of ../periodicArray's run at the same phi and
    cpd). In the sphere's frame the zero-flux suspension is the fixed array with superficial
    velocity W (the mean over the box of the velocity is -phi W in the fluid and the
    sphere's W, shifted by W). K of Zick and Homsy counts the whole force of the fluid on the
    sphere, the mean pressure gradient's share included (the gradient times the box volume),
    and that whole force carries the sphere's net weight: (rho_p - rho_f) V_p g =
    6 pi mu a W K(phi), so K_settling = V_s/W, V_s the Stokes speed of the sphere alone,
    against K of the fixed array on the same mesh (../periodicArray/results/runs.csv) and
    Zick and Homsy."""
    sys.path.insert(0, str(HERE.parent / "periodicArray"))
    import periodicArray as pa
    import summarise
    results = os.path.join(args.out, "results")
    os.makedirs(results, exist_ok=True)
    fixed = {r["name"]: r for r in read_csv(HERE.parent / "periodicArray" / "results" /
                                             "runs.csv")}
    g = 18 * ARRAY_NU * ARRAY_STOKES_SPEED / (RATIO - 1.0)
    rows = []
    for phi, cpd in ARRAY_RUNS:
        plan = pa.mesh_plan(phi, cpd)
        L, n = plan["box"], plan["n"]
        h = L / n
        dt = ARRAY_NU * h * h / ARRAY_NU ** 2      # viscous number nu dt/h^2 = 1
        steps = int(round(ARRAY_END / dt))
        name = f"array-phi{pa.tag(phi)}-c{cpd}"
        case = os.path.join(args.out, "run", name)
        if os.path.exists(case):
            shutil.rmtree(case)
        write_case(case, phi, cpd, L, 1, steps * dt, write_interval=steps * dt,
                   single=dict(n=n, nu=ARRAY_NU, g=g, dt=dt))
        print(f"{name}: box {L:.6g} D, {n}^3 cells, {steps} steps", flush=True)
        rc = run_logged(["nice", "-n", "10", "immersedSpheroidFoam"], case, SOLVER_LOG)
        if rc != 0 or not finished(case, steps * dt):
            raise RuntimeError(f"immersedSpheroidFoam failed in {case} (see {SOLVER_LOG})")
        s = summarise.read_series(case)
        t, w = s["time"], -s["velocity"][:, 0, 2]
        w_end = float(w[-1])
        w_before = float(np.interp(0.9 * t[-1], t, w))
        k_settling = ARRAY_STOKES_SPEED / w_end
        k_ref, source = pa.reference_K(phi)
        k_fixed = float(fixed[f"phi{pa.tag(phi)}-c{cpd}"]["K"]) \
            if f"phi{pa.tag(phi)}-c{cpd}" in fixed else float("nan")
        logged = summarise.read_log(case)
        # the box's mean velocity at the end (the flux hold's residue), against W
        residue = float(np.linalg.norm(logged[1][-1]) / w_end) if logged is not None \
            else float("nan")
        rows.append(dict(name=name, phi=phi, L=f"{L:.8g}", cells=n ** 3,
                         cpd_eff=f"{n / L:.4f}", dt=f"{dt:.6g}", steps=steps,
                         w=f"{w_end:.8g}", w_change=f"{(w_end - w_before) / w_end:.2e}",
                         K_settling=f"{k_settling:.6f}", K_fixed=f"{k_fixed:.6f}",
                         K_ref=f"{k_ref:.5g}", ref_source=source,
                         difference_pct=f"{100 * (k_settling / k_fixed - 1):.4f}",
                         error_pct=f"{100 * (k_settling / k_ref - 1):.4f}",
                         flux_residue=f"{residue:.2g}",
                         cpu_s=f"{cpu_seconds(case, SOLVER_LOG):.0f}", **provenance()))
        print(f"  -> K {k_settling:.5f} settling, {k_fixed:.5f} fixed on the same mesh "
              f"({rows[-1]['difference_pct']} %), {k_ref:.5g} {source}", flush=True)
    write_csv(os.path.join(results, "array.csv"), rows, ARRAY_FIELDS)


def do_held(args):
    """The moving sphere against the fixed one at Re_t, at 8 and 12 cells per D: the free
    sphere of single-c<cpd>-L4 (one sphere per 4 D box, meanFlow zeroFlux) settles at W (its
    runs.csv row; runs not made yet are skipped); in its frame that
    is the fixed sphere in the same box and mesh with the superficial velocity W held along z
    (meanVelocityForce, no gravity). Galilean invariance makes the fixed sphere's whole force
    (the held gradient's share included, as in ../periodicArray) the free sphere's net weight:
    the difference is the error of the moving sphere's coupling (its forcing crossing cells,
    the time stepping of its motion) against the fixed sphere's. Its velocity equivalent uses
    the local slope dln F/dln U of the Schiller-Naumann law at Re = W D/nu."""
    import summarise
    results = os.path.join(args.out, "results")
    runs = {r["name"]: r for r in read_csv(os.path.join(results, "runs.csv"))}
    rows = []
    in_campaign = {name for name, _ in campaign()}
    for free_name in (name for name in HELD_FREE if name in in_campaign):
        free = runs.get(free_name)
        if free is None:
            print(f"hinderedSettling held: no row {free_name} in {results}/runs.csv (run "
                  f"`hinderedSettling.py run --only {free_name}`): skipped", flush=True)
            continue
        rows.append(held_run(args.out, free_name, free, summarise))
    write_csv(os.path.join(results, "held.csv"), rows, HELD_FIELDS)


def held_run(out, free_name, free, summarise):
    """The held sphere of the free run free (its runs.csv row): its held.csv row."""
    w, L, cpd = float(free["w"]), float(free["L"]), int(free["cpd"])
    name = f"held-c{cpd}-L{L:g}"
    case = os.path.join(out, "run", name)
    if os.path.exists(case):
        shutil.rmtree(case)
    write_case(case, float(free["phi"]), cpd, L, 1, END_TIME, write_interval=END_TIME,
               single=dict(n=int(round(cpd * L)), nu=NU, g=0.0, motion="fixed", ubar=w))
    print(f"{name}: the sphere of {free_name} held fixed, superficial velocity {w:.6g} V_g",
          flush=True)
    rc = run_logged(["nice", "-n", "10", "immersedSpheroidFoam"], case, SOLVER_LOG)
    if rc != 0 or not finished(case, END_TIME):
        raise RuntimeError(f"immersedSpheroidFoam failed in {case} (see {SOLVER_LOG})")
    s = summarise.read_series(case)
    t, fz = s["time"], s["hydroForce"][:, 0, 2]
    weight = (RATIO - 1.0) * math.pi / 6.0
    late = t >= AVERAGE_FROM
    f_mean = float(np.trapz(fz[late], t[late]) / (t[late][-1] - t[late][0]))
    f_before = float(np.interp(0.9 * t[-1], t, fz))
    re = w / NU
    x = 0.15 * re ** 0.687
    slope = 1.0 + 0.687 * x / (1.0 + x)
    row = dict(name=name, free=free_name, W=f"{w:.6f}", Re=f"{re:.4f}",
               force_over_weight=f"{f_mean / weight:.6f}",
               force_change=f"{(fz[-1] - f_before) / weight:.2e}",
               difference_pct=f"{100 * (f_mean / weight - 1):.4f}", slope=f"{slope:.4f}",
               velocity_equivalent_pct=f"{100 * ((weight / f_mean) ** (1 / slope) - 1):.4f}",
               cells=mesh_cells(case), steps=len(t), cpu_s=f"{solver_cpu(case):.0f}",
               **provenance())
    print(f"  -> F/W {row['force_over_weight']} ({row['difference_pct']} %): the free sphere "
          f"settles {row['velocity_equivalent_pct']} % off the held one's speed", flush=True)
    return row


def do_quick(args):
    results = os.path.join(args.out, "results")
    os.makedirs(results, exist_ok=True)
    name = "quick-phi0.1-c4-L4-s1"
    row, history = run_case(os.path.join(args.out, "run", name), name, phi=0.1, cpd=4, L=4,
                            seed=1, end_time=4.0, average_from=2.0, fresh=True,
                            write_interval=1.0)
    save_history(results, name, history)
    write_csv(os.path.join(results, "runs.csv"), [row], RUN_FIELDS)
    do_plot(args)


def do_plot(args):
    import plotHinderedSettling
    plotHinderedSettling.report(os.path.join(args.out, "results"))


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    ref = sub.add_parser("reference")
    ref.add_argument("--cpd", type=int, default=8)
    ref.add_argument("--domain-scale", type=float, default=1.0)
    r = sub.add_parser("run")
    r.add_argument("--force", action="store_true")
    r.add_argument("--only", action="append", default=[])
    r.add_argument("--analyse", action="store_true",
                   help="analyse the finished runs again (rows and histories), run nothing")
    sub.add_parser("plot")
    sub.add_parser("quick")
    sub.add_parser("array")
    sub.add_parser("held")
    for p in sub.choices.values():
        p.add_argument("--out", default=None)
        p.add_argument("--ga", type=float, default=None,
                       help=f"Galileo number of a new results folder (default {DEFAULT_GA:g}); "
                            "a folder keeps the one it was made with")
        p.add_argument("--ddt", choices=DDT_SCHEMES, default=None,
                       help="time scheme of a new results folder (default: the "
                            "periodicSuspension tutorial's); a folder keeps the one it was made with")
        p.add_argument("--collision", choices=COLLISION_MODELS, default=None,
                       help="collision model of a new results folder (default the tutorial's "
                            "lubricationContact; contact: the same contact without the "
                            "lubrication correction); a folder keeps the one it was made with")
    args = ap.parse_args()
    if args.out is None:
        args.out = str(HERE / ("run-quick" if args.cmd == "quick" else "."))
    args.out = os.path.abspath(args.out)
    set_galileo(os.path.join(args.out, "results"), args.ga)
    global DDT, COLLISION
    results = os.path.join(args.out, "results")
    DDT = set_folder_choice(results, "ddt", "--ddt", args.ddt, None)
    COLLISION = (set_folder_choice(results, "collision", "--collision", args.collision,
                                   COLLISION_MODELS[0]) or COLLISION_MODELS[0])
    {"reference": do_reference, "run": do_run, "plot": do_plot, "quick": do_quick,
     "array": do_array, "held": do_held}[args.cmd](args)


if __name__ == "__main__":
    main()
