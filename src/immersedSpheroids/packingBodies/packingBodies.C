/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "packingBodies.H"
#include "dictionaryChecks.H"

#include "packing/PackingIO.hpp"

#include <stdexcept>

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::immersedSpheroids::readPackingBodies
(
    const dictionary& dict,
    const Time& time,
    PtrList<immersedBody>& bodies
)
{
    checkKeywords(dict, wordList({"file", "density", "offset", "scale", "motion"}));

    fileName file = readChecked<fileName>
    (
        dict, "file", "the packing file (.h5, .hdf5 or .csv) of packSpheroids"
    );
    file.expand();
    if (!file.isAbsolute())
    {
        file = time.globalPath()/file;
    }
    const scalar density = readPositive(dict, "density", "the body density [kg/m^3], > 0");
    const vector offset = readCheckedOrDefault<vector>
    (
        dict, "offset", Zero, "a vector (x y z) [m] added to the centres"
    );
    const scalar scale = readCheckedOrDefault<scalar>
    (
        dict, "scale", 1, "a factor > 0 applied to the lengths of the packing"
    );
    if (scale <= 0)
    {
        entryError(dict, "scale", "must be > 0, got " + Foam::name(scale));
    }
    if (!dict.isDict("motion"))
    {
        entryError
        (
            dict, "motion",
            "a motion sub-dictionary { type <fixed|prescribed|free|"
            "freeTranslation|freeRotation>; } is required"
        );
    }

    packing::Packing p;
    try
    {
        p = packing::readPacking(file);
    }
    catch (const std::exception& err)
    {
        entryError(dict, "file", string("could not be read: ") + err.what());
    }

    const scalar L = scale*p.boxLength;
    label crossing = 0;
    forAll(p.bodies, i)
    {
        const ellipsoids::Ellipsoid& e = p.bodies[i];
        bodyState s;
        s.centre = offset + scale*point(e.centre().x(), e.centre().y(), e.centre().z());
        const ellipsoids::Quat& q = e.orientation();
        s.orientation = quaternion(q.w(), vector(q.x(), q.y(), q.z()));
        s.orientation.normalize();
        const vector semiAxes
        (
            scale*e.semiAxes().x(), scale*e.semiAxes().y(), scale*e.semiAxes().z()
        );

        bodies.append
        (
            new immersedBody
            (
                "packing" + Foam::name(i), semiAxes, density, s, dict.subDict("motion")
            )
        );

        const boundBox bb = bodies.last().bounds();
        const boundBox box(offset, offset + vector(L, L, L));
        if (!box.contains(bb))
        {
            ++crossing;
        }
    }

    Info<< "immersedBodies: " << p.bodies.size() << " bodies from " << file
        << " (box " << L << ", volume fraction " << p.volumeFraction << ')' << endl;
    if (crossing)
    {
        // along the mesh's periodic axes they are represented through their
        // images; a body beyond any other boundary stops the run
        // (checkInsideMesh)
        Info<< "immersedBodies: " << crossing << " bodies of " << file
            << " cross the faces of the periodic packing box" << endl;
    }
}


// ************************************************************************* //
