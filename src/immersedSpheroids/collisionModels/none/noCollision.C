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
    const scalar
)
:
    collisionModel(mesh)
{
    immersedSpheroids::checkKeywords(dict, wordList({"type"}));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::collisionModels::none::forces
(
    const PtrList<immersedBody>& bodies,
    const UList<bodyState>&,
    const scalar,
    const scalar,
    vectorField& force,
    vectorField& torque,
    const bool
)
{
    force.setSize(bodies.size());
    torque.setSize(bodies.size());
    force = Zero;
    torque = Zero;
}


void Foam::collisionModels::none::dampingForces
(
    const PtrList<immersedBody>& bodies,
    const UList<bodyState>&,
    const UList<bodyState>&,
    const UList<bodyState>&,
    const scalar,
    vectorField& force,
    vectorField& torque
)
{
    force.setSize(bodies.size());
    torque.setSize(bodies.size());
    force = Zero;
    torque = Zero;
}


// ************************************************************************* //
