/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "collisionModel.H"

#include <algorithm>
#include "processCpuTime.H"
#include "HashSet.H"
#include "coreConversions.H"
#include "pstreamWorkShare.H"
#include "collision/SubStepper.hpp"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(collisionModel, 0);
    defineRunTimeSelectionTable(collisionModel, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::collisionModel::collisionModel(const fvMesh& mesh)
:
    mesh_(mesh),
    interactingIslands_(0),
    islandBodies_(0),
    evaluatedBodies_(0),
    evaluations_(0),
    subStepCpu_(0),
    stepper_(new collision::SubStepper())
{}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::collisionModel::~collisionModel() = default;


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::collisionModel::tooManySubSteps
(
    const collision::BodySet& bodies,
    const std::vector<collision::BodyState>& states,
    const scalar dt,
    const std::string& what
) const
{
    // the body that sets the sub-step: the fastest (speed plus rotation at
    // its largest semi-axis)
    const std::vector<collision::CollisionBody> collisionBodies =
        bodies.collisionBodies(states);
    label fastest = 0;
    scalar speed = -1;
    for (std::size_t i = 0; i < collisionBodies.size(); ++i)
    {
        const collision::CollisionBody& b = collisionBodies[i];
        const scalar s =
            b.velocity.norm() + b.angularVelocity.norm()*b.shape.maxSemiAxis();
        if (b.movable && s > speed)
        {
            speed = s;
            fastest = label(i);
        }
    }
    FatalErrorInFunction
        << "Collision sub-steps of the step " << dt << " s: " << what.c_str()
        << nl << "    The fastest body is '"
        << bodies.name(fastest).c_str() << "' at "
        << immersedSpheroids::toFoam(states[fastest].centre) << ", "
        << mag(immersedSpheroids::toFoam(states[fastest].velocity))
        << " m/s and "
        << mag(immersedSpheroids::toFoam(states[fastest].angularVelocity))
        << " rad/s. If that speed is not physical, the run went wrong"
        << " before this step (bodies thrown apart, an unstable body:"
        << " see its time series); otherwise raise maxSubSteps ("
        << const_cast<collisionModel&>(*this).coreModel()->settings().maxSubSteps
        << ") in the collision dictionary or reduce deltaT" << nl
        << exit(FatalError);
}


const Foam::pstreamWorkShare* Foam::collisionModel::pstreamShare() const
{
    const collision::CollisionModel* core =
        const_cast<collisionModel&>(*this).coreModel();
    return
        core
      ? dynamic_cast<const pstreamWorkShare*>(core->workShare())
      : nullptr;
}


Foam::scalar Foam::collisionModel::collectiveCpu() const
{
    const pstreamWorkShare* share = pstreamShare();
    return share ? share->cpu() : 0;
}


void Foam::collisionModel::resetSubStepCpu()
{
    subStepCpu_ = 0;
    const pstreamWorkShare* share = pstreamShare();
    if (share)
    {
        share->resetCpu();
    }
}


Foam::label Foam::collisionModel::advance
(
    collision::BodySet& bodies,
    std::vector<collision::BodyState>& states,
    const scalar t,
    const scalar dt,
    const label minSubSteps,
    const std::vector<collision::BodyState>& referenceStates,
    vectorField& force,
    vectorField& torque
)
{
    collision::CollisionModel* model = coreModel();
    if (!model)
    {
        FatalErrorInFunction
            << "advance needs an active collision model" << exit(FatalError);
    }
    const double cpu0 = immersedSpheroids::processCpuTime();
    try
    {
        stepper_->stepIslands
        (
            bodies, states, *model, contactTime(dt), t, dt, minSubSteps,
            referenceStates
        );
    }
    catch (const collision::TooManySubSteps& err)
    {
        tooManySubSteps(bodies, states, dt, err.what());
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << "Collision step from time " << t << " s: " << err.what()
            << nl << exit(FatalError);
    }
    subStepCpu_ += immersedSpheroids::processCpuTime() - cpu0;

    // two evaluations a sub-step of each number of sub-steps the
    // interacting islands took (those with the same number step together)
    labelHashSet counts;
    interactingIslands_ = 0;
    islandBodies_ = 0;
    {
        const std::vector<char>& evaluated = model->evaluatedBodies();
        evaluatedBodies_ =
            evaluated.empty()
          ? label(states.size())
          : label(std::count(evaluated.begin(), evaluated.end(), 1));
    }
    for (const collision::Island& island : stepper_->islands())
    {
        if (island.interacts)
        {
            counts.insert(max(minSubSteps, label(island.subSteps)));
            ++interactingIslands_;
            islandBodies_ += label(island.bodies.size());
        }
    }
    for (const label n : counts)
    {
        evaluations_ += 2*n;
    }

    label most = 1;
    force.setSize(label(states.size()));
    torque.setSize(label(states.size()));
    forAll(force, i)
    {
        force[i] = immersedSpheroids::toFoam(stepper_->meanForce()[i]);
        torque[i] = immersedSpheroids::toFoam(stepper_->meanTorque()[i]);
        most = max(most, label(stepper_->subSteps()[i]));
    }
    return most;
}


void Foam::collisionModel::subStep
(
    collision::BodySet& bodies,
    std::vector<collision::BodyState>& states,
    const scalar t,
    const scalar dt,
    const scalar subDt,
    const std::vector<collision::BodyState>& referenceStates,
    vectorField& force,
    vectorField& torque
)
{
    collision::CollisionModel* model = coreModel();
    const double cpu0 = immersedSpheroids::processCpuTime();
    try
    {
        stepper_->step
        (
            bodies, states, model, contactTime(dt), t, subDt, referenceStates
        );
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << "Collision sub-step at time " << t << " s: " << err.what()
            << nl << exit(FatalError);
    }
    subStepCpu_ += immersedSpheroids::processCpuTime() - cpu0;
    if (model)
    {
        evaluations_ += 2;
    }
    force.setSize(label(states.size()));
    torque.setSize(label(states.size()));
    forAll(force, i)
    {
        force[i] = immersedSpheroids::toFoam(stepper_->force()[i]);
        torque[i] = immersedSpheroids::toFoam(stepper_->torque()[i]);
    }
}


// ************************************************************************* //
