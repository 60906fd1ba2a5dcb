/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "immersedBodies.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::immersedBodies::writeData(Ostream& os) const
{
    // the restart state round-trips exactly: 17 significant digits
    const int oldPrecision = os.precision(17);

    os.writeEntry("eta", forcing_->eta());
    os.writeEntry("deltaT", lastDeltaT_);
    os.writeEntry
    (
        "ddtCoefficients",
        FixedList<scalar, 3>({solveDdt_.c, solveDdt_.c0, solveDdt_.c00})
    );
    os.beginBlock("bodies");
    for (const immersedBody& body : bodies_)
    {
        os.beginBlock(body.name());
        body.writeState(os);
        os.endBlock();
    }
    os.endBlock();
    integrator_->collision().writeHistory(os);

    os.precision(oldPrecision);
    return os.good();
}


bool Foam::immersedBodies::writeObject
(
    IOstream::streamFormat,
    IOstream::versionNumber ver,
    IOstream::compressionType,
    const bool valid
) const
{
    output_->write();
    integrator_->collision().collectHistory();

    // every rank holds the same bodies (and the pair history of the pairs
    // it owns, gathered on the master above): the master writes the state
    // once (in processor0/ when decomposed, which reconstructPar carries to
    // the case and decomposePar to every processor directory;
    // readRestartState reads the master's copy)
    if (Pstream::parRun() && !Pstream::master())
    {
        return true;
    }

    // always ASCII, uncompressed: small, readable, exact at 17 digits
    return regIOobject::writeObject
    (
        IOstream::ASCII, ver, IOstream::UNCOMPRESSED, valid
    );
}


// ************************************************************************* //
