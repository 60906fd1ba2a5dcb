/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "immersedBodiesOutput.H"
#include "immersedBodies.H"
#include "dictionaryChecks.H"

#include "bodyOutput/bodyOutput.hpp"
#include "collision/Range.hpp"

#include <stdexcept>

// * * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// The defaults and ranges of the output keywords (the members' initial values
// and the reader's checks and messages)
constexpr bool timeSeriesDefault = true;
constexpr bool surfacesDefault = true;
constexpr bool solidFractionDefault = false;
constexpr label surfaceSubdivisionsDefault = 3;
constexpr scalar timeSeriesIntervalDefault = 1;
constexpr collision::Range timeStepIntervalRange{1, 1e9};
constexpr collision::Range surfaceSubdivisionsRange
{
    0, bodyoutput::kMaxSurfaceSubdivisions
};

std::array<double, 3> toArray(const vector& v)
{
    return {v.x(), v.y(), v.z()};
}

std::array<double, 4> toArray(const quaternion& q)
{
    return {q.w(), q.v().x(), q.v().y(), q.v().z()};
}

} // End anonymous namespace


// * * * * * * * * * * * * * Static Member Data  * * * * * * * * * * * * * //

const Foam::Enum<Foam::immersedBodiesOutput::seriesControl>
Foam::immersedBodiesOutput::seriesControlNames
({
    { seriesControl::timeStep, "timeStep" },
    { seriesControl::runTime, "runTime" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::immersedBodiesOutput::seriesIndex
(
    const scalar t,
    const scalar deltaT
) const
{
    return std::floor((t + 0.5*deltaT)/seriesInterval_);
}


bool Foam::immersedBodiesOutput::rowDue(const Time& time)
{
    bool due = time.writeTime();
    if (seriesControl_ == seriesControl::timeStep)
    {
        due = due || time.timeIndex() % label(seriesInterval_) == 0;
    }
    else
    {
        const scalar index = seriesIndex(time.value(), time.deltaTValue());
        due = due || index > lastSeriesIndex_;
        lastSeriesIndex_ = index;
    }
    return due;
}


void Foam::immersedBodiesOutput::writeRow(const scalar t)
{
    std::vector<bodyoutput::BodyRecord> records;
    records.reserve(bodies_.bodies().size());
    for (const immersedBody& body : bodies_.bodies())
    {
        const bodyState& s = body.state();
        bodyoutput::BodyRecord r;
        r.centre = toArray(s.centre);
        r.velocity = toArray(s.velocity);
        r.angularVelocity = toArray(s.angularVelocity);
        r.orientation = toArray(s.orientation);
        r.hydroForce = toArray(body.hydroForce());
        r.hydroTorque = toArray(body.hydroTorque());
        r.collisionForce = toArray(body.collisionForce());
        r.collisionTorque = toArray(body.collisionTorque());
        r.unwrappedCentre = toArray(body.unwrappedCentre());
        records.push_back(r);
    }
    try
    {
        writer_->append(t, records);
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << "Cannot append to the time series of the bodies "
            << writer_->path() << ": " << err.what() << nl << exit(FatalError);
    }
}


void Foam::immersedBodiesOutput::writeSurfaces
(
    const scalar t,
    const word& timeName
) const
{
    if (!series_)
    {
        return;
    }

    std::vector<bodyoutput::BodyShape> shapes;
    shapes.reserve(bodies_.bodies().size());
    forAll(bodies_.bodies(), bodyi)
    {
        // a body across a periodic face is drawn on each side (its images
        // that overlap the mesh)
        const immersedBody& body = bodies_.bodies()[bodyi];
        const boundBox bb = body.bounds();
        for (const vector& shift : body.images())
        {
            if
            (
                shift != vector::zero
             && !boundBox(bb.min() + shift, bb.max() + shift).overlaps
                (
                    bodies_.domain().bounds()
                )
            )
            {
                continue;
            }
            bodyoutput::BodyShape s;
            s.id = int(bodyi);
            s.semiAxes = toArray(body.semiAxes());
            s.centre = toArray(body.state().centre + shift);
            s.orientation = toArray(body.state().orientation);
            shapes.push_back(s);
        }
    }

    const word name("surfaces_" + timeName + ".vtk");
    const fileName surfacesDir(dir_/"surfaces");
    try
    {
        bodyoutput::writeSurfacesVtk(surfacesDir/name, shapes, surfaceSubdivisions_);
        series_->add("surfaces"/name, t);
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << "Cannot write the body surfaces " << surfacesDir/name << ": "
            << err.what() << nl << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::immersedBodiesOutput::immersedBodiesOutput
(
    const immersedBodies& bodies,
    const dictionary& dict
)
:
    bodies_(bodies),
    timeSeries_(timeSeriesDefault),
    seriesControl_(seriesControl::timeStep),
    seriesInterval_(timeSeriesIntervalDefault),
    lastSeriesIndex_(0),
    surfaces_(surfacesDefault),
    surfaceSubdivisions_(surfaceSubdivisionsDefault),
    solidFraction_(solidFractionDefault),
    dir_(bodies.mesh().time().globalPath()/"postProcessing"/"immersedBodies")
{
    using namespace immersedSpheroids;

    checkKeywords
    (
        dict,
        wordList
        ({
            "timeSeries", "timeSeriesControl", "timeSeriesInterval",
            "surfaces", "surfaceSubdivisions", "solidFraction"
        })
    );
    const string yesNo("yes or no (a switch)");
    timeSeries_ =
        readCheckedOrDefault<Switch>(dict, "timeSeries", timeSeriesDefault, yesNo);
    seriesControl_ = readOptionalEnum
    (
        dict, "timeSeriesControl", seriesControlNames, seriesControl::timeStep,
        "what sets the time series' interval: timeStep (timeSeriesInterval"
        " steps) or runTime (timeSeriesInterval seconds)"
    );
    if (seriesControl_ == seriesControl::timeStep)
    {
        seriesInterval_ = readOptionalInRange<label>
        (
            dict, "timeSeriesInterval", label(timeSeriesIntervalDefault),
            timeStepIntervalRange,
            "the time steps between two rows of the time series"
            " (timeSeriesControl timeStep), an integer"
        );
    }
    else
    {
        seriesInterval_ = readPositive
        (
            dict, "timeSeriesInterval",
            "the simulated time between two rows of the time series [s]"
            " (timeSeriesControl runTime), > 0"
        );
    }
    surfaces_ =
        readCheckedOrDefault<Switch>(dict, "surfaces", surfacesDefault, yesNo);
    solidFraction_ = readCheckedOrDefault<Switch>
    (
        dict, "solidFraction", solidFractionDefault, yesNo
    );
    surfaceSubdivisions_ = readOptionalInRange<label>
    (
        dict, "surfaceSubdivisions", surfaceSubdivisionsDefault,
        surfaceSubdivisionsRange,
        "the subdivisions of the icosahedron triangulating each surface"
        " (20 x 4^s triangles), an integer"
    );
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * //

Foam::immersedBodiesOutput::~immersedBodiesOutput()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::immersedBodiesOutput::start(const scalar t0)
{
    if (!Pstream::master())
    {
        return;
    }

    // rows after the start time belong to a later part of an earlier run
    // (this run replaces them); the start row itself is written again
    const scalar restartTime = t0 - 0.5*bodies_.mesh().time().deltaTValue();

    if (timeSeries_)
    {
        std::vector<bodyoutput::BodyInfo> infos;
        for (const immersedBody& body : bodies_.bodies())
        {
            bodyoutput::BodyInfo info;
            info.name = body.name();
            info.semiAxes = toArray(body.semiAxes());
            info.density = body.density();
            infos.push_back(info);
        }
        const fileName file(dir_/"bodies.h5");
        try
        {
            writer_.reset(new bodyoutput::TimeSeriesWriter(file, infos, restartTime));
        }
        catch (const std::exception& err)
        {
            FatalErrorInFunction
                << "Cannot open the time series of the bodies " << file
                << ": " << err.what() << nl << exit(FatalError);
        }
        writeRow(t0);
        lastSeriesIndex_ =
            seriesIndex(t0, bodies_.mesh().time().deltaTValue());
    }

    if (surfaces_)
    {
        const fileName file(dir_/"surfaces.vtk.series");
        try
        {
            series_.reset(new bodyoutput::VtkSeries(file, restartTime));
        }
        catch (const std::exception& err)
        {
            FatalErrorInFunction
                << "Cannot read the series of surfaces " << file << ": "
                << err.what() << nl << exit(FatalError);
        }
        // start() runs within the first step, when the run's time is already
        // t0 + deltaT: the file is named after t0 itself, as the time folder
        // of t0 is (a write at t0 + deltaT then gets a file of its own)
        const Time& time = bodies_.mesh().time();
        writeSurfaces(t0, Time::timeName(time.timeToUserTime(t0)));
    }
}


void Foam::immersedBodiesOutput::append()
{
    if (!writer_)
    {
        return;
    }
    const Time& time = bodies_.mesh().time();
    if (rowDue(time))
    {
        writeRow(time.value());
    }
}


void Foam::immersedBodiesOutput::write() const
{
    const Time& time = bodies_.mesh().time();
    if (Pstream::master() && series_)
    {
        writeSurfaces(time.value(), time.timeName());
    }
    if (solidFraction_)
    {
        bodies_.solidFraction()().write();
    }
}


// ************************************************************************* //
