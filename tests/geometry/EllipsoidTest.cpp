// Ellipsoid: construction checks, quadratic form and support mapping against
// closed forms.
#include "ellipsoids/Ellipsoid.hpp"
#include "TestGeometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

using ellipsoids::Ellipsoid;
using ellipsoids::Quat;
using ellipsoids::Scalar;
using ellipsoids::Vec3;
using testgeometry::randomRotation;
using testgeometry::randomUnit;


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

TEST(Ellipsoid, HomogeneousFormIsTwiceTheLevelSet) {
  std::mt19937_64 rng(4);
  std::normal_distribution<Scalar> g;
  const Ellipsoid e(Vec3(2, 0.5, 1), Vec3(1, -2, 3), randomRotation(rng));
  const auto H = e.homogeneousMatrix();
  EXPECT_LT((H - H.transpose()).norm(), 1e-14);
  for (int i = 0; i < 50; ++i) {
    const Vec3 x(g(rng), g(rng), g(rng));
    const ellipsoids::Vec4 X(x.x(), x.y(), x.z(), 1);
    EXPECT_NEAR(X.dot(H * X), 2 * e.levelSet(x), 1e-12 * (1 + std::abs(e.levelSet(x))));
    // the paper's (A, b, alpha): f = 1/2 x^T A x + b^T x + alpha
    const Scalar f = 0.5 * x.dot(e.quadraticMatrix() * x) + e.linearTerm().dot(x) + e.constantTerm();
    EXPECT_NEAR(f, e.levelSet(x), 1e-12 * (1 + std::abs(f)));
  }
}

TEST(Ellipsoid, SpheroidFactoryKeepsVolumeAndAspectRatio) {
  for (Scalar ar : {1.0 / 6, 1.0 / 3, 2.0 / 3, 1.5, 3.0, 6.0}) {
    const Ellipsoid e = Ellipsoid::spheroid(ar, 2.0, Vec3::Zero(), Quat::Identity());
    EXPECT_NEAR(e.equivalentRadius(), 1.0, 1e-14);
    EXPECT_NEAR(e.aspectRatio(), ar, 1e-13);
    EXPECT_NEAR(e.elongation(), std::max(ar, 1 / ar), 1e-13);
  }
  EXPECT_THROW(Ellipsoid::spheroid(0, 1, Vec3::Zero(), Quat::Identity()), std::invalid_argument);
  EXPECT_THROW(Ellipsoid::spheroid(2, -1, Vec3::Zero(), Quat::Identity()), std::invalid_argument);
}

TEST(Ellipsoid, CurvatureRadiiOfASphereAreItsRadius) {
  const Ellipsoid s = Ellipsoid::sphere(2.5, Vec3(1, 1, 1));
  std::mt19937_64 rng(5);
  for (int i = 0; i < 20; ++i) {
    const auto r = s.curvatureRadii(s.support(randomUnit(rng)));
    EXPECT_NEAR(r.rMin, 2.5, 1e-13);
    EXPECT_NEAR(r.rMax, 2.5, 1e-13);
    EXPECT_NEAR(r.gaussian, 2.5, 1e-13);
  }
}

TEST(Ellipsoid, CurvatureRadiiAtTheVerticesMatchClosedForms) {
  // At (a,0,0) the principal radii are b^2/a and c^2/a, and so on.
  std::mt19937_64 rng(6);
  const Quat q = randomRotation(rng);
  const Scalar a = 3, b = 2, c = 0.5;
  const Ellipsoid e(Vec3(a, b, c), Vec3(-1, 0.5, 2), q);
  const Vec3 axes[3] = {e.rotation().col(0), e.rotation().col(1), e.rotation().col(2)};
  const Scalar len[3] = {a, b, c};
  for (int i = 0; i < 3; ++i) {
    const Scalar r1 = len[(i + 1) % 3] * len[(i + 1) % 3] / len[i];
    const Scalar r2 = len[(i + 2) % 3] * len[(i + 2) % 3] / len[i];
    for (Scalar sign : {1.0, -1.0}) {
      const auto r = e.curvatureRadii(e.centre() + sign * len[i] * axes[i]);
      EXPECT_NEAR(r.rMin, std::min(r1, r2), 1e-12);
      EXPECT_NEAR(r.rMax, std::max(r1, r2), 1e-12);
      EXPECT_NEAR(r.gaussian, std::sqrt(r1 * r2), 1e-12);
    }
  }
}

TEST(Ellipsoid, ProlateSpheroidEquatorAndPole) {
  // prolate a > b = c: at the pole both radii are b^2/a; on the equator b and a^2/b
  const Scalar a = 3, b = 1;
  const Ellipsoid e(Vec3(a, b, b), Vec3::Zero(), Quat::Identity());
  const auto pole = e.curvatureRadii(Vec3(a, 0, 0));
  EXPECT_NEAR(pole.rMin, b * b / a, 1e-13);
  EXPECT_NEAR(pole.rMax, b * b / a, 1e-13);
  const auto equator = e.curvatureRadii(Vec3(0, b, 0));
  EXPECT_NEAR(equator.rMin, b, 1e-13);
  EXPECT_NEAR(equator.rMax, a * a / b, 1e-13);
  EXPECT_NEAR(e.maxOfMaxCurvatureRadius(), a * a / b, 1e-13);
  EXPECT_NEAR(e.minOfMinCurvatureRadius(), b * b / a, 1e-13);
  EXPECT_NEAR(e.minGaussianRadius(), b * b / a, 1e-13);
}

TEST(Ellipsoid, CurvatureTensorHasThePrincipalCurvaturesOnTheTangentPlane) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<Scalar> u(0.2, 3);
  for (int k = 0; k < 20; ++k) {
    const Ellipsoid e(Vec3(u(rng), u(rng), u(rng)), Vec3(u(rng), -u(rng), 0.5), randomRotation(rng));
    for (int i = 0; i < 50; ++i) {
      const Vec3 m = randomUnit(rng);
      const Vec3 x = e.support(m);
      const ellipsoids::Mat3 S = e.curvatureTensor(x);
      const auto r = e.curvatureRadii(x);
      const Scalar scale = 1 / r.rMin;
      EXPECT_LT((S - S.transpose()).norm(), 1e-14 * scale);
      EXPECT_LT((S * m).norm(), 1e-12 * scale);
      // trace and tangent determinant: k1 + k2 and k1 k2
      const Scalar trace = S.trace();
      const Scalar det2 = (trace * trace - (S * S).trace()) / 2;
      EXPECT_NEAR(trace, 1 / r.rMin + 1 / r.rMax, 1e-11 * scale);
      EXPECT_NEAR(det2, 1 / (r.rMin * r.rMax), 1e-10 * scale * scale);
    }
  }
}

TEST(Ellipsoid, CurvatureTensorGivesTheSurfaceToSecondOrder) {
  // the surface along -m at a tangent offset t lies at depth t^T S t/2 + O(|t|^3)
  std::mt19937_64 rng(18);
  const Ellipsoid e(Vec3(2, 1, 0.7), Vec3(0.3, -0.2, 1), randomRotation(rng));
  for (int i = 0; i < 20; ++i) {
    const Vec3 m = randomUnit(rng);
    const Vec3 x = e.support(m);
    const ellipsoids::Mat3 S = e.curvatureTensor(x);
    Vec3 t = randomUnit(rng);
    t = (t - t.dot(m) * m).normalized();
    Scalar previous = 0;
    for (Scalar len : {1e-2, 5e-3}) {
      const auto hit = e.intersectLine(x + len * t, -m);
      ASSERT_EQ(hit.count, 2);
      const Scalar error = std::abs(hit.tEnter - len * len * t.dot(S * t) / 2);
      EXPECT_LT(error, 2 * len * len * len);
      if (previous > 0) EXPECT_LT(error, previous / 6);  // third order: 8 x smaller
      previous = error;
    }
  }
}

TEST(Ellipsoid, SurfaceThirdDerivativeGivesTheSurfaceToThirdOrder) {
  // the depth along -m at a tangent offset t is t^T S t/2 + C(t, t, t)/6 + O(|t|^4): the
  // residual falls 16 x when t halves; C is symmetric in its three indices and zero on
  // tangents at a vertex
  std::mt19937_64 rng(19);
  const Ellipsoid e(Vec3(2, 1, 0.7), Vec3(0.3, -0.2, 1), randomRotation(rng));
  auto cubic = [](const ellipsoids::Tensor3& C, const Vec3& t) {
    Scalar sum = 0;
    for (int k = 0; k < 3; ++k) sum += t.dot(C[k] * t) * t(k);
    return sum;
  };
  for (int i = 0; i < 20; ++i) {
    const Vec3 m = randomUnit(rng);
    const Vec3 x = e.support(m);
    const ellipsoids::Mat3 S = e.curvatureTensor(x);
    const ellipsoids::Tensor3 C = e.surfaceThirdDerivative(x);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(C[c](a, b), C[a](b, c), 1e-12);
          EXPECT_NEAR(C[c](a, b), C[b](c, a), 1e-12);
        }
    Vec3 t = randomUnit(rng);
    t = (t - t.dot(m) * m).normalized();
    Scalar previous = 0;
    for (Scalar len : {1e-2, 5e-3}) {
      const auto hit = e.intersectLine(x + len * t, -m);
      ASSERT_EQ(hit.count, 2);
      const Scalar error =
          std::abs(hit.tEnter - len * len * t.dot(S * t) / 2 - len * len * len * cubic(C, t) / 6);
      EXPECT_LT(error, 10 * len * len * len * len);
      if (previous > 0) {
        EXPECT_LT(error, previous / 12);  // fourth order: 16 x smaller
      }
      previous = error;
    }
  }
  // at a vertex and on a sphere: no cubic term
  const Ellipsoid vertexBody(Vec3(2, 1, 0.7), Vec3::Zero(), Quat::Identity());
  const Ellipsoid sphere(Vec3(1.5, 1.5, 1.5), Vec3(1, 2, 3), randomRotation(rng));
  for (int k = 0; k < 3; ++k) {
    EXPECT_LT(vertexBody.surfaceThirdDerivative(Vec3(0, 1, 0))[k].norm(), 1e-15);
    EXPECT_LT(sphere.surfaceThirdDerivative(sphere.support(randomUnit(rng)))[k].norm(), 1e-14);
  }
}

TEST(Ellipsoid, ProlateCurvatureTensorOnTheEquator) {
  // prolate (a, b, b) at (0, b, 0): curvature 1/b around the axis, b/a^2 along it
  const Scalar a = 3, b = 1;
  const Ellipsoid e(Vec3(a, b, b), Vec3::Zero(), Quat::Identity());
  const ellipsoids::Mat3 S = e.curvatureTensor(Vec3(0, b, 0));
  EXPECT_NEAR(S(0, 0), b / (a * a), 1e-14);
  EXPECT_NEAR(S(2, 2), 1 / b, 1e-14);
  EXPECT_NEAR(S(1, 1), 0, 1e-14);
  EXPECT_NEAR(S(0, 2), 0, 1e-14);
}

TEST(Ellipsoid, SurfaceExtremaOfCurvatureBoundEverySurfacePoint) {
  std::mt19937_64 rng(7);
  for (int k = 0; k < 20; ++k) {
    std::uniform_real_distribution<Scalar> u(0.1, 3);
    const Ellipsoid e(Vec3(u(rng), u(rng), u(rng)), Vec3::Zero(), randomRotation(rng));
    for (int i = 0; i < 500; ++i) {
      const auto r = e.curvatureRadii(e.support(randomUnit(rng)));
      EXPECT_LE(r.rMin, r.rMax * (1 + 1e-12));
      EXPECT_LE(r.rMax, e.maxOfMaxCurvatureRadius() * (1 + 1e-12));
      EXPECT_GE(r.rMin, e.minOfMinCurvatureRadius() * (1 - 1e-12));
      EXPECT_GE(r.gaussian, e.minGaussianRadius() * (1 - 1e-12));
      EXPECT_NEAR(r.gaussian * r.gaussian, r.rMin * r.rMax, 1e-10 * r.rMin * r.rMax);
    }
  }
}

TEST(Ellipsoid, LineIntersectionOfASphereAndTangentAndMiss) {
  const Ellipsoid s = Ellipsoid::sphere(1, Vec3(0, 0, 0));
  const auto through = s.intersectLine(Vec3(-3, 0, 0), Vec3(1, 0, 0));
  ASSERT_EQ(through.count, 2);
  EXPECT_NEAR(through.tEnter, 2, 1e-15);
  EXPECT_NEAR(through.tExit, 4, 1e-15);
  const auto miss = s.intersectLine(Vec3(-3, 1.5, 0), Vec3(1, 0, 0));
  EXPECT_EQ(miss.count, 0);
  const auto fromInside = s.intersectLine(Vec3(0.2, 0, 0), Vec3(0, 2, 0));
  ASSERT_EQ(fromInside.count, 2);
  EXPECT_LT(fromInside.tEnter, 0);
  EXPECT_NEAR(fromInside.tExit, std::sqrt(1 - 0.04) / 2, 1e-15);
  // no cancellation for a tiny sphere far away
  const Ellipsoid tiny = Ellipsoid::sphere(1e-6, Vec3(1e3, 0, 0));
  const auto far = tiny.intersectLine(Vec3::Zero(), Vec3(1, 0, 0));
  ASSERT_EQ(far.count, 2);
  EXPECT_NEAR(far.tEnter, 1e3 - 1e-6, 1e-15 * 1e3);
  EXPECT_NEAR(far.tExit, 1e3 + 1e-6, 1e-15 * 1e3);
}

TEST(Ellipsoid, LineIntersectionPointsAreOnTheSurface) {
  std::mt19937_64 rng(8);
  std::normal_distribution<Scalar> g;
  for (int i = 0; i < 200; ++i) {
    const Ellipsoid e(Vec3(2, 1, 0.3), Vec3(g(rng), g(rng), g(rng)), randomRotation(rng));
    const Vec3 o = e.centre() + 0.2 * Vec3(g(rng), g(rng), g(rng));
    const Vec3 d(g(rng), g(rng), g(rng));
    const auto li = e.intersectLine(o, d);
    if (li.count < 2) continue;
    EXPECT_NEAR(e.levelSet(o + li.tEnter * d), 0, 1e-12);
    EXPECT_NEAR(e.levelSet(o + li.tExit * d), 0, 1e-12);
  }
}

TEST(Ellipsoid, ProjectRadiallyLandsOnTheSurface) {
  const Ellipsoid e(Vec3(2, 1, 0.5), Vec3(1, 2, 3), Quat::Identity());
  EXPECT_NEAR(e.levelSet(e.projectRadially(Vec3(5, 5, 5))), 0, 1e-14);
  EXPECT_THROW(e.projectRadially(e.centre()), std::invalid_argument);
}

TEST(Ellipsoid, CurvatureRadiiAgreeWithAppendixBFormulas) {
  // K and H of eq. B.1, radii of eq. B.3, away from umbilic points
  std::mt19937_64 rng(9);
  const Scalar a = 2.5, b = 1.2, c = 0.4;
  const Ellipsoid e(Vec3(a, b, c), Vec3(0.3, 0.2, 0.1), randomRotation(rng));
  for (int i = 0; i < 200; ++i) {
    const Vec3 x = e.support(randomUnit(rng));
    const Vec3 xb = e.rotation().transpose() * (x - e.centre());
    const Scalar s = xb.x() * xb.x() / std::pow(a, 4) + xb.y() * xb.y() / std::pow(b, 4) +
                     xb.z() * xb.z() / std::pow(c, 4);
    const Scalar K = std::pow(1 / (a * b * c * s), 2);
    const Scalar H = (a * a + b * b + c * c - xb.squaredNorm()) /
                     (2 * std::pow(a * b * c, 2) * std::pow(s, 1.5));
    const Scalar rMin = (H - std::sqrt(H * H - K)) / K;
    const Scalar rMax = (H + std::sqrt(H * H - K)) / K;
    const auto r = e.curvatureRadii(x);
    EXPECT_NEAR(r.rMin, rMin, 1e-9 * rMax);
    EXPECT_NEAR(r.rMax, rMax, 1e-9 * rMax);
    EXPECT_NEAR(r.gaussian, 1 / std::sqrt(K), 1e-12 * rMax);
  }
}
