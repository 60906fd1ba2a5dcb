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
#include <stdexcept>
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

/// The largest overlaps of a stacked landing, as fractions of the cap, and its cost.
struct Landing {
  Scalar speed = 0;        ///< the trailing body's speed when the leading one lands
  Scalar before = 0;       ///< largest overlap / cap before the landing
  Scalar largest = 0;      ///< largest overlap / cap over the run
  long stiffened = 0;      ///< contact evaluations that stiffened a spring
  long distances = 0;      ///< distance queries
  long subSteps = 0;       ///< the trailing body's sub-steps over the run
};

/// The spheres of validation/drafting (d = 1/6 cm, rho_p 1140 in water), in
/// contact, falling at 0.09 m/s onto the floor; fluid steps of 1 ms, contact
/// time 10 steps. The pair's contact carries the push (one buoyant weight)
/// at about half the cap; the wall's impact then stops the leading sphere
/// within a few sub-steps while the trailing one comes on at 0.09 m/s.
Landing stackedLanding(Scalar e, Scalar approachContactTimeScale) {
  const Scalar a = 0.8333e-3, dt = 1e-3, cap = 0.1;  // cap: maxOverlap, of the radius
  const Vec3 g(0, 0, -9.81 * 140 / 1140);
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
  s.settings.approachContactTimeScale = approachContactTimeScale;
  CollisionModel model = makeModel(s, {PlaneWall{"floor", Vec3::Zero(), Vec3::UnitZ()}});
  SubStepper stepper;
  Landing r;
  bool landed = false;
  for (int k = 0; k < 300; ++k) {
    const Scalar speed = states[1].velocity.z();
    stepper.stepIslands(set, states, model, 10 * dt, k * dt, dt, 1);
    r.subSteps += stepper.subSteps()[1];
    for (const BodyState& b : states) {
      if (!b.centre.allFinite()) throw std::runtime_error("non-finite centre");
    }
    landed = landed || states[0].centre.z() <= a;
    if (!landed) {
      r.before = model.statistics().maxOverlapRatio / cap;
      r.speed = -speed;
    }
  }
  r.largest = model.statistics().maxOverlapRatio / cap;
  r.stiffened = model.statistics().stiffened;
  r.distances = model.statistics().distanceQueries;
  return r;
}

}  // namespace

TEST(StackedLanding, TheTrailingBodyIsStoppedWithinTheOverlapCap) {
  for (const Scalar e : {0.97, 0.5}) {
    const Landing r = stackedLanding(e, CollisionSettings().approachContactTimeScale);
    std::printf("e %.2f: landing at %.4f m/s, largest overlap / cap %.3f before the landing, %.3f in it\n",
                e, r.speed, r.before, r.largest);
    ASSERT_GT(r.speed, 0.08) << "e " << e << ": the pair lands at speed";
    EXPECT_LT(r.before, 0.6) << "e " << e << ": the pair's contact carries the push";
    EXPECT_LE(r.largest, 1.05) << "e " << e << ": the landing stays within the cap";
    EXPECT_GT(r.stiffened, 0);
  }
}

TEST(StackedLanding, AShorterApproachBoundStiffensTheLanding) {
  // the approach check's shortest contact time halved and doubled: a shorter
  // bound stiffens more (a smaller overlap), a longer one less (the cap
  // overrun of a spring left soft). The cost of a shorter bound shows where
  // contacts persist (validation/dryCollisions, the WorkShare column)
  const Scalar scales[] = {0.5, 1, 2};
  Landing r[3];
  for (int i = 0; i < 3; ++i) {
    r[i] = stackedLanding(0.97, scales[i]);
    std::printf("approachContactTimeScale %.1f: largest overlap / cap %.3f, %ld sub-steps, "
                "%ld distance queries, %ld stiffened evaluations\n",
                scales[i], r[i].largest, r[i].subSteps, r[i].distances, r[i].stiffened);
  }
  EXPECT_LT(r[0].largest, r[1].largest);
  EXPECT_LT(r[1].largest, r[2].largest);
  EXPECT_GT(r[2].largest, 1.1) << "the bound doubled leaves the landing spring too soft";
}
