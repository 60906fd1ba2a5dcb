/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "fixedMotion.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bodyMotions
{
    defineTypeNameAndDebug(fixed, 0);
    addToRunTimeSelectionTable(bodyMotion, fixed, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyMotions::fixed::fixed(const word& type, const dictionary& dict)
:
    bodyMotion(type)
{
    immersedSpheroids::checkKeywords(dict, wordList({"type"}));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bodyMotions::fixed::initialise(bodyState& state, const scalar) const
{
    state.velocity = Zero;
    state.angularVelocity = Zero;
}


void Foam::bodyMotions::fixed::advance
(
    bodyState& state,
    const scalar,
    const scalar,
    const vector&,
    const vector&,
    const scalar,
    const vector&
) const
{
    state.velocity = Zero;
    state.angularVelocity = Zero;
}


// ************************************************************************* //
