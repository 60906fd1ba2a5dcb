// GJK: the paper's initial vector (eq. 3.3), overlap, bracket = [mu, |v|].
#include "ellipsoids/Gjk.hpp"
#include "TestGeometry.hpp"

#include <gtest/gtest.h>

using namespace ellipsoids;
using namespace testgeometry;

TEST(Gjk, CentreLineStartSolvesTheMirrorCaseAtOnce) {
  // the paper notes v0 = r1 - r2 gives the answer in one iteration
  const Gjk gjk;
  const MirrorCase m = mirrorCase(3, 1e-2, 1);
  DistanceOptions o;
  o.epsD = 1e-8;
  const DistanceResult r = gjk.distance(m.e1, m.e2, o);
  EXPECT_EQ(r.status, DistanceStatus::converged);
  EXPECT_LE(r.iterations, 1);
}

TEST(Gjk, Eq33StartConvergesWithinTheTolerance) {
  const Gjk gjk;
  for (Scalar ar : {1.0 / 6, 1.0 / 3, 2.0 / 3, 1.5, 3.0, 6.0}) {
    for (Scalar d : {1.0, 1e-3, 1e-6}) {
      const MirrorCase m = mirrorCase(ar, d, 1);
      DistanceOptions o;
      o.epsD = 1e-8;
      o.useInitialDirection = true;
      o.initialDirection = -Vec3(2 * m.xc, 2 * m.b, 2 * m.b).normalized();  // v0 = (2xc, 2b, 2b)
      const DistanceResult r = gjk.distance(m.e1, m.e2, o);
      EXPECT_EQ(r.status, DistanceStatus::converged);
      EXPECT_GT(r.iterations, 1);
      EXPECT_LE(std::abs(r.distance - m.exactDistance), 1e-8);
      EXPECT_LE(r.lower, m.exactDistance);
      EXPECT_GE(r.upper, m.exactDistance);
    }
  }
}

TEST(Gjk, OverlapWhenTheSimplexEnclosesTheOrigin) {
  const Gjk gjk;
  DistanceOptions o;
  o.epsD = 1e-8;
  const DistanceResult r =
      gjk.distance(Ellipsoid::sphere(1, Vec3::Zero()), Ellipsoid::sphere(1, Vec3(1, 0.2, 0.1)), o);
  EXPECT_EQ(r.status, DistanceStatus::overlapping);
  EXPECT_EQ(r.distance, 0);
}
