// Ellipsoid: construction checks, quadratic form and support mapping against
// closed forms.
#include "ellipsoids/Ellipsoid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

using ellipsoids::Ellipsoid;
using ellipsoids::Quat;
using ellipsoids::Scalar;
using ellipsoids::Vec3;

namespace {

Quat randomRotation(std::mt19937_64& rng) {
  std::normal_distribution<Scalar> g;
  Quat q(g(rng), g(rng), g(rng), g(rng));
  q.normalize();
  return q;
}

}  // namespace

TEST(Ellipsoid, RejectsBadInput) {
  const Vec3 c = Vec3::Zero();
  EXPECT_THROW(Ellipsoid(Vec3(1, 0, 1), c, Quat::Identity()), std::invalid_argument);
  EXPECT_THROW(Ellipsoid(Vec3(1, -2, 1), c, Quat::Identity()), std::invalid_argument);
  EXPECT_THROW(Ellipsoid(Vec3(1, std::numeric_limits<Scalar>::quiet_NaN(), 1), c, Quat::Identity()),
               std::invalid_argument);
  EXPECT_THROW(Ellipsoid(Vec3(1, 1, 1), Vec3(0, std::numeric_limits<Scalar>::infinity(), 0),
                         Quat::Identity()),
               std::invalid_argument);
  EXPECT_THROW(Ellipsoid(Vec3(1, 1, 1), c, Quat(2, 0, 0, 0)), std::invalid_argument);
  EXPECT_THROW(Ellipsoid::sphere(1, c).support(Vec3::Zero()), std::invalid_argument);
}

TEST(Ellipsoid, QuaternionMatchesPaperRotation) {
  // Eq. A.6 written out for q = (q0, q1, q2, q3).
  std::mt19937_64 rng(1);
  const Quat q = randomRotation(rng);
  const Scalar q0 = q.w(), q1 = q.x(), q2 = q.y(), q3 = q.z();
  Eigen::Matrix3d U;
  U << 1 - 2 * (q2 * q2 + q3 * q3), 2 * (q1 * q2 - q0 * q3), 2 * (q0 * q2 + q1 * q3),
      2 * (q1 * q2 + q0 * q3), 1 - 2 * (q1 * q1 + q3 * q3), 2 * (q2 * q3 - q0 * q1),
      2 * (q1 * q3 - q0 * q2), 2 * (q0 * q1 + q2 * q3), 1 - 2 * (q1 * q1 + q2 * q2);
  const Ellipsoid e(Vec3(3, 2, 1), Vec3(1, 2, 3), q);
  EXPECT_LT((e.rotation() - U).norm(), 1e-14);
  EXPECT_LT((e.quadraticMatrix() * e.shapeMatrix() - Eigen::Matrix3d::Identity()).norm(), 1e-13);
}

TEST(Ellipsoid, SphereSupportIsCentrePlusRadiusTimesDirection) {
  const Vec3 c(0.5, -1.0, 2.0);
  const Ellipsoid s = Ellipsoid::sphere(0.25, c);
  std::mt19937_64 rng(2);
  std::normal_distribution<Scalar> g;
  for (int i = 0; i < 100; ++i) {
    const Vec3 n(g(rng), g(rng), g(rng));
    const Vec3 expected = c + 0.25 * n.normalized();
    EXPECT_LT((s.support(n) - expected).norm(), 1e-15);
    EXPECT_NEAR(s.supportValue(n.normalized()), n.normalized().dot(c) + 0.25, 1e-15);
  }
}

TEST(Ellipsoid, SupportPointIsOnSurfaceWithNormalAlongDirection) {
  std::mt19937_64 rng(3);
  std::normal_distribution<Scalar> g;
  for (int i = 0; i < 200; ++i) {
    const Ellipsoid e(Vec3(6, 1, 1), Vec3(g(rng), g(rng), g(rng)), randomRotation(rng));
    const Vec3 n = Vec3(g(rng), g(rng), g(rng)).normalized();
    const Vec3 x = e.support(n);
    EXPECT_NEAR(e.levelSet(x), 0, 1e-13);
    const Vec3 normal = (e.quadraticMatrix() * (x - e.centre())).normalized();
    EXPECT_LT((normal - n).norm(), 1e-12);
    EXPECT_NEAR(n.dot(x), e.supportValue(n), 1e-12);
  }
}

TEST(Ellipsoid, AxisAlignedSupportValuesAreSemiAxes) {
  const Ellipsoid e(Vec3(3, 2, 0.5), Vec3::Zero(), Quat::Identity());
  EXPECT_DOUBLE_EQ(e.supportValue(Vec3::UnitX()), 3);
  EXPECT_DOUBLE_EQ(e.supportValue(Vec3::UnitY()), 2);
  EXPECT_DOUBLE_EQ(e.supportValue(-Vec3::UnitZ()), 0.5);
}
