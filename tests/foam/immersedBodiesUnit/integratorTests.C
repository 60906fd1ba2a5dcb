/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
Description
    5. One body integrator. A spinning prolate spheroid thrown at a sphere
    in vacuum (no fluid, no gravity; contact with friction), stepped twice:
    - as coupled runs step bodies: immersedBody objects in a coupledBodySet,
      island by island through the run-time selected collision model
      (collisionModel::advance);
    - as the core steps them: collision::RigidBody in a
      collision::RigidBodySet, collision::SubStepper::stepIslands.
    With no fluid every extra force of the coupled set is zero, so the two
    trajectories must agree exactly (same operations on the same numbers):
    any difference between the two paths' sub-step or rigid-body step fails
    the test. The bodies must touch (the contact changes both velocities)
    for the comparison to mean something.
\*---------------------------------------------------------------------------*/

#include "immersedBodiesTests.H"
#include "immersedBody.H"
#include "coupledBodySet.H"
#include "coreConversions.H"
#include "collisionModel.H"
#include "collision/CollisionModel.hpp"
#include "collision/RigidBody.hpp"
#include "collision/RigidBodySet.hpp"
#include "collision/SubStepper.hpp"

using namespace testChecks;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;
using namespace immersedBodiesTests;
using immersedSpheroids::toCore;

collision::RigidBody rigidCopy(const immersedBody& body)
{
    collision::RigidBody b;
    static_cast<collision::BodyState&>(b) = toCore(body.state());
    b.semiAxes = toCore(body.semiAxes());
    b.density = body.density();
    return b;
}

bool sameState(const collision::BodyState& a, const collision::BodyState& b)
{
    return
        a.centre == b.centre && a.velocity == b.velocity
     && a.angularVelocity == b.angularVelocity
     && a.orientation.coeffs() == b.orientation.coeffs();
}

} // End anonymous namespace


void immersedBodiesTests::testIntegrator(const fvMesh& mesh)
{
    PtrList<immersedBody> bodies(2);
    bodies.set
    (
        0,
        new immersedBody
        (
            "spheroid",
            parse
            (
                "semiAxes (0.002 0.001 0.001); density 7800; centre (0 0 0);"
                "axis (1 1 0); velocity (0.5 0.02 0); angularVelocity (0 0 30);"
                "motion { type free; }",
                "test/spheroid"
            )
        )
    );
    bodies.set
    (
        1,
        new immersedBody
        (
            "sphere",
            parse
            (
                "semiAxes (0.001 0.001 0.001); density 2500;"
                "centre (0.0032 0.0004 0); velocity (-0.3 0 0);"
                "motion { type free; }",
                "test/sphere"
            )
        )
    );
    const scalar dt = 1e-4;
    const dictionary properties = parse
    (
        "collision { type contact; restitution 0.8; friction 0.3;"
        " contactSteps 10; } filmStabilisation no;",
        "test/integrator"
    );

    // coupled: no fluid, no gravity, no virtual mass, no film
    const filmCorrection film(properties, mesh, 0, true);
    autoPtr<collisionModel> coupledModel =
        collisionModel::New(properties, mesh, film);
    coupledBodySet set(bodies, 0, Zero, 0, 0, 0);
    std::vector<collision::BodyState> states;
    for (const immersedBody& b : bodies)
    {
        states.push_back(toCore(b.state()));
    }

    // vacuum: the core's own
    collision::InteractionParameters laws;
    laws.contact.restitution = 0.8;
    laws.contact.friction = 0.3;
    collision::CollisionModel vacuumModel
    (
        collision::CollisionSettings(),
        collision::PairModel::New("springDashpot", laws),
        collision::WallModel::New("springDashpot", laws),
        {}
    );
    std::vector<collision::RigidBody> vacuum{rigidCopy(bodies[0]), rigidCopy(bodies[1])};
    collision::RigidBodySet vacuumSet(vacuum);
    std::vector<collision::BodyState> vacuumStates{vacuum[0], vacuum[1]};
    collision::SubStepper vacuumStepper;

    const collision::BodyState start0 = states[0], start1 = states[1];
    bool same = true;
    label maxSubSteps = 0;
    vectorField Fc, Tc;
    for (label stepi = 0; stepi < 80 && same; ++stepi)
    {
        const scalar t = stepi*dt;
        const label nSub = coupledModel->advance(set, states, t, dt, 1, {}, Fc, Tc);
        maxSubSteps = max(maxSubSteps, nSub);
        vacuumStepper.stepIslands(vacuumSet, vacuumStates, vacuumModel, 10*dt, t, dt, 1);
        label nVacuum = 1;
        for (const int n : vacuumStepper.subSteps())
        {
            nVacuum = max(nVacuum, label(n));
        }
        same = nVacuum == nSub;
        for (std::size_t i = 0; i < states.size(); ++i)
        {
            same = same && sameState(states[i], vacuumStates[i]);
        }
        if (!same)
        {
            Info<< "    the paths differ after step " << stepi << endl;
        }
    }
    const scalar dv0 = (states[0].velocity - start0.velocity).norm();
    const scalar dv1 = (states[1].velocity - start1.velocity).norm();
    const scalar dw0 = (states[0].angularVelocity - start0.angularVelocity).norm();
    Info<< "    velocity change by the contact: spheroid " << dv0 << " m/s, sphere "
        << dv1 << " m/s; spin change " << dw0 << " rad/s; up to " << maxSubSteps
        << " sub-steps" << endl;
    check
    (
        dv0 > 0.05 && dv1 > 0.2 && dw0 > 1 && maxSubSteps > 1,
        "integrator: the bodies touch (velocities and spin changed by the contact)"
    );
    check
    (
        same,
        "integrator: coupled sub-steps (coupledBodySet, collisionModel) equal the"
        " core's vacuum stepIslands exactly"
    );
}


// ************************************************************************* //
