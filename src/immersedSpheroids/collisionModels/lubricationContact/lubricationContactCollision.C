/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "lubricationContactCollision.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace collisionModels
{
    defineTypeNameAndDebug(lubricationContact, 0);
    addToRunTimeSelectionTable(collisionModel, lubricationContact, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::collisionModels::lubricationContact::lubricationContact
(
    const dictionary& dict,
    const fvMesh& mesh,
    const filmCorrection& film
)
:
    contact(dict, mesh, film, "lubricatedSpringDashpot")
{}


// ************************************************************************* //
