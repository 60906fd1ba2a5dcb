/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "immersedBodies.H"
#include "StringStream.H"
#include "processCpuTime.H"
#include "dictionaryChecks.H"
#include "packingBodies.H"
#include "bodyChecks.H"
#include "Enum.H"
#include "IFstream.H"
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
constexpr scalar softCellStepsDefault = 1;
constexpr collision::Range softCellStepsRange{0, 100, true, false};
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

//- The penalty in the cells across a face from another body's terms, where
//  two bodies touch (the same two choices)
constexpr wallCellPenaltyType contactCellPenaltyDefault = wallCellPenaltyType::soft;

//- Stop the run if a keyword stands twice in one dictionary of the file
//  (two bodies of one name, a setting given twice): OpenFOAM keeps the
//  last silently. The file is read again with duplicates as errors (a
//  top-level read resets the input mode, a dictionary's read does not).
void checkDuplicateEntries(const fileName& file)
{
    if (!Pstream::master() || !isFile(file))
    {
        return;
    }
    IFstream is(file);
    const entry::inputMode before = entry::globalInputMode;
    entry::globalInputMode = entry::inputMode::ERROR;
    dictionary dict;
    dict.read(is);
    entry::globalInputMode = before;
}

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


bool Foam::immersedBodies::readRestartState()
{
    // the master's copy of the state (writeObject writes only that one),
    // sent to every rank: any decomposition restarts from the same state
    bool found = Pstream::master() && headerOk();
    Pstream::scatter(found);
    if (!found)
    {
        // every rank names the master's file, the one that is read
        fileName statePath = objectPath();
        Pstream::scatter(statePath);
        // a fresh start, unless the run continues from a later time than
        // the first of the case: then the bodies' state is lost
        const scalar t = mesh_.time().value();
        for (const instant& i : mesh_.time().times())
        {
            if (i.name() != mesh_.time().constant() && i.value() < t - 1e-12*mag(t))
            {
                FatalErrorInFunction
                    << "The run starts at t = " << t << " after the case's"
                    << " time " << i.name() << ", but " << statePath
                    << " (the bodies' state at the start time, written by"
                    << " this module at every write time) is missing: the"
                    << " bodies would restart from "
                    << properties_.objectPath() << " while the fluid"
                    << " continues. Restart from a time written with the"
                    << " bodies, or move the earlier time directories away to"
                    << " start the bodies afresh at t = " << t << nl
                    << exit(FatalError);
            }
        }
        return false;
    }

    // sent as text and parsed on each rank (ASCII, as written: a dictionary
    // sent in the binary Pstream format cannot read back its lists)
    string text;
    fileName path(objectPath());
    if (Pstream::master())
    {
        OStringStream os;
        os << dictionary(readStream(typeName));
        close();
        text = os.str();
    }
    Pstream::scatter(text);
    Pstream::scatter(path);
    IStringStream is(text);
    dictionary dict(is);
    dict.name() = path;  // the messages name the file on every rank

    using namespace immersedSpheroids;
    restartEta_ = readCheckedOrDefault<scalar>
    (
        dict, "eta", 0, "the penalty time scale [s]"
    );
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
    integrator_->collision().readHistory(dict);
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
    domain_(mesh),
    fluidDensity_(0),
    UName_(UNameDefault),
    penaltyRatio_(penaltyRatioDefault),
    updateIndex_(-1),
    restartEta_(0),
    lastDeltaT_(0),
    ddtScheme_(immersedSpheroids::ddtCoefficients::scheme::Euler),
    solveDdt_(),
    updateCpu_(0)
{
    using namespace immersedSpheroids;

    checkDuplicateEntries(properties_.filePath());

    checkKeywords
    (
        properties_,
        wordList
        ({
            "fluidDensity", "U", "forcing", "penaltyRatio", "wallCellPenalty",
            "contactCellPenalty", "softCellSteps", "subSteps",
            "virtualMass", "bodies", "packing", "output", "collision",
            "filmStabilisation", "filmGap", "filmDampingScale", "viscosity",
            "meanFlow", "maxViscousNumber"
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
    const wallCellPenaltyType wallCells = readOptionalEnum
    (
        properties_, "wallCellPenalty", wallCellPenaltyNames,
        wallCellPenaltyDefault,
        "the penalty time scale in the cells on a wall patch: soft, eta"
        " at least the fluid's own time scale there; stiff, eta everywhere"
    );
    const wallCellPenaltyType contactCells = readOptionalEnum
    (
        properties_, "contactCellPenalty", wallCellPenaltyNames,
        contactCellPenaltyDefault,
        "the penalty in the cells across a face from another body's cells"
        " (two bodies touching): soft, at most the fluid's own rate c/dt;"
        " stiff, 1/eta"
    );
    if
    (
        wallCells == wallCellPenaltyType::stiff
     && contactCells == wallCellPenaltyType::stiff
     && properties_.found("softCellSteps")
    )
    {
        entryError
        (
            properties_, "softCellSteps",
            "is used only with soft wall or contact cells (wallCellPenalty"
            " and contactCellPenalty are stiff here); remove it"
        );
    }
    const scalar softCellSteps = readOptionalInRange<scalar>
    (
        properties_, "softCellSteps", softCellStepsDefault, softCellStepsRange,
        "the soft cells' penalty time scale over the fluid's own, dt/c,"
    );
    const label subSteps = readOptionalInRange<label>
    (
        properties_, "subSteps", subStepsDefault, subStepsRange,
        "the number of body sub-steps per time step, an integer"
    );
    const scalar virtualMass = readOptionalInRange<scalar>
    (
        properties_, "virtualMass", virtualMassDefault, virtualMassRange,
        "the virtual-mass coefficient C_v of the stabilisation (0: off)"
    );

    readBodies();
    const filmCorrection film
    (
        properties_, mesh_, fluidDensity_,
        collisionModel::selectedType(properties_) != "none"
    );

    const penaltyForcing::method forcing = readOptionalEnum
    (
        properties_, "forcing", penaltyForcing::methodNames,
        penaltyForcing::method::surfaceCorrected,
        "the penalty method: surfaceCorrected (the wall at the surface,"
        " second order, steady answers independent of dt) or cutCellFraction"
        " (solid-fraction coefficient, first order, for comparison)"
    );
    forcing_.reset
    (
        new penaltyForcing
        (
            mesh, forcing, wallCells == wallCellPenaltyType::soft,
            contactCells == wallCellPenaltyType::soft,
            softCellSteps,
            forcing == penaltyForcing::method::surfaceCorrected
          ? film.viscosity()/fluidDensity_
          : 0,
            domain_, UName_
        )
    );
    integrator_.reset
    (
        new bodyIntegrator
        (
            mesh, properties_, bodies_, fluidDensity_, subSteps, virtualMass,
            film
        )
    );
    ddtScheme_ = immersedSpheroids::ddtCoefficients::read(mesh, UName_);
    meanFlow_.reset(new meanFlowForcing(properties_, mesh_, domain_));
    viscousLimit_.reset
    (
        new viscousNumberLimit
        (
            properties_, mesh_, UName_, film.viscosity()/fluidDensity_,
            fluidDensity_, virtualMass,
            max(domain_.period(0), max(domain_.period(1), domain_.period(2)))
        )
    );

    const bool restarted = readRestartState();
    if (!restarted)
    {
        const scalar t = mesh.time().value();
        for (immersedBody& body : bodies_)
        {
            body.motion().initialise(body.state(), t);
            body.wrapCentre(domain_);
        }
    }
    const string start
    (
        restarted
      ? "at the start (from the restart state " + objectPath() + ")"
      : "at the start (from " + properties_.objectPath() + ")"
    );
    checkReplicatedState(bodies_, start);
    integrator_->checkOverlaps(bodies_, restarted);
    checkInsideMesh
    (
        mesh, domain_, bodies_, start, integrator_->collision().wallOverlapCap()
    );
    checkResolution(mesh, bodies_);

    output_.reset
    (
        new immersedBodiesOutput
        (
            *this,
            properties_.subOrEmptyDict("output")
        )
    );

    Info<< "immersedBodies: " << bodies_.size() << " bodies, rho_f "
        << fluidDensity_ << ", forcing "
        << penaltyForcing::methodNames[forcing_->forcingMethod()]
        << ", eta = " << penaltyRatio_ << " deltaT, "
        << subSteps << " sub-step(s) per step";
    if (virtualMass > 0)
    {
        Info<< ", virtual mass C_v " << virtualMass;
    }
    wordList fixedFlux;
    for (const label patchi : penaltyForcing::fixedFluxPatches(mesh, UName_))
    {
        fixedFlux.append(mesh.boundaryMesh()[patchi].name());
    }
    Info<< ", wall cells " << wallCellPenaltyNames[wallCells]
        << " (on patches " << fixedFlux << ")"
        << ", contact cells " << wallCellPenaltyNames[contactCells];
    if (softCellSteps != softCellStepsDefault)
    {
        Info<< " (soft cells over " << softCellSteps << " steps)";
    }
    Info
        << ", periodic axes " << domain_.describe().c_str()
        << ", meanFlow "
        << meanFlowForcing::conditionNames[meanFlow_->active()
          ? meanFlowForcing::condition::zeroFlux : meanFlowForcing::condition::none];
    if (mag(integrator_->g()) > 0)
    {
        Info<< ", g " << integrator_->g();
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
    using immersedSpheroids::processCpuTime;
    const double cpu0 = processCpuTime();
    double lap = cpu0;
    // the CPU time since the last lap [s]
    auto split = [&lap]()
    {
        const double now = processCpuTime();
        const double t = now - lap;
        lap = now;
        return t;
    };

    const scalar dt = time.deltaTValue();
    const scalar t0 = time.value() - dt;

    if (updateIndex_ < 0)
    {
        // first update of this run: the cells and the penalty of the solve
        // that produced U (none at the start of a fresh run: eta 0)
        forcing_->updateCells(bodies_);
        forcing_->assemble(bodies_, restartEta_, lastDeltaT_, solveDdt_.c);
        output_->start(t0);
    }
    const double setupCpu = split();

    loads_.update(bodies_, *forcing_, U, fluidDensity_, solveDdt_, lastDeltaT_, debug);
    const double loadsCpu = split();
    // the coefficients of the fluid solve that takes the bodies' new
    // velocities (the virtual-mass term and the forcing of that solve)
    const immersedSpheroids::ddtCoefficients ddt =
        immersedSpheroids::ddtCoefficients::of
        (
            ddtScheme_, time.timeIndex(), dt, time.deltaT0Value()
        );
    integrator_->collision().resetSubStepCpu();
    integrator_->advance(bodies_, t0, dt, ddt);
    for (immersedBody& body : bodies_)
    {
        body.wrapCentre(domain_);
    }
    const double motionCpu = split();
    const double subStepCpu = integrator_->collision().subStepCpu();
    const double collectiveCpu = integrator_->collision().collectiveCpu();
    const string afterStep("after the step to t = " + time.timeName());
    immersedSpheroids::checkReplicatedState(bodies_, afterStep);
    immersedSpheroids::checkInsideMesh
    (
        mesh_, domain_, bodies_, afterStep,
        integrator_->collision().wallOverlapCap()
    );
    const double checksCpu = split();
    forcing_->updateCells(bodies_);
    forcing_->assemble(bodies_, penaltyRatio_*dt, dt, ddt.c);
    meanFlow_->update(bodies_, fluidDensity_, integrator_->g(), U, dt, ddt.c);
    viscousLimit_->check(bodies_, dt);
    solveDdt_ = ddt;
    lastDeltaT_ = dt;
    updateIndex_ = time.timeIndex();
    const double cellsCpu = split();

    output_->append();
    const double outputCpu = split();

    // the module's cost: this update by part, and the penalty terms of the
    // last step
    const scalar lastPenaltyCpu = forcing_->cpu();
    forcing_->resetCpu();
    updateCpu_ = (processCpuTime() - cpu0);
    Info<< "immersedBodies: " << bodies_.size() << " bodies, "
        << returnReduce(forcing_->nCells(), sumOp<label>())
        << " covered cells, " << returnReduce(forcing_->nTerms(), sumOp<label>())
        << " penalty terms, CPU update " << updateCpu_ << " s (loads "
        << loadsCpu << ", motion " << motionCpu << " of which sub-steps "
        << subStepCpu;
    if (Pstream::parRun())
    {
        // (the exchanges of the sub-steps and the wait for the other ranks)
        Info<< " (collectives " << collectiveCpu << ")";
    }
    Info<< ", checks " << checksCpu << ", cells "
        << cellsCpu + setupCpu << ", output " << outputCpu
        << "), penalty (last step) " << lastPenaltyCpu << " s"
        << ", " << viscousLimit_->describe().c_str();
    if (Pstream::parRun())
    {
        // the rank with the most bodies in its cells (each rank's forcing
        // and load work is over those)
        label local = 0;
        for (const immersedBody& body : bodies_)
        {
            local += body.cells().size() > 0;
        }
        Info<< ", bodies in a rank's cells (max) "
            << returnReduce(local, maxOp<label>());
    }
    Info<< endl;
    if (meanFlow_->active())
    {
        Info<< "immersedBodies: " << meanFlow_->describe(fluidDensity_).c_str() << endl;
    }
}


void Foam::immersedBodies::checkUpdated() const
{
    if (updateIndex_ != mesh_.time().timeIndex())
    {
        FatalErrorInFunction
            << "immersedBodies::update(U) was not called in this time step"
            << " (time " << mesh_.time().timeName() << "): the penalty would"
            << " be that of the previous step" << nl << exit(FatalError);
    }
}


void Foam::immersedBodies::addPenalty(fvVectorMatrix& source) const
{
    checkUpdated();
    forcing_->addTo(source);
    meanFlow_->addTo(source);
}


Foam::tmp<Foam::fvVectorMatrix>
Foam::immersedBodies::penalty(const volVectorField& U) const
{
    checkUpdated();
    tmp<fvVectorMatrix> tsource = forcing_->penalty(U);
    meanFlow_->addTo(tsource.ref());
    return tsource;
}


Foam::tmp<Foam::volScalarField> Foam::immersedBodies::solidFraction() const
{
    return forcing_->solidFraction();
}


Foam::tmp<Foam::volVectorField> Foam::immersedBodies::bodyVelocity() const
{
    return forcing_->bodyVelocity();
}


// ************************************************************************* //
