// Collisions across periodic boundaries: a cluster of bodies straddling the
// faces (and a corner) of a triply periodic box gets the same contact and
// lubrication forces, the same damping solve and the same pair histories (per
// image) as the same cluster in the middle of the box.
#include "collision/RigidBody.hpp"
#include "ModelSetup.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

using namespace collision;

namespace {

/// A cluster of spheroids (Ar 3 and 1/3, D_eq 1 mm) around centre, some
/// overlapping, some within the lubrication reach.
std::vector<CollisionBody> cluster(const Vec3& centre, const PeriodicBox& box) {
  std::mt19937_64 rng(81);
  std::normal_distribution<Scalar> g;
  std::vector<CollisionBody> bodies;
  for (int k = 0; k < 12; ++k) {
    RigidBody b;
    const Scalar ar = k % 2 ? 3.0 : 1.0 / 3;
    b.semiAxes = Vec3(std::cbrt(ar * ar), 1 / std::cbrt(ar), 1 / std::cbrt(ar)) * 0.5e-3;
    const Vec3 offset = 0.75e-3 * Vec3(k % 3 - 1.0, (k / 3) % 2 - 0.5, k / 6 - 0.5) +
                        0.1e-3 * Vec3(g(rng), g(rng), g(rng));
    b.centre = box.wrap(centre + offset);  // as the coupling keeps them: inside the box
    b.orientation = Quat(g(rng), g(rng), g(rng), g(rng)).normalized();
    b.velocity = 1e-2 * Vec3(g(rng), g(rng), g(rng));
    b.angularVelocity = 10 * Vec3(g(rng), g(rng), g(rng));
    b.density = 2500;
    bodies.push_back(b.collisionBody());
  }
  return bodies;
}

CollisionModel lubricatedModel(const PeriodicBox& box) {
  ModelSetup s;
  s.model = "lubricatedSpringDashpot";
  s.laws.viscosity = 1e-3;
  s.laws.lubrication.pairActivation = 0.5;  // wide: many lubricated pairs
  s.settings.distanceAccuracy = 1e-10;
  CollisionModel model = makeModel(s, {});
  model.setPeriodicBox(box);
  return model;
}

Scalar largest(const std::vector<Vec3>& v) {
  Scalar m = 0;
  for (const Vec3& x : v) m = std::max(m, x.norm());
  return m;
}

}  // namespace

TEST(PeriodicCollision, AClusterAcrossTheFacesFeelsWhatItFeelsInTheMiddle) {
  const PeriodicBox box(Vec3(0.01, -0.02, 0.003), Vec3(12e-3, 11e-3, 13e-3), {true, true, true});
  const Vec3 middle = box.origin() + 0.5 * box.length();
  const std::vector<CollisionBody> inside = cluster(middle, box);
  std::vector<Vec3> F0, T0, D0, G0;
  CollisionModel reference = lubricatedModel(box);
  reference.forces(inside, 1e-3, 1e-4, F0, T0);
  const CollisionStatistics s0 = reference.statistics();
  ASSERT_GT(s0.contacts, 2);
  ASSERT_GT(s0.lubricated, 5);
  std::vector<Vec3> v0, w0;
  for (const CollisionBody& b : inside) {
    v0.push_back(b.velocity);
    w0.push_back(b.angularVelocity);
  }
  reference.dampingForces(inside, v0, w0, {}, {}, 1e-4, D0, G0);

  // the same cluster around a face centre, an edge and a corner
  const Vec3 L = box.length();
  const std::vector<Vec3> places = {box.origin() + Vec3(0, 0.5 * L.y(), 0.5 * L.z()),
                                    box.origin() + Vec3(0, 0, 0.5 * L.z()), box.origin(),
                                    Vec3(box.origin() + L)};
  for (const Vec3& at : places) {
    const std::vector<CollisionBody> across = cluster(at, box);
    CollisionModel model = lubricatedModel(box);
    std::vector<Vec3> F, T, D, G;
    model.forces(across, 1e-3, 1e-4, F, T);
    const CollisionStatistics s = model.statistics();
    EXPECT_EQ(s.contacts, s0.contacts);
    EXPECT_EQ(s.lubricated, s0.lubricated);
    EXPECT_EQ(s.candidatePairs, s0.candidatePairs);
    model.dampingForces(across, v0, w0, {}, {}, 1e-4, D, G);
    // the coordinates differ by whole periods: forces agree to their rounding
    const Scalar f = largest(F0), t = largest(T0), d = largest(D0), gg = largest(G0);
    for (std::size_t i = 0; i < inside.size(); ++i) {
      EXPECT_LT((F[i] - F0[i]).norm(), 1e-7 * f) << "body " << i << " at " << at.transpose();
      EXPECT_LT((T[i] - T0[i]).norm(), 1e-7 * t) << "body " << i;
      EXPECT_LT((D[i] - D0[i]).norm(), 1e-7 * d) << "body " << i;
      EXPECT_LT((G[i] - G0[i]).norm(), 1e-7 * gg) << "body " << i;
    }
    // the pairs that meet across a face remember their image
    const std::vector<PairRecord> history = model.history();
    EXPECT_TRUE(std::any_of(history.begin(), history.end(), [](const PairRecord& r) {
      return r.image != std::array<int, 3>{0, 0, 0};
    }));
    // and a restart from that history continues it (same forces on the next call)
    CollisionModel restarted = lubricatedModel(box);
    restarted.setHistory(history);
    EXPECT_EQ(restarted.history().size(), history.size());
    std::vector<Vec3> F1, T1, F2, T2;
    model.forces(across, 1e-3, 1e-4, F1, T1);
    restarted.forces(across, 1e-3, 1e-4, F2, T2);
    for (std::size_t i = 0; i < inside.size(); ++i) EXPECT_EQ(F1[i], F2[i]) << "body " << i;
  }
}

TEST(PeriodicCollision, WithoutThePeriodicBoxTheFacesSeparateTheBodies) {
  // the same straddling cluster without periodic axes: the pairs across the faces are apart
  const PeriodicBox box(Vec3::Zero(), Vec3(12e-3, 12e-3, 12e-3), {true, true, true});
  const std::vector<CollisionBody> across = cluster(box.origin(), box);
  std::vector<Vec3> F, T;
  CollisionModel periodic = lubricatedModel(box);
  periodic.forces(across, 1e-3, 1e-4, F, T);
  CollisionModel open = lubricatedModel(PeriodicBox());
  open.forces(across, 1e-3, 1e-4, F, T);
  EXPECT_LT(open.statistics().contacts, periodic.statistics().contacts);
}

TEST(PeriodicCollision, HistoryWithABadImageIsRejected) {
  CollisionModel model = lubricatedModel(PeriodicBox(Vec3::Zero(), Vec3(12e-3, 12e-3, 12e-3), {true, true, true}));
  PairRecord r;
  r.first = 0;
  r.second = 1;
  r.image = {3, 0, 0};  // more periods away than an image code holds
  try {
    model.setHistory({r});
    FAIL() << "image (3 0 0) accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("image multiples must be in [-2, 2]"), std::string::npos) << e.what();
  }
  r.image = {1, 0, -1};
  r.warm = true;
  r.direction = Vec3(1, 0, 0);
  model.setHistory({r});
  ASSERT_EQ(model.history().size(), 1u);
  EXPECT_EQ(model.history()[0].image, (std::array<int, 3>{1, 0, -1}));
}
