/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).

Description
    The coupling steps of immersedBodies: forces, motion, cells, penalty.

\*---------------------------------------------------------------------------*/

#include "immersedBodies.H"
#include "coupledBodySet.H"
#include "coreConversions.H"
#include "processCpuTime.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::immersedBodies::computeForces(const volVectorField& U)
{
    const label nBodies = bodies_.size();
    const scalarField& V = mesh_.V();
    const vectorField& C = mesh_.C().primitiveField();
    const vectorField& u = U.primitiveField();

    // per body: penalty force, penalty torque, momentum, angular momentum
    // (rho_f applied after the reduction)
    List<scalar> sums(12*nBodies, Zero);

    forAll(bodies_, bodyi)
    {
        const immersedBody& body = bodies_[bodyi];
        const point& X = body.state().centre;
        const labelList& slots = bodySlots_[bodyi];
        const DynamicList<label>& cells = body.cells();
        const DynamicList<scalar>& fractions = body.fractions();

        vector F(Zero), T(Zero), P(Zero), L(Zero);
        forAll(cells, i)
        {
            const label celli = cells[i];
            const scalar alpha = fractions[i];
            const vector r = C[celli] - X;

            if (eta_ > 0)
            {
                // the cell's penalty force, shared between the bodies
                // covering it in proportion to alpha
                const label s = slots[i];
                const scalar share = alpha/penaltyAlphaSum_[s];
                const vector f =
                    (share*penaltyCoeff_[s]*V[celli])
                   *(u[celli] - penaltyVelocity_[s]);
                F += f;
                T += r ^ f;
            }

            const vector p = (alpha*V[celli])*u[celli];
            P += p;
            L += r ^ p;
        }

        SubList<scalar> out(sums, 12, 12*bodyi);
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            out[d] = F[d];
            out[3 + d] = T[d];
            out[6 + d] = P[d];
            out[9 + d] = L[d];
        }
    }

    // one reduction for all bodies; every rank gets the master's sums
    Pstream::listCombineGather(sums, plusEqOp<scalar>());
    Pstream::listCombineScatter(sums);

    forAll(bodies_, bodyi)
    {
        immersedBody& body = bodies_[bodyi];
        const label o = 12*bodyi;
        const vector F(sums[o], sums[o + 1], sums[o + 2]);
        const vector T(sums[o + 3], sums[o + 4], sums[o + 5]);
        const vector P(sums[o + 6], sums[o + 7], sums[o + 8]);
        const vector L(sums[o + 9], sums[o + 10], sums[o + 11]);

        vector hydroForce = fluidDensity_*F;
        vector hydroTorque = fluidDensity_*T;
        if (body.nFluidMomenta() > 0 && lastDeltaT_ > 0)
        {
            // rate of change of the momentum of the fluid inside the body
            // over the step that produced U, differenced as the fluid's ddt
            immersedSpheroids::ddtCoefficients ddt = solveDdt_;
            if (body.nFluidMomenta() < 2)
            {
                ddt = immersedSpheroids::ddtCoefficients();
            }
            hydroForce += fluidDensity_*ddt.derivative
            (
                P, body.fluidMomentum(), body.fluidMomentum0(), lastDeltaT_
            );
            hydroTorque += fluidDensity_*ddt.derivative
            (
                L, body.fluidAngularMomentum(), body.fluidAngularMomentum0(),
                lastDeltaT_
            );
        }
        if (debug)
        {
            Info<< "immersedBodies: " << body.name() << ": penalty force "
                << fluidDensity_*F << ", internal-fluid momentum "
                << fluidDensity_*P << ", hydrodynamic force " << hydroForce
                << endl;
        }
        body.setHydro(hydroForce, hydroTorque);
        body.pushFluidMomentum(P, L);
    }
}


void Foam::immersedBodies::advanceBodies(const scalar t0, const scalar dt)
{
    using immersedSpheroids::toCore;
    using immersedSpheroids::toFoam;

    const label nBodies = bodies_.size();
    coupledBodySet set(bodies_, fluidDensity_, g_, virtualMass_, collision_->filmGap());
    std::vector<collision::BodyState> states(nBodies);
    forAll(bodies_, i)
    {
        states[i] = toCore(bodies_[i].state());
    }

    const bool colliding = collision_->active();
    const label nSub =
        colliding
      ? max(subSteps_, collision_->subSteps(set, states, dt))
      : subSteps_;
    const scalar subDt = dt/nSub;

    // the states the hydrodynamic force of this step responded to (the
    // film correction)
    std::vector<collision::BodyState> referenceStates;
    if (colliding)
    {
        referenceStates = states;
    }

    vectorField Fc, Tc;
    vectorField FcMean(nBodies, Zero), TcMean(nBodies, Zero);
    for (label stepi = 0; stepi < nSub; ++stepi)
    {
        collision_->subStep
        (
            set, states, t0 + stepi*subDt, dt, subDt, referenceStates, Fc, Tc
        );
        FcMean += Fc/nSub;
        TcMean += Tc/nSub;
    }

    forAll(bodies_, i)
    {
        bodies_[i].state() = toFoam(states[i]);
    }
    if (colliding)
    {
        forAll(bodies_, i)
        {
            bodies_[i].setCollision(FcMean[i], TcMean[i]);
        }
        collision_->report(nSub);
    }
}


void Foam::immersedBodies::updateCells()
{
    for (immersedBody& body : bodies_)
    {
        if (!cellsFound_ || body.motion().moves())
        {
            body.updateCells(mesh_, cellRadius_);
        }
    }
    cellsFound_ = true;
}


void Foam::immersedBodies::assemblePenalty
(
    const scalar eta,
    const scalar dt,
    const scalar ddtCoeff
)
{
    eta_ = eta;

    for (const label celli : penaltyCells_)
    {
        cellSlot_[celli] = -1;
    }

    const vectorField& C = mesh_.C().primitiveField();

    DynamicList<label> cells;
    DynamicList<scalar> alphaSum;
    DynamicList<vector> alphaVelocity;

    forAll(bodies_, bodyi)
    {
        const immersedBody& body = bodies_[bodyi];
        const DynamicList<label>& bodyCells = body.cells();
        const DynamicList<scalar>& fractions = body.fractions();
        labelList& slots = bodySlots_[bodyi];
        slots.setSize(bodyCells.size());

        forAll(bodyCells, i)
        {
            const label celli = bodyCells[i];
            label& slot = cellSlot_[celli];
            if (slot < 0)
            {
                slot = cells.size();
                cells.append(celli);
                alphaSum.append(0);
                alphaVelocity.append(Zero);
            }
            alphaSum[slot] += fractions[i];
            alphaVelocity[slot] += fractions[i]*body.state().velocityAt(C[celli]);
            slots[i] = slot;
        }
    }

    penaltyCells_.transfer(cells);
    penaltyAlphaSum_.transfer(alphaSum);
    penaltyVelocity_.transfer(alphaVelocity);
    penaltyVelocity_ /= penaltyAlphaSum_;
    penaltyCoeff_.setSize(penaltyCells_.size());
    forAll(penaltyCoeff_, s)
    {
        // k = alpha/(eta + (1 - alpha) dt/c): the implicit step gives
        // U = alpha U_s + (1 - alpha) U* + O(eta/dt) in a cut cell, so the
        // penalty carries the inertia of the fluid volume alpha V
        //
        // In a cell with a face on a wall the rigid-body velocity cannot be
        // imposed when it has a component through the wall (a body touching
        // or overlapping the wall in a collision): the wall face admits no
        // flux, and a stiff penalty turns the conflict into a pressure of
        // order rho_f U dx/eta, 1/penaltyRatio times the fluid's inertial
        // scale, that pushes an approaching body off and sucks a receding
        // one back (measured in docs/immersedBodies.md, wall cells). There
        // eta is at least the fluid's own time scale dt/c (the strength of
        // direct forcing): U_s is imposed over about a step
        const scalar alpha = min(penaltyAlphaSum_[s], scalar(1));
        const scalar etaCell =
            softWallCells_ && wallCell_[penaltyCells_[s]]
          ? max(eta, dt/ddtCoeff)
          : eta;
        penaltyCoeff_[s] =
            eta > 0 ? alpha/(etaCell + (1 - alpha)*dt/ddtCoeff) : 0;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::immersedBodies::addPenalty(fvVectorMatrix& source) const
{
    const double cpu0 = immersedSpheroids::processCpuTime();
    if (updateIndex_ != mesh_.time().timeIndex())
    {
        FatalErrorInFunction
            << "immersedBodies::update(U) was not called in this time step"
            << " (time " << mesh_.time().timeName() << "): the penalty would"
            << " be that of the previous step" << nl << exit(FatalError);
    }

    // source = -(alpha/eta)(U - U_s): implicit part on the diagonal, the
    // explicit part (alpha/eta) U_s in the source (stored negated)
    scalarField& diag = source.diag();
    vectorField& su = source.source();
    const scalarField& V = mesh_.V();
    forAll(penaltyCells_, s)
    {
        const label celli = penaltyCells_[s];
        const scalar k = penaltyCoeff_[s]*V[celli];
        diag[celli] -= k;
        su[celli] -= k*penaltyVelocity_[s];
    }
    penaltyCpu_ += (immersedSpheroids::processCpuTime() - cpu0);
}


Foam::tmp<Foam::fvVectorMatrix>
Foam::immersedBodies::penalty(const volVectorField& U) const
{
    const double cpu0 = immersedSpheroids::processCpuTime();
    auto tsource = tmp<fvVectorMatrix>::New
    (
        U,
        dimVolume*U.dimensions()/dimTime
    );
    penaltyCpu_ += (immersedSpheroids::processCpuTime() - cpu0);   // the matrix; addPenalty times itself
    addPenalty(tsource.ref());
    return tsource;
}


Foam::tmp<Foam::volScalarField> Foam::immersedBodies::solidFraction() const
{
    auto talpha = tmp<volScalarField>::New
    (
        IOobject
        (
            "solidFraction",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh_,
        dimensionedScalar(dimless, Zero)
    );
    scalarField& alpha = talpha.ref().primitiveFieldRef();
    forAll(penaltyCells_, s)
    {
        alpha[penaltyCells_[s]] = min(penaltyAlphaSum_[s], scalar(1));
    }
    talpha.ref().correctBoundaryConditions();
    return talpha;
}


Foam::tmp<Foam::volVectorField> Foam::immersedBodies::bodyVelocity() const
{
    auto tUs = tmp<volVectorField>::New
    (
        IOobject
        (
            "bodyVelocity",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh_,
        dimensionedVector(dimVelocity, Zero)
    );
    vectorField& Us = tUs.ref().primitiveFieldRef();
    forAll(penaltyCells_, s)
    {
        Us[penaltyCells_[s]] = penaltyVelocity_[s];
    }
    tUs.ref().correctBoundaryConditions();
    return tUs;
}


// ************************************************************************* //
