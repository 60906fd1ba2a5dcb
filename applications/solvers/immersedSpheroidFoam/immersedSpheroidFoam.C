/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).

Application
    immersedSpheroidFoam

Description
    Transient incompressible flow (PIMPLE, laminar or turbulent) with
    immersed moving spheroids: pimpleFoam on a static mesh plus the
    immersedBodies class API, the example of its use in a custom solver.

    In each time step, in the first PIMPLE iteration, the bodies take the
    forces of the last solve, move, and set the implicit penalisation of
    the momentum equation for this step (see immersedBodies.H):
    \verbatim
        immersedBodies& bodies = immersedBodies::New(mesh);
        ...
        if (pimple.firstIter())
        {
            bodies.update(U);
        }
        UEqn == fvOptions(U) + bodies.penalty(U)
    \endverbatim

    Inputs: those of pimpleFoam (static mesh) plus
    constant/immersedBodiesProperties and, with free bodies, constant/g.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "singlePhaseTransportModel.H"
#include "turbulentTransportModel.H"
#include "pimpleControl.H"
#include "fvOptions.H"
#include "immersedBodies.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Transient incompressible flow with immersed moving spheroids"
        " (volume penalisation, rigid-body motion)."
    );

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "createControl.H"
    #include "createTimeControls.H"
    #include "createFields.H"
    #include "initContinuityErrs.H"
    #include "CourantNo.H"
    #include "setInitialDeltaT.H"

    turbulence->validate();

    // * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "readTimeControls.H"
        #include "CourantNo.H"
        #include "setDeltaT.H"

        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        while (pimple.loop())
        {
            if (pimple.firstIter())
            {
                bodies.update(U);
            }

            #include "UEqn.H"

            while (pimple.correct())
            {
                #include "pEqn.H"
            }

            if (pimple.turbCorr())
            {
                laminarTransport.correct();
                turbulence->correct();
            }
        }

        runTime.write();

        runTime.printExecutionTime(Info);
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
