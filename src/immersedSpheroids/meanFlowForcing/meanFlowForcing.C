/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "meanFlowForcing.H"
#include "dictionaryChecks.H"

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

const Foam::Enum<Foam::meanFlowForcing::condition>
Foam::meanFlowForcing::conditionNames
({
    { condition::none, "none" },
    { condition::zeroFlux, "zeroFlux" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meanFlowForcing::meanFlowForcing
(
    const dictionary& properties,
    const fvMesh& mesh,
    const periodicDomain& domain
)
:
    mesh_(mesh),
    condition_(condition::none),
    axes_(domain.periodic(0), domain.periodic(1), domain.periodic(2)),
    boxVolume_(gSum(mesh.V())),
    weightTerm_(Zero),
    fluxTerm_(Zero),
    meanVelocity_(Zero)
{
    condition_ = immersedSpheroids::readOptionalEnum
    (
        properties, "meanFlow", conditionNames, condition::none,
        "the mean-flow condition of a periodic box: none, or zeroFlux (a mean"
        " pressure gradient carries the bodies' net weight and holds the"
        " volume flux at zero)"
    );
    if (active() && !domain.anyPeriodic())
    {
        FatalIOErrorInFunction(properties)
            << "meanFlow zeroFlux in " << properties.name() << " needs a"
            << " periodic axis (cyclic patches on opposite faces of the box);"
            << " the mesh of " << mesh.time().path() << " has none. Allowed"
            << " here: meanFlow none" << nl << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meanFlowForcing::update
(
    const PtrList<immersedBody>& bodies,
    const scalar fluidDensity,
    const vector& g,
    const volVectorField& U,
    const scalar dt,
    const scalar ddtCoeff
)
{
    if (!active())
    {
        return;
    }
    // every rank holds every body: the same sum everywhere
    vector weight(Zero);
    for (const immersedBody& body : bodies)
    {
        if (body.motion().isFreeInTranslation())
        {
            weight += (body.density() - fluidDensity)*body.volume()*g;
        }
    }
    meanVelocity_ = gSum(mesh_.V()*U.primitiveField())/boxVolume_;
    for (direction d = 0; d < 3; ++d)
    {
        weightTerm_[d] = axes_[d] ? -weight[d]/(fluidDensity*boxVolume_) : 0;
        fluxTerm_[d] = axes_[d] ? -meanVelocity_[d]*ddtCoeff/dt : 0;
    }
}


void Foam::meanFlowForcing::addTo(fvVectorMatrix& source) const
{
    if (!active())
    {
        return;
    }
    // an explicit source, stored negated in the matrix
    source.source() -= force()*mesh_.V();
}


Foam::string Foam::meanFlowForcing::describe(const scalar fluidDensity) const
{
    OStringStream os;
    os  << "meanFlow zeroFlux: mean pressure gradient "
        << -fluidDensity*force() << " Pa/m (net weight "
        << -fluidDensity*weightTerm_ << ", flux hold " << -fluidDensity*fluxTerm_
        << "), mean velocity of the last solve " << meanVelocity_ << " m/s";
    return os.str();
}


// ************************************************************************* //
