/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "freeMotion.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"
#include "coreConversions.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bodyMotions
{
    defineTypeNameAndDebug(free, 0);
    addToRunTimeSelectionTable(bodyMotion, free, dictionary);
    addNamedToRunTimeSelectionTable(bodyMotion, free, dictionary, freeTranslation);
    addNamedToRunTimeSelectionTable(bodyMotion, free, dictionary, freeRotation);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyMotions::free::free(const word& type, const dictionary& dict)
:
    bodyMotion(type),
    translates_(type != "freeRotation"),
    rotates_(type != "freeTranslation")
{
    immersedSpheroids::checkKeywords(dict, wordList({"type"}));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bodyMotions::free::initialise(bodyState& state, const scalar) const
{
    if (!translates_)
    {
        state.velocity = Zero;
    }
    if (!rotates_)
    {
        state.angularVelocity = Zero;
    }
}


void Foam::bodyMotions::free::advance
(
    bodyState& state,
    const scalar,
    const scalar dt,
    const vector& impulse,
    const vector& angularImpulse,
    const scalar mass,
    const vector& bodyInertia
) const
{
    collision::BodyState s = immersedSpheroids::toCore(state);
    collision::advanceRigidBody
    (
        s,
        dt,
        immersedSpheroids::toCore(impulse),
        immersedSpheroids::toCore(angularImpulse),
        mass,
        immersedSpheroids::toCore(bodyInertia),
        translates_,
        rotates_
    );
    state = immersedSpheroids::toFoam(s);
}


// ************************************************************************* //
