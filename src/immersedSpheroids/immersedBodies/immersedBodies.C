/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "immersedBodies.H"
#include "wallPolyPatch.H"
#include "processCpuTime.H"
#include "cellSolidFraction.H"
#include "dictionaryChecks.H"
#include "packingBodies.H"
#include "uniformDimensionedFields.H"
#include "Enum.H"
#include "collision/Range.hpp"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(immersedBodies, 0);
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// The defaults and ranges of the top-level settings (the members' initial
// values and the reader's checks and messages)

//- The name of the velocity field
const char* const UNameDefault = "U";

//- eta/deltaT, the penalty time scale over the time step
constexpr scalar penaltyRatioDefault = 1e-3;
constexpr collision::Range penaltyRatioRange{0, 1, true, false};

//- Body sub-steps per fluid time step (the collision model may ask for more)
constexpr label subStepsDefault = 1;
constexpr collision::Range subStepsRange{1, 100000};

//- The virtual-mass coefficient C_v of the stabilisation (0: off)
constexpr scalar virtualMassDefault = 0.5;
constexpr collision::Range virtualMassRange{0, 10};

//- The penalty time scale in the cells on a wall patch
enum class wallCellPenaltyType { soft, stiff };
const Enum<wallCellPenaltyType> wallCellPenaltyNames
({
    { wallCellPenaltyType::soft, "soft" },
    { wallCellPenaltyType::stiff, "stiff" },
});
constexpr wallCellPenaltyType wallCellPenaltyDefault = wallCellPenaltyType::soft;

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::immersedBodies::readBodies()
{
    using namespace immersedSpheroids;

    const bool hasBodies = properties_.found("bodies");
    const bool hasPacking = properties_.found("packing");
    if (!hasBodies && !hasPacking)
    {
        entryError
        (
            properties_, "bodies",
            "is missing: give a bodies { name { ... } ... } dictionary"
            " and/or a packing { file ...; } dictionary"
        );
    }

    if (hasBodies)
    {
        if (!properties_.isDict("bodies"))
        {
            entryError
            (
                properties_, "bodies",
                "must be a dictionary of bodies: bodies { name { semiAxes ...; } }"
            );
        }
        const dictionary& bodiesDict = properties_.subDict("bodies");
        for (const entry& e : bodiesDict)
        {
            if (!e.isDict())
            {
                entryError
                (
                    bodiesDict, e.keyword(),
                    "must be a body dictionary { semiAxes ...; density ...;"
                    " centre ...; motion { type ...; } }"
                );
            }
            bodies_.append(new immersedBody(e.keyword(), e.dict()));
        }
    }

    if (hasPacking)
    {
        if (!properties_.isDict("packing"))
        {
            entryError
            (
                properties_, "packing",
                "must be a dictionary: packing { file ...; density ...;"
                " motion { type ...; } }"
            );
        }
        readPackingBodies(properties_.subDict("packing"), mesh_.time(), bodies_);
    }

    if (bodies_.empty())
    {
        entryError(properties_, "bodies", "lists no body");
    }

    // unique names (the time series and the restart state are keyed by them)
    wordHashSet names;
    for (const immersedBody& body : bodies_)
    {
        if (!names.insert(body.name()))
        {
            entryError
            (
                properties_, "bodies",
                "has two bodies named '" + body.name() + "'"
            );
        }
    }
}


void Foam::immersedBodies::readGravity()
{
    g_ = Zero;
    bool needed = false;
    for (const immersedBody& body : bodies_)
    {
        needed = needed || body.motion().isFreeInTranslation();
    }
    if (!needed)
    {
        return;
    }

    IOobject gIO
    (
        "g",
        mesh_.time().constant(),
        mesh_,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );
    if (!gIO.typeHeaderOk<uniformDimensionedVectorField>(true))
    {
        FatalErrorInFunction
            << "A body is free in translation, which needs gravity: the file "
            << gIO.objectPath() << " (uniformDimensionedVectorField g, e.g."
            << " value (0 0 -9.81);) is missing" << nl
            << exit(FatalError);
    }
    const uniformDimensionedVectorField g(gIO);
    if (g.dimensions() != dimAcceleration)
    {
        FatalIOErrorInFunction(gIO.objectPath())
            << "Entry 'dimensions' of " << gIO.objectPath()
            << " must be those of an acceleration " << dimAcceleration
            << ", not " << g.dimensions() << nl
            << exit(FatalIOError);
    }
    g_ = g.value();
}


bool Foam::immersedBodies::readRestartState()
{
    if (!headerOk())
    {
        return false;
    }

    const dictionary dict(readStream(typeName));
    close();

    using namespace immersedSpheroids;
    eta_ = readCheckedOrDefault<scalar>(dict, "eta", 0, "the penalty time scale [s]");
    lastDeltaT_ = readCheckedOrDefault<scalar>
    (
        dict, "deltaT", 0, "the time step of the last update [s]"
    );
    const FixedList<scalar, 3> ddt = readCheckedOrDefault<FixedList<scalar, 3>>
    (
        dict, "ddtCoefficients", FixedList<scalar, 3>({1, 1, 0}),
        "(c c0 c00), the ddt coefficients of the last solve"
    );
    solveDdt_.c = ddt[0];
    solveDdt_.c0 = ddt[1];
    solveDdt_.c00 = ddt[2];
    if (!dict.isDict("bodies"))
    {
        entryError(dict, "bodies", "is missing (restart state of each body)");
    }
    const dictionary& states = dict.subDict("bodies");
    for (immersedBody& body : bodies_)
    {
        if (!states.isDict(body.name()))
        {
            entryError
            (
                states, body.name(),
                "is missing: the restart state has no body of this name"
                " (bodies may not be added or renamed on restart)"
            );
        }
        body.readState(states.subDict(body.name()));
    }
    collision_->readHistory(dict);
    return true;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::immersedBodies::immersedBodies(const fvMesh& mesh)
:
    regIOobject
    (
        IOobject
        (
            typeName,
            mesh.time().timeName(),
            "uniform",
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        )
    ),
    mesh_(mesh),
    properties_
    (
        IOobject
        (
            "immersedBodiesProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    ),
    fluidDensity_(0),
    UName_(UNameDefault),
    penaltyRatio_(penaltyRatioDefault),
    subSteps_(subStepsDefault),
    virtualMass_(virtualMassDefault),
    g_(Zero),
    cellRadius_(immersedSpheroids::cellRadii(mesh)),
    updateIndex_(-1),
    eta_(0),
    lastDeltaT_(0),
    ddtScheme_(immersedSpheroids::ddtCoefficients::scheme::Euler),
    solveDdt_(),
    cellsFound_(false),
    softWallCells_(wallCellPenaltyDefault == wallCellPenaltyType::soft),
    wallCell_(mesh.nCells(), false),
    cellSlot_(mesh.nCells(), -1),
    updateCpu_(0),
    penaltyCpu_(0)
{
    using namespace immersedSpheroids;

    checkKeywords
    (
        properties_,
        wordList
        ({
            "fluidDensity", "U", "penaltyRatio", "wallCellPenalty", "subSteps",
            "virtualMass", "bodies", "packing", "output", "collision",
            "filmStabilisation", "filmGap", "viscosity"
        })
    );
    fluidDensity_ = readPositive
    (
        properties_, "fluidDensity", "the fluid density rho_f [kg/m^3], > 0"
    );
    UName_ = readCheckedOrDefault<word>
    (
        properties_, "U", word(UNameDefault), "the name of the velocity field"
    );
    penaltyRatio_ = readOptionalInRange<scalar>
    (
        properties_, "penaltyRatio", penaltyRatioDefault, penaltyRatioRange,
        "eta/deltaT, the penalty time scale over the time step,"
    );
    softWallCells_ =
    (
        readOptionalEnum
        (
            properties_, "wallCellPenalty", wallCellPenaltyNames,
            wallCellPenaltyDefault,
            "the penalty time scale in the cells on a wall patch: soft, eta"
            " at least the fluid's own time scale there; stiff, eta everywhere"
        )
     == wallCellPenaltyType::soft
    );
    forAll(mesh.boundaryMesh(), patchi)
    {
        const polyPatch& pp = mesh.boundaryMesh()[patchi];
        if (isA<wallPolyPatch>(pp))
        {
            for (const label celli : pp.faceCells())
            {
                wallCell_[celli] = true;
            }
        }
    }

    subSteps_ = readOptionalInRange<label>
    (
        properties_, "subSteps", subStepsDefault, subStepsRange,
        "the number of body sub-steps per time step, an integer"
    );
    virtualMass_ = readOptionalInRange<scalar>
    (
        properties_, "virtualMass", virtualMassDefault, virtualMassRange,
        "the virtual-mass coefficient C_v of the stabilisation (0: off)"
    );

    readBodies();
    readGravity();
    const filmCorrection film
    (
        properties_, mesh_, fluidDensity_,
        collisionModel::selectedType(properties_) != "none"
    );
    collision_ = collisionModel::New(properties_, mesh_, film);
    ddtScheme_ = immersedSpheroids::ddtCoefficients::read(mesh, UName_);

    if (!readRestartState())
    {
        const scalar t = mesh.time().value();
        for (immersedBody& body : bodies_)
        {
            body.motion().initialise(body.state(), t);
        }
    }

    bodySlots_.setSize(bodies_.size());

    output_.reset
    (
        new immersedBodiesOutput
        (
            *this,
            properties_.subOrEmptyDict("output")
        )
    );

    Info<< "immersedBodies: " << bodies_.size() << " bodies, rho_f "
        << fluidDensity_ << ", eta = " << penaltyRatio_ << " deltaT, "
        << subSteps_ << " sub-step(s) per step";
    if (virtualMass_ > 0)
    {
        Info<< ", virtual mass C_v " << virtualMass_;
    }
    Info<< ", wall cells "
        << wallCellPenaltyNames
           [
               softWallCells_ ? wallCellPenaltyType::soft : wallCellPenaltyType::stiff
           ];
    if (mag(g_) > 0)
    {
        Info<< ", g " << g_;
    }
    Info<< endl;
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::immersedBodies& Foam::immersedBodies::New(const fvMesh& mesh)
{
    immersedBodies* ptr = mesh.getObjectPtr<immersedBodies>(typeName);
    if (!ptr)
    {
        ptr = new immersedBodies(mesh);
        regIOobject::store(ptr);
    }
    return *ptr;
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * //

Foam::immersedBodies::~immersedBodies()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::immersedBodies::update(const volVectorField& U)
{
    const Time& time = mesh_.time();
    if (time.timeIndex() == updateIndex_)
    {
        return;
    }
    const double cpu0 = immersedSpheroids::processCpuTime();

    const scalar dt = time.deltaTValue();
    const scalar t0 = time.value() - dt;

    if (updateIndex_ < 0)
    {
        // first update of this run: the cells and the penalty of the solve
        // that produced U (none at the start of a fresh run: eta_ = 0)
        updateCells();
        assemblePenalty(eta_, lastDeltaT_, solveDdt_.c);
        output_->start(t0);
    }

    computeForces(U);
    advanceBodies(t0, dt);
    updateCells();

    const immersedSpheroids::ddtCoefficients ddt =
        immersedSpheroids::ddtCoefficients::of
        (
            ddtScheme_, time.timeIndex(), dt, time.deltaT0Value()
        );
    assemblePenalty(penaltyRatio_*dt, dt, ddt.c);
    solveDdt_ = ddt;
    lastDeltaT_ = dt;
    updateIndex_ = time.timeIndex();

    output_->append(time.value());

    // the module's cost: this update, and the penalty terms of the last step
    const scalar lastPenaltyCpu = penaltyCpu_;
    penaltyCpu_ = 0;
    updateCpu_ = (immersedSpheroids::processCpuTime() - cpu0);
    Info<< "immersedBodies: " << bodies_.size() << " bodies, "
        << returnReduce(penaltyCells_.size(), sumOp<label>())
        << " covered cells, CPU update " << updateCpu_
        << " s, penalty (last step) " << lastPenaltyCpu << " s" << endl;
}


// ************************************************************************* //
