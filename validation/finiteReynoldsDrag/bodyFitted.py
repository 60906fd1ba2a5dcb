#!/usr/bin/python3
"""Independent reference for the drag and lift: body-fitted simpleFoam solutions (no
immersed body) of the sphere and of the prolate spheroid AR 2.5 on three meshes each
(validation/finiteReynoldsDrag, README "Body-fitted reference"): axisymmetric wedges
along the axis (bodyFittedMesh), half-space three-dimensional meshes at 45 and 90 degrees
(bodyFittedMesh3D; the sphere at 90 degrees checks them against the wedge).

    bodyFitted.py run [--force] [--only NAME ...]   the campaign (two may run at once) (finiteReynoldsDrag.py plot
                                                    adds it to results/table.md, metrics.json)
    bodyFitted.py collect                           C_D, C_L, C_T and their changes again from the
                                                    runs' force and moment files
    bodyFitted.py single CASE --ar AR --re RE --n-eta N [--incidence DEG] [--iterations I]
        one case in the folder CASE; writes CASE/drag.csv (used by
        tests/foam/finiteReynoldsDragBodyFitted)

Each case is a steady solve until the initial residuals of p and U fall below 1e-10
(simpleFoam's residualControl), at most ITERATIONS iterations: the end is decided inside
the solver, so the run is deterministic. The drag is the last iteration's; its change
over the last ITER_WINDOW iterations is recorded. Runs in run-bodyFitted/<name>/ (git-ignored).

The pitching torque C_T = T_z/(rho U^2/2 pi D_eq^2/4 D_eq/2) (Zastawny et al.'s
normalisation, references.zastawny_torque) is the moment the forces function object
writes about CofR (0 0 0), the body's centre (the meshes are centred on it), positive
when it turns the symmetry axis (x) away from the stream (cos theta, sin theta, 0),
towards broadside: C_T = -T_z/(...).
"""
import argparse
import fcntl
import math
import os
import shutil
import sys
from pathlib import Path

import bodyFittedMesh
import bodyFittedMesh3D

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
from validationTools import cpu_seconds, provenance, read_csv, run_logged, write_csv, write_dict  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "results")
CSV = os.path.join(RESULTS, "bodyFitted.csv")
OUTER_RADIUS = 100.0     # outer boundary, in D_eq
ITERATIONS = 800
ITER_WINDOW = 50
N_ETA = (32, 64, 128)   # cells over the half meridian: the three wedge meshes
N_ETA_3D = (32, 48, 72)  # the half-space meshes, n_eta/2 cells over phi in [0, pi]
N_ETA_3D_RE100 = 108     # a fourth for the spheroid at Re 100 (its coarse meshes converge slowly)
ITERATIONS_RE100_FINEST = 400   # its cap (1 M cells); the table reports how much it still moves
FIELDS = ["name", "ar", "Re", "incidence", "n_eta", "cells", "wall_cells_per_D", "iterations",
          "C_D", "C_L", "C_D_change_pct", "C_L_change_pct", "cpu_s", "host", "date", "commit",
          "C_T", "C_T_change_pct"]
SIDES = {"wedge": "front { type wedge; }\n    back { type wedge; }",
         "half": "symmetry { type symmetryPlane; }"}

FILES = {
    "system/controlDict": """application simpleFoam;
startFrom latestTime; startTime 0; stopAt endTime; endTime @ITERATIONS@;
deltaT 1; writeControl timeStep; writeInterval @ITERATIONS@; purgeWrite 1;
writeFormat binary; writePrecision 12; runTimeModifiable false;
functions
{
    forces
    {
        type forces; libs ("libforces.so"); patches (body);
        rho rhoInf; rhoInf 1; CofR (0 0 0); writeControl timeStep; writeInterval 1;
        log false;
    }
}
""",
    "system/fvSchemes": """ddtSchemes { default steadyState; }
gradSchemes { default Gauss linear; }
divSchemes
{
    default none;
    div(phi,U) bounded Gauss linearUpwind grad(U);
    div((nuEff*dev2(T(grad(U))))) Gauss linear;
}
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
""",
    "system/fvSolution": """solvers
{
    p { solver GAMG; smoother GaussSeidel; tolerance 1e-12; relTol 0.01; }
    U { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-12; relTol 0.01; }
}
SIMPLE { nNonOrthogonalCorrectors 0; consistent yes; residualControl { p 1e-10; U 1e-10; } }
relaxationFactors { equations { U 0.9; } }
""",
    "constant/transportProperties": "transportModel Newtonian;\nnu @NU@;\n",
    "constant/turbulenceProperties": "simulationType laminar;\n",
    "0/U": """dimensions [0 1 -1 0 0 0 0];
internalField uniform @UINF@;
boundaryField
{
    body { type noSlip; }
    inlet { type fixedValue; value uniform @UINF@; }
    outlet { type inletOutlet; inletValue uniform (0 0 0); value uniform @UINF@; }
    @SIDES@
}
""",
    "0/p": """dimensions [0 2 -2 0 0 0 0];
internalField uniform 0;
boundaryField
{
    body { type zeroGradient; }
    inlet { type zeroGradient; }
    outlet { type fixedValue; value uniform 0; }
    @SIDES@
}
""",
}


def campaign():
    """[(name, {ar, re, n_eta, incidence})]: incidence 0 on wedges, the others in 3D."""
    runs = [(f"sphere-Re{re}-n{n}", dict(ar=1.0, re=re, n_eta=n))
            for re in (20, 50, 100) for n in N_ETA]
    runs += [(f"prolate-Re{re}-n{n}", dict(ar=2.5, re=re, n_eta=n))
             for re in (20, 100) for n in N_ETA]
    runs += [(f"sphere-Re100-i90-n{n}", dict(ar=1.0, re=100, n_eta=n, incidence=90))
             for n in N_ETA_3D]
    runs += [(f"prolate-Re{re}-i{i}-n{n}", dict(ar=2.5, re=re, n_eta=n, incidence=i))
             for re in (20, 100) for i in (45, 90) for n in N_ETA_3D]
    runs += [(f"prolate-Re100-i{i}-n{N_ETA_3D_RE100}",
              dict(ar=2.5, re=100, n_eta=N_ETA_3D_RE100, incidence=i,
                   iterations=ITERATIONS_RE100_FINEST)) for i in (45, 90)]
    return runs


def write_case(case, ar, re, n_eta, incidence=0, iterations=ITERATIONS):
    """The case and its mesh (a wedge at incidence 0, else the half space); the cells."""
    if os.path.exists(case):
        shutil.rmtree(case)
    theta = math.radians(incidence)
    values = {"@ITERATIONS@": str(iterations), "@NU@": f"{1.0 / re:.12g}",
              "@UINF@": f"({math.cos(theta):.15g} {math.sin(theta):.15g} 0)",
              "@SIDES@": SIDES["half" if incidence else "wedge"]}
    for rel, text in FILES.items():
        for key, value in values.items():
            text = text.replace(key, value)
        cls = "volVectorField" if rel == "0/U" else "volScalarField" if rel == "0/p" else "dictionary"
        write_dict(os.path.join(case, rel), cls, os.path.dirname(rel), os.path.basename(rel),
                   text, f"validation/finiteReynoldsDrag/bodyFitted.py: {os.path.basename(case)}")
    if incidence:
        return bodyFittedMesh3D.write_mesh(case, ar, n_eta, n_eta // 2, OUTER_RADIUS, incidence)
    return bodyFittedMesh.write_mesh(case, ar, n_eta, OUTER_RADIUS)


def _vectors(path):
    """The first vector (the total) of each line of a forces function object's file."""
    out = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            v = line.replace("(", " ").replace(")", " ").split()
            out.append((float(v[1]), float(v[2]), float(v[3])))
    return out


def read_coefficients(case, incidence=0):
    """[(C_D, C_L, C_T)] per iteration: the force along and across the stream (in the plane
    of the stream and the axis) of the whole body (the wedge's times 360/WEDGE_DEG, the half
    space's times 2) over rho U^2/2 pi/4, and the pitching torque about the centre over
    rho U^2/2 pi/4 1/2 (zero by symmetry on the wedge). The mirror image of the half space
    in z = 0 has the same T_z, so the whole body's is twice the half's."""
    folder = os.path.join(case, "postProcessing", "forces", "0")
    whole = 2.0 if incidence else 360.0 / bodyFittedMesh.WEDGE_DEG
    scale = whole / (0.5 * math.pi / 4)
    theta = math.radians(incidence)
    forces = _vectors(os.path.join(folder, "force.dat"))
    torques = (_vectors(os.path.join(folder, "moment.dat")) if incidence
               else [(0.0, 0.0, 0.0)] * len(forces))
    if len(torques) != len(forces):
        raise RuntimeError(f"{case}: force.dat and moment.dat have different lengths")
    out = []
    for (fx, fy, _), (_, _, tz) in zip(forces, torques):
        lift = abs(-fx * math.sin(theta) + fy * math.cos(theta)) if incidence else 0.0
        out.append((scale * (fx * math.cos(theta) + fy * math.sin(theta)), scale * lift,
                    -scale * tz / 0.5))
    return out


def wall_cells_per_d(ar, n_eta):
    """The cells along the body's meridian per D_eq (its mean resolution), formatted."""
    X, R = bodyFittedMesh.meridian_nodes(ar, n_eta, OUTER_RADIUS)
    length = sum(math.hypot(X[0, j + 1] - X[0, j], R[0, j + 1] - R[0, j]) for j in range(n_eta))
    return f"{n_eta / length:.1f}"


def force_columns(coefficients):
    """The columns iterations, C_D, C_L and C_T (the last iteration's) and C_D_change_pct,
    C_L_change_pct, C_T_change_pct (their change over the last ITER_WINDOW iterations, or
    half the run if shorter, relative; 0 for a lift or torque below 1e-4, zero by
    symmetry)."""
    back = -1 - min(ITER_WINDOW, len(coefficients) // 2)
    (cd, cl, ct), (cd0, cl0, ct0) = coefficients[-1], coefficients[back]
    return dict(iterations=len(coefficients), C_D=f"{cd:.6f}", C_L=f"{cl:.6f}",
                C_D_change_pct=f"{100 * (cd - cd0) / cd:.2e}",
                C_L_change_pct=f"{100 * (cl - cl0) / cl if cl > 1e-4 else 0.0:.2e}",
                C_T=f"{ct:.6f}",
                C_T_change_pct=f"{100 * (ct - ct0) / ct if abs(ct) > 1e-4 else 0.0:.2e}")


def run_case(name, ar, re, n_eta, incidence=0, case=None, iterations=ITERATIONS):
    case = case or os.path.join(HERE, "run-bodyFitted", name)
    cells = write_case(case, ar, re, n_eta, incidence, iterations)
    print(f"{name}: {cells} cells", flush=True)
    for app in (["checkMesh"], ["nice", "-n", "10", "simpleFoam"]):
        if run_logged(app, case, f"log.{app[-1]}") != 0:
            raise RuntimeError(f"{app[-1]} failed in {case} (see log.{app[-1]})")
    row = dict(name=name, ar=ar, Re=re, incidence=incidence, n_eta=n_eta, cells=cells,
               wall_cells_per_D=wall_cells_per_d(ar, n_eta),
               **force_columns(read_coefficients(case, incidence)),
               cpu_s=f"{cpu_seconds(case, 'log.simpleFoam'):.0f}",
               **provenance())
    return row


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("mode", choices=["run", "collect", "single"])
    parser.add_argument("case", nargs="?")
    parser.add_argument("--force", action="store_true")
    parser.add_argument("--only", action="append")
    parser.add_argument("--ar", type=float, default=1.0)
    parser.add_argument("--re", type=float, default=20.0)
    parser.add_argument("--n-eta", type=int, default=32)
    parser.add_argument("--incidence", type=float, default=0.0)
    parser.add_argument("--iterations", type=int, default=ITERATIONS)
    args = parser.parse_args()
    if args.mode == "collect":
        rows = read_csv(CSV, missing_ok=False)
        for r in rows:
            incidence = float(r.get("incidence") or 0)
            r.update(force_columns(read_coefficients(
                         os.path.join(HERE, "run-bodyFitted", r["name"]), incidence)),
                     incidence=f"{incidence:g}",
                     wall_cells_per_D=wall_cells_per_d(float(r["ar"]), int(r["n_eta"])))
        write_csv(CSV, rows, FIELDS)
    if args.mode == "single":
        if not args.case:
            parser.error("single needs the folder CASE")
        row = run_case(os.path.basename(args.case), args.ar, args.re, args.n_eta,
                       args.incidence, case=os.path.abspath(args.case), iterations=args.iterations)
        write_csv(os.path.join(args.case, "drag.csv"), [row], FIELDS)
        return
    if args.mode == "run":
        os.makedirs(RESULTS, exist_ok=True)
        done = {r["name"] for r in read_csv(CSV)} if os.path.exists(CSV) else set()
        for name, kw in campaign():
            if args.only and name not in args.only:
                continue
            if name in done and not args.force:
                continue
            row = run_case(name, **kw)
            with open(CSV + ".lock", "w") as lock:
                fcntl.flock(lock, fcntl.LOCK_EX)    # two campaigns may share the machine
                rows = [r for r in (read_csv(CSV) if os.path.exists(CSV) else [])
                        if r["name"] != name]
                write_csv(CSV, rows + [row], FIELDS)
    import bodyFittedTable
    print("\n".join(bodyFittedTable.tables(CSV)[0]))


if __name__ == "__main__":
    main()
