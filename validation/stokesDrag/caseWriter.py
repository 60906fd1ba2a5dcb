#!/usr/bin/python3
"""Write the OpenFOAM dictionaries of one fixed-spheroid Stokes-drag case
(used by stokesDrag.py and tests/foam/stokesDragQuick).

Units: D_eq = 1 m (diameter of the equal-volume sphere), nu = 1 m^2/s,
rho_f = 1 kg/m^3, so mu = 1 Pa s; the superficial velocity U is held by
OpenFOAM's meanVelocityForce (Re = U D_eq / nu).
"""
import math
import os
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
from validationTools import refined_box_mesh, write_dict  # noqa: E402

TITLE = "spheroidFoam validation: Stokes drag of a fixed spheroid (validation/stokesDrag)"


def semi_axes(ar, d_eq=1.0):
    """(polar, equatorial, equatorial) semi-axes of the spheroid of aspect ratio
    ar = polar/equatorial with the volume of the sphere of diameter d_eq."""
    r = 0.5 * d_eq
    return (r * ar ** (2.0 / 3.0), r * ar ** (-1.0 / 3.0), r * ar ** (-1.0 / 3.0))


def write(path, cls, loc, obj, body):
    """Write one OpenFOAM file of a Stokes-drag case (the banner names this validation)."""
    write_dict(path, cls, loc, obj, body, TITLE)


def fine_half_widths(axes, h, margin):
    """Half-widths of the uniform fine region: the body's bounding box plus
    margin, rounded up to whole cells (an even number of cells per direction,
    so the body centre is a mesh point, the same for every box size)."""
    return [math.ceil((s + margin) / h) * h for s in axes]


def write_case(case, ar, flow, box, cpd, dt, end_time, u=0.02, nu=1.0,
               penalty_ratio=None, forcing=None, margin=0.25, growth=1.1, max_ratio=4.0,
               ddt="Euler", write_interval=None, ubar=None, body_velocity=None,
               centre=(0.0, 0.0, 0.0), max_viscous_number=None):
    """Write case/ (system, constant, 0) for a body of aspect ratio ar with its
    symmetry (body x) axis along world x, in a triply periodic box of side
    box (D_eq units; or its sides along x, y and z), flow direction flow =
    'x' (axial) or 'y' (transverse), cpd cells per D_eq in the fine region,
    Euler steps dt up to end_time.
    ubar: the superficial velocity held (default u along the flow directions);
    body_velocity: a prescribed constant velocity of the body (default fixed),
    which starts at centre; max_viscous_number: the module's limit of nu dt/h^2 in the body's
    cells (maxViscousNumber; default: the one measured for the case's PIMPLE settings)."""
    h = 1.0 / cpd
    axes = semi_axes(ar)
    fine = fine_half_widths(axes, h, margin)
    sides = (box, box, box) if isinstance(box, (int, float)) else tuple(box)
    halves = [0.5 * side for side in sides]
    if any(f >= half for f, half in zip(fine, halves)):
        sys.exit(f"caseWriter: the fine region {fine} does not fit in the box {box}")
    refined_box_mesh(case, [
        "--box", *map(str, (x for half in halves for x in (-half, half))),
        "--fine", *(f"{s:.12g}" for f in fine for s in (-f, f)),
        "--h", f"{h:.12g}", "--growth", str(growth), "--max-ratio", str(max_ratio),
        "--periodic", "x", "--periodic", "y", "--periodic", "z"])

    # flow: 'x' (along the symmetry axis), 'y' (across it) or 'xy' (both at
    # once: Stokes flow is linear, the drag along x and along y are those of the
    # two flows; each mean component is held by its own meanVelocityForce)
    if ubar is None:
        ubar = (u if "x" in flow else 0.0, u if "y" in flow else 0.0, 0.0)
    if write_interval is None:
        write_interval = 10 ** 8       # the runner stops the run with stopAt writeNow
    write(os.path.join(case, "system", "controlDict"), "dictionary", "system", "controlDict", f"""\
application     pimpleFoam;

libs            ("libimmersedSpheroidsFvOptions.so");

startFrom       latestTime;
startTime       0;
stopAt          endTime;
endTime         {end_time:.12g};
deltaT          {dt:.12g};

writeControl    timeStep;
writeInterval   {write_interval};
purgeWrite      2;
writeFormat     binary;
writePrecision  12;
writeCompression off;
timeFormat      general;
timePrecision   17;

// the runner changes deltaT and stopAt while the solver runs
runTimeModifiable yes;
OptimisationSwitches
{{
    fileModificationChecking timeStamp;
    fileModificationSkew 0;
}}
""")
    write(os.path.join(case, "system", "fvOptions"), "dictionary", "system", "fvOptions", """\
// the immersed body (volume penalisation, constant/immersedBodiesProperties)
bodies
{
    type            immersedBodies;
    libs            ("libimmersedSpheroidsFvOptions.so");
}

""" + "".join(f"""
// holds the {d} component of the superficial velocity (the mean of U over the
// whole box, body included) at {v:.12g} with a uniform pressure gradient along
// {d}, printed in the log
meanFlow{d.upper()}
{{
    type            meanVelocityForce;
    selectionMode   all;
    fields          (U);
    Ubar            ({v if d == "x" else 0:.12g} {v if d == "y" else 0:.12g} 0);
}}
""" for d, v in (("x", ubar[0]), ("y", ubar[1])) if v != 0))
    write(os.path.join(case, "system", "fvSchemes"), "dictionary", "system", "fvSchemes", f"""\
ddtSchemes
{{
    default         {ddt};
}}

gradSchemes
{{
    default         Gauss linear;
}}

divSchemes
{{
    default         none;
    div(phi,U)      Gauss linear;
    div((nuEff*dev2(T(grad(U))))) Gauss linear;
}}

laplacianSchemes
{{
    default         Gauss linear corrected;
}}

interpolationSchemes
{{
    default         linear;
}}

snGradSchemes
{{
    default         corrected;
}}
""")
    write(os.path.join(case, "system", "fvSolution"), "dictionary", "system", "fvSolution", """\
solvers
{
    p
    {
        solver          GAMG;
        smoother        DIC;
        tolerance       1e-9;
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
        tolerance       1e-12;
        relTol          0;
    }
}

PIMPLE
{
    momentumPredictor yes;
    nOuterCorrectors 1;
    nCorrectors     2;
    nNonOrthogonalCorrectors 0;
    pRefCell        0;
    pRefValue       0;
}
""")
    write(os.path.join(case, "constant", "transportProperties"), "dictionary", "constant",
          "transportProperties", f"""\
transportModel  Newtonian;

nu              {nu:.12g};
""")
    write(os.path.join(case, "constant", "turbulenceProperties"), "dictionary", "constant",
          "turbulenceProperties", "simulationType  laminar;\n")
    motion = ("{ type fixed; }" if body_velocity is None else
              "{ type prescribed; velocity (" + " ".join(f"{v:.12g}" for v in body_velocity)
              + "); angularVelocity (0 0 0); }")
    # the module's defaults unless a run asks for another forcing or penalty
    settings = "".join(f"{k:<15} {v};\n" for k, v in (("forcing", forcing),
                                                      ("penaltyRatio", penalty_ratio),
                                                      ("maxViscousNumber", max_viscous_number))
                       if v is not None)
    write(os.path.join(case, "constant", "immersedBodiesProperties"), "dictionary", "constant",
          "immersedBodiesProperties", f"""\
fluidDensity    1;

{settings}
bodies
{{
    spheroid
    {{
        semiAxes        ({axes[0]:.12g} {axes[1]:.12g} {axes[2]:.12g});
        density         1;
        centre          ({centre[0]:.12g} {centre[1]:.12g} {centre[2]:.12g});
        axis            (1 0 0);
        motion          {motion}
    }}
}}

output
{{
    timeSeries      yes;
    surfaces        no;
}}
""")
    for name, cls, dims, value in (("U", "volVectorField", "[0 1 -1 0 0 0 0]",
                                    f"uniform ({ubar[0]:.12g} {ubar[1]:.12g} {ubar[2]:.12g})"),
                                   ("p", "volScalarField", "[0 2 -2 0 0 0 0]", "uniform 0")):
        write(os.path.join(case, "0", name), cls, "0", name, f"""\
dimensions      {dims};

internalField   {value};

boundaryField
{{
    ".*"
    {{
        type            cyclic;
    }}
}}
""")
    return {"h": h, "semiAxes": axes, "fine": fine}
