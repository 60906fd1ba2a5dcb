// The certified bracket: L(n) <= d* <= |x2 - x1| whatever n and the points.
#include "ellipsoids/CertifiedBracket.hpp"
#include "ellipsoids/DistanceMethod.hpp"
#include "LongDoubleReference.hpp"
#include "ReferencePairs.hpp"
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

TEST(CertifiedBracket, LowerBoundHoldsAtAndNearTheOptimumDirection) {
  // where L(n) is within rounding of d*: the optimum direction and directions a
  // small angle from it (L falls by about R angle^2); L(n) - roundingAllowance
  // must stay below the exact distance (long-double reference), and L must be
  // tight there (within a few allowances of it), elongated bodies included
  std::mt19937_64 rng(21);
  const LongDoubleReference reference;
  int tight = 0;
  for (int i = 0; i < 200; ++i) {
    const Scalar ar = std::pow(10.0, std::uniform_real_distribution<Scalar>(-2, 2)(rng));
    const BodyInput b1{Ellipsoid::spheroid(ar, 1, Vec3::Zero(), Quat::Identity()).semiAxes(),
                       Vec3(0.5, -0.25, 2), randomRotation(rng)};
    const Ellipsoid e1 = b1.body();
    const Vec3 axes2 = randomEllipsoid(rng, 0.2, 2, 0).semiAxes();
    const Quat q2 = randomRotation(rng);
    const Vec3 n = randomUnit(rng);
    const Scalar gap = std::pow(10.0, std::uniform_real_distribution<Scalar>(-9, 0)(rng));
    const BodyInput b2{axes2, e1.support(n) + Ellipsoid(axes2, Vec3::Zero(), q2).support(n) + gap * n, q2};
    const Ellipsoid e2 = b2.body();
    const Scalar allow = roundingAllowance(e1, e2);
    const ReferenceBracket ref = reference.distance(b1, b2, n, referenceTarget(e1, e2));
    ASSERT_TRUE(ref.tight) << i;
    const Vec3 best = ref.direction;
    for (Scalar angle : {0.0, 1e-9, 1e-7, 1e-5}) {
      const Vec3 m = (best + angle * randomUnit(rng)).normalized();
      const Scalar L = separatingPlaneBound(e1, e2, m);
      EXPECT_LE(L - allow, ref.upper) << "pair " << i << ", angle " << angle << ": L - allowance above d* by "
                                      << double(L - allow - ref.upper);
      if (angle == 0) tight += L >= ref.lower - 4 * allow;
    }
  }
  EXPECT_EQ(tight, 200);  // the test is where the bound is sharp
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
    r.distance = (r.point2 - r.point1).norm();
    certifyFromPoints(e1, e2, r);
    EXPECT_LE(r.lower, ref.upper);
    EXPECT_GE(r.upper, ref.lower);
    EXPECT_LE(r.lower, r.distance);
    EXPECT_GE(r.upper, r.distance);
    // the exact points give a tight bracket
    r.point1 = ref.point1;
    r.point2 = ref.point2;
    r.distance = (r.point2 - r.point1).norm();
    certifyFromPoints(e1, e2, r);
    EXPECT_LT(r.bracketWidth(), 1e-10);
  }
}

TEST(CertifiedBracket, BodyFrameEvaluationIsWellConditionedForNeedles) {
  // The certificate evaluates L(n) and the membership of points in the body
  // frame, to a few eps of the largest semi-axis whatever the elongation. On
  // oblique Ar 100 needles at the reference's optimum: L(n) and the upper bound
  // from the reference's own points within 64 eps (|dr| + sizes + |points|) of
  // d*, far inside the allowance. (Through the world-frame quadratic form A a
  // point on a needle is off the surface by up to eps a kappa^2, 2.4e-11 here.)
  std::mt19937_64 rng(23);
  const LongDoubleReference reference;
  for (int k = 0; k < 200; ++k) {
    const Scalar gap = std::pow(10.0, std::uniform_real_distribution<Scalar>(-12, -3)(rng));
    const InputPair p = obliqueNeedles(rng, k % 4 == 3 ? 0.01 : 100, gap, k % 2 == 1);
    const Ellipsoid e1 = p.b1.body(), e2 = p.b2.body();
    const ReferenceBracket ref = reference.distance(p.b1, p.b2, p.normal, referenceTarget(e1, e2));
    ASSERT_TRUE(ref.tight) << k;
    const long double exact = (ref.lower + ref.upper) / 2;
    const Scalar sizes = (e2.centre() - e1.centre()).norm() + e1.maxSemiAxis() + e2.maxSemiAxis();
    EXPECT_LE(std::abs(double(separatingPlaneBound(e1, e2, ref.direction) - exact)), 64 * kEps * sizes) << k;
    DistanceResult r;
    r.status = DistanceStatus::converged;
    r.point1 = ref.point1;
    r.point2 = ref.point2;
    r.distance = (r.point2 - r.point1).norm();
    certifyFromPoints(e1, e2, r);
    const Scalar coordinates = 4 * kEps * (r.point1.cwiseAbs().sum() + r.point2.cwiseAbs().sum());
    const Scalar rawUpper = r.upper - roundingAllowance(e1, e2) - coordinates;
    EXPECT_LE(std::abs(double(rawUpper - exact)), 64 * kEps * sizes + coordinates) << k;
  }
}
