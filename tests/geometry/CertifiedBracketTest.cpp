// The certified bracket: L(n) <= d* <= |x2 - x1| whatever n and the points.
#include "ellipsoids/CertifiedBracket.hpp"
#include "ellipsoids/DistanceMethod.hpp"
#include "TestGeometry.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace ellipsoids;
using namespace testgeometry;

TEST(CertifiedBracket, SpheresAlongTheCentreLineIsExact) {
  const Ellipsoid s1 = Ellipsoid::sphere(1, Vec3(1, 2, 3));
  const Ellipsoid s2 = Ellipsoid::sphere(0.5, Vec3(4, 6, 3));
  const Vec3 n = (s2.centre() - s1.centre()).normalized();
  EXPECT_NEAR(separatingPlaneBound(s1, s2, n), 5 - 1.5, 1e-14);
  EXPECT_LT(separatingPlaneBound(s1, s2, Vec3(0, 0, 1)), 0);
}

TEST(CertifiedBracket, LowerBoundHoldsForAnyDirection) {
  std::mt19937_64 rng(21);
  const auto dual = makeDistanceMethod("dual");
  DistanceOptions tight;
  tight.epsD = 1e-12;
  for (int i = 0; i < 300; ++i) {
    const Ellipsoid e1 = randomEllipsoid(rng, 0.2, 2, 1);
    const Ellipsoid e2 = movedTo(randomEllipsoid(rng, 0.2, 2, 1), Vec3(6, 0, 0) + randomUnit(rng));
    const DistanceResult ref = dual->distance(e1, e2, tight);
    ASSERT_EQ(ref.status, DistanceStatus::converged);
    for (int k = 0; k < 20; ++k) {
      EXPECT_LE(separatingPlaneBound(e1, e2, randomUnit(rng)), ref.upper);
    }
  }
}

TEST(CertifiedBracket, FromPointsContainsTheDistanceEvenForPoorPoints) {
  std::mt19937_64 rng(22);
  const auto dual = makeDistanceMethod("dual");
  DistanceOptions tight;
  tight.epsD = 1e-12;
  for (int i = 0; i < 300; ++i) {
    const Ellipsoid e1 = randomEllipsoid(rng, 0.2, 2, 1);
    const Ellipsoid e2 = movedTo(randomEllipsoid(rng, 0.2, 2, 1), Vec3(0, 8, 0) + randomUnit(rng));
    const DistanceResult ref = dual->distance(e1, e2, tight);
    ASSERT_EQ(ref.status, DistanceStatus::converged);
    // arbitrary points, even off the surface: the bracket still holds
    DistanceResult r;
    r.status = DistanceStatus::converged;
    r.point1 = e1.support(randomUnit(rng)) * 1.01;
    r.point2 = e2.support(randomUnit(rng));
    certifyFromPoints(e1, e2, r);
    EXPECT_LE(r.lower, ref.upper);
    EXPECT_GE(r.upper, ref.lower);
    // the exact points give a tight bracket
    r.point1 = ref.point1;
    r.point2 = ref.point2;
    certifyFromPoints(e1, e2, r);
    EXPECT_LT(r.bracketWidth(), 1e-10);
  }
}
