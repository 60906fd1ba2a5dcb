/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
Application
    Test-uniformBodyForce

Description
    Unit test of the uniformBodyForce fvOption on a small mesh (run in a case
    made by blockMesh): the source it adds equals -V a (kinematic) and
    -V rho a (density-weighted) in the selected cells and nothing elsewhere;
    bad dictionaries stop with FatalIOError naming the keyword and file.
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "fvOption.H"
#include "IStringStream.H"
#include "testChecks.H"

using namespace testChecks;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

dictionary parse(const std::string& text, const word& name)
{
    IStringStream is(text, IOstream::ASCII, IOstream::currentVersion, name);
    return dictionary(is);
}

autoPtr<fv::option> make(const fvMesh& mesh, const dictionary& dict)
{
    return fv::option::New("drive", dict, mesh);
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::noParallel();
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    volVectorField U
    (
        IOobject("U", runTime.timeName(), mesh),
        mesh,
        dimensionedVector("U", dimVelocity, Zero)
    );
    volScalarField rho
    (
        IOobject("rho", runTime.timeName(), mesh),
        mesh,
        dimensionedScalar("rho", dimDensity, 1000)
    );
    const vector a(0.8, -0.2, 9.81);
    const scalarField& V = mesh.V();

    // Kinematic source in every cell
    {
        autoPtr<fv::option> opt = make(mesh, parse
        (
            "type uniformBodyForce; selectionMode all; acceleration (0.8 -0.2 9.81);",
            "test/all"
        ));
        fvMatrix<vector> eqn(U, dimVelocity/dimTime*dimVolume);
        opt->addSup(eqn, 0);
        scalar maxErr = 0;
        forAll(V, celli)
        {
            maxErr = max(maxErr, mag(eqn.source()[celli] + V[celli]*a));
        }
        check(maxErr < 1e-14*mag(a)*max(V), "kinematic source = -V a in all cells");
        check(opt->applyToField("U") == 0, "default fields is (U)");

        fvMatrix<vector> rhoEqn(U, dimDensity*dimVelocity/dimTime*dimVolume);
        opt->addSup(rho, rhoEqn, 0);
        maxErr = 0;
        forAll(V, celli)
        {
            maxErr = max(maxErr, mag(rhoEqn.source()[celli] + V[celli]*1000*a));
        }
        check(maxErr < 1e-14*1000*mag(a)*max(V), "density-weighted source = -V rho a");
    }

    // Restricted to the cell holding one point: only that cell is touched
    {
        const point p(0.1, 0.1, 0.1);
        const label cellp = mesh.findCell(p);
        autoPtr<fv::option> opt = make(mesh, parse
        (
            "type uniformBodyForce; uniformBodyForceCoeffs"
            "{ selectionMode points; points ((0.1 0.1 0.1));"
            "  acceleration (0.8 -0.2 9.81); fields (U); }",
            "test/points"
        ));
        fvMatrix<vector> eqn(U, dimVelocity/dimTime*dimVolume);
        opt->addSup(eqn, 0);
        label nTouched = 0;
        forAll(V, celli)
        {
            if (mag(eqn.source()[celli]) > 0) ++nTouched;
        }
        check(cellp >= 0 && nTouched == 1, "points selection touches one cell");
        check
        (
            cellp >= 0 && mag(eqn.source()[cellp] + V[cellp]*a) < 1e-14*mag(a)*V[cellp],
            "that cell gets -V a (Coeffs sub-dictionary form)"
        );
    }

    // Bad input: each names the keyword and the dictionary
    expectFatalIOError
    (
        [&](){ make(mesh, parse("type uniformBodyForce; selectionMode all;", "test/missing")); },
        {"acceleration", "test/missing", "missing"},
        "missing acceleration"
    );
    expectFatalIOError
    (
        [&](){ make(mesh, parse("type uniformBodyForce; selectionMode all; acceleration 5;", "test/scalar")); },
        {"acceleration", "test/scalar", "vector"},
        "scalar where a vector is expected"
    );
    expectFatalIOError
    (
        [&](){ make(mesh, parse("type uniformBodyForce; selectionMode all; acceleration (1 two 3);", "test/word")); },
        {"acceleration", "test/word"},
        "word inside the vector"
    );
    expectFatalIOError
    (
        [&](){ make(mesh, parse("type uniformBodyForce; selectionMode all; acceleration (1 0 0) 2;", "test/excess")); },
        {"acceleration", "test/excess", "excess"},
        "excess tokens"
    );
    expectFatalIOError
    (
        [&](){ make(mesh, parse("type uniformBodyForce; selectionMode all; acceleration (1 0 0); acceleraton (1 0 0);", "test/typo")); },
        {"acceleraton", "test/typo", "Allowed keywords"},
        "unknown keyword (typo)"
    );
    expectFatalIOError
    (
        [&](){ make(mesh, parse("type uniformBodyForce; selectionMode all; acceleration (1 0 0); fields ();", "test/fields")); },
        {"fields", "test/fields"},
        "empty fields"
    );
    expectFatalIOError
    (
        [&](){ make(mesh, parse("type uniformBodyForc; selectionMode all; acceleration (1 0 0);", "test/type")); },
        {"uniformBodyForc", "uniformBodyForce"},
        "unknown fvOption type lists the valid ones"
    );

    return exitCode();
}


// ************************************************************************* //
