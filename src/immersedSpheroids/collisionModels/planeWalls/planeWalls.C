/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "planeWalls.H"
#include "dictionaryChecks.H"
#include "coupledPolyPatch.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

std::vector<collision::PlaneWall> Foam::immersedSpheroids::planeWalls
(
    const fvMesh& mesh,
    const dictionary& dict,
    const word& keyword
)
{
    std::vector<collision::PlaneWall> walls;
    if (!dict.found(keyword))
    {
        return walls;
    }

    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    wordList candidates;
    for (const polyPatch& pp : patches)
    {
        if (!isA<coupledPolyPatch>(pp) && pp.type() != "empty")
        {
            candidates.append(pp.name());
        }
    }
    word allowed;
    for (const word& c : candidates)
    {
        allowed += (allowed.empty() ? "" : " ") + c;
    }

    const wordList names
    (
        readChecked<wordList>
        (
            dict, keyword,
            "a list of plane boundary patches, e.g. (bottom top); patches: ("
          + allowed + ")"
        )
    );

    // a patch named twice would act twice (its film and lubrication forces
    // doubled)
    wordHashSet named;
    for (const word& name : names)
    {
        if (!named.insert(name))
        {
            entryError
            (
                dict, keyword,
                "names '" + name + "' twice; each wall patch once: patches: ("
              + allowed + ")"
            );
        }
    }

    for (const word& name : names)
    {
        const label patchi = patches.findPatchID(name);
        if (patchi < 0 || !candidates.found(name))
        {
            entryError
            (
                dict, keyword,
                "names '" + name + "', which is not a non-coupled, non-empty"
                " boundary patch of the mesh; allowed: (" + allowed + ")"
            );
        }
        const polyPatch& pp = patches[patchi];
        const vectorField& Sf = pp.faceAreas();
        const vectorField& Cf = pp.faceCentres();

        // area-weighted plane, reduced over the ranks
        vector sumSf(Zero), sumACf(Zero);
        scalar sumA = 0;
        forAll(Sf, facei)
        {
            const scalar a = mag(Sf[facei]);
            sumSf += Sf[facei];
            sumACf += a*Cf[facei];
            sumA += a;
        }
        reduce(sumSf, sumOp<vector>());
        reduce(sumACf, sumOp<vector>());
        reduce(sumA, sumOp<scalar>());
        if (sumA <= 0)
        {
            entryError
            (
                dict, keyword,
                "names the patch '" + name + "', which has no faces"
            );
        }
        const vector n = sumSf/mag(sumSf);
        const point p = sumACf/sumA;

        // planarity: face normals and points
        scalar maxAngle = 0;
        forAll(Sf, facei)
        {
            maxAngle = max(maxAngle, mag(Sf[facei]/mag(Sf[facei]) ^ n));
        }
        boundBox bb(pp.localPoints(), true);
        scalar maxOffset = 0;
        for (const point& x : pp.localPoints())
        {
            maxOffset = max(maxOffset, mag((x - p) & n));
        }
        reduce(maxAngle, maxOp<scalar>());
        reduce(maxOffset, maxOp<scalar>());
        const scalar extent = bb.mag();
        if (maxAngle > 1e-6 || maxOffset > 1e-6*extent)
        {
            entryError
            (
                dict, keyword,
                "names the patch '" + name + "', which is not a plane: a face"
                " normal deviates by " + Foam::name(maxAngle) + " rad and a"
                " point lies " + Foam::name(maxOffset) + " m off its mean"
                " plane (allowed: 1e-6 rad, 1e-6 of the patch extent "
              + Foam::name(extent) + " m); collision walls must be planes"
            );
        }

        collision::PlaneWall w;
        w.name = name;
        w.point = collision::Vec3(p.x(), p.y(), p.z());
        w.normal = -collision::Vec3(n.x(), n.y(), n.z());   // into the fluid
        walls.push_back(w);
    }
    return walls;
}


// ************************************************************************* //
