/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "bodyMotion.H"
#include "dictionaryChecks.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::bodyMotion> Foam::bodyMotion::New(const dictionary& dict)
{
    const word modelType
    (
        immersedSpheroids::readChecked<word>
        (
            dict,
            "type",
            "a motion type ("
          + immersedSpheroids::commaList
            (
                dictionaryConstructorTablePtr_->sortedToc()
            )
          + ")"
        )
    );

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "bodyMotion",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<bodyMotion>(cstrIter()(modelType, dict));
}


// ************************************************************************* //
