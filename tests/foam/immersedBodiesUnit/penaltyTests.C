/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
Description
    3. Penalty (forcing cutCellFraction): the case's constant/immersedBodiesProperties holds one
    prolate spheroid with a prescribed constant velocity U_p and angular
    velocity omega in a closed unit box of fluid at rest (rho_f 1000,
    penaltyRatio r = eta/dt = 1e-3). Each step: runTime++,
    bodies.update(U), solve(fvm::ddt(U) == bodies.penalty(U)) (Euler).
    With no other term every cell is its own equation, so the implicit step
    is known in closed form. With k = alpha/(eta + (1 - alpha) dt) (the
    penalty coefficient of penaltyForcing.C) a covered cell gets
        u = ((1 + r - alpha) u_prev + alpha U_s)/(1 + r)
    and the checks are:
    - the body path: X = X0 + U_p t, R = exp(t [omega]x) R0;
    - bodyVelocity() = U_s = U_p + omega ^ (x - X) from the analytic path;
    - every covered cell follows the formula above (round-off);
    - in fully covered cells |u - U_s| <= 2 r/(1 + r) max|U_s|: the
      residual of one step is r/(1 + r) (u_prev - U_s), and |u_prev| <=
      max|U_s| (u is a convex combination of 0 and earlier U_s);
    - cells not covered keep their velocity (to the last bit but one: the
      solve divides u0 V/dt by V/dt), cells never covered stay exactly at
      rest;
    - the hydrodynamic force and torque reported at the next update equal
      minus the change of the momentum of the fluid outside the body:
      F = -rho_f [sum V (u - u_prev) - (P - P_prev)]/dt with P = sum alpha
      V u (the penalty force plus the internal-fluid term of
      immersedBodies.H), and for the impulsive start (fluid at rest) the
      momentum given to the fluid is rho_f sum alpha V U_s/(1 + r), the
      first force -rho_f sum alpha (1 - alpha) V U_s/((1 + r) dt), against
      the motion;
    - the cell list is a small part of the mesh, near the body.
\*---------------------------------------------------------------------------*/

#include "immersedBodiesTests.H"
#include "immersedBodies.H"
#include "cellSolidFraction.H"
#include "bitSet.H"

using namespace testChecks;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

void immersedBodiesTests::testPenalty(Time& runTime, const fvMesh& mesh)
{
    volVectorField U
    (
        IOobject
        (
            "U",
            runTime.timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedVector(dimVelocity, Zero)
    );

    immersedBodies bodies(mesh);
    if (!check(bodies.bodies().size() == 1, "penalty case: one body"))
    {
        return;
    }
    const immersedBody& body = bodies.bodies()[0];
    const scalar rhoF = bodies.fluidDensity();
    check(rhoF == 1000, "penalty case: fluidDensity 1000");

    // The analytic path (values of constant/immersedBodiesProperties)
    const point X0(0.35, 0.45, 0.5);
    const vector Up(0.5, 0.2, 0);
    const vector omega(0, 0.5, 2);
    const scalar r = 1e-3;
    const tensor R0 = rodrigues(vector(0, 0, 1), constant::mathematical::pi/4);
    check
    (
        mag(body.state().centre - X0) < 1e-15 && maxAbs(body.state().R() - R0) < 1e-15
     && body.state().velocity == Up && body.state().angularVelocity == omega,
        "penalty case: initial state (axis (1 1 0): the body x axis at 45 degrees)"
    );

    const scalarField& V = mesh.V();
    const vectorField& C = mesh.C().primitiveField();
    const label nCells = mesh.nCells();
    const scalarField cellRadius(immersedSpheroids::cellRadii(mesh));

    bitSet everCovered(nCells);
    vectorField uPrev(U.primitiveField());

    // momenta of the last solve: inside the body (P, L about X) and the
    // expected force and torque at the next update
    vector Pprev(Zero), Lprev(Zero);
    vector Fexpected(Zero), Texpected(Zero), Fimpulsive(Zero);
    scalar forceScale = 0;

    scalar maxPathError = 0, maxUsError = 0, maxFormulaError = 0;
    scalar maxFullResidual = 0, maxUs = 0;
    scalar maxForceError = 0, maxTorqueError = 0;
    label nFull = 0, nMovedNeverCovered = 0;
    scalar maxOutsideChange = 0;
    label maxListed = 0, nOutsideBounds = 0;
    bool etaOk = true;

    const label nSteps = 20;
    for (label step = 1; step <= nSteps; ++step)
    {
        ++runTime;
        bodies.update(U);
        const scalar t = runTime.value();
        const scalar dt = runTime.deltaTValue();

        // The force and torque of the last solve
        const vector& F = body.hydroForce();
        const vector& T = body.hydroTorque();
        if (step == 1)
        {
            check
            (
                F == vector::zero && T == vector::zero,
                "penalty: no force at the first update (no solve yet)"
            );
        }
        else
        {
            maxForceError = max(maxForceError, mag(F - Fexpected)/forceScale);
            maxTorqueError = max(maxTorqueError, mag(T - Texpected)/(forceScale*0.2));
        }
        if (step == 2)
        {
            // Impulsive start: only the cut cells push the outside fluid
            const scalar e = mag(F - Fimpulsive)/mag(Fimpulsive);
            check
            (
                e < 1e-9,
                "penalty: first force = -rho_f sum alpha (1 - alpha) V U_s/((1 + r) dt) = "
              + str(Fimpulsive.x()) + " " + str(Fimpulsive.y()) + " " + str(Fimpulsive.z())
              + " N (rel. error " + str(e) + ")"
            );
            check
            (
                (F & Up) < 0,
                "penalty: the first force opposes the motion (F.U_p = " + str(F & Up) + ")"
            );
        }

        // The body path and its velocity
        const point X = X0 + Up*t;
        const tensor R = rodrigues(omega, mag(omega)*t) & R0;
        maxPathError = max
        (
            maxPathError,
            max(mag(body.state().centre - X), maxAbs(body.state().R() - R))
        );
        etaOk = etaOk && mag(bodies.eta() - r*dt) < 1e-15*dt;

        const DynamicList<label>& cells = body.cells();
        const DynamicList<scalar>& fractions = body.fractions();
        maxListed = max(maxListed, cells.size());
        const boundBox bb = body.bounds();
        const tmp<volVectorField> tUs = bodies.bodyVelocity();
        const vectorField& UsLib = tUs().primitiveField();
        vectorField Us(cells.size());
        forAll(cells, i)
        {
            const label celli = cells[i];
            Us[i] = Up + (omega ^ (C[celli] - X));
            maxUs = max(maxUs, mag(Us[i]));
            maxUsError = max(maxUsError, mag(UsLib[celli] - Us[i]));
            everCovered.set(celli);
            const scalar d = cellRadius[celli];
            if
            (
                !boundBox(bb.min() - vector::one*d, bb.max() + vector::one*d)
                .contains(C[celli])
            )
            {
                ++nOutsideBounds;
            }
        }

        uPrev = U.primitiveField();
        solve(fvm::ddt(U) == bodies.penalty(U));
        const vectorField& u = U.primitiveField();

        bitSet covered(nCells);
        vector P(Zero), L(Zero), dM(Zero), dMr(Zero), alphaVUs(Zero);
        vector firstForce(Zero);
        forAll(cells, i)
        {
            const label celli = cells[i];
            const scalar alpha = fractions[i];
            covered.set(celli);
            const vector uExpected =
                ((1 + r - alpha)*uPrev[celli] + alpha*Us[i])/(1 + r);
            maxFormulaError = max(maxFormulaError, mag(u[celli] - uExpected));
            if (alpha == 1)
            {
                ++nFull;
                maxFullResidual = max(maxFullResidual, mag(u[celli] - Us[i]));
            }
            const vector rc = C[celli] - X;
            P += alpha*V[celli]*u[celli];
            L += rc ^ (alpha*V[celli]*u[celli]);
            dM += V[celli]*(u[celli] - uPrev[celli]);
            dMr += rc ^ (V[celli]*(u[celli] - uPrev[celli]));
            alphaVUs += alpha*V[celli]*Us[i];
            firstForce -= alpha*(1 - alpha)*V[celli]*Us[i];
        }
        forAll(u, celli)
        {
            if (!covered.test(celli))
            {
                // (u0 V/dt)/(V/dt): within an ulp or two of u0
                maxOutsideChange = max
                (
                    maxOutsideChange,
                    mag(u[celli] - uPrev[celli])/max(mag(uPrev[celli]), VSMALL)
                );
            }
            if (!everCovered.test(celli) && u[celli] != vector::zero)
            {
                ++nMovedNeverCovered;
            }
        }

        if (step == 1)
        {
            // Momentum given to the fluid at rest by the impulsive start
            const vector M = gSum(V*u);
            const scalar e = mag(M*(1 + r) - alphaVUs)/mag(alphaVUs);
            check
            (
                e < 1e-12,
                "penalty: impulsive start gives the fluid the momentum rho_f sum alpha V"
                " U_s/(1 + r) (rel. error " + str(e) + ")"
            );
            check
            (
                mag(M - alphaVUs) <= 1.01*r*mag(alphaVUs),
                "penalty: ... which is rho_f sum alpha V U_s within r (rel. "
              + str(mag(M - alphaVUs)/mag(alphaVUs)) + ")"
            );
            Fimpulsive = rhoF*firstForce/((1 + r)*dt);
            forceScale = rhoF*mag(alphaVUs)/dt;
        }

        // What the next update must report
        Fexpected = -rhoF*(dM - (P - Pprev))/dt;
        Texpected = -rhoF*(dMr - (L - Lprev))/dt;
        Pprev = P;
        Lprev = L;

        // The solid-fraction field: the list's fractions (one body)
        if (step == nSteps)
        {
            const tmp<volScalarField> talpha = bodies.solidFraction();
            scalar sumField = gSum(talpha().primitiveField()*V), sumList = 0;
            forAll(cells, i)
            {
                sumList += fractions[i]*V[cells[i]];
            }
            check
            (
                mag(sumField - sumList) < 1e-14*sumList
             && mag(sumList - body.volume()) < 0.05*body.volume(),
                "penalty: solidFraction() field = the body's fractions, sum alpha V = "
              + str(sumList) + " (body " + str(body.volume()) + ")"
            );
        }
    }

    Info<< "  penalty: " << nSteps << " steps, largest cell list " << maxListed
        << " of " << nCells << " cells" << endl;
    check(maxPathError < 1e-13, "penalty: body path X0 + U_p t, exp(t [omega]x) R0 (error " + str(maxPathError) + ")");
    check(etaOk, "penalty: eta = penaltyRatio x deltaT");
    check(maxUsError < 1e-14*maxUs, "penalty: bodyVelocity() = U_p + omega ^ (x - X) (error " + str(maxUsError) + ")");
    check
    (
        maxFormulaError < 1e-13*maxUs,
        "penalty: every covered cell u = ((1 + r - alpha) u_prev + alpha U_s)/(1 + r) (error "
      + str(maxFormulaError) + ")"
    );
    check
    (
        nFull > 0 && maxFullResidual <= 2*r/(1 + r)*maxUs,
        "penalty: fully covered cells move with the body: max |u - U_s|/max|U_s| = "
      + str(maxFullResidual/maxUs) + " <= 2 r/(1 + r) (" + std::to_string(nFull) + " cell-steps)"
    );
    check
    (
        maxOutsideChange < 1e-15,
        "penalty: cells not covered keep their velocity (max relative change "
      + str(maxOutsideChange) + ": round-off of (u0 V/dt)/(V/dt))"
    );
    check(nMovedNeverCovered == 0, "penalty: cells never covered stay at rest");
    check
    (
        maxForceError < 1e-10,
        "penalty: reported force = -rho_f d/dt(momentum of the fluid outside the body) (rel. error "
      + str(maxForceError) + ")"
    );
    check
    (
        maxTorqueError < 1e-10,
        "penalty: reported torque likewise, about the centre (rel. error " + str(maxTorqueError) + ")"
    );
    check
    (
        maxListed < nCells/20 && nOutsideBounds == 0,
        "penalty: the cell list (" + std::to_string(maxListed) + " of "
      + std::to_string(nCells) + ") is within the body's bounds"
    );
}


// ************************************************************************* //
