// The collision sub-step (SubStepper) over a BodySet with forces of its own:
// without a collision model the bodies move under those forces alone; with
// one, the collision force it reports for a sub-step is the one the body got
// (the momentum balance of every sub-step closes), each accepted step starts
// where the last ended, and a body falling onto a wall stays above it.
#include "collision/SubStepper.hpp"
#include "collision/RigidBody.hpp"
#include "ModelSetup.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

using namespace collision;

namespace {

/// Rigid bodies under a constant force each (gravity), recording the steps taken.
class LoadedBodies : public BodySet {
 public:
  LoadedBodies(const std::vector<RigidBody>& bodies, const Vec3& g) : bodies_(bodies), g_(g) {}

  std::size_t size() const override { return bodies_.size(); }
  CollisionBody collisionBody(std::size_t i, const BodyState& s) const override {
    CollisionBody b = bodies_[i].collisionBody(s);
    b.externalForce = bodies_[i].mass() * g_;
    return b;
  }
  void advance(std::size_t i, BodyState& s, Scalar, Scalar dt, const Vec3& fc,
               const Vec3& tc) const override {
    const RigidBody& b = bodies_[i];
    advanceRigidBody(s, dt, (b.mass() * g_ + fc) * dt, tc * dt, b.mass(), b.bodyInertia());
  }
  void accept(std::size_t i, const BodyState& start, const BodyState& end, Scalar dt,
              const Vec3& fc, const Vec3&) override {
    steps.push_back(Step{i, start, end, dt, fc});
  }

  struct Step {
    std::size_t body;
    BodyState start, end;
    Scalar dt;
    Vec3 collisionForce;
  };
  std::vector<Step> steps;

 private:
  const std::vector<RigidBody>& bodies_;
  Vec3 g_;
};

RigidBody sphere(Scalar r, const Vec3& c, const Vec3& u) {
  RigidBody b;
  b.semiAxes = Vec3::Constant(r);
  b.centre = c;
  b.velocity = u;
  b.density = 2500;
  return b;
}

}  // namespace

TEST(SubStepper, WithoutACollisionModelTheBodiesMoveUnderTheirOwnForces) {
  const std::vector<RigidBody> bodies{sphere(1e-3, Vec3(0, 0, 0.1), Vec3(0.2, 0, 0))};
  LoadedBodies set(bodies, Vec3(0, 0, -9.81));
  std::vector<BodyState> states{bodies[0]};
  SubStepper stepper;
  const Scalar dt = 1e-3;
  const int n = 50;
  for (int k = 0; k < n; ++k) {
    stepper.step(set, states, nullptr, 0, k * dt, dt);
    EXPECT_EQ(stepper.force()[0], Vec3::Zero());
  }
  const Scalar t = n * dt;
  // constant acceleration: the trapezoidal step is exact (round-off only)
  EXPECT_NEAR(states[0].velocity.z(), -9.81 * t, 1e-14);
  EXPECT_NEAR(states[0].centre.z(), 0.1 - 0.5 * 9.81 * t * t, 1e-14);
  EXPECT_NEAR(states[0].centre.x(), 0.2 * t, 1e-15);
  ASSERT_EQ(set.steps.size(), std::size_t(n));
  for (std::size_t k = 1; k < set.steps.size(); ++k) {
    EXPECT_EQ(set.steps[k].start.centre, set.steps[k - 1].end.centre);
  }
}

TEST(SubStepper, TheReportedCollisionForceIsTheOneTheBodyGot) {
  // a glass sphere dropped onto a floor: it bounces and comes to rest on it
  const PlaneWall floorWall{"floor", Vec3::Zero(), Vec3::UnitZ()};
  const Scalar a = 1e-3;
  const std::vector<RigidBody> bodies{sphere(a, Vec3(0, 0, 1.05 * a), Vec3(0, 0, -0.05))};
  LoadedBodies set(bodies, Vec3(0, 0, -9.81));
  ModelSetup setup;
  setup.laws.contact.restitution = 0.5;
  CollisionModel model = makeModel(setup, {floorWall});
  std::vector<BodyState> states{bodies[0]};
  SubStepper stepper;
  const Scalar dt = 2e-5, contactTime = 2e-4;
  Scalar lowest = 1, largestForce = 0, t = 0;
  for (int step = 0; step < 2000; ++step) {
    std::vector<CollisionBody> cb{set.collisionBody(0, states[0])};
    const int n = model.subSteps(cb, dt, contactTime);
    for (int k = 0; k < n; ++k, t += dt / n) {
      stepper.step(set, states, &model, contactTime, t, dt / n);
      const LoadedBodies::Step& s = set.steps.back();
      EXPECT_EQ(s.collisionForce, stepper.force()[0]);
      // m (u1 - u0) = (m g + F_c) dt: the step used the force it reports
      const Scalar m = bodies[0].mass();
      const Vec3 imbalance =
          m * (s.end.velocity - s.start.velocity) - (m * Vec3(0, 0, -9.81) + s.collisionForce) * s.dt;
      EXPECT_LE(imbalance.norm(), 1e-12 * m * 0.05) << "step " << step;
      lowest = std::min(lowest, states[0].centre.z() - a);
      largestForce = std::max(largestForce, stepper.force()[0].z());
    }
  }
  EXPECT_GT(largestForce, 0);                                  // it touched
  EXPECT_GT(lowest, -setup.settings.maxOverlap * a * 1.05);           // within the overlap cap
  EXPECT_LT(states[0].velocity.norm(), 1e-3);                   // and came to rest
  EXPECT_NEAR(stepper.force()[0].z(), bodies[0].mass() * 9.81, 0.05 * bodies[0].mass() * 9.81);
}

TEST(SubStepper, StatesOfAnotherSizeThanTheSetAreRejected) {
  const std::vector<RigidBody> bodies{sphere(1e-3, Vec3::Zero(), Vec3::Zero())};
  LoadedBodies set(bodies, Vec3::Zero());
  std::vector<BodyState> states(2);
  SubStepper stepper;
  EXPECT_THROW(stepper.step(set, states, nullptr, 0, 0, 1e-3), std::invalid_argument);
}

namespace {

/// a body set whose body 0 is pushed by a force that grows 10^4-fold in a
/// step (a speed the islands' margin cannot foresee)
class KickedBodies : public LoadedBodies {
 public:
  using LoadedBodies::LoadedBodies;
  void advance(std::size_t i, BodyState& s, Scalar t, Scalar dt, const Vec3& fc,
               const Vec3& tc) const override {
    LoadedBodies::advance(i, s, t, dt, fc, tc);
    if (i == 0) s.centre.x() += 2e-3;  // 2 mm a sub-step
  }
};

}  // namespace

TEST(SubStepper, IslandsTakeTheSubStepsOfTheirOwnContacts) {
  // two spheres colliding near the origin, and one far away: the pair takes
  // the sub-steps of its contact, the far one a single step, and the pair
  // moves exactly as when every body takes the pair's sub-steps
  const Scalar a = 1e-3;
  const std::vector<RigidBody> bodies{sphere(a, Vec3(-1.02 * a, 0, 0), Vec3(0.3, 0, 0)),
                                      sphere(a, Vec3(1.02 * a, 0, 0), Vec3(-0.3, 0, 0)),
                                      sphere(a, Vec3(0, 20 * a, 0), Vec3(0, 0.3, 0))};
  LoadedBodies set(bodies, Vec3(0, 0, -9.81));
  const Scalar dt = 1e-4, contactTime = 1e-4;
  CollisionModel islandsModel = makeModel(ModelSetup(), {});
  CollisionModel globalModel = makeModel(ModelSetup(), {});
  std::vector<BodyState> islandStates(bodies.begin(), bodies.end());
  std::vector<BodyState> globalStates = islandStates;
  SubStepper islands, global;
  int pairSteps = 0, together = 0;
  for (int step = 0; step < 20; ++step) {
    const Scalar t = step * dt;
    islands.stepIslands(set, islandStates, islandsModel, contactTime, t, dt, 1);
    const std::vector<Island>& found = islands.islands();
    // the far body alone, in one step
    ASSERT_GE(found.size(), 2u) << "step " << step;
    EXPECT_EQ(found.back().bodies, std::vector<int>{2}) << "step " << step;
    EXPECT_FALSE(found.back().interacts) << "step " << step;
    EXPECT_EQ(islands.subSteps()[2], 1) << "step " << step;
    if (found.size() != 2 || together < step) continue;  // the pair apart: compared while together
    ++together;
    EXPECT_TRUE(found[0].interacts);
    EXPECT_EQ(islands.subSteps()[0], found[0].subSteps);
    pairSteps = std::max(pairSteps, found[0].subSteps);
    // the global scheme: every body in the pair's sub-steps
    const int n = found[0].subSteps;
    for (int k = 0; k < n; ++k) {
      global.step(set, globalStates, &globalModel, contactTime, t + k * dt / n, dt / n);
    }
    for (int i = 0; i < 2; ++i) {
      EXPECT_LE((islandStates[i].centre - globalStates[i].centre).norm(), 1e-15) << "step " << step;
      EXPECT_LE((islandStates[i].velocity - globalStates[i].velocity).norm(), 1e-12) << "step " << step;
    }
  }
  EXPECT_GE(together, 3);
  EXPECT_GE(pairSteps, 10);  // the contact's
  EXPECT_LT(islandStates[0].velocity.x(), 0);  // the pair rebounded
  // the far body: one step a fluid step, free flight under gravity
  EXPECT_NEAR(islandStates[2].centre.y(), 20 * a + 0.3 * 20 * dt, 1e-15);
  EXPECT_NEAR(islandStates[2].velocity.z(), -9.81 * 20 * dt, 1e-14);
}

namespace {

/// Three steps of 0.1 ms of the kicked bodies (body 0 moved 2 mm a sub-step)
/// beside the walls: the message of the error they must end in ("" if none).
std::string kickedStepsError(const std::vector<RigidBody>& bodies, std::vector<PlaneWall> walls) {
  KickedBodies set(bodies, Vec3::Zero());
  CollisionModel model = makeModel(ModelSetup(), std::move(walls));
  std::vector<BodyState> states(bodies.begin(), bodies.end());
  SubStepper stepper;
  try {
    for (int step = 0; step < 3; ++step) stepper.stepIslands(set, states, model, 1e-4, step * 1e-4, 1e-4, 1);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(SubStepper, BodiesOfDifferentIslandsThatMeetWithinAStepAreAnError) {
  // body 0 at rest gets kicked 2 mm a sub-step towards body 1, 5 mm away:
  // the islands' margin (twice the largest speed, 0.3 m/s) foresaw 0.06 mm
  const Scalar a = 1e-3;
  const std::string what = kickedStepsError(
      {sphere(a, Vec3(0, 0, 0), Vec3::Zero()), sphere(a, Vec3(5 * a, 0, 0), Vec3(0.3, 0, 0))}, {});
  EXPECT_NE(what.find("body 0 and body 1"), std::string::npos) << what;
  EXPECT_NE(what.find("different islands"), std::string::npos) << what;
  EXPECT_NE(what.find("reduce the time step"), std::string::npos) << what;
}

TEST(SubStepper, ABodyWithoutCollisionForcesThatReachesAWallWithinAStepIsAnError) {
  // body 0 at rest, 4 mm from a wall, alone: its island takes no collision
  // forces; kicked 2 mm a sub-step it reaches the wall in the second step
  const Scalar a = 1e-3;
  const std::string what = kickedStepsError({sphere(a, Vec3(0, 0, 0), Vec3::Zero())},
                                            {PlaneWall{"side", Vec3(5 * a, 0, 0), -Vec3::UnitX()}});
  EXPECT_NE(what.find("body 0 and wall 'side'"), std::string::npos) << what;
  EXPECT_NE(what.find("reduce the time step"), std::string::npos) << what;
}
