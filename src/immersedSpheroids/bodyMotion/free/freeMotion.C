/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "freeMotion.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"
#include "diagTensor.H"

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


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::tensor Foam::bodyMotions::inverseWorldInertia
(
    const quaternion& q,
    const vector& bodyInertia
)
{
    const tensor R = q.R();
    const diagTensor invI(1/bodyInertia.x(), 1/bodyInertia.y(), 1/bodyInertia.z());
    return R & invI & R.T();
}


Foam::tensor Foam::bodyMotions::worldInertia
(
    const quaternion& q,
    const vector& bodyInertia
)
{
    const tensor R = q.R();
    const diagTensor I(bodyInertia.x(), bodyInertia.y(), bodyInertia.z());
    return R & I & R.T();
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
    if (translates_)
    {
        const vector U1 = state.velocity + impulse/mass;
        state.centre += 0.5*dt*(state.velocity + U1);
        state.velocity = U1;
    }
    else
    {
        state.velocity = Zero;
    }

    if (rotates_)
    {
        const quaternion& q0 = state.orientation;
        const vector L0 = worldInertia(q0, bodyInertia) & state.angularVelocity;
        const vector L1 = L0 + angularImpulse;
        // attitude at the middle of the step with the old angular velocity
        quaternion qHalf = rotationQuaternion(0.5*dt*state.angularVelocity)*q0;
        qHalf.normalize();
        const vector omegaHalf = inverseWorldInertia(qHalf, bodyInertia) & (L0 + 0.5*angularImpulse);
        quaternion q1 = rotationQuaternion(dt*omegaHalf)*q0;
        q1.normalize();
        state.orientation = q1;
        state.angularVelocity = inverseWorldInertia(q1, bodyInertia) & L1;
    }
    else
    {
        state.angularVelocity = Zero;
    }
}


// ************************************************************************* //
