// The distanceMethod setting: checked against the methods that can serve, and
// whatever the choice, the same contacts (penetration depth from the signed
// dual method) and the same lubrication to the distance accuracy.
#include "collision/RigidBody.hpp"
#include "ModelSetup.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>

using namespace collision;

TEST(DistanceMethodChoice, TheSettingIsCheckedAgainstTheMethodsThatCanServe) {
  CollisionSettings s;
  EXPECT_EQ(s.distanceMethod, "dual");
  EXPECT_EQ(CollisionSettings::distanceMethods().front(), "dual");
  for (const std::string& name : CollisionSettings::distanceMethods()) {
    s.distanceMethod = name;
    EXPECT_NO_THROW(s.validate()) << name;
  }
  for (const std::string bad : {"newtonCoulomb", "exteriorPenalty", "jain", "gkj", ""}) {
    s.distanceMethod = bad;
    try {
      s.validate();
      ADD_FAILURE() << "'" << bad << "' accepted";
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("distanceMethod = " + bad), std::string::npos) << what;
      EXPECT_NE(what.find("dual, paper, auto, gjk, movingBalls"), std::string::npos) << what;
    }
  }
}

namespace {

/// A cluster of spheroids (Ar 3 and 1/3, D_eq 1 mm), some overlapping, some
/// within the lubrication reach.
std::vector<CollisionBody> cluster() {
  std::mt19937_64 rng(81);
  std::normal_distribution<Scalar> g;
  std::vector<CollisionBody> bodies;
  for (int k = 0; k < 12; ++k) {
    RigidBody b;
    const Scalar ar = k % 2 ? 3.0 : 1.0 / 3;
    b.semiAxes = Vec3(std::cbrt(ar * ar), 1 / std::cbrt(ar), 1 / std::cbrt(ar)) * 0.5e-3;
    b.centre = 0.75e-3 * Vec3(k % 3, (k / 3) % 2, k / 6) + 0.1e-3 * Vec3(g(rng), g(rng), g(rng));
    b.orientation = Quat(g(rng), g(rng), g(rng), g(rng)).normalized();
    b.velocity = 1e-2 * Vec3(g(rng), g(rng), g(rng));
    b.density = 2500;
    bodies.push_back(b.collisionBody());
  }
  return bodies;
}

}  // namespace

TEST(DistanceMethodChoice, SameContactsAndLubricationWhateverTheMethod) {
  const std::vector<CollisionBody> bodies = cluster();
  auto run = [&](const std::string& method, std::vector<Vec3>& F, std::vector<Vec3>& T) {
    ModelSetup s;
    s.model = "lubricatedSpringDashpot";
    s.laws.viscosity = 1e-3;
    s.laws.lubrication.pairActivation = 0.5;  // wide: many lubricated pairs
    s.settings.distanceMethod = method;
    s.settings.distanceAccuracy = 1e-9;  // gaps equal to 1e-9 R_G: forces to about that
    CollisionModel model = makeModel(s, {});
    model.forces(bodies, 1e-3, 1e-4, F, T);
    return std::make_pair(model.statistics(), model.dampedPairs());
  };
  std::vector<Vec3> F0, T0;
  const auto [dual, dualDamped] = run("dual", F0, T0);
  std::cout << "[ info ] " << dual.candidatePairs << " candidate pairs, " << dual.contacts << " contacts, "
            << dual.lubricated << " lubricated\n";
  ASSERT_GT(dual.contacts, 2);    // the scene has overlaps
  ASSERT_GT(dual.lubricated, 5);  // and lubricated gaps
  EXPECT_EQ(dual.distanceQueries, dual.candidatePairs - dual.prefilterRejected);
  for (const char* method : {"paper", "auto", "gjk", "movingBalls"}) {
    std::vector<Vec3> F, T;
    const auto [stats, damped] = run(method, F, T);
    EXPECT_EQ(stats.contacts, dual.contacts) << method;
    EXPECT_EQ(stats.lubricated, dual.lubricated) << method;
    EXPECT_EQ(stats.distanceNotConverged, 0) << method;
    // the overlapping pairs were asked again, of the signed dual method (auto
    // answers unsigned too, even though it runs the dual)
    EXPECT_EQ(stats.distanceQueries, dual.distanceQueries + dual.contacts) << method;
    Scalar scale = 0;
    for (const Vec3& f : F0) scale = std::max(scale, f.norm());
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      EXPECT_LT((F[i] - F0[i]).norm(), 1e-6 * scale) << method << ", body " << i;
    }
    ASSERT_EQ(damped.size(), dualDamped.size()) << method;
    for (std::size_t k = 0; k < damped.size(); ++k) {
      EXPECT_NEAR(damped[k].gap, dualDamped[k].gap, 2e-9 * 0.5e-3) << method << ", pair " << k;
      // (the coefficient also takes the curvature radii at the closest points,
      // which a method places only to about sqrt(eps_d R): 5e-5 R here)
      EXPECT_NEAR(damped[k].lubrication, dualDamped[k].lubrication, 1e-3 * dualDamped[k].lubrication)
          << method << ", pair " << k;
    }
  }
}
