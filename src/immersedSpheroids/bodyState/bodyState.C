/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "bodyState.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

void Foam::bodyState::write(Ostream& os) const
{
    os.writeEntry("centre", centre);
    os.writeEntry("velocity", velocity);
    os.writeEntry("orientation", quaternionToList(orientation));
    os.writeEntry("angularVelocity", angularVelocity);
}


Foam::FixedList<Foam::scalar, 4> Foam::quaternionToList(const quaternion& q)
{
    return FixedList<scalar, 4>({q.w(), q.v().x(), q.v().y(), q.v().z()});
}


Foam::quaternion Foam::listToQuaternion(const FixedList<scalar, 4>& l)
{
    return quaternion(l[0], vector(l[1], l[2], l[3]));
}


Foam::quaternion Foam::rotationQuaternion(const vector& w)
{
    const scalar angle = mag(w);
    if (angle < VSMALL)
    {
        return quaternion::I;
    }
    // quaternion(d, theta): rotation by theta about the unit vector d
    return quaternion(w/angle, angle);
}


// ************************************************************************* //
