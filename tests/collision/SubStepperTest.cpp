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
