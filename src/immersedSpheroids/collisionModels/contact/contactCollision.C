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

//- An optional scalar in [lo, hi]
scalar optionalInRange
(
    const dictionary& dict,
    const word& keyword,
    const scalar deflt,
    const scalar lo,
    const scalar hi,
    const string& expected
)
{
    const scalar v =
        immersedSpheroids::readCheckedOrDefault<scalar>(dict, keyword, deflt, expected);
    if (!(v >= lo && v <= hi))
    {
        immersedSpheroids::entryError
        (
            dict, keyword,
            "is " + Foam::name(v) + "; allowed: " + expected
        );
    }
    return v;
}

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

    collision::CollisionSettings s;
    s.mode = mode;
    s.contact.restitution = optionalInRange
    (
        dict, "restitution", 0.97, 1e-6, 1,
        "the dry restitution coefficient e in (0, 1] (default 0.97)"
    );
    s.contact.friction = optionalInRange
    (
        dict, "friction", 0, 0, 100,
        "the Coulomb friction coefficient in [0, 100] (default 0)"
    );
    s.subStepsPerContact = label
    (
        optionalInRange
        (
            dict, "subStepsPerContact", 10, 4, 10000,
            "the body sub-steps per contact time, an integer in [4, 10000]"
            " (default 10)"
        )
    );
    s.maxOverlap = optionalInRange
    (
        dict, "maxOverlap", 0.1, 1e-6, 0.5,
        "the largest overlap over the smallest semi-axis in (0, 0.5]"
        " (default 0.1)"
    );
    s.distanceAccuracy = optionalInRange
    (
        dict, "distanceAccuracy", 1e-5, 1e-12, 0.1,
        "eps_d over the smallest Gaussian curvature radius of the pair, in"
        " [1e-12, 0.1] (default 1e-5)"
    );
    s.maxSubSteps = label
    (
        optionalInRange
        (
            dict, "maxSubSteps", 100000, 1, 1e9,
            "the largest number of body sub-steps per fluid step, in [1, 1e9]"
            " (default 100000)"
        )
    );
    s.filmStabilisation = readCheckedOrDefault<bool>
    (
        dict, "filmStabilisation", true,
        "yes or no (default yes): the film correction for the pairs closer than filmGap"
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
        s.lubrication.saturation = optionalInRange
        (
            dict, "saturation", 1e-3, 1e-12, 0.5,
            "the saturation gap ratio eps_sat in (0, 0.5] (default 1e-3)"
        );
        s.lubrication.pairActivation = optionalInRange
        (
            dict, "pairActivation", 0.025, s.lubrication.saturation*(1 + 1e-12), 1,
            "the pair activation gap ratio 2h/(R1 + R2) in (saturation, 1]"
            " (default 0.025)"
        );
        s.lubrication.wallActivation = optionalInRange
        (
            dict, "wallActivation", 0.075, s.lubrication.saturation*(1 + 1e-12), 1,
            "the wall activation gap ratio h/R in (saturation, 1]"
            " (default 0.075)"
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
        optionalInRange
        (
            dict, "contactSteps", 10, 1e-3, 1e6,
            "the contact time over the fluid time step, T_c/deltaT, in"
            " [1e-3, 1e6] (default 10)"
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
    // fx fy fz); the 10-entry form of earlier versions has no contact force
    // (zero), the 7-entry form starts the spring from k delta
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
