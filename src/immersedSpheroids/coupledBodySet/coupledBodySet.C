/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "coupledBodySet.H"
#include "coreConversions.H"

#include <limits>

using namespace Foam::immersedSpheroids;

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coupledBodySet::coupledBodySet
(
    PtrList<immersedBody>& bodies,
    const scalar fluidDensity,
    const vector& g,
    const scalar virtualMass,
    const scalar filmGap,
    const scalar cellSize,
    const immersedSpheroids::ddtCoefficients& ddt,
    const scalar fluidDeltaT
)
:
    bodies_(bodies),
    fluidDensity_(fluidDensity),
    g_(g),
    virtualMass_(virtualMass),
    filmGap_(filmGap),
    cellSize_(cellSize),
    ddt_(ddt),
    fluidDeltaT_(fluidDeltaT)
{
    if (ddt_.c00 != 0 && fluidDeltaT_ <= 0)
    {
        FatalErrorInFunction
            << "A three-level time difference (c00 = " << ddt_.c00
            << ") needs the fluid step, given as " << fluidDeltaT_
            << " (it must be positive)" << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coupledBodySet::virtualInertia
(
    const label i,
    const bodyState& state,
    scalar& mass,
    vector& inertia
) const
{
    // C_v rho_f V plus the fluid outside the body that the last step's
    // forcing held to it, with their body-frame moments of inertia
    const immersedBody& body = bodies_[i];
    const scalar beta = virtualMass_*fluidDensity_/body.density();
    const tensor R = state.R();
    const symmTensor heldBody = symm(R.T() & body.heldInertia() & R);
    mass = beta*body.mass() + body.heldMass();
    inertia = beta*body.bodyInertia() + heldBody.diag();
}


Foam::vector Foam::coupledBodySet::externalForce(const label i) const
{
    const immersedBody& body = bodies_[i];
    return
        body.hydroForce() + (body.density() - fluidDensity_)*body.volume()*g_;
}


std::size_t Foam::coupledBodySet::size() const
{
    return bodies_.size();
}


std::string Foam::coupledBodySet::name(std::size_t i) const
{
    return bodies_[i].name();
}


collision::CollisionBody Foam::coupledBodySet::collisionBody
(
    std::size_t i,
    const collision::BodyState& s
) const
{
    const immersedBody& body = bodies_[i];
    collision::CollisionBody c
    {
        ellipsoids::Ellipsoid
        (
            toCore(body.semiAxes()), s.centre, s.orientation.normalized()
        )
    };
    c.velocity = s.velocity;
    c.angularVelocity = s.angularVelocity;
    c.movable = body.motion().moves();
    c.stationary = body.motion().frozen();
    c.filmGap = filmGap_;
    c.cellSize = cellSize_;
    c.externalForce = toCore(externalForce(i));
    scalar virtualMass = 0;
    vector virtualMoments = Zero;
    virtualInertia(i, toFoam(s), virtualMass, virtualMoments);
    c.mass =
        body.motion().isFreeInTranslation()
      ? body.mass() + virtualMass
      : std::numeric_limits<scalar>::infinity();
    c.inverseInertia.setZero();
    if (body.motion().isFreeInRotation())
    {
        c.inverseInertia =
            collision::inverseWorldInertia
            (
                s.orientation,
                toCore(body.bodyInertia() + virtualMoments)
            );
    }
    return c;
}


void Foam::coupledBodySet::advance
(
    std::size_t i,
    collision::BodyState& s,
    collision::Scalar t,
    collision::Scalar dt,
    const collision::Vec3& fc,
    const collision::Vec3& tc
) const
{
    const immersedBody& body = bodies_[i];
    if (!body.motion().moves())
    {
        return;
    }
    const vector Fc = toFoam(fc);
    const vector Tc = toFoam(tc);

    // m_v D(U) implicit on the left (c m_v) and lagged on the right, D the
    // fluid solve's time difference of the last step's velocity change
    // (held over the sub-steps like the force, so that sub-stepping does
    // not iterate the lag away); the collision force acts on m + c m_v
    // like every other force (class description)
    const scalar m = body.mass();
    const vector J = body.bodyInertia();
    bodyState state = toFoam(s);
    scalar virtualMass = 0;
    vector virtualInertia = Zero;
    this->virtualInertia(i, state, virtualMass, virtualInertia);
    const scalar addedMass = ddt_.c*virtualMass;
    const vector addedInertia = ddt_.c*virtualInertia;
    const tensor virtualWorld =
        toFoam(collision::worldInertia(s.orientation, toCore(virtualInertia)));

    vector impulse = (externalForce(i) + Fc)*dt;
    vector angularImpulse = (body.hydroTorque() + Tc)*dt;
    vector lagged = body.acceleration();
    vector angularLagged = body.angularAcceleration();
    if (ddt_.c00 != 0)
    {
        lagged += ddt_.c00*body.velocityIncrement()/fluidDeltaT_;
        angularLagged += ddt_.c00*body.angularVelocityIncrement()/fluidDeltaT_;
    }
    impulse += virtualMass*lagged*dt;
    angularImpulse += dt*(virtualWorld & angularLagged);

    body.motion().advance
    (
        state,
        t,
        dt,
        impulse,
        angularImpulse,
        m + addedMass,
        J + addedInertia
    );
    s = toCore(state);
}


// ************************************************************************* //
