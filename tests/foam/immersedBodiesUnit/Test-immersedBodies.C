/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
Application
    Test-immersedBodies

Description
    Unit tests of libimmersedSpheroids (run in the case made by the run
    script: a unit box, and the volume meshes as regions):
    1. solid fraction: body volumes of a sphere, a prolate and an oblate
       spheroid at several placements against 4/3 pi abc, second-order
       convergence in the cell size, exact 1/0 in cells entirely
       inside/outside, cell lists against a brute-force pass
       (solidFractionTests.C);
    2. motion models against analytic solutions without fluid (fixed,
       prescribed, free, freeTranslation, freeRotation; torque-free
       precession of a spheroid) (motionTests.C);
    3. the penalty of a prescribed body in fluid at rest, solved with
       fvm::ddt(U) == bodies.penalty(U): rigid-body velocity in covered
       cells, fluid outside untouched, the reported hydrodynamic force and
       torque (penaltyTests.C);
    4. bad constant/immersedBodiesProperties: FatalIOError naming the
       keyword and the file (badInputTests.C);
    5. the coupled runs' body sub-step (coupledBodySet through the
       collision model) against the core's vacuum one (collisionStep, which
       the collision unit tests and validation/dryCollisions run): equal
       trajectories in vacuum through a contact (integratorTests.C);
    6. the surface-corrected penalty of a moving sphere: every cell's
       equation from the method's definition, the force and torque against
       the fluid's momentum (surfacePenaltyTests.C);
    7. the virtual-mass stabilisation of a light body in a model fluid
       whose lagged reaction is the added-mass force under the solve's own
       time difference (Euler, backward): the added-mass acceleration
       without alternation, and a contact in that fluid moving the body as
       the same contact in vacuum (virtualMassTests.C).

Usage
    Test-immersedBodies -case CASE -volumeMeshes '(vol16 vol32 vol64)'
        [-parts '(solidFraction motion penalty badInput integrator surfacePenalty)']
\*---------------------------------------------------------------------------*/

#include "immersedBodiesTests.H"

using namespace testChecks;
using namespace immersedBodiesTests;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

bool immersedBodiesTests::expectFatalError
(
    const std::function<void()>& f,
    std::initializer_list<std::string> mustContain,
    const std::string& what
)
{
    const bool throwing = FatalError.throwExceptions();
    const bool throwingIO = FatalIOError.throwExceptions();
    std::string message;
    bool thrown = false;
    try
    {
        f();
    }
    catch (const Foam::error& err)
    {
        thrown = true;
        message = err.message();
    }
    FatalError.throwExceptions(throwing);
    FatalIOError.throwExceptions(throwingIO);

    if (!thrown)
    {
        return check(false, what + ": no FatalError raised");
    }
    std::string missing;
    for (const std::string& word : mustContain)
    {
        if (message.find(word) == std::string::npos)
        {
            missing += " '" + word + "'";
        }
    }
    Info<< "    message: " << message.c_str() << endl;
    return check(missing.empty(), what + (missing.empty() ? "" : ": message lacks" + missing));
}


int main(int argc, char *argv[])
{
    argList::noParallel();
    argList::addOption
    (
        "volumeMeshes",
        "(region ...)",
        "the mesh regions of the solid-fraction test, coarse to fine"
    );
    argList::addOption
    (
        "parts",
        "(name ...)",
        "run only these parts: solidFraction motion penalty badInput integrator"
        " surfacePenalty virtualMass"
    );
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    wordList parts
    ({
        "solidFraction", "motion", "penalty", "badInput", "integrator",
        "surfacePenalty", "virtualMass"
    });
    args.readListIfPresent("parts", parts);

    if (parts.found("solidFraction"))
    {
        wordList regions;
        if (!args.readListIfPresent("volumeMeshes", regions) || regions.size() < 2)
        {
            FatalErrorInFunction
                << "-volumeMeshes needs at least two mesh regions" << exit(FatalError);
        }
        Info<< nl << "==== 1. Solid fraction" << endl;
        testSolidFraction(runTime, regions);
    }
    if (parts.found("motion"))
    {
        Info<< nl << "==== 2. Motion models" << endl;
        testMotion();
    }
    if (parts.found("penalty"))
    {
        Info<< nl << "==== 3. Penalty" << endl;
        testPenalty(runTime, mesh);
    }
    if (parts.found("badInput"))
    {
        Info<< nl << "==== 4. Bad input" << endl;
        testBadInput(runTime, mesh);
    }
    if (parts.found("integrator"))
    {
        Info<< nl << "==== 5. One body integrator" << endl;
        testIntegrator(mesh);
    }
    if (parts.found("surfacePenalty"))
    {
        Info<< nl << "==== 6. Surface-corrected penalty" << endl;
        testSurfacePenalty(runTime, mesh);
    }
    if (parts.found("virtualMass"))
    {
        Info<< nl << "==== 7. Virtual mass under the fluid's time difference" << endl;
        testVirtualMass(mesh);
    }

    // OpenFOAM v1912's argList destructor ends the process with
    // Pstream::exit(0) whatever main returns: exit here with the status
    const int code = exitCode();
    UPstream::exit(code);
    return code;
}


// ************************************************************************* //
