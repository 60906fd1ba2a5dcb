// Moving Balls: the paper's stopping rule (eq. 2.9, F.6) and the App. E test.
#include "ellipsoids/MovingBalls.hpp"
#include "TestGeometry.hpp"

#include <gtest/gtest.h>

using namespace ellipsoids;
using namespace testgeometry;

TEST(MovingBalls, AngleTestOfAppendixE) {
  const Vec3 a(1, 0, 0);
  for (Scalar angle : {1e-4, 1e-2, 0.3}) {
    const Vec3 b(std::cos(angle), std::sin(angle), 0);
    EXPECT_TRUE(angleWithin(a, 2 * b, angle * 1.01));
    EXPECT_FALSE(angleWithin(a, b, angle * 0.9));
  }
  EXPECT_FALSE(angleWithin(a, -a, 0.1));  // opposite vectors: the squared test alone would pass
}

TEST(MovingBalls, EpsThetaFollowsEq29) {
  const Ellipsoid e1(Vec3(2, 1, 1), Vec3::Zero(), Quat::Identity());
  const Ellipsoid e2 = Ellipsoid::sphere(1, Vec3(5, 0, 0));
  // max R_max: 4 (a^2/b) and 1
  EXPECT_NEAR(epsThetaGlobal(e1, e2, 1e-6), std::sqrt(2e-6 / 5), 1e-15);
}

TEST(MovingBalls, PaperRuleMeetsTheToleranceOnTheMirrorCase) {
  const MovingBalls mb;
  for (bool adaptive : {false, true}) {
    for (Scalar ar : {1.0 / 6, 3.0}) {
      for (Scalar d : {1.0, 1e-4}) {
        const MirrorCase m = mirrorCase(ar, d, 1);
        DistanceOptions o;
        o.epsD = 1e-6;
        o.adaptiveEpsTheta = adaptive;
        const DistanceResult r = mb.distance(m.e1, m.e2, o);
        EXPECT_EQ(r.status, DistanceStatus::converged);
        EXPECT_LE(std::abs(r.distance - m.exactDistance), 1e-6);
        EXPECT_LE(r.lower, m.exactDistance);
        EXPECT_GE(r.upper, m.exactDistance);
      }
    }
  }
}

TEST(MovingBalls, AdaptiveEpsThetaNeedsNoMoreIterations) {
  const MovingBalls mb;
  const MirrorCase m = mirrorCase(6, 1e-2, 1);
  DistanceOptions o;
  o.epsD = 1e-6;
  const int fixed = mb.distance(m.e1, m.e2, o).iterations;
  o.adaptiveEpsTheta = true;
  EXPECT_LE(mb.distance(m.e1, m.e2, o).iterations, fixed);
}

TEST(MovingBalls, CentreSegmentPointsDetectOverlap) {
  Vec3 x1, x2;
  const Ellipsoid s1 = Ellipsoid::sphere(1, Vec3::Zero());
  EXPECT_TRUE(centreSegmentPoints(s1, Ellipsoid::sphere(1, Vec3(3, 0, 0)), x1, x2));
  EXPECT_LT((x1 - Vec3(1, 0, 0)).norm(), 1e-15);
  EXPECT_LT((x2 - Vec3(2, 0, 0)).norm(), 1e-15);
  EXPECT_FALSE(centreSegmentPoints(s1, Ellipsoid::sphere(1, Vec3(1.5, 0, 0)), x1, x2));
  EXPECT_FALSE(centreSegmentPoints(s1, Ellipsoid::sphere(3, Vec3(0.5, 0, 0)), x1, x2));
  EXPECT_FALSE(centreSegmentPoints(s1, s1, x1, x2));
}
