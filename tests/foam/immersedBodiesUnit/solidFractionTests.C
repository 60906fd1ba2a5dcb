/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
Description
    1. Solid fraction (immersedBody::updateCells, cellSolidFraction.H).

    On uniform cubic meshes of the box [-0.32, 0.32]^3 (regions given
    coarse to fine, made by the run script), for a sphere (R 0.2), a
    prolate (0.25 0.1 0.1, aspect ratio 2.5) and an oblate (0.1 0.25 0.25,
    aspect ratio 0.4) spheroid, each at four placements (centre offsets that
    are not multiples of the cell size, one grid-aligned and three oblique
    orientations):
    - the body volume sum(alpha V) against 4/3 pi abc: never above it (the
      level set is convex, so its linear interpolant on the tetrahedra is
      above it and the clipped volume below the exact one), error within an
      a priori bound 2 (S/V) a_max (5/32) (h/b_min)^2, and falling at order
      >= 1.7 in h (mean of |error| over the placements, so that a lucky
      cancellation at one placement does not decide the order);
    - the cell list: fractions in (0, 1], no duplicates; every cell with all
      points inside gets exactly 1, no cell separated from the body by a
      support plane is listed (certificates independent of the library's
      level set: the rotation is built here with Rodrigues' formula);
    - on the smaller meshes, against a brute-force pass of
      cellSolidFraction over every cell: the same cells (the octree search
      and the Lipschitz shortcut miss nothing), the same fractions; and
      each cut cell's fraction against an independent reference (analytic
      chords of the ellipsoid integrated over the cell): within the a
      priori bound, the mean error falling at first order (the volume
      could be second order by cancellation with wrong cells);
    - bounds() against the analytic support of the ellipsoid, and the
      second moment sum(alpha V (x - X)(x - X)) against V/5 R diag(a^2) R^T
      (checks the orientation convention of the clipping).
\*---------------------------------------------------------------------------*/

#include "immersedBodiesTests.H"
#include "immersedBody.H"
#include "cellSolidFraction.H"
#include "diagTensor.H"
#include "mathematicalConstants.H"

using namespace testChecks;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

struct Shape
{
    const char* name;
    vector semiAxes;
};

struct Placement
{
    vector offset;
    vector axis;
    scalar angle;
};

//- Solid volume of the axis-aligned box [lo, hi] inside the ellipsoid
//  (d^T Ainv d < 1, d = x - X): the chord of the ellipsoid along z is
//  analytic, integrated over x and y by the midpoint rule on n x n points
//  (an independent reference for the fraction of a cube cell)
scalar boxSolidVolume
(
    const point& lo,
    const point& hi,
    const point& X,
    const tensor& Ainv,
    const label n
)
{
    const scalar dx = (hi.x() - lo.x())/n, dy = (hi.y() - lo.y())/n;
    const scalar a = Ainv.zz();
    scalar sum = 0;
    for (label i = 0; i < n; ++i)
    {
        const scalar x = lo.x() + (i + 0.5)*dx - X.x();
        for (label j = 0; j < n; ++j)
        {
            const scalar y = lo.y() + (j + 0.5)*dy - X.y();
            // a z^2 + 2 b z + c = 1, z = x_z - X_z
            const scalar b = Ainv.zx()*x + Ainv.zy()*y;
            const scalar c = Ainv.xx()*x*x + 2*Ainv.xy()*x*y + Ainv.yy()*y*y;
            const scalar disc = b*b - a*(c - 1);
            if (disc <= 0)
            {
                continue;
            }
            const scalar root = Foam::sqrt(disc);
            const scalar z1 = (-b - root)/a + X.z();
            const scalar z2 = (-b + root)/a + X.z();
            sum += max(min(z2, hi.z()) - max(z1, lo.z()), scalar(0));
        }
    }
    return sum*dx*dy;
}


//- Surface area of a spheroid: semi-axes (a b b), a along its axis
scalar spheroidArea(const vector& abc)
{
    const scalar pi = constant::mathematical::pi;
    const scalar a = abc.x(), b = abc.y();
    if (mag(a - b) < 1e-12*b)
    {
        return 4*pi*sqr(b);
    }
    if (a > b)
    {
        const scalar e = Foam::sqrt(1 - sqr(b/a));
        return 2*pi*sqr(b)*(1 + a/(b*e)*std::asin(e));
    }
    const scalar e = Foam::sqrt(1 - sqr(a/b));
    return 2*pi*sqr(b)*(1 + (1 - sqr(e))/e*std::atanh(e));
}

} // End anonymous namespace


void immersedBodiesTests::testSolidFraction
(
    const Time& runTime,
    const wordList& regions
)
{
    const scalar pi = constant::mathematical::pi;

    const List<Shape> shapes
    ({
        {"sphere", vector(0.2, 0.2, 0.2)},
        {"prolate", vector(0.25, 0.1, 0.1)},
        {"oblate", vector(0.1, 0.25, 0.25)}
    });
    // Centre offsets in no simple ratio to the cell sizes; the first
    // orientation is the identity (axes along the grid lines)
    const List<Placement> placements
    ({
        {vector(0.0123, -0.0071, 0.0042), vector(1, 0, 0), 0},
        {vector(-0.0157, 0.0093, 0.0188), vector(1, 2, 3), 0.7},
        {vector(0.0031, 0.0179, -0.0113), vector(-2, 1, 0.5), 1.9},
        {vector(-0.0066, -0.0142, -0.0017), vector(0.3, -1, 2), 2.6}
    });
    const dictionary motionDict(parse("type fixed;", "test/fixed"));

    const label nMeshes = regions.size();
    scalarField h(nMeshes);
    // err[meshi][shapei][placementi]: relative volume error
    List<List<scalarField>> err(nMeshes);
    // cellErr[meshi][shapei][placementi]: mean |alpha - alpha_ref| over the
    // cut cells (brute-force meshes only)
    List<List<scalarField>> cellErr(nMeshes);
    label nBruteMeshes = 0;

    forAll(regions, meshi)
    {
        polyMesh mesh
        (
            IOobject
            (
                regions[meshi],
                runTime.timeName(),
                runTime,
                IOobject::MUST_READ
            )
        );
        const scalarField& V = mesh.cellVolumes();
        const pointField& C = mesh.cellCentres();
        const pointField& pts = mesh.points();
        const labelListList& cellPoints = mesh.cellPoints();
        const label nCells = mesh.nCells();
        h[meshi] = Foam::cbrt(sum(V)/nCells);
        const scalarField cellRadius(immersedSpheroids::cellRadii(mesh));
        const autoPtr<indexedOctree<treeDataCell>> cellTree
        (
            immersedSpheroids::cachedCellTree(mesh)
        );
        const bool brute = nCells <= 40000;

        Info<< nl << "Mesh " << regions[meshi] << ": " << nCells
            << " cells, h = " << h[meshi]
            << (brute ? " (with brute-force comparison)" : "") << endl;

        err[meshi].setSize(shapes.size());
        cellErr[meshi].setSize(shapes.size());
        if (brute)
        {
            ++nBruteMeshes;
        }
        forAll(shapes, shapei)
        {
            const Shape& shape = shapes[shapei];
            const vector& abc = shape.semiAxes;
            const scalar exact = 4.0/3.0*pi*abc.x()*abc.y()*abc.z();
            err[meshi][shapei].setSize(placements.size());
            cellErr[meshi][shapei].setSize(placements.size(), 0);

            forAll(placements, placei)
            {
                const Placement& pl = placements[placei];
                const std::string what =
                    std::string(regions[meshi]) + " " + shape.name
                  + " placement " + std::to_string(placei);

                bodyState state;
                state.centre = pl.offset;
                state.orientation =
                    rotationQuaternion(pl.angle*pl.axis/mag(pl.axis));
                immersedBody body(shape.name, abc, 1000, state, motionDict);

                // The independent geometry: R from Rodrigues' formula
                const tensor R = rodrigues(pl.axis, pl.angle);
                const tensor P = R & diagTensor(sqr(abc.x()), sqr(abc.y()), sqr(abc.z())) & R.T();
                const tensor Ainv = R & diagTensor(1/sqr(abc.x()), 1/sqr(abc.y()), 1/sqr(abc.z())) & R.T();
                const point& X = pl.offset;

                body.updateCells
                (
                    mesh, *cellTree, cellRadius, periodicDomain(mesh), 0
                );
                const DynamicList<label>& cells = body.cells();
                const DynamicList<scalar>& fractions = body.fractions();

                // Volume
                scalar vol = 0;
                tensor S(Zero);
                forAll(cells, i)
                {
                    const scalar aV = fractions[i]*V[cells[i]];
                    vol += aV;
                    const vector r = C[cells[i]] - X;
                    S += aV*(r*r);
                }
                const scalar e = (vol - exact)/exact;
                err[meshi][shapei][placei] = e;

                // Convex level set: the clipped volume is never above the
                // exact one (up to round-off in the sum)
                check(e <= 1e-12, what + ": volume not above 4/3 pi abc (error " + str(e) + ")");

                // List sanity, and the cell-by-cell certificates
                labelList fractionOf(nCells, -1);
                bool fractionsOk = true, duplicates = false;
                forAll(cells, i)
                {
                    fractionsOk = fractionsOk && fractions[i] > 0 && fractions[i] <= 1;
                    duplicates = duplicates || fractionOf[cells[i]] >= 0;
                    fractionOf[cells[i]] = i;
                }

                label nInside = 0, nInsideWrong = 0, nSeparated = 0, nSeparatedListed = 0;
                label nBruteCells = 0, nFractionDiffer = 0, nCut = 0;
                scalar maxFractionDiff = 0, sumCellErr = 0, maxCellErr = 0;
                scalar refVolume = 0;
                for (label celli = 0; celli < nCells; ++celli)
                {
                    const labelList& cp = cellPoints[celli];
                    bool allInside = true;
                    for (const label pointi : cp)
                    {
                        const vector d = pts[pointi] - X;
                        allInside = allInside && (d & (Ainv & d)) < 1;
                    }
                    const vector dC = C[celli] - X;
                    bool separated = false;
                    if (mag(dC) > 0)
                    {
                        const vector n = dC/mag(dC);
                        const scalar support = Foam::sqrt(n & (P & n));
                        scalar nearest = GREAT;
                        for (const label pointi : cp)
                        {
                            nearest = min(nearest, n & (pts[pointi] - X));
                        }
                        separated = nearest > support;
                    }
                    const label i = fractionOf[celli];
                    if (allInside)
                    {
                        ++nInside;
                        if (i < 0 || fractions[i] != 1)
                        {
                            ++nInsideWrong;
                        }
                    }
                    if (separated)
                    {
                        ++nSeparated;
                        if (i >= 0)
                        {
                            ++nSeparatedListed;
                        }
                    }
                    if (brute)
                    {
                        const scalar aB = immersedSpheroids::cellSolidFraction
                        (
                            mesh, celli, X, body.quadraticForm()
                        );
                        const scalar aL = i >= 0 ? fractions[i] : 0;
                        if (aB > 0)
                        {
                            ++nBruteCells;
                        }
                        maxFractionDiff = max(maxFractionDiff, mag(aB - aL));
                        if (aB != aL)
                        {
                            ++nFractionDiffer;
                        }

                        // Against the analytic reference, in the cells
                        // neither entirely inside (exactly 1, checked
                        // above) nor separated from the body
                        if (!allInside && !separated)
                        {
                            point lo(GREAT, GREAT, GREAT), hi(-GREAT, -GREAT, -GREAT);
                            for (const label pointi : cp)
                            {
                                lo = min(lo, pts[pointi]);
                                hi = max(hi, pts[pointi]);
                            }
                            const scalar aRef =
                                boxSolidVolume(lo, hi, X, Ainv, 48)/V[celli];
                            if (aRef > 0 || aL > 0)
                            {
                                ++nCut;
                                sumCellErr += mag(aL - aRef);
                                maxCellErr = max(maxCellErr, mag(aL - aRef));
                                refVolume += aRef*V[celli];
                            }
                        }
                        else if (allInside)
                        {
                            refVolume += V[celli];
                        }
                    }
                }

                check
                (
                    fractionsOk && !duplicates,
                    what + ": " + std::to_string(cells.size())
                  + " listed cells, fractions in (0, 1], no duplicates"
                );
                check
                (
                    nInside > 0 && nInsideWrong == 0,
                    what + ": all " + std::to_string(nInside)
                  + " cells entirely inside have fraction exactly 1 ("
                  + std::to_string(nInsideWrong) + " do not)"
                );
                check
                (
                    nSeparated > 0 && nSeparatedListed == 0,
                    what + ": none of the " + std::to_string(nSeparated)
                  + " cells separated from the body by a support plane is listed ("
                  + std::to_string(nSeparatedListed) + " are)"
                );
                if (brute)
                {
                    // The same function on the same cell: identical values
                    check
                    (
                        nBruteCells == cells.size() && nFractionDiffer == 0,
                        what + ": brute force over all cells finds the same "
                      + std::to_string(nBruteCells) + " cells and fractions (max diff "
                      + str(maxFractionDiff) + ")"
                    );

                    // The reference itself: its body volume within 2e-4
                    // (midpoint rule on 48^2 chords per cell: O(1/48^2)
                    // but for the sqrt of the chord at the silhouette)
                    const scalar refErr = (refVolume - exact)/exact;
                    check
                    (
                        mag(refErr) < 2e-4,
                        what + ": the analytic-chord reference volume is exact to "
                      + str(refErr)
                    );

                    // Per cell: the interpolated surface lies within delta
                    // = 2 a_max (5/32) (h/b_min)^2 of the true one (see the
                    // volume bound below) over at most sqrt(2) h^2 of
                    // surface in a cube cell: |alpha - alpha_ref| <=
                    // sqrt(2) delta/h, plus 5e-3 for the reference (the
                    // chord is a square root at the silhouette: the
                    // midpoint rule errs by O(48^-1.5) = 3e-3 there)
                    const scalar cellBound =
                        std::sqrt(2.0)*2*cmptMax(abc)*(5.0/32.0)
                       *h[meshi]/sqr(cmptMin(abc)) + 5e-3;
                    cellErr[meshi][shapei][placei] = sumCellErr/max(nCut, 1);
                    check
                    (
                        nCut > 0 && maxCellErr <= cellBound,
                        what + ": " + std::to_string(nCut) + " cut cells, |alpha - alpha_ref|"
                        " mean " + str(cellErr[meshi][shapei][placei]) + ", max "
                      + str(maxCellErr) + " <= " + str(cellBound)
                    );
                }

                // bounds(): half-widths sqrt(P_ii) of the exact support
                const boundBox bb = body.bounds();
                const vector half(Foam::sqrt(P.xx()), Foam::sqrt(P.yy()), Foam::sqrt(P.zz()));
                check
                (
                    mag(bb.min() - (X - half)) < 1e-14 && mag(bb.max() - (X + half)) < 1e-14,
                    what + ": bounds() is the exact bounding box"
                );

                // Second moment on the finest mesh: midpoint quadrature error
                // (h^2/12 per axis, relative (h^2/12)/(b^2/5) = 0.4% at
                // h = 0.01, b = 0.1) plus the volume error; 2%
                if (meshi == nMeshes - 1)
                {
                    const tensor Sexact = (exact/5)*P;
                    const scalar relS = maxAbs(S - Sexact)/maxAbs(Sexact);
                    check
                    (
                        relS < 0.02,
                        what + ": second moment of alpha V = V/5 R diag(a^2) R^T"
                        " (rel. error " + str(relS) + ")"
                    );
                }
            }
        }

        Info<< "  volume errors (relative, per placement):" << endl;
        forAll(shapes, shapei)
        {
            Info<< "    " << shapes[shapei].name << ":";
            for (const scalar e : err[meshi][shapei])
            {
                Info<< ' ' << str(e).c_str();
            }
            Info<< endl;
        }
    }

    // Bound and order of the volume error
    Info<< nl << "Volume error, mean |error| over the placements:" << endl;
    forAll(shapes, shapei)
    {
        const vector& abc = shapes[shapei].semiAxes;
        const scalar bMin = cmptMin(abc);
        scalarField meanErr(nMeshes);
        forAll(regions, meshi)
        {
            meanErr[meshi] = average(mag(err[meshi][shapei]));
            Info<< "    " << shapes[shapei].name << " h = " << h[meshi]
                << ": " << str(meanErr[meshi]).c_str() << endl;

            // A priori bound. The tetrahedra of a cube cell (its centre, a
            // face centre, an edge) have circumradius^2 5h^2/16; linear
            // interpolation there overestimates psi by at most
            // (1/2)(5h^2/16) max|Hess psi|, and |Hess psi| <= 1/b_min^2 on
            // the surface (psi is a norm minus one); with |grad psi| >=
            // 1/a_max the surface moves in by at most delta = a_max (5/32)
            // (h/b_min)^2, the volume by at most area x delta. A factor 2
            // covers |Hess psi| growing as 1/rho inside the surface.
            // (Measured: 0.03 to 0.2 of it.)
            const scalar bound =
                2*spheroidArea(abc)/(4.0/3.0*pi*abc.x()*abc.y()*abc.z())
               *cmptMax(abc)*(5.0/32.0)*sqr(h[meshi]/bMin);
            forAll(placements, placei)
            {
                check
                (
                    mag(err[meshi][shapei][placei]) <= bound,
                    std::string(shapes[shapei].name) + " on " + regions[meshi]
                  + " placement " + std::to_string(placei)
                  + ": |volume error| " + str(mag(err[meshi][shapei][placei]))
                  + " <= 2 (S/V) a_max (5/32) (h/b_min)^2 = " + str(bound)
                );
            }
        }
        // Per cell the error is delta/h ~ h: first order. A fraction that
        // is wrong per cell but right on average (e.g. cutting the edges
        // at their midpoints instead of at the zero of the interpolant:
        // the body volume stays second order by cancellation) does not
        // converge per cell.
        for (label meshi = 0; meshi < nBruteMeshes - 1; ++meshi)
        {
            const scalar e1 = average(cellErr[meshi][shapei]);
            const scalar e2 = average(cellErr[meshi + 1][shapei]);
            const scalar p = order(e1, e2, h[meshi], h[meshi + 1]);
            check
            (
                p >= 0.8,
                std::string(shapes[shapei].name) + ": mean per-cell fraction error "
              + str(e1) + " at h = " + str(h[meshi]) + ", " + str(e2) + " at h = "
              + str(h[meshi + 1]) + ": order " + str(p) + " (>= 0.8, expected 1)"
            );
        }
        for (label meshi = 0; meshi < nMeshes - 1; ++meshi)
        {
            const scalar p =
                order(meanErr[meshi], meanErr[meshi + 1], h[meshi], h[meshi + 1]);
            // Second order is claimed (cellSolidFraction.H); 1.7 leaves room
            // for the variation with the placement left after averaging
            check
            (
                p >= 1.7,
                std::string(shapes[shapei].name) + ": observed order of the volume"
                " error between h = " + str(h[meshi]) + " and " + str(h[meshi + 1])
              + ": " + str(p) + " (>= 1.7)"
            );
        }
    }
}


// ************************************************************************* //
