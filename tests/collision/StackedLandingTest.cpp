// A stacked pair landing on a wall, through the collision sub-step coupled
// runs use (SubStepper): the trailing body, pushed onto the leading one by
// the flow, keeps coming on when the wall stops the leading one. The pair's
// contact, made for the slow kissing and the push, must take up that
// approach within the overlap cap (SpringDashpotContact's energy rule).
#include "collision/SubStepper.hpp"
#include "collision/RigidBody.hpp"
#include "ModelSetup.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

using namespace collision;

namespace {

/// Bodies under their buoyant weight; the first (the leading one) also
/// under a drag -c u, which carries the pair's weight: the second is pushed
/// onto it as the trailing body of a drafting pair is.
class DraggedPair : public BodySet {
 public:
  DraggedPair(const std::vector<RigidBody>& bodies, const Vec3& g, Scalar drag)
      : bodies_(bodies), g_(g), drag_(drag) {}
  std::size_t size() const override { return bodies_.size(); }
  CollisionBody collisionBody(std::size_t i, const BodyState& s) const override {
    CollisionBody b = bodies_[i].collisionBody(s);
    b.externalForce = external(i, s);
    return b;
  }
  void advance(std::size_t i, BodyState& s, Scalar, Scalar dt, const Vec3& fc,
               const Vec3& tc) const override {
    const RigidBody& b = bodies_[i];
    advanceRigidBody(s, dt, (external(i, s) + fc) * dt, tc * dt, b.mass(), b.bodyInertia());
  }

 private:
  Vec3 external(std::size_t i, const BodyState& s) const {
    Vec3 f = bodies_[i].mass() * g_;
    if (i == 0) f -= drag_ * s.velocity;
    return f;
  }
  const std::vector<RigidBody>& bodies_;
  Vec3 g_;
  Scalar drag_;
};

}  // namespace

TEST(StackedLanding, TheTrailingBodyIsStoppedWithinTheOverlapCap) {
  // the spheres of validation/drafting (d = 1/6 cm, rho_p 1140 in water),
  // in contact, falling at 0.09 m/s onto the floor; fluid steps of 1 ms,
  // contact time 10 steps. The pair's contact carries the push (one buoyant
  // weight) at about half the cap; the wall's impact then stops the leading
  // sphere within a few sub-steps while the trailing one comes on at 0.09 m/s
  const Scalar a = 0.8333e-3, dt = 1e-3;
  const Vec3 g(0, 0, -9.81 * 140 / 1140);
  for (const Scalar e : {0.97, 0.5}) {
    RigidBody leading;
    leading.semiAxes = Vec3::Constant(a);
    leading.density = 1140;
    leading.centre = Vec3(0, 0, 12 * a);
    leading.velocity = Vec3(0, 0, -0.05);
    RigidBody trailing = leading;
    trailing.centre = Vec3(0.01 * a, 0, 14 * a + 1e-7);
    const std::vector<RigidBody> bodies{leading, trailing};
    const Scalar drag = leading.mass() * g.norm() / 0.05;  // terminal speed 0.1 m/s
    DraggedPair set(bodies, g, drag);
    std::vector<BodyState> states{leading, trailing};
    ModelSetup s;
    s.laws.contact.restitution = e;
    CollisionModel model = makeModel(s, {PlaneWall{"floor", Vec3::Zero(), Vec3::UnitZ()}});
    SubStepper stepper;
    Scalar landing = 0, before = 0;
    bool landed = false;
    for (int k = 0; k < 300; ++k) {
      const Scalar speed = states[1].velocity.z();
      stepper.stepIslands(set, states, model, 10 * dt, k * dt, dt, 1);
      for (const BodyState& b : states) ASSERT_TRUE(b.centre.allFinite());
      landed = landed || states[0].centre.z() <= a;
      if (!landed) {
        before = model.statistics().maxOverlapRatio;
        landing = speed;
      }
    }
    const Scalar cap = 0.1;  // maxOverlap, of the radius
    const Scalar largest = model.statistics().maxOverlapRatio;
    std::printf("e %.2f: landing at %.4f m/s, largest overlap / cap %.3f before the landing, %.3f in it\n",
                e, -landing, before / cap, largest / cap);
    ASSERT_LT(landing, -0.08) << "e " << e << ": the pair lands at speed";
    EXPECT_LT(before, 0.6 * cap) << "e " << e << ": the pair's contact carries the push";
    EXPECT_LE(largest, 1.05 * cap) << "e " << e << ": the landing stays within the cap";
    EXPECT_GT(model.statistics().stiffened, 0);
  }
}
