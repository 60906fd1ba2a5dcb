/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "dictionaryChecks.H"
#include "error.H"
#include "FlatOutput.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::immersedSpheroids::entryError
(
    const dictionary& dict,
    const word& keyword,
    const string& what
)
{
    const entry* ePtr = dict.findEntry(keyword, keyType::LITERAL);
    const label line = ePtr ? ePtr->startLineNumber() : dict.startLineNumber();

    FatalIOError
    (
        FUNCTION_NAME,
        __FILE__,
        __LINE__,
        dict.name(),
        line,
        -1
    )   << "Entry '" << keyword << "' in dictionary " << dict.name()
        << ' ' << what.c_str() << nl
        << exit(FatalIOError);
}


void Foam::immersedSpheroids::checkKeywords
(
    const dictionary& dict,
    const wordList& allowed
)
{
    for (const entry& e : dict)
    {
        if (!allowed.found(e.keyword()))
        {
            FatalIOError
            (
                FUNCTION_NAME,
                __FILE__,
                __LINE__,
                dict.name(),
                e.startLineNumber(),
                -1
            )   << "Unknown keyword '" << e.keyword() << "' in dictionary "
                << dict.name() << nl
                << "Allowed keywords: " << flatOutput(allowed) << nl
                << exit(FatalIOError);
        }
    }
}


Foam::scalar Foam::immersedSpheroids::readInRange
(
    const dictionary& dict,
    const word& keyword,
    const scalar minValue,
    const scalar maxValue,
    const string& expected
)
{
    const scalar value = readChecked<scalar>(dict, keyword, expected);

    if (!(value >= minValue && value <= maxValue))
    {
        entryError
        (
            dict,
            keyword,
            "= " + Foam::name(value) + " is out of range; expected "
          + expected + " in [" + Foam::name(minValue) + ", "
          + Foam::name(maxValue) + "]"
        );
    }
    return value;
}


Foam::scalar Foam::immersedSpheroids::readPositive
(
    const dictionary& dict,
    const word& keyword,
    const string& expected
)
{
    const scalar value = readChecked<scalar>(dict, keyword, expected);

    if (!(value > 0))
    {
        entryError
        (
            dict,
            keyword,
            "= " + Foam::name(value) + " must be > 0; expected " + expected
        );
    }
    return value;
}


Foam::string Foam::immersedSpheroids::commaList(const UList<word>& words)
{
    string text;
    forAll(words, i)
    {
        text += (i ? ", " : "") + words[i];
    }
    return text;
}


// ************************************************************************* //
