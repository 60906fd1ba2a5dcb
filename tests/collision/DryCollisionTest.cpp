// Dry collisions in vacuum through the collision sub-step and the rigid-body
// step that coupled runs use (SubStepper, RigidBodyStep; validation/dryCollisions
// reports the same measurements over wider ranges).
#include "collision/RigidBody.hpp"
#include "ModelSetup.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace collision;

namespace {

/// The one rigid-body step (RigidBodyStep.hpp) under F and T held over dt.
void advanceBody(RigidBody& b, const Vec3& force, const Vec3& torque, Scalar dt) {
  if (b.movable) advanceRigidBody(b, dt, force * dt, torque * dt, b.mass(), b.bodyInertia());
}

struct RunSummary {
  Scalar maxOverlapRatio = 0;
  long contacts = 0;
  long notConverged = 0;
};

/// Advance the bodies for `time` with fluid steps dt (contact time nc dt),
/// the sub-steps the model asks for.
RunSummary simulate(std::vector<RigidBody>& bodies, CollisionModel& model, Scalar dt, Scalar time,
             int nc = 8) {
  const int steps = int(std::ceil(time / dt - 1e-9));
  for (int s = 0; s < steps; ++s) collisionStep(bodies, model, nc * dt, dt);
  return RunSummary{model.statistics().maxOverlapRatio, model.statistics().contacts + model.statistics().wallContacts,
             model.statistics().distanceNotConverged};
}

RigidBody sphere(Scalar r, const Vec3& c, const Vec3& u) {
  RigidBody b;
  b.semiAxes = Vec3::Constant(r);
  b.centre = c;
  b.velocity = u;
  b.density = 7800;
  return b;
}

ModelSetup contactOnly(Scalar e) {
  ModelSetup s;
  s.laws.contact.restitution = e;
  return s;
}

/// Normal speed of body point closest to the wall (z = 0, normal +z).
Scalar wallNormalSpeed(const RigidBody& b) {
  const WallDistance d = wallDistance(b.collisionBody().shape, PlaneWall{"w", Vec3::Zero(), Vec3::UnitZ()});
  return (b.velocity + b.angularVelocity.cross(d.bodyPoint - b.centre)).z();
}

}  // namespace

TEST(DryCollision, HeadOnSpheresReboundWithTheRestitutionAndConserveMomentum) {
  // 50 sub-steps per contact: the onset of the dashpot force inside a
  // sub-step costs ~ -ln(e)/subStepsPerContact of the rebound speed
  for (Scalar e : {0.97, 0.5, 0.1}) {
    std::vector<RigidBody> b{sphere(1e-3, Vec3(-1.1e-3, 0, 0), Vec3(0.3, 0, 0)),
                             sphere(0.5e-3, Vec3(0.6e-3, 0, 0), Vec3(-0.2, 0, 0))};
    ModelSetup s = contactOnly(e);
    s.settings.subStepsPerContact = 50;
    CollisionModel model = makeModel(s, {});
    const Vec3 p0 = b[0].linearMomentum() + b[1].linearMomentum();
    const Scalar u0 = b[1].velocity.x() - b[0].velocity.x();
    simulate(b, model, 1e-5, 2e-3);
    const Scalar u1 = b[1].velocity.x() - b[0].velocity.x();
    EXPECT_NEAR(-u1 / u0, e, 0.01 * e) << "e = " << e;
    const Vec3 p1 = b[0].linearMomentum() + b[1].linearMomentum();
    EXPECT_LT((p1 - p0).norm(), 1e-12 * b[0].linearMomentum().norm());
    EXPECT_EQ(model.activeContacts(), 0u);
  }
}

TEST(DryCollision, SphereOnWallReboundsWithTheRestitution) {
  for (Scalar e : {0.97, 0.5}) {
    std::vector<RigidBody> b{sphere(2e-3, Vec3(0, 0, 2.2e-3), Vec3(0, 0, -0.5))};
    CollisionModel model = makeModel(contactOnly(e), {PlaneWall{"floor", Vec3::Zero(), Vec3::UnitZ()}});
    simulate(b, model, 1e-5, 2e-3);
    EXPECT_NEAR(b[0].velocity.z() / 0.5, e, 0.01 * e);
    EXPECT_LT(model.statistics().maxOverlapRatio, 0.1 * 1.05);
  }
}

TEST(DryCollision, TiltedSpheroidOnWallContactPointReboundsWithTheRestitution) {
  // the contact point's normal speed is reversed with e (the rotation is part
  // of the effective mass), for several tilts of a prolate and an oblate body,
  // with a contact short against the rotation it starts (0.004 rad; over
  // longer contacts the contact point moves and m_eff changes:
  // validation/dryCollisions measures e against the contact time)
  for (Scalar ar : {3.0, 1.0 / 3.0}) {
    for (Scalar tilt : {0.0, 0.3, 0.8, 1.2, M_PI / 2}) {
      const ellipsoids::Ellipsoid shape = ellipsoids::Ellipsoid::spheroid(ar, 2e-3, Vec3::Zero(), Quat::Identity());
      RigidBody b;
      b.semiAxes = shape.semiAxes();
      b.orientation = Quat(Eigen::AngleAxis<Scalar>(tilt, Vec3::UnitY()));
      b.density = 2500;
      b.velocity = Vec3(0, 0, -0.2);
      const Scalar h = std::sqrt(Vec3::UnitZ().dot(b.collisionBody().shape.shapeMatrix() * Vec3::UnitZ()));
      b.centre = Vec3(0, 0, h + 1e-5);
      std::vector<RigidBody> bodies{b};
      CollisionModel model = makeModel(contactOnly(0.8), {PlaneWall{"floor", Vec3::Zero(), Vec3::UnitZ()}});
      const Scalar before = wallNormalSpeed(bodies[0]);
      // stop as soon as the contact ends (a tumbling body may come back)
      bool touched = false;
      for (int s = 0; s < 200000; ++s) {
        collisionSubStep(bodies, model, 2e-5, 2e-7);
        if (model.activeContacts() > 0) touched = true;
        if (touched && model.activeContacts() == 0) break;
      }
      ASSERT_TRUE(touched);
      // the contact point at the end: the point of the body nearest the wall
      const Scalar after = wallNormalSpeed(bodies[0]);
      EXPECT_NEAR(-after / before, 0.8, 0.02) << "ar " << ar << " tilt " << tilt;
    }
  }
}

TEST(DryCollision, ObliqueSpheroidImpactConservesLinearAndAngularMomentum) {
  RigidBody a, c;
  a.semiAxes = Vec3(3e-3, 1e-3, 1e-3);
  a.orientation = Quat(Eigen::AngleAxis<Scalar>(0.6, Vec3(0, 0.3, 1).normalized()));
  a.centre = Vec3(-3.2e-3, 0.4e-3, 0);
  a.velocity = Vec3(0.4, 0.02, 0.01);
  a.angularVelocity = Vec3(0, 5, 20);
  a.density = 1100;
  c.semiAxes = Vec3(0.6e-3, 2e-3, 2e-3);
  c.orientation = Quat(Eigen::AngleAxis<Scalar>(-0.4, Vec3(1, 0.2, 0).normalized()));
  c.centre = Vec3(1.5e-3, -0.5e-3, 0.3e-3);
  c.velocity = Vec3(-0.3, 0, 0);
  c.density = 1100;
  std::vector<RigidBody> b{a, c};
  ModelSetup s = contactOnly(0.7);
  s.laws.contact.friction = 0.3;
  CollisionModel model = makeModel(s, {});
  const Vec3 p0 = b[0].linearMomentum() + b[1].linearMomentum();
  const Vec3 l0 = b[0].angularMomentum() + b[1].angularMomentum();
  const RunSummary run = simulate(b, model, 1e-5, 1.5e-2);
  ASSERT_GT(run.contacts, 0);
  EXPECT_EQ(run.notConverged, 0);
  const Vec3 p1 = b[0].linearMomentum() + b[1].linearMomentum();
  const Vec3 l1 = b[0].angularMomentum() + b[1].angularMomentum();
  EXPECT_LT((p1 - p0).norm(), 1e-12 * p0.norm());
  // equal and opposite forces at one point: the torques balance exactly; the
  // trapezoidal position update moves x ^ p by O(dt^2) per contact (measured
  // 4e-8 of the scale sum |x_i| |p_i| + |I_i omega_i|)
  Scalar scale = 0;
  for (const RigidBody& x : b) {
    scale += x.centre.norm() * x.linearMomentum().norm() +
             (x.worldInertia(x.orientation) * x.angularVelocity).norm();
  }
  EXPECT_LT((l1 - l0).norm(), 1e-6 * scale);
  EXPECT_LE(b[0].kineticEnergy() + b[1].kineticEnergy(),
            (a.kineticEnergy() + c.kineticEnergy()) * (1 + 1e-9));
}

TEST(DryCollision, CappedImpactsOfTurningSpheroidsNeverGainEnergy) {
  // fast enough for the overlap cap to shorten the contact, so that the body
  // turns by ~0.2 rad in it and the contact point's effective mass changes:
  // with k_n following it, Ar 3 at 15 deg and Ar 1/3 at 75 deg left the wall
  // with 6 % more kinetic energy (validation/dryCollisions)
  for (const auto& [ar, tiltDeg] : {std::pair<Scalar, Scalar>{3.0, 15}, {1.0 / 3.0, 75}, {6.0, 30}}) {
    const ellipsoids::Ellipsoid shape = ellipsoids::Ellipsoid::spheroid(ar, 2e-3, Vec3::Zero(), Quat::Identity());
    RigidBody b;
    b.semiAxes = shape.semiAxes();
    b.orientation = Quat(Eigen::AngleAxis<Scalar>(tiltDeg * M_PI / 180, Vec3::UnitY()));
    b.density = 2500;
    b.velocity = Vec3(0, 0, -10);
    const Scalar h = std::sqrt(Vec3::UnitZ().dot(b.collisionBody().shape.shapeMatrix() * Vec3::UnitZ()));
    b.centre = Vec3(0, 0, h + 1e-6);
    std::vector<RigidBody> bodies{b};
    ModelSetup s = contactOnly(0.97);
    s.settings.subStepsPerContact = 20;
    CollisionModel model = makeModel(s, {PlaneWall{"floor", Vec3::Zero(), Vec3::UnitZ()}});
    const Scalar ke0 = bodies[0].kineticEnergy();
    bool touched = false;
    Scalar keMax = 0;
    for (int k = 0; k < 20000 && !(touched && model.activeContacts() == 0); ++k) {
      collisionStep(bodies, model, 1e-4, 1e-5);
      touched = touched || model.statistics().wallContacts > 0;
      keMax = std::max(keMax, bodies[0].kineticEnergy());
    }
    ASSERT_TRUE(touched);
    EXPECT_EQ(model.activeContacts(), 0u);
    EXPECT_LE(bodies[0].kineticEnergy(), ke0 * (1 + 1e-9)) << "Ar " << ar << " tilt " << tiltDeg;
    EXPECT_LE(keMax, ke0 * (1 + 1e-9)) << "Ar " << ar << " tilt " << tiltDeg;
    EXPECT_LT(model.statistics().maxOverlapRatio, 0.1 * 1.05);
  }
}

TEST(DryCollision, ABodySwingingIntoAContactKeepsTheOverlapNearTheCap) {
  // a prolate Ar 6 lying on the wall, barely approaching but spinning about
  // a horizontal axis: at the touch (its middle) the normal speed is 1 mm/s
  // (the nominal contact time, a soft spring), then one end swings into the
  // wall at up to omega a = 6.6 m/s. The contact time follows the normal
  // speed (with the first touch's spring the end would sink by ~40 a_min)
  const ellipsoids::Ellipsoid shape = ellipsoids::Ellipsoid::spheroid(6, 2e-3, Vec3::Zero(), Quat::Identity());
  RigidBody b;
  b.semiAxes = shape.semiAxes();
  b.density = 2500;
  b.velocity = Vec3(0, 0, -0.001);
  b.angularVelocity = Vec3(0, 2000, 0);
  const Scalar h = std::sqrt(Vec3::UnitZ().dot(b.collisionBody().shape.shapeMatrix() * Vec3::UnitZ()));
  b.centre = Vec3(0, 0, h + 1e-7);
  std::vector<RigidBody> bodies{b};
  CollisionModel model = makeModel(contactOnly(0.9), {PlaneWall{"floor", Vec3::Zero(), Vec3::UnitZ()}});
  const Scalar ke0 = bodies[0].kineticEnergy();
  for (int k = 0; k < 200; ++k) collisionStep(bodies, model, 1e-3, 1e-5);
  ASSERT_GT(model.statistics().wallContacts, 0);
  EXPECT_GT(model.statistics().stiffened, 0);
  EXPECT_LT(model.statistics().maxOverlapRatio, 0.15);
  EXPECT_LE(bodies[0].kineticEnergy(), ke0 * (1 + 1e-9));
  EXPECT_GT(bodies[0].centre.z(), 0);
}

TEST(DryCollision, ExtremeAspectRatiosAtGrazingAnglesAndHighSpeedNeitherTunnelNorGiveNaN) {
  // Ar 6 and Ar 1/6 (D_eq 1 mm), approach speeds up to 10 m/s (~ 1e4 D_eq/s), grazing offsets
  for (Scalar speed : {0.1, 10.0}) {
    for (Scalar offset : {0.0, 0.5e-3, 0.9e-3}) {
      const auto p = ellipsoids::Ellipsoid::spheroid(6, 1e-3, Vec3::Zero(), Quat::Identity());
      const auto o = ellipsoids::Ellipsoid::spheroid(1.0 / 6, 1e-3, Vec3::Zero(), Quat::Identity());
      RigidBody a, c;
      a.semiAxes = p.semiAxes();
      a.orientation = Quat(Eigen::AngleAxis<Scalar>(0.3, Vec3::UnitZ()));
      a.centre = Vec3(-2.5e-3, offset, 0);
      a.velocity = Vec3(speed, 0, 0);
      c.semiAxes = o.semiAxes();
      c.orientation = Quat(Eigen::AngleAxis<Scalar>(1.2, Vec3(0, 1, 1).normalized()));
      c.centre = Vec3(1.5e-3, 0, 0);
      c.velocity = Vec3(-speed, 0, 0);
      std::vector<RigidBody> b{a, c};
      CollisionModel model = makeModel(contactOnly(0.9), {});
      const Scalar time = 8e-3 / speed;
      const RunSummary run = simulate(b, model, time / 400, time);
      for (const RigidBody& x : b) {
        ASSERT_TRUE(x.centre.allFinite() && x.velocity.allFinite() && x.angularVelocity.allFinite());
      }
      // never deeper than the cap allows (maxOverlap 0.1 of the smallest semi-axis, with margin)
      EXPECT_LT(run.maxOverlapRatio, 0.15) << speed << " " << offset;
      EXPECT_EQ(run.notConverged, 0);
      // after the run they are apart again (no interpenetrated end state)
      const auto r = ellipsoids::DualNewton().distance(b[0].collisionBody().shape,
                                                        b[1].collisionBody().shape, {});
      EXPECT_GT(r.distance, 0) << speed << " " << offset;
      if (offset == 0) {  // head-on: they came back the way they came
        EXPECT_LT(b[0].velocity.x(), 0);
        EXPECT_GT(b[1].velocity.x(), 0);
      }
    }
  }
}

TEST(DryCollision, DeepOverlapAtStartAndTinyGapsWithLubricationStayFinite) {
  ModelSetup s;
  s.model = "lubricatedSpringDashpot";
  s.laws.viscosity = 1e-3;
  s.filmViscosity = 1e-3;
  CollisionModel model = makeModel(s, {PlaneWall{"floor", Vec3::Zero(), Vec3::UnitZ()}});
  // concentric bodies, a body half through the floor, gaps 1e-6 D_eq
  const Scalar d = 1e-3;
  for (Scalar gap : {-0.5 * d, 0.0, 1e-6 * d, 1e-9 * d}) {
    RigidBody a = sphere(0.5 * d, Vec3(0, 0, 0.5 * d + gap), Vec3(0, 0, -0.1));
    RigidBody c = a;
    c.semiAxes = Vec3(1.5 * d, 0.3 * d, 0.3 * d);
    c.centre = a.centre + Vec3(0, 0, 0.8 * d + gap);
    RigidBody concentric = c;
    concentric.centre = c.centre;
    std::vector<RigidBody> b{a, c, concentric};
    std::vector<CollisionBody> cb;
    for (const RigidBody& x : b) cb.push_back(x.collisionBody());
    std::vector<Vec3> F, T;
    ASSERT_NO_THROW(model.forces(cb, 1e-4, 1e-6, F, T)) << gap;
    for (std::size_t i = 0; i < F.size(); ++i) {
      EXPECT_TRUE(F[i].allFinite() && T[i].allFinite()) << gap;
    }
    std::vector<Vec3> FL, TL, v, w;
    for (const CollisionBody& x : cb) {
      v.push_back(x.velocity);
      w.push_back(x.angularVelocity);
    }
    ASSERT_NO_THROW(model.dampingForces(cb, v, w, {}, {}, 1e-6, FL, TL)) << gap;
    for (std::size_t i = 0; i < FL.size(); ++i) {
      EXPECT_TRUE(FL[i].allFinite() && TL[i].allFinite()) << gap;
    }
    std::vector<CollisionBody> alone{a.collisionBody()};
    model.forces(alone, 1e-4, 1e-6, F, T);
    model.dampingForces(alone, {alone[0].velocity}, {alone[0].angularVelocity}, {}, {}, 1e-6, FL, TL);
    if (gap == 0) {
      // touching: no overlap for the spring yet, and the lubrication's gap
      // path (0 to inside the contact) is over
      EXPECT_EQ(F[0].z() + FL[0].z(), 0) << "at gap 0";
    } else {
      EXPECT_GT(F[0].z() + FL[0].z(), 0) << "the floor pushes the approaching sphere up at gap " << gap;
    }
  }
  EXPECT_GT(model.statistics().lubricated, 0);
}

TEST(DryCollision, RestartFromTheHistoryContinuesBitwiseAsTheUninterruptedRun) {
  // a spheroid pair and a wall contact, stopped mid-contact: a new model given
  // history() continues exactly as the model that kept it
  auto scene = [] {
    std::vector<RigidBody> b{sphere(1e-3, Vec3(0, 0, 1.1e-3), Vec3(0.1, 0, -3)),
                             sphere(0.8e-3, Vec3(1.9e-3, 0, 1.2e-3), Vec3(-0.3, 0, -0.1))};
    b[1].semiAxes = Vec3(1.2e-3, 0.6e-3, 0.6e-3);
    b[1].orientation = Quat(Eigen::AngleAxis<Scalar>(0.4, Vec3(0, 1, 1).normalized()));
    return b;
  };
  const std::vector<PlaneWall> walls{PlaneWall{"floor", Vec3::Zero(), Vec3::UnitZ()}};
  ModelSetup s = contactOnly(0.7);
  s.laws.contact.friction = 0.2;
  const Scalar dt = 2e-5;
  const Scalar tc = 8 * dt;

  std::vector<RigidBody> a = scene();
  CollisionModel uninterrupted = makeModel(s, walls);
  std::vector<RigidBody> b = scene();
  CollisionModel first = makeModel(s, walls);
  int k = 0;
  for (; k < 400 && first.activeContacts() < 1; ++k) {
    collisionStep(a, uninterrupted, tc, dt);
    collisionStep(b, first, tc, dt);
  }
  ASSERT_EQ(first.activeContacts(), 1u) << "the sphere should touch the wall first";
  const std::vector<PairRecord> saved = first.history();
  ASSERT_GE(saved.size(), 1u);
  CollisionModel restarted = makeModel(s, walls);
  restarted.setHistory(saved);
  EXPECT_EQ(restarted.activeContacts(), 1u);
  long pairContacts = 0;
  for (int m = 0; m < 200; ++m) {
    collisionStep(a, uninterrupted, tc, dt);
    collisionStep(b, restarted, tc, dt);
  }
  pairContacts = restarted.statistics().contacts;
  EXPECT_GT(pairContacts, 0) << "the continuation should include the body-body contact";
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(a[i].centre, b[i].centre);
    EXPECT_EQ(a[i].velocity, b[i].velocity);
    EXPECT_EQ(a[i].angularVelocity, b[i].angularVelocity);
  }
  PairRecord bad;
  bad.first = 1;
  bad.second = 0;
  EXPECT_THROW(restarted.setHistory({bad}), std::invalid_argument);
}

TEST(DryCollision, ASustainedLoadIsCarriedWithinTheOverlapCap) {
  // a sphere resting on the floor under its weight, with a contact time of
  // 40 ms (ten fluid steps of 4 ms): the spring made for it would sink the
  // sphere by g T_c^2/(pi^2 + ln^2 e) = 1.6 mm, 80 % of its radius. A drag
  // -c v (as a liquid's film gives) keeps it slow, so that the speed rule of
  // the first touch does not see an impact. Declared as the body's external
  // force, the load stiffens the contact so that the sphere rests about half
  // the cap (0.1 a) deep; undeclared, the sphere creeps in until the energy
  // rule (the slow approach's kinetic energy against the overlap left) holds
  // it at the cap
  const Scalar a = 2e-3, contactTime = 0.04, dt = 1e-4, drag = 1;  // drag dt/m = 0.38
  const Vec3 g(0, 0, -9.81);
  const Scalar cap = 0.1 * a;
  std::vector<Scalar> resting;
  for (const bool declared : {true, false}) {
    CollisionModel model = makeModel(contactOnly(0.9), {PlaneWall{"floor", Vec3::Zero(), Vec3::UnitZ()}});
    RigidBody b = sphere(a, Vec3(0, 0, a), Vec3::Zero());
    Scalar deepest = 0;
    for (int step = 0; step < 20000; ++step) {  // 2 s, the contact's oscillation damped
      std::vector<CollisionBody> cb{b.collisionBody()};
      const Vec3 external = b.mass() * g - drag * b.velocity;
      if (declared) cb[0].externalForce = external;
      std::vector<Vec3> F, T;
      model.forces(cb, contactTime, dt, F, T);
      advanceBody(b, F[0] + external, T[0], dt);
      ASSERT_TRUE(b.centre.allFinite());
      deepest = std::max(deepest, a - b.centre.z());
    }
    resting.push_back(a - b.centre.z());
    EXPECT_GT(resting.back(), 0) << declared;
    EXPECT_GT(model.statistics().stiffened, 0) << declared;
    // while the body creeps in, the drag offsets part of its weight and the
    // spring is stiffened gradually (dF = k d(delta) does not push it back out)
    EXPECT_LE(deepest, 1.01 * cap) << declared << ": the landing stays within the cap";
  }
  std::printf("resting overlap / cap: load declared %.3f, undeclared %.3f\n", resting[0] / cap,
              resting[1] / cap);
  EXPECT_LE(resting[0], 0.75 * cap) << "the declared load is held within the cap";
  EXPECT_GT(resting[1], 0.95 * cap) << "undeclared, only the approach holds it, at the cap";
}

TEST(DryCollision, TheSustainedLoadOverlapSetsTheRestingOverlap) {
  // the sphere of the test above, its weight declared, with the static
  // overlap of a sustained load at 1/4, 1/2 and all of the cap: the stiffer
  // the rule, the shallower it rests; within the cap at each (at f = 1 the
  // energy rule holds the creeping body, as the load rule alone does not)
  const Scalar a = 2e-3, contactTime = 0.04, dt = 1e-4, drag = 1;
  const Vec3 g(0, 0, -9.81);
  const Scalar cap = 0.1 * a;
  std::vector<Scalar> resting;
  for (const Scalar fraction : {0.25, 0.5, 1.0}) {
    ModelSetup s = contactOnly(0.9);
    s.laws.contact.sustainedLoadOverlap = fraction;
    CollisionModel model = makeModel(s, {PlaneWall{"floor", Vec3::Zero(), Vec3::UnitZ()}});
    RigidBody b = sphere(a, Vec3(0, 0, a), Vec3::Zero());
    for (int step = 0; step < 20000; ++step) {
      std::vector<CollisionBody> cb{b.collisionBody()};
      const Vec3 external = b.mass() * g - drag * b.velocity;
      cb[0].externalForce = external;
      std::vector<Vec3> F, T;
      model.forces(cb, contactTime, dt, F, T);
      advanceBody(b, F[0] + external, T[0], dt);
      ASSERT_TRUE(b.centre.allFinite());
    }
    resting.push_back(a - b.centre.z());
    EXPECT_GT(resting.back(), 0) << fraction;
    // the spring is stiffened while the body creeps in (dF = k d(delta)):
    // the rest overlap exceeds the fraction of the cap that the rule aims at
    EXPECT_LE(resting.back(), cap) << fraction;
  }
  std::printf("resting overlap / cap at 1/4, 1/2, 1: %.3f %.3f %.3f\n", resting[0] / cap,
              resting[1] / cap, resting[2] / cap);
  EXPECT_LT(resting[0], resting[1]);
  EXPECT_LT(resting[1], resting[2]);
}

TEST(DryCollision, ARestartInsideALoadedStackContinuesBitwise) {
  // two spheres stacked on the floor under their weight (declared as external
  // forces, with a drag as a liquid gives): the load rule reads each body's
  // other contacts from the last call; a model given history() mid-way must
  // continue exactly as the one that kept its state
  const Scalar a = 1e-3, contactTime = 0.04, dt = 1e-4, drag = 0.5;
  const Vec3 g(0, 0, -9.81);
  const std::vector<PlaneWall> walls{PlaneWall{"floor", Vec3::Zero(), Vec3::UnitZ()}};
  auto step = [&](std::vector<RigidBody>& b, CollisionModel& model) {
    std::vector<CollisionBody> cb;
    std::vector<Vec3> external;
    for (const RigidBody& x : b) {
      external.push_back(x.mass() * g - drag * x.velocity);
      cb.push_back(x.collisionBody());
      cb.back().externalForce = external.back();
    }
    std::vector<Vec3> F, T;
    model.forces(cb, contactTime, dt, F, T);
    for (std::size_t i = 0; i < b.size(); ++i) advanceBody(b[i], F[i] + external[i], T[i], dt);
  };
  std::vector<RigidBody> b{sphere(a, Vec3(0, 0, a), Vec3::Zero()),
                           sphere(a, Vec3(0.3 * a, 0, a + 1.977 * a), Vec3::Zero())};  // touching
  CollisionModel model = makeModel(contactOnly(0.9), walls);
  // restart while the load still grows (the upper sphere settling): a lost
  // load of the other contact would leave a spring softer than it should be
  for (int k = 0; k < 5; ++k) step(b, model);
  ASSERT_EQ(model.activeContacts(), 2u) << "both contacts under way";
  const std::vector<PairRecord> saved = model.history();
  std::vector<RigidBody> c = b;
  CollisionModel restarted = makeModel(contactOnly(0.9), walls);
  restarted.setHistory(saved);
  // the pairs' last contact forces (the other contacts' load) survive the restart
  const std::vector<PairRecord> again = restarted.history();
  ASSERT_EQ(again.size(), saved.size());
  for (std::size_t k = 0; k < saved.size(); ++k) {
    EXPECT_GT(saved[k].contactForce.norm(), 0) << k;
    EXPECT_EQ(again[k].contactForce, saved[k].contactForce) << k;
  }
  for (int k = 0; k < 300; ++k) {
    step(b, model);
    step(c, restarted);
  }
  for (std::size_t i = 0; i < b.size(); ++i) {
    EXPECT_EQ(b[i].centre, c[i].centre) << i;
    EXPECT_EQ(b[i].velocity, c[i].velocity) << i;
  }
  EXPECT_GT(model.statistics().stiffened, 0) << "the load rule acted";
}

namespace {

/// Tangential speed along x of the lowest point of a sphere of radius r (the contact point on z = 0).
Scalar contactPointSlip(const RigidBody& b, Scalar r) {
  return (b.velocity + b.angularVelocity.cross(Vec3(0, 0, -r))).x();
}

/// A sphere (r 2 mm, steel) thrown at the floor with a tangential speed ut
/// and the normal speed 0.5 m/s, friction mu of the given law, e 0.9, 40
/// sub-steps per contact: its velocity after the impact.
RigidBody obliqueSphereImpact(Scalar ut, Scalar mu, const std::string& law) {
  const Scalar r = 2e-3;
  std::vector<RigidBody> b{sphere(r, Vec3(0, 0, r + 1e-5), Vec3(ut, 0, -0.5))};
  ModelSetup s = contactOnly(0.9);
  s.laws.contact.friction = mu;
  s.laws.contact.frictionModel = law;
  s.settings.subStepsPerContact = 40;
  CollisionModel model = makeModel(s, {PlaneWall{"floor", Vec3::Zero(), Vec3::UnitZ()}});
  simulate(b, model, 1e-5, 1e-3);
  EXPECT_EQ(model.activeContacts(), 0u);
  return b[0];
}

}  // namespace

TEST(Friction, ASphereThatSticksLeavesWithItsContactPointsSlipReversedByE) {
  // small slip (0.05 against 0.5 normal): the tangential impulse that
  // reverses it is far below mu times the normal one, so the contact sticks;
  // the tangential spring has the normal one's period and damping, and
  // returns the contact point's slip with -e (0.9). Sliding friction only
  // stops it (slip 0 after the impact)
  const Scalar r = 2e-3, ut = 0.05;
  const RigidBody spring = obliqueSphereImpact(ut, 0.5, "coulombSpring");
  EXPECT_NEAR(contactPointSlip(spring, r) / ut, -0.9, 0.05);
  EXPECT_NEAR(spring.velocity.z() / 0.5, 0.9, 0.02);
  const RigidBody sliding = obliqueSphereImpact(ut, 0.5, "coulombSliding");
  EXPECT_LT(std::abs(contactPointSlip(sliding, r)) / ut, 0.05);
}

TEST(Friction, ASphereThatSlidesGetsMuTimesTheNormalImpulseWithEitherLaw) {
  // large slip (1 m/s) and mu 0.1: sliding throughout, the tangential impulse
  // is mu (1 + e) m u_n: the centre loses 0.1 x 1.9 x 0.5 = 0.095 m/s
  for (const std::string law : {"coulombSpring", "coulombSliding"}) {
    const RigidBody b = obliqueSphereImpact(1.0, 0.1, law);
    EXPECT_NEAR(1.0 - b.velocity.x(), 0.1 * 1.9 * 0.5, 0.002) << law;
    EXPECT_GT(contactPointSlip(b, 2e-3), 0.5) << law << ": still sliding";
  }
}

TEST(Friction, AProlateOnAnInclineIsHeldByStaticFrictionWithTheSpringOnly) {
  // a prolate spheroid (4 x 2 x 2 mm) lying on the floor with its axis down
  // the slope of gravity (tan theta 0.3 < mu 0.5: it must not move), the load
  // declared, a drag -c v (c dt/m = 0.1, as a liquid gives) that damps its
  // rocking onto the contact point below its centre; contact time 1 ms (10
  // steps). With the spring it comes to rest; with sliding friction only it
  // creeps down the slope at a steady speed (measured 0.48 mm/s)
  const Scalar a = 2e-3, b = 1e-3, theta = std::atan(0.3), drag = 0.02;
  const Vec3 g = 9.81 * Vec3(std::sin(theta), 0, -std::cos(theta));
  const Scalar dt = 1e-4, contactTime = 1e-3;
  Scalar drift[2], speed[2];
  int k = 0;
  for (const std::string law : {"coulombSpring", "coulombSliding"}) {
    ModelSetup s = contactOnly(0.5);
    s.laws.contact.friction = 0.5;
    s.laws.contact.frictionModel = law;
    CollisionModel model = makeModel(s, {PlaneWall{"floor", Vec3::Zero(), Vec3::UnitZ()}});
    RigidBody body;
    body.semiAxes = Vec3(a, b, b);
    body.density = 2500;
    body.centre = Vec3(0, 0, b);
    Scalar xHalf = 0;
    const int steps = 5000;  // 0.5 s
    for (int step = 0; step < steps; ++step) {
      std::vector<CollisionBody> cb{body.collisionBody()};
      const Vec3 external = body.mass() * g - drag * body.velocity;
      cb[0].externalForce = external;
      std::vector<Vec3> F, T;
      model.forces(cb, contactTime, dt, F, T);
      advanceBody(body, F[0] + external, T[0], dt);
      ASSERT_TRUE(body.centre.allFinite());
      ASSERT_EQ(model.activeContacts(), step == 0 ? model.activeContacts() : 1u) << law << " lost the floor";
      if (step == steps / 2) xHalf = body.centre.x();
    }
    drift[k] = body.centre.x() - xHalf;  // over the last 0.25 s
    speed[k++] = body.velocity.x();
  }
  EXPECT_GT(speed[1], 1e-4) << "sliding friction alone creeps";
  EXPECT_GT(drift[1], 1e-5);
  EXPECT_LT(std::abs(speed[0]), 1e-3 * speed[1]) << "the spring holds it";
  EXPECT_LT(std::abs(drift[0]), 1e-6);
}

TEST(Friction, ASphereRollingOnTheFloorDeceleratesAtFiveSeventhsMuRG) {
  // a sphere (r 2 mm) rolling without slip at 0.1 m/s on the floor under its
  // weight (declared), friction 0.5 (it keeps rolling), rolling friction
  // mu_r: dv/dt = -(5/7) mu_r g; without it the speed is kept
  const Scalar r = 2e-3, dt = 1e-4, contactTime = 1e-3;
  const Vec3 g(0, 0, -9.81);
  for (const Scalar muR : {0.0, 0.02, 0.05}) {
    ModelSetup s = contactOnly(0.5);
    s.laws.contact.friction = 0.5;
    s.laws.contact.rollingFriction = muR;
    CollisionModel model = makeModel(s, {PlaneWall{"floor", Vec3::Zero(), Vec3::UnitZ()}});
    RigidBody b = sphere(r, Vec3(0, 0, r), Vec3(0.1, 0, 0));
    b.angularVelocity = Vec3(0, 0.1 / r, 0);
    Scalar v0 = 0;
    const int steps = 1500, start = 500;  // measured over 0.05-0.15 s
    for (int step = 0; step < steps; ++step) {
      std::vector<CollisionBody> cb{b.collisionBody()};
      cb[0].externalForce = b.mass() * g;
      std::vector<Vec3> F, T;
      model.forces(cb, contactTime, dt, F, T);
      advanceBody(b, F[0] + b.mass() * g, T[0], dt);
      if (step == start) v0 = b.velocity.x();
    }
    const Scalar deceleration = (v0 - b.velocity.x()) / ((steps - 1 - start) * dt);
    const Scalar expected = 5.0 / 7.0 * muR * 9.81;
    EXPECT_NEAR(deceleration, expected, 0.03 * expected + 2e-3) << "mu_r " << muR;
    EXPECT_LT(std::abs(contactPointSlip(b, r)), 1e-3) << "rolls without slipping";
  }
}
