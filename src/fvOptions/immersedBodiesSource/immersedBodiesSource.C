/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "immersedBodiesSource.H"
#include "dictionaryChecks.H"
#include "fvMatrices.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(immersedBodiesSource, 0);
    addToRunTimeSelectionTable(option, immersedBodiesSource, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fv::immersedBodiesSource::immersedBodiesSource
(
    const word& name,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    option(name, modelType, dict, mesh),
    bodies_(immersedBodies::New(mesh))
{
    read(dict);
    fieldNames_ = wordList({bodies_.UName()});
    applied_.setSize(fieldNames_.size(), false);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fv::immersedBodiesSource::addSup
(
    fvMatrix<vector>& eqn,
    const label
)
{
    bodies_.update(eqn.psi());
    bodies_.addPenalty(eqn);
}


void Foam::fv::immersedBodiesSource::addSup
(
    const volScalarField&,
    fvMatrix<vector>& eqn,
    const label
)
{
    FatalErrorInFunction
        << "The immersedBodies fvOption " << name_ << " is for"
        << " incompressible solvers (kinematic U and p, e.g. pimpleFoam);"
        << " the solver solving " << eqn.psi().name()
        << " is a compressible one" << nl << exit(FatalError);
}


bool Foam::fv::immersedBodiesSource::read(const dictionary& dict)
{
    if (!option::read(dict))
    {
        return false;
    }
    const wordList allowed({"type", "active", "log", "libs", typeName + "Coeffs"});
    immersedSpheroids::checkKeywords(dict, allowed);
    return true;
}


// ************************************************************************* //
