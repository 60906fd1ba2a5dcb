/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "hydrodynamicLoads.H"

// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * * //

Foam::Istream& Foam::operator>>(Istream& is, bodyFluidSums& b)
{
    is  >> b.penaltyForce >> b.penaltyTorque >> b.momentum >> b.angularMomentum
        >> b.heldVolume >> b.heldMoment;
    return is;
}


Foam::Ostream& Foam::operator<<(Ostream& os, const bodyFluidSums& b)
{
    os  << b.penaltyForce << token::SPACE << b.penaltyTorque << token::SPACE
        << b.momentum << token::SPACE << b.angularMomentum << token::SPACE
        << b.heldVolume << token::SPACE << b.heldMoment;
    return os;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::hydrodynamicLoads::update
(
    PtrList<immersedBody>& bodies,
    const penaltyForcing& forcing,
    const volVectorField& U,
    const scalar fluidDensity,
    const immersedSpheroids::ddtCoefficients& solveDdt,
    const scalar lastDeltaT,
    const bool debug
)
{
    const fvMesh& mesh = U.mesh();
    const scalarField& V = mesh.V();
    const vectorField& C = mesh.C().primitiveField();
    const vectorField& u = U.primitiveField();

    sums_.setSize(bodies.size());
    forAll(bodies, bodyi)
    {
        const immersedBody& body = bodies[bodyi];
        const point& X = body.state().centre;
        const DynamicList<label>& cells = body.cells();
        const DynamicList<scalar>& fractions = body.fractions();

        bodyFluidSums& s = sums_[bodyi];
        s = bodyFluidSums();
        forcing.bodyForce(bodyi, body, u, s.penaltyForce, s.penaltyTorque);
        forcing.held(bodyi, body, s.heldVolume, s.heldMoment);
        forAll(cells, i)
        {
            const label celli = cells[i];
            const vector p = (fractions[i]*V[celli])*u[celli];
            s.momentum += p;
            s.angularMomentum += (C[celli] - body.cellShift(i) - X) ^ p;
        }
    }

    // one reduction for all bodies; every rank gets the master's sums
    Pstream::listCombineGather(sums_, plusEqOp<bodyFluidSums>());
    Pstream::listCombineScatter(sums_);

    forAll(bodies, bodyi)
    {
        immersedBody& body = bodies[bodyi];
        const bodyFluidSums& s = sums_[bodyi];

        vector force = fluidDensity*s.penaltyForce;
        vector torque = fluidDensity*s.penaltyTorque;
        if (body.nFluidMomenta() > 0 && lastDeltaT > 0)
        {
            // rate of change of the momentum of the fluid inside the body
            // over the step that produced U, differenced as the fluid's ddt
            immersedSpheroids::ddtCoefficients ddt = solveDdt;
            if (body.nFluidMomenta() < 2)
            {
                ddt = immersedSpheroids::ddtCoefficients();
            }
            force += fluidDensity*ddt.derivative
            (
                s.momentum, body.fluidMomentum(), body.fluidMomentum0(),
                lastDeltaT
            );
            torque += fluidDensity*ddt.derivative
            (
                s.angularMomentum, body.fluidAngularMomentum(),
                body.fluidAngularMomentum0(), lastDeltaT
            );
        }
        if (debug)
        {
            // the links' part, summed over the ranks (diagnostic only)
            vector links(Zero);
            label nLinks = 0;
            forcing.linkForce(bodyi, body, u, links, nLinks);
            reduce(links, sumOp<vector>());
            reduce(nLinks, sumOp<label>());
            Info<< "immersedBodies: " << body.name() << ": penalty force "
                << fluidDensity*s.penaltyForce << " (links " << fluidDensity*links
                << " from " << nLinks << " terms of "
                << returnReduce(forcing.bodyTerms(bodyi).size(), sumOp<label>())
                << "), internal-fluid momentum "
                << fluidDensity*s.momentum << ", hydrodynamic force " << force
                << endl;
        }
        body.setHydro(force, torque);
        body.setHeld(fluidDensity*s.heldVolume, fluidDensity*s.heldMoment);
        body.pushFluidMomentum(s.momentum, s.angularMomentum);
    }
}


// ************************************************************************* //
