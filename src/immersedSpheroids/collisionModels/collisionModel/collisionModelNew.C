/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "collisionModel.H"
#include "dictionaryChecks.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::word Foam::collisionModel::selectedType(const dictionary& properties)
{
    using namespace immersedSpheroids;

    const string allowed
    (
        commaList(dictionaryConstructorTablePtr_->sortedToc())
    );
    if (!properties.found("collision"))
    {
        return "none";
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
    if (!dictionaryConstructorTablePtr_->found(modelType))
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
    return modelType;
}


Foam::autoPtr<Foam::collisionModel> Foam::collisionModel::New
(
    const dictionary& properties,
    const fvMesh& mesh,
    const filmCorrection& film
)
{
    const word modelType(selectedType(properties));
    const dictionary& dict =
        properties.found("collision")
      ? properties.subDict("collision")
      : dictionary::null;
    autoPtr<collisionModel> model
    (
        dictionaryConstructorTablePtr_->cfind(modelType)()(dict, mesh, film)
    );
    film.checkViscosityUsed();
    return model;
}


// ************************************************************************* //
