/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "uniformBodyForce.H"
#include "dictionaryChecks.H"
#include "fvMatrices.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(uniformBodyForce, 0);
    addToRunTimeSelectionTable(option, uniformBodyForce, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fv::uniformBodyForce::readCoeffs()
{
    // Keywords of fv::option, fv::cellSetOption and this class
    const wordList allowed
    ({
        "type", "active", "log", "libs", typeName + "Coeffs",
        "selectionMode", "cellZone", "cellSet", "points",
        "timeStart", "duration",
        "fields", "acceleration"
    });
    immersedSpheroids::checkKeywords(dict_, allowed);
    if (&coeffs_ != &dict_)
    {
        immersedSpheroids::checkKeywords(coeffs_, allowed);
    }

    acceleration_ = immersedSpheroids::readChecked<vector>
    (
        coeffs_,
        "acceleration",
        "a vector (ax ay az): force per unit mass in m/s^2"
    );

    fieldNames_ = immersedSpheroids::readCheckedOrDefault<wordList>
    (
        coeffs_,
        "fields",
        wordList({"U"}),
        "a list of vector field names, e.g. (U)"
    );
    if (fieldNames_.empty())
    {
        immersedSpheroids::entryError
        (
            coeffs_,
            "fields",
            "is empty; expected at least one vector field name, e.g. (U)"
        );
    }
    applied_.setSize(fieldNames_.size(), false);
}


void Foam::fv::uniformBodyForce::addSource
(
    fvMatrix<vector>& eqn,
    const volScalarField* rhoPtr
)
{
    // fvMatrix sign convention: "eqn += Su" is source -= V Su
    const scalarField& V = mesh_.V();
    vectorField& source = eqn.source();

    if (rhoPtr)
    {
        const scalarField& rho = rhoPtr->primitiveField();
        for (const label celli : cells_)
        {
            source[celli] -= V[celli]*rho[celli]*acceleration_;
        }
    }
    else
    {
        for (const label celli : cells_)
        {
            source[celli] -= V[celli]*acceleration_;
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fv::uniformBodyForce::uniformBodyForce
(
    const word& name,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    cellSetOption(name, modelType, dict, mesh),
    acceleration_(Zero)
{
    readCoeffs();

    Info<< "    acceleration " << acceleration_ << " m/s^2 on "
        << returnReduce(cells_.size(), sumOp<label>()) << " cells" << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fv::uniformBodyForce::addSup
(
    fvMatrix<vector>& eqn,
    const label fieldi
)
{
    addSource(eqn, nullptr);
}


void Foam::fv::uniformBodyForce::addSup
(
    const volScalarField& rho,
    fvMatrix<vector>& eqn,
    const label fieldi
)
{
    addSource(eqn, &rho);
}


bool Foam::fv::uniformBodyForce::read(const dictionary& dict)
{
    if (cellSetOption::read(dict))
    {
        readCoeffs();
        return true;
    }
    return false;
}


// ************************************************************************* //
