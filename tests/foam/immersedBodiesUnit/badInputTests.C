/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
Description
    4. Bad input: broken versions of constant/immersedBodiesProperties are
    written into the case and immersedBodies(mesh) constructed from each:
    a FatalIOError whose message names the keyword (or the bad value) and
    whose file is constant/immersedBodiesProperties. A free body without
    constant/g is a FatalError naming g. The good file is restored at the
    end.
\*---------------------------------------------------------------------------*/

#include "immersedBodiesTests.H"
#include "immersedBodies.H"
#include "collision/CollisionModel.hpp"
#include <fstream>

using namespace testChecks;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

const char* const header =
    "FoamFile { version 2.0; format ascii; class dictionary;"
    " object immersedBodiesProperties; }\n";

const std::string goodBody =
    "semiAxes (0.1 0.05 0.05); density 1100; centre (0.5 0.5 0.5);"
    " motion { type fixed; }";

void writeProperties(const fileName& file, const std::string& text)
{
    std::ofstream os(file.c_str());
    os << header << text << '\n';
}

} // End anonymous namespace


void immersedBodiesTests::testBadInput(const Time& runTime, const fvMesh& mesh)
{
    const fileName file = runTime.path()/runTime.constant()/"immersedBodiesProperties";
    const fileName saved = file + ".good";
    if (!Foam::cp(file, saved))
    {
        check(false, "bad input: cannot copy " + file + " to " + saved);
        return;
    }
    const bool throwingFatal = FatalError.throwExceptions(true);

    const std::string fname("immersedBodiesProperties");
    const std::string output = " output { timeSeries no; surfaces no; }";

    // Write text as the file and construct the bodies from it
    auto constructRaw = [&](const std::string& text)
    {
        return [&, text]()
        {
            writeProperties(file, text);
            immersedBodies bodies(mesh);
        };
    };
    // The same for expectFatalIOError: a FatalError that is not an IO error
    // (FatalError throws in this part) is shown and swallowed, so that the
    // check fails as "no FatalIOError raised"
    auto construct = [&](const std::string& text)
    {
        return [&, text]()
        {
            try
            {
                constructRaw(text)();
            }
            catch (const Foam::IOerror&)
            {
                throw;
            }
            catch (const Foam::error& err)
            {
                Info<< "    a FatalError, not a FatalIOError: "
                    << err.message().c_str() << endl;
            }
        };
    };
    auto withBody = [&](const std::string& body)
    {
        return "fluidDensity 1000;" + output + " bodies { b1 { " + body + " } }";
    };

    // Construct from text; passes if no error is raised
    auto expectConstructs = [&](const std::string& text, const std::string& what)
    {
        bool ok = true;
        const bool throwing = FatalIOError.throwExceptions();
        try
        {
            constructRaw(text)();
        }
        catch (const Foam::error& err)
        {
            ok = false;
            Info<< err.message().c_str() << endl;
        }
        FatalIOError.throwExceptions(throwing);
        check(ok, "bad input: " + what);
    };

    // The writer and the construction work: a good file constructs
    expectConstructs(withBody(goodBody), "the good reference file constructs");

    expectFatalIOError
    (
        construct(withBody("semiAxes (0.1 0.05 0.05); density 1100; centre (0.5 0.5 0.5);")),
        {"'motion'", fname},
        "missing motion"
    );
    expectFatalIOError
    (
        construct(withBody("semiAxes (0.1 0.05 0.05); density 1100; centre (0.5 0.5 0.5); motion { type floating; }")),
        {"floating", "fixed", "prescribed", "free", "freeTranslation", "freeRotation", fname},
        "unknown motion type lists the allowed types"
    );
    expectFatalIOError
    (
        construct(withBody("semiAxes (0.1 0.05 0.05); density 1100; centre (0.5 0.5 0.5); motion { }")),
        {"'type'", "fixed", fname},
        "motion without type"
    );
    expectFatalIOError
    (
        construct(withBody("semiAxes (0.1 -0.05 0.05); density 1100; centre (0.5 0.5 0.5); motion { type fixed; }")),
        {"'semiAxes'", "> 0", fname},
        "negative semi-axis"
    );
    expectFatalIOError
    (
        construct(withBody("semiAxes (0.1 0 0.05); density 1100; centre (0.5 0.5 0.5); motion { type fixed; }")),
        {"'semiAxes'", "> 0", fname},
        "zero semi-axis"
    );
    expectFatalIOError
    (
        construct(withBody("semiAxes (0.1 0.05 0.05); density -1100; centre (0.5 0.5 0.5); motion { type fixed; }")),
        {"'density'", "> 0", fname},
        "negative density"
    );
    expectFatalIOError
    (
        construct(output + " bodies { b1 { " + goodBody + " } }"),
        {"'fluidDensity'", "missing", fname},
        "missing fluidDensity"
    );
    for (const char* ratio : {"0", "1.5", "-1e-3"})
    {
        expectFatalIOError
        (
            construct("penaltyRatio " + std::string(ratio) + "; " + withBody(goodBody)),
            {"'penaltyRatio'", "(0, 1]", fname},
            std::string("penaltyRatio ") + ratio + " out of (0, 1]"
        );
    }
    expectFatalIOError
    (
        construct("wallCellPenalty hard; " + withBody(goodBody)),
        {"'wallCellPenalty'", "soft", "stiff", "hard", fname},
        "wallCellPenalty not soft or stiff"
    );
    expectFatalIOError
    (
        construct("softCellSteps 0; " + withBody(goodBody)),
        {"'softCellSteps'", "(0, 100]", fname},
        "softCellSteps out of (0, 100]"
    );
    expectFatalIOError
    (
        construct
        (
            "wallCellPenalty stiff; contactCellPenalty stiff; softCellSteps 2; "
          + withBody(goodBody)
        ),
        {"'softCellSteps'", "soft wall or contact cells", fname},
        "softCellSteps with stiff wall and contact cells"
    );
    expectFatalIOError
    (
        construct
        (
            "collision { type contact; } filmDampingScale 0; " + withBody(goodBody)
        ),
        {
            "'filmDampingScale'",
            collision::FilmCorrection::kDampingScaleRange.str(),
            fname
        },
        "filmDampingScale out of range"
    );
    expectFatalIOError
    (
        construct
        (
            "collision { type contact; } filmStabilisation no;"
            " filmDampingScale 2; " + withBody(goodBody)
        ),
        {"'filmDampingScale'", "filmStabilisation yes", fname},
        "filmDampingScale without the film correction"
    );
    expectFatalIOError
    (
        construct
        (
            "collision { type contact; sustainedLoadOverlap 1.5; } "
          + withBody(goodBody)
        ),
        {
            "'sustainedLoadOverlap'",
            collision::ContactParameters::kSustainedLoadOverlapRange.str(),
            fname
        },
        "collision sustainedLoadOverlap out of range"
    );
    expectFatalIOError
    (
        construct("contactCellPenalty firm; " + withBody(goodBody)),
        {"'contactCellPenalty'", "soft", "stiff", "firm", fname},
        "contactCellPenalty not soft or stiff"
    );
    // Collision settings out of range: the message shows the range of the
    // collision core's constants, which validate() checks too
    expectFatalIOError
    (
        construct
        (
            "collision { type contact; maxOverlap 0.7; } " + withBody(goodBody)
        ),
        {
            "'maxOverlap'",
            collision::CollisionSettings::kMaxOverlapRange.str(),
            fname
        },
        "collision maxOverlap out of range"
    );
    expectFatalIOError
    (
        construct
        (
            "collision { type contact; subStepsPerContact 2; } "
          + withBody(goodBody)
        ),
        {
            "'subStepsPerContact'",
            collision::CollisionSettings::kSubStepsPerContactRange.str(),
            fname
        },
        "collision subStepsPerContact out of range"
    );
    expectFatalIOError
    (
        construct
        (
            "collision { type lubricationContact;"
            " pairActivation 2; } viscosity 1e-3; " + withBody(goodBody)
        ),
        {
            "'pairActivation'",
            collision::LubricationParameters().activationRange().str(),
            fname
        },
        "collision pairActivation out of range"
    );
    expectFatalIOError
    (
        construct
        (
            "collision { type lubricationContact; wallActivation 0.1;"
            " wallResolvedGapCells 1; } viscosity 1e-3; " + withBody(goodBody)
        ),
        {"'wallResolvedGapCells'", "wallActivation", "give one of them", fname},
        "collision activation given both as a ratio and in cells"
    );
    expectFatalIOError
    (
        construct
        (
            "collision { type lubricationContact;"
            " pairResolvedGapCells 0; } viscosity 1e-3; " + withBody(goodBody)
        ),
        {
            "'pairResolvedGapCells'",
            collision::LubricationParameters::kCellsRange.str(),
            fname
        },
        "collision pairResolvedGapCells out of range"
    );
    expectFatalIOError
    (
        construct
        (
            "collision { type lubrication; } " + withBody(goodBody)
        ),
        {"lubrication", "contact, lubricationContact, none", fname},
        "unknown collision type lists the allowed types"
    );
    expectFatalIOError
    (
        construct
        (
            "collision { type contact; pairModel hertz; } filmStabilisation no; "
          + withBody(goodBody)
        ),
        {"'pairModel'", "hertz", "springDashpot, lubricatedSpringDashpot", fname},
        "unknown pair model lists the allowed models"
    );
    // a distance method that cannot serve (it does not certify eps_d)
    expectFatalIOError
    (
        construct
        (
            "collision { type contact; distanceMethod newtonCoulomb; }"
            " filmStabilisation no; " + withBody(goodBody)
        ),
        {
            "'distanceMethod'", "newtonCoulomb",
            "dual, paper, auto, gjk, movingBalls", fname
        },
        "unknown distance method lists the allowed methods"
    );
    expectFatalIOError
    (
        construct
        (
            "collision { type none; } filmStabilisation yes; "
          + withBody(goodBody)
        ),
        {"'filmStabilisation'", "collision", "type", fname},
        "film correction without a collision model"
    );
    expectFatalIOError
    (
        construct
        (
            "collision { type contact; } filmStabilisation no; viscosity 1e-3;"
            " forcing cutCellFraction; "
          + withBody(goodBody)
        ),
        {"'viscosity'", "remove it", fname},
        "viscosity nothing uses"
    );
    expectFatalIOError
    (
        construct("forcing directForcing; " + withBody(goodBody)),
        {"'forcing'", "surfaceCorrected", "cutCellFraction", fname},
        "unknown forcing"
    );
    expectFatalIOError
    (
        construct("penaltyRatoi 1e-3; " + withBody(goodBody)),
        {"penaltyRatoi", "Allowed keywords", "penaltyRatio", fname},
        "misspelt top-level keyword"
    );
    expectFatalIOError
    (
        construct(withBody("semiAxes (0.1 0.05 0.05); densty 1100; centre (0.5 0.5 0.5); motion { type fixed; }")),
        {"densty", "Allowed keywords", fname},
        "misspelt body keyword"
    );
    expectFatalIOError
    (
        construct(withBody("semiAxes (0.1 0.05 0.05); density 1100; centre (0.5 0.5 0.5); motion { type prescribed; velocty (1 0 0); }")),
        {"velocty", "Allowed keywords", fname},
        "misspelt motion keyword"
    );
    expectFatalIOError
    (
        construct(withBody("semiAxes (0.1 0.05 0.05); density 1100; centre (0.5 0.5 0.5); motion { type prescribed; frozen maybe; }")),
        {"frozen", "yes or no", fname},
        "a frozen entry that is not yes or no"
    );
    expectFatalIOError
    (
        construct(withBody("semiAxes (0.1 0.05 0.05); density 1100; centre middle; motion { type fixed; }")),
        {"'centre'", "expected", fname},
        "word where a vector is expected"
    );
    expectFatalIOError
    (
        construct(withBody("semiAxes 0.1; density 1100; centre (0.5 0.5 0.5); motion { type fixed; }")),
        {"'semiAxes'", "expected", fname},
        "scalar where a vector is expected"
    );
    expectFatalIOError
    (
        construct("fluidDensity water; " + output + " bodies { b1 { " + goodBody + " } }"),
        {"'fluidDensity'", "water", fname},
        "word where a number is expected"
    );
    expectFatalIOError
    (
        construct(withBody("semiAxes (0.1 0.05 0.05); density 1100; centre (0.5 0.5 0.5); motion { type prescribed; velocity (1 fast 0); }")),
        {"velocity", fname},
        "word inside a prescribed velocity"
    );
    expectFatalIOError
    (
        construct(withBody("semiAxes (0.1 0.05 0.05); density 1100; centre (0.5 0.5 0.5); orientation (1 0 0 0.5); motion { type fixed; }")),
        {"'orientation'", "unit", "differs from 1 by more than 0.0001", fname},
        "orientation not a unit quaternion, the tolerance stated"
    );
    // four significant digits are a unit quaternion
    expectConstructs
    (
        withBody("semiAxes (0.1 0.05 0.05); density 1100; centre (0.5 0.5 0.5); orientation (0.7071 0 0 0.7071); motion { type fixed; }"),
        "orientation (0.7071 0 0 0.7071) is accepted"
    );
    expectFatalIOError
    (
        construct("fluidDensity 1000;" + output + " bodies { b1 { " + goodBody + " } b1 { " + goodBody + " } }"),
        {"duplicate entry", "b1", fname},
        "two bodies of one name"
    );
    expectFatalIOError
    (
        construct("fluidDensity 1000; fluidDensity 900;" + output + " bodies { b1 { " + goodBody + " } }"),
        {"duplicate entry", "fluidDensity", fname},
        "a setting given twice"
    );
    expectFatalIOError
    (
        construct(withBody("semiAxes (0.1 0.05 0.05); density 1100; centre (0.5 0.5 0.5); motion { type prescribed; velocity table ((0 (1 0 0)) (0.5 (0 1 0)) (0.2 (0 0 1))); }")),
        {"'velocity'", "not a valid function of time", "out-of-order", fname},
        "a prescribed table with times out of order"
    );
    expectFatalIOError
    (
        construct("fluidDensity 1000;" + output + " bodies { b1 { " + goodBody + " } } collision { type contact; walls (walls walls); }"),
        {"'walls'", "twice", fname},
        "a wall patch named twice"
    );
    expectFatalIOError
    (
        construct(withBody("semiAxes (0.1 0.05 0.05); density 1100; centre (0.5 0.5 0.5); orientation (1 0 0 0); axis (1 0 0); motion { type fixed; }")),
        {"'axis'", "orientation", fname},
        "both orientation and axis"
    );
    expectFatalIOError
    (
        construct("fluidDensity 1000;" + output),
        {"'bodies'", "packing", fname},
        "neither bodies nor packing"
    );
    expectFatalIOError
    (
        construct("subSteps 0; " + withBody(goodBody)),
        {"'subSteps'", fname},
        "subSteps 0"
    );
    expectFatalIOError
    (
        construct
        (
            "fluidDensity 1000;" + output + " packing { file \"constant/noSuchPacking.h5\";"
            " density 1100; motion { type fixed; } }"
        ),
        {"'file'", "noSuchPacking.h5", fname},
        "packing file that does not exist"
    );
    expectFatalIOError
    (
        construct
        (
            "fluidDensity 1000;" + output + " packing { density 1100; motion { type fixed; } }"
        ),
        {"'file'", "missing", fname},
        "packing without file"
    );

    // A body free in translation needs constant/g, which this case lacks
    expectFatalError
    (
        constructRaw(withBody("semiAxes (0.1 0.05 0.05); density 1100; centre (0.5 0.5 0.5); motion { type free; }")),
        {"gravity", "constant/g"},
        "free body without constant/g"
    );

    // The output dictionary: every keyword accepted, range and misspelling
    // checked
    {
        std::string problem;
        const bool throwing = FatalIOError.throwExceptions();
        try
        {
            constructRaw
            (
                "fluidDensity 1000; bodies { b1 { " + goodBody + " } }"
                " output { timeSeries no; timeSeriesControl timeStep;"
                " timeSeriesInterval 2; surfaces no; surfaceSubdivisions 3;"
                " solidFraction no; }"
            )();
        }
        catch (const Foam::error& err)
        {
            problem = err.message();
        }
        FatalIOError.throwExceptions(throwing);
        check
        (
            problem.empty(),
            "output dictionary with all its keywords constructs"
          + (problem.empty() ? std::string() : ": " + problem)
        );
    }
    expectFatalIOError
    (
        construct
        (
            "fluidDensity 1000; bodies { b1 { " + goodBody + " } }"
            " output { timeSeries no; surfaces no; surfaceSubdivisions 9; }"
        ),
        {"'surfaceSubdivisions'", "[0, 8]", fname},
        "output surfaceSubdivisions out of range"
    );
    expectFatalIOError
    (
        construct
        (
            "fluidDensity 1000; bodies { b1 { " + goodBody + " } }"
            " output { timeSeries no; surfaces no; timeSeriesInterval 0; }"
        ),
        {"'timeSeriesInterval'", "[1, 1e+09]", "an integer", fname},
        "output timeSeriesInterval (steps) out of range"
    );
    expectFatalIOError
    (
        construct
        (
            "fluidDensity 1000; bodies { b1 { " + goodBody + " } }"
            " output { timeSeries no; surfaces no; timeSeriesInterval 2.5; }"
        ),
        {"timeSeriesInterval", fname},
        "output timeSeriesInterval (steps) not an integer"
    );
    expectFatalIOError
    (
        construct
        (
            "fluidDensity 1000; bodies { b1 { " + goodBody + " } }"
            " output { timeSeries no; surfaces no; timeSeriesControl everyStep; }"
        ),
        {"'timeSeriesControl'", "everyStep", "timeStep", "runTime", fname},
        "output timeSeriesControl not a control"
    );
    expectFatalIOError
    (
        construct
        (
            "fluidDensity 1000; bodies { b1 { " + goodBody + " } }"
            " output { timeSeries no; surfaces no; timeSeriesControl runTime; }"
        ),
        {"'timeSeriesInterval'", "missing", "(timeSeriesControl runTime)", fname},
        "output timeSeriesControl runTime without an interval"
    );
    expectFatalIOError
    (
        construct
        (
            "fluidDensity 1000; bodies { b1 { " + goodBody + " } }"
            " output { timeSeries no; surfaces no; timeSeriesControl runTime;"
            " timeSeriesInterval -0.1; }"
        ),
        {"'timeSeriesInterval'", "-0.1", "> 0", fname},
        "output timeSeriesInterval (time) out of range"
    );
    expectFatalIOError
    (
        construct
        (
            "fluidDensity 1000; bodies { b1 { " + goodBody + " } }"
            " output { timeSeries no; surfaces no; surfaceResolution 24; }"
        ),
        {"surfaceResolution", "Allowed keywords", "surfaceSubdivisions", fname},
        "unknown output keyword"
    );

    FatalError.throwExceptions(throwingFatal);
    Foam::mv(saved, file);
}


// ************************************************************************* //
