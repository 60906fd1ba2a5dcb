/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "contactCollision.H"
#include "pstreamWorkShare.H"

#include <algorithm>
#include <tuple>
#include "immersedBody.H"
#include "coreConversions.H"
#include "collision/BodySet.hpp"
#include "collision/Range.hpp"
#include "planeWalls.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"

#include <memory>
#include <stdexcept>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace collisionModels
{
    defineTypeNameAndDebug(contact, 0);
    addToRunTimeSelectionTable(collisionModel, contact, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The contact time over the fluid time step, T_c/deltaT: default and range
constexpr scalar contactStepsDefault = 10;
constexpr collision::Range contactStepsRange{1e-3, 1e6};

//- Does the named pair or wall model have a lubrication law?
bool lubricated(const word& model)
{
    return model == "lubricatedSpringDashpot";
}

//- Read a name (pairModel, wallModel, distanceMethod) and check it against
//  the names the core accepts
word readModelName
(
    const dictionary& dict,
    const word& keyword,
    const word& deflt,
    const std::vector<std::string>& names
)
{
    wordList allowed;
    for (const std::string& n : names)
    {
        allowed.append(word(n));
    }
    const string expected =
        immersedSpheroids::commaList(allowed) + " (default " + deflt + ")";
    const word name
    (
        immersedSpheroids::readCheckedOrDefault<word>
        (
            dict, keyword, deflt, expected
        )
    );
    if (!allowed.found(name))
    {
        immersedSpheroids::entryError
        (
            dict, keyword, "is " + name + "; allowed: " + expected
        );
    }
    return name;
}

//- A lubrication law takes either the resolved-gap form (its resolved gap
//  in cells, the default) or the ratio form (its activation gap ratio
//  given): the resolved gap in cells, 0 in the ratio form
scalar readResolvedGapCells
(
    const dictionary& dict,
    const word& ratioKeyword,
    const word& cellsKeyword,
    const scalar deflt
)
{
    if (!dict.found(ratioKeyword))
    {
        return immersedSpheroids::readOptionalInRange<scalar>
        (
            dict, cellsKeyword, deflt,
            collision::LubricationParameters::kCellsRange,
            "the resolved gap in cells of the smallest cell size"
        );
    }
    if (dict.found(cellsKeyword))
    {
        immersedSpheroids::entryError
        (
            dict, cellsKeyword,
            "is given with " + ratioKeyword + ": give one of them, "
          + cellsKeyword + " (the resolved-gap form, the default) or "
          + ratioKeyword + " (the activation gap ratio form)"
        );
    }
    return 0;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::collisionModels::contact::contact
(
    const dictionary& dict,
    const fvMesh& mesh,
    const filmCorrection& film,
    const word& defaultModel
)
:
    collisionModel(mesh),
    contactSteps_
    (
        immersedSpheroids::readOptionalInRange<scalar>
        (
            dict, "contactSteps", contactStepsDefault, contactStepsRange,
            "the contact time over the fluid time step, T_c/deltaT,"
        )
    ),
    model_(),
    filmGap_(film.filmGap()),
    cellSize_(film.cellSize())
{
    using namespace immersedSpheroids;

    const word pairName
    (
        readModelName
        (
            dict, "pairModel", defaultModel, collision::PairModel::names()
        )
    );
    const word wallName
    (
        readModelName
        (
            dict, "wallModel", defaultModel, collision::WallModel::names()
        )
    );
    const bool lubrication = lubricated(pairName) || lubricated(wallName);

    wordList allowed
    ({
        "type", "walls", "restitution", "friction", "frictionModel",
        "rollingFriction", "sustainedLoadOverlap", "contactSteps",
        "subStepsPerContact", "maxOverlap", "distanceAccuracy", "maxSubSteps",
        "distanceMethod", "pairModel", "wallModel"
    });
    if (lubrication)
    {
        allowed.append
        (
            wordList
            ({
                "pairActivation", "wallActivation", "pairResolvedGapCells",
                "wallResolvedGapCells", "saturation", "tangentialLubrication"
            })
        );
    }
    checkKeywords(dict, allowed);

    // The defaults are those of default-constructed settings and
    // parameters, the ranges their constants: the core checks the same
    // numbers
    using Settings = collision::CollisionSettings;
    using Contact = collision::ContactParameters;
    using Lubrication = collision::LubricationParameters;
    const Settings defaults;
    const collision::InteractionParameters lawDefaults;

    Settings s;
    collision::InteractionParameters p;
    p.contact.restitution = readOptionalInRange<scalar>
    (
        dict, "restitution", lawDefaults.contact.restitution,
        Contact::kRestitutionRange, "the dry restitution coefficient e"
    );
    p.contact.friction = readOptionalInRange<scalar>
    (
        dict, "friction", lawDefaults.contact.friction,
        Contact::kFrictionRange, "the Coulomb friction coefficient"
    );
    p.contact.rollingFriction = readOptionalInRange<scalar>
    (
        dict, "rollingFriction", lawDefaults.contact.rollingFriction,
        Contact::kRollingFrictionRange,
        "the rolling friction coefficient mu_r (torque mu_r R_r |F_n|)"
    );
    p.contact.sustainedLoadOverlap = readOptionalInRange<scalar>
    (
        dict, "sustainedLoadOverlap", lawDefaults.contact.sustainedLoadOverlap,
        Contact::kSustainedLoadOverlapRange,
        "the static overlap of a sustained load over the overlap cap"
    );
    p.contact.frictionModel = readModelName
    (
        dict, "frictionModel", word(lawDefaults.contact.frictionModel),
        Contact::frictionModels()
    );
    s.subStepsPerContact = label
    (
        readOptionalInRange<scalar>
        (
            dict, "subStepsPerContact", defaults.subStepsPerContact,
            Settings::kSubStepsPerContactRange,
            "the body sub-steps per contact time, an integer"
        )
    );
    s.maxOverlap = readOptionalInRange<scalar>
    (
        dict, "maxOverlap", defaults.maxOverlap, Settings::kMaxOverlapRange,
        "the largest overlap over the smallest semi-axis"
    );
    s.distanceAccuracy = readOptionalInRange<scalar>
    (
        dict, "distanceAccuracy", defaults.distanceAccuracy,
        Settings::kDistanceAccuracyRange,
        "eps_d over the smallest Gaussian curvature radius of the pair"
    );
    s.maxSubSteps = label
    (
        readOptionalInRange<scalar>
        (
            dict, "maxSubSteps", defaults.maxSubSteps,
            Settings::kMaxSubStepsRange,
            "the largest number of body sub-steps per fluid step"
        )
    );
    s.distanceMethod = readModelName
    (
        dict, "distanceMethod", word(defaults.distanceMethod),
        Settings::distanceMethods()
    );
    if (lubrication)
    {
        p.lubrication.saturation = readOptionalInRange<scalar>
        (
            dict, "saturation", lawDefaults.lubrication.saturation,
            Lubrication::kSaturationRange,
            "the saturation gap ratio eps_sat"
        );
        p.lubrication.pairActivation = readOptionalInRange<scalar>
        (
            dict, "pairActivation", lawDefaults.lubrication.pairActivation,
            p.lubrication.activationRange(),
            "the pair activation gap ratio 2h/(R1 + R2), above saturation,"
        );
        p.lubrication.wallActivation = readOptionalInRange<scalar>
        (
            dict, "wallActivation", lawDefaults.lubrication.wallActivation,
            p.lubrication.activationRange(),
            "the wall activation gap ratio h/R, above saturation,"
        );
        p.lubrication.pairResolvedGapCells = readResolvedGapCells
        (
            dict, "pairActivation", "pairResolvedGapCells",
            Lubrication::kPairResolvedGapCells
        );
        p.lubrication.wallResolvedGapCells = readResolvedGapCells
        (
            dict, "wallActivation", "wallResolvedGapCells",
            Lubrication::kWallResolvedGapCells
        );
        p.lubrication.tangential = immersedSpheroids::readCheckedOrDefault<bool>
        (
            dict, "tangentialLubrication", lawDefaults.lubrication.tangential,
            string("yes or no (default ")
          + (lawDefaults.lubrication.tangential ? "yes" : "no")
          + "): the logarithmic tangential and rotational lubrication terms"
        );
        p.viscosity = film.viscosity();
    }
    std::vector<collision::PlaneWall> walls
    (
        immersedSpheroids::planeWalls(mesh, dict, "walls")
    );
    try
    {
        model_.reset
        (
            new collision::CollisionModel
            (
                s,
                collision::PairModel::New(pairName, p),
                collision::WallModel::New(wallName, p),
                std::move(walls),
                film.active()
              ? std::make_unique<collision::FilmCorrection>
                (
                    film.viscosity(), film.dampingScale()
                )
              : nullptr
            )
        );
    }
    catch (const std::exception& err)
    {
        FatalIOErrorInFunction(dict)
            << "Invalid collision settings in " << dict.name() << ": "
            << err.what() << nl << exit(FatalIOError);
    }
    // pairs meet through their minimum image along the mesh's periodic axes
    const periodicDomain domain(mesh);
    const point& lo = domain.bounds().min();
    model_->setPeriodicBox
    (
        collision::PeriodicBox
        (
            collision::Vec3(lo.x(), lo.y(), lo.z()),
            collision::Vec3(domain.period(0), domain.period(1), domain.period(2)),
            {domain.periodic(0), domain.periodic(1), domain.periodic(2)}
        )
    );
    // in a parallel run each rank computes the pairs it owns (the core's
    // collectives combine them)
    if (Pstream::parRun())
    {
        model_->setWorkShare(std::make_shared<pstreamWorkShare>());
    }

    Info<< "immersedBodies: collision model " << dict.get<word>("type")
        << ": pair model " << pairName << ", wall model " << wallName
        << ", e " << p.contact.restitution << ", friction "
        << p.contact.friction << " (" << p.contact.frictionModel.c_str()
        << "), rolling friction " << p.contact.rollingFriction << ", T_c = " << contactSteps_ << " deltaT, "
        << s.subStepsPerContact << " sub-steps per contact, max overlap "
        << s.maxOverlap << " a_min, eps_d " << s.distanceAccuracy << " R_G"
        << " (distance method " << s.distanceMethod.c_str() << ")";
    if (lubrication)
    {
        const auto activation = [&](const scalar cells, const scalar ratio)
        {
            const std::string text
            (
                cells > 0
              ? "resolved gap " + Foam::name(cells) + " cells ("
              + Foam::name(cells*cellSize_) + " m)"
              : "ratio " + Foam::name(ratio)
            );
            return text;
        };
        Info<< ", lubrication: mu " << p.viscosity << ", activation "
            << activation
               (
                   p.lubrication.pairResolvedGapCells,
                   p.lubrication.pairActivation
               ).c_str()
            << " (pairs) "
            << activation
               (
                   p.lubrication.wallResolvedGapCells,
                   p.lubrication.wallActivation
               ).c_str()
            << " (walls), saturation "
            << p.lubrication.saturation << ", tangential terms "
            << (p.lubrication.tangential ? "yes" : "no");
    }
    if (film.active())
    {
        Info<< ", film correction below " << filmGap_ << " m (mu "
            << film.viscosity() << ")";
    }
    Info<< ", walls (";
    for (const collision::PlaneWall& w : model_->walls())
    {
        Info<< ' ' << w.name << " n = " << immersedSpheroids::toFoam(w.normal);
    }
    Info<< " ), periodic axes " << domain.describe().c_str() << endl;
}


Foam::collisionModels::contact::contact
(
    const dictionary& dict,
    const fvMesh& mesh,
    const filmCorrection& film
)
:
    contact(dict, mesh, film, "springDashpot")
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::collisionModels::contact::checkOverlaps
(
    const collision::BodySet& bodies,
    const std::vector<collision::BodyState>& states,
    const bool restarted
)
{
    // the shapes once, body by body: one outside the collision core's range
    // (ellipsoids::SupportedRange: semi-axes, elongation) stops the run here
    std::vector<collision::CollisionBody> collisionBodies;
    for (std::size_t i = 0; i < states.size(); ++i)
    {
        try
        {
            collisionBodies.push_back(bodies.collisionBody(i, states[i]));
        }
        catch (const std::invalid_argument& err)
        {
            FatalErrorInFunction
                << "Body '" << bodies.name(i).c_str() << "' is outside the"
                << " shapes the collision core supports: " << err.what()
                << nl << exit(FatalError);
        }
    }
    const scalar cap = model_->settings().maxOverlap;
    const scalar allowed = restarted ? 2*cap : cap;
    const std::vector<collision::CollisionModel::Overlap> found =
        model_->overlaps(collisionBodies, allowed);
    if (found.empty())
    {
        return;
    }
    const collision::CollisionModel::Overlap& o = found.front();
    const std::string other =
        o.second >= 0
      ? "body '" + bodies.name(o.second) + "'"
      : "wall '" + model_->walls()[-1 - o.second].name + "'";
    FatalErrorInFunction
        << "Body '" << bodies.name(o.first).c_str() << "' overlaps "
        << other.c_str() << " at the"
        << " start by " << o.ratio << " of the pair's smallest semi-axis"
        << " (" << found.size() << " pair(s) in all overlap too much); the"
        << " collision model allows " << allowed
        << (restarted ? " on a restart (twice maxOverlap)" : " (maxOverlap)")
        << " and would throw the bodies apart. Place the bodies apart and in"
        << " front of every collision wall (a body behind a wall overlaps it"
        << " by its depth)" << nl << exit(FatalError);
}


void Foam::collisionModels::contact::report(const label nSubSteps)
{
    // each rank's counts are of the pairs it owns (summed here); the
    // damping solve is every rank's alike
    const collision::CollisionStatistics& st = model_->statistics();
    const scalar calls = max(evaluations_, 1);
    const label queries = label(st.distanceQueries);
    const scalar distances = returnReduce(scalar(st.distanceQueries), sumOp<scalar>());
    const scalar iterations = returnReduce(scalar(st.distanceIterations), sumOp<scalar>());
    const scalar distanceNotConverged =
        returnReduce(scalar(st.distanceNotConverged), sumOp<scalar>());
    Info<< "collisions: " << nSubSteps << " sub-step(s) (the most of "
        << interactingIslands_ << " island(s) of " << islandBodies_
        << " bodies), per evaluation "
        << returnReduce(scalar(st.candidatePairs), sumOp<scalar>())/calls
        << " candidate pairs, "
        << returnReduce(scalar(st.prefilterRejected), sumOp<scalar>())/calls
        << " out of reach by the overlap test, "
        << distances/calls << " distances (" << (distances ? iterations/distances : 0)
        << " iterations each";
    if (Pstream::parRun())
    {
        Info<< "; most on one rank " << returnReduce(queries, maxOp<label>())/calls;
    }
    Info<< ")";
    if (Pstream::parRun())
    {
        Info<< ", bodies evaluated on one rank (max) "
            << returnReduce(evaluatedBodies_, maxOp<label>());
    }
    Info<< "; in contact now "
        << returnReduce(label(model_->activeContacts()), sumOp<label>())
        << ", max overlap "
        << returnReduce(st.maxOverlapRatio, maxOp<scalar>()) << " a_min";
    if
    (
        model_->pairModel().lubrication().acts()
     || model_->wallModel().lubrication().acts()
    )
    {
        Info<< ", lubricated "
            << returnReduce(scalar(st.lubricated), sumOp<scalar>())/calls;
    }
    if (model_->filmCorrection())
    {
        Info<< ", film pairs "
            << returnReduce(scalar(st.filmPairs), sumOp<scalar>())/calls;
    }
    if (st.dampingSolves > 0)
    {
        Info<< " (implicit damping: "
            << st.dampingSweeps/scalar(st.dampingSolves) << " sweeps)";
    }
    Info<< endl;
    if (st.dampingNotConverged > 0)
    {
        WarningInFunction
            << st.dampingNotConverged << " implicit damping solves of"
            << " this step stopped at "
            << collision::CollisionModel::kMaxDampingSweeps
            << " sweeps; their last iterate was used" << endl;
    }
    if (st.lubricationNotConverged > 0)
    {
        WarningInFunction
            << st.lubricationNotConverged << " lubricated pairs of this step"
            << " stopped their end-speed iteration at "
            << collision::CollisionModel::kMaxLubricationIterations
            << " iterations; the last iterate was used" << endl;
    }
    if (distanceNotConverged > 0)
    {
        WarningInFunction
            << distanceNotConverged << " distance queries of this step did"
            << " not converge to distanceAccuracy "
            << model_->settings().distanceAccuracy
            << "; their last iterate (certified bracket) was used" << endl;
    }
    model_->resetStatistics();
    evaluations_ = 0;
}


void Foam::collisionModels::contact::readHistory(const dictionary& dict)
{
    // (first second warm dx dy dz contactTime springForce stiffness overlap
    // fx fy fz ix iy iz tx ty tz sx sy sz gx gy gz); i: the periodic image of
    // second (multiples of the periods), t the tangential spring, s the slip
    // velocity of its last call, g the damping force (lubrication and film)
    // of the last call; a 22-entry record has no damping force (zero), a
    // 16-entry one no spring and slip either, a 13-entry one image 0 too, a
    // 10-entry one no contact force either (zero), a 7-entry one starts the
    // spring from k delta
    const List<scalarList> records =
        immersedSpheroids::readCheckedOrDefault<List<scalarList>>
        (
            dict, "collisionPairs", List<scalarList>(),
            "a list of (first second warm dx dy dz contactTime springForce"
            " stiffness overlap fx fy fz ix iy iz tx ty tz sx sy sz gx gy gz)"
        );
    std::vector<collision::PairRecord> history;
    for (const scalarList& r : records)
    {
        if
        (
            r.size() != 25 && r.size() != 22 && r.size() != 16 && r.size() != 13
         && r.size() != 10 && r.size() != 7
        )
        {
            immersedSpheroids::entryError
            (
                dict, "collisionPairs",
                "a record has " + std::to_string(r.size()) + " entries; allowed:"
                " 25 (first second warm dx dy dz contactTime springForce"
                " stiffness overlap fx fy fz ix iy iz tx ty tz sx sy sz gx gy"
                " gz), 22 (without the damping force), 16 (without the"
                " tangential spring and slip either), 13 (without the image"
                " either), 10 (without the contact force either) or 7"
                " (without the last eighteen)"
            );
        }
        collision::PairRecord p;
        p.first = label(r[0]);
        p.second = label(r[1]);
        p.warm = r[2] > 0.5;
        p.direction = collision::Vec3(r[3], r[4], r[5]);
        p.contactTime = r[6];
        if (r.size() >= 10)
        {
            p.springForce = r[7];
            p.stiffness = r[8];
            p.overlap = r[9];
        }
        if (r.size() >= 13)
        {
            p.contactForce = collision::Vec3(r[10], r[11], r[12]);
        }
        if (r.size() >= 16)
        {
            for (int d = 0; d < 3; ++d)
            {
                p.image[d] = int(std::lround(r[13 + d]));
            }
        }
        if (r.size() >= 22)
        {
            p.tangentialSpring = collision::Vec3(r[16], r[17], r[18]);
            p.tangentialSlip = collision::Vec3(r[19], r[20], r[21]);
        }
        if (r.size() == 25)
        {
            p.dampingForce = collision::Vec3(r[22], r[23], r[24]);
        }
        history.push_back(p);
    }
    try
    {
        model_->setHistory(history);
    }
    catch (const std::exception& err)
    {
        immersedSpheroids::entryError(dict, "collisionPairs", err.what());
    }
}


Foam::List<Foam::FixedList<Foam::scalar, 25>>
Foam::collisionModels::contact::historyRecords() const
{
    const std::vector<collision::PairRecord> history = model_->history();
    List<FixedList<scalar, 25>> records(label(history.size()));
    forAll(records, i)
    {
        const collision::PairRecord& p = history[i];
        records[i] = FixedList<scalar, 25>
        ({
            scalar(p.first), scalar(p.second), p.warm ? 1.0 : 0.0,
            p.direction.x(), p.direction.y(), p.direction.z(), p.contactTime,
            p.springForce, p.stiffness, p.overlap,
            p.contactForce.x(), p.contactForce.y(), p.contactForce.z(),
            scalar(p.image[0]), scalar(p.image[1]), scalar(p.image[2]),
            p.tangentialSpring.x(), p.tangentialSpring.y(),
            p.tangentialSpring.z(),
            p.tangentialSlip.x(), p.tangentialSlip.y(), p.tangentialSlip.z(),
            p.dampingForce.x(), p.dampingForce.y(), p.dampingForce.z()
        });
    }
    return records;
}


void Foam::collisionModels::contact::collectHistory() const
{
    if (!Pstream::parRun())
    {
        return;
    }
    // each rank holds the history of the pairs it owns: all of them on the
    // master, in the order of (first, second, image) as a serial run has them
    List<List<FixedList<scalar, 25>>> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = historyRecords();
    Pstream::gatherList(all);
    collected_.clear();
    if (Pstream::master())
    {
        for (const List<FixedList<scalar, 25>>& records : all)
        {
            collected_.append(records);
        }
        auto order = [](const FixedList<scalar, 25>& r)
        {
            return std::make_tuple(r[0], r[1], r[13], r[14], r[15]);
        };
        std::sort
        (
            collected_.begin(), collected_.end(),
            [&](const FixedList<scalar, 25>& a, const FixedList<scalar, 25>& b)
            {
                return order(a) < order(b);
            }
        );
    }
}


void Foam::collisionModels::contact::writeHistory(Ostream& os) const
{
    if (Pstream::parRun())
    {
        os.writeEntry("collisionPairs", collected_);
    }
    else
    {
        os.writeEntry("collisionPairs", historyRecords());
    }
}


// ************************************************************************* //
