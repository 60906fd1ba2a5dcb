/*---------------------------------------------------------------------------*\
  spheroidFoam: particle-resolved flows of immersed spheroids for OpenFOAM
-------------------------------------------------------------------------------
Description
    7. The virtual-mass stabilisation under the fluid's own time difference.
    A light sphere (rho_p/rho_f = 0.1, so C_v rho_f V = 5 m with C_v 0.5)
    in a model fluid whose reaction to the velocity the body imposes is the
    added-mass force -m_v D(U) (D the difference the fluid solve applies,
    Euler or backward; m_v = C_v rho_f V, nothing held), plus a force F and
    a torque T that double after five steps; stepped from rest by
    bodyIntegrator::advance as coupled runs step bodies. With the lag
    cancelled the increments obey (m + c m_v) dU_{n+1} = F dt + c00 m_v dU_n:
    after the jump they tend to the added-mass acceleration F/(m + m_v)
    without changing sign about it (root c00 m_v/(m + c m_v) = 0.29 with
    backward, 0 with Euler). A virtual mass that used dU/dt under a
    backward solve leaves the root -0.89 here: increments alternating about
    the limit, 3e-3 off it after 40 steps. The rotation likewise.
    A contact in the same model fluid: a steel sphere (rho_p/rho_f 8.3)
    hits a fixed sphere head-on (restitution 0.9, contact time 10 steps),
    the fluid's reaction the added-mass force -m_v D(U) of the velocities
    it saw. The contact acts on the body with its virtual mass and its
    velocity change enters the lagged difference, so the fluid's reaction
    to the reversal is cancelled. Euler: the velocity history is the one
    of the same contact in vacuum (the contact law scales with the mass)
    to round-off (a contact on the body's own mass alone does not give
    it). Backward: inside a step the contact meets m + (3/2) m_v and the
    next step returns (1/2) m_v of the change, an O(dt/T_c) departure from
    the vacuum contact (printed), checked within 0.02 U_in. Both: the sphere pressed on the anvil
    by a constant load comes to rest with the collision force carrying the
    load to 1e-6.
    Constant/g (zero) is written for the test and removed after it.
\*---------------------------------------------------------------------------*/

#include "immersedBodiesTests.H"
#include "immersedBody.H"
#include "bodyIntegrator.H"
#include "ddtCoefficients.H"
#include "filmCorrection.H"
#include "OFstream.H"
#include "OSspecific.H"

using namespace testChecks;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;
using namespace immersedBodiesTests;
using immersedSpheroids::ddtCoefficients;

//- Step the light body in the model fluid with the scheme's differences;
//  check the last increment against the limit and that no increment
//  changes sign about it after the jump
void runModelFluid
(
    const fvMesh& mesh,
    const ddtCoefficients::scheme scheme,
    const word& name
)
{
    const scalar rhoF = 1000;
    const scalar Cv = 0.5;
    PtrList<immersedBody> bodies(1);
    bodies.set
    (
        0,
        new immersedBody
        (
            "light",
            parse
            (
                "semiAxes (0.05 0.05 0.05); density 100; centre (0.5 0.5 0.5);"
                "motion { type free; }",
                "test/light"
            )
        )
    );
    immersedBody& body = bodies[0];
    const dictionary properties = parse("filmStabilisation no;", "test/virtualMass");
    const filmCorrection film(properties, mesh, 0, true);
    bodyIntegrator integrator(mesh, properties, bodies, rhoF, 1, Cv, film);

    const scalar m = body.mass();
    const scalar mv = Cv*rhoF*body.volume();
    const scalar Jv = Cv*rhoF/body.density()*body.bodyInertia().x();
    const scalar J = body.bodyInertia().x();
    const vector F0(0, 0, 2e-3);
    const vector T0(1e-6, 0, 0);
    const label jumpStep = 5;
    const vector aLimit = 2*F0/(m + mv);
    const vector alphaLimit = 2*T0/(J + Jv);
    const scalar dt = 1e-3;

    // the velocities the fluid saw: U^n, U^{n-1}, U^{n-2}
    vector U = Zero, U0 = Zero, U00 = Zero;
    vector W = Zero, W0 = Zero, W00 = Zero;
    ddtCoefficients solve;      // the solve that produced the force
    bool alternated = false;
    scalar lastDev = 0, lastAngularDev = 0;
    scalar prevSign = 0, prevAngularSign = 0;
    const label nSteps = 40;
    for (label stepi = 1; stepi <= nSteps; ++stepi)
    {
        // the model fluid's reaction to the velocities it saw
        const vector D = (solve.c*U - solve.c0*U0 + solve.c00*U00)/dt;
        const vector DW = (solve.c*W - solve.c0*W0 + solve.c00*W00)/dt;
        const scalar load = stepi <= jumpStep ? 1 : 2;
        body.setHydro(load*F0 - mv*D, load*T0 - Jv*DW);

        const ddtCoefficients next = ddtCoefficients::of(scheme, stepi, dt, dt);
        integrator.advance(bodies, (stepi - 1)*dt, dt, next);
        const vector Unew = body.state().velocity;
        const vector Wnew = body.state().angularVelocity;

        const scalar dev = ((Unew - U)/dt - aLimit).z()/aLimit.z();
        const scalar angularDev = ((Wnew - W)/dt - alphaLimit).x()/alphaLimit.x();
        // a change of sign about the limit, above round-off
        if (stepi > jumpStep + 1 && mag(dev) > 1e-12 && mag(angularDev) > 1e-12)
        {
            alternated =
                alternated || dev*prevSign < 0 || angularDev*prevAngularSign < 0;
        }
        prevSign = mag(dev) > 1e-12 ? sign(dev) : 0;
        prevAngularSign = mag(angularDev) > 1e-12 ? sign(angularDev) : 0;
        lastDev = mag(dev);
        lastAngularDev = mag(angularDev);

        U00 = U0; U0 = U; U = Unew;
        W00 = W0; W0 = W; W = Wnew;
        solve = next;
    }
    Info<< "    " << name << ": acceleration after " << nSteps
        << " steps within " << lastDev << " (angular " << lastAngularDev
        << ") of F/(m + m_v); increments alternating about it: "
        << alternated << endl;
    check
    (
        lastDev < 1e-9 && lastAngularDev < 1e-9,
        "virtual mass, " + name + ": the light body reaches the added-mass"
        " acceleration F/(m + m_v) (and T/(J + J_v))"
    );
    check
    (
        !alternated,
        "virtual mass, " + name + ": no alternation from step to step"
    );
}


//- A steel sphere hitting a fixed sphere head-on with the fluid density
//  rhoF in the model fluid (the scheme's added-mass reaction to the
//  velocities it saw); the free sphere's velocity after every step
List<vector> contactHistory
(
    const fvMesh& mesh,
    const ddtCoefficients::scheme scheme,
    const scalar rhoF,
    const word& restitution = "0.9",
    const word& start = "centre (0.5 0.5 0.602); velocity (0 0 -0.5);",
    const vector& load = Zero,
    const label nSteps = 40,
    vector* collisionForce = nullptr
)
{
    const scalar Cv = 0.5;
    PtrList<immersedBody> bodies(2);
    bodies.set
    (
        0,
        new immersedBody
        (
            "steel",
            parse
            (
                "semiAxes (0.05 0.05 0.05); density 7800; " + start
              + " motion { type free; }",
                "test/steel"
            )
        )
    );
    bodies.set
    (
        1,
        new immersedBody
        (
            "anvil",
            parse
            (
                "semiAxes (0.05 0.05 0.05); density 7800;"
                " centre (0.5 0.5 0.5); motion { type fixed; }",
                "test/anvil"
            )
        )
    );
    immersedBody& body = bodies[0];
    const dictionary properties = parse
    (
        "collision { type contact; restitution " + restitution + "; }"
        " filmStabilisation no;",
        "test/contactVirtualMass"
    );
    const filmCorrection film(properties, mesh, 0, true);
    bodyIntegrator integrator(mesh, properties, bodies, rhoF, 1, Cv, film);
    const scalar mv = Cv*rhoF*body.volume();
    const scalar dt = 1e-3;

    vector U = body.state().velocity, U0 = U, U00 = U;
    ddtCoefficients solve;
    List<vector> history;
    for (label stepi = 1; stepi <= nSteps; ++stepi)
    {
        const vector D = (solve.c*U - solve.c0*U0 + solve.c00*U00)/dt;
        body.setHydro(load - mv*D, Zero);
        const ddtCoefficients next = ddtCoefficients::of(scheme, stepi, dt, dt);
        integrator.advance(bodies, (stepi - 1)*dt, dt, next);
        U00 = U0; U0 = U; U = body.state().velocity;
        history.append(U);
        solve = next;
    }
    if (collisionForce)
    {
        *collisionForce = body.collisionForce();
    }
    return history;
}


//- The contact in the model fluid against the same contact in vacuum
void checkContactInModelFluid
(
    const fvMesh& mesh,
    const ddtCoefficients::scheme scheme,
    const word& name,
    const scalar tolerance
)
{
    const List<vector> fluid = contactHistory(mesh, scheme, 935);
    const List<vector> vacuum = contactHistory(mesh, scheme, 0);
    scalar maxDiff = 0;
    forAll(fluid, i)
    {
        maxDiff = max(maxDiff, mag(fluid[i] - vacuum[i]));
    }
    const scalar uIn = 0.5;
    const scalar e = fluid.last().z()/uIn;
    Info<< "    contact in the model fluid, " << name << ": rebound "
        << e << " U_in (vacuum " << vacuum.last().z()/uIn
        << "), largest velocity difference " << maxDiff/uIn << " U_in"
        << endl;
    check
    (
        e > 0.8,
        "virtual mass, " + name + ": the sphere rebounds from the contact"
    );
    check
    (
        maxDiff < tolerance*uIn,
        "virtual mass, " + name + ": a contact in the model fluid moves the"
        " sphere as the same contact in vacuum to " + Foam::name(tolerance)
        + " U_in (the fluid's reaction to the reversal cancelled, the"
        " restitution kept)"
    );

    // a load pressing the sphere on the anvil from rest at the touch
    // (restitution 0.3, so that it settles within the run): the contact
    // carries the load
    const vector load(0, 0, -1e-2);
    vector Fc = Zero;
    contactHistory
    (
        mesh, scheme, 935, "0.3",
        "centre (0.5 0.5 0.6); velocity (0 0 0);", load, 400, &Fc
    );
    Info<< "    resting on the contact, " << name << ": collision force "
        << Fc << " against the load " << load << endl;
    check
    (
        mag(Fc + load) < 1e-6*mag(load),
        "virtual mass, " + name + ": a contact at rest carries its load"
        " exactly (the virtual-mass terms vanish at rest)"
    );
}

} // End anonymous namespace


void immersedBodiesTests::testVirtualMass(const fvMesh& mesh)
{
    const fileName gFile(mesh.time().path()/mesh.time().constant()/"g");
    {
        OFstream os(gFile);
        os  << "FoamFile { version 2.0; format ascii;"
            << " class uniformDimensionedVectorField; object g; }" << nl
            << "dimensions [0 1 -2 0 0 0 0];" << nl
            << "value (0 0 0);" << nl;
    }
    runModelFluid(mesh, ddtCoefficients::scheme::Euler, "Euler");
    runModelFluid(mesh, ddtCoefficients::scheme::backward, "backward");
    checkContactInModelFluid
    (
        mesh, ddtCoefficients::scheme::Euler, "Euler", 1e-9
    );
    checkContactInModelFluid
    (
        mesh, ddtCoefficients::scheme::backward, "backward", 0.02
    );
    rm(gFile);
}


// ************************************************************************* //
