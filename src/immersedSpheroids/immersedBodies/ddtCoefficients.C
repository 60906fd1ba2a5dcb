/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "ddtCoefficients.H"

// * * * * * * * * * * * * * * * * Static Functions * * * * * * * * * * * * //

Foam::immersedSpheroids::ddtCoefficients::scheme
Foam::immersedSpheroids::ddtCoefficients::read
(
    const fvMesh& mesh,
    const word& fieldName
)
{
    const word ddtName("ddt(" + fieldName + ')');
    ITstream& is = mesh.ddtScheme(ddtName);
    const word name(is);
    if (name == "Euler")
    {
        return scheme::Euler;
    }
    if (name == "backward")
    {
        return scheme::backward;
    }

    FatalIOErrorInFunction(mesh.schemesDict())
        << "The ddt scheme of " << fieldName << " in "
        << mesh.schemesDict().name() << " (ddtSchemes, " << ddtName
        << " or default) is '" << name << "'; immersed bodies work with"
        << " Euler or backward" << nl << exit(FatalIOError);
    return scheme::Euler;
}


Foam::immersedSpheroids::ddtCoefficients
Foam::immersedSpheroids::ddtCoefficients::of
(
    const scheme s,
    const label timeIndex,
    const scalar dt,
    const scalar dt0
)
{
    ddtCoefficients k;
    if (s == scheme::backward && timeIndex >= 2 && dt0 > 0)
    {
        // backwardDdtScheme: coefft, coefft0, coefft00
        k.c = 1 + dt/(dt + dt0);
        k.c00 = dt*dt/(dt0*(dt + dt0));
        k.c0 = k.c + k.c00;
    }
    return k;
}


// ************************************************************************* //
