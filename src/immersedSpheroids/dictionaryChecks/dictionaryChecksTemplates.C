/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "dictionaryChecks.H"
#include "error.H"
#include "OStringStream.H"
#include "stringOps.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

template<class T>
T Foam::immersedSpheroids::readChecked
(
    const dictionary& dict,
    const word& keyword,
    const string& expected
)
{
    const entry* ePtr = dict.findEntry(keyword, keyType::LITERAL);

    if (!ePtr)
    {
        entryError(dict, keyword, "is missing; expected " + expected);
    }
    if (ePtr->isDict())
    {
        entryError(dict, keyword, "is a sub-dictionary; expected " + expected);
    }

    // Parse with exceptions on so that a type mismatch is reported with the
    // keyword and the expected form, not only the token that failed
    const bool throwing = FatalIOError.throwExceptions();
    T value;
    string problem;
    try
    {
        ITstream& is = ePtr->stream();
        is >> value;
        if (is.nRemainingTokens())
        {
            problem = "has excess tokens";
        }
    }
    catch (const Foam::IOerror& err)
    {
        string why(err.message());
        why.replaceAll("\n", " ");
        problem = "could not be read (" + stringOps::trim(why) + ")";
    }
    FatalIOError.throwExceptions(throwing);

    if (!problem.empty())
    {
        OStringStream os;
        ePtr->write(os);
        entryError
        (
            dict,
            keyword,
            problem + "; expected " + expected + ", got: "
          + stringOps::trim(os.str())
        );
    }

    return value;
}


template<class T>
T Foam::immersedSpheroids::readCheckedOrDefault
(
    const dictionary& dict,
    const word& keyword,
    const T& deflt,
    const string& expected
)
{
    if (dict.findEntry(keyword, keyType::LITERAL))
    {
        return readChecked<T>(dict, keyword, expected);
    }
    return deflt;
}


template<class T, class RangeType>
T Foam::immersedSpheroids::readOptionalInRange
(
    const dictionary& dict,
    const word& keyword,
    const T& deflt,
    const RangeType& range,
    const string& what
)
{
    const string expected =
        what + " in " + range.str() + " (default " + Foam::name(deflt) + ")";
    const T value = readCheckedOrDefault<T>(dict, keyword, deflt, expected);
    if (!range.contains(scalar(value)))
    {
        entryError
        (
            dict, keyword,
            "is " + Foam::name(value) + "; allowed: " + expected
        );
    }
    return value;
}


template<class EnumType>
EnumType Foam::immersedSpheroids::readOptionalEnum
(
    const dictionary& dict,
    const word& keyword,
    const Enum<EnumType>& names,
    const EnumType deflt,
    const string& what
)
{
    const string expected =
        commaList(names.names()) + " (default " + names.get(deflt) + "): "
      + what;
    const word value =
        readCheckedOrDefault<word>(dict, keyword, names.get(deflt), expected);
    if (!names.found(value))
    {
        entryError(dict, keyword, "is " + value + "; allowed: " + expected);
    }
    return names.get(value);
}


// ************************************************************************* //
