/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
License
    GPL-3.0-or-later (as OpenFOAM).

\*---------------------------------------------------------------------------*/

#include "viscousNumberLimit.H"
#include "dictionaryChecks.H"
#include "surfaceFields.H"
#include "volFields.H"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <utility>

// * * * * * * * * * * * * * * * Local Constants * * * * * * * * * * * * * * //

namespace
{

using Foam::label;
using Foam::scalar;

//- The limits the module enforces, from validation/viscousNumber
//  (results/moduleLimits.md, which derives them from the measured scans):
//  {free body, momentum predictor, consistent (SIMPLEC), outer correctors
//  (outerMode), pressure correctors, limit at 16 cells per equal-volume
//  diameter, exponent p, density ratio rho_p/rho_f and virtual-mass
//  coefficient C_v of a free body's scan (0 for fixed bodies)}
struct measuredSetting
{
    bool freeBody;
    bool momentumPredictor;
    bool consistent;
    label outer;
    label nCorrectors;
    //- The limit at referenceCellsPerDiameter cells per D_eq
    scalar limit;
    //- p of the limit's resolution law limit (reference/c)^p
    scalar exponent;
    //- The free body's density ratio rho_p/rho_f (0: any)
    scalar densityRatio;
    //- The free body's virtual-mass coefficient C_v (0 for fixed bodies)
    scalar virtualMass;
};

//- The resolution the table's limits are given at (cells per equal-volume
//  diameter)
constexpr scalar referenceCellsPerDiameter = 16;

//- The side of the periodic box of the fixed-body scans, in equal-volume
//  diameters: in a longer period the limit is taken to fall as it does with
//  the resolution (the scans in boxes of 6 and 8 D_eq; boxes of 12 and 16
//  D_eq fall less, so the rule is conservative there)
constexpr scalar scannedPeriod = 4;

constexpr measuredSetting measuredLimits[] =
{
    // VISCOUS_NUMBER_LIMITS_BEGIN (checked against moduleLimits.md by
    // tests/foam/viscousNumberQuick)
    {false, false, false, 0, 1, 843, 1.28, 0, 0},
    {false, false, false, 0, 2, 843, 1.28, 0, 0},
    {false, true, false, 0, 1, 0.0865, 1.28, 0, 0},
    {false, true, false, 1, 1, 0.0727, 1.28, 0, 0},
    {false, true, false, 2, 1, 0.346, 1.28, 0, 0},
    {false, true, false, 0, 2, 1.99, 1.25, 0, 0},
    {false, true, true, 0, 2, 4.41, 0.26, 0, 0},
    {false, true, false, 1, 2, 1.95, 1.28, 0, 0},
    {false, true, false, 2, 2, 5.53, 1.28, 0, 0},
    {false, true, false, 0, 3, 22.1, 1.28, 0, 0},
    {false, true, false, 1, 3, 22.1, 1.28, 0, 0},
    {false, true, false, 0, 4, 74.5, 1.28, 0, 0},
    {true, false, false, 0, 2, 1, 0, 0.1, 0},
    {true, false, false, 0, 2, 1.68, 0, 0.1, 0.5},
    {true, false, false, 0, 2, 1, 0, 0.3, 0},
    {true, false, false, 0, 2, 1.68, 0, 0.3, 0.5},
    {true, false, false, 0, 2, 1.18, 0, 0.5, 0},
    {true, false, false, 0, 2, 1.68, 0, 0.5, 0.5},
    {true, false, false, 0, 2, 1.68, 0, 1.16, 0},
    {true, false, false, 0, 2, 2.37, 0, 1.16, 0.5},
    {true, false, false, 0, 2, 2, 0, 2, 0},
    {true, false, false, 0, 2, 2.82, 0, 2, 0.5},
    {true, false, false, 0, 2, 4.75, 0, 8, 0},
    {true, false, false, 0, 2, 4.75, 0, 8, 0.5},
    {true, true, false, 0, 2, 1, 0, 0.1, 0},
    {true, true, false, 0, 2, 1.41, 0, 0.1, 0.5},
    {true, true, false, 0, 2, 1, 0, 0.3, 0},
    {true, true, false, 0, 2, 1.68, 0, 0.3, 0.5},
    {true, true, false, 0, 2, 1.18, 0, 0.5, 0},
    {true, true, false, 0, 2, 1.68, 0, 0.5, 0.5},
    {true, true, false, 0, 2, 1.41, 0, 1.16, 0},
    {true, true, false, 0, 2, 2, 0, 1.16, 0.5},
    {true, true, false, 0, 2, 2, 0, 2, 0},
    {true, true, false, 0, 2, 2.82, 0, 2, 0.5},
    {true, true, false, 0, 2, 3.36, 0, 8, 0},
    {true, true, false, 0, 2, 3.36, 0, 8, 0.5},
    {true, true, true, 0, 2, 4, 0, 0.1, 0},
    {true, true, true, 0, 2, 4, 0, 0.1, 0.5},
    {true, true, true, 0, 2, 4, 0, 0.3, 0},
    {true, true, true, 0, 2, 4, 0, 0.3, 0.5},
    {true, true, true, 0, 2, 4, 0, 0.5, 0},
    {true, true, true, 0, 2, 4, 0, 0.5, 0.5},
    {true, true, true, 0, 2, 4, 0, 1.16, 0},
    {true, true, true, 0, 2, 4, 0, 1.16, 0.5},
    {true, true, true, 0, 2, 4, 0, 2, 0},
    {true, true, true, 0, 2, 4, 0, 2, 0.5},
    {true, true, true, 0, 2, 4, 0, 8, 0},
    {true, true, true, 0, 2, 4, 0, 8, 0.5},
    {true, true, false, 0, 3, 2.37, 0, 0.1, 0},
    {true, true, false, 0, 3, 3.36, 0, 0.1, 0.5},
    {true, true, false, 0, 3, 2.82, 0, 0.3, 0},
    {true, true, false, 0, 3, 4, 0, 0.3, 0.5},
    {true, true, false, 0, 3, 2.82, 0, 0.5, 0},
    {true, true, false, 0, 3, 4.75, 0, 0.5, 0.5},
    {true, true, false, 0, 3, 4, 0, 1.16, 0},
    {true, true, false, 0, 3, 4.75, 0, 1.16, 0.5},
    {true, true, false, 0, 3, 4.75, 0, 2, 0},
    {true, true, false, 0, 3, 5.65, 0, 2, 0.5},
    {true, true, false, 0, 3, 8, 0, 8, 0},
    {true, true, false, 0, 3, 9.51, 0, 8, 0.5},
    {true, true, false, 0, 4, 3.36, 0, 0.1, 0},
    {true, true, false, 0, 4, 4.75, 0, 0.1, 0.5},
    {true, true, false, 0, 4, 4, 0, 0.3, 0},
    {true, true, false, 0, 4, 5.65, 0, 0.3, 0.5},
    {true, true, false, 0, 4, 4, 0, 0.5, 0},
    {true, true, false, 0, 4, 5.65, 0, 0.5, 0.5},
    {true, true, false, 0, 4, 4.75, 0, 1.16, 0},
    {true, true, false, 0, 4, 6.72, 0, 1.16, 0.5},
    {true, true, false, 0, 4, 5.65, 0, 2, 0},
    {true, true, false, 0, 4, 6.72, 0, 2, 0.5},
    {true, true, false, 0, 4, 13.4, 0, 8, 0},
    {true, true, false, 0, 4, 13.4, 0, 8, 0.5}
    // VISCOUS_NUMBER_LIMITS_END
};

//- The entries nearest to value by key among those keep accepts: the one
//  with the largest key up to value and the one with the smallest key above
//  it (nullptr where there is none)
template<class Keep, class Key>
std::pair<const measuredSetting*, const measuredSetting*> bracket
(
    const Keep& keep,
    const Key& key,
    const scalar value
)
{
    const measuredSetting* below = nullptr;
    const measuredSetting* above = nullptr;
    for (const measuredSetting& m : measuredLimits)
    {
        if (!keep(m))
        {
            continue;
        }
        if (key(m) <= value)
        {
            if (!below || key(m) > key(*below))
            {
                below = &m;
            }
        }
        else if (!above || key(m) < key(*above))
        {
            above = &m;
        }
    }
    return {below, above};
}

//- The entry with the motion, predictor, pressure equation (the standard
//  one's where the consistent one was not measured) and outer correctors
//  (those of one outer corrector where none was measured), and the most
//  pressure correctors up to nCorrectors (fewer correctors are the less
//  stable), or else the fewest above it; nullptr if none
const measuredSetting* tableEntry
(
    const bool freeBody,
    const bool momentumPredictor,
    const bool consistent,
    const label outer,
    const label nCorrectors
)
{
    for (const bool simplec : {consistent, false})
    {
        for (const label mode : {outer, label(0)})
        {
            const auto nearest = bracket
            (
                [&](const measuredSetting& m)
                {
                    return
                        m.freeBody == freeBody
                     && m.momentumPredictor == momentumPredictor
                     && m.consistent == simplec
                     && m.outer == mode;
                },
                [](const measuredSetting& m) { return scalar(m.nCorrectors); },
                nCorrectors
            );
            if (nearest.first || nearest.second)
            {
                return nearest.first ? nearest.first : nearest.second;
            }
        }
    }
    return nullptr;
}

//- Whether m is a free entry with the settings of setting
bool sameFreeSetting(const measuredSetting& m, const measuredSetting& setting)
{
    return
        m.freeBody
     && m.momentumPredictor == setting.momentumPredictor
     && m.consistent == setting.consistent
     && m.outer == setting.outer
     && m.nCorrectors == setting.nCorrectors;
}

//- The smaller of the limits of the two entries of a bracket (the one entry's
//  outside the measured range)
scalar smallerLimit
(
    const std::pair<const measuredSetting*, const measuredSetting*>& nearest
)
{
    if (nearest.first && nearest.second)
    {
        return Foam::min(nearest.first->limit, nearest.second->limit);
    }
    return nearest.first ? nearest.first->limit : nearest.second->limit;
}

//- The limit of the free entries of setting's settings at densityRatio and
//  virtualMass: of the measured C_v that bracket virtualMass (the nearest
//  outside the measured range), the smaller of their limits, each the
//  smaller of the limits of the two measured density ratios that bracket
//  densityRatio (the nearest ratio's outside the measured range)
scalar freeLimitAt
(
    const measuredSetting& setting,
    const scalar densityRatio,
    const scalar virtualMass
)
{
    const auto levels = bracket
    (
        [&](const measuredSetting& m) { return sameFreeSetting(m, setting); },
        [](const measuredSetting& m) { return m.virtualMass; },
        virtualMass
    );
    scalar limit = Foam::GREAT;
    for (const measuredSetting* level : {levels.first, levels.second})
    {
        if (level)
        {
            const scalar cv = level->virtualMass;
            limit = Foam::min
            (
                limit,
                smallerLimit
                (
                    bracket
                    (
                        [&](const measuredSetting& m)
                        {
                            return
                                sameFreeSetting(m, setting)
                             && m.virtualMass == cv;
                        },
                        [](const measuredSetting& m)
                        {
                            return m.densityRatio;
                        },
                        densityRatio
                    )
                )
            );
        }
    }
    return limit;
}

//- v to 4 significant digits, for a message
std::string shortNumber(const scalar v)
{
    std::ostringstream os;
    os << std::setprecision(4) << v;
    return os.str();
}

//- v rounded down to 3 significant digits (a bound that stays below v)
scalar floorSignificant(const scalar v)
{
    if (!(v > 0))
    {
        return v;
    }
    const scalar unit = std::pow(10.0, std::floor(std::log10(v)) - 2);
    return std::floor(v/unit)*unit;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::viscousNumberLimit::viscousNumberLimit
(
    const dictionary& properties,
    const fvMesh& mesh,
    const word& UName,
    const scalar nu,
    const scalar fluidDensity,
    const scalar virtualMass,
    const scalar longestPeriod
)
:
    mesh_(mesh),
    UName_(UName),
    nu_(nu),
    fluidDensity_(fluidDensity),
    virtualMass_(virtualMass),
    longestPeriod_(longestPeriod),
    userLimit_(0),
    inverseSquareSpacing_(mesh.nCells(), scalar(0)),
    lastMax_(0),
    lastLimit_(GREAT)
{
    if (properties.found("maxViscousNumber"))
    {
        userLimit_ = immersedSpheroids::readPositive
        (
            properties, "maxViscousNumber",
            "the largest viscous number nu deltaT/h^2 allowed in the bodies'"
            " cells, > 0 (default: the limit measured for the PIMPLE settings"
            " of system/fvSolution)"
        );
    }

    // sum_f |S_f| deltaCoeff_f over each cell's faces, the patches' included
    // (the diffusion to a wall, or across a processor or cyclic patch)
    const surfaceScalarField& deltaCoeffs = mesh.nonOrthDeltaCoeffs();
    const surfaceScalarField& magSf = mesh.magSf();
    const labelUList& owner = mesh.owner();
    const labelUList& neighbour = mesh.neighbour();
    forAll(owner, facei)
    {
        const scalar g = magSf[facei]*deltaCoeffs[facei];
        inverseSquareSpacing_[owner[facei]] += g;
        inverseSquareSpacing_[neighbour[facei]] += g;
    }
    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& patch = mesh.boundary()[patchi];
        const scalarField& pd = deltaCoeffs.boundaryField()[patchi];
        const scalarField& pS = magSf.boundaryField()[patchi];
        const labelUList& cells = patch.faceCells();
        forAll(cells, i)
        {
            inverseSquareSpacing_[cells[i]] += pS[i]*pd[i];
        }
    }
    inverseSquareSpacing_ /= 6*mesh.V().field();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::viscousNumberLimit::settings
Foam::viscousNumberLimit::readSettings() const
{
    settings s{word::null, true, false, 1, 1, label(outerMode::single)};
    const dictionary& solution = mesh_.solutionDict();
    for (const word algorithm : {"PIMPLE", "PISO"})
    {
        if (solution.found(algorithm))
        {
            const dictionary& dict = solution.subDict(algorithm);
            // the defaults of OpenFOAM's solutionControl and pisoControl
            s.dictName = algorithm;
            s.momentumPredictor =
                dict.lookupOrDefault<bool>("momentumPredictor", true);
            s.consistent = dict.lookupOrDefault<bool>("consistent", false);
            s.nCorrectors = dict.lookupOrDefault<label>("nCorrectors", 1);
            s.nOuterCorrectors =
                dict.lookupOrDefault<label>("nOuterCorrectors", 1);
            // the outer correctors but the last may relax the momentum
            // equation
            s.outer =
                s.nOuterCorrectors <= 1 ? label(outerMode::single)
              : mesh_.relaxEquation(UName_)
             && mesh_.equationRelaxationFactor(UName_) < 1
              ? label(outerMode::relaxed)
              : label(outerMode::unrelaxed);
            break;
        }
    }
    return s;
}


Foam::scalar Foam::viscousNumberLimit::measuredLimit
(
    const bool freeBody,
    const bool momentumPredictor,
    const bool consistent,
    const label outer,
    const label nCorrectors,
    const scalar cellsPerDiameter,
    const scalar densityRatio,
    const scalar virtualMass
)
{
    auto atResolution = [cellsPerDiameter](const measuredSetting& m)
    {
        return
            m.limit
           *std::pow(referenceCellsPerDiameter/cellsPerDiameter, m.exponent);
    };
    // a fixed body's limit bounds a free one's (the body's response to the
    // force adds to the coupling's instability)
    const measuredSetting* fixed =
        tableEntry(false, momentumPredictor, consistent, outer, nCorrectors);
    const scalar fixedLimit = fixed ? atResolution(*fixed) : 0;
    if (!freeBody)
    {
        return fixedLimit;
    }
    const measuredSetting* free =
        tableEntry(true, momentumPredictor, consistent, outer, nCorrectors);
    return
        free
      ? min(fixedLimit, freeLimitAt(*free, densityRatio, virtualMass))
      : fixedLimit;
}


Foam::scalar Foam::viscousNumberLimit::limit
(
    const immersedBody& body,
    const scalar cellsPerDiameter,
    const settings& s
) const
{
    if (userLimit_ > 0)
    {
        return userLimit_;
    }
    return
        s.dictName.empty()
      ? GREAT
      : measuredLimit
        (
            body.motion().isFree(), s.momentumPredictor, s.consistent,
            s.outer, s.nCorrectors, cellsPerDiameter,
            body.density()/fluidDensity_, virtualMass_
        );
}


std::string Foam::viscousNumberLimit::describe() const
{
    return
        "viscous number " + shortNumber(lastMax_) + " (limit "
      + (lastLimit_ < GREAT ? shortNumber(lastLimit_) : std::string("none"))
      + ")";
}


void Foam::viscousNumberLimit::stop
(
    const immersedBody& body,
    const scalar lambda,
    const scalar lim,
    const scalar bodyCells,
    const scalar periodScale,
    const scalar dt,
    const settings& s
) const
{
    const scalar cells = bodyCells*periodScale;
    const bool freeBody = body.motion().isFree();
    const scalar ratio = body.density()/fluidDensity_;
    // the limit of this body with the momentum predictor and other pressure
    // correctors, or the consistent pressure equation
    auto alternative = [&](const bool consistent, const label nCorrectors)
    {
        return
            shortNumber
            (
                measuredLimit
                (
                    freeBody, true, consistent, s.outer, nCorrectors, cells,
                    ratio, virtualMass_
                )
            );
    };
    const std::string alternatives =
        "momentumPredictor yes with nCorrectors 2 / 3 / 4: "
      + alternative(false, 2) + " / " + alternative(false, 3) + " / "
      + alternative(false, 4) + ", consistent yes with 2: "
      + alternative(true, 2);
    // the body, its resolution and the settings its limit was measured for
    const std::string measured =
        (
            freeBody
          ? "a free body of density ratio " + shortNumber(ratio)
          + " and virtual mass C_v " + shortNumber(virtualMass_)
          : std::string("a fixed or prescribed body")
        )
      + " at " + shortNumber(bodyCells)
      + " cells per equal-volume diameter"
      + (
            periodScale > 1
          ? " in a period of " + shortNumber(scannedPeriod*periodScale)
          + " D_eq (as limiting as " + shortNumber(cells)
          + " cells per D_eq in the scans' period of "
          + shortNumber(scannedPeriod) + " D_eq)"
          : std::string()
        )
      + " with " + s.dictName + " momentumPredictor "
      + (s.momentumPredictor ? "yes" : "no")
      + (s.consistent ? ", consistent yes" : "") + ", nCorrectors "
      + std::to_string(s.nCorrectors) + " and nOuterCorrectors "
      + std::to_string(s.nOuterCorrectors)
      + (s.outer == label(outerMode::relaxed) ? " (relaxed)" : "")
      + " in system/fvSolution";

    const std::string where =
        userLimit_ > 0
      ? std::string("maxViscousNumber of constant/immersedBodiesProperties")
      : "the limit measured (validation/viscousNumber) for " + measured;
    FatalErrorInFunction
        << "the viscous number nu deltaT/h^2 in the cells of body '"
        << body.name() << "' is " << shortNumber(lambda).c_str()
        << " at deltaT " << shortNumber(dt).c_str() << ", above "
        << shortNumber(lim).c_str() << ", " << where.c_str() << nl
        << "    Above it the pressure-velocity coupling grows a period-two"
        << " oscillation until the run fails." << nl
        << "    Allowed: deltaT <= "
        << shortNumber(floorSignificant(dt*lim/lambda)).c_str()
        << " (maxDeltaT in system/controlDict), or settings with a higher"
        << " limit for this body: " << alternatives.c_str()
        << ", or maxViscousNumber in constant/immersedBodiesProperties"
        << " for a set-up shown stable above it."
        << exit(FatalError);
}


Foam::scalar Foam::viscousNumberLimit::check
(
    const PtrList<immersedBody>& bodies,
    const scalar dt
)
{
    // per body: the largest viscous number over its cells (on every rank)
    scalarList bodyMax(bodies.size(), scalar(0));
    forAll(bodies, bodyi)
    {
        for (const label celli : bodies[bodyi].cells())
        {
            bodyMax[bodyi] =
                max(bodyMax[bodyi], nu_*dt*inverseSquareSpacing_[celli]);
        }
    }
    Pstream::listCombineGather(bodyMax, maxEqOp<scalar>());
    Pstream::listCombineScatter(bodyMax);

    // per body: its cells per equal-volume diameter at its finest cell
    // (lambda = nu dt/h^2) and its limit there; in a periodic domain whose
    // longest period exceeds the scans' box, at the resolution that has as
    // many cells across the scans' box as the body has across that period
    const settings s = readSettings();
    scalarList bodyLimit(bodies.size(), GREAT);
    scalarList bodyCells(bodies.size(), scalar(0));
    scalarList periodScale(bodies.size(), scalar(1));
    label worst = -1;
    forAll(bodies, bodyi)
    {
        if (!(bodyMax[bodyi] > 0))
        {
            continue;
        }
        const vector& axes = bodies[bodyi].semiAxes();
        const scalar dEq = 2*std::cbrt(axes.x()*axes.y()*axes.z());
        bodyCells[bodyi] = dEq*std::sqrt(bodyMax[bodyi]/(nu_*dt));
        periodScale[bodyi] =
            max(scalar(1), longestPeriod_/(scannedPeriod*dEq));
        bodyLimit[bodyi] =
            limit(bodies[bodyi], bodyCells[bodyi]*periodScale[bodyi], s);
        // the largest ratio of value to limit, compared without dividing (a
        // measured limit may be 0)
        if
        (
            worst < 0
         || bodyMax[bodyi]*bodyLimit[worst] > bodyMax[worst]*bodyLimit[bodyi]
        )
        {
            worst = bodyi;
        }
    }
    lastMax_ = bodyMax.empty() ? 0 : max(bodyMax);
    lastLimit_ = bodyLimit.empty() ? GREAT : min(bodyLimit);
    if (worst < 0 || bodyMax[worst] <= bodyLimit[worst])
    {
        return lastMax_;
    }

    stop
    (
        bodies[worst], bodyMax[worst], bodyLimit[worst], bodyCells[worst],
        periodScale[worst], dt, s
    );
    return lastMax_;
}


// ************************************************************************* //
