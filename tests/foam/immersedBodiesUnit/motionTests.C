/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
Description
    2. Motion models without fluid, against analytic solutions: bodies built
    from their dictionaries (immersedBody(name, dict)), advanced with
    bodyMotion::advance and given impulses.

    - fixed: velocities zeroed, never moves whatever the impulses;
    - prescribed: constant velocity and angular velocity (exact: the
      centre by the integral, the attitude by exp(t omega)), a piecewise
      linear table velocity (exact integral), a sine angular velocity about
      a fixed axis (midpoint rule: error <= T dt^2/24 max|omega''|, order
      2), a sine velocity (the header promises any Function1); frozen:
      the velocities follow a table, centre and orientation stay exactly;
    - free under a constant force: x0 + v0 t + F t^2/(2m) (the trapezoidal
      centre update is exact for a linear velocity: round-off only); a
      sphere under a constant torque parallel to omega: angle
      omega0 t + tau t^2/(2I) (exact likewise);
    - torque-free spheroid (prolate, aspect ratio 2.5) with omega not along
      a principal axis: the body-frame angular velocity precesses about
      the symmetry axis at Omega = (I3 - I1)/I1 omega3; the lab-frame
      angular momentum is conserved to round-off (updated exactly by the
      scheme), the kinetic energy and the cone angle between the symmetry
      axis and L to O(dt^2); phase and energy errors measured at two steps
      give the order;
    - the quaternion stays unit;
    - freeTranslation keeps the attitude and zero angular velocity,
      freeRotation keeps the centre and zero velocity.
\*---------------------------------------------------------------------------*/

#include "immersedBodiesTests.H"
#include "immersedBody.H"
#include "freeMotion.H"
#include "diagTensor.H"
#include "mathematicalConstants.H"

using namespace testChecks;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;
using namespace immersedBodiesTests;

const scalar pi = constant::mathematical::pi;

immersedBody makeBody(const std::string& entries, const word& name)
{
    return immersedBody(name, parse(entries, "test/" + name));
}


void advance
(
    immersedBody& body,
    const scalar t,
    const scalar dt,
    const vector& J = Zero,
    const vector& H = Zero
)
{
    body.motion().advance
    (
        body.state(), t, dt, J, H, body.mass(), body.bodyInertia()
    );
}


scalar unitError(const quaternion& q)
{
    return mag(mag(q) - 1);
}


void testFixed()
{
    immersedBody body = makeBody
    (
        "semiAxes (0.2 0.1 0.1); density 1100; centre (0.1 0.2 0.3);"
        "axis (1 1 0); velocity (1 2 3); angularVelocity (3 2 1);"
        "motion { type fixed; }",
        "fixed"
    );
    const bodyState s0 = body.state();
    body.motion().initialise(body.state(), 0);
    check
    (
        !body.motion().isFree() && !body.motion().moves()
     && body.state().velocity == vector::zero
     && body.state().angularVelocity == vector::zero,
        "fixed: not free, does not move, initial velocities zeroed"
    );
    for (label i = 0; i < 10; ++i)
    {
        advance(body, 0.1*i, 0.1, vector(1, 2, 3), vector(4, 5, 6));
    }
    check
    (
        body.state().centre == s0.centre
     && body.state().orientation == s0.orientation
     && body.state().velocity == vector::zero
     && body.state().angularVelocity == vector::zero,
        "fixed: centre and orientation unchanged (exactly) under impulses"
    );
}


void testPrescribed()
{
    // Constant velocity and angular velocity (not along an axis), from
    // t0 = 0.3: exact, round-off only (100 steps of relative 1e-16)
    {
        const vector U(0.3, -0.1, 0.2);
        const vector w(0.5, -1, 2);
        immersedBody body = makeBody
        (
            "semiAxes (0.2 0.1 0.1); density 1100; centre (0.1 0.2 0.3);"
            "orientation (0.5 0.5 0.5 0.5);"
            "motion { type prescribed; velocity constant (0.3 -0.1 0.2);"
            " angularVelocity (0.5 -1 2); }",
            "prescribedConstant"
        );
        const scalar t0 = 0.3, dt = 0.01;
        const label n = 100;
        body.motion().initialise(body.state(), t0);
        check
        (
            body.state().velocity == U && body.state().angularVelocity == w,
            "prescribed: initialise sets the velocities of time t0"
        );
        const bodyState s0 = body.state();
        scalar maxUnit = 0;
        for (label i = 0; i < n; ++i)
        {
            advance(body, t0 + i*dt, dt, vector(1, 1, 1), vector(1, 1, 1));
            maxUnit = max(maxUnit, unitError(body.state().orientation));
        }
        const scalar T = n*dt;
        const point xExact = s0.centre + U*T;
        const tensor RExact = rodrigues(w, mag(w)*T) & s0.R();
        const scalar ex = mag(body.state().centre - xExact)/mag(U*T);
        const scalar eR = maxAbs(body.state().R() - RExact);
        check(ex < 1e-13, "prescribed constant: centre = x0 + U t (rel. error " + str(ex) + ")");
        check(eR < 1e-12, "prescribed constant: R = exp(t [omega]x) R0 (error " + str(eR) + ")");
        check
        (
            body.state().velocity == U && body.state().angularVelocity == w,
            "prescribed constant: velocities are the functions' values, impulses ignored"
        );
        check(maxUnit < 1e-14, "prescribed: quaternion stays unit (" + str(maxUnit) + ")");
    }

    // Piecewise linear velocity (table), steps not on the table's points:
    // the table's integral is exact, so the centre too (round-off)
    {
        immersedBody body = makeBody
        (
            "semiAxes (0.2 0.1 0.1); density 1100; centre (0 0 0);"
            "motion { type prescribed;"
            " velocity table ((0 (0 0 0)) (1 (1 0.5 0)) (3 (1 0.5 -1))); }",
            "prescribedTable"
        );
        body.motion().initialise(body.state(), 0);
        const scalar dt = 0.07;
        const label n = 40;
        for (label i = 0; i < n; ++i)
        {
            advance(body, i*dt, dt);
        }
        // t = 2.8: (0.5, 0.25, 0) at t = 1, then (t - 1)(1, 0.5) and
        // -(t - 1)^2/4 in z
        const scalar t = n*dt;
        const point xExact
        (
            0.5 + (t - 1), 0.25 + 0.5*(t - 1), -sqr(t - 1)/4
        );
        const scalar ex = mag(body.state().centre - xExact)/mag(xExact);
        check(ex < 1e-12, "prescribed table velocity: centre = its exact integral (rel. error " + str(ex) + ")");
        check
        (
            mag(body.state().velocity - vector(1, 0.5, -(t - 1)/2)) < 1e-14,
            "prescribed table velocity: velocity = value at the end of the step"
        );
    }

    // Sine angular velocity about the fixed unit axis n:
    // omega = n A sin(2 pi f t), angle = A (1 - cos(2 pi f t))/(2 pi f);
    // midpoint rule: angle error <= T dt^2/24 max|omega''|
    {
        const scalar A = 3, f = 0.5, T = 1;
        const vector n(0.6, 0, 0.8);
        scalarField errs(2), dts(2);
        dts[0] = 0.05;
        dts[1] = 0.025;
        forAll(dts, k)
        {
            immersedBody body = makeBody
            (
                "semiAxes (0.2 0.1 0.1); density 1100; centre (0 0 0); axis (1 -1 0.5);"
                "motion { type prescribed; angularVelocity sine;"
                " angularVelocityCoeffs { amplitude 3; frequency 0.5;"
                " scale (0.6 0 0.8); level (0 0 0); } }",
                "prescribedSine"
            );
            body.motion().initialise(body.state(), 0);
            const tensor R0 = body.state().R();
            const label nSteps = label(T/dts[k] + 0.5);
            for (label i = 0; i < nSteps; ++i)
            {
                advance(body, i*dts[k], dts[k]);
            }
            const scalar angle = A*(1 - Foam::cos(2*pi*f*T))/(2*pi*f);
            // the angle error of a rotation about a fixed axis: |R - R'| ~ |dangle|
            errs[k] = maxAbs(body.state().R() - (rodrigues(n, angle) & R0));
            const scalar bound = T*sqr(dts[k])/24*A*sqr(2*pi*f);
            check
            (
                errs[k] <= bound,
                "prescribed sine angular velocity, dt " + str(dts[k])
              + ": attitude error " + str(errs[k]) + " <= T dt^2/24 max|omega''| = " + str(bound)
            );
            const vector wEnd = n*A*Foam::sin(2*pi*f*nSteps*dts[k]);
            check
            (
                mag(body.state().angularVelocity - wEnd) < 1e-12,
                "prescribed sine angular velocity: omega = value at the end of the step"
            );
        }
        const scalar p = order(errs[0], errs[1], dts[0], dts[1]);
        check(p >= 1.7, "prescribed sine angular velocity: order " + str(p) + " (>= 1.7, claimed 2)");
    }

    // Sine velocity: "any Function1 (constant, table, sine, ...)" says
    // prescribedMotion.H. Exact centre: x0 + A (1 - cos(2 pi f t))/(2 pi f) s
    // + l t; a quadrature of the velocity would be within T dt^2/24 A
    // (2 pi f)^2 |s| (midpoint) or twice that (trapezoid).
    {
        const scalar A = 0.2, f = 0.5, dt = 0.05;
        const label nSteps = 20;
        const scalar T = nSteps*dt;
        std::string problem;
        point x = Zero;
        const bool throwing = FatalError.throwExceptions();
        const bool throwingIO = FatalIOError.throwExceptions();
        try
        {
            immersedBody body = makeBody
            (
                "semiAxes (0.2 0.1 0.1); density 1100; centre (0 0 0);"
                "motion { type prescribed; velocity sine;"
                " velocityCoeffs { amplitude 0.2; frequency 0.5;"
                " scale (1 0 0); level (0 0.1 0); } }",
                "prescribedSineVelocity"
            );
            body.motion().initialise(body.state(), 0);
            for (label i = 0; i < nSteps; ++i)
            {
                advance(body, i*dt, dt);
            }
            x = body.state().centre;
        }
        catch (const Foam::error& err)
        {
            problem = err.message();
        }
        FatalError.throwExceptions(throwing);
        FatalIOError.throwExceptions(throwingIO);

        const point xExact(A*(1 - Foam::cos(2*pi*f*T))/(2*pi*f), 0.1*T, 0);
        const scalar bound = 2*T*sqr(dt)/24*A*sqr(2*pi*f);
        if (!problem.empty())
        {
            check
            (
                false,
                "prescribed sine velocity (any Function1 per prescribedMotion.H):"
                " advance failed: " + problem
            );
        }
        else
        {
            check
            (
                mag(x - xExact) <= bound,
                "prescribed sine velocity: centre error " + str(mag(x - xExact))
              + " <= 2 T dt^2/24 A (2 pi f)^2 = " + str(bound)
            );
        }
    }

    // frozen: the velocities follow the table, the centre and orientation
    // stay exactly where they are
    {
        immersedBody body = makeBody
        (
            "semiAxes (0.2 0.1 0.1); density 1100; centre (0.1 0.2 0.3);"
            "orientation (0.5 0.5 0.5 0.5);"
            "motion { type prescribed; frozen yes;"
            " velocity table ((0 (0 0 -1)) (1 (0 0 -3)));"
            " angularVelocity (0 1 0); }",
            "prescribedFrozen"
        );
        body.motion().initialise(body.state(), 0);
        const bodyState s0 = body.state();
        for (label i = 0; i < 50; ++i)
        {
            advance(body, 0.01*i, 0.01, vector(1, 1, 1), vector(1, 1, 1));
        }
        check
        (
            body.motion().moves() && body.motion().frozen()
         && body.state().centre == s0.centre
         && body.state().orientation == s0.orientation,
            "prescribed frozen: centre and orientation unchanged (exactly)"
        );
        check
        (
            mag(body.state().velocity - vector(0, 0, -2)) < 1e-12
         && body.state().angularVelocity == vector(0, 1, 0),
            "prescribed frozen: the velocities of the table at t = 0.5 ("
          + str(body.state().velocity.z()) + ", expected -2)"
        );
    }
}


void testFreeForce()
{
    // Constant force: trapezoidal centre update of a linearly varying
    // velocity is exact (round-off only: 50 steps x 1e-16)
    immersedBody body = makeBody
    (
        "semiAxes (0.2 0.1 0.05); density 1100; centre (0.1 0.2 0.3);"
        "axis (1 2 3); velocity (0.1 0.05 -0.2); motion { type free; }",
        "freeForce"
    );
    body.motion().initialise(body.state(), 0);
    check
    (
        body.motion().isFree() && body.motion().isFreeInTranslation(),
        "free: free, free in translation"
    );
    const bodyState s0 = body.state();
    const scalar m = body.mass();
    check
    (
        mag(m - 1100*4.0/3.0*pi*0.2*0.1*0.05) < 1e-14*m,
        "mass = density 4/3 pi abc"
    );
    const vector F = m*vector(0.3, -0.2, 0.5);
    const scalar dt = 0.02;
    const label n = 50;
    scalar maxUnit = 0;
    for (label i = 0; i < n; ++i)
    {
        advance(body, i*dt, dt, F*dt, Zero);
        maxUnit = max(maxUnit, unitError(body.state().orientation));
    }
    const scalar T = n*dt;
    const point xExact = s0.centre + s0.velocity*T + F*sqr(T)/(2*m);
    const vector UExact = s0.velocity + F*T/m;
    const scalar scale = mag(s0.centre) + mag(s0.velocity)*T + mag(F)*sqr(T)/(2*m);
    const scalar ex = mag(body.state().centre - xExact)/scale;
    const scalar eU = mag(body.state().velocity - UExact)/mag(UExact);
    check(ex < 1e-13, "free, constant force: x = x0 + v0 t + F t^2/(2m) (rel. error " + str(ex) + ")");
    check(eU < 1e-13, "free, constant force: v = v0 + F t/m (rel. error " + str(eU) + ")");
    check
    (
        maxAbs(body.state().R() - s0.R()) < 1e-15 && body.state().angularVelocity == vector::zero,
        "free, no torque, no spin: attitude unchanged"
    );
    check(maxUnit < 1e-14, "free: quaternion stays unit (" + str(maxUnit) + ")");

    // Sphere under a constant torque parallel to its spin: rotation about a
    // fixed axis with angle w0 t + tau t^2/(2I): the midpoint attitude
    // update is exact for a linear angular velocity (round-off)
    immersedBody sphere = makeBody
    (
        "semiAxes (0.1 0.1 0.1); density 1000; centre (0 0 0);"
        "orientation (0.5 0.5 -0.5 0.5); angularVelocity (0.4 0.8 -0.8);"
        "motion { type free; }",
        "freeTorque"
    );
    const scalar I = sphere.bodyInertia().x();
    check
    (
        mag(sphere.bodyInertia() - vector::one*(2.0/5.0)*sphere.mass()*0.01) < 1e-14*I,
        "sphere inertia 2/5 m R^2 about each axis"
    );
    const vector spin(1.0/3, 2.0/3, -2.0/3);
    const scalar w0 = 1.2, tau = 0.7*I;
    const tensor R0 = sphere.state().R();
    for (label i = 0; i < 40; ++i)
    {
        advance(sphere, i*0.025, 0.025, Zero, spin*tau*0.025);
    }
    const scalar t = 40*0.025;
    const scalar angle = w0*t + tau*sqr(t)/(2*I);
    const scalar eR = maxAbs(sphere.state().R() - (rodrigues(spin, angle) & R0));
    const scalar ew = mag(sphere.state().angularVelocity - spin*(w0 + tau*t/I));
    check(eR < 1e-13, "free sphere, constant torque: angle w0 t + tau t^2/(2I) (error " + str(eR) + ")");
    check(ew < 1e-13, "free sphere, constant torque: omega = w0 + tau t/I (error " + str(ew) + ")");
}


struct TorqueFreeResult
{
    scalar phaseError = 0;
    scalar phase = 0;
    scalar maxEnergyError = 0;
    scalar maxMomentumError = 0;
    scalar maxConeError = 0;
    scalar maxOmega3Error = 0;
    scalar maxUnitError = 0;
};


TorqueFreeResult torqueFree(const word& type, const scalar dt, const scalar T)
{
    immersedBody body = makeBody
    (
        "semiAxes (0.25 0.1 0.1); density 1000; centre (0.1 0.2 0.3);"
        "velocity (0.01 0 0); motion { type " + std::string(type) + "; }",
        type
    );
    const vector I = body.bodyInertia();     // (I3, I1, I1): axis = body x
    const scalar omega3 = 2;
    const vector wBody0(omega3, 1, 0);
    body.state().orientation = rotationQuaternion(vector(0.3, -0.5, 0.8));
    body.state().angularVelocity = body.state().R() & wBody0;
    const scalar Omega = (I.x() - I.y())/I.y()*omega3;

    const diagTensor Id(I.x(), I.y(), I.z());
    auto momentum = [&](const bodyState& s)
    {
        return s.R() & Id & s.R().T() & s.angularVelocity;
    };
    const vector L0 = momentum(body.state());
    const scalar E0 = 0.5*(body.state().angularVelocity & L0);
    // the symmetry axis (body x) in the world: the first column of R
    auto axisOf = [](const bodyState& s) { return s.R().T().x(); };
    const scalar coneCos0 = (axisOf(body.state()) & L0)/mag(L0);

    TorqueFreeResult res;
    const label n = label(T/dt + 0.5);
    vector wPrev = wBody0;
    for (label i = 0; i < n; ++i)
    {
        advance(body, i*dt, dt);
        const bodyState& s = body.state();
        const vector wBody = s.R().T() & s.angularVelocity;
        // phase increment of the transverse part (y, z) in the body frame
        res.phase += Foam::atan2
        (
            wPrev.y()*wBody.z() - wPrev.z()*wBody.y(),
            wPrev.y()*wBody.y() + wPrev.z()*wBody.z()
        );
        wPrev = wBody;
        const vector L = momentum(s);
        const scalar E = 0.5*(s.angularVelocity & L);
        res.maxMomentumError = max(res.maxMomentumError, mag(L - L0)/mag(L0));
        res.maxEnergyError = max(res.maxEnergyError, mag(E - E0)/E0);
        res.maxConeError = max(res.maxConeError, mag((axisOf(s) & L)/mag(L) - coneCos0));
        res.maxOmega3Error = max(res.maxOmega3Error, mag(wBody.x() - omega3)/omega3);
        res.maxUnitError = max(res.maxUnitError, unitError(s.orientation));
    }
    res.phaseError = mag(res.phase - Omega*n*dt);
    Info<< "  torque-free " << type << ", dt " << dt << ": Omega T = "
        << Omega*n*dt << ", phase " << res.phase << endl;
    return res;
}


void testTorqueFree()
{
    const scalar T = 5;
    const scalar dt1 = 0.01, dt2 = 0.005;
    const TorqueFreeResult r1 = torqueFree("free", dt1, T);
    const TorqueFreeResult r2 = torqueFree("free", dt2, T);

    // Omega T = -7.24 rad (more than a precession period). A second-order
    // rotation update errs per step by about dt^3 |omega|^3/12 (the
    // midpoint rule for an angle whose rate turns at |omega|): a phase
    // error of at most T |omega|^3 dt^2/12 (measured: about a fifth)
    const scalar w = mag(vector(2, 1, 0));
    const scalar phaseBound = T*pow3(w)*sqr(dt2)/12;
    check
    (
        r2.phaseError < phaseBound,
        "torque-free spheroid: precession phase error at dt = " + str(dt2)
      + ": " + str(r2.phaseError) + " rad < T |omega|^3 dt^2/12 = " + str(phaseBound)
      + " (" + str(r1.phaseError) + " at dt = " + str(dt1) + ")"
    );
    const scalar pPhase = order(r1.phaseError, r2.phaseError, dt1, dt2);
    check(pPhase >= 1.7, "torque-free spheroid: order of the phase error " + str(pPhase) + " (>= 1.7)");

    // L is updated exactly (L' = L + H): round-off only, a few eps per
    // step through I_w and its inverse (condition 3.6): 20 n eps
    const scalar roundOff = 20*(T/dt2)*2.2e-16;
    check
    (
        r1.maxMomentumError < roundOff && r2.maxMomentumError < roundOff,
        "torque-free spheroid: lab-frame angular momentum conserved to round-off ("
      + str(r1.maxMomentumError) + ", " + str(r2.maxMomentumError) + ")"
    );

    // Second order: the relative energy error within (|omega| dt)^2
    check
    (
        r2.maxEnergyError < sqr(w*dt2),
        "torque-free spheroid: max kinetic energy error " + str(r2.maxEnergyError)
      + " at dt = " + str(dt2) + " < (|omega| dt)^2 = " + str(sqr(w*dt2)) + " ("
      + str(r1.maxEnergyError) + " at dt = " + str(dt1) + ")"
    );
    const scalar pEnergy = order(r1.maxEnergyError, r2.maxEnergyError, dt1, dt2);
    check(pEnergy >= 1.7, "torque-free spheroid: order of the energy error " + str(pEnergy) + " (>= 1.7)");

    const scalar pCone = order(r1.maxConeError, r2.maxConeError, dt1, dt2);
    check
    (
        pCone >= 1.7,
        "torque-free spheroid: cone angle (axis, L) error " + str(r1.maxConeError)
      + ", " + str(r2.maxConeError) + ": order " + str(pCone) + " (>= 1.7)"
    );
    const scalar pOmega3 = order(r1.maxOmega3Error, r2.maxOmega3Error, dt1, dt2);
    check
    (
        pOmega3 >= 1.7,
        "torque-free spheroid: body-frame omega3 error " + str(r1.maxOmega3Error)
      + ", " + str(r2.maxOmega3Error) + ": order " + str(pOmega3) + " (>= 1.7)"
    );
    check
    (
        r1.maxUnitError < 1e-14 && r2.maxUnitError < 1e-14,
        "torque-free spheroid: quaternion stays unit ("
      + str(max(r1.maxUnitError, r2.maxUnitError)) + ")"
    );

    // freeRotation: the same rotation, the centre fixed
    const TorqueFreeResult r3 = torqueFree("freeRotation", dt1, T);
    check
    (
        r3.phase == r1.phase && r3.maxEnergyError == r1.maxEnergyError,
        "freeRotation rotates exactly as free"
    );
}


void testConstrained()
{
    const vector J(0.01, -0.02, 0.03), H(1e-4, 2e-4, -1e-4);

    // freeTranslation: the attitude never changes, omega zeroed
    {
        immersedBody body = makeBody
        (
            "semiAxes (0.2 0.1 0.1); density 1100; centre (0.1 0.2 0.3);"
            "axis (1 1 1); velocity (0.1 0 0); angularVelocity (1 2 3);"
            "motion { type freeTranslation; }",
            "freeTranslation"
        );
        check
        (
            body.motion().motionType() == "freeTranslation"
         && body.motion().isFreeInTranslation(),
            "freeTranslation: type and free in translation"
        );
        body.motion().initialise(body.state(), 0);
        check
        (
            body.state().angularVelocity == vector::zero
         && body.state().velocity == vector(0.1, 0, 0),
            "freeTranslation: initial angular velocity zeroed, velocity kept"
        );
        const bodyState s0 = body.state();
        const scalar dt = 0.01, m = body.mass();
        for (label i = 0; i < 20; ++i)
        {
            advance(body, i*dt, dt, J, H);
        }
        const scalar T = 20*dt;
        const point xExact = s0.centre + s0.velocity*T + J/dt*sqr(T)/(2*m);
        check
        (
            body.state().orientation == s0.orientation
         && body.state().angularVelocity == vector::zero,
            "freeTranslation: orientation unchanged (exactly) under angular impulses"
        );
        check
        (
            mag(body.state().centre - xExact) < 1e-13*mag(xExact),
            "freeTranslation: centre follows the impulses"
        );
    }

    // freeRotation: the centre never moves, velocity zeroed
    {
        immersedBody body = makeBody
        (
            "semiAxes (0.2 0.1 0.1); density 1100; centre (0.1 0.2 0.3);"
            "axis (1 1 1); velocity (0.1 0 0); angularVelocity (1 2 3);"
            "motion { type freeRotation; }",
            "freeRotation"
        );
        immersedBody reference = makeBody
        (
            "semiAxes (0.2 0.1 0.1); density 1100; centre (0.1 0.2 0.3);"
            "axis (1 1 1); velocity (0.1 0 0); angularVelocity (1 2 3);"
            "motion { type free; }",
            "freeReference"
        );
        check
        (
            body.motion().motionType() == "freeRotation"
         && body.motion().isFree() && !body.motion().isFreeInTranslation(),
            "freeRotation: type, free, not free in translation (no gravity needed)"
        );
        body.motion().initialise(body.state(), 0);
        reference.motion().initialise(reference.state(), 0);
        check
        (
            body.state().velocity == vector::zero
         && body.state().angularVelocity == vector(1, 2, 3),
            "freeRotation: initial velocity zeroed, angular velocity kept"
        );
        const point c0 = body.state().centre;
        for (label i = 0; i < 20; ++i)
        {
            advance(body, i*0.01, 0.01, J, H);
            advance(reference, i*0.01, 0.01, J, H);
        }
        check
        (
            body.state().centre == c0 && body.state().velocity == vector::zero,
            "freeRotation: centre unchanged (exactly) under impulses"
        );
        check
        (
            body.state().orientation == reference.state().orientation
         && body.state().angularVelocity == reference.state().angularVelocity,
            "freeRotation: rotation identical to that of a free body"
        );
    }
}

} // End anonymous namespace


void immersedBodiesTests::testMotion()
{
    testFixed();
    testPrescribed();
    testFreeForce();
    testTorqueFree();
    testConstrained();
}


// ************************************************************************* //
