/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "prescribedMotion.H"
#include "dictionaryChecks.H"
#include "Constant.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bodyMotions
{
    defineTypeNameAndDebug(prescribed, 0);
    addToRunTimeSelectionTable(bodyMotion, prescribed, dictionary);
}
}


// * * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * //

namespace
{

Foam::autoPtr<Foam::Function1<Foam::vector>> readFunction
(
    const Foam::dictionary& dict,
    const Foam::word& name
)
{
    using namespace Foam;
    if (!dict.found(name))
    {
        return autoPtr<Function1<vector>>
        (
            new Function1Types::Constant<vector>(name, vector::zero)
        );
    }
    // the Function1's own checks (e.g. a table's times out of order) name
    // neither the keyword nor the file: rethrown with both
    const bool throwing = FatalError.throwExceptions();
    const bool throwingIO = FatalIOError.throwExceptions();
    autoPtr<Function1<vector>> f;
    std::string problem;
    try
    {
        f = Function1<vector>::New(name, dict);
    }
    catch (const Foam::error& err)
    {
        problem = err.message();
    }
    FatalError.throwExceptions(throwing);
    FatalIOError.throwExceptions(throwingIO);
    if (!problem.empty())
    {
        immersedSpheroids::entryError
        (
            dict, name,
            "is not a valid function of time (a Function1 of vector: constant,"
            " table with increasing times, sine, ...): " + problem
        );
    }
    return f;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyMotions::prescribed::prescribed(const word& type, const dictionary& dict)
:
    bodyMotion(type),
    velocity_(readFunction(dict, "velocity")),
    angularVelocity_(readFunction(dict, "angularVelocity")),
    integrable_(true),
    frozen_
    (
        immersedSpheroids::readCheckedOrDefault<bool>
        (
            dict, "frozen", false,
            "yes or no (default no): keep the centre and orientation and"
            " impose only the velocities"
        )
    )
{
    // OpenFOAM v1912 implements Function1::integrate only for these types
    // (calling it on the others aborts; probing it is unsafe: the table's
    // integrationWeights corrupts the heap for an empty interval)
    static const wordHashSet integrable
    ({
        "constant", "uniform", "zero", "one", "polynomial",
        "table", "tableFile", "csvFile"
    });
    integrable_ = integrable.found(velocity_->type());

    immersedSpheroids::checkKeywords
    (
        dict,
        wordList
        ({
            "type", "velocity", "velocityCoeffs",
            "angularVelocity", "angularVelocityCoeffs", "frozen"
        })
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bodyMotions::prescribed::initialise(bodyState& state, const scalar t) const
{
    state.velocity = velocity_->value(t);
    state.angularVelocity = angularVelocity_->value(t);
}


void Foam::bodyMotions::prescribed::advance
(
    bodyState& state,
    const scalar t,
    const scalar dt,
    const vector&,
    const vector&,
    const scalar,
    const vector&
) const
{
    state.velocity = velocity_->value(t + dt);
    state.angularVelocity = angularVelocity_->value(t + dt);
    if (frozen_)
    {
        return;
    }
    if (integrable_)
    {
        state.centre += velocity_->integrate(t, t + dt);
    }
    else
    {
        state.centre +=
            dt/6
           *(
                velocity_->value(t)
              + 4*velocity_->value(t + 0.5*dt)
              + velocity_->value(t + dt)
            );
    }
    const vector omegaMid = angularVelocity_->value(t + 0.5*dt);
    state.orientation = rotationQuaternion(dt*omegaMid)*state.orientation;
    state.orientation.normalize();
}


// ************************************************************************* //
