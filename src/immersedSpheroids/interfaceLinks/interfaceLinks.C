/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "interfaceLinks.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "syncTools.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The fraction t in (0, 1] of the segment from x0 (outside the ellipsoid
//  of centre c and quadratic form A) to x1 (inside) where it crosses the
//  surface: the smaller root of (x0 - c + t d)^T A (x0 - c + t d) = 1
scalar crossingFraction
(
    const point& x0,
    const point& x1,
    const point& c,
    const symmTensor& A
)
{
    const vector r0 = x0 - c;
    const vector d = x1 - x0;
    const vector Ad = A & d;
    const scalar a = d & Ad;
    const scalar b = r0 & Ad;                 // < 0: the segment enters
    const scalar c0 = (r0 & (A & r0)) - 1;    // > 0: x0 outside
    const scalar disc = max(b*b - a*c0, scalar(0));
    // the product of the roots is c0/a: the smaller one without cancellation
    const scalar t = c0/(Foam::sqrt(disc) - b);
    return min(max(t, scalar(0)), scalar(1));
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::interfaceLinks::interfaceLinks
(
    const fvMesh& mesh,
    const scalar nu,
    const boolList& softCell
)
:
    mesh_(mesh),
    nu_(nu),
    coupledSlot_(mesh.nBoundaryFaces(), -1),
    softCell_(softCell),
    visited_(mesh.nCells(), -1),
    stamp_(0)
{
    const surfaceScalarField& deltaCoeffs = mesh.nonOrthDeltaCoeffs();
    DynamicList<label> faces;
    DynamicList<point> across;
    DynamicList<scalar> weights;
    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& patch = mesh.boundary()[patchi];
        if (!patch.coupled())
        {
            continue;
        }
        // delta: from the cell centre to the centre of the cell across
        const vectorField delta(patch.delta());
        const vectorField Cc(patch.Cn());
        const scalarField& magSf = patch.magSf();
        const scalarField& dc = deltaCoeffs.boundaryField()[patchi];
        forAll(patch, i)
        {
            const label facei = patch.start() + i;
            coupledSlot_[facei - mesh.nInternalFaces()] = faces.size();
            faces.append(facei);
            across.append(Cc[i] + delta[i]);
            weights.append(magSf[i]*dc[i]);
        }
    }
    coupledFaces_.transfer(faces);
    boolList softAcross;
    syncTools::swapBoundaryCellList(mesh, softCell_, softAcross);
    acrossSoft_.setSize(coupledFaces_.size());
    forAll(coupledFaces_, slot)
    {
        acrossSoft_[slot] = softAcross[coupledFaces_[slot] - mesh.nInternalFaces()];
    }
    acrossCentres_.transfer(across);
    coupledWeights_.transfer(weights);

    if (acrossCentres_.size())
    {
        // the tree needs a box of non-zero width in every direction: the
        // centres across one processor patch lie in one plane. Grown by a
        // fraction of its size and of its distance from the origin (an
        // absolute tolerance is lost in the coordinates' rounding).
        treeBoundBox bb(acrossCentres_);
        const scalar grow =
            1e-6*(mag(bb.span()) + mag(bb.min()) + mag(bb.max())) + VSMALL;
        bb.min() -= point::uniform(grow);
        bb.max() += point::uniform(grow);
        acrossTree_.reset
        (
            new indexedOctree<treeDataPoint>
            (
                treeDataPoint(acrossCentres_), bb, 8, 10, 3.0
            )
        );
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::interfaceLinks::linkCell
(
    const label celli,
    const immersedBody& body,
    const symmTensor& A,
    const scalar maxCoeff,
    DynamicList<penaltyTerm>& terms
) const
{
    const vectorField& C = mesh_.C().primitiveField();
    const scalarField& magSf = mesh_.magSf().primitiveField();
    const scalarField& deltaCoeffs = mesh_.nonOrthDeltaCoeffs().primitiveField();
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    const point& X = body.state().centre;
    const DynamicList<vector>& images = body.images();
    const scalar nuByV = nu_/mesh_.V()[celli];

    for (const label facei : mesh_.cells()[celli])
    {
        point across;
        scalar weight;
        if (facei < mesh_.nInternalFaces())
        {
            const label other = own[facei] == celli ? nei[facei] : own[facei];
            if (softCell_[other])
            {
                continue;
            }
            across = C[other];
            weight = magSf[facei]*deltaCoeffs[facei];
        }
        else
        {
            const label slot = coupledSlot_[facei - mesh_.nInternalFaces()];
            if (slot < 0 || acrossSoft_[slot])
            {
                continue;
            }
            across = acrossCentres_[slot];
            weight = coupledWeights_[slot];
        }
        // the image of the body whose inside holds the cell across (the
        // body itself unless the domain is periodic)
        label imagei = 0;
        while
        (
            imagei < images.size()
         && immersedBody::levelSet(across, X + images[imagei], A) > 0
        )
        {
            ++imagei;
        }
        if (imagei == images.size())
        {
            continue;
        }
        const vector& shift = images[imagei];

        const scalar theta = crossingFraction(C[celli], across, X + shift, A);
        const point wall = C[celli] + theta*(across - C[celli]);
        const vector Uw = body.state().velocityAt(wall - shift);
        const vector Uacross = body.state().velocityAt(across - shift);

        // -g nu (1/theta - 1) u_P + g nu (U_w/theta - U_s(C_N)), capped:
        // coeff theta = g nu (1 - theta), source theta = g nu (U_w - theta U_s)
        penaltyTerm term;
        term.cell = celli;
        term.shift = shift;
        const scalar g = nuByV*weight;
        if (g*(1 - theta) < maxCoeff*theta)
        {
            term.coeff = g*(1/theta - 1);
            term.source = g*(Uw/theta - Uacross);
        }
        else
        {
            // the centre of P is at the surface (to within the cap): the
            // cell is penalised towards the wall velocity
            term.coeff = maxCoeff;
            term.source = maxCoeff*Uw;
        }
        terms.append(term);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::interfaceLinks::append
(
    const immersedBody& body,
    const boolList& solid,
    const boolList& wallCell,
    const scalar maxCoeff,
    const scalar maxWallCoeff,
    DynamicList<penaltyTerm>& terms
)
{
    ++stamp_;
    const symmTensor A = body.quadraticForm();
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();

    auto visit = [&](const label celli)
    {
        if (!solid[celli] && visited_[celli] != stamp_)
        {
            visited_[celli] = stamp_;
            linkCell
            (
                celli, body, A,
                wallCell[celli] ? maxWallCoeff : maxCoeff,
                terms
            );
        }
    };

    for (const label celli : body.cells())
    {
        if (!solid[celli])
        {
            visit(celli);
            continue;
        }
        for (const label facei : mesh_.cells()[celli])
        {
            if (facei < mesh_.nInternalFaces())
            {
                visit(own[facei] == celli ? nei[facei] : own[facei]);
            }
        }
    }

    // fluid cells whose neighbour across a coupled face is in the body
    if (acrossTree_.valid())
    {
        const boundBox bb = body.bounds();
        for (const vector& shift : body.images())
        {
            const labelList found = acrossTree_->findBox
            (
                treeBoundBox(bb.min() + shift, bb.max() + shift)
            );
            for (const label slot : found)
            {
                visit(own[coupledFaces_[slot]]);
            }
        }
    }
}


// ************************************************************************* //
