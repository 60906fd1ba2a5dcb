#!/usr/bin/python3
"""Body-fitted reference for validation/tenCate, case E1: the steady terminal settling speed
of the sphere (d 15 mm, rho_p 1120 kg/m^3; fluid rho_f 970 kg/m^3, mu 0.373 Pa s) on the axis
of an infinitely long square duct with the box's cross-section (100 mm x 100 mm). The box's
floor, lid and the acceleration from rest only slow the sphere, so this speed is an upper
bound of the largest settling speed u_max in the experiment's box.

    ductReference.py run [--force] [--only NAME ...]   mesh, solve and collect (the campaign)
    ductReference.py collect                           the table and summary from the runs again
    ductReference.py list                              the campaign's cases

Set-up, in the sphere's frame (steady, laminar simpleFoam): the sphere fixed (no-slip), the
duct walls moving at the settling speed U along the axis (+z), a uniform inflow U at the
upstream end, p = 0 at the downstream end. A quarter of the duct is meshed (symmetryPlane
patches at x = 0 and y = 0); blockMesh background plus snappyHexMesh on a searchableSphere
(snapped, no boundary layers). The drag is the forces function object's z-force (pressure +
viscous, rho = rho_f) times 4.

Cases (run/<name>/, git-ignored; the meshes in run/mesh-<mesh>/):
  m17 ... m48       four meshes, 16.8 / 24 / 33.6 / 48 cells per sphere diameter: the same
                    level structure (surface level 3) on backgrounds of 7, 10, 14, 20 cells
                    over the quarter's half-width; each at U = 0.034 and 0.037 m/s
  m17 at U_t(m17)   the linearity check: the coarse mesh at its own interpolated U_t
  m17long           the coarse mesh in a duct 1.5 times as long (upstream 15 d,
                    downstream 22.5 d), at U = 0.034: the sensitivity to the duct's length
  wide24            the set-up check: a 32 d x 32 d duct (walls moving at U, i.e. at rest
                    in the fluid far away), 24 cells/D near the sphere, against the
                    unbounded correlations at the same Re; wide24x64 the same 64 d x 64 d,
                    wide24long the same twice as long: what is left of the walls and ends
  wedge-n64, -n128  the unbounded sphere at the same Re on another mesh generator: the
                    axisymmetric body-fitted wedges of validation/finiteReynoldsDrag
                    (bodyFitted.write_case: conformal, orthogonal cells, outer boundary at
                    100 d; 64 and 128 cells over the half meridian), an accurate C_D to
                    tell the correlations' own error from the wide duct's

Each solve stops when the initial residuals of p and U fall below RESIDUAL (simpleFoam's
residualControl, so the end is decided inside the solver) and is continued if the drag still
changed by more than CONVERGED_CHANGE (relative) over the last ITER_WINDOW iterations (the
wedges keep bodyFitted's residualControl, 1e-10, at most ITERATIONS iterations).
The terminal speed of a mesh is the linear interpolation of F(U) = W between the two speeds;
its Richardson extrapolation uses the three finest meshes (h = 1/background cells; the
coarsest three are a check of the asymptotic range) with the generalised procedure for
unequal refinement ratios (Celik et al. 2008, J. Fluids Eng. 130, 078001). Results:
results/duct.csv, results/summary.md and results/metrics.json, with ten Cate's u_max and the
module's against the bound (validation/tenCate/results, Allrun -plot) and, if
results/immersed.csv exists (ductImmersed.py), the module's sphere in the same duct. The whole campaign takes about 45 min of one core
(2 GHz Xeon), the finest duct mesh about 13 min per speed.
"""
import argparse
import json
import math
import os
import re
import resource
import shutil
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools"))
from validationTools import cpu_seconds, read_csv, run_logged, write_csv, write_dict  # noqa: E402

# the unbounded wedge reference's case writer (imported, not modified)
sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "finiteReynoldsDrag"))
import bodyFitted  # noqa: E402
import references  # noqa: E402  (the drag correlations)
from references import clift, schiller_naumann  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
RUN = os.path.join(HERE, "run")
RESULTS = os.path.join(HERE, "results")
CSV = os.path.join(RESULTS, "duct.csv")
SUMMARY = os.path.join(RESULTS, "summary.md")
METRICS = os.path.join(RESULTS, "metrics.json")
IMMERSED = os.path.join(RESULTS, "immersed.csv")   # ductImmersed.py's rows
FIELDS = ["name", "mesh", "cells", "U", "Re", "drag_N", "drag_over_weight", "iterations",
          "converged_change", "cpu_s"]

# physical parameters (SI), ten Cate et al. (2002) case E1
D = 0.015
RHO_P = 1120.0
RHO_F = 970.0
MU = 0.373
NU = MU / RHO_F
G = 9.81
WEIGHT = (RHO_P - RHO_F) * G * math.pi * D ** 3 / 6.0   # net weight W (N)
HALF_WIDTH = 0.05     # the duct's half-width (the quarter's side)
SPEEDS = (0.034, 0.037)
TEN_CATE_RESULTS = Path(__file__).resolve().parents[1] / "results"


def e1_speeds():
    """For comparison in the summary, from validation/tenCate/results (Allrun -plot): the
    measured u_max of case E1 (the published value, the same with the unrounded u_inf, and
    the digitised curve's largest speed) and the module's u_max per cells/D (the case's
    default mesh, time step and forcing)."""
    metrics = json.load(open(TEN_CATE_RESULTS / "metrics.json"))
    rows = [r for r in read_csv(str(TEN_CATE_RESULTS / "summary.csv"))
            if r["case"] == "E1" and not r["variant"] and r["column"] == "2.5"
            and r["dtScale"] == "1" and r["forcing"] == "surfaceCorrected"]
    measured = [float(rows[0]["umaxRef"]), metrics["E1_reference_umax_unrounded_m_s"],
                metrics["E1_data_curve_umax_m_s"]]
    return measured, {int(r["cpd"]): float(r["umax"]) for r in rows}

# numerics
SURFACE_LEVEL = 3                  # snappy's level on the sphere (duct meshes)
# distance refinement around the sphere: (distance from its surface / d, level below the
# surface level); the same structure on every mesh so that the series refines consistently
SHELLS = ((0.3, 0), (1.0, 1), (2.5, 2))
RESIDUAL = 1e-9
ITERATIONS = 4000                  # first run's cap
ITERATIONS_MAX = 12000             # cap over all continuations
ITER_WINDOW = 50
CONVERGED_CHANGE = 1e-5


def mesh_spec(n, upstream=10.0, downstream=15.0, half_width=HALF_WIDTH, level=SURFACE_LEVEL,
              wall="duct"):
    """A mesh: n background cells over the half-width, the sphere's surface at level; the
    inlet upstream and the outlet downstream sphere diameters from the sphere's centre."""
    return dict(n=n, upstream=upstream, downstream=downstream, half_width=half_width,
                level=level, wall=wall)


MESHES = {
    "m17": mesh_spec(7),
    "m24": mesh_spec(10),
    "m34": mesh_spec(14),
    "m48": mesh_spec(20),
    "m17long": mesh_spec(7, upstream=15.0, downstream=22.5),
    # 32 d x 32 d; background d/1.5, surface level 4: 24 cells/D and the same shells as
    # m24 (SHELLS plus one more level outside them)
    "wide24": mesh_spec(24, half_width=16 * D, level=4, wall="wide"),
    # the same near the sphere: the duct twice as wide (64 d; background d/0.75, one level
    # more), and twice as long (upstream 20 d, downstream 30 d)
    "wide24x64": mesh_spec(24, half_width=32 * D, level=5, wall="wide"),
    "wide24long": mesh_spec(24, half_width=16 * D, level=4, wall="wide", upstream=20.0,
                            downstream=30.0),
}
# the unbounded axisymmetric reference: cells over the half meridian
WEDGES = {"wedge-n64": 64, "wedge-n128": 128}
WIDE = ("wide24", "wide24x64", "wide24long")   # the set-up check and its sensitivities
SERIES = ("m17", "m24", "m34", "m48")   # the convergence study, coarse first; the
                                        # extrapolation uses the finest three


def cells_per_d(mesh):
    """The cells per sphere diameter at the surface (the wedge's: along its meridian)."""
    if mesh in WEDGES:
        return 2.0 * WEDGES[mesh] / math.pi   # n cells over the half meridian, pi d / 2
    spec = MESHES[mesh]
    return D * spec["n"] * 2 ** spec["level"] / spec["half_width"]


def campaign():
    """[(name, mesh, U)]; U None: the coarse mesh's own interpolated terminal speed."""
    runs = [(f"{m}-U{u:.4f}", m, u) for m in SERIES for u in SPEEDS]
    runs.append(("m17-Ut", "m17", None))
    runs.append(("m17long-U0.0340", "m17long", 0.034))
    runs += [(f"{m}-U0.0340", m, 0.034) for m in WIDE]
    runs += [(f"{m}-U0.0340", m, 0.034) for m in WEDGES]
    return runs


# ---------------------------------------------------------------------------
# case files

BLOCK_MESH = """convertToMeters 1;
vertices
(
    (0 0 @Z0@) (@H@ 0 @Z0@) (@H@ @H@ @Z0@) (0 @H@ @Z0@)
    (0 0 0) (@H@ 0 0) (@H@ @H@ 0) (0 @H@ 0)
    (0 0 @Z1@) (@H@ 0 @Z1@) (@H@ @H@ @Z1@) (0 @H@ @Z1@)
);
blocks
(
    hex (0 1 2 3 4 5 6 7) (@N@ @N@ @NZU@) simpleGrading (1 1 1)
    hex (4 5 6 7 8 9 10 11) (@N@ @N@ @NZD@) simpleGrading (1 1 1)
);
edges ();
boundary
(
    inlet { type patch; faces ((0 3 2 1)); }
    outlet { type patch; faces ((8 9 10 11)); }
    walls { type wall; faces ((1 2 6 5) (5 6 10 9) (2 3 7 6) (6 7 11 10)); }
    symX { type symmetryPlane; faces ((0 4 7 3) (4 8 11 7)); }
    symY { type symmetryPlane; faces ((0 1 5 4) (4 5 9 8)); }
);
mergePatchPairs ();
"""

SNAPPY = """castellatedMesh true;
snap true;
addLayers false;
geometry
{
    sphere { type searchableSphere; centre (0 0 0); radius @R@; }
}
castellatedMeshControls
{
    maxLocalCells 2000000; maxGlobalCells 4000000; minRefinementCells 0;
    maxLoadUnbalance 0.1; nCellsBetweenLevels 3;
    features ();
    refinementSurfaces { sphere { level (@LEVEL@ @LEVEL@); patchInfo { type wall; } } }
    resolveFeatureAngle 30;
    refinementRegions { sphere { mode distance; levels (@SHELLS@); } }
    locationInMesh (@INSIDE@);
    allowFreeStandingZoneFaces true;
}
snapControls
{
    nSmoothPatch 3; tolerance 2.0; nSolveIter 100; nRelaxIter 5;
    nFeatureSnapIter 10; implicitFeatureSnap false; explicitFeatureSnap false;
    multiRegionFeatureSnap false;
}
addLayersControls
{
    relativeSizes true; layers {}; expansionRatio 1.2; finalLayerThickness 0.5;
    minThickness 0.1; nGrow 0; featureAngle 60; nRelaxIter 3; nSmoothSurfaceNormals 1;
    nSmoothNormals 3; nSmoothThickness 10; maxFaceThicknessRatio 0.5;
    maxThicknessToMedialRatio 0.3; minMedialAxisAngle 90; nBufferCellsNoExtrude 0;
    nLayerIter 50;
}
meshQualityControls
{
    maxNonOrtho 65; maxBoundarySkewness 20; maxInternalSkewness 4; maxConcave 80;
    minVol 1e-13; minTetQuality 1e-15; minArea -1; minTwist 0.02; minDeterminant 0.001;
    minFaceWeight 0.05; minVolRatio 0.01; minTriangleTwist -1; nSmoothScale 4;
    errorReduction 0.75;
}
mergeTolerance 1e-6;
"""

CONTROL = """application simpleFoam;
startFrom latestTime; startTime 0; stopAt endTime; endTime @END@;
deltaT 1; writeControl timeStep; writeInterval @END@; purgeWrite 1;
writeFormat binary; writePrecision 12; runTimeModifiable false;
functions
{
    forces
    {
        type forces; libs ("libforces.so"); patches (sphere);
        rho rhoInf; rhoInf @RHO@; CofR (0 0 0); writeControl timeStep; writeInterval 1;
        log false;
    }
}
"""

# second-order convection, the schemes of validation/finiteReynoldsDrag/bodyFitted.py
SCHEMES = bodyFitted.FILES["system/fvSchemes"]

SOLUTION = """solvers
{
    p { solver GAMG; smoother GaussSeidel; tolerance 1e-14; relTol 0.01; }
    U { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-14; relTol 0.01; }
}
SIMPLE
{
    nNonOrthogonalCorrectors 0; consistent yes;
    residualControl { p @RES@; U @RES@; }
}
relaxationFactors { equations { U 0.9; } }
"""

FIELD_U = """dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 @U@);
boundaryField
{
    sphere { type noSlip; }
    inlet { type fixedValue; value uniform (0 0 @U@); }
    outlet { type inletOutlet; inletValue uniform (0 0 0); value uniform (0 0 @U@); }
    walls { type fixedValue; value uniform (0 0 @U@); }
    symX { type symmetryPlane; }
    symY { type symmetryPlane; }
}
"""

FIELD_P = """dimensions [0 2 -2 0 0 0 0];
internalField uniform 0;
boundaryField
{
    sphere { type zeroGradient; }
    inlet { type zeroGradient; }
    outlet { type fixedValue; value uniform 0; }
    walls { type zeroGradient; }
    symX { type symmetryPlane; }
    symY { type symmetryPlane; }
}
"""


def fill(text, values):
    """text with each @KEY@ replaced by values[KEY]; an @...@ left over is an error."""
    for key, value in values.items():
        text = text.replace(f"@{key}@", str(value))
    left = re.findall(r"@[A-Z0-9]+@", text)
    if left:
        raise RuntimeError(f"placeholders not filled: {left}")
    return text


def write_file(case, rel, body, cls="dictionary"):
    write_dict(os.path.join(case, rel), cls, os.path.dirname(rel), os.path.basename(rel), body,
               f"validation/tenCate/ductReference/ductReference.py: {os.path.basename(case)}")


def write_mesh_case(folder, spec):
    """blockMeshDict and snappyHexMeshDict (plus a minimal controlDict, fvSchemes and
    fvSolution, which the mesh utilities read) in folder."""
    h = spec["half_width"]
    cell = h / spec["n"]
    z0, z1 = -spec["upstream"] * D, spec["downstream"] * D
    # the sphere's centre on a background node (z = 0); the axial cells as near cubic as
    # the lengths allow
    nzu, nzd = (max(1, round(abs(z) / cell)) for z in (z0, z1))
    write_file(folder, "system/blockMeshDict", fill(BLOCK_MESH, dict(
        H=f"{h:.12g}", Z0=f"{z0:.12g}", Z1=f"{z1:.12g}", N=spec["n"], NZU=nzu, NZD=nzd)))
    level = spec["level"]
    shells = [(f, level - k) for f, k in SHELLS]
    if spec["wall"] == "wide":
        # the wide ducts' backgrounds are 2 or 4 times the duct meshes': a shell per level
        # more, each twice as far out
        shells += [(6.0 * 2 ** (k - 3), level - k) for k in range(3, level)]
    write_file(folder, "system/snappyHexMeshDict", fill(SNAPPY, dict(
        R=f"{D / 2:.12g}", LEVEL=level,
        SHELLS=" ".join(f"({f * D:.12g} {lv})" for f, lv in shells),
        # a point in the fluid off every face of the background and of its refinements
        INSIDE=f"{0.6137 * h:.12g} {0.5741 * h:.12g} {0.4313 * z1:.12g}")))
    # ASCII, so that sphere_area can read the mesh
    write_file(folder, "system/controlDict",
               fill(CONTROL, dict(END=1, RHO=RHO_F)).replace("writeFormat binary",
                                                              "writeFormat ascii"))
    write_file(folder, "system/fvSchemes", SCHEMES)
    write_file(folder, "system/fvSolution", fill(SOLUTION, dict(RES=RESIDUAL)))


def child_cpu():
    """The CPU time (user + system, s) of the finished child processes so far."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run(cmd, case, log):
    if run_logged(cmd, case, log) != 0:
        raise RuntimeError(f"{cmd[-1]} failed in {case} (see {log})")


def build_mesh(mesh):
    """run/mesh-<mesh>/ with its polyMesh (blockMesh, snappyHexMesh, checkMesh); reused when
    it is there. Returns the folder."""
    folder = os.path.join(RUN, f"mesh-{mesh}")
    done = os.path.join(folder, "log.checkMesh")
    if os.path.exists(done) and "Mesh OK." in open(done).read():
        return folder
    if os.path.exists(folder):
        shutil.rmtree(folder)
    write_mesh_case(folder, MESHES[mesh])
    start = child_cpu()
    run(["blockMesh"], folder, "log.blockMesh")
    run(["nice", "-n", "15", "snappyHexMesh", "-overwrite"], folder, "log.snappyHexMesh")
    run(["checkMesh"], folder, "log.checkMesh")
    with open(os.path.join(folder, "meshCpu"), "w") as f:
        f.write(f"{child_cpu() - start:.1f}\n")
    if "Mesh OK." not in open(done).read():
        raise RuntimeError(f"checkMesh failed for {folder}")
    return folder


def mesh_info(mesh):
    """(cells, sphere area over pi d^2 (the whole sphere), mesh CPU s) from the mesh's
    checkMesh log."""
    folder = os.path.join(RUN, f"mesh-{mesh}")
    if mesh in WEDGES:
        # the wedge's mesh is written with its case (run/<mesh>-U0.0340), in Python
        text = open(os.path.join(RUN, f"{mesh}-U0.0340", "log.checkMesh")).read()
        cells = int(re.search(r"^\s*cells:\s*(\d+)", text, re.M).group(1))
        return cells, float("nan"), 0.0
    text = open(os.path.join(folder, "log.checkMesh")).read()
    cells = int(re.search(r"^\s*cells:\s*(\d+)", text, re.M).group(1))
    area = sphere_area(folder)
    cpu = float(open(os.path.join(folder, "meshCpu")).read())
    return cells, area, cpu


def sphere_area(folder):
    """The area of the sphere patch (the quarter's, times 4) over pi d^2: how well snapping
    reproduced the surface. From polyMesh's points, faces and boundary."""
    poly = os.path.join(folder, "constant", "polyMesh")
    bnd = open(os.path.join(poly, "boundary")).read()
    m = re.search(r"sphere\s*\{[^}]*nFaces\s+(\d+);[^}]*startFace\s+(\d+);", bnd)
    n_faces, start = int(m.group(1)), int(m.group(2))
    points = _foam_list(os.path.join(poly, "points"), vector=True)
    faces = _foam_list(os.path.join(poly, "faces"), vector=False)
    area = 0.0
    for f in faces[start:start + n_faces]:
        p0 = points[f[0]]
        ax = ay = az = 0.0
        for i in range(1, len(f) - 1):
            a, b = points[f[i]], points[f[i + 1]]
            u = (a[0] - p0[0], a[1] - p0[1], a[2] - p0[2])
            v = (b[0] - p0[0], b[1] - p0[1], b[2] - p0[2])
            ax += u[1] * v[2] - u[2] * v[1]
            ay += u[2] * v[0] - u[0] * v[2]
            az += u[0] * v[1] - u[1] * v[0]
        area += 0.5 * math.sqrt(ax * ax + ay * ay + az * az)
    return 4.0 * area / (math.pi * D * D)


def _foam_list(path, vector):
    """An ASCII polyMesh points (vector True) or faces list."""
    text = open(path).read()
    body = text[text.index("}", text.index("FoamFile")) + 1:]
    if vector:
        triple = r"\(([^()\s]+)\s+([^()\s]+)\s+([^()\s]+)\)"
        return [tuple(map(float, t)) for t in re.findall(triple, body)]
    return [tuple(map(int, t.split())) for t in re.findall(r"\d+\(([\d\s]+)\)", body)]


def write_case(case, mesh, u):
    """The solver case: the mesh's polyMesh, the fields and the dictionaries at speed u."""
    if os.path.exists(case):
        shutil.rmtree(case)
    if mesh in WEDGES:
        # bodyFitted's case is dimensionless (d = 1, U = 1, nu = 1/Re): the same Re
        bodyFitted.write_case(case, 1.0, reynolds(u), WEDGES[mesh], 0, ITERATIONS)
        run(["checkMesh"], case, "log.checkMesh")
        return
    folder = build_mesh(mesh)
    shutil.copytree(os.path.join(folder, "constant", "polyMesh"),
                    os.path.join(case, "constant", "polyMesh"))
    os.makedirs(os.path.join(case, "system"))
    for rel in ("system/blockMeshDict", "system/snappyHexMeshDict"):
        shutil.copy(os.path.join(folder, rel), os.path.join(case, rel))
    write_file(case, "system/controlDict", fill(CONTROL, dict(END=ITERATIONS, RHO=RHO_F)))
    write_file(case, "system/fvSchemes", SCHEMES)
    write_file(case, "system/fvSolution", fill(SOLUTION, dict(RES=RESIDUAL)))
    write_file(case, "constant/transportProperties",
               f"transportModel Newtonian;\nnu {NU:.12g};\n")
    write_file(case, "constant/turbulenceProperties", "simulationType laminar;\n")
    write_file(case, "0/U", fill(FIELD_U, dict(U=f"{u:.12g}")), "volVectorField")
    write_file(case, "0/p", FIELD_P, "volScalarField")


# ---------------------------------------------------------------------------
# results

def drag_history(case, u=None):
    """The whole sphere's drag (N, along +z) per iteration: the forces function object's
    total z-force of the quarter times 4, over all (continued) runs of the case. A wedge
    case (u its speed): its C_D times rho_f u^2/2 pi d^2/4."""
    if os.path.basename(case).startswith("wedge"):
        scale = 0.5 * RHO_F * u * u * math.pi * D * D / 4.0
        return [c[0] * scale for c in bodyFitted.read_coefficients(case)]
    root = os.path.join(case, "postProcessing", "forces")
    rows = {}
    for start in sorted(os.listdir(root), key=float):
        with open(os.path.join(root, start, "force.dat")) as f:
            for line in f:
                if line.startswith("#") or not line.strip():
                    continue
                v = line.replace("(", " ").replace(")", " ").split()
                rows[int(float(v[0]))] = 4.0 * float(v[3])
    return [rows[k] for k in sorted(rows)]


def converged_change(drag):
    """The drag's change over the last ITER_WINDOW iterations, relative (absolute value)."""
    back = -1 - min(ITER_WINDOW, len(drag) - 1)
    return abs(drag[-1] - drag[back]) / abs(drag[-1])


def solve(case, u):
    """simpleFoam (continued while the drag's change criterion is not met); total CPU s."""
    cpu = 0.0
    end = ITERATIONS
    while True:
        log = f"log.simpleFoam.{end}"
        run(["nice", "-n", "15", "simpleFoam"], case, log)
        cpu += cpu_seconds(case, log)
        drag = drag_history(case, u)
        if converged_change(drag) < CONVERGED_CHANGE:
            return cpu
        if end >= ITERATIONS_MAX or os.path.basename(case).startswith("wedge"):
            print(f"{case}: not converged after {len(drag)} iterations", flush=True)
            return cpu
        end = min(end + ITERATIONS, ITERATIONS_MAX)
        # a continuation: iterate on from the last written fields, tighter residuals
        write_file(case, "system/controlDict", fill(CONTROL, dict(END=end, RHO=RHO_F)))
        write_file(case, "system/fvSolution", fill(SOLUTION, dict(RES=RESIDUAL * 0.01)))


def reynolds(u):
    return u * D / NU


def row_of(name, mesh, u, cpu):
    case = os.path.join(RUN, name)
    drag = drag_history(case, u)
    cells = mesh_info(mesh)[0]
    return dict(name=name, mesh=mesh, cells=cells, U=f"{u:.6g}", Re=f"{reynolds(u):.4f}",
                drag_N=f"{drag[-1]:.8e}", drag_over_weight=f"{drag[-1] / WEIGHT:.6f}",
                iterations=len(drag), converged_change=f"{converged_change(drag):.2e}",
                cpu_s=f"{cpu:.0f}")


def case_cpu(case):
    """The CPU time of all simpleFoam runs of a case, from their logs."""
    return sum(cpu_seconds(case, log) for log in os.listdir(case)
               if log.startswith("log.simpleFoam"))


def terminal_speed(rows, mesh):
    """U_t of a mesh: F = W on the line through its runs at SPEEDS."""
    pts = sorted((float(r["U"]), float(r["drag_N"])) for r in rows
                 if r["mesh"] == mesh and r["name"].endswith(tuple(f"U{u:.4f}" for u in SPEEDS)))
    if len(pts) < 2:
        return None
    (u1, f1), (u2, f2) = pts[0], pts[-1]
    return u1 + (WEIGHT - f1) * (u2 - u1) / (f2 - f1)


def richardson(h, phi):
    """Generalised Richardson extrapolation (Celik et al. 2008) from three solutions phi at
    spacings h (fine first): (order p, extrapolated value, the fine solution's relative error
    estimate); p from the fixed-point iteration for unequal ratios."""
    (h1, h2, h3), (f1, f2, f3) = h, phi
    r21, r32 = h2 / h1, h3 / h2
    e21, e32 = f2 - f1, f3 - f2
    if e21 == 0 or e32 == 0:
        return float("nan"), f1, 0.0
    s = math.copysign(1.0, e32 / e21)
    p = 2.0
    for _ in range(200):
        q = math.log((r21 ** p - s) / (r32 ** p - s))
        p_new = abs(math.log(abs(e32 / e21)) + q) / math.log(r21)
        if abs(p_new - p) < 1e-12:
            break
        p = p_new
    else:
        raise RuntimeError(f"richardson: the order did not converge in 200 iterations "
                           f"(last {p:.6g}, solutions {phi})")
    ext = (r21 ** p * f1 - f2) / (r21 ** p - 1.0)
    return p, ext, (f1 - ext) / ext


def unbounded_terminal_speed(cd):
    """The speed at which the drag C_D(Re) rho_f U^2/2 pi d^2/4 equals W."""
    return references.terminal_speed(cd, RHO_P, RHO_F, MU, D, G)[0]


def drag_coefficient(drag, u):
    return drag / (0.5 * RHO_F * u * u * math.pi * D * D / 4.0)


def summary(rows):
    """results/summary.md: the table, U_t per mesh, the order and the extrapolated U_t, the
    linearity, length and wide-duct checks, and the unbounded correlations."""
    by_name = {r["name"]: r for r in rows}
    metrics = {}
    out = ["# Sphere settling on the axis of an infinitely long square duct (ten Cate E1)", "",
           f"d = {D} m, rho_p = {RHO_P}, rho_f = {RHO_F} kg/m^3, mu = {MU} Pa s, "
           f"nu = {NU:.6e} m^2/s, g = {G}; duct {2 * HALF_WIDTH} m x {2 * HALF_WIDTH} m; "
           f"W = {WEIGHT:.6e} N. Steady simpleFoam (laminar, linearUpwind), quarter duct "
           "(two symmetryPlanes), snappyHexMesh on a searchableSphere, snapped, no layers. "
           "Generated by `ductReference.py`.", "",
           "| name | mesh | cells/D | cells | sphere area / pi d^2 | U (m/s) | Re | drag (N) | "
           "drag / W | C_D | iterations | change over last 50 | solver CPU (s) |",
           "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    mesh_cpu = {}
    for r in rows:
        cells, area, mcpu = mesh_info(r["mesh"])
        if r["mesh"] not in WEDGES:
            mesh_cpu[r["mesh"]] = mcpu
        out.append(f"| {r['name']} | {r['mesh']} | {cells_per_d(r['mesh']):.1f} | "
                   f"{r['cells']} | {'-' if math.isnan(area) else f'{area:.5f}'} | "
                   f"{r['U']} | {r['Re']} | {r['drag_N']} | "
                   f"{r['drag_over_weight']} | "
                   f"{drag_coefficient(float(r['drag_N']), float(r['U'])):.4f} | "
                   f"{r['iterations']} | {r['converged_change']} | {r['cpu_s']} |")
    out += ["", "## Terminal speed per mesh (F = W, linear between U = "
            + " and ".join(f"{u}" for u in SPEEDS) + " m/s)", "",
            "| mesh | background cells over half-width | cells/D | cells | U_t (m/s) | Re_t |",
            "|---|---|---|---|---|---|"]
    ut = {}
    for m in SERIES:
        u = terminal_speed(rows, m)
        if u is None:
            continue
        ut[m] = u
        out.append(f"| {m} | {MESHES[m]['n']} | {cells_per_d(m):.1f} | "
                   f"{mesh_info(m)[0]} | {u:.6f} | {reynolds(u):.4f} |")
    for triple in (SERIES[-3:], SERIES[:3]):
        if not all(m in ut for m in triple):
            continue
        fine_first = list(reversed(triple))
        h = [1.0 / MESHES[m]["n"] for m in fine_first]
        p, ext, err = richardson(h, [ut[m] for m in fine_first])
        bold = "**" if triple == SERIES[-3:] else ""
        out += ["", f"Richardson from {', '.join(triple)} (h = 1/background cells, ratios "
                f"{h[2] / h[1]:.4f} and {h[1] / h[0]:.4f}): observed order p = {p:.3f}, "
                f"{bold}extrapolated U_t = {ext:.6f} m/s{bold} (Re {reynolds(ext):.4f}); "
                f"{fine_first[0]}'s U_t is {100 * err:+.3f} % from it."]
        if bold:
            metrics.update(duct_terminal_speed_m_s=round(ext, 6),
                           duct_terminal_speed_order=round(p, 3),
                           duct_terminal_speed_finest_m_s=round(ut[fine_first[0]], 6))
            measured, immersed = e1_speeds()
            # the parameters that would bring the bound to each measured u_max: with
            # F = mu U d f(Re) and f ~ Re^k locally (k = d ln F/d ln U - 1 of the finest
            # mesh), F ~ mu^(1-k) U^(1+k), so U ~ (rho_p - rho_f)^(1/(1+k)) mu^(-(1-k)/(1+k))
            k = _dlnf_dlnu(rows, fine_first[0]) - 1.0
            for label, v in zip(("published", "unrounded_u_inf", "data_curve"), measured):
                metrics[f"measured_umax_{label}_vs_duct_bound_pct"] = round(
                    100 * (v / ext - 1), 3)
                metrics[f"duct_bound_vs_measured_umax_{label}_pct"] = round(
                    100 * (ext / v - 1), 3)
                metrics[f"viscosity_change_to_reach_{label}_pct"] = round(
                    100 * ((v / ext) ** (-(1 + k) / (1 - k)) - 1), 2)
                metrics[f"density_difference_change_to_reach_{label}_pct"] = round(
                    100 * ((v / ext) ** (1 + k) - 1), 2)
            out.append(f"With d ln F/d ln U = {1 + k:.4f} on {fine_first[0]}, the bound reaches "
                       "them with the viscosity changed by " + " / ".join(
                           f"{100 * ((v / ext) ** (-(1 + k) / (1 - k)) - 1):+.1f}"
                           for v in measured)
                       + " %, or the density difference rho_p - rho_f by " + " / ".join(
                           f"{100 * ((v / ext) ** (1 + k) - 1):+.1f}" for v in measured)
                       + f" % ({RHO_P - RHO_F:g} kg/m^3).")
            for c, v in immersed.items():
                metrics[f"immersed_box_umax_vs_duct_bound_pct_c{c}"] = round(
                    100 * (v / ext - 1), 3)
            out.append("Against it: ten Cate et al.'s measured u_max "
                       + " / ".join(f"{v:.6f}" for v in measured)
                       + " m/s (published, with the unrounded u_inf, the digitised curve's "
                       "largest) is "
                       + " / ".join(f"{100 * (v / ext - 1):+.1f}" for v in measured)
                       + " % from it; the immersed-boundary runs' u_max in the finite box "
                       + ", ".join(f"{v:.5f} m/s ({100 * (v / ext - 1):+.2f} %) at {c} cells/D"
                                   for c, v in sorted(immersed.items())) + ".")
        for u in SPEEDS:
            f = [float(by_name[f"{m}-U{u:.4f}"]["drag_N"]) for m in fine_first]
            pu, eu, erru = richardson(h, f)
            out.append(f"Drag at U = {u}: order {pu:.3f}, extrapolated {eu:.6e} N "
                       f"(drag/W {eu / WEIGHT:.6f}); {fine_first[0]} {100 * erru:+.3f} % from it.")
            if bold:
                metrics[f"duct_drag_over_weight_U{u:.4f}"] = round(eu / WEIGHT, 6)
        # the same with the formal order 2, from the two finest of the triple
        r21 = h[1] / h[0]
        f1, f2 = ut[fine_first[0]], ut[fine_first[1]]
        out.append(f"With the formal order 2 instead (from {fine_first[1]} and {fine_first[0]}): "
                   f"U_t = {(r21 ** 2 * f1 - f2) / (r21 ** 2 - 1):.6f} m/s.")
    if "m17-Ut" in by_name and "m17" in ut:
        r = by_name["m17-Ut"]
        excess = float(r["drag_over_weight"]) - 1.0
        slope = _dlnf_dlnu(rows, "m17")
        out += ["", f"Linearity: m17 at its interpolated U_t = {float(r['U']):.6f} m/s gives "
                f"drag/W = {r['drag_over_weight']} (1 if F(U) were linear); with "
                f"d ln F/d ln U = {slope:.4f} the interpolated U_t is off by "
                f"{-100 * excess / slope:+.4f} % "
                f"(F = W at {float(r['U']) * (1 - excess / slope):.6f} m/s)."]
    if "m17long-U0.0340" in by_name and "m17-U0.0340" in by_name:
        a, b = (float(by_name[n]["drag_N"]) for n in ("m17-U0.0340", "m17long-U0.0340"))
        out += ["", f"Length: the duct 1.5 times as long (upstream 15 d, downstream 22.5 d) "
                f"changes the drag at U = 0.034 on m17 by {100 * (b - a) / a:+.4f} %."]
    out += ["", "## Unbounded fluid (correlations)", ""]
    for label, cd in (("Schiller-Naumann", schiller_naumann), ("Clift et al. (Re <= 20)", clift)):
        u = unbounded_terminal_speed(cd)
        out.append(f"- {label}: U_t = {u:.6f} m/s (Re {reynolds(u):.4f})")
    for m in WIDE:
        r = by_name.get(f"{m}-U0.0340")
        if r is None:
            continue
        spec = MESHES[m]
        u, f = float(r["U"]), float(r["drag_N"])
        cd = drag_coefficient(f, u)
        re_ = reynolds(u)
        out += ["", f"Set-up check {m}: the duct {2 * spec['half_width'] / D:.0f} d x "
                f"{2 * spec['half_width'] / D:.0f} d (walls moving at U), inlet "
                f"{spec['upstream']:g} d upstream, outlet {spec['downstream']:g} d downstream, "
                f"{cells_per_d(m):.0f} cells/D, U = {u} (Re {re_:.4f}): C_D = {cd:.4f}; "
                f"Schiller-Naumann {schiller_naumann(re_):.4f} "
                f"({100 * (cd / schiller_naumann(re_) - 1):+.2f} %), "
                f"Clift {clift(re_):.4f} ({100 * (cd / clift(re_) - 1):+.2f} %)."]
    for m in WEDGES:
        r = by_name.get(f"{m}-U0.0340")
        if r is None:
            continue
        u, f = float(r["U"]), float(r["drag_N"])
        cd = drag_coefficient(f, u)
        re_ = reynolds(u)
        line = (f"Unbounded axisymmetric body-fitted sphere ({m}, outer boundary 100 d), "
                f"Re {re_:.4f}: C_D = {cd:.4f}; Schiller-Naumann "
                f"{100 * (cd / schiller_naumann(re_) - 1):+.2f} %, Clift "
                f"{100 * (cd / clift(re_) - 1):+.2f} %")
        line += "; the wide ducts' drags are " + ", ".join(
            f"{w} {100 * (float(by_name[w + '-U0.0340']['drag_N']) / f - 1):+.2f} %"
            for w in WIDE if w + "-U0.0340" in by_name) + " from it"
        out += ["", line + "."]
    out += ["", "Mesh CPU (blockMesh + snappyHexMesh + checkMesh, s): "
            + ", ".join(f"{m} {c:.0f}" for m, c in mesh_cpu.items())
            + f"; solver CPU total {sum(float(r['cpu_s']) for r in rows):.0f} s."]
    out += immersed_comparison(metrics)
    os.makedirs(RESULTS, exist_ok=True)
    with open(SUMMARY, "w") as f:
        f.write("\n".join(out) + "\n")
    with open(METRICS, "w") as f:
        json.dump(metrics, f, indent=1, sort_keys=True)
        f.write("\n")
    return out


def immersed_comparison(metrics):
    """The module's immersed sphere in the same duct (ductImmersed.py, results/immersed.csv)
    against the extrapolated body-fitted drags and terminal speed in metrics (added to it);
    the summary's lines."""
    rows = read_csv(IMMERSED)
    if not rows or "duct_terminal_speed_m_s" not in metrics:
        return []
    out = ["", "## The immersed body in the same duct (`ductImmersed.py`)", "",
           "| cells/D | U (m/s) | drag / W | against the body-fitted extrapolation |",
           "|---|---|---|---|"]
    for r in sorted(rows, key=lambda r: (int(r["cpd"]), float(r["U"]))):
        ref = metrics.get(f"duct_drag_over_weight_U{float(r['U']):.4f}")
        if ref is None:
            continue
        err = 100 * (float(r["drag_over_weight"]) / ref - 1)
        metrics[f"immersed_duct_drag_error_pct_c{r['cpd']}_U{float(r['U']):.4f}"] = round(err, 3)
        out.append(f"| {r['cpd']} | {r['U']} | {r['drag_over_weight']} | {err:+.2f} % |")
    ext = metrics["duct_terminal_speed_m_s"]
    for cpd in sorted({int(r["cpd"]) for r in rows}):
        pts = sorted((float(r["U"]), float(r["drag_over_weight"]))
                     for r in rows if int(r["cpd"]) == cpd)
        if len(pts) < 2:
            continue
        (u0, f0), (u1, f1) = pts[0], pts[-1]
        u_t = u0 + (1.0 - f0) * (u1 - u0) / (f1 - f0)
        metrics[f"immersed_duct_terminal_speed_m_s_c{cpd}"] = round(u_t, 6)
        metrics[f"immersed_duct_terminal_speed_vs_body_fitted_pct_c{cpd}"] = round(
            100 * (u_t / ext - 1), 3)
        line = (f"\nImmersed, {cpd} cells/D: U_t = {u_t:.6f} m/s, "
                f"{100 * (u_t / ext - 1):+.2f} % from the body-fitted {ext:.6f} m/s.")
        box = metrics.get(f"immersed_box_umax_vs_duct_bound_pct_c{cpd}")
        if box is not None:
            # the box run's u_max against the bound with the forcing's share taken out
            net = 100 * ((1 + box / 100) / (u_t / ext) - 1)
            metrics[f"immersed_box_umax_without_forcing_share_vs_bound_pct_c{cpd}"] = round(
                net, 3)
            line += (f" The box run's u_max ({box:+.2f} % from the bound) with that share taken "
                     f"out: {net:+.2f} %.")
        out.append(line)
    return out


def _dlnf_dlnu(rows, mesh):
    """d ln F / d ln U of a mesh between its two speeds."""
    pts = sorted((float(r["U"]), float(r["drag_N"])) for r in rows
                 if r["mesh"] == mesh and r["name"].endswith(tuple(f"U{u:.4f}" for u in SPEEDS)))
    (u1, f1), (u2, f2) = pts[0], pts[-1]
    return math.log(f2 / f1) / math.log(u2 / u1)


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        epilog="Modes: run (mesh, solve and collect; a case already in results/duct.csv is "
               "skipped unless --force), collect (rebuild results/ from run/), list.",
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("mode", choices=["run", "collect", "list"])
    parser.add_argument("--force", action="store_true", help="rerun cases already done")
    parser.add_argument("--only", action="append", metavar="NAME",
                        help="run only this case (repeatable)")
    args = parser.parse_args()
    if args.mode == "list":
        for name, mesh, u in campaign():
            print(f"{name}: mesh {mesh} ({cells_per_d(mesh):.1f} cells/D), "
                  f"U {u if u else 'U_t of m17'}")
        return
    rows = read_csv(CSV)
    if args.mode == "collect":
        for r in rows:
            r.update(row_of(r["name"], r["mesh"], float(r["U"]),
                            case_cpu(os.path.join(RUN, r["name"]))))
    else:
        for name, mesh, u in campaign():
            if args.only and name not in args.only:
                continue
            if any(r["name"] == name for r in rows) and not args.force:
                continue
            if u is None:
                u = terminal_speed(rows, mesh)
                if u is None:
                    print(f"{name}: needs the runs of {mesh} at both speeds first", flush=True)
                    continue
                u = float(f"{u:.6f}")
            case = os.path.join(RUN, name)
            write_case(case, mesh, u)
            print(f"{name}: {mesh_info(mesh)[0]} cells, U = {u}", flush=True)
            cpu = solve(case, u)
            rows = [r for r in rows if r["name"] != name] + [row_of(name, mesh, u, cpu)]
            write_csv(CSV, rows, FIELDS)
    order = {n: i for i, (n, _, _) in enumerate(campaign())}
    rows.sort(key=lambda r: order.get(r["name"], len(order)))
    write_csv(CSV, rows, FIELDS)
    print("\n".join(summary(rows)))


if __name__ == "__main__":
    main()
