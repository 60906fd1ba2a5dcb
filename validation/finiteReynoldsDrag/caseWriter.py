#!/usr/bin/python3
"""Write one fixed-body finite-Reynolds-number case of validation/finiteReynoldsDrag
(a sphere or a spheroid held in a uniform stream).

Units: D_eq = 1 m (diameter of the equal-volume sphere), U = 1 m/s, rho_f = 1
kg/m^3, nu = 1/Re m^2/s. The stream enters at xMin, leaves at xMax; the four
sides are symmetry planes 12 D_eq from the body (blockage (pi/4)/24^2 = 0.14 %).

Mesh: a graded blockMesh whose uniform core has cells of 8 h (h = 1/cpd), then
three nested boxes each refined once (2 x 2 x 2, refineMesh), so the body and
its near wake sit in uniform cells of size h, at least four cells inside the
finest box on every side of the body.
"""
import math
import os
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
from validationTools import refined_box_mesh, write_dict  # noqa: E402

TITLE = "spheroidFoam validation: finite-Re drag of a fixed body (validation/finiteReynoldsDrag)"
DOMAIN = (-12.0, 24.0, -12.0, 12.0, -12.0, 12.0)
# refinement boxes, coarsest first (x0 x1 y0 y1 z0 z1, D_eq units), each snapped
# outwards to the grid of the level it refines
BOXES = ((-3.5, 8.0, -3.0, 3.0, -3.0, 3.0),
         (-2.0, 4.0, -2.0, 2.0, -1.75, 1.75),
         (-1.25, 2.0, -1.25, 1.25, -1.0, 1.0))


def semi_axes(ar, d_eq=1.0):
    """(polar, equatorial, equatorial) semi-axes of the spheroid of aspect ratio
    ar = polar/equatorial with the volume of the sphere of diameter d_eq."""
    r = 0.5 * d_eq
    return (r * ar ** (2.0 / 3.0), r * ar ** (-1.0 / 3.0), r * ar ** (-1.0 / 3.0))


def write(path, cls, loc, obj, body):
    write_dict(path, cls, loc, obj, body, TITLE)


def snapped(box, spacing):
    """box grown outwards to multiples of spacing."""
    return tuple(math.floor(v / spacing + 1e-9) * spacing if i % 2 == 0
                 else math.ceil(v / spacing - 1e-9) * spacing for i, v in enumerate(box))


def levels(cpd, boxes=BOXES):
    """The base cell size and the snapped refinement boxes for cpd cells per D_eq."""
    h0 = 8.0 / cpd
    return h0, [snapped(b, h0 / 2 ** k) for k, b in enumerate(boxes)]


def check_fits(axes, axis, cpd, boxes=BOXES):
    """Exit with a message unless the body plus four fine cells lies in the finest box."""
    h0, boxes = levels(cpd, boxes)
    h = 1.0 / cpd
    e = [axis[0], axis[1], axis[2]]
    n = math.sqrt(sum(c * c for c in e))
    e = [c / n for c in e]
    # half-extent of a spheroid along world direction i: sqrt(a^2 e_i^2 + b^2 (1 - e_i^2))
    ext = [math.sqrt(axes[0] ** 2 * c * c + axes[1] ** 2 * (1 - c * c)) for c in e]
    fine = boxes[-1]
    for i in range(3):
        if fine[2 * i] > -ext[i] - 4 * h or fine[2 * i + 1] < ext[i] + 4 * h:
            sys.exit(f"caseWriter: the body (half-extent {ext[i]:.3g} along axis {i}) with four "
                     f"cells of margin does not fit in the finest box {fine}")


def scaled_domain(scale):
    """DOMAIN with every side moved scale times as far from the body."""
    return tuple(scale * v for v in DOMAIN)


def build_mesh(case, cpd, domain=DOMAIN, side_walls=False, boxes=BOXES):
    """blockMesh over domain, then topoSet + refineMesh once per box (boxes, coarsest
    first, inside domain); logs in case/. The four sides are symmetry planes, or walls if
    side_walls."""
    h0, boxes = levels(cpd, boxes)
    side = "wall" if side_walls else "symmetryPlane"
    refined_box_mesh(case, [
        "--box", *map(str, domain), "--fine", *(f"{v:.12g}" for v in boxes[0]),
        "--h", f"{h0:.12g}", "--growth", "1.25", "--max-ratio", "8",
        "--patch", f"yMin:{side}", "--patch", f"yMax:{side}",
        "--patch", f"zMin:{side}", "--patch", f"zMax:{side}"])

    def run(app, log, *args):
        with open(os.path.join(case, log), "w") as out:
            rc = subprocess.run([app, *args], cwd=case, stdout=out, stderr=subprocess.STDOUT)
        if rc.returncode != 0:
            raise RuntimeError(f"{app} failed in {case} (see {log})")

    run("blockMesh", "log.blockMesh")
    write(os.path.join(case, "system", "refineMeshDict"), "dictionary", "system",
          "refineMeshDict", """\
set             refine;
coordinateSystem global;
globalCoeffs
{
    tan1            (1 0 0);
    tan2            (0 1 0);
}
directions      (tan1 tan2 normal);
useHexTopology  yes;
geometricCut    no;
writeMesh       no;
""")
    for k, b in enumerate(boxes):
        write(os.path.join(case, "system", "topoSetDict"), "dictionary", "system",
              "topoSetDict", f"""\
actions
(
    {{
        name    refine;
        type    cellSet;
        action  new;
        source  boxToCell;
        box     ({b[0]:.12g} {b[2]:.12g} {b[4]:.12g}) ({b[1]:.12g} {b[3]:.12g} {b[5]:.12g});
    }}
);
""")
        run("topoSet", f"log.topoSet.{k + 1}")
        run("refineMesh", f"log.refineMesh.{k + 1}", "-dict", "system/refineMeshDict",
            "-overwrite")


def mesh_cells(case):
    """The cell count in the header note of constant/polyMesh/owner."""
    with open(os.path.join(case, "constant", "polyMesh", "owner"), "rb") as f:
        head = f.read(2000).decode("latin-1")
    for word in head.split():
        if word.startswith("nCells:"):
            return int(word.split(":")[1])
    raise RuntimeError(f"{case}/constant/polyMesh/owner: no nCells in its note")


def write_case(case, ar, incidence_deg, re, cpd, end_time, courant=1.0, domain=DOMAIN,
               side_walls=False, boxes=BOXES, max_viscous_number=None):
    """Write and mesh case/ for a body of aspect ratio ar whose symmetry axis makes
    incidence_deg with the stream (x), at Re = U D_eq/nu, cpd cells per D_eq,
    Euler steps dt = courant h / U up to end_time (D_eq/U units), in domain
    (x0 x1 y0 y1 z0 z1, D_eq units) with the refinement boxes boxes.
    side_walls: the four sides are no-slip walls moving with the stream (the frame of a
    body settling steadily along a duct) instead of symmetry planes.
    Returns the time step, the step count and the cell count."""
    h = 1.0 / cpd
    axes = semi_axes(ar)
    phi = math.radians(incidence_deg)
    axis = (math.cos(phi), math.sin(phi), 0.0)
    check_fits(axes, axis, cpd, boxes)
    dt = courant * h
    steps = int(round(end_time / dt))
    write(os.path.join(case, "system", "controlDict"), "dictionary", "system", "controlDict", f"""\
application     pimpleFoam;

libs            ("libimmersedSpheroidsFvOptions.so");

startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         {steps * dt:.12g};
deltaT          {dt:.12g};

writeControl    timeStep;
writeInterval   {steps};
purgeWrite      1;
writeFormat     binary;
writePrecision  12;
writeCompression off;
timeFormat      general;
timePrecision   12;
runTimeModifiable no;
""")
    write(os.path.join(case, "system", "fvOptions"), "dictionary", "system", "fvOptions", """\
// the immersed body (volume penalisation, constant/immersedBodiesProperties)
bodies
{
    type            immersedBodies;
    libs            ("libimmersedSpheroidsFvOptions.so");
}
""")
    write(os.path.join(case, "system", "fvSchemes"), "dictionary", "system", "fvSchemes", """\
ddtSchemes
{
    default         Euler;
}

gradSchemes
{
    default         Gauss linear;
}

divSchemes
{
    default         none;
    // second order, upwind-biased: the coarse far-field cells have cell Reynolds
    // numbers up to 400 at Re 100
    div(phi,U)      Gauss linearUpwind grad(U);
    div((nuEff*dev2(T(grad(U))))) Gauss linear;
}

laplacianSchemes
{
    default         Gauss linear corrected;
}

interpolationSchemes
{
    default         linear;
}

snGradSchemes
{
    default         corrected;
}
""")
    write(os.path.join(case, "system", "fvSolution"), "dictionary", "system", "fvSolution", """\
solvers
{
    p
    {
        solver          GAMG;
        smoother        DIC;
        tolerance       1e-8;
        relTol          0.01;
    }

    pFinal
    {
        $p;
        relTol          0;
    }

    "(U|UFinal)"
    {
        solver          PBiCGStab;
        preconditioner  DILU;
        tolerance       1e-10;
        relTol          0;
    }
}

PIMPLE
{
    momentumPredictor yes;
    nOuterCorrectors 1;
    nCorrectors     2;
    // the faces between refinement levels are slightly non-orthogonal
    nNonOrthogonalCorrectors 1;
}
""")
    write(os.path.join(case, "constant", "transportProperties"), "dictionary", "constant",
          "transportProperties", f"""\
transportModel  Newtonian;

nu              {1.0 / re:.12g};
""")
    write(os.path.join(case, "constant", "turbulenceProperties"), "dictionary", "constant",
          "turbulenceProperties", "simulationType  laminar;\n")
    write(os.path.join(case, "constant", "immersedBodiesProperties"), "dictionary", "constant",
          "immersedBodiesProperties", f"""\
fluidDensity    1;
{"" if max_viscous_number is None else f"maxViscousNumber {max_viscous_number:g};"}

bodies
{{
    spheroid
    {{
        semiAxes        ({axes[0]:.12g} {axes[1]:.12g} {axes[2]:.12g});
        density         1;
        centre          (0 0 0);
        axis            ({axis[0]:.12g} {axis[1]:.12g} {axis[2]:.12g});
        motion          {{ type fixed; }}
    }}
}}

output
{{
    timeSeries      yes;
    surfaces        no;
}}
""")
    side_u, side_p = (("fixedValue;\n        value           uniform (1 0 0)", "zeroGradient")
                      if side_walls else ("symmetryPlane", "symmetryPlane"))
    sides_u, sides_p = (f"""
    "(yMin|yMax|zMin|zMax)"
    {{
        type            {side};
    }}""" for side in (side_u, side_p))
    write(os.path.join(case, "0", "U"), "volVectorField", "0", "U", f"""\
dimensions      [0 1 -1 0 0 0 0];

internalField   uniform (1 0 0);

boundaryField
{{
    xMin
    {{
        type            fixedValue;
        value           uniform (1 0 0);
    }}
    xMax
    {{
        type            inletOutlet;
        inletValue      uniform (0 0 0);
        value           uniform (1 0 0);
    }}{sides_u}
}}
""")
    write(os.path.join(case, "0", "p"), "volScalarField", "0", "p", f"""\
dimensions      [0 2 -2 0 0 0 0];

internalField   uniform 0;

boundaryField
{{
    xMin
    {{
        type            zeroGradient;
    }}
    xMax
    {{
        type            fixedValue;
        value           uniform 0;
    }}{sides_p}
}}
""")
    build_mesh(case, cpd, domain, side_walls, boxes)
    return dt, steps, mesh_cells(case)
