/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "contactCollision.H"
#include "immersedBody.H"
#include "coreConversions.H"
#include "collision/BodySet.hpp"
#include "collision/Range.hpp"
#include "planeWalls.H"
#include "dictionaryChecks.H"
#include "IOdictionary.H"
#include "volMesh.H"
#include "dimensionedScalar.H"
#include "addToRunTimeSelectionTable.H"

#include <cmath>
#include <limits>
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

//- The film gap: the filmGap entry, else the smallest cell size of the mesh
//  (the cube root of the smallest cell volume, over all ranks)
scalar readFilmGap(const dictionary& dict, const fvMesh& mesh)
{
    const string expected =
        "the film thickness below which the mesh cannot resolve the flow"
        " between two surfaces [m] > 0 (default: the smallest cell size)";
    if (dict.found("filmGap"))
    {
        return immersedSpheroids::readPositive(dict, "filmGap", expected);
    }
    scalar vMin = GREAT;
    for (const scalar v : mesh.V().field())
    {
        vMin = min(vMin, v);
    }
    reduce(vMin, minOp<scalar>());
    return std::cbrt(vMin);
}

//- The dynamic viscosity: the viscosity entry, else rho_f nu of
//  constant/transportProperties
scalar readViscosity
(
    const dictionary& dict,
    const fvMesh& mesh,
    const scalar fluidDensity
)
{
    const string expected =
        "the dynamic viscosity mu [Pa s] > 0 (default: fluidDensity x nu of"
        " constant/transportProperties)";
    if (dict.found("viscosity"))
    {
        return immersedSpheroids::readPositive(dict, "viscosity", expected);
    }
    IOdictionary transport
    (
        IOobject
        (
            "transportProperties",
            mesh.time().constant(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::NO_WRITE,
            false
        )
    );
    if (!transport.found("nu"))
    {
        immersedSpheroids::entryError
        (
            dict, "viscosity",
            "is missing and " + transport.objectPath()
          + " has no entry nu; expected " + expected
        );
    }
    const dimensionedScalar nu("nu", dimViscosity, transport);
    if (!(nu.value() > 0))
    {
        immersedSpheroids::entryError
        (
            transport, "nu",
            "must be > 0 for the lubrication force and the film correction"
        );
    }
    return fluidDensity*nu.value();
}

} // End anonymous namespace


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

::collision::CollisionSettings Foam::collisionModels::contact::readSettings
(
    const dictionary& dict,
    const fvMesh& mesh,
    const scalar fluidDensity,
    const collision::CollisionMode mode
)
{
    using namespace immersedSpheroids;
    const bool lubrication = mode == collision::CollisionMode::lubricationContact;

    wordList allowed
    ({
        "type", "walls", "restitution", "friction", "contactSteps",
        "subStepsPerContact", "maxOverlap", "distanceAccuracy", "maxSubSteps",
        "filmStabilisation", "filmGap", "viscosity"
    });
    if (lubrication)
    {
        allowed.append
        (
            wordList({"pairActivation", "wallActivation", "saturation"})
        );
    }
    checkKeywords(dict, allowed);

    // The defaults are those of a default-constructed settings struct, the
    // ranges its constants: validate() checks the same numbers
    using Settings = collision::CollisionSettings;
    using Contact = collision::ContactParameters;
    using Lubrication = collision::LubricationParameters;
    const Settings defaults;

    Settings s;
    s.mode = mode;
    s.contact.restitution = readOptionalInRange<scalar>
    (
        dict, "restitution", defaults.contact.restitution,
        Contact::kRestitutionRange, "the dry restitution coefficient e"
    );
    s.contact.friction = readOptionalInRange<scalar>
    (
        dict, "friction", defaults.contact.friction,
        Contact::kFrictionRange, "the Coulomb friction coefficient"
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
    s.filmStabilisation = readCheckedOrDefault<bool>
    (
        dict, "filmStabilisation", defaults.filmStabilisation,
        string("yes or no (default ")
      + (defaults.filmStabilisation ? "yes" : "no")
      + "): the film correction for the pairs closer than filmGap"
    );
    if (!s.filmStabilisation && dict.found("filmGap"))
    {
        entryError
        (
            dict, "filmGap",
            "is used only with filmStabilisation yes (it is no here); remove it"
        );
    }
    if (!lubrication && !s.filmStabilisation && dict.found("viscosity"))
    {
        entryError
        (
            dict, "viscosity",
            "is used only by type lubricationContact or by filmStabilisation"
            " yes (here type contact, filmStabilisation no); remove it"
        );
    }
    if (lubrication || s.filmStabilisation)
    {
        s.viscosity = readViscosity(dict, mesh, fluidDensity);
    }
    if (lubrication)
    {
        s.lubrication.saturation = readOptionalInRange<scalar>
        (
            dict, "saturation", defaults.lubrication.saturation,
            Lubrication::kSaturationRange,
            "the saturation gap ratio eps_sat"
        );
        s.lubrication.pairActivation = readOptionalInRange<scalar>
        (
            dict, "pairActivation", defaults.lubrication.pairActivation,
            s.lubrication.activationRange(),
            "the pair activation gap ratio 2h/(R1 + R2), above saturation,"
        );
        s.lubrication.wallActivation = readOptionalInRange<scalar>
        (
            dict, "wallActivation", defaults.lubrication.wallActivation,
            s.lubrication.activationRange(),
            "the wall activation gap ratio h/R, above saturation,"
        );
    }
    try
    {
        s.validate();
    }
    catch (const std::exception& err)
    {
        FatalIOErrorInFunction(dict)
            << "Invalid collision settings in " << dict.name() << ": "
            << err.what() << nl << exit(FatalIOError);
    }
    return s;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::collisionModels::contact::contact
(
    const dictionary& dict,
    const fvMesh& mesh,
    const scalar fluidDensity,
    const collision::CollisionMode mode
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
    model_
    (
        readSettings(dict, mesh, fluidDensity, mode),
        immersedSpheroids::planeWalls(mesh, dict, "walls")
    ),
    filmGap_
    (
        model_.settings().filmStabilisation ? readFilmGap(dict, mesh) : 0
    )
{
    const collision::CollisionSettings& s = model_.settings();
    Info<< "immersedBodies: collision model " << collision::toString(s.mode)
        << ": e " << s.contact.restitution << ", friction "
        << s.contact.friction << ", T_c = " << contactSteps_ << " deltaT, "
        << s.subStepsPerContact << " sub-steps per contact, max overlap "
        << s.maxOverlap << " a_min, eps_d " << s.distanceAccuracy << " R_G";
    if (s.mode == collision::CollisionMode::lubricationContact)
    {
        Info<< ", lubrication: mu " << s.viscosity << ", activation "
            << s.lubrication.pairActivation << " (pairs) "
            << s.lubrication.wallActivation << " (walls), saturation "
            << s.lubrication.saturation;
    }
    if (s.filmStabilisation)
    {
        Info<< ", film correction below " << filmGap_ << " m (mu " << s.viscosity
            << ")";
    }
    Info<< ", walls (";
    for (const collision::PlaneWall& w : model_.walls())
    {
        Info<< ' ' << w.name << " n = " << immersedSpheroids::toFoam(w.normal);
    }
    Info<< " )" << endl;
}


Foam::collisionModels::contact::contact
(
    const dictionary& dict,
    const fvMesh& mesh,
    const scalar fluidDensity
)
:
    contact(dict, mesh, fluidDensity, collision::CollisionMode::contact)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::collisionModels::contact::subSteps
(
    const collision::BodySet& bodies,
    const std::vector<collision::BodyState>& states,
    const scalar dt
)
{
    std::vector<collision::CollisionBody> collisionBodies;
    collisionBodies.reserve(states.size());
    for (std::size_t i = 0; i < states.size(); ++i)
    {
        collisionBodies.push_back(bodies.collisionBody(i, states[i]));
    }
    try
    {
        return model_.subSteps(collisionBodies, dt, contactSteps_*dt);
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << "Collision sub-steps of the step " << dt << " s: " << err.what()
            << nl << "    (raise maxSubSteps in the collision dictionary or"
            << " reduce deltaT)" << nl << exit(FatalError);
    }
    return 1;
}


void Foam::collisionModels::contact::report(const label nSubSteps)
{
    const collision::CollisionStatistics& st = model_.statistics();
    const scalar calls = max(evaluations_, 1);
    Info<< "collisions: " << nSubSteps << " sub-step(s), per evaluation "
        << st.candidatePairs/calls << " candidate pairs, "
        << st.prefilterRejected/calls << " out of reach by the overlap test, "
        << st.distanceQueries/calls << " distances ("
        << (st.distanceQueries ? scalar(st.distanceIterations)/st.distanceQueries : 0)
        << " iterations each); in contact now " << model_.activeContacts()
        << ", max overlap " << st.maxOverlapRatio << " a_min";
    if (model_.settings().mode == collision::CollisionMode::lubricationContact)
    {
        Info<< ", lubricated " << st.lubricated/calls;
    }
    if (model_.settings().filmStabilisation)
    {
        Info<< ", film pairs " << st.filmPairs/calls;
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
    if (st.distanceNotConverged > 0)
    {
        WarningInFunction
            << st.distanceNotConverged << " distance queries of this step did"
            << " not converge to distanceAccuracy "
            << model_.settings().distanceAccuracy
            << "; their last iterate (certified bracket) was used" << endl;
    }
    model_.resetStatistics();
    evaluations_ = 0;
}


void Foam::collisionModels::contact::readHistory(const dictionary& dict)
{
    // (first second warm dx dy dz contactTime springForce stiffness overlap
    // fx fy fz); a 10-entry record has no contact force (zero), a 7-entry
    // one starts the spring from k delta
    const List<scalarList> records =
        immersedSpheroids::readCheckedOrDefault<List<scalarList>>
        (
            dict, "collisionPairs", List<scalarList>(),
            "a list of (first second warm dx dy dz contactTime springForce"
            " stiffness overlap fx fy fz)"
        );
    std::vector<collision::PairRecord> history;
    for (const scalarList& r : records)
    {
        if (r.size() != 13 && r.size() != 10 && r.size() != 7)
        {
            immersedSpheroids::entryError
            (
                dict, "collisionPairs",
                "a record has " + std::to_string(r.size()) + " entries; allowed:"
                " 13 (first second warm dx dy dz contactTime springForce"
                " stiffness overlap fx fy fz), 10 (without the contact force)"
                " or 7 (without the last six)"
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
        if (r.size() == 13)
        {
            p.contactForce = collision::Vec3(r[10], r[11], r[12]);
        }
        history.push_back(p);
    }
    try
    {
        model_.setHistory(history);
    }
    catch (const std::exception& err)
    {
        immersedSpheroids::entryError(dict, "collisionPairs", err.what());
    }
}


void Foam::collisionModels::contact::writeHistory(Ostream& os) const
{
    const std::vector<collision::PairRecord> history = model_.history();
    List<FixedList<scalar, 13>> records(label(history.size()));
    forAll(records, i)
    {
        const collision::PairRecord& p = history[i];
        records[i] = FixedList<scalar, 13>
        ({
            scalar(p.first), scalar(p.second), p.warm ? 1.0 : 0.0,
            p.direction.x(), p.direction.y(), p.direction.z(), p.contactTime,
            p.springForce, p.stiffness, p.overlap,
            p.contactForce.x(), p.contactForce.y(), p.contactForce.z()
        });
    }
    os.writeEntry("collisionPairs", records);
}


// ************************************************************************* //
