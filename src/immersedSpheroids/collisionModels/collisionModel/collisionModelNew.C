/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "collisionModel.H"
#include "dictionaryChecks.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::collisionModel> Foam::collisionModel::New
(
    const dictionary& properties,
    const fvMesh& mesh,
    const scalar fluidDensity
)
{
    using namespace immersedSpheroids;

    const string allowed
    (
        commaList(dictionaryConstructorTablePtr_->sortedToc())
    );

    if (!properties.found("collision"))
    {
        // no collision entry: the model none (no cost)
        return dictionaryConstructorTablePtr_->cfind("none")()
        (
            dictionary::null, mesh, fluidDensity
        );
    }
    if (!properties.isDict("collision"))
    {
        entryError
        (
            properties, "collision",
            "must be a dictionary: collision { type ...; } with type one of: "
          + allowed
        );
    }
    const dictionary& dict = properties.subDict("collision");
    const word modelType
    (
        readChecked<word>(dict, "type", "a collision model (" + allowed + ")")
    );

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);
    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "collisionModel",
            modelType,
            *dictionaryConstructorTablePtr_
        )   << "Entry 'type' in dictionary " << dict.name() << " is '"
            << modelType << "'; allowed: " << allowed.c_str() << nl
            << exit(FatalIOError);
    }
    return cstrIter()(dict, mesh, fluidDensity);
}


// ************************************************************************* //
