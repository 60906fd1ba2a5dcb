/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "cellSolidFraction.H"
#include "Random.H"
#include "immersedBody.H"

// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

inline scalar tetVolume(const point& a, const point& b, const point& c, const point& d)
{
    return mag((b - a) & ((c - a) ^ (d - a)))/6;
}

inline point cut(const point& a, const point& b, const scalar sa, const scalar sb)
{
    // the zero of the linear interpolant on the edge a-b (sa, sb of opposite signs)
    return a + (sa/(sa - sb))*(b - a);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::immersedSpheroids::tetInsideVolume
(
    const FixedList<point, 4>& p,
    const FixedList<scalar, 4>& s
)
{
    label inside[4], outside[4];
    label nIn = 0, nOut = 0;
    for (label i = 0; i < 4; ++i)
    {
        if (s[i] < 0)
        {
            inside[nIn++] = i;
        }
        else
        {
            outside[nOut++] = i;
        }
    }

    if (nIn == 0)
    {
        return 0;
    }
    const scalar V = tetVolume(p[0], p[1], p[2], p[3]);
    if (nIn == 4)
    {
        return V;
    }
    if (nIn == 1)
    {
        // a corner tetrahedron: product of the edge parameters
        const label i = inside[0];
        scalar f = 1;
        for (label k = 0; k < 3; ++k)
        {
            const label j = outside[k];
            f *= s[i]/(s[i] - s[j]);
        }
        return V*f;
    }
    if (nIn == 3)
    {
        // the complement of the outside corner tetrahedron
        const label o = outside[0];
        scalar f = 1;
        for (label k = 0; k < 3; ++k)
        {
            const label j = inside[k];
            f *= s[o]/(s[o] - s[j]);
        }
        return V*(1 - f);
    }

    // two inside (a, b), two outside (c, d): a convex wedge with vertices
    // a, b and the four cut points, split into three tetrahedra from a
    const label a = inside[0], b = inside[1], c = outside[0], d = outside[1];
    const point pac = cut(p[a], p[c], s[a], s[c]);
    const point pad = cut(p[a], p[d], s[a], s[d]);
    const point pbc = cut(p[b], p[c], s[b], s[c]);
    const point pbd = cut(p[b], p[d], s[b], s[d]);
    return
        tetVolume(p[a], p[b], pbc, pbd)
      + tetVolume(p[a], pac, pad, pbd)
      + tetVolume(p[a], pac, pbd, pbc);
}


Foam::scalar Foam::immersedSpheroids::cellSolidFraction
(
    const polyMesh& mesh,
    const label celli,
    const point& centre,
    const symmTensor& A
)
{
    const point& C = mesh.cellCentres()[celli];
    const scalar sC = immersedBody::levelSet(C, centre, A);
    const pointField& pts = mesh.points();

    scalar total = 0, inside = 0;
    FixedList<point, 4> tet;
    FixedList<scalar, 4> val;
    tet[0] = C;
    val[0] = sC;
    for (const label facei : mesh.cells()[celli])
    {
        const face& f = mesh.faces()[facei];
        tet[1] = mesh.faceCentres()[facei];
        val[1] = immersedBody::levelSet(tet[1], centre, A);
        scalar sPrev = immersedBody::levelSet(pts[f.last()], centre, A);
        point pPrev = pts[f.last()];
        for (const label pointi : f)
        {
            const point& q = pts[pointi];
            const scalar sq = immersedBody::levelSet(q, centre, A);
            tet[2] = pPrev;
            tet[3] = q;
            val[2] = sPrev;
            val[3] = sq;
            total += tetVolume(tet[0], tet[1], tet[2], tet[3]);
            inside += tetInsideVolume(tet, val);
            pPrev = q;
            sPrev = sq;
        }
    }
    return total > 0 ? min(max(inside/total, scalar(0)), scalar(1)) : scalar(0);
}


Foam::tmp<Foam::scalarField> Foam::immersedSpheroids::cellRadii(const polyMesh& mesh)
{
    auto tr = tmp<scalarField>::New(mesh.nCells(), Zero);
    scalarField& r = tr.ref();
    const pointField& pts = mesh.points();
    const labelListList& cellPoints = mesh.cellPoints();
    forAll(r, celli)
    {
        const point& C = mesh.cellCentres()[celli];
        for (const label pointi : cellPoints[celli])
        {
            r[celli] = max(r[celli], mag(pts[pointi] - C));
        }
    }
    return tr;
}


Foam::autoPtr<Foam::indexedOctree<Foam::treeDataCell>>
Foam::immersedSpheroids::cachedCellTree(const polyMesh& mesh)
{
    // the bounds and octree parameters of polyMesh::cellTree
    treeBoundBox overallBb(mesh.points());
    Random rndGen(261782);
    overallBb = overallBb.extend(rndGen, 1e-4);
    overallBb.min() -= point::uniform(ROOTVSMALL);
    overallBb.max() += point::uniform(ROOTVSMALL);
    return autoPtr<indexedOctree<treeDataCell>>
    (
        new indexedOctree<treeDataCell>
        (
            treeDataCell(true, mesh, polyMesh::CELL_TETS),
            overallBb,
            8,      // maxLevel
            10,     // leafsize
            5.0     // duplicity
        )
    );
}


// ************************************************************************* //
