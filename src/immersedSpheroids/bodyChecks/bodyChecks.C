/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "bodyChecks.H"
#include "indexedOctree.H"
#include "treeDataCell.H"
#include "cellSolidFraction.H"

#include <cstring>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The directions of the surface points checked by checkInsideMesh
const FixedList<vector, 6> directions
({
    vector(1, 0, 0), vector(-1, 0, 0), vector(0, 1, 0),
    vector(0, -1, 0), vector(0, 0, 1), vector(0, 0, -1)
});

const FixedList<word, 6> directionNames({"+x", "-x", "+y", "-y", "+z", "-z"});

//- FNV-1a over the bytes of a double
void hashScalar(uint64_t& h, const scalar v)
{
    unsigned char bytes[sizeof(scalar)];
    std::memcpy(bytes, &v, sizeof(scalar));
    for (const unsigned char b : bytes)
    {
        h ^= b;
        h *= 1099511628211ull;
    }
}

uint64_t bodyChecksum(const immersedBody& body)
{
    uint64_t h = 14695981039346656037ull;
    const bodyState& s = body.state();
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        hashScalar(h, s.centre[d]);
        hashScalar(h, s.velocity[d]);
        hashScalar(h, s.angularVelocity[d]);
        hashScalar(h, s.orientation.v()[d]);
    }
    hashScalar(h, s.orientation.w());
    return h;
}

//- Whether a 64-bit value differs between the ranks (one reduction for
//  all values: the largest of each 32-bit half and of its negative)
boolList differsBetweenRanks(const List<uint64_t>& values)
{
    scalarList extremes(4*values.size());
    forAll(values, i)
    {
        const scalar hi = scalar(values[i] >> 32);
        const scalar lo = scalar(values[i] & 0xffffffffull);
        extremes[4*i] = hi;
        extremes[4*i + 1] = lo;
        extremes[4*i + 2] = -hi;
        extremes[4*i + 3] = -lo;
    }
    Pstream::listCombineGather(extremes, maxEqOp<scalar>());
    Pstream::listCombineScatter(extremes);
    boolList differs(values.size());
    forAll(values, i)
    {
        differs[i] =
            extremes[4*i] != -extremes[4*i + 2]
         || extremes[4*i + 1] != -extremes[4*i + 3];
    }
    return differs;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::immersedSpheroids::checkInsideMesh
(
    const polyMesh& mesh,
    const periodicDomain& domain,
    const PtrList<immersedBody>& bodies,
    const string& when,
    const scalar wallOverlapCap
)
{
    const label nPoints = 1 + directions.size();
    // the depth beyond the boundary each checked point allows, over the
    // body's extent along its direction
    scalarList tolerance(nPoints*bodies.size(), outsideTolerance);
    List<point> points(nPoints*bodies.size());
    boolList found(points.size(), false);
    forAll(bodies, bodyi)
    {
        const immersedBody& body = bodies[bodyi];
        const point& c = body.state().centre;
        points[nPoints*bodyi] = c;
        const scalar wallDepth =
            wallOverlapMargin*wallOverlapCap*body.minSemiAxis();
        forAll(directions, k)
        {
            const vector extent = body.supportPoint(directions[k]) - c;
            scalar& tol = tolerance[nPoints*bodyi + 1 + k];
            tol = max(outsideTolerance, wallDepth/mag(extent));
            points[nPoints*bodyi + 1 + k] = c + (1 - tol)*extent;
        }
    }
    // each rank searches only the points within its own cells' bounds (a
    // box test first: the cell search is the costly part, done once a point).
    // The search's tet decomposition is built on first use by a collective
    // exchange: every rank builds it here, whether it searches or not
    (void)mesh.tetBasePtIs();
    const treeBoundBox& localBounds = mesh.cellTree().bb();
    forAll(points, i)
    {
        const point p = domain.wrap(points[i]);
        found[i] = localBounds.contains(p) && mesh.findCell(p) >= 0;
    }
    Pstream::listCombineGather(found, orEqOp<bool>());
    Pstream::listCombineScatter(found);

    forAll(bodies, bodyi)
    {
        const immersedBody& body = bodies[bodyi];
        if (!found[nPoints*bodyi])
        {
            FatalErrorInFunction
                << "Body '" << body.name() << "' is outside the mesh " << when.c_str()
                << ": its centre " << body.state().centre << " lies in no cell"
                << " (mesh bounds " << boundBox(mesh.points(), true)
                << "). A body must stay inside the mesh: give its centre (or"
                << " the packing's offset) a point of the mesh, and make every"
                << " boundary a body may reach a collision wall"
                << " (collision { walls (...); })" << nl << exit(FatalError);
        }
        forAll(directions, k)
        {
            if (!found[nPoints*bodyi + 1 + k])
            {
                FatalErrorInFunction
                    << "Body '" << body.name() << "' is partly outside the mesh "
                    << when.c_str() << ": its surface point farthest along "
                    << directionNames[k] << ", "
                    << body.supportPoint(directions[k]) << ", is beyond the"
                    << " boundary by more than "
                    << tolerance[nPoints*bodyi + 1 + k]
                    << " of its extent (centre " << body.state().centre
                    << ", mesh bounds "
                    << boundBox(mesh.points(), true)
                    << "): the cells beyond the boundary are missing, so the"
                    << " fluid sees only part of it. A body may overlap only a"
                    << " collision wall, by at most maxOverlap, or cross a"
                    << " cyclic patch pair on opposite faces of the box"
                    << " (periodic axes: " << domain.describe().c_str() << ")"
                    << nl << exit(FatalError);
            }
        }
    }
}


void Foam::immersedSpheroids::checkResolution
(
    const polyMesh& mesh,
    const PtrList<immersedBody>& bodies
)
{
    // the size of the cell holding each body's centre, on the rank that has it
    scalarList cellSize(bodies.size(), scalar(-1));
    const scalarField& V = mesh.cellVolumes();
    forAll(bodies, bodyi)
    {
        const label celli = mesh.findCell(bodies[bodyi].state().centre);
        if (celli >= 0)
        {
            cellSize[bodyi] = Foam::cbrt(V[celli]);
        }
    }
    Pstream::listCombineGather(cellSize, maxEqOp<scalar>());
    Pstream::listCombineScatter(cellSize);

    label coarse = 0;
    label coarsest = -1;
    scalar fewest = GREAT;
    forAll(bodies, bodyi)
    {
        const immersedBody& body = bodies[bodyi];
        const scalar h = cellSize[bodyi];
        if (!(h > 0))
        {
            continue;   // outside the mesh: checkInsideMesh reports it
        }
        const vector& s = body.semiAxes();
        const scalar dEq = 2*Foam::cbrt(s.x()*s.y()*s.z());
        const scalar cells = dEq/h;
        const scalar tolerance = 1 - cellsPerDiameterTolerance;
        if
        (
            cells < tolerance*minCellsPerDiameter
         || 2*body.minSemiAxis() < tolerance*h
        )
        {
            FatalErrorInFunction
                << "Body '" << body.name() << "' (semiAxes " << s
                << ") is too thin for the mesh: its equal-volume diameter "
                << dEq << " m spans " << cells << " cells and its smallest"
                << " diameter " << 2*body.minSemiAxis() << " m "
                << 2*body.minSemiAxis()/h << " cells of size " << h
                << " m (the cell at its centre). The fluid cannot see it: at"
                << " least " << minCellsPerDiameter << " cells per"
                << " equal-volume diameter and one across the smallest"
                << " diameter are needed (" << warnCellsPerDiameter
                << "-16 are validated)" << nl << exit(FatalError);
        }
        if (cells < tolerance*warnCellsPerDiameter)
        {
            ++coarse;
            if (cells < fewest)
            {
                fewest = cells;
                coarsest = bodyi;
            }
        }
    }
    if (coarse > 0)
    {
        WarningInFunction
            << coarse << " of " << bodies.size() << " bodies span fewer than "
            << warnCellsPerDiameter << " cells per equal-volume diameter (the"
            << " fewest: '" << bodies[coarsest].name() << "', " << fewest
            << " cells of size " << cellSize[coarsest] << " m): their forces are"
            << " coarse (" << warnCellsPerDiameter << "-16 cells per diameter"
            << " are validated, docs/immersedBodies.md)" << endl;
    }
}


uint64_t Foam::immersedSpheroids::stateChecksum
(
    const PtrList<immersedBody>& bodies
)
{
    uint64_t h = 14695981039346656037ull;
    for (const immersedBody& body : bodies)
    {
        h ^= bodyChecksum(body);
        h *= 1099511628211ull;
    }
    return h;
}


void Foam::immersedSpheroids::checkReplicatedState
(
    const PtrList<immersedBody>& bodies,
    const string& when
)
{
    if (!Pstream::parRun())
    {
        return;
    }
    if (!differsBetweenRanks(List<uint64_t>({stateChecksum(bodies)}))[0])
    {
        return;
    }
    List<uint64_t> perBody(bodies.size());
    forAll(bodies, bodyi)
    {
        perBody[bodyi] = bodyChecksum(bodies[bodyi]);
    }
    const label first = max(differsBetweenRanks(perBody).find(true), 0);
    FatalErrorInFunction
        << "The ranks hold different states of the bodies " << when.c_str()
        << " (first: body '" << bodies[first].name() << "', on this rank at "
        << bodies[first].state().centre << "). Every rank must hold the same"
        << " bodies: a restart must read processor*/<time>/uniform/"
        << "immersedBodies written by one run at one time" << nl
        << exit(FatalError);
}


// ************************************************************************* //
