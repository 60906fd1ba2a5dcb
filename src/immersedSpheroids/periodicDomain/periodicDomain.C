/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "periodicDomain.H"
#include "cyclicPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "processorPolyPatch.H"
#include "Pstream.H"
#include "SubField.H"

#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

const char* const axisNames[3] = {"x", "y", "z"};

//- The patches before the first processor patch (the same on every rank)
label nonProcessorPatches(const polyBoundaryMesh& bm)
{
    forAll(bm, patchi)
    {
        if (isA<processorPolyPatch>(bm[patchi]))
        {
            return patchi;
        }
    }
    return bm.size();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::periodicDomain::periodicDomain(const polyMesh& mesh)
:
    bounds_(mesh.bounds()),
    periodic_(false, false, false),
    period_(Zero),
    patchNames_(word::null)
{
    const polyBoundaryMesh& bm = mesh.boundaryMesh();
    const label n = nonProcessorPatches(bm);

    // per cyclic patch, over all ranks: the sum of its face area vectors,
    // its faces, and the box of its face centres (a processorCyclic patch's
    // faces count for the cyclic patch it refers to)
    List<vector> sumSf(n, Zero);
    labelList nFaces(n, 0);
    List<point> ctrMin(n, point::uniform(GREAT));
    List<point> ctrMax(n, point::uniform(-GREAT));
    auto add = [&](const label cyclici, const polyPatch& pp)
    {
        nFaces[cyclici] += pp.size();
        forAll(pp, facei)
        {
            sumSf[cyclici] += pp.faceAreas()[facei];
            ctrMin[cyclici] = min(ctrMin[cyclici], pp.faceCentres()[facei]);
            ctrMax[cyclici] = max(ctrMax[cyclici], pp.faceCentres()[facei]);
        }
    };
    forAll(bm, patchi)
    {
        const polyPatch& pp = bm[patchi];
        if (isA<processorCyclicPolyPatch>(pp))
        {
            add(refCast<const processorCyclicPolyPatch>(pp).referPatchID(), pp);
        }
        else if (patchi < n && isA<cyclicPolyPatch>(pp))
        {
            add(patchi, pp);
        }
    }
    Pstream::listCombineGather(sumSf, plusEqOp<vector>());
    Pstream::listCombineScatter(sumSf);
    Pstream::listCombineGather(nFaces, plusEqOp<label>());
    Pstream::listCombineScatter(nFaces);
    Pstream::listCombineGather(ctrMin, minEqOp<point>());
    Pstream::listCombineScatter(ctrMin);
    Pstream::listCombineGather(ctrMax, maxEqOp<point>());
    Pstream::listCombineScatter(ctrMax);

    const vector span = bounds_.span();
    const scalar tol = 1e-6*mag(span);

    // a cyclic patch's axis and side of the box (-1 low, +1 high)
    auto placement = [&](const label patchi, direction& axis, label& side)
    {
        const vector& S = sumSf[patchi];
        axis = findMax(cmptMag(S));
        vector across(S);
        across[axis] = 0;
        const scalar off = mag(across);     // 0 for a plane normal to the axis
        side = 0;
        if (off <= 1e-6*mag(S) && ctrMax[patchi][axis] - ctrMin[patchi][axis] <= tol)
        {
            if (mag(ctrMin[patchi][axis] - bounds_.min()[axis]) <= tol)
            {
                side = -1;
            }
            else if (mag(ctrMax[patchi][axis] - bounds_.max()[axis]) <= tol)
            {
                side = 1;
            }
        }
        if (side == 0)
        {
            FatalErrorInFunction
                << "Cyclic patch '" << bm[patchi].name() << "' of mesh "
                << mesh.objectPath() << " is not a face of the mesh's bounding"
                << " box " << bounds_ << " normal to a coordinate axis (its"
                << " face centres span " << ctrMin[patchi] << " to "
                << ctrMax[patchi] << ", its mean normal " << S/mag(S) << ")."
                << " Immersed bodies support translational periodicity of a"
                << " box along x, y and/or z: cyclic patches on opposite faces"
                << " of the box" << nl << exit(FatalError);
        }
    };

    for (label patchi = 0; patchi < n; ++patchi)
    {
        if (!isA<cyclicPolyPatch>(bm[patchi]) || nFaces[patchi] == 0)
        {
            continue;
        }
        const cyclicPolyPatch& cyc = refCast<const cyclicPolyPatch>(bm[patchi]);
        if (!cyc.owner())
        {
            continue;
        }
        direction axis, nbrAxis;
        label side, nbrSide;
        placement(patchi, axis, side);
        placement(cyc.neighbPatchID(), nbrAxis, nbrSide);
        if (nbrAxis != axis || nbrSide != -side)
        {
            FatalErrorInFunction
                << "Cyclic patches '" << cyc.name() << "' and '"
                << cyc.neighbPatchName() << "' of mesh " << mesh.objectPath()
                << " are not opposite faces of the mesh's bounding box "
                << bounds_ << " (normal to " << axisNames[axis] << " and "
                << axisNames[nbrAxis] << "): immersed bodies support"
                << " translational periodicity of the box only" << nl
                << exit(FatalError);
        }
        periodic_[axis] = true;
        period_[axis] = span[axis];
        patchNames_[axis] = cyc.name();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::point Foam::periodicDomain::wrap(const point& x) const
{
    point w(x);
    for (direction d = 0; d < 3; ++d)
    {
        if (!periodic_[d])
        {
            continue;
        }
        const scalar lo = bounds_.min()[d];
        w[d] -= std::floor((x[d] - lo)/period_[d])*period_[d];
        // the quotient's rounding can leave it just outside [lo, lo + L)
        if (w[d] >= lo + period_[d])
        {
            w[d] -= period_[d];
        }
        if (w[d] < lo)
        {
            w[d] += period_[d];
        }
    }
    return w;
}


void Foam::periodicDomain::images
(
    const boundBox& bb,
    const scalar reach,
    DynamicList<vector>& shifts
) const
{
    shifts.clear();
    shifts.append(Zero);
    if (!anyPeriodic())
    {
        return;
    }
    // the multiples -1, 0, 1 along each periodic axis (a wrapped body's box
    // reaches at most one period beyond the box)
    const label m[3] =
    {
        periodic_[0] ? 1 : 0, periodic_[1] ? 1 : 0, periodic_[2] ? 1 : 0
    };
    for (label i = -m[0]; i <= m[0]; ++i)
    {
        for (label j = -m[1]; j <= m[1]; ++j)
        {
            for (label k = -m[2]; k <= m[2]; ++k)
            {
                if (i == 0 && j == 0 && k == 0)
                {
                    continue;
                }
                const vector s
                (
                    i*period(0), j*period(1), k*period(2)
                );
                const vector grow(vector::uniform(reach));
                if (boundBox(bb.min() + s - grow, bb.max() + s + grow).overlaps(bounds_))
                {
                    shifts.append(s);
                }
            }
        }
    }
}


Foam::string Foam::periodicDomain::describe() const
{
    if (!anyPeriodic())
    {
        return "none";
    }
    string s;
    for (direction d = 0; d < 3; ++d)
    {
        if (periodic_[d])
        {
            s += (s.empty() ? "" : ", ") + string(axisNames[d]) + " (period "
                + Foam::name(period(d)) + ", patch " + patchNames_[d] + ")";
        }
    }
    return s;
}


// ************************************************************************* //
