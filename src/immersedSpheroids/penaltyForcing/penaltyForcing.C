/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "penaltyForcing.H"
#include "wallPolyPatch.H"
#include "processCpuTime.H"
#include "cellSolidFraction.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- A zero field of the mesh for output (not registered, not written)
template<class Type>
Foam::tmp<Foam::GeometricField<Type, Foam::fvPatchField, Foam::volMesh>>
zeroField
(
    const Foam::fvMesh& mesh,
    const Foam::word& name,
    const Foam::dimensionSet& dims
)
{
    using namespace Foam;
    return tmp<GeometricField<Type, fvPatchField, volMesh>>::New
    (
        IOobject
        (
            name,
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh,
        dimensioned<Type>(dims, Zero)
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::penaltyForcing::penaltyForcing
(
    const fvMesh& mesh,
    const bool softWallCells
)
:
    mesh_(mesh),
    softWallCells_(softWallCells),
    wallCell_(mesh.nCells(), false),
    cellRadius_(immersedSpheroids::cellRadii(mesh)),
    cellsFound_(false),
    eta_(0),
    cellSlot_(mesh.nCells(), -1),
    cpu_(0)
{
    forAll(mesh.boundaryMesh(), patchi)
    {
        const polyPatch& pp = mesh.boundaryMesh()[patchi];
        if (isA<wallPolyPatch>(pp))
        {
            for (const label celli : pp.faceCells())
            {
                wallCell_[celli] = true;
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::penaltyForcing::updateCells(PtrList<immersedBody>& bodies)
{
    for (immersedBody& body : bodies)
    {
        if (!cellsFound_ || body.motion().moves())
        {
            body.updateCells(mesh_, cellRadius_);
        }
    }
    cellsFound_ = true;
}


void Foam::penaltyForcing::assemble
(
    const PtrList<immersedBody>& bodies,
    const scalar eta,
    const scalar dt,
    const scalar ddtCoeff
)
{
    eta_ = eta;

    for (const label celli : cells_)
    {
        cellSlot_[celli] = -1;
    }

    const vectorField& C = mesh_.C().primitiveField();

    DynamicList<label> cells;
    DynamicList<scalar> alphaSum;
    DynamicList<vector> alphaVelocity;

    bodySlots_.setSize(bodies.size());
    forAll(bodies, bodyi)
    {
        const immersedBody& body = bodies[bodyi];
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

    cells_.transfer(cells);
    alphaSum_.transfer(alphaSum);
    velocity_.transfer(alphaVelocity);
    velocity_ /= alphaSum_;
    coeff_.setSize(cells_.size());
    forAll(coeff_, s)
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
        const scalar alpha = min(alphaSum_[s], scalar(1));
        const scalar etaCell =
            softWallCells_ && wallCell_[cells_[s]]
          ? max(eta, dt/ddtCoeff)
          : eta;
        coeff_[s] = eta > 0 ? alpha/(etaCell + (1 - alpha)*dt/ddtCoeff) : 0;
    }
}


void Foam::penaltyForcing::bodyForce
(
    const label bodyi,
    const immersedBody& body,
    const vectorField& U,
    vector& force,
    vector& torque
) const
{
    force = Zero;
    torque = Zero;
    if (!(eta_ > 0))
    {
        return;
    }
    const scalarField& V = mesh_.V();
    const vectorField& C = mesh_.C().primitiveField();
    const point& X = body.state().centre;
    const labelList& slots = bodySlots_[bodyi];
    const DynamicList<label>& cells = body.cells();
    const DynamicList<scalar>& fractions = body.fractions();
    forAll(cells, i)
    {
        // the cell's penalty force, shared between the bodies covering it
        // in proportion to alpha
        const label celli = cells[i];
        const label s = slots[i];
        const scalar share = fractions[i]/alphaSum_[s];
        const vector f = (share*coeff_[s]*V[celli])*(U[celli] - velocity_[s]);
        force += f;
        torque += (C[celli] - X) ^ f;
    }
}


void Foam::penaltyForcing::addTo(fvVectorMatrix& source) const
{
    const double cpu0 = immersedSpheroids::processCpuTime();

    // source = -k (U - U_s): implicit part on the diagonal, the explicit
    // part k U_s in the source (stored negated)
    scalarField& diag = source.diag();
    vectorField& su = source.source();
    const scalarField& V = mesh_.V();
    forAll(cells_, s)
    {
        const label celli = cells_[s];
        const scalar k = coeff_[s]*V[celli];
        diag[celli] -= k;
        su[celli] -= k*velocity_[s];
    }
    cpu_ += (immersedSpheroids::processCpuTime() - cpu0);
}


Foam::tmp<Foam::fvVectorMatrix>
Foam::penaltyForcing::penalty(const volVectorField& U) const
{
    const double cpu0 = immersedSpheroids::processCpuTime();
    auto tsource = tmp<fvVectorMatrix>::New
    (
        U,
        dimVolume*U.dimensions()/dimTime
    );
    cpu_ += (immersedSpheroids::processCpuTime() - cpu0);   // the matrix; addTo times itself
    addTo(tsource.ref());
    return tsource;
}


Foam::tmp<Foam::volScalarField> Foam::penaltyForcing::solidFraction() const
{
    auto talpha = zeroField<scalar>(mesh_, "solidFraction", dimless);
    scalarField& alpha = talpha.ref().primitiveFieldRef();
    forAll(cells_, s)
    {
        alpha[cells_[s]] = min(alphaSum_[s], scalar(1));
    }
    talpha.ref().correctBoundaryConditions();
    return talpha;
}


Foam::tmp<Foam::volVectorField> Foam::penaltyForcing::bodyVelocity() const
{
    auto tUs = zeroField<vector>(mesh_, "bodyVelocity", dimVelocity);
    vectorField& Us = tUs.ref().primitiveFieldRef();
    forAll(cells_, s)
    {
        Us[cells_[s]] = velocity_[s];
    }
    tUs.ref().correctBoundaryConditions();
    return tUs;
}


// ************************************************************************* //
