#!/usr/bin/python3
"""Write the OpenFOAM dictionaries of one Jeffery-orbit case (used by
jefferyOrbit.py and tests/foam/jefferyOrbitQuick).

A prolate spheroid (semi-axes a > b = c, r = a/b), centre fixed at the origin,
rotation free (motion freeRotation), in the simple shear u = gamma y e_x
between two walls y = -H/2, H/2 moving at -gamma H/2 and +gamma H/2; x (flow)
and z (vorticity) are periodic. The symmetry axis starts along the gradient
axis y (phi = 0, in the flow-gradient plane). Units: b = 0.5, gamma = 1,
rho_f = 1; nu = gamma a^2/Re.
"""
import math
import os
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
from validationTools import refined_box_mesh, write_dict  # noqa: E402

TITLE = "spheroidFoam validation: Jeffery orbit of a spheroid in shear (validation/jefferyOrbit)"


def write(path, cls, loc, obj, body):
    """Write one OpenFOAM file of a Jeffery-orbit case (the banner names this validation)."""
    write_dict(path, cls, loc, obj, body, TITLE)


def write_case(case, r=2.5, re=0.1, cpd=8, dt=0.02, end_time=20.0, box=(10.0, 10.0, 6.0),
               density_ratio=1.0, penalty_ratio=1e-3, sub_steps=1, ddt="Euler",
               margin=0.15, growth=1.15, max_ratio=6.0, phi0=0.0, n_correctors=2,
               n_outer=1, write_interval=None, gamma=1.0, virtual_mass=0.5,
               prescribed_omega=None):
    """Write case/. cpd: cells per minor diameter 2b in the fine region;
    box = (Lx, H, Lz); phi0: initial angle of the axis from y towards x [rad]."""
    b = 0.5
    a = r * b
    h = 2 * b / cpd
    nu = gamma * a * a / re
    lx, hy, lz = box
    fxy = math.ceil((a + margin) / h) * h
    fz = math.ceil((b + margin) / h) * h
    if fxy >= 0.5 * min(lx, hy) or fz >= 0.5 * lz:
        sys.exit("caseWriter: the fine region does not fit in the box")
    refined_box_mesh(case, [
        "--box", *(f"{v:.12g}" for v in (-lx / 2, lx / 2, -hy / 2, hy / 2, -lz / 2, lz / 2)),
        "--fine", *(f"{v:.12g}" for v in (-fxy, fxy, -fxy, fxy, -fz, fz)),
        "--h", f"{h:.12g}", "--growth", str(growth), "--max-ratio", str(max_ratio),
        "--periodic", "x", "--periodic", "z", "--patch", "yMin:wall", "--patch", "yMax:wall"])
    if write_interval is None:
        write_interval = end_time
    write(os.path.join(case, "system", "controlDict"), "dictionary", "system", "controlDict", f"""\
application     immersedSpheroidFoam;

startFrom       latestTime;
startTime       0;
stopAt          endTime;
endTime         {end_time:.12g};
deltaT          {dt:.12g};
adjustTimeStep  no;

writeControl    runTime;
writeInterval   {write_interval:.12g};
purgeWrite      0;
writeFormat     binary;
writePrecision  12;
writeCompression off;
timeFormat      general;
timePrecision   10;
runTimeModifiable false;
""")
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
    write(os.path.join(case, "system", "fvSolution"), "dictionary", "system", "fvSolution", f"""\
solvers
{{
    p
    {{
        solver          GAMG;
        smoother        DIC;
        tolerance       1e-9;
        relTol          0.01;
    }}

    pFinal
    {{
        $p;
        relTol          0;
    }}

    "(U|UFinal)"
    {{
        solver          PBiCGStab;
        preconditioner  DILU;
        tolerance       1e-12;
        relTol          0;
    }}
}}

PIMPLE
{{
    momentumPredictor yes;
    nOuterCorrectors {n_outer};
    nCorrectors     {n_correctors};
    nNonOrthogonalCorrectors 0;
    pRefCell        0;
    pRefValue       0;
}}
""")
    write(os.path.join(case, "constant", "transportProperties"), "dictionary", "constant",
          "transportProperties", f"""\
transportModel  Newtonian;

nu              {nu:.12g};      // gamma a^2/Re
""")
    write(os.path.join(case, "constant", "turbulenceProperties"), "dictionary", "constant",
          "turbulenceProperties", "simulationType  laminar;\n")
    axis = (math.sin(phi0), math.cos(phi0), 0.0)
    if prescribed_omega is None:
        motion = "{ type freeRotation; }"
    else:
        # a diagnosis: the rotation imposed (the torque is measured, not used)
        motion = f"{{ type prescribed; angularVelocity constant (0 0 {prescribed_omega:.12g}); }}"
    write(os.path.join(case, "constant", "immersedBodiesProperties"), "dictionary", "constant",
          "immersedBodiesProperties", f"""\
fluidDensity    1;

penaltyRatio    {penalty_ratio:.12g};
subSteps        {sub_steps};
virtualMass     {virtual_mass:.12g};        // C_v of the virtual-mass stabilisation

bodies
{{
    spheroid
    {{
        semiAxes        ({a:.12g} {b:.12g} {b:.12g});
        density         {density_ratio:.12g};
        centre          (0 0 0);
        axis            ({axis[0]:.12g} {axis[1]:.12g} {axis[2]:.12g});
        motion          {motion}
    }}
}}

output
{{
    timeSeries      yes;
    surfaces        no;
}}
""")
    uw = 0.5 * gamma * hy
    write(os.path.join(case, "0", "U"), "volVectorField", "0", "U", f"""\
dimensions      [0 1 -1 0 0 0 0];

// the simple shear u = gamma y e_x (set in the cells by the runner)
internalField   uniform (0 0 0);

boundaryField
{{
    xMin {{ type cyclic; }}
    xMax {{ type cyclic; }}
    zMin {{ type cyclic; }}
    zMax {{ type cyclic; }}
    yMin {{ type fixedValue; value uniform ({-uw:.12g} 0 0); }}
    yMax {{ type fixedValue; value uniform ({uw:.12g} 0 0); }}
}}
""")
    write(os.path.join(case, "0", "p"), "volScalarField", "0", "p", """\
dimensions      [0 2 -2 0 0 0 0];

internalField   uniform 0;

boundaryField
{
    xMin { type cyclic; }
    xMax { type cyclic; }
    zMin { type cyclic; }
    zMax { type cyclic; }
    yMin { type zeroGradient; }
    yMax { type zeroGradient; }
}
""")
    return dict(a=a, b=b, h=h, nu=nu, lam=nu * dt / (h * h), gamma=gamma)
