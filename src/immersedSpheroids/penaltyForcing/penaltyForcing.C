/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "penaltyForcing.H"
#include "wallPolyPatch.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"
#include "fixedValueFvPatchFields.H"
#include "syncTools.H"
#include "processCpuTime.H"
#include "cellSolidFraction.H"
#include "diagTensor.H"
#include "mathematicalConstants.H"

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


// * * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * //

const Foam::Enum<Foam::penaltyForcing::method>
Foam::penaltyForcing::methodNames
({
    { method::surfaceCorrected, "surfaceCorrected" },
    { method::cutCellFraction, "cutCellFraction" },
});


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::labelList Foam::penaltyForcing::fixedFluxPatches
(
    const fvMesh& mesh,
    const word& UName
)
{
    // A rigid-body velocity with a component through a boundary face cannot
    // be imposed in the cell behind it where the face's flux is prescribed:
    // wall patches, and any other patch whose velocity condition is a fixed
    // value (fixedValue and the conditions derived from it: an inlet). A
    // mixed condition such as inletOutlet leaves the outflow to the
    // pressure, and coupled, empty and wedge patches carry no such
    // condition; without the velocity field (a caller that has none
    // registered) only the wall patches are known.
    const volVectorField* U = mesh.findObject<volVectorField>(UName);
    DynamicList<label> patches;
    forAll(mesh.boundaryMesh(), patchi)
    {
        const polyPatch& pp = mesh.boundaryMesh()[patchi];
        const bool fixedVelocity =
            U && !pp.coupled() && !isA<emptyPolyPatch>(pp)
         && !isA<wedgePolyPatch>(pp)
         && isA<fixedValueFvPatchVectorField>(U->boundaryField()[patchi]);
        if (isA<wallPolyPatch>(pp) || fixedVelocity)
        {
            patches.append(patchi);
        }
    }
    return labelList(std::move(patches));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::penaltyForcing::penaltyForcing
(
    const fvMesh& mesh,
    const method forcing,
    const bool softWallCells,
    const bool softContactCells,
    const scalar softCellSteps,
    const scalar nu,
    const periodicDomain& domain,
    const word& UName
)
:
    mesh_(mesh),
    method_(forcing),
    softWallCells_(softWallCells),
    softContactCells_(softContactCells),
    softCellSteps_(softCellSteps),
    wallCell_(mesh.nCells(), false),
    cellRadius_(immersedSpheroids::cellRadii(mesh)),
    cellTree_(immersedSpheroids::cachedCellTree(mesh)),
    domain_(domain),
    linkReach_(2*returnReduce(max(cellRadius_), maxOp<scalar>())),
    cellsFound_(false),
    eta_(0),
    bodyStart_(1, 0),
    cellSlot_(mesh.nCells(), -1),
    inside_(mesh.nCells(), 0),
    solid_(mesh.nCells(), false),
    termBody_(mesh.nCells(), -1),
    cellCoeff_(mesh.nCells(), 0),
    cellAlpha_(mesh.nCells(), 0),
    cellHeld_(mesh.nCells(), 0),
    cpu_(0)
{
    for (const label patchi : fixedFluxPatches(mesh, UName))
    {
        for (const label celli : mesh.boundaryMesh()[patchi].faceCells())
        {
            wallCell_[celli] = true;
        }
    }
    if (method_ == method::surfaceCorrected)
    {
        links_.reset
        (
            new interfaceLinks
            (
                mesh, nu,
                softWallCells_ ? wallCell_ : boolList(mesh.nCells(), false)
            )
        );
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::penaltyForcing::collectCoveredCells
(
    const PtrList<immersedBody>& bodies
)
{
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
            alphaVelocity[slot] +=
                fractions[i]*body.state().velocityAt(C[celli] - body.cellShift(i));
            slots[i] = slot;
        }
    }

    cells_.transfer(cells);
    alphaSum_.transfer(alphaSum);
    velocity_.transfer(alphaVelocity);
    velocity_ /= alphaSum_;
}


void Foam::penaltyForcing::addCutCellTerms
(
    const PtrList<immersedBody>& bodies,
    const scalar eta,
    const scalar dt,
    const scalar ddtCoeff
)
{
    const vectorField& C = mesh_.C().primitiveField();
    forAll(bodies, bodyi)
    {
        const immersedBody& body = bodies[bodyi];
        const DynamicList<label>& bodyCells = body.cells();
        const DynamicList<scalar>& fractions = body.fractions();
        const labelList& slots = bodySlots_[bodyi];
        forAll(bodyCells, i)
        {
            // k = alpha/(eta + (1 - alpha) dt/c): the implicit step gives
            // U = alpha U_s + (1 - alpha) U* + O(eta/dt) in a cut cell, so
            // the penalty carries the inertia of the fluid volume alpha V
            const label celli = bodyCells[i];
            const label s = slots[i];
            const scalar alpha = min(alphaSum_[s], scalar(1));
            const scalar k =
                alpha/(cellEta(celli, eta, dt, ddtCoeff) + (1 - alpha)*dt/ddtCoeff);
            penaltyTerm term;
            term.cell = celli;
            term.coeff = k*fractions[i]/alphaSum_[s];
            term.shift = body.cellShift(i);
            term.source = term.coeff*body.state().velocityAt(C[celli] - term.shift);
            terms_.append(term);
        }
        bodyStart_[bodyi + 1] = terms_.size();
    }
}


void Foam::penaltyForcing::addSurfaceCorrectedTerms
(
    const PtrList<immersedBody>& bodies,
    const scalar eta,
    const scalar dt,
    const scalar ddtCoeff
)
{
    const vectorField& C = mesh_.C().primitiveField();

    // the cells whose centre is inside a body
    List<symmTensor> forms(bodies.size());
    forAll(bodies, bodyi)
    {
        const immersedBody& body = bodies[bodyi];
        forms[bodyi] = body.quadraticForm();
        forAll(body.cells(), i)
        {
            const label celli = body.cells()[i];
            const point X = body.state().centre + body.cellShift(i);
            if (immersedBody::levelSet(C[celli], X, forms[bodyi]) <= 0)
            {
                ++inside_[celli];
                solid_[celli] = true;
            }
        }
    }

    const scalar maxCoeff = 1/eta;
    const scalar maxWallCoeff =
        1/max(eta, softWallCells_ ? softCellSteps_*dt/ddtCoeff : eta);
    forAll(bodies, bodyi)
    {
        const immersedBody& body = bodies[bodyi];
        forAll(body.cells(), i)
        {
            const label celli = body.cells()[i];
            const vector& shift = body.cellShift(i);
            if (immersedBody::levelSet(C[celli], body.state().centre + shift, forms[bodyi]) <= 0)
            {
                penaltyTerm term;
                term.cell = celli;
                term.coeff =
                    1/(cellEta(celli, eta, dt, ddtCoeff)*inside_[celli]);
                term.shift = shift;
                term.source = term.coeff*body.state().velocityAt(C[celli] - shift);
                terms_.append(term);
            }
        }
        links_->append(body, solid_, wallCell_, maxCoeff, maxWallCoeff, terms_);
        bodyStart_[bodyi + 1] = terms_.size();
    }
    softenSharedCells(bodies.size(), dt, ddtCoeff);

    for (const immersedBody& body : bodies)
    {
        for (const label celli : body.cells())
        {
            inside_[celli] = 0;
            solid_[celli] = false;
        }
    }
}


void Foam::penaltyForcing::softenSharedCells
(
    const label nBodies,
    const scalar dt,
    const scalar ddtCoeff
)
{
    // A cell with the terms of two bodies (the fluid between two surfaces
    // less than about a cell apart, or a cell inside both) couples them
    // directly: its velocity is a weighted mean of the two, and the force
    // on each is its coefficient times their velocity difference. The body
    // update is explicit in that force; with a coefficient of 1/eta it
    // exceeds the bodies' inertia by about rho_f V_cell/(m eta) and the
    // relative motion of the pair grows step by step. There the terms are
    // capped at the fluid's own rate c/dt (direct forcing: the velocity is
    // imposed over about a step), as in the soft wall cells: the target
    // velocity of each term is kept, its strength is bounded.
    if (nBodies < 2)
    {
        return;
    }
    for (label bodyi = 0; bodyi < nBodies; ++bodyi)
    {
        for (const penaltyTerm& term : bodyTerms(bodyi))
        {
            label& owner = termBody_[term.cell];
            owner = owner == -1 || owner == bodyi ? bodyi : -2;
        }
    }
    if (softContactCells_)
    {
        markContactZone();
    }
    const scalar maxSharedCoeff = ddtCoeff/(softCellSteps_*dt);
    for (penaltyTerm& term : terms_)
    {
        if (termBody_[term.cell] == -2 && term.coeff > maxSharedCoeff)
        {
            const scalar scale = maxSharedCoeff/term.coeff;
            term.coeff *= scale;
            term.source *= scale;
        }
    }
    for (const penaltyTerm& term : terms_)
    {
        termBody_[term.cell] = -1;
    }
}


void Foam::penaltyForcing::markContactZone()
{
    // Two cells across a face that carry the terms of two different bodies
    // (the bodies touch or overlap between their centres) impose rigid
    // velocities whose normal components differ by the pair's approach
    // speed: the flux through the face cannot match both, and with stiff
    // terms the pressure resolving it is of order rho_f u_n h/eta, an
    // explicit coupling of the pair's relative motion far above the bodies'
    // inertia. Both cells are marked shared (-2) and so capped at c/dt.
    const labelUList& own = mesh_.faceOwner();
    const labelUList& nei = mesh_.faceNeighbour();
    const label nInternal = mesh_.nInternalFaces();
    labelList nbrBody;
    syncTools::swapBoundaryCellList(mesh_, termBody_, nbrBody);
    DynamicList<label> marked;
    for (const penaltyTerm& term : terms_)
    {
        const label celli = term.cell;
        const label bodyi = termBody_[celli];
        if (bodyi < 0)
        {
            continue;
        }
        for (const label facei : mesh_.cells()[celli])
        {
            const label other =
                facei < nInternal
              ? termBody_[own[facei] == celli ? nei[facei] : own[facei]]
              : nbrBody[facei - nInternal];
            if (other >= 0 && other != bodyi)
            {
                marked.append(celli);
                break;
            }
        }
    }
    for (const label celli : marked)
    {
        termBody_[celli] = -2;
    }
}


Foam::scalar Foam::penaltyForcing::cellEta
(
    const label celli,
    const scalar eta,
    const scalar dt,
    const scalar ddtCoeff
) const
{
    // In a cell with a face on a wall the rigid-body velocity cannot be
    // imposed when it has a component through the wall (a body touching or
    // overlapping the wall in a collision): the wall face admits no flux,
    // and a stiff penalty turns the conflict into a pressure of order
    // rho_f U dx/eta, 1/penaltyRatio times the fluid's inertial scale, that
    // pushes an approaching body off and sucks a receding one back
    // (measured in docs/immersedBodies.md, wall cells). There eta is at
    // least the fluid's own time scale dt/c (the strength of direct
    // forcing; times softCellSteps): U_s is imposed over about a step
    return
        softWallCells_ && wallCell_[celli]
      ? max(eta, softCellSteps_*dt/ddtCoeff)
      : eta;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::penaltyForcing::updateCells(PtrList<immersedBody>& bodies)
{
    for (immersedBody& body : bodies)
    {
        if (!cellsFound_ || body.motion().moves())
        {
            body.updateCells(mesh_, *cellTree_, cellRadius_, domain_, linkReach_);
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
    collectCoveredCells(bodies);

    terms_.clear();
    bodyStart_.setSize(bodies.size() + 1);
    bodyStart_ = 0;
    heldVolume_.setSize(bodies.size());
    heldVolume_ = 0;
    heldMoment_.setSize(bodies.size());
    heldMoment_ = Zero;
    if (!(eta > 0))
    {
        return;
    }
    if (method_ == method::surfaceCorrected)
    {
        addSurfaceCorrectedTerms(bodies, eta, dt, ddtCoeff);
    }
    else
    {
        addCutCellTerms(bodies, eta, dt, ddtCoeff);
    }
    computeHeld(bodies, dt, ddtCoeff);
}


void Foam::penaltyForcing::computeHeld
(
    const PtrList<immersedBody>& bodies,
    const scalar dt,
    const scalar ddtCoeff
)
{
    const scalarField& V = mesh_.V();
    const vectorField& C = mesh_.C().primitiveField();
    const scalar ddtRate = ddtCoeff/dt;

    for (const penaltyTerm& term : terms_)
    {
        cellCoeff_[term.cell] += term.coeff;
    }
    DynamicList<label> touched;
    DynamicList<vector> touchedShift;
    forAll(bodies, bodyi)
    {
        const immersedBody& body = bodies[bodyi];
        forAll(body.cells(), i)
        {
            cellAlpha_[body.cells()[i]] = body.fractions()[i];
        }
        touched.clear();
        touchedShift.clear();
        for (const penaltyTerm& term : bodyTerms(bodyi))
        {
            if (cellHeld_[term.cell] == 0)
            {
                touched.append(term.cell);
                touchedShift.append(term.shift);
            }
            cellHeld_[term.cell] += term.coeff/(cellCoeff_[term.cell] + ddtRate);
        }
        const point& X = body.state().centre;
        forAll(touched, t)
        {
            const label celli = touched[t];
            const scalar v = max(cellHeld_[celli] - cellAlpha_[celli], scalar(0))*V[celli];
            const vector r = C[celli] - touchedShift[t] - X;
            heldVolume_[bodyi] += v;
            heldMoment_[bodyi] += v*(magSqr(r)*symmTensor::I - sqr(r));
            cellHeld_[celli] = 0;
        }
        for (const label celli : body.cells())
        {
            cellAlpha_[celli] = 0;
        }

        // the Stokes layer the step sets moving beyond the held cells: the
        // momentum thickness 2 sqrt(nu dt/pi) of Stokes' first problem over
        // the tangential motion of the surface (translation: the largest of
        // the three axes; rotation: per body axis); once, on the master (the
        // held sums are added over the ranks)
        if (links_.valid() && Pstream::master())
        {
            const scalar delta =
                2*Foam::sqrt(links_->nu()*dt/constant::mathematical::pi);
            heldVolume_[bodyi] += delta*cmptMax(body.tangentialArea());
            const tensor R = body.state().R();
            const vector& B = body.tangentialMoment();
            heldMoment_[bodyi] +=
                delta*symm(R & diagTensor(B.x(), B.y(), B.z()) & R.T());
        }
    }
    for (const penaltyTerm& term : terms_)
    {
        cellCoeff_[term.cell] = 0;
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
    const scalarField& V = mesh_.V();
    const vectorField& C = mesh_.C().primitiveField();
    const point& X = body.state().centre;
    for (const penaltyTerm& term : bodyTerms(bodyi))
    {
        const vector f = V[term.cell]*(term.coeff*U[term.cell] - term.source);
        force += f;
        torque += (C[term.cell] - term.shift - X) ^ f;
    }
}


void Foam::penaltyForcing::linkForce
(
    const label bodyi,
    const immersedBody& body,
    const vectorField& U,
    vector& force,
    label& nLinks
) const
{
    force = Zero;
    nLinks = 0;
    const scalarField& V = mesh_.V();
    const vectorField& C = mesh_.C().primitiveField();
    const symmTensor A = body.quadraticForm();
    for (const penaltyTerm& term : bodyTerms(bodyi))
    {
        if (immersedBody::levelSet(C[term.cell], body.state().centre + term.shift, A) > 0)
        {
            force += V[term.cell]*(term.coeff*U[term.cell] - term.source);
            ++nLinks;
        }
    }
}


void Foam::penaltyForcing::addTo(fvVectorMatrix& source) const
{
    const double cpu0 = immersedSpheroids::processCpuTime();

    // -coeff U + source: the implicit part on the diagonal, the explicit
    // part in the matrix source (stored negated)
    scalarField& diag = source.diag();
    vectorField& su = source.source();
    const scalarField& V = mesh_.V();
    for (const penaltyTerm& term : terms_)
    {
        const scalar v = V[term.cell];
        diag[term.cell] -= term.coeff*v;
        su[term.cell] -= term.source*v;
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
