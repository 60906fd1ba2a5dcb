#!/usr/bin/python3
"""The film force of a sphere approaching a wall: resolved flow plus the lubrication
correction, against Brenner's exact Stokes force (validation/lubricationResolution).

A sphere of diameter d = 1 (nu = 1, rho_f = 1, mu = 1) is held at a gap h above the bottom wall
(`motion { type prescribed; frozen yes; }`) with the velocity -U towards the wall imposed on
the fluid (Re = U d/nu = 0.01): the quasi-steady Stokes problem of a sphere approaching a
plane at that gap, one run per gap, run until the force is steady. The force the module puts on
the body, hydrodynamic plus collision (the lubrication correction of `lubricationContact` and
the film correction, as they run in production), over 6 pi mu a U, is compared with Brenner
(1961):

    lambda(alpha) = (4/3) sinh(alpha) sum_n n (n+1)/((2n-1)(2n+3))
                    [(2 sinh((2n+1) alpha) + (2n+1) sinh(2 alpha))
                     / (4 sinh^2((n+1/2) alpha) - (2n+1)^2 sinh^2(alpha)) - 1],
    cosh(alpha) = 1 + h/a.

With `--motion sliding` the sphere moves parallel to the wall instead (U along x, no
rotation) and its drag and rolling torque are compared with the sphere-wall Stokes solution of
sphereWallStokes.py (reference/sphereWall.csv): the check of the tangential lubrication terms,
with the resolved gap fitted on the approach; rows in results/slidingRuns.csv.

With `--shape prolateBroadside` or `prolateTipOn` the body is a prolate spheroid of aspect
ratio 2 whose minor diameter is d (semi-axes 1, 0.5, 0.5), its long axis along the wall or
normal to it, approaching the wall: no exact Stokes solution exists, so its force is compared
with the leading term of the squeeze film on the gap's paraboloid, F_par = 6 pi mu U R*^2/h
(R* from the principal curvatures of the body at its closest point: 0.894 broadside, 0.25
tip-on), and with the Reynolds equation on the exact gap (validation/squeezeFilm): the check
that resolved flow plus correction carry the spheroid's film at every resolution and tend to
the paraboloid's force as the gap closes; rows in results/spheroidRuns.csv. With
`--shape prolatePairCrossed` two such spheroids side by side, their axes crossed (along x and
y), approach each other (each at U) at a gap centred 6 d above the floor: the same comparison
for a spheroid pair, whose paraboloid (R* = 0.4, at the closing speed 2U) the spheres of the
Gaussian radii (R* = 0.5) miss by 56 % in the force; rows in the same file.

    lubricationResolution.py run [--cpd N] [--gap G ...] [--motion approach|sliding] [--quick]
                                 [--force] [--rescore] [--shape S]
    lubricationResolution.py fit --cpd N  the resolved gap c (delta = c h_cell) that best
                                          completes that resolution's resolved forces
    lubricationResolution.py plot        results/table.md, metrics.json, force.png, sliding.png
                                         (and movingApproach.py's table and figure)

Each finished run appends a row to results/runs.csv (gap, forces, steadiness, CPU time, host,
commit).
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
from validationTools import (cpu_seconds, merge_row, mesh_cells, provenance,  # noqa: E402
                             read_csv, refined_box_mesh, run_logged, write_dict)
from sphereWallStokes import brenner, two_spheres_approaching  # noqa: E402  (gap over the radius)

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "results")
RUNS = os.path.join(HERE, "run")
RUNS_CSV = os.path.join(RESULTS, "runs.csv")
TITLE = "spheroidFoam validation: a sphere approaching a wall (validation/lubricationResolution)"

A = 0.5                 # sphere radius (d = 1)
U = 0.01                # approach speed, Re = U d/nu
GAPS = (2.0, 1.0, 0.5, 0.2, 0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001)   # h/d
LAMBDA = 1.0            # nu dt/h^2 (the forcing is unstable here at 4: README)
T_STEADY = 8.0          # run length in d^2/nu (steady to about 1e-4 by 5 at 4 cells/d)
FIT_CPD = 8             # the resolution the resolved gap is fitted at (README)
ACTIVATION_OVER_DELTA = 4.0   # collision::LubricationParameters::kActivationOverResolvedGap
WALL_RESOLVED_GAP_CELLS = 0.62   # the c of the module's resolved-gap form (fitted below, FIT_CPD)
# the pairs' c: the wall's in quadrature for two diffuse surfaces
# (collision::LubricationParameters::kPairResolvedGapCells; predicted, checked by --shape spherePair)
PAIR_RESOLVED_GAP_CELLS = math.sqrt(2) * WALL_RESOLVED_GAP_CELLS
RESCORE_STEPS = 2       # steps a finished run is continued by to rescore its correction
BOX_HALF, BOX_TOP = 6.0, 12.0
FIELDS = ["name", "cpd", "gap", "cells", "dt", "steps", "F_hydro", "F_collision", "F_total",
          "brenner", "error_pct", "error_pct_hydro_only", "unsteadiness", "box_half", "cpu_s",
          "host", "date", "commit"]
SLIDING_CSV = os.path.join(RESULTS, "slidingRuns.csv")
SLIDING_FIELDS = ["name", "cpd", "gap", "cells", "dt", "steps", "F_hydro", "F_collision",
                  "F_total", "reference", "error_pct", "error_pct_hydro_only", "T_hydro",
                  "T_collision", "T_total", "torque_reference", "unsteadiness", "box_half",
                  "cpu_s", "host", "date", "commit"]
# the imposed velocity of each motion and the axis its force is read along; the sliding
# sphere's torque about y (the rolling axis) is read beside its drag
MOTIONS = {"approach": ((0.0, 0.0, -U), 2), "sliding": ((U, 0.0, 0.0), 0)}
# body shapes: semi-axes along x, y, z (the wall is z = 0) and R*, the radius of the squeeze
# film's leading term 6 pi mu U R*^2/h: R*^2 = 2/(sqrt(k1 k2)(k1 + k2)) with k1, k2 the body's
# principal curvatures at its lowest point (validation/squeezeFilm). Broadside: 1/b = 2 across
# the axis and b/a^2 = 0.5 along it; tip-on: a/b^2 = 4 in both directions.
SHAPES = {"sphere": ((A, A, A), A),
          "prolateBroadside": ((1.0, 0.5, 0.5), math.sqrt(2 / (math.sqrt(2 * 0.5) * 2.5))),
          "prolateTipOn": ((0.5, 0.5, 1.0), math.sqrt(2 / (math.sqrt(4 * 4) * 8))),
          "spherePair": ((A, A, A), A / 2),
          "prolatePairCrossed": ((1.0, 0.5, 0.5), 0.4)}
# the pairs: two bodies approaching each other, each at U (the closing speed 2U), the second
# body's semi-axes. Crossed prolates AR 2 side by side (axes along x and y): at the closest
# points each surface has curvatures 2 across its axis and 0.5 along it, so K = S1 + S2 =
# diag(2.5, 2.5) and R*^2 = 2/(2.5 x 5) = 0.16 (the spheres of the Gaussian radii, R_G = 1
# each: 0.25)
PAIR_SECOND = {"spherePair": (A, A, A), "prolatePairCrossed": (0.5, 1.0, 0.5)}
# two equal spheres approaching each other (each at U), their gap centred PAIR_MID above the
# floor: compared with the exact series (sphereWallStokes.two_spheres_approaching); rows in
# results/pairRuns.csv, the columns of runs.csv
PAIR_MID = 6.0
PAIR_GAPS = (1.0, 0.5, 0.2, 0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001)
PAIR_CSV = os.path.join(RESULTS, "pairRuns.csv")
SPHEROID_GAPS = (0.05, 0.015, 0.005, 0.0015)     # h/d = h0/2, h0 the gaps of squeezeFilm
SPHEROID_CSV = os.path.join(RESULTS, "spheroidRuns.csv")
SPHEROID_FIELDS = ["name", "shape", "cpd", "gap", "cells", "dt", "steps", "F_hydro",
                   "F_collision", "F_total", "paraboloid", "ratio", "ratio_hydro_only",
                   "reynolds_exact_gap_ratio", "unsteadiness", "cpu_s", "host", "date", "commit"]
# the squeezeFilm configuration of each spheroid (its lengths in the smallest semi-axis, b)
SQUEEZE_FILM_CONFIG = {"sphere": "spherePlane", "prolateBroadside": "prolateBroadside",
                       "prolateTipOn": "prolateTip", "prolatePairCrossed": "prolatesCrossed"}
SQUEEZE_FILM_CSV = os.path.join(HERE, "..", "squeezeFilm", "results", "results.csv")


def body_entry(name, semi, centre, velocity):
    """One frozen prescribed body of immersedBodiesProperties."""
    return f"""\
    {name}
    {{
        semiAxes        ({" ".join(f"{v:g}" for v in semi)});
        density         1;
        centre          ({" ".join(f"{v:.12g}" for v in centre)});
        motion
        {{
            type            prescribed;
            frozen          yes;
            velocity        constant ({" ".join(f"{v:.12g}" for v in velocity)});
            angularVelocity constant (0 0 0);
        }}
    }}
"""


def write_case(case, cpd, gap, end_time, motion="approach", box_half=BOX_HALF, shape="sphere"):
    h = 1.0 / cpd
    semi = SHAPES[shape][0]
    second = PAIR_SECOND.get(shape, semi)
    fine_x = math.ceil((max(semi[0], second[0]) + 0.25) / h) * h
    fine_y = math.ceil((max(semi[1], second[1]) + 0.25) / h) * h
    if shape in PAIR_SECOND:
        # the pair's gap centred at PAIR_MID; the first body above it, moving down
        half = math.ceil((gap / 2 + 2 * max(semi[2], second[2]) + 0.25) / h) * h
        fine_z = (PAIR_MID - half, PAIR_MID + half)
        bodies = (body_entry("upper", semi, (0, 0, PAIR_MID + gap / 2 + semi[2]), (0, 0, -U))
                  + body_entry("lower", second, (0, 0, PAIR_MID - gap / 2 - second[2]),
                               (0, 0, U)))
    else:
        fine_z = (0.0, math.ceil((gap + 2 * semi[2] + 0.25) / h) * h)
        bodies = body_entry("sphere", semi, (0, 0, semi[2] + gap), MOTIONS[motion][0])
    refined_box_mesh(case, [
        "--box", *map(str, (-box_half, box_half, -box_half, box_half, 0.0, BOX_TOP)),
        "--fine", *(f"{v:.12g}" for v in (-fine_x, fine_x, -fine_y, fine_y, *fine_z)),
        "--h", f"{h:.12g}", "--growth", "1.15", "--max-ratio", "16",
        "--patch", "xMin:wall", "--patch", "xMax:wall", "--patch", "yMin:wall",
        "--patch", "yMax:wall", "--patch", "zMin:wall", "--patch", "zMax:patch"])
    dt = LAMBDA * h * h
    w = lambda rel, cls, obj, body: write_dict(  # noqa: E731
        os.path.join(case, *rel.split("/")), cls, rel.split("/")[0], obj, body, TITLE)
    w("system/controlDict", "dictionary", "controlDict", f"""\
application     immersedSpheroidFoam;

startFrom       latestTime;
startTime       0;
stopAt          endTime;
endTime         {end_time:.12g};
deltaT          {dt:.12g};

writeControl    runTime;
writeInterval   {end_time:.12g};
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
{bodies}}}

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
    return {"dt": dt, "end_time": end_time, "motion": motion, "shape": shape}


def analyse(h5, motion="approach"):
    """The last step's hydrodynamic and collision force along the motion over 6 pi mu a U
    (positive against the motion), and the hydrodynamic force's change over the last quarter of
    the run relative to the total (the flow's unsteadiness; the correction of a frozen body is
    constant, but for the build). For the sliding sphere also the torque about y over
    8 pi mu a^2 U (positive in the sense of rolling along the motion)."""
    import h5py
    velocity, axis = MOTIONS[motion]
    sign = -1.0 if velocity[axis] > 0 else 1.0
    with h5py.File(h5, "r", locking=False) as f:
        fh = sign * f["hydroForce"][:, 0, axis]
        fc = sign * f["collisionForce"][:, 0, axis]
        if motion == "sliding":
            th = f["hydroTorque"][:, 0, 1]
            tc = f["collisionTorque"][:, 0, 1]
    scale = 6 * math.pi * A * U
    total = (fh + fc) / scale
    quarter = max(1, len(total) // 4)
    change = abs(fh[-1] - fh[-quarter]) / scale / abs(total[-1])
    out = {"hydro": fh[-1] / scale, "collision": fc[-1] / scale, "total": total[-1],
           "unsteadiness": change}
    if motion == "sliding":
        tscale = 8 * math.pi * A * A * U
        out.update(torque_hydro=th[-1] / tscale, torque_collision=tc[-1] / tscale,
                   torque_total=(th[-1] + tc[-1]) / tscale)
    return out


def rescore(case, info):
    """Continue a finished run by RESCORE_STEPS steps with the solver as built now: the frozen
    body's flow is steady and does not depend on the collision model, so the last step's
    collision force is the current correction on the run's resolved flow."""
    def times():
        out = {}
        for d in os.listdir(case):
            try:
                out[float(d)] = d
            except ValueError:
                pass
        return out
    end, dt = info["end_time"], info["dt"]
    last = max(times())
    if abs(last - end) > 0.5 * dt:
        sys.exit(f"lubricationResolution: {case} has no time directory at its end time {end:g} to "
                 f"continue (the latest is {last:g}; run it again with --force)")
    new_end = last + RESCORE_STEPS * dt
    cd = os.path.join(case, "system", "controlDict")
    text = open(cd).read()
    text = text.replace(f"endTime         {end:.12g};", f"endTime         {new_end:.12g};")
    open(cd, "w").write(text)
    status = run_logged(["immersedSpheroidFoam"], case, "log.rescore")
    open(cd, "w").write(text.replace(f"endTime         {new_end:.12g};",
                                     f"endTime         {end:.12g};"))
    for t, d in times().items():
        if t > last:
            shutil.rmtree(os.path.join(case, d))
    if status != 0:
        sys.exit(f"lubricationResolution: the solver failed in {case} (log.rescore)")


def run_one(cpd, gap, force, quick, rescore_only=False, motion="approach", box_half=BOX_HALF,
            shape="sphere"):
    if shape != "sphere" and (motion != "approach" or box_half != BOX_HALF):
        sys.exit(f"lubricationResolution: --shape {shape} runs the approach in the standard box "
                 f"only (got --motion {motion}, --box-half {box_half:g})")
    name = ((f"{shape}-" if shape != "sphere" else "") + f"c{cpd}-h{gap:g}"
            + ("-sliding" if motion == "sliding" else "")
            + (f"-box{box_half:g}" if box_half != BOX_HALF else "") + ("-quick" if quick else ""))
    case = os.path.join(RUNS, name)
    if rescore_only:
        if not os.path.isdir(case):
            sys.exit(f"lubricationResolution: no run {case} to rescore")
        rescore(case, json.load(open(os.path.join(case, "info.json"))))
    else:
        if os.path.isdir(case) and force:
            shutil.rmtree(case)
        if not os.path.isdir(case):
            os.makedirs(case)
            info = write_case(case, cpd, gap, 1.0 if quick else T_STEADY, motion, box_half, shape)
            with open(os.path.join(case, "info.json"), "w") as f:
                json.dump(info, f)
        if run_logged(["blockMesh"], case, "log.blockMesh") != 0:
            sys.exit(f"lubricationResolution: blockMesh failed in {case}")
        if run_logged(["immersedSpheroidFoam"], case, "log.solver") != 0:
            sys.exit(f"lubricationResolution: the solver failed in {case} (log.solver)")
    x = analyse(os.path.join(case, "postProcessing", "immersedBodies", "bodies.h5"), motion)
    if shape not in ("sphere", "spherePair"):
        record_spheroid(case, name, shape, cpd, gap, x, quick)
        return
    if motion == "sliding":
        ref_row = sphere_wall_reference(gap)
        ref, what = ref_row["f_par"], "the sliding sphere's drag"
    elif shape == "spherePair":
        ref, what = two_spheres_approaching(gap / A), "the two spheres' exact force"
    else:
        ref, what = brenner(gap / A), "Brenner"
    err = 100 * (x["total"] / ref - 1)
    err_h = 100 * (x["hydro"] / ref - 1)
    print(f"{name}: F/(6 pi mu a U) {x['total']:.5g} (resolved {x['hydro']:.5g}, correction "
          f"{x['collision']:.5g}) against {what} {ref:.5g}: {err:+.2f} % (resolved alone "
          f"{err_h:+.2f} %), change over the last quarter {x['unsteadiness']:.1e}", flush=True)
    if quick:
        with open(os.path.join(case, "result.json"), "w") as f:
            json.dump({"motion": motion, "cpd": cpd, "gap": gap, "reference": ref,
                       "error_pct": err, "error_pct_hydro_only": err_h, **x}, f, indent=1)
        return
    info = json.load(open(os.path.join(case, "info.json")))
    row = {"name": name, "cpd": cpd, "gap": gap, "cells": mesh_cells(case), "dt": info["dt"],
           "steps": int(round(T_STEADY / info["dt"])),
           "F_hydro": f"{x['hydro']:.6g}", "F_collision": f"{x['collision']:.6g}",
           "F_total": f"{x['total']:.6g}", "error_pct": f"{err:.3f}",
           "error_pct_hydro_only": f"{err_h:.3f}", "unsteadiness": f"{x['unsteadiness']:.2e}",
           "box_half": f"{box_half:g}", "cpu_s": f"{cpu_seconds(case, 'log.solver'):.0f}",
           **provenance()}
    os.makedirs(RESULTS, exist_ok=True)
    if motion == "sliding":
        row.update(reference=f"{ref:.6g}", T_hydro=f"{x['torque_hydro']:.6g}",
                   T_collision=f"{x['torque_collision']:.6g}",
                   T_total=f"{x['torque_total']:.6g}",
                   torque_reference=f"{ref_row['g_par']:.6g}")
        csv, fields = SLIDING_CSV, SLIDING_FIELDS
    else:
        row["brenner"] = f"{ref:.6g}"
        csv, fields = (PAIR_CSV if shape == "spherePair" else RUNS_CSV), FIELDS
    # two runs at a time share the CSV
    merge_row(csv, row, "name", fields, ignore_extra=True)


def paraboloid_force(shape, gap):
    """The squeeze film's leading term 6 pi mu V R*^2/h over 6 pi mu a U (a = d/2), V the
    closing speed: U against the wall, 2 U for a pair."""
    closing = 2.0 if shape in PAIR_SECOND else 1.0
    return closing * SHAPES[shape][1] ** 2 / (A * gap)


def reynolds_exact_gap_ratio(shape, gap):
    """F_num/F_par of validation/squeezeFilm (the Reynolds equation on the exact gap) for the
    shape at h/d = gap (h0 = gap/b, b = 0.5 the smallest semi-axis), or None if that campaign
    has no row there."""
    for r in read_csv(SQUEEZE_FILM_CSV):
        if r["config"] == SQUEEZE_FILM_CONFIG[shape] and abs(float(r["h0"]) / (gap / 0.5) - 1) < 1e-6:
            return float(r["ratio"])
    return None


def record_spheroid(case, name, shape, cpd, gap, x, quick):
    """Report a spheroid's run against the paraboloid's force and add its row to
    results/spheroidRuns.csv; a --quick run writes its figures to the case's result.json
    instead (read by tests/foam/lubricationResolutionQuick)."""
    par = paraboloid_force(shape, gap)
    ratio, ratio_h = x["total"] / par, x["hydro"] / par
    rey = reynolds_exact_gap_ratio(shape, gap)
    print(f"{name}: F/(6 pi mu a U) {x['total']:.5g} (resolved {x['hydro']:.5g}, correction "
          f"{x['collision']:.5g}); over the paraboloid's {par:.5g}: {ratio:.4f} (resolved alone "
          f"{ratio_h:.4f}; Reynolds on the exact gap {rey if rey is None else f'{rey:.4f}'}), "
          f"change over the last quarter {x['unsteadiness']:.1e}", flush=True)
    if quick:
        with open(os.path.join(case, "result.json"), "w") as f:
            json.dump({"shape": shape, "cpd": cpd, "gap": gap, "paraboloid": par, "ratio": ratio,
                       "ratio_hydro_only": ratio_h, "reynolds_exact_gap_ratio": rey, **x}, f,
                      indent=1)
        return
    info = json.load(open(os.path.join(case, "info.json")))
    row = {"name": name, "shape": shape, "cpd": cpd, "gap": gap, "cells": mesh_cells(case),
           "dt": info["dt"], "steps": int(round(T_STEADY / info["dt"])),
           "F_hydro": f"{x['hydro']:.6g}", "F_collision": f"{x['collision']:.6g}",
           "F_total": f"{x['total']:.6g}", "paraboloid": f"{par:.6g}", "ratio": f"{ratio:.6f}",
           "ratio_hydro_only": f"{ratio_h:.6f}",
           "reynolds_exact_gap_ratio": "" if rey is None else f"{rey:.6f}",
           "unsteadiness": f"{x['unsteadiness']:.2e}",
           "cpu_s": f"{cpu_seconds(case, 'log.solver'):.0f}", **provenance()}
    os.makedirs(RESULTS, exist_ok=True)
    merge_row(SPHEROID_CSV, row, "name", SPHEROID_FIELDS, ignore_extra=True)


def sphere_wall_reference(gap):
    """The sliding sphere's drag f_par (over 6 pi mu a U) and torque g_par (over
    8 pi mu a^2 U) at h/d = gap, from reference/sphereWall.csv (sphereWallStokes.py)."""
    path = os.path.join(HERE, "reference", "sphereWall.csv")
    for r in read_csv(path, missing_ok=False):
        if abs(float(r["gap_over_d"]) / gap - 1) < 1e-9:
            return {"f_par": float(r["f_par"]), "g_par": float(r["g_par"])}
    sys.exit(f"lubricationResolution: no row for h/d = {gap:g} in {path} "
             f"(sphereWallStokes.py table writes the gaps of GAPS)")


def wall_lambda(eps):
    """Cox & Brenner's lambda of a sphere and a plane (collision::wallLubricationLambda)."""
    return 1 / eps - math.log(eps) / 5 - eps * math.log(eps) / 21 + 0.9713


def resolved_gap_correction(gap, c, cpd, saturation=1e-3, activation_over_delta=None,
                            pair=False):
    """The correction of the resolved-gap form over 6 pi mu a U (the law of
    collision::LubricationGapLaw; a sphere and a wall: A = 1, B = 1/5; two equal spheres
    approaching, each at U: A = 1/2, B = 9/20): the singular terms A/x + B ln(1/x) at the gap
    less those at the widened gap sqrt(x^2 + x_d^2), x_d = c h_cell/a, shifted to zero at the
    activation gap 4 x_d. Used to fit c; the recorded results are the module's own."""
    xd = c / cpd / A
    act = min((activation_over_delta or ACTIVATION_OVER_DELTA) * xd, 1.0)
    x = gap / A
    if x >= act:
        return 0.0
    a_coef, b_coef = (0.5, 0.45) if pair else (1.0, 0.2)

    def u(y):
        return a_coef * (1 / y - 1 / math.hypot(y, xd)) + 0.5 * b_coef * math.log1p(xd * xd / (y * y))
    return u(max(x, saturation)) - u(act)


def do_fit(cpd):
    """The resolved gap c (in cells, to 0.01) whose correction brings the resolved forces of
    the runs at cpd closest to Brenner's (least squares of the relative errors over the gaps);
    results/fit.md with the errors at c and at 0.5 and 2 times it."""
    rows = sorted((float(r["gap"]), float(r["F_hydro"])) for r in read_csv(RUNS_CSV, missing_ok=False)
                  if int(r["cpd"]) == cpd and default_box(r))
    if len(rows) < 3:
        sys.exit(f"lubricationResolution fit: {len(rows)} runs at {cpd} cells/d in {RUNS_CSV} "
                 f"(at least 3 gaps needed)")

    def errors(c):
        return [100 * ((fh + resolved_gap_correction(g, c, cpd)) / brenner(g / A) - 1)
                for g, fh in rows]

    grid = [i / 100 for i in range(10, 301)]
    best = min(grid, key=lambda c: sum(e * e for e in errors(c)))
    lines = [f"Resolved gap fitted on the resolved forces at {cpd} cells/d "
             f"(`lubricationResolution.py fit --cpd {cpd}`): c = {best:.2f} "
             "(least squares of the relative errors over the gaps, c on a grid of 0.01).", "",
             "| h/d | Brenner | resolved | " + " | ".join(f"c = {c:.2f}" for c in
                                                          (best / 2, best, 2 * best)) + " |",
             "|---|---|---|---|---|---|"]
    table = {c: errors(c) for c in (best / 2, best, 2 * best)}
    for k, (g, fh) in enumerate(reversed(rows)):
        i = len(rows) - 1 - k
        lines.append(f"| {g:g} | {brenner(g / A):.4g} | {100 * (fh / brenner(g / A) - 1):+.1f} % | "
                     + " | ".join(f"{table[c][i]:+.1f} %" for c in table) + " |")
    lines.append("| largest \|error\| | | | " + " | ".join(
        f"{max(abs(e) for e in table[c]):.1f} %" for c in table) + " |")
    # the activation gap, ACTIVATION_OVER_DELTA resolved gaps, is chosen, not fitted: the
    # errors at c with half and twice that multiple (c not refitted)
    act = {k: [100 * ((fh + resolved_gap_correction(g, best, cpd, activation_over_delta=k))
                      / brenner(g / A) - 1) for g, fh in rows]
           for k in (ACTIVATION_OVER_DELTA / 2, 2 * ACTIVATION_OVER_DELTA)}
    lines += ["", f"The activation gap ({ACTIVATION_OVER_DELTA:g} resolved gaps, "
              "`LubricationParameters::kActivationOverResolvedGap`) at half and twice its value, "
              f"c = {best:.2f}:", "",
              "| h/d | " + " | ".join(f"activation {k:g} delta" for k in act) + " |", "|---|---|---|"]
    for k, (g, fh) in enumerate(reversed(rows)):
        i = len(rows) - 1 - k
        lines.append(f"| {g:g} | " + " | ".join(f"{act[m][i]:+.1f} %" for m in act) + " |")
    lines.append("| largest \|error\| | " + " | ".join(
        f"{max(abs(e) for e in act[m]):.1f} %" for m in act) + " |")
    os.makedirs(RESULTS, exist_ok=True)
    with open(os.path.join(RESULTS, "fit.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    worst = {c: max(abs(e) for e in table[c]) for c in table}
    worst.update({("activation", m): max(abs(e) for e in act[m]) for m in act})
    return best, worst


def do_plot():
    rows = [r for r in read_csv(RUNS_CSV, missing_ok=False) if default_box(r)]
    cpds = sorted({int(r["cpd"]) for r in rows})
    gaps = sorted({float(r["gap"]) for r in rows}, reverse=True)
    by = {(int(r["cpd"]), float(r["gap"])): r for r in rows}
    lines = ["| h/d | Brenner | " + " | ".join(f"{c} cells/d: total (resolved)" for c in cpds) + " |",
             "|---|---|" + "---|" * len(cpds)]
    for g in gaps:
        cells = []
        for c in cpds:
            r = by.get((c, g))
            cells.append("-" if r is None else
                         f"{float(r['error_pct']):+.1f} % ({float(r['error_pct_hydro_only']):+.1f} %)")
        lines.append(f"| {g:g} | {brenner(g / A):.4g} | " + " | ".join(cells) + " |")
    gg = np.logspace(-3, math.log10(2), 200)
    force_figure(rows, (gg, [brenner(x / A) for x in gg]), "Brenner (1961), exact",
                 "F / (6 pi mu a U)", "resolved + correction against Brenner [%]",
                 "Sphere approaching a wall (Stokes): resolved force plus lubrication correction",
                 os.path.join(RESULTS, "force.png"), log_force=True)
    metrics = {"max_abs_force_error_pct": round(max(abs(float(r["error_pct"])) for r in rows), 3)}
    if FIT_CPD in cpds:
        best, worst = do_fit(FIT_CPD)
        metrics["fitted_resolved_gap_cells"] = best
        metrics[f"max_abs_force_error_pct_{FIT_CPD}_half_c"] = round(worst[best / 2], 3)
        metrics[f"max_abs_force_error_pct_{FIT_CPD}_double_c"] = round(worst[2 * best], 3)
        metrics[f"max_abs_force_error_pct_{FIT_CPD}_half_activation"] = round(
            worst[("activation", ACTIVATION_OVER_DELTA / 2)], 3)
        metrics[f"max_abs_force_error_pct_{FIT_CPD}_double_activation"] = round(
            worst[("activation", 2 * ACTIVATION_OVER_DELTA)], 3)
    for c in cpds:
        metrics[f"max_abs_force_error_pct_{c}"] = round(
            max(abs(float(r["error_pct"])) for r in rows if int(r["cpd"]) == c), 3)
        metrics[f"gaps_{c}"] = sum(1 for r in rows if int(r["cpd"]) == c)
    sliding = [r for r in read_csv(SLIDING_CSV) if default_box(r)]
    box_checks = [r for r in read_csv(SLIDING_CSV) + read_csv(RUNS_CSV) if not default_box(r)]
    if box_checks:
        lines += ["", f"Checks of the box ({2 * BOX_HALF:g} d wide in the runs above): the same "
                  "run in a wider box.", "", "| run | box width [d] | total against the exact force |",
                  "|---|---|---|"]
        lines += [f"| {r['name']} | {2 * float(r['box_half']):g} | {float(r['error_pct']):+.2f} % |"
                  for r in box_checks]
    if sliding:
        lines += ["", sliding_table_and_figure(sliding)]
        metrics.update(error_metrics(sliding, "sliding"))
    pairs = read_csv(PAIR_CSV)
    if pairs:
        lines += ["", pair_table_and_figure(pairs)]
        metrics.update(error_metrics(pairs, "pair"))
        metrics.update(pair_fit(pairs))
    import movingApproach
    moving_table, moving_metrics = movingApproach.plot()
    if moving_table:
        lines += ["", moving_table]
        metrics.update(moving_metrics)
    spheroids = read_csv(SPHEROID_CSV)
    if spheroids:
        lines += ["", spheroid_table_and_figure(spheroids, rows)]
        for shape in sorted({r["shape"] for r in spheroids}):
            sel = [r for r in spheroids if r["shape"] == shape]
            for c in sorted({int(r["cpd"]) for r in sel}):
                at = sorted((float(r["gap"]), r) for r in sel if int(r["cpd"]) == c)
                metrics[f"{shape}_ratio_to_paraboloid_{c}_h{at[0][0]:g}"] = round(
                    float(at[0][1]["ratio"]), 4)
                metrics[f"{shape}_gaps_{c}"] = len(at)
            change = resolution_changes(sel)
            if change:
                metrics[f"{shape}_max_abs_resolution_change_pct"] = round(
                    max(abs(v) for v in change.values()), 3)
    with open(os.path.join(RESULTS, "table.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(os.path.join(RESULTS, "metrics.json"), "w") as f:
        json.dump(metrics, f, indent=1, sort_keys=True)
        f.write("\n")
    print("\n".join(lines))


def force_figure(rows, reference, reference_label, force_label, error_label, title, path,
                 log_force, fitted_here=True):
    """Two panels against the gap: the force of each resolution (resolved plus correction, and
    resolved alone) with the exact curve, and the error of the total with the 10 % band."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axs = plt.subplots(1, 2, figsize=(11, 4))
    draw = axs[0].loglog if log_force else axs[0].semilogx
    draw(*reference, "k-", label=reference_label)
    for k, c in enumerate(sorted({int(r["cpd"]) for r in rows})):
        sel = sorted((float(r["gap"]), r) for r in rows if int(r["cpd"]) == c)
        h = [g for g, _ in sel]
        name = f"{c} cells/d" + (" (c fitted)" if fitted_here and c == FIT_CPD else "")
        draw(h, [float(r["F_total"]) for _, r in sel], "o-", color=f"C{k}",
             label=f"{name}: resolved + correction")
        draw(h, [float(r["F_hydro"]) for _, r in sel], "x:", color=f"C{k}",
             label=f"{name}: resolved alone")
        axs[1].semilogx(h, [float(r["error_pct"]) for _, r in sel], "o-", color=f"C{k}", label=name)
    axs[0].set_xlabel("gap h / d")
    axs[0].set_ylabel(force_label)
    axs[1].set_xlabel("gap h / d")
    axs[1].set_ylabel(error_label)
    axs[1].axhspan(-10, 10, color="0.9")
    for ax in axs:
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def error_metrics(rows, kind):
    """max_abs_<kind>_force_error_pct over the rows, and per resolution with <kind>_gaps_N."""
    out = {f"max_abs_{kind}_force_error_pct": round(max(abs(float(r["error_pct"])) for r in rows), 3)}
    for c in sorted({int(r["cpd"]) for r in rows}):
        sel = [r for r in rows if int(r["cpd"]) == c]
        out[f"max_abs_{kind}_force_error_pct_{c}"] = round(
            max(abs(float(r["error_pct"])) for r in sel), 3)
        out[f"{kind}_gaps_{c}"] = len(sel)
    return out


def pair_fit(rows):
    """results/pairFit.md: per resolution, the pair's errors with the walls' resolved gap, with
    sqrt(2) times it (the two surfaces' unresolved layers in quadrature) and, where three gaps
    or more were run, with the least-squares c; from the runs' resolved forces and the law's
    formula (checked: its correction at the pairs' c, PAIR_RESOLVED_GAP_CELLS, against the
    module's). Returns metrics."""
    wall_c = WALL_RESOLVED_GAP_CELLS
    lines, metrics = [], {}
    for cpd in sorted({int(r["cpd"]) for r in rows}):
        sel = sorted((float(r["gap"]), float(r["F_hydro"]), float(r["F_collision"]))
                     for r in rows if int(r["cpd"]) == cpd)

        def errors(c):
            return [100 * ((fh + resolved_gap_correction(g, c, cpd, pair=True))
                           / two_spheres_approaching(g / A) - 1) for g, fh, _ in sel]
        formula_check = max((abs(resolved_gap_correction(g, PAIR_RESOLVED_GAP_CELLS, cpd,
                                                         pair=True) - fc) / fc
                             for g, _, fc in sel if fc > 0), default=0.0)
        cs = {"walls' c": wall_c, "sqrt(2) x walls' c": math.sqrt(2) * wall_c}
        if len(sel) >= 3:
            cs["least squares"] = min((i / 100 for i in range(10, 301)),
                                      key=lambda c: sum(e * e for e in errors(c)))
            metrics[f"pair_least_squares_resolved_gap_cells_{cpd}"] = cs["least squares"]
        table = {k: errors(c) for k, c in cs.items()}
        lines += [f"Two spheres approaching at {cpd} cells/d: resolved force plus the pair law's "
                  "correction (formula of `resolved_gap_correction`, pair terms) against the exact "
                  "force, for resolved gaps c in cells. The formula at the pairs' c (sqrt(2) x walls') "
                  "against the "
                  f"module's correction: largest relative difference {formula_check:.1e}.", "",
                  "| h/d | " + " | ".join(f"{k}, c = {c:.3f}" for k, c in cs.items()) + " |",
                  "|---|" + "---|" * len(cs)]
        for i, (g, _, _) in enumerate(sel):
            lines.append(f"| {g:g} | " + " | ".join(f"{table[k][i]:+.1f} %" for k in cs) + " |")
        lines += ["| largest \\|error\\| | " + " | ".join(
            f"{max(abs(e) for e in table[k]):.2f} %" for k in cs) + " |", ""]
        metrics[f"max_abs_pair_force_error_pct_{cpd}_c_sqrt2"] = round(
            max(abs(e) for e in table["sqrt(2) x walls' c"]), 3)
    with open(os.path.join(RESULTS, "pairFit.md"), "w") as f:
        f.write("\n".join(lines))
    return metrics


def pair_table_and_figure(rows):
    """The two approaching spheres' table (markdown, returned) and results/pair.png."""
    cpds = sorted({int(r["cpd"]) for r in rows})
    by = {(int(r["cpd"]), float(r["gap"])): r for r in rows}
    lines = ["Two equal spheres approaching each other (each at U): the force on one, resolved + "
             "correction, over 6 pi mu a U against the exact series (Brenner's sphere and free "
             "surface; resolved alone in brackets). h is the gap between the spheres; the pair's "
             f"resolved gap c = {PAIR_RESOLVED_GAP_CELLS:.3f} is sqrt(2) x the walls' 0.62 "
             "(fitted on the sphere and the wall), a prediction.", "",
             "| h/d | exact | " + " | ".join(f"{c} cells/d: total (resolved)" for c in cpds) + " |",
             "|---|---|" + "---|" * len(cpds)]
    for g in sorted({float(r["gap"]) for r in rows}, reverse=True):
        cells = ["-" if (c, g) not in by else f"{float(by[(c, g)]['error_pct']):+.1f} % "
                 f"({float(by[(c, g)]['error_pct_hydro_only']):+.1f} %)" for c in cpds]
        lines.append(f"| {g:g} | {two_spheres_approaching(g / A):.4g} | " + " | ".join(cells) + " |")
    gg = np.logspace(-3, 0, 200)
    force_figure(rows, (gg, [two_spheres_approaching(x / A) for x in gg]),
                 "exact (Brenner 1961, free surface)", "F / (6 pi mu a U)",
                 "resolved + correction against the exact force [%]",
                 "Two spheres approaching each other (Stokes): resolved force plus correction",
                 os.path.join(RESULTS, "pair.png"), log_force=True, fitted_here=False)
    return "\n".join(lines)


def resolution_changes(rows):
    """{gap: change of the total force in % from the coarsest to the finest resolution run at
    that gap} over the gaps run at two resolutions or more."""
    out = {}
    for g in sorted({float(r["gap"]) for r in rows}):
        at = sorted((int(r["cpd"]), float(r["F_total"])) for r in rows if float(r["gap"]) == g)
        if len(at) > 1:
            out[g] = 100 * (at[-1][1] / at[0][1] - 1)
    return out


def spheroid_table_and_figure(rows, sphere_rows):
    """The spheroids' table (markdown, returned) and results/spheroid.png: the force over the
    paraboloid's leading term and the excess over it, against the sphere's exact values."""
    shapes = sorted({r["shape"] for r in rows})
    cpds = sorted({int(r["cpd"]) for r in rows})
    lines = ["Prolate spheroid AR 2 (minor diameter d) approaching the wall, and two crossed "
             "ones approaching each other side by side (prolatePairCrossed, each at U: F_par at "
             "the closing speed 2U, the force on one body): the force, resolved + "
             "correction, over the paraboloid's leading term F_par = 6 pi mu U R*^2/h (resolved "
             "alone in brackets); the Reynolds equation on the exact gap over F_par "
             "(validation/squeezeFilm); the change of the total from the coarsest to the finest "
             "resolution; and the excess (F - F_par)/(6 pi mu a U), a = d/2. The sphere's exact "
             "values (Brenner) for comparison: F/F_par = h lambda/a, excess lambda - a/h.", "",
             "| shape | R*/a | h/d | F_par/(6 pi mu a U) | " + " | ".join(
                 f"{c} cells/d: F/F_par (resolved)" for c in cpds)
             + " | Reynolds, exact gap | resolution change | " + " | ".join(
                 f"{c} cells/d: excess" for c in cpds) + " | sphere: F/F_par, excess |",
             "|---|---|---|---|" + "---|" * len(cpds) + "---|---|" + "---|" * len(cpds) + "---|"]
    for shape in shapes:
        sel = [r for r in rows if r["shape"] == shape]
        by = {(int(r["cpd"]), float(r["gap"])): r for r in sel}
        change = resolution_changes(sel)
        for g in sorted({float(r["gap"]) for r in sel}, reverse=True):
            any_row = next(by[(c, g)] for c in cpds if (c, g) in by)
            par = float(any_row["paraboloid"])
            ratio = ["-" if (c, g) not in by else f"{float(by[(c, g)]['ratio']):.4f} "
                     f"({float(by[(c, g)]['ratio_hydro_only']):.3f})" for c in cpds]
            excess = ["-" if (c, g) not in by else
                      f"{float(by[(c, g)]['F_total']) - par:.3f}" for c in cpds]
            lam = brenner(g / A)
            rey = any_row["reynolds_exact_gap_ratio"]
            lines.append(f"| {shape} | {SHAPES[shape][1] / A:.3f} | {g:g} | {par:.4g} | "
                         + " | ".join(ratio) + f" | {f'{float(rey):.4f}' if rey else '-'} | "
                         + (f"{change[g]:+.2f} %" if g in change else "-") + " | "
                         + " | ".join(excess) + f" | {lam * g / A:.4f}, {lam - A / g:.3f} |")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axs = plt.subplots(1, 2, figsize=(11, 4))
    gg = np.logspace(math.log10(0.001), math.log10(0.1), 100)
    axs[0].semilogx(gg, [brenner(x / A) * x / A for x in gg], "k-", label="sphere, exact (Brenner)")
    axs[1].semilogx(gg, [brenner(x / A) - A / x for x in gg], "k-", label="sphere, exact (Brenner)")
    sphere_at = sorted((float(r["gap"]), int(r["cpd"]), float(r["F_total"])) for r in sphere_rows
                       if float(r["gap"]) <= 0.1)
    for k, c in enumerate(sorted({c for _, c, _ in sphere_at})):
        pts = [(g, f) for g, cc, f in sphere_at if cc == c]
        axs[0].semilogx([g for g, _ in pts], [f * g / A for g, f in pts], "k" + "sd^"[k % 3],
                        mfc="none", label=f"sphere, {c} cells/d")
        axs[1].semilogx([g for g, _ in pts], [f - A / g for g, f in pts], "k" + "sd^"[k % 3],
                        mfc="none", label=f"sphere, {c} cells/d")
    for i, shape in enumerate(shapes):
        sel = [r for r in rows if r["shape"] == shape]
        for k, c in enumerate(cpds):
            pts = sorted((float(r["gap"]), r) for r in sel if int(r["cpd"]) == c)
            if not pts:
                continue
            style = dict(color=f"C{i}", marker="o^s"[k % 3], linestyle="-" if k == 0 else "--")
            axs[0].semilogx([g for g, _ in pts], [float(r["ratio"]) for _, r in pts],
                            label=f"{shape}, {c} cells/d", **style)
            axs[1].semilogx([g for g, _ in pts],
                            [float(r["F_total"]) - float(r["paraboloid"]) for _, r in pts],
                            label=f"{shape}, {c} cells/d", **style)
        rey = sorted((float(r["gap"]), float(r["reynolds_exact_gap_ratio"])) for r in sel
                     if r["reynolds_exact_gap_ratio"])
        if rey:
            axs[0].semilogx([g for g, _ in rey], [v for _, v in rey], ":", color=f"C{i}",
                            label=f"{shape}, Reynolds on the exact gap")
    axs[0].axhline(1, color="0.5", lw=0.8)
    axs[0].set_ylabel("F / F_par (paraboloid's leading term)")
    axs[1].set_ylabel("(F - F_par) / (6 pi mu a U)")
    for ax in axs:
        ax.set_xlabel("gap h / d")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=6)
    fig.suptitle("Prolate spheroids AR 2 approaching a wall or each other (Stokes): "
                 "resolved force plus correction")
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "spheroid.png"), dpi=120)
    plt.close(fig)
    return "\n".join(lines)


def default_box(row):
    """Whether a run is in the standard box (rows without the column are)."""
    return float(row.get("box_half") or BOX_HALF) == BOX_HALF


def sliding_table_and_figure(rows):
    """The sliding sphere's table (markdown, returned) and results/sliding.png: drag and torque,
    resolved plus correction against the reference of sphereWallStokes.py."""
    cpds = sorted({int(r["cpd"]) for r in rows})
    gaps = sorted({float(r["gap"]) for r in rows}, reverse=True)
    by = {(int(r["cpd"]), float(r["gap"])): r for r in rows}
    lines = ["Sphere sliding parallel to the wall (no rotation): drag F_x/(6 pi mu a U), resolved + "
             "correction against the reference (resolved alone in brackets); torque about the "
             "rolling axis T_y/(8 pi mu a^2 U) total against the reference.", "",
             "| h/d | drag reference | " + " | ".join(f"{c} cells/d: drag (resolved)" for c in cpds)
             + " | torque reference | " + " | ".join(f"{c} cells/d: torque" for c in cpds) + " |",
             "|---|---|" + "---|" * len(cpds) + "---|" + "---|" * len(cpds)]
    for g in gaps:
        any_row = next(by[(c, g)] for c in cpds if (c, g) in by)
        drag, torque = [], []
        for c in cpds:
            r = by.get((c, g))
            drag.append("-" if r is None else f"{float(r['error_pct']):+.1f} % "
                        f"({float(r['error_pct_hydro_only']):+.1f} %)")
            torque.append("-" if r is None else f"{float(r['T_total']):.4g}")
        lines.append(f"| {g:g} | {float(any_row['reference']):.4g} | " + " | ".join(drag)
                     + f" | {float(any_row['torque_reference']):.4g} | " + " | ".join(torque) + " |")
    ref = sorted((float(r["gap"]), float(r["reference"])) for r in rows)
    force_figure(rows, ([g for g, _ in ref], [f for _, f in ref]), "exact (sphereWallStokes.py)",
                 "drag F_x / (6 pi mu a U)", "resolved + correction against the exact drag [%]",
                 "Sphere sliding parallel to a wall (Stokes): resolved drag plus lubrication correction",
                 os.path.join(RESULTS, "sliding.png"), log_force=False)
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sp = ap.add_subparsers(dest="cmd", required=True)
    r = sp.add_parser("run")
    r.add_argument("--cpd", type=int, default=8, choices=[4, 8, 12, 16])
    r.add_argument("--gap", type=float, action="append", default=[],
                   help="h/d (repeatable; default: all of GAPS)")
    r.add_argument("--quick", action="store_true", help="one gap, 1 d^2/nu, not recorded")
    r.add_argument("--force", action="store_true")
    r.add_argument("--rescore", action="store_true",
                   help="continue finished runs by a few steps with the solver as built now")
    r.add_argument("--box-half", type=float, default=BOX_HALF,
                   help=f"half width of the box in d (default {BOX_HALF:g}; other widths are "
                        "checks of the box's effect, listed apart)")
    r.add_argument("--motion", choices=sorted(MOTIONS), default="approach",
                   help="approach: towards the wall (Brenner); sliding: parallel to it")
    r.add_argument("--shape", choices=sorted(SHAPES), default="sphere",
                   help="a prolate spheroid AR 2 (minor diameter d) approaching the wall "
                        "broadside or tip-on, or two crossed ones approaching each other "
                        "(default gaps: SPHEROID_GAPS); two spheres (spherePair, PAIR_GAPS)")
    fp = sp.add_parser("fit")
    fp.add_argument("--cpd", type=int, default=8, choices=[4, 8, 12, 16])
    sp.add_parser("plot")
    a = ap.parse_args()
    if a.cmd == "run":
        default = {"sphere": GAPS, "spherePair": PAIR_GAPS}.get(a.shape, SPHEROID_GAPS)
        for gap in a.gap or ([0.5] if a.quick else default):
            run_one(a.cpd, gap, a.force, a.quick, a.rescore, a.motion, a.box_half, a.shape)
    elif a.cmd == "fit":
        do_fit(a.cpd)
    else:
        do_plot()


if __name__ == "__main__":
    main()
