/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "noCollision.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace collisionModels
{
    defineTypeNameAndDebug(none, 0);
    addToRunTimeSelectionTable(collisionModel, none, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::collisionModels::none::none
(
    const dictionary& dict,
    const fvMesh& mesh,
    const filmCorrection&
)
:
    collisionModel(mesh)
{
    immersedSpheroids::checkKeywords(dict, wordList({"type"}));
}


// ************************************************************************* //
