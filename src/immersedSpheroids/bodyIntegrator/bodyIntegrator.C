/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "bodyIntegrator.H"
#include "coupledBodySet.H"
#include "coreConversions.H"
#include "uniformDimensionedFields.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::vector Foam::bodyIntegrator::readGravity
(
    const fvMesh& mesh,
    const PtrList<immersedBody>& bodies
)
{
    bool needed = false;
    for (const immersedBody& body : bodies)
    {
        needed = needed || body.motion().isFreeInTranslation();
    }
    if (!needed)
    {
        return Zero;
    }

    IOobject gIO
    (
        "g",
        mesh.time().constant(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );
    if (!gIO.typeHeaderOk<uniformDimensionedVectorField>(true))
    {
        FatalErrorInFunction
            << "A body is free in translation, which needs gravity: the file "
            << gIO.objectPath() << " (uniformDimensionedVectorField g, e.g."
            << " value (0 0 -9.81);) is missing" << nl
            << exit(FatalError);
    }
    const uniformDimensionedVectorField g(gIO);
    if (g.dimensions() != dimAcceleration)
    {
        FatalIOErrorInFunction(gIO.objectPath())
            << "Entry 'dimensions' of " << gIO.objectPath()
            << " must be those of an acceleration " << dimAcceleration
            << ", not " << g.dimensions() << nl
            << exit(FatalIOError);
    }
    return g.value();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyIntegrator::bodyIntegrator
(
    const fvMesh& mesh,
    const dictionary& properties,
    const PtrList<immersedBody>& bodies,
    const scalar fluidDensity,
    const label subSteps,
    const scalar virtualMass,
    const filmCorrection& film
)
:
    fluidDensity_(fluidDensity),
    subSteps_(subSteps),
    virtualMass_(virtualMass),
    g_(readGravity(mesh, bodies)),
    collision_(collisionModel::New(properties, mesh, film))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bodyIntegrator::checkOverlaps
(
    PtrList<immersedBody>& bodies,
    const bool restarted
)
{
    const coupledBodySet set
    (
        bodies, fluidDensity_, g_, virtualMass_, collision_->filmGap(),
        collision_->cellSize()
    );
    std::vector<collision::BodyState> states;
    for (const immersedBody& body : bodies)
    {
        states.push_back(immersedSpheroids::toCore(body.state()));
    }
    collision_->checkOverlaps(set, states, restarted);
}


void Foam::bodyIntegrator::setVirtualMassAccelerations
(
    immersedBody& body,
    const collision::BodyState& end,
    const scalar dt,
    const immersedSpheroids::ddtCoefficients& ddt
)
{
    using immersedSpheroids::toFoam;

    if (!body.motion().moves())
    {
        return;
    }
    // the step's velocity change, the collision's included, and its
    // difference as the fluid solve of the next step takes it,
    // (c dU - c00 dU_last)/dt: the virtual-mass term of the next step
    // (coupledBodySet::advance)
    const bodyState& start = body.state();
    const vector dU = toFoam(end.velocity) - start.velocity;
    const vector dOmega =
        toFoam(end.angularVelocity) - start.angularVelocity;
    body.setAccelerations
    (
        (ddt.c*dU - ddt.c00*body.velocityIncrement())/dt,
        (ddt.c*dOmega - ddt.c00*body.angularVelocityIncrement())/dt,
        dU,
        dOmega
    );
}


void Foam::bodyIntegrator::advance
(
    PtrList<immersedBody>& bodies,
    const scalar t0,
    const scalar dt,
    const immersedSpheroids::ddtCoefficients& ddt
)
{
    using immersedSpheroids::toCore;
    using immersedSpheroids::toFoam;

    const label nBodies = bodies.size();
    coupledBodySet set
    (
        bodies, fluidDensity_, g_, virtualMass_, collision_->filmGap(),
        collision_->cellSize(), ddt, dt
    );
    std::vector<collision::BodyState> states(nBodies);
    forAll(bodies, i)
    {
        states[i] = toCore(bodies[i].state());
    }

    const bool colliding = collision_->active();
    vectorField FcMean(nBodies, Zero), TcMean(nBodies, Zero);
    label nSub = subSteps_;
    if (colliding)
    {
        // island by island; the states the hydrodynamic force of this step
        // responded to for the film correction
        const std::vector<collision::BodyState> referenceStates(states);
        nSub = collision_->advance
        (
            set, states, t0, dt, subSteps_, referenceStates, FcMean, TcMean
        );
    }
    else
    {
        const scalar subDt = dt/nSub;
        vectorField Fc, Tc;
        for (label stepi = 0; stepi < nSub; ++stepi)
        {
            collision_->subStep(set, states, t0 + stepi*subDt, dt, subDt, {}, Fc, Tc);
        }
    }

    forAll(bodies, i)
    {
        setVirtualMassAccelerations(bodies[i], states[i], dt, ddt);
        bodies[i].state() = toFoam(states[i]);
    }
    if (colliding)
    {
        forAll(bodies, i)
        {
            bodies[i].setCollision(FcMean[i], TcMean[i]);
        }
        collision_->report(nSub);
    }
}


// ************************************************************************* //
