/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "collisionModel.H"
#include "processCpuTime.H"
#include "coreConversions.H"
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
    evaluations_(0),
    subStepCpu_(0),
    stepper_(new collision::SubStepper())
{}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::collisionModel::~collisionModel() = default;


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

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
