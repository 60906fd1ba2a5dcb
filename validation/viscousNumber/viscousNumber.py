#!/usr/bin/python3
"""Stability of the pressure-velocity coupling against the viscous number
lambda = nu dt/h^2 (validation/viscousNumber, see README.md).

    viscousNumber.py run [--force] [--only CASE ...]
    viscousNumber.py confirm [--only CASE ...]
    viscousNumber.py plot
    viscousNumber.py quick DIR LIMIT

OpenFOAM's PISO/PIMPLE coupling with Euler steps is not unconditionally
stable: above a viscous number that depends on its settings (momentum
predictor, pressure correctors, outer correctors) a period-two oscillation
in time grows. This campaign measures that limit for each setting, with and
without an immersed body:
  sphere6, sphere8, sphere12, sphere16: a fixed sphere (D = 1, nu = 1) at 6,
     8, 12 and 16 cells/D in a triply periodic box of 4 D, the Stokes flow of
     validation/stokesDrag (meanVelocityForce holds the mean velocity at 0.02
     along x);
  prolate8, oblate8: the same for spheroids of aspect ratio 2 and 0.5 (flow
     along the symmetry axis), 8 cells per equal-volume diameter D_eq;
  sphere8_box6, sphere8_box8, sphere8_box12, sphere8_box16: sphere8 in
     periodic boxes of 6, 8, 12 and 16 D (BOX); sphere12_box8, sphere16_box8:
     sphere12 and sphere16 in the box of 8 D;
  sphere8_box4x4x8, sphere8_box8x4x4: sphere8 in periodic boxes 8 D long
     across the flow (z) and along it (x), 4 D in the other directions;
  moving8_box4, moving8_box8: the sphere of sphere8 moved at 0.02 through fluid
     at rest in periodic boxes of 4 and 8 D, no mean flow held (MOVING);
  settling_periodic4, settling_periodic8: a free sphere (density ratio 2) at
     6 cells/D settling from rest in triply periodic boxes of 4 and 8 D
     (validation/hinderedSettling's single-sphere case, PERIODIC_SETTLING);
  sphere8_open, sphere8_open_small: sphere8 in the inlet-outlet domain of
     validation/finiteReynoldsDrag at Re 0.02 (nu = 50), sides 12 and 4 D
     from the sphere (OPEN_DOMAIN);
  settling24, settling36: a free spheroid settling from rest (the case of
     tests/foam/settlingSphereCase: semi-axes 9, 6, 6 mm, density ratio 1.17,
     Euler steps of 4 ms) on its mesh of 24 x 24 x 32 cells (5.5 cells per
     D_eq) and refined to 36 x 36 x 48 (8.2); lambda is set through nu; each
     test runs SETTLING_STEPS steps from rest (no base), its signal the body's
     vertical velocity;
  settling24_ratio0p1, _ratio0p3, _ratio0p5, _ratio2, _ratio8: settling24 at
     density ratios 0.1, 0.3, 0.5, 2 and 8 (SETTLING_DENSITY_RATIO), gravity
     scaled so that the body's net weight per fluid mass is the same;
  settling24_cv0, settling24_ratio<r>_cv0: the same without virtual mass
     (virtualMass 0, VIRTUAL_MASS; the others 0.5); settling24_cv0p25,
     settling24_cv1, settling24_ratio0p5_cv1, settling24_ratio8_cv1: with C_v
     0.25 and 1, checks of how the module brackets C_v;
  sphere8_backward, settling24_backward: sphere8 and settling24 with backward
     steps (the other cases use Euler);
  cavity: the lid-driven square cavity (32 x 32 cells, side 1, lid speed 1,
     nu = 1: Re 1) without a body, OpenFOAM's own coupling alone.
Each fixed-body and cavity case is first run to a near-steady state at
lambda = 1 (the base); each test restarts from it for STEPS steps at one
lambda with one setting. Its signal is the body's drag F_x, its vertical
velocity (settling) or the largest Courant number (cavity) per step; the
period-two amplitude a_n = |s_n - 2 s_(n-1) + s_(n-2)|/4 (from rest: the third
difference |s_n - 3 s_(n-1) + 3 s_(n-2) - s_(n-3)|/8) measures the
oscillation, and its growth per step g is (a_end/a_mid)^(1/m), a_mid the
largest a_n over 10 steps from a quarter of the run, a_end over the last 5, m
the steps between their centres. A test is unstable when the solver fails, or
when the oscillation grows (g > 1) and a_end exceeds 1e-6 of the signal (a
decaying or roundoff-level oscillation is stable; settling: 1e-3 of the
signal, with the third difference alternating in sign at 80 % of the last 9
steps, as the settling body's velocity carries an irregular ripple of about
1e-4 from the cells it crosses). A settling test found unstable without
diverging, with a_end below CONFIRM_BELOW of the signal, is run again for
CONFIRM_STEPS steps and takes that run's verdict (steps in its row): the
ripple of a fast body can exceed 1e-3 of its velocity for a few steps and
look like a growing oscillation over 100 steps, where a real instability
keeps growing. For each case and setting
lambda is doubled from 0.0625 until the first unstable test, then bisected on
the grid 2^(k/4) between the last stable and the first unstable lambda (the
limit, the largest stable lambda, to a factor 2^(1/4) = 1.19; stability is
taken to fall with lambda).

run: the scans, rows appended to results/runs.csv (each test once, unless
     --force); --only restricts to the named cases.
confirm: runs the confirmation of every row of results/runs.csv that needs
     one and has none (a row of 100 steps) and replaces the row;
     `run` then continues a scan whose verdict changed.
plot: results/table.md, results/metrics.json (limit_<case>_<setting>: the
     largest stable lambda; first_unstable_<case>_<setting>;
     cpd_exponent_<setting>: p of lambda_c ~ (cells per D)^-p fitted over the
     spheres at 8-16 cells/D), results/viscousNumber.png (g against lambda for
     sphere8 and the cavity; the limit against the resolution).
quick: the check of tests/foam/viscousNumberQuick, in DIR: sphere8 with the
     default setting (momentum predictor, 2 pressure correctors) must be
     stable at LIMIT (the module's limit for it) and unstable at
     QUICK_UNSTABLE, and the same sphere in a periodic box of 8 D must be
     stopped by the module at QUICK_PERIOD_LAMBDA; exit status 1 otherwise.
"""
import argparse
import json
import math
import os
import re
import shutil
import sys
from pathlib import Path

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "stokesDrag"))
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
import caseWriter  # noqa: E402
from validationTools import (locked, provenance, read_csv, run_logged,  # noqa: E402
                             set_entry, substitute, write_csv, write_dict)

RESULTS = os.path.join(HERE, "results")
RUNS_CSV = os.path.join(RESULTS, "runs.csv")
RUN_DIR = os.path.join(HERE, "run")

# the settings of the PIMPLE dictionary: (momentumPredictor, nCorrectors,
# nOuterCorrectors, relaxation factors of U and p in the outer correctors but
# the last, or None)
SETTINGS = {
    "pred_c1": ("yes", 1, 1, None),
    "pred_c2": ("yes", 2, 1, None),
    "pred_c3": ("yes", 3, 1, None),
    "pred_c4": ("yes", 4, 1, None),
    "pred_c1_o3": ("yes", 1, 3, None),
    "pred_c1_o3_relax": ("yes", 1, 3, (0.7, 0.3)),
    "pred_c2_o3": ("yes", 2, 3, None),
    "pred_c2_o3_relax": ("yes", 2, 3, (0.7, 0.3)),
    "pred_c3_o3": ("yes", 3, 3, None),
    "pred_c2_consistent": ("yes", 2, 1, None),
    "nopred_c1": ("no", 1, 1, None),
    "nopred_c2": ("no", 2, 1, None),
}
# the lambdas tested: 2^(k/4), k from K_MIN to K_MAX (0.0625 to 2048)
K_MIN, K_MAX = -16, 44
STEPS = 60
SETTLING_STEPS = 100
# a settling test unstable with its last oscillation below CONFIRM_BELOW of its
# signal is confirmed by a run of CONFIRM_STEPS steps (a light body at lambda 0.0625
# rises about 35 mm, 2.5 D_eq, in 140 steps from 30 mm above the floor, and stays clear
# of the lid at 80 mm)
CONFIRM_BELOW = 0.05
CONFIRM_STEPS = 140
SETTLING_CASE = os.path.join(HERE, "..", "..", "tests", "foam", "settlingSphereCase")
# quick: a lambda that must be unstable with pred_c2 on sphere8
QUICK_UNSTABLE = 9
# quick: a lambda the module must refuse for sphere8 in a periodic box of 8 D (its limit
# there is that of 16 cells per D_eq, 1.99; 4.73 in the box of 4 D)
QUICK_PERIOD_LAMBDA = 3
# the settings scanned on free bodies
FREE_SETTINGS = ["pred_c2", "pred_c3", "pred_c4", "nopred_c2", "pred_c2_consistent"]
CASES = {
    # name: (kind, cells per length unit: cells per D_eq or cells per cavity side,
    #        base run length, settings scanned, the body's aspect ratio)
    "sphere6": ("body", 6, 1.6, ["pred_c2", "pred_c3"], 1.0),
    "sphere8": ("body", 8, 1.6, list(SETTINGS), 1.0),
    "sphere12": ("body", 12, 1.6, ["pred_c2", "pred_c3", "nopred_c2", "pred_c2_consistent"],
                 1.0),
    "sphere16": ("body", 16, 0.8, ["pred_c2", "pred_c3", "pred_c2_consistent"], 1.0),
    "prolate8": ("body", 8, 1.6, ["pred_c2"], 2.0),
    # sphere8 in domains with an inlet and an outlet (OPEN_DOMAIN)
    "sphere8_open": ("body", 8, 1.6, ["pred_c2"], 1.0),
    "sphere8_open_small": ("body", 8, 1.6, ["pred_c2"], 1.0),
    # a sphere moved at constant velocity through fluid at rest (MOVING)
    "moving8_box4": ("body", 8, 1.6, ["pred_c2"], 1.0),
    "moving8_box8": ("body", 8, 1.6, ["pred_c2"], 1.0),
    # sphere8 in larger boxes (BOX), sphere12 and sphere16 in the box of 8 D (as many cells
    # across as sphere8 in those of 12 and 16 D), and sphere8 in boxes 8 D long across the
    # flow and along it
    "sphere8_box12": ("body", 8, 1.6, ["pred_c2"], 1.0),
    "sphere12_box8": ("body", 12, 1.6, ["pred_c2"], 1.0),
    "sphere8_box16": ("body", 8, 1.6, ["pred_c2"], 1.0),
    "sphere16_box8": ("body", 16, 0.8, ["pred_c2"], 1.0),
    "sphere8_box4x4x8": ("body", 8, 1.6, ["pred_c2"], 1.0),
    "sphere8_box8x4x4": ("body", 8, 1.6, ["pred_c2"], 1.0),
    "sphere8_box6": ("body", 8, 1.6, ["pred_c2", "pred_c3", "pred_c2_consistent"], 1.0),
    "sphere8_box8": ("body", 8, 1.6, ["pred_c2", "pred_c3", "pred_c2_consistent"], 1.0),
    "oblate8": ("body", 8, 1.6, ["pred_c2"], 0.5),
    # free settling: cells across the 60 mm box width
    "settling24": ("settling", 24, None, FREE_SETTINGS, None),
    "settling36": ("settling", 36, None, ["pred_c2", "pred_c3"], None),
    # the same spheroid at other density ratios (SETTLING_DENSITY_RATIO)
    **{name: ("settling", 24, None, FREE_SETTINGS, None) for name in
       ("settling24_ratio0p1", "settling24_ratio0p3", "settling24_ratio0p5",
        "settling24_ratio2", "settling24_ratio8")},
    # the same spheroid without virtual mass at every density ratio (VIRTUAL_MASS)
    **{name: ("settling", 24, None, FREE_SETTINGS, None) for name in
       ("settling24_cv0", "settling24_ratio0p1_cv0", "settling24_ratio0p3_cv0",
        "settling24_ratio0p5_cv0",
        "settling24_ratio2_cv0", "settling24_ratio8_cv0")},
    # and with C_v between and above the table's 0 and 0.5 (checks of the bracketing)
    **{name: ("settling", 24, None, ["pred_c2", "pred_c3"], None) for name in
       ("settling24_cv0p25", "settling24_cv1")},
    **{name: ("settling", 24, None, ["pred_c2"], None) for name in
       ("settling24_ratio0p5_cv1", "settling24_ratio8_cv1")},
    # a free sphere in triply periodic boxes (PERIODIC_SETTLING)
    "settling_periodic4": ("settling", 6, None, ["pred_c2"], None),
    "settling_periodic8": ("settling", 6, None, ["pred_c2"], None),
    # the same with backward steps (the README's advice for moving bodies)
    "sphere8_backward": ("body", 8, 1.6, ["pred_c2", "pred_c3"], 1.0),
    "settling24_backward": ("settling", 24, None, ["pred_c2", "pred_c3"], None),
    "cavity": ("cavity", 32, 0.3, list(SETTINGS), None),
    "cavity64": ("cavity", 64, 0.3, ["pred_c2", "pred_c3"], None),
    "cavity128": ("cavity", 128, 0.3, ["pred_c2"], None),
}
# the density ratio rho_p/rho_f of a settling case (that of settlingSphereCase, 1120/960,
# unless named here); gravity is scaled so that (rho_p/rho_f - 1)|g| is the base case's, and a
# body lighter than the fluid starts as far below the lid as the base case's starts above the
# floor, so that every body moves as far in its 100 steps
SETTLING_BASE_RATIO = 1120 / 960
SETTLING_DENSITY_RATIO = {f"settling24_ratio{tag}{cv}": ratio
                          for tag, ratio in (("0p1", 0.1), ("0p3", 0.3), ("0p5", 0.5),
                                             ("2", 2.0), ("8", 8.0))
                          for cv in ("", "_cv0", "_cv1")}
# the virtual-mass coefficient C_v (virtualMass) of a settling case (the base case's, 0.5,
# unless named here); viscousNumberLimit.C's free entries are those of TABLE_VIRTUAL_MASS, the
# others check how it brackets C_v
SETTLING_BASE_VIRTUAL_MASS = 0.5
TABLE_VIRTUAL_MASS = (0.0, 0.5)
VIRTUAL_MASS = {name: cv for name in CASES
                for tag, cv in (("_cv0", 0.0), ("_cv0p25", 0.25), ("_cv1", 1.0))
                if name.startswith("settling24") and name.endswith(tag)}
# the periodic box's side of a fixed-body case in D_eq (SCANNED_PERIOD unless named here), or
# its sides along x (the flow), y and z; viscousNumberLimit.C counts a body at c cells per D_eq
# in a longest period L above SCANNED_PERIOD as one at c L/SCANNED_PERIOD (period_cells)
SCANNED_PERIOD = 4.0
BOX = {"sphere8_box6": 6.0, "sphere8_box8": 8.0, "sphere8_box12": 12.0, "sphere12_box8": 8.0,
       "sphere8_box16": 16.0, "sphere16_box8": 8.0,
       "moving8_box4": 4.0, "moving8_box8": 8.0,
       "sphere8_box4x4x8": (4.0, 4.0, 8.0), "sphere8_box8x4x4": (8.0, 4.0, 4.0)}
# prescribed-motion cases: the sphere moves at (-0.02, 0, 0) through fluid at rest in the
# periodic box, no mean flow held (sphere8's relative flow without meanVelocityForce)
MOVING = ("moving8_box4", "moving8_box8")
# fixed-body cases in the domain of validation/finiteReynoldsDrag (a uniform stream from an
# inlet to an outlet, symmetry sides, the mesh refined towards the body) at Re 0.02:
# (x0 x1 y0 y1 z0 z1) in D_eq
OPEN_DOMAIN = {"sphere8_open": (-12.0, 24.0, -12.0, 12.0, -12.0, 12.0),
               "sphere8_open_small": (-4.0, 9.0, -4.0, 4.0, -4.0, 4.0)}
# free spheres settling from rest in triply periodic boxes: the single sphere of
# validation/hinderedSettling (density ratio 2, meanFlow zeroFlux, the periodicSuspension
# tutorial's numerics, uniform cells) in boxes of PERIODIC_SETTLING[name] D, steps of
# PERIODIC_DT D/V_g, nu set for lambda
PERIODIC_SETTLING = {"settling_periodic4": 4.0, "settling_periodic8": 8.0}
PERIODIC_DT = 0.05
# the time scheme of a case (Euler unless named here)
BACKWARD = ("sphere8_backward", "settling24_backward")

FIELDS = ["case", "setting", "lam", "status", "growth", "amp_mid", "amp_end", "signal_end",
          "steps", "cpu_s", "host", "date", "commit"]


# ---------------------------------------------------------------------------
# cases

def write_cavity(case, n):
    """The lid-driven cavity: side 1, n x n cells, one cell deep (2D), nu = 1, lid speed 1."""
    title = "spheroidFoam validation: viscous-number stability (validation/viscousNumber)"
    write_dict(os.path.join(case, "system", "blockMeshDict"), "dictionary", "system",
               "blockMeshDict", f"""
convertToMeters 1;
vertices ( (0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 0.1) (1 0 0.1) (1 1 0.1) (0 1 0.1) );
blocks ( hex (0 1 2 3 4 5 6 7) ({n} {n} 1) simpleGrading (1 1 1) );
boundary
(
    movingWall {{ type wall; faces ((3 7 6 2)); }}
    fixedWalls {{ type wall; faces ((0 4 7 3) (2 6 5 1) (1 5 4 0)); }}
    frontAndBack {{ type empty; faces ((0 3 2 1) (4 5 6 7)); }}
);
""", title)
    write_dict(os.path.join(case, "system", "controlDict"), "dictionary", "system",
               "controlDict", """
application     pimpleFoam;
startFrom       latestTime;
startTime       0;
stopAt          endTime;
endTime         1;
deltaT          1;
writeControl    timeStep;
writeInterval   100000;
writeFormat     binary;
writePrecision  12;
timeFormat      general;
timePrecision   17;
""", title)
    write_dict(os.path.join(case, "system", "fvSchemes"), "dictionary", "system", "fvSchemes",
               """
ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes
{
    default         none;
    div(phi,U)      Gauss linear;
    div((nuEff*dev2(T(grad(U))))) Gauss linear;
}
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
""", title)
    write_dict(os.path.join(case, "system", "fvSolution"), "dictionary", "system",
               "fvSolution", """
solvers
{
    p { solver PCG; preconditioner DIC; tolerance 1e-10; relTol 0.01; }
    pFinal { $p; relTol 0; }
    "(U|UFinal)" { solver PBiCGStab; preconditioner DILU; tolerance 1e-12; relTol 0; }
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
""", title)
    write_dict(os.path.join(case, "constant", "transportProperties"), "dictionary",
               "constant", "transportProperties", "\ntransportModel  Newtonian;\nnu 1;\n",
               title)
    write_dict(os.path.join(case, "constant", "turbulenceProperties"), "dictionary",
               "constant", "turbulenceProperties", "\nsimulationType  laminar;\n", title)
    write_dict(os.path.join(case, "0", "U"), "volVectorField", "0", "U", """
dimensions      [0 1 -1 0 0 0 0];
internalField   uniform (0 0 0);
boundaryField
{
    movingWall { type fixedValue; value uniform (1 0 0); }
    fixedWalls { type noSlip; }
    frontAndBack { type empty; }
}
""", title)
    write_dict(os.path.join(case, "0", "p"), "volScalarField", "0", "p", """
dimensions      [0 2 -2 0 0 0 0];
internalField   uniform 0;
boundaryField
{
    movingWall { type zeroGradient; }
    fixedWalls { type zeroGradient; }
    frontAndBack { type empty; }
}
""", title)


def base_case(name):
    """Write and run the base of case name (lambda 1 to a near-steady state) in run/<name>/base
    unless it is there; returns its folder."""
    kind, n, t_end, _, ar = CASES[name]
    base = os.path.join(RUN_DIR, name, "base")
    if os.path.exists(os.path.join(base, "done")):
        return base
    shutil.rmtree(base, ignore_errors=True)
    dt = 1.0 / n ** 2                       # lambda 1 (nu = 1)
    steps = int(round(t_end / dt))
    if name in OPEN_DOMAIN:
        frd = open_domain_writer()
        frd.write_case(base, ar, 0.0, 0.02, n, 1.0, domain=OPEN_DOMAIN[name],
                       max_viscous_number=1e6)
        dt = 0.02 / n ** 2                  # lambda 1 (nu = 50)
        steps = int(round(t_end * 0.02 / dt))
    elif kind == "body":
        # this campaign runs past the module's viscous-number limit on purpose
        moving = (dict(ubar=(0.0, 0.0, 0.0), body_velocity=(-0.02, 0.0, 0.0))
                  if name in MOVING else {})
        caseWriter.write_case(base, ar, "x", BOX.get(name, SCANNED_PERIOD), n, dt, steps * dt,
                              max_viscous_number=1e6, **moving,
                              ddt="backward" if name in BACKWARD else "Euler")
    else:
        write_cavity(base, n)
    set_entry(os.path.join(base, "system", "controlDict"), "deltaT", f"{dt:.12g}")
    set_entry(os.path.join(base, "system", "controlDict"), "endTime", f"{steps * dt:.12g}")
    set_entry(os.path.join(base, "system", "controlDict"), "writeControl", "timeStep")
    set_entry(os.path.join(base, "system", "controlDict"), "writeInterval", str(steps))
    for cmd in ([["pimpleFoam"]] if name in OPEN_DOMAIN else [["blockMesh"], ["pimpleFoam"]]):
        if run_logged(cmd, base, f"log.{cmd[0]}") != 0:
            sys.exit(f"viscousNumber: {cmd[0]} failed in {base}")
    open(os.path.join(base, "done"), "w").close()
    return base


def validation_module(folder, file, name):
    """The module file of validation/folder, loaded as name (several validations have a
    caseWriter.py)."""
    import importlib.util
    path = Path(__file__).resolve().parents[1] / folder / file
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def open_domain_writer():
    """validation/finiteReynoldsDrag's case writer."""
    return validation_module("finiteReynoldsDrag", "caseWriter.py", "finiteReynoldsDragCaseWriter")


def periodic_settling_case(case, n, box, lam, steps=SETTLING_STEPS):
    """A free sphere (D = 1) at the centre of a triply periodic box of side box on
    (n box)^3 cells, from rest, SETTLING_STEPS steps of PERIODIC_DT, nu set for
    nu dt/h^2 = lam (validation/hinderedSettling's single-sphere case)."""
    hs = validation_module("hinderedSettling", "hinderedSettling.py", "hinderedSettling")
    end = steps * PERIODIC_DT
    hs.write_case(case, 0.0, n, box, 1, end, write_interval=end,
                  single=dict(n=int(round(n * box)), nu=lam / n ** 2 / PERIODIC_DT, g=1.0,
                              dt=PERIODIC_DT))
    substitute(os.path.join(case, "constant", "immersedBodiesProperties"), "fluidDensity",
               "maxViscousNumber 1e6;\n\nfluidDensity")


def signal(case, kind):
    """The per-step signal of a test: the body's drag F_x, or the largest Courant number."""
    if kind in ("body", "settling"):
        import h5py
        path = os.path.join(case, "postProcessing", "immersedBodies", "bodies.h5")
        if not os.path.exists(path):
            sys.exit(f"viscousNumber: no time series {path}: the run did not start (its log)")
        with h5py.File(path, "r", locking=False) as f:
            if kind == "settling":
                return np.array(f["velocity"][:, 0, 2])
            return np.array(f["hydroForce"][:, 0, 0])
    with open(os.path.join(case, "log.pimpleFoam")) as f:
        return np.array([float(x) for x in
                         re.findall(r"^Courant Number mean: \S+ max: (\S+)", f.read(),
                                    flags=re.M)])


def period_two(s, kind):
    """The amplitude of the period-two oscillation of s per step: a_n = |s_n - 2 s_(n-1) +
    s_(n-2)|/4 from a steady base; from rest (settling) the third difference |s_n -
    3 s_(n-1) + 3 s_(n-2) - s_(n-3)|/8, which a smooth transient leaves small where its
    curvature would not be (both are A for s_n = A (-1)^n)."""
    if kind == "settling":
        return np.abs(s[3:] - 3 * s[2:-1] + 3 * s[1:-2] - s[:-3]) / 8
    return np.abs(s[2:] - 2 * s[1:-1] + s[:-2]) / 4


def settling_cells_per_diameter(n):
    """Cells per equal-volume diameter of the settling spheroid (semi-axes 9, 6, 6 mm) on
    n cells across the 60 mm box."""
    return 2 * (9 * 6 * 6) ** (1 / 3) / (60 / n)


def settling_case(case, n, lam, ratio=None, virtual_mass=None, steps=SETTLING_STEPS):
    """The settling spheroid of tests/foam/settlingSphereCase in case/, on n x n x 4n/3
    cells, nu set for nu dt/h^2 = lam, SETTLING_STEPS steps of 4 ms from rest; with ratio,
    the body's density is ratio times the fluid's (SETTLING_DENSITY_RATIO); with
    virtual_mass, that virtualMass (VIRTUAL_MASS)."""
    shutil.copytree(SETTLING_CASE, case)
    shutil.copytree(os.path.join(case, "0.orig"), os.path.join(case, "0"))
    substitute(os.path.join(case, "system", "blockMeshDict"), "(24 24 32)",
               f"({n} {n} {4 * n // 3})")
    h, dt = 0.06 / n, 0.004
    set_entry(os.path.join(case, "constant", "transportProperties"), "nu",
              f"{lam * h * h / dt:.12g}")
    control = os.path.join(case, "system", "controlDict")
    set_entry(control, "deltaT", f"{dt:g}")
    set_entry(control, "endTime", f"{steps * dt:g}")
    properties = os.path.join(case, "constant", "immersedBodiesProperties")
    substitute(properties, "fluidDensity", "maxViscousNumber 1e6;\n\nfluidDensity")
    if ratio is not None:
        substitute(properties, "density         1120;", f"density         {960 * ratio:.12g};")
        g = 9.81 * (SETTLING_BASE_RATIO - 1) / abs(ratio - 1)
        substitute(os.path.join(case, "constant", "g"), "(0 0 -9.81)", f"(0 0 -{g:.12g})")
        if ratio < 1:
            substitute(properties, "(0.0285 0.031 0.05)", "(0.0285 0.031 0.03)")
    if virtual_mass is not None:
        substitute(properties, "virtualMass     0.5;", f"virtualMass     {virtual_mass:g};")


def run_test(name, setting, lam, confirmation=False):
    """One test: STEPS steps at lambda from the base of case name (SETTLING_STEPS from rest
    for a settling case, CONFIRM_STEPS for the confirmation of a marginal instability, which
    a settling test that needs one runs at once); returns its row."""
    kind, n, _, _, _ = CASES[name]
    case = os.path.join(RUN_DIR, name, f"{setting}_lam{lam:g}")
    shutil.rmtree(case, ignore_errors=True)
    steps = STEPS
    if kind == "settling":
        steps = CONFIRM_STEPS if confirmation else SETTLING_STEPS
        if name in PERIODIC_SETTLING:
            periodic_settling_case(case, n, PERIODIC_SETTLING[name], lam, steps)
        else:
            settling_case(case, n, lam, SETTLING_DENSITY_RATIO.get(name),
                          VIRTUAL_MASS.get(name), steps)
        if name in BACKWARD:
            substitute(os.path.join(case, "system", "fvSchemes"), "default         Euler;",
                       "default         backward;")
    else:
        shutil.copytree(base_case(name), case)
        t0 = float(max((d for d in os.listdir(case) if re.fullmatch(r"[0-9.eE+-]+", d)),
                       key=float))
        dt = lam / n ** 2 * (0.02 if name in OPEN_DOMAIN else 1.0)   # nu 50 or 1
        control = os.path.join(case, "system", "controlDict")
        set_entry(control, "deltaT", f"{dt:.12g}")
        set_entry(control, "endTime", f"{t0 + STEPS * dt:.12g}")
        set_entry(control, "writeInterval", str(10 * STEPS))
    predictor, correctors, outer, relax = SETTINGS[setting]
    solution = os.path.join(case, "system", "fvSolution")
    set_entry(solution, "momentumPredictor", predictor)
    set_entry(solution, "nCorrectors", str(correctors))
    set_entry(solution, "nOuterCorrectors", str(outer))
    if setting.endswith("_consistent"):
        # SIMPLEC's form of the pressure equation (pimpleControl's consistent)
        substitute(solution, "nOuterCorrectors", "consistent      yes;\n    nOuterCorrectors")
    if relax is not None:
        with open(solution, "a") as f:
            f.write("relaxationFactors\n{\n    equations { U %g; UFinal 1; }\n"
                    "    fields { p %g; pFinal 1; }\n}\n" % relax)
    solver = "immersedSpheroidFoam" if kind == "settling" else "pimpleFoam"
    if kind == "settling" and run_logged(["blockMesh"], case, "log.blockMesh") != 0:
        sys.exit(f"viscousNumber: blockMesh failed in {case}")
    status = run_logged([solver], case, f"log.{solver}")
    with open(os.path.join(case, f"log.{solver}")) as f:
        log = f.read()
    cpu = re.findall(r"^ExecutionTime = (\S+) s", log, flags=re.M)
    row = dict(case=name, setting=setting, lam=f"{lam:g}", cpu_s=cpu[-1] if cpu else "",
               **provenance())
    s = signal(case, kind)
    s = s[-steps:]
    row["steps"] = len(s)
    if status != 0 or len(s) < steps or not np.all(np.isfinite(s)):
        row.update(status="diverged", growth="inf", amp_mid="", amp_end="",
                   signal_end=f"{s[-1]:.6g}" if len(s) else "")
        return row
    a = period_two(s, kind)
    # a_mid over 10 steps from a quarter of the run, a_end over the last 5; the
    # growth per step between their centres
    q = steps // 4
    mid, end = a[q - 2:q + 8].max(), a[-5:].max()
    growth = (max(end, 1e-300) / max(mid, 1e-300)) ** (1 / (len(a) - 3 - (q + 3)))
    if kind == "settling":
        # a moving body's velocity carries the ripple of the cells it crosses (about 1e-4
        # of it here, irregular): its oscillation must alternate in sign every step and
        # reach 1e-3 of the signal
        d = np.diff(s[-12:], 3)
        alternating = np.mean(d[1:] * d[:-1] < 0)
        unstable = growth > 1 and end > 1e-3 * abs(s[-1]) and alternating >= 0.8
    else:
        unstable = growth > 1 and end > 1e-6 * abs(s[-1])
    row.update(status="unstable" if unstable else "stable", growth=f"{growth:.4f}",
               amp_mid=f"{mid:.3e}", amp_end=f"{end:.3e}", signal_end=f"{s[-1]:.6g}")
    shutil.rmtree(case)
    if needs_confirmation(row, kind):
        return run_test(name, setting, lam, confirmation=True)
    return row


def needs_confirmation(row, kind):
    """Whether a test's row is a marginal instability of a settling body that a longer
    run must confirm: unstable without diverging, its last oscillation below CONFIRM_BELOW
    of the signal, and not itself a confirmation."""
    return (kind == "settling" and row["status"] == "unstable"
            and int(row["steps"]) < CONFIRM_STEPS
            and float(row["amp_end"]) < CONFIRM_BELOW * abs(float(row["signal_end"])))


def do_quick(args):
    global RUN_DIR
    RUN_DIR = os.path.abspath(args.dir)
    ok = True
    for lam, expected in ((args.limit, "stable"), (QUICK_UNSTABLE, "unstable")):
        row = run_test("sphere8", "pred_c2", lam)
        print(f"sphere8 pred_c2 lambda {lam:g}: {row['status']} (growth {row['growth']}/step, "
              f"period-two amplitude {row['amp_mid']} -> {row['amp_end']}), expected "
              f"{expected}")
        ok = ok and (row["status"] == expected
                     or (expected == "unstable" and row["status"] == "diverged"))
    ok = quick_period() and ok
    sys.exit(0 if ok else 1)


def quick_period():
    """sphere8 in a periodic box of 8 D at QUICK_PERIOD_LAMBDA with the module's own limit:
    the run must stop at its first step with the error naming the period."""
    case = os.path.join(RUN_DIR, "period")
    shutil.rmtree(case, ignore_errors=True)
    dt = QUICK_PERIOD_LAMBDA / CASES["sphere8"][1] ** 2
    caseWriter.write_case(case, 1.0, "x", 8.0, CASES["sphere8"][1], dt, 2 * dt)
    if run_logged(["blockMesh"], case, "log.blockMesh") != 0:
        sys.exit(f"viscousNumber: blockMesh failed in {case}")
    status = run_logged(["pimpleFoam"], case, "log.pimpleFoam")
    with open(os.path.join(case, "log.pimpleFoam")) as f:
        log = f.read()
    expected = ["FOAM FATAL ERROR", "in the cells of body", "in a period of 8 D_eq"]
    missing = [e for e in expected if e not in log]
    print(f"sphere8 in a periodic box of 8 D at lambda {QUICK_PERIOD_LAMBDA:g}: exit status "
          f"{status}, expected non-zero with {expected}"
          + (f"; missing: {missing} (see {case}/log.pimpleFoam)" if missing else ""))
    return status != 0 and not missing


def lam_of(k):
    """The lambda of grid index k, as written in runs.csv."""
    return float(f"{2 ** (k / 4):.6g}")


def do_confirm(args):
    """The confirmation of every row that needs one and has none, each
    replacing its row."""
    names = args.only or list(CASES)
    for r in read_csv(RUNS_CSV, missing_ok=False):
        if r["case"] not in names or not needs_confirmation(r, CASES[r["case"]][0]):
            continue
        row = run_test(r["case"], r["setting"], float(r["lam"]), confirmation=True)
        with locked(RUNS_CSV):
            rows = [x for x in read_csv(RUNS_CSV)
                    if not (x["case"] == r["case"] and x["setting"] == r["setting"]
                            and x["lam"] == r["lam"])] + [row]
            write_csv(RUNS_CSV, rows, FIELDS)
        print(f"{r['case']} {r['setting']} lambda {r['lam']}: {r['status']} in "
              f"{r['steps']} steps, {row['status']} in {row['steps']} (growth "
              f"{row['growth']}/step)", flush=True)


def do_run(args):
    """Per case and setting: lambda doubled from the grid's start until the first unstable
    test (or the grid's end), then bisection on the grid between the last stable and the
    first unstable lambda."""
    rows = read_csv(RUNS_CSV)
    names = args.only or list(CASES)
    for name in names:
        if name not in CASES:
            sys.exit(f"viscousNumber: unknown case {name}; cases: {', '.join(CASES)}")

    def status_at(name, setting, k):
        nonlocal rows
        lam = lam_of(k)
        done = [r for r in rows if r["case"] == name and r["setting"] == setting
                and abs(float(r["lam"]) / lam - 1) < 1e-9]
        if done and not args.force:
            return done[-1]["status"] == "stable"
        row = run_test(name, setting, lam)
        # merged with the file's current rows under its lock: scans of other cases may
        # run beside this one
        with locked(RUNS_CSV):
            rows = [r for r in read_csv(RUNS_CSV)
                    if not (r["case"] == name and r["setting"] == setting
                            and abs(float(r["lam"]) / lam - 1) < 1e-9)] + [row]
            write_csv(RUNS_CSV, rows, FIELDS)
        print(f"{name} {setting} lambda {lam:g}: {row['status']} (growth "
              f"{row['growth']}/step)", flush=True)
        return row["status"] == "stable"

    for name in names:
        for setting in CASES[name][3]:
            stable, unstable = None, None
            for k in range(K_MIN, K_MAX + 1, 4):
                if status_at(name, setting, k):
                    stable = k
                else:
                    unstable = k
                    break
            if unstable is None or stable is None:
                continue
            while unstable - stable > 1:
                k = (stable + unstable) // 2
                if status_at(name, setting, k):
                    stable = k
                else:
                    unstable = k


# ---------------------------------------------------------------------------
# tables and figures

def limits(rows):
    """{(case, setting): (largest stable lambda, first unstable lambda or None)}."""
    out = {}
    for name, (_, _, _, settings, _) in CASES.items():
        for setting in settings:
            rs = sorted((r for r in rows if r["case"] == name and r["setting"] == setting),
                        key=lambda r: float(r["lam"]))
            if not rs:
                continue
            stable, first = None, None
            for r in rs:
                if r["status"] == "stable":
                    stable = float(r["lam"])
                else:
                    first = float(r["lam"])
                    break
            out[(name, setting)] = (stable, first)
    return out


def do_plot(_args):
    rows = read_csv(RUNS_CSV, missing_ok=False)
    lim = limits(rows)
    metrics = {}
    lines = ["| case | momentumPredictor | consistent | nCorrectors | nOuterCorrectors | "
             "largest stable lambda | first unstable lambda |", "|---|---|---|---|---|---|---|"]
    for (name, setting), (stable, first) in lim.items():
        predictor, correctors, outer, relax = SETTINGS[setting]
        outer = f"{outer} (relaxation U {relax[0]:g}, p {relax[1]:g})" if relax else outer
        consistent = "yes" if setting.endswith("_consistent") else "no"
        lines.append(f"| {name} | {predictor} | {consistent} | {correctors} | {outer} | "
                     f"{'-' if stable is None else f'{stable:g}'} | "
                     f"{'> ' + f'{lam_of(K_MAX):g}' if first is None else f'{first:g}'} |")
        if stable is not None:
            metrics[f"limit_{name}_{setting}"] = stable
        if first is not None:
            metrics[f"first_unstable_{name}_{setting}"] = first
    mod = module_limits(lim)
    mlines = ["| body | density ratio | virtual mass C_v | momentumPredictor | consistent | "
              f"nCorrectors | outer correctors | limit at {REFERENCE_CPD} cells/D_eq | "
              "exponent p | C++ entry |", "|---|---|---|---|---|---|---|---|---|---|"]
    for (free, setting, ratio, cv), (value, p) in sorted(mod.items(), key=lambda kv: kv[0]):
        predictor, correctors, outer, relax = SETTINGS[setting]
        # viscousNumberLimit::outerMode: single, unrelaxed, relaxed
        mode = 0 if outer == 1 else (2 if relax else 1)
        v, p = floor3(value), round(p, 2)
        if free:
            metrics[f"module_limit_free_{setting}_ratio{ratio:g}_cv{cv:g}".replace(".", "p")] = v
        else:
            metrics[f"module_limit_fixed_{setting}"] = v
        consistent = setting.endswith("_consistent")
        mlines.append(f"| {'free' if free else 'fixed or prescribed'} | "
                      f"{f'{ratio:g}' if free else 'any'} | {f'{cv:g}' if free else 'any'} | "
                      f"{predictor} | "
                      f"{'yes' if consistent else 'no'} | "
                      f"{correctors} | {('1', 'several', 'several, relaxed')[mode]} | {v:g} | "
                      f"{p:g} | {{{str(free).lower()}, {str(predictor == 'yes').lower()}, "
                      f"{str(consistent).lower()}, {mode}, {correctors}, {v:g}, {p:g}, "
                      f"{ratio:g}, {cv:g}}} |")
    hosts = sorted({r["host"] for r in rows})
    commits = sorted({r["commit"] for r in rows})
    os.makedirs(RESULTS, exist_ok=True)
    with open(os.path.join(RESULTS, "moduleLimits.md"), "w") as f:
        f.write("The limits src/immersedSpheroids/viscousNumberLimit enforces (measuredLimits in "
                "viscousNumberLimit.C; module_limits() of viscousNumber.py, from table.md): "
                f"a body at c cells per D_eq has the limit lambda ({REFERENCE_CPD}/c)^p, "
                "lambda rounded down to 3 digits; a free body of density ratio r has the "
                "smaller of the limits of the two measured ratios that bracket r (the nearest "
                "measured ratio's outside their range), and with virtualMass C_v the smaller of "
                "those of the two measured C_v that bracket C_v (the nearest's outside), at most "
                "the fixed body's; 0: no stable lambda measured (the module refuses the "
                "body).\n\n"
                + "\n".join(mlines) + "\n")
    with open(os.path.join(RESULTS, "table.md"), "w") as f:
        f.write("Largest stable viscous number nu dt/h^2 (Euler; lambdas scanned: "
                + f"2^(k/4) from {lam_of(K_MIN):g} to {lam_of(K_MAX):g}; {STEPS} steps each).\n"
                f"Runs: {len(rows)} on {', '.join(hosts)}, commit(s) {', '.join(commits)}."
                "\n\n" + "\n".join(lines) + "\n")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 4, figsize=(21, 4.8))
    for ax, name in zip(axes[:2], ("sphere8", "cavity")):
        for setting in CASES[name][3]:
            rs = sorted((r for r in rows if r["case"] == name and r["setting"] == setting),
                        key=lambda r: float(r["lam"]))
            lam = [float(r["lam"]) for r in rs]
            g = [float(r["growth"]) if r["growth"] != "inf" else 10.0 for r in rs]
            ax.plot(lam, g, "o-", ms=3, label=setting)
        ax.axhline(1.0, color="k", lw=0.8)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylim(0.5, 12)
        ax.set_xlabel(r"viscous number $\nu\,\Delta t/h^2$")
        ax.set_title(f"{name}: growth per step of the period-two oscillation")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    axes[0].set_ylabel("growth per step (diverged: 10)")
    ax = axes[2]
    for setting, colour in (("pred_c2", "C1"), ("pred_c3", "C2"), ("pred_c2_consistent", "C4")):
        cpd, lam = [], []
        for name in ("sphere6", "sphere8", "sphere12", "sphere16"):
            stable = lim.get((name, setting), (None, None))[0]
            if stable is not None:
                cpd.append(CASES[name][1])
                lam.append(stable)
        ax.plot(cpd, lam, "o-", color=colour, label=f"sphere, {setting}")
        fit = cpd_exponent(lim, setting)
        if fit is not None:
            metrics[f"cpd_exponent_{setting}"] = round(fit, 2)
    mod = module_limits(lim)
    for setting, colour in (("pred_c2", "C1"), ("pred_c3", "C2"), ("pred_c2_consistent", "C4")):
        cpd = [settling_cells_per_diameter(CASES[n][1])
               for n in FREE_CASES if (n, setting) in lim]
        lam = [lim[(n, setting)][0] for n in FREE_CASES if (n, setting) in lim]
        ax.plot(cpd, lam, "s--", color=colour, mfc="none", label=f"free spheroid, {setting}")
        if (False, setting, 0.0, 0.0) in mod:
            value, p = mod[(False, setting, 0.0, 0.0)]
            c = np.array([6.0, REFERENCE_CPD * 2])
            ax.plot(c, floor3(value) * (REFERENCE_CPD / c) ** p, ":", color=colour,
                    label=f"module's limit, fixed, {setting}")
    for name, marker in (("prolate8", "^"), ("oblate8", "v")):
        stable = lim.get((name, "pred_c2"), (None, None))[0]
        if stable is not None:
            ax.plot([CASES[name][1]], [stable], marker, color="C1",
                    label=f"{name} (AR {CASES[name][4]:g}), pred_c2")
    for setting, colour in (("pred_c2", "C1"), ("pred_c3", "C2"), ("pred_c2_consistent", "C4")):
        pts = [(period_cells(n), lim[(n, setting)][0]) for n in BOX
               if lim.get((n, setting), (None, None))[0] is not None]
        if pts:
            ax.plot(*zip(*pts), "D", color=colour, mfc="none",
                    label=f"sphere8 in boxes of {', '.join(box_label(BOX[n]) for n in BOX)} D "
                          f"at 8 L/{SCANNED_PERIOD:g}, {setting}")
    if ax.lines:
        ax.set_xscale("log")
        ax.set_yscale("log")
    ax.set_xlabel("cells per equal-volume diameter")
    ax.set_ylabel(r"largest stable $\nu\,\Delta t/h^2$")
    ax.set_title("limit against the body's resolution")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    ax = axes[3]
    ratio_cases = sorted(["settling24", "settling24_cv0"] + list(SETTLING_DENSITY_RATIO),
                         key=settling_ratio)
    for i, setting in enumerate(FREE_SETTINGS):
        for cv, style in zip(TABLE_VIRTUAL_MASS, ("o--", "s-")):
            pts = [(settling_ratio(n), lim[(n, setting)][0]) for n in ratio_cases
                   if settling_virtual_mass(n) == cv
                   and lim.get((n, setting), (None, None))[0] is not None]
            if pts:
                ax.plot(*zip(*pts), style, color=f"C{i}", mfc="none" if cv == 0 else None,
                        label=f"{setting}, C_v {cv:g}")
    if ax.lines:
        ax.set_xscale("log")
        ax.set_yscale("log")
    ax.set_xlabel(r"density ratio $\rho_p/\rho_f$")
    ax.set_ylabel(r"largest stable $\nu\,\Delta t/h^2$")
    ax.set_title("free spheroid, 5.5 cells per D_eq: limit against rho_p/rho_f")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "viscousNumber.png"), dpi=120)
    with open(os.path.join(RESULTS, "metrics.json"), "w") as f:
        json.dump(metrics, f, indent=2, sort_keys=True)
        f.write("\n")
    print(open(os.path.join(RESULTS, "table.md")).read())
    print(json.dumps(metrics, indent=1, sort_keys=True))


FIXED_CASES = ["sphere6", "sphere8", "sphere12", "sphere16", "prolate8", "oblate8",
               "sphere8_box6", "sphere8_box8", "sphere8_open", "sphere8_open_small",
               "moving8_box4", "moving8_box8", "sphere8_box4x4x8", "sphere8_box8x4x4",
               "sphere8_box12", "sphere12_box8", "sphere8_box16", "sphere16_box8"]
FREE_CASES = ["settling24", "settling36"]


REFERENCE_CPD = 16


def period_cells(name):
    """The resolution a fixed-body case counts as in viscousNumberLimit.C: its cells per D_eq
    times its box's side over SCANNED_PERIOD, where that is larger than one."""
    return CASES[name][1] * max(1.0, longest_period(BOX.get(name, SCANNED_PERIOD))
                                / SCANNED_PERIOD)


def longest_period(box):
    """The longest side of a BOX entry."""
    return box if isinstance(box, float) else max(box)


def box_label(box):
    """A BOX entry as text: 8 or 4x4x8."""
    return f"{box:g}" if isinstance(box, float) else "x".join(f"{s:g}" for s in box)


def settling_ratio(name):
    """The density ratio rho_p/rho_f of settling case name."""
    return SETTLING_DENSITY_RATIO.get(name, SETTLING_BASE_RATIO)


def settling_virtual_mass(name):
    """The virtual-mass coefficient C_v of settling case name."""
    return VIRTUAL_MASS.get(name, SETTLING_BASE_VIRTUAL_MASS)


def module_limits(lim):
    """The limits viscousNumberLimit.C enforces, derived from the scans:
    {(free, setting, density ratio): (lambda at REFERENCE_CPD cells per D_eq, exponent p)},
    the limit of a body at c cells per D_eq being lambda (REFERENCE_CPD/c)^p. A fixed (or
    prescribed) body's p is the exponent fitted over the spheres at 8-16 cells/D for each
    setting run at two or more of them (cpd_exponent), for the others the larger of those of
    nCorrectors 2 and 3 with the standard pressure equation; its lambda is the smallest over
    the fixed cases that ran the setting, each moved to REFERENCE_CPD with p (the spheroids
    included); its density ratio is 0 (any). A free body's limit is, per density ratio
    (rounded down to 3 digits), the smallest over the settling cases of that ratio (p = 0:
    the same at 5.5 and 8.2 cells per D_eq); viscousNumberLimit.C takes the smaller of the
    two measured ratios' limits that bracket a body's ratio and bounds it by the fixed
    body's at the body's resolution."""
    exps = {s: cpd_exponent(lim, s) for s in SETTINGS}
    known = [exps[s] for s in ("pred_c2", "pred_c3") if exps[s] is not None]
    p_other = max(known) if known else 1.0
    out = {}
    for setting in SETTINGS:
        p = exps.get(setting) or p_other
        vals = [lim[(c, setting)][0] * (period_cells(c) / REFERENCE_CPD) ** p
                for c in FIXED_CASES if (c, setting) in lim and lim[(c, setting)][0]]
        if vals:
            out[(False, setting, 0.0, 0.0)] = (min(vals), p)
        for c in FREE_CASES + list(SETTLING_DENSITY_RATIO) + list(VIRTUAL_MASS):
            cv = settling_virtual_mass(c)
            if (c, setting) not in lim or cv not in TABLE_VIRTUAL_MASS:
                continue
            stable, first = lim[(c, setting)]
            if stable is None and first is None:
                continue
            # no stable lambda on the grid: the limit is 0 (the module refuses the body)
            value = stable or 0.0
            key = (True, setting, floor3(settling_ratio(c)), cv)
            out[key] = (min(value, out.get(key, (value,))[0]), 0.0)
    return out


def floor3(x):
    """x rounded down to 3 significant digits."""
    if x <= 0:
        return 0.0
    unit = 10 ** (math.floor(math.log10(x)) - 2)
    return math.floor(x / unit + 1e-9) * unit


def cpd_exponent(lim, setting):
    """p of the fit lambda_c ~ cpd^-p over the spheres at 8 cells/D and finer (least
    squares in log-log), from the scans that found an unstable lambda (a scan stable up to
    the grid's end bounds the limit from below only); None with fewer than two."""
    pts = [(CASES[n][1], lim[(n, setting)][0]) for n in ("sphere8", "sphere12", "sphere16")
           if lim.get((n, setting), (None, None))[0] is not None
           and lim[(n, setting)][1] is not None]
    if len(pts) < 2:
        return None
    x, y = np.log([p[0] for p in pts]), np.log([p[1] for p in pts])
    return -float(np.polyfit(x, y, 1)[0])


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("run")
    r.add_argument("--force", action="store_true")
    r.add_argument("--only", action="append", default=[])
    sub.add_parser("plot")
    c = sub.add_parser("confirm")
    c.add_argument("--only", action="append", default=[])
    q = sub.add_parser("quick")
    q.add_argument("dir")
    q.add_argument("limit", type=float)
    args = ap.parse_args()
    {"run": do_run, "confirm": do_confirm, "plot": do_plot, "quick": do_quick}[args.cmd](args)


if __name__ == "__main__":
    main()
