// Properties every robust method must have (Moving Balls, GJK, dual, auto, paper),
// run for each of them: closed forms, invariances, agreement, extremes.
#include "ellipsoids/CertifiedBracket.hpp"
#include "ellipsoids/DistanceMethod.hpp"
#include "ellipsoids/OverlapTest.hpp"
#include "TestGeometry.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace ellipsoids;
using namespace testgeometry;

namespace {

class RobustMethod : public ::testing::TestWithParam<std::string> {
 protected:
  std::unique_ptr<DistanceMethod> method = makeDistanceMethod(GetParam());
  DistanceOptions options(Scalar eps) const {
    DistanceOptions o;
    o.epsD = eps;
    o.stopRule = StopRule::certified;
    return o;
  }
  /// The result is an honest answer: converged, bracket within eps and containing `exact`.
  void expectCertified(const DistanceResult& r, Scalar exact, Scalar eps, const std::string& what) {
    EXPECT_EQ(r.status, DistanceStatus::converged) << what;
    EXPECT_LE(r.bracketWidth(), eps) << what;
    EXPECT_LE(r.lower, exact) << what;
    EXPECT_GE(r.upper, exact) << what;
    EXPECT_LE(std::abs(r.distance - exact), eps) << what;
  }
};

std::string paramName(const ::testing::TestParamInfo<std::string>& info) { return info.param; }

}  // namespace

TEST_P(RobustMethod, SphereSphereSweepOverDistanceAndDirection) {
  std::mt19937_64 rng(31);
  for (Scalar gap : {10.0, 1.0, 1e-2, 1e-4, 1e-6}) {
    for (int k = 0; k < 20; ++k) {
      const Vec3 n = randomUnit(rng);
      const Ellipsoid s1 = Ellipsoid::sphere(0.7, Vec3(1, 2, 3));
      const Ellipsoid s2 = Ellipsoid::sphere(0.3, s1.centre() + (1.0 + gap) * n);
      for (Scalar eps : {1e-4, 1e-8}) {
        const DistanceResult r = method->distance(s1, s2, options(eps));
        expectCertified(r, gap, eps, "gap " + std::to_string(gap));
        EXPECT_LT((r.point1 - (s1.centre() + 0.7 * n)).norm(), 1e-3 * std::sqrt(eps));
        EXPECT_LT((r.point2 - (s2.centre() - 0.3 * n)).norm(), 1e-3 * std::sqrt(eps));
      }
    }
  }
}

TEST_P(RobustMethod, MirrorCaseMeetsTheTolerance) {
  for (Scalar ar : {1.0 / 6, 1.0 / 3, 2.0 / 3, 1.5, 3.0, 6.0}) {
    for (Scalar d : {1.0, 1e-3, 1e-6}) {
      const MirrorCase m = mirrorCase(ar, d, 1);
      for (Scalar eps : {1e-4, 1e-6, 1e-8}) {
        expectCertified(method->distance(m.e1, m.e2, options(eps)), m.exactDistance, eps,
                        "Ar " + std::to_string(ar) + " d " + std::to_string(d));
      }
    }
  }
}

TEST_P(RobustMethod, TangentPairsAtSmallGapsAndExtremeAspectRatios) {
  // Ar 1/10 to 10, any orientation, gaps 1e-6 .. 1e-1 of D_eq: the exact distance is the gap
  std::mt19937_64 rng(32);
  for (Scalar ar : {0.1, 1.0 / 6, 0.5, 2.0, 6.0, 10.0}) {
    for (int k = 0; k < 25; ++k) {
      const Ellipsoid e1 = Ellipsoid::spheroid(ar, 1, Vec3(0.1, -0.2, 0.3), randomRotation(rng));
      const Ellipsoid shape2 = Ellipsoid::spheroid(1 / ar, 1, Vec3::Zero(), randomRotation(rng));
      const Vec3 n = randomUnit(rng);
      for (Scalar gap : {1e-1, 1e-3, 1e-6}) {
        const Ellipsoid e2 = tangentPartner(e1, shape2.semiAxes(), shape2.orientation(), n, gap);
        const Scalar eps = 1e-5 * std::min(e1.minGaussianRadius(), e2.minGaussianRadius());
        expectCertified(method->distance(e1, e2, options(eps)), gap, eps,
                        "Ar " + std::to_string(ar) + " gap " + std::to_string(gap));
      }
    }
  }
}

TEST_P(RobustMethod, InvariantUnderSwapRigidMotionAndScaling) {
  std::mt19937_64 rng(33);
  for (int k = 0; k < 100; ++k) {
    const Ellipsoid e1 = randomEllipsoid(rng, 0.2, 2, 0.5);
    const Ellipsoid e2 = movedTo(randomEllipsoid(rng, 0.2, 2, 0.5), Vec3(5, 1, 0) + randomUnit(rng));
    const Scalar eps = 1e-8;
    const DistanceResult r = method->distance(e1, e2, options(eps));
    ASSERT_EQ(r.status, DistanceStatus::converged);
    const DistanceResult swapped = method->distance(e2, e1, options(eps));
    EXPECT_NEAR(swapped.distance, r.distance, 2 * eps);
    EXPECT_LT((swapped.point1 - r.point2).norm(), 1e-3);
    const Quat R = randomRotation(rng);
    for (Scalar s : {1e-6, 1.0, 1e6}) {
      const Vec3 t = s * Vec3(-3, 7, 2);
      const DistanceResult m = method->distance(transformed(e1, s, R, t), transformed(e2, s, R, t),
                                                options(s * eps));
      EXPECT_EQ(m.status, DistanceStatus::converged) << "scale " << s;
      EXPECT_NEAR(m.distance / s, r.distance, 2 * eps) << "scale " << s;
      EXPECT_LT((m.point1 - (s * (R * r.point1) + t)).norm() / s, 1e-3) << "scale " << s;
    }
  }
}

TEST_P(RobustMethod, AgreesWithTheOtherMethodsOnRandomPairs) {
  std::mt19937_64 rng(34);
  const auto gjk = makeDistanceMethod("gjk");
  const auto dual = makeDistanceMethod("dual");
  const JiaOverlapTest jia;
  int separated = 0;
  for (int k = 0; k < 2000; ++k) {
    const Ellipsoid e1 = randomEllipsoid(rng, 0.1, 2, 1);
    const Ellipsoid e2 = randomEllipsoid(rng, 0.1, 2, 2);
    const Scalar eps = 1e-7;
    const DistanceResult r = method->distance(e1, e2, options(eps));
    const OverlapStatus overlap = jia.test(e1, e2);
    if (overlap == OverlapStatus::overlapping) {
      EXPECT_EQ(r.status, DistanceStatus::overlapping) << "pair " << k;
      continue;
    }
    ASSERT_EQ(overlap, OverlapStatus::separated);
    ++separated;
    ASSERT_EQ(r.status, DistanceStatus::converged) << "pair " << k;
    // independent references: GJK and the dual method at a much tighter tolerance
    const DistanceResult a = gjk->distance(e1, e2, options(1e-12));
    const DistanceResult b = dual->distance(e1, e2, options(1e-12));
    EXPECT_LE(r.lower, std::min(a.upper, b.upper)) << "pair " << k;
    EXPECT_GE(r.upper, std::max(a.lower, b.lower)) << "pair " << k;
    EXPECT_NEAR(r.distance, b.distance, eps) << "pair " << k;
    // a unit direction: a drifting |n| once made the dual's lower bound exceed the distance
    EXPECT_NEAR(r.direction.norm(), 1, 1e-14) << "pair " << k;
  }
  EXPECT_GT(separated, 500);
}

TEST_P(RobustMethod, OverlappingPairsAreReportedAsSuch) {
  std::mt19937_64 rng(35);
  for (int k = 0; k < 200; ++k) {
    const Ellipsoid e1 = randomEllipsoid(rng, 0.5, 2, 0.1);
    const Ellipsoid e2 = movedTo(randomEllipsoid(rng, 0.5, 2, 0.1), e1.centre() + 0.3 * randomUnit(rng));
    const DistanceResult r = method->distance(e1, e2, options(1e-6));
    EXPECT_EQ(r.status, DistanceStatus::overlapping);
    EXPECT_LE(r.lower, 0);
    EXPECT_LE(r.upper, 1e-12);
    EXPECT_TRUE(std::isfinite(r.distance) && r.point1.allFinite() && r.point2.allFinite());
  }
}

TEST_P(RobustMethod, AxisAlignedDegenerateDirections) {
  // identical axis-aligned bodies stacked exactly along each axis, and the
  // support direction along a coordinate axis
  for (int axis = 0; axis < 3; ++axis) {
    for (Scalar ar : {0.1, 10.0}) {
      const Ellipsoid e1 = Ellipsoid::spheroid(ar, 1, Vec3::Zero(), Quat::Identity());
      Vec3 offset = Vec3::Zero();
      offset[axis] = 2 * e1.semiAxes()[axis] + 1e-4;
      const Ellipsoid e2 = Ellipsoid::spheroid(ar, 1, offset, Quat::Identity());
      expectCertified(method->distance(e1, e2, options(1e-9)), 1e-4, 1e-9,
                      "axis " + std::to_string(axis));
    }
  }
}

TEST_P(RobustMethod, ParallelNeedlesSideBySide) {
  // long prolate bodies side by side, shifted along their axis: the centre line
  // is a poor first direction
  for (Scalar shift : {0.0, 0.5, 1.0, 1.5}) {
    const Ellipsoid e1 = Ellipsoid::spheroid(10, 1, Vec3::Zero(), Quat::Identity());
    const Scalar b = e1.semiAxes().y();
    const Ellipsoid e2 = Ellipsoid::spheroid(10, 1, Vec3(shift, 2 * b + 1e-3, 0), Quat::Identity());
    const DistanceResult r = method->distance(e1, e2, options(1e-9));
    EXPECT_EQ(r.status, DistanceStatus::converged) << "shift " << shift;
    EXPECT_LE(r.bracketWidth(), 1e-9);
    // the gap at zero shift is the y offset; a shift only widens it
    EXPECT_GE(r.distance, 1e-3 - 1e-9);
    if (shift == 0) {
      EXPECT_NEAR(r.distance, 1e-3, 1e-9);
    }
    // two other methods, tight
    for (const char* other : {"gjk", "dual"}) {
      const DistanceResult ref = makeDistanceMethod(other)->distance(e1, e2, options(1e-13));
      EXPECT_NEAR(r.distance, ref.distance, 1e-9) << other << " shift " << shift;
    }
  }
}

TEST_P(RobustMethod, IterationLimitIsReportedNotHidden) {
  const MirrorCase m = mirrorCase(6, 1e-3, 1);
  DistanceOptions o = options(1e-12);
  o.maxIterations = 1;
  o.useInitialDirection = true;
  o.initialDirection = Vec3(0.3, 1, 1).normalized();  // a poor start
  const DistanceResult r = method->distance(m.e1, m.e2, o);
  if (r.status == DistanceStatus::converged) {
    EXPECT_LE(r.bracketWidth(), 1e-12);  // converged only if it really did
  } else {
    EXPECT_TRUE(r.status == DistanceStatus::maxIterations || r.status == DistanceStatus::failed);
  }
  EXPECT_LE(r.lower, m.exactDistance);
  EXPECT_GE(r.upper, m.exactDistance);
}

INSTANTIATE_TEST_SUITE_P(Methods, RobustMethod,
                         ::testing::Values("movingBalls", "gjk", "dual", "auto", "paper"), paramName);

TEST(DistanceMethods, FactoryListsAndRejectsNames) {
  for (const auto& name : distanceMethodNames()) {
    EXPECT_EQ(makeDistanceMethod(name)->name(), name);
  }
  try {
    makeDistanceMethod("gkj");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("gkj"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("movingBalls"), std::string::npos);
  }
}

TEST(DistanceMethods, OptionsAreValidated) {
  const auto dual = makeDistanceMethod("dual");
  const Ellipsoid s1 = Ellipsoid::sphere(1, Vec3::Zero()), s2 = Ellipsoid::sphere(1, Vec3(3, 0, 0));
  DistanceOptions o;
  o.epsD = 0;
  EXPECT_THROW(dual->distance(s1, s2, o), std::invalid_argument);
  o.epsD = std::numeric_limits<Scalar>::quiet_NaN();
  EXPECT_THROW(dual->distance(s1, s2, o), std::invalid_argument);
  o.epsD = 1e-6;
  o.maxIterations = -1;
  EXPECT_THROW(dual->distance(s1, s2, o), std::invalid_argument);
}
