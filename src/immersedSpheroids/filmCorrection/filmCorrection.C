/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "filmCorrection.H"
#include "dictionaryChecks.H"
#include "collision/FilmCorrection.hpp"
#include "IOdictionary.H"
#include "dimensionedScalar.H"
#include "volMesh.H"

#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The smallest cell size: the cube root of the smallest cell volume, over
//  all ranks
scalar smallestCellSize(const fvMesh& mesh)
{
    scalar vMin = GREAT;
    for (const scalar v : mesh.V().field())
    {
        vMin = min(vMin, v);
    }
    reduce(vMin, minOp<scalar>());
    return std::cbrt(vMin);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::filmCorrection::filmCorrection
(
    const dictionary& properties,
    const fvMesh& mesh,
    const scalar fluidDensity,
    const bool collisions
)
:
    properties_(properties),
    mesh_(mesh),
    fluidDensity_(fluidDensity),
    active_(false),
    filmGap_(0),
    dampingScale_(1),
    cellSize_(smallestCellSize(mesh)),
    viscosity_(0)
{
    using namespace immersedSpheroids;

    active_ = readCheckedOrDefault<bool>
    (
        properties, "filmStabilisation", collisions,
        string("yes or no (default ")
      + (collisions ? "yes" : "no")
      + "): the film correction for the pairs closer than filmGap"
    );
    if (active_ && !collisions)
    {
        entryError
        (
            properties, "filmStabilisation",
            "yes needs a collision model: the film correction acts through"
            " it; set collision { type contact; } (or lubricationContact)"
            " or filmStabilisation no"
        );
    }
    if (!active_)
    {
        for (const word key : {"filmGap", "filmDampingScale"})
        {
            if (properties.found(key))
            {
                entryError
                (
                    properties, key,
                    "is used only with filmStabilisation yes (it is no here);"
                    " remove it"
                );
            }
        }
        return;
    }
    if (properties.found("filmGap"))
    {
        filmGap_ = readPositive
        (
            properties, "filmGap",
            "the film thickness below which the mesh cannot resolve the flow"
            " between two surfaces [m] > 0 (default: the smallest cell size)"
        );
    }
    else
    {
        filmGap_ = cellSize_;
    }
    dampingScale_ = readOptionalInRange<scalar>
    (
        properties, "filmDampingScale", dampingScale_,
        collision::FilmCorrection::kDampingScaleRange,
        "the factor on the film damping estimate D"
    );
}



// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::filmCorrection::viscosity() const
{
    using namespace immersedSpheroids;

    if (viscosity_ > 0)
    {
        return viscosity_;
    }
    const string expected =
        "the dynamic viscosity mu [Pa s] > 0 (default: fluidDensity x nu of"
        " constant/transportProperties)";
    if (properties_.found("viscosity"))
    {
        viscosity_ = readPositive(properties_, "viscosity", expected);
        return viscosity_;
    }
    IOdictionary transport
    (
        IOobject
        (
            "transportProperties",
            mesh_.time().constant(),
            mesh_,
            IOobject::READ_IF_PRESENT,
            IOobject::NO_WRITE,
            false
        )
    );
    if (!transport.found("nu"))
    {
        entryError
        (
            properties_, "viscosity",
            "is missing and " + transport.objectPath()
          + " has no entry nu; expected " + expected
        );
    }
    const dimensionedScalar nu("nu", dimViscosity, transport);
    if (!(nu.value() > 0))
    {
        entryError
        (
            transport, "nu",
            "must be > 0 for the surface-corrected forcing, the lubrication force"
            " and the film correction"
        );
    }
    viscosity_ = fluidDensity_*nu.value();
    return viscosity_;
}


void Foam::filmCorrection::checkViscosityUsed() const
{
    if (properties_.found("viscosity") && !(viscosity_ > 0))
    {
        immersedSpheroids::entryError
        (
            properties_, "viscosity",
            "is used only by forcing surfaceCorrected, a lubricated pair or"
            " wall model (lubricatedSpringDashpot) or filmStabilisation yes;"
            " remove it"
        );
    }
}


// ************************************************************************* //
