/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
Description
    6. The surface-corrected penalty (penaltyForcing, interfaceLinks): a
    sphere of radius R = 0.15 (4.5 cells) with a prescribed velocity and
    angular velocity in the closed unit box of fluid at rest (rho_f 1000,
    viscosity 100: nu = 0.1, nu dt/h^2 = 1.8), forcing surfaceCorrected,
    penaltyRatio r = 1e-3. Each step: runTime++, bodies.update(U),
    solve(fvm::ddt(U) == bodies.penalty(U)) (Euler), so every cell is its
    own equation
        u = (u_prev/dt + sum s)/(1/dt + sum c),
    whose terms this test computes independently of the library from the
    method's definition (interfaceLinks.H), with the sphere's exact
    crossing point of each face's centre-to-centre segment:
    - a cell whose centre is inside the sphere: c = 1/(r dt),
      s = c U_s(C);
    - a cell outside with a face to a cell N inside: per such face, theta
      the fraction of C_P -> C_N outside the sphere, g = 1/h^2,
      c = nu g (1/theta - 1), s = nu g (U_w/theta - U_s(C_N)), U_w the
      body velocity at the crossing point (capped at c = 1/(r dt),
      s = c U_w);
    - every other cell keeps its velocity.
    Also the sphere's surface integrals of the Stokes-layer estimate
    (immersedBody::tangentialArea, tangentialMoment; penaltyForcing::held):
    int (1 - n_k^2) dS = 8 pi R^2/3 and int |e_k ^ x|^2 dS = 8 pi R^4/3.
    Checks: every cell against that (round-off), at two step sizes (the
    last two steps take half the step: the link terms hold no dt); the reported
    force and torque equal minus the change of the momentum of the fluid
    outside the body, sum over all cells (u - u_prev) V less the change of
    the internal-fluid momentum sum alpha V u (the force is what the fluid
    receives).
\*---------------------------------------------------------------------------*/

#include "immersedBodiesTests.H"
#include "immersedBodies.H"
#include "mathematicalConstants.H"
#include <fstream>

using namespace testChecks;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The fraction of the segment x0 -> x1 (x0 outside, x1 inside the sphere)
//  outside the sphere: |x0 + t (x1 - x0) - X| = R
scalar sphereCrossing(const point& x0, const point& x1, const point& X, const scalar R)
{
    const vector d = x1 - x0;
    const vector r0 = x0 - X;
    const scalar a = magSqr(d);
    const scalar b = r0 & d;
    const scalar c = magSqr(r0) - R*R;
    return (-b - Foam::sqrt(b*b - a*c))/a;
}

} // End anonymous namespace


void immersedBodiesTests::testSurfacePenalty(Time& runTime, const fvMesh& mesh)
{
    const fileName file = runTime.path()/runTime.constant()/"immersedBodiesProperties";
    const fileName saved = file + ".penalty";
    if (!Foam::cp(file, saved))
    {
        check(false, "surface penalty: cannot copy " + file);
        return;
    }
    const scalar R = 0.15;
    const scalar r = 1e-3;
    const scalar nu = 0.1;
    {
        std::ofstream os(file.c_str());
        os  << "FoamFile { version 2.0; format ascii; class dictionary;"
               " object immersedBodiesProperties; }\n"
               "fluidDensity 1000; viscosity 100; forcing surfaceCorrected;"
               " penaltyRatio 1e-3;"
               " output { timeSeries no; surfaces no; }"
               " bodies { sphere { semiAxes (0.15 0.15 0.15); density 1200;"
               " centre (0.4 0.45 0.5); motion { type prescribed;"
               " velocity (0.5 0.2 0); angularVelocity (0 0.5 2); } } }\n";
    }

    volVectorField U
    (
        IOobject("U", runTime.timeName(), mesh, IOobject::NO_READ, IOobject::NO_WRITE),
        mesh,
        dimensionedVector(dimVelocity, Zero)
    );

    immersedBodies bodies(mesh);
    Foam::mv(saved, file);
    const immersedBody& body = bodies.bodies()[0];
    const scalar rhoF = bodies.fluidDensity();
    {
        const scalar area = 8*constant::mathematical::pi*R*R/3;
        const scalar e = max
        (
            cmptMax(cmptMag(body.tangentialArea() - area*vector::one))/area,
            cmptMax(cmptMag(body.tangentialMoment() - area*R*R*vector::one))/(area*R*R)
        );
        check
        (
            e < 2e-3,
            "surface penalty: the sphere's tangential surface integrals 8 pi R^2/3 and"
            " 8 pi R^4/3 per axis (rel. error " + str(e) + ")"
        );
    }

    const scalarField& V = mesh.V();
    const vectorField& C = mesh.C().primitiveField();
    const labelList& own = mesh.faceOwner();
    const labelList& nei = mesh.faceNeighbour();
    const scalar h = 1.0/30;

    vector Pprev(Zero), Lprev(Zero), Fexpected(Zero), Texpected(Zero);
    scalar forceScale = 0;
    scalar maxCellError = 0, maxU = 0, maxForceError = 0, maxTorqueError = 0;
    label nSolid = 0, nLinked = 0, nCapped = 0;
    label nLinkedHalfStep = 0;

    const label nSteps = 6;
    for (label step = 1; step <= nSteps; ++step)
    {
        // the last two steps with half the step
        if (step == nSteps - 1)
        {
            runTime.setDeltaT(0.5*runTime.deltaTValue());
        }
        ++runTime;
        bodies.update(U);
        const scalar dt = runTime.deltaTValue();
        const bodyState& state = body.state();
        const point X = state.centre;

        if (step > 1)
        {
            maxForceError = max(maxForceError, mag(body.hydroForce() - Fexpected)/forceScale);
            maxTorqueError =
                max(maxTorqueError, mag(body.hydroTorque() - Texpected)/(forceScale*R));
        }

        // the terms of every cell, from the definition
        scalarField c(mesh.nCells(), 0);
        vectorField s(mesh.nCells(), Zero);
        const scalar cap = 1/(r*dt);
        forAll(C, celli)
        {
            if (mag(C[celli] - X) <= R)
            {
                c[celli] = cap;
                s[celli] = cap*state.velocityAt(C[celli]);
                ++nSolid;
            }
        }
        forAll(nei, facei)
        {
            for (const label side : {0, 1})
            {
                const label P = side == 0 ? own[facei] : nei[facei];
                const label N = side == 0 ? nei[facei] : own[facei];
                if (mag(C[P] - X) <= R || mag(C[N] - X) > R)
                {
                    continue;
                }
                const scalar theta = sphereCrossing(C[P], C[N], X, R);
                const point w = C[P] + theta*(C[N] - C[P]);
                const scalar g = nu/(h*h);
                scalar cf = g*(1/theta - 1);
                vector sf = g*(state.velocityAt(w)/theta - state.velocityAt(C[N]));
                if (cf >= cap)
                {
                    cf = cap;
                    sf = cap*state.velocityAt(w);
                    ++nCapped;
                }
                c[P] += cf;
                s[P] += sf;
                ++nLinked;
                nLinkedHalfStep += (step >= nSteps - 1);
            }
        }
        const vectorField uPrev(U.primitiveField());
        solve(fvm::ddt(U) == bodies.penalty(U));
        const vectorField& u = U.primitiveField();

        forAll(u, celli)
        {
            const vector expected = (uPrev[celli]/dt + s[celli])/(1/dt + c[celli]);
            maxCellError = max(maxCellError, mag(u[celli] - expected));
            maxU = max(maxU, mag(u[celli]));
        }

        // the fluid's momentum change and the internal-fluid momentum
        vector dM(Zero), dMr(Zero), P(Zero), L(Zero);
        forAll(u, celli)
        {
            const vector du = V[celli]*(u[celli] - uPrev[celli]);
            dM += du;
            dMr += (C[celli] - X) ^ du;
        }
        forAll(body.cells(), i)
        {
            const label celli = body.cells()[i];
            const vector p = body.fractions()[i]*V[celli]*u[celli];
            P += p;
            L += (C[celli] - X) ^ p;
        }
        Fexpected = -rhoF*(dM - (P - Pprev))/dt;
        Texpected = -rhoF*(dMr - (L - Lprev))/dt;
        if (step == 1)
        {
            forceScale = rhoF*mag(P)/dt;
        }
        Pprev = P;
        Lprev = L;

    }

    Info<< "  surface penalty: " << nSolid << " solid and " << nLinked
        << " linked cell-steps, " << nCapped << " capped" << endl;
    check
    (
        nSolid > 0 && nLinked > 0,
        "surface penalty: the sphere has solid and linked cells"
    );
    // the crossing fraction comes through the rotated quadratic form, to
    // ~1e-16 absolute: in c = g (1/theta - 1) that is 1e-16/theta relative
    // (theta down to ~1e-7 before the cap)
    check
    (
        maxCellError < 1e-8*maxU,
        "surface penalty: every cell u = (u_prev/dt + sum s)/(1/dt + sum c) from the"
        " definition (error " + str(maxCellError/maxU) + " of max|u|)"
    );
    check(nLinkedHalfStep > 0, "surface penalty: linked cells checked at the half step too");
    check
    (
        maxForceError < 1e-10,
        "surface penalty: reported force = -rho_f d/dt(momentum of the fluid outside the"
        " body) (rel. error " + str(maxForceError) + ")"
    );
    check
    (
        maxTorqueError < 1e-10,
        "surface penalty: reported torque likewise (rel. error " + str(maxTorqueError) + ")"
    );
}


// ************************************************************************* //
