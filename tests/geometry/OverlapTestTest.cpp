// Jia et al.'s overlap test: closed forms (spheres), Wang's root criterion,
// the touching band in floating point, scale/rigid-motion invariance.
#include "ellipsoids/OverlapTest.hpp"
#include "TestGeometry.hpp"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <random>

using namespace ellipsoids;
using namespace testgeometry;

TEST(JiaOverlap, SpheresClosedForm) {
  const JiaOverlapTest jia;
  const Ellipsoid s1 = Ellipsoid::sphere(1, Vec3::Zero());
  std::mt19937_64 rng(11);
  for (int i = 0; i < 100; ++i) {
    const Vec3 n = randomUnit(rng);
    EXPECT_EQ(jia.test(s1, Ellipsoid::sphere(0.5, 1.6 * n)), OverlapStatus::separated);
    EXPECT_EQ(jia.test(s1, Ellipsoid::sphere(0.5, 1.4 * n)), OverlapStatus::overlapping);
    EXPECT_EQ(jia.test(s1, Ellipsoid::sphere(0.5, 0.1 * n)), OverlapStatus::overlapping);  // inside
  }
  // exactly representable tangency: touching
  EXPECT_EQ(jia.test(s1, Ellipsoid::sphere(1, Vec3(2, 0, 0))), OverlapStatus::touching);
  EXPECT_EQ(jia.test(s1, Ellipsoid::sphere(0.5, Vec3(0, 0, -1.5))), OverlapStatus::touching);
  // concentric
  EXPECT_EQ(jia.test(s1, Ellipsoid::sphere(1, Vec3::Zero())), OverlapStatus::overlapping);
}

TEST(JiaOverlap, AgreesWithWangRootCriterion) {
  // Wang et al.: separated iff det(l I + A1^-1 A2) has two distinct positive roots.
  const JiaOverlapTest jia;
  std::mt19937_64 rng(12);
  int separated = 0, overlapping = 0;
  for (int i = 0; i < 5000; ++i) {
    const Ellipsoid e1 = randomEllipsoid(rng, 0.2, 3, 1);
    const Ellipsoid e2 = randomEllipsoid(rng, 0.2, 3, 3);
    const Mat4 M = e1.homogeneousMatrix().inverse() * e2.homogeneousMatrix();
    const auto ev = Eigen::EigenSolver<Mat4>(M).eigenvalues();
    int positive = 0;
    for (int k = 0; k < 4; ++k) {
      const Scalar re = -ev[k].real(), im = ev[k].imag();
      if (re > 0 && std::abs(im) <= 1e-9 * std::abs(re)) ++positive;
    }
    const OverlapDetails d = jia.details(e1, e2);
    // the coefficients are those of prod (l + eig)
    const std::complex<Scalar> l(0.3, 0.7);
    std::complex<Scalar> byRoots = 1;
    for (int k = 0; k < 4; ++k) byRoots *= (l + ev[k]);
    const std::complex<Scalar> byCoefficients = l * l * l * l + d.coefficients[0] * l * l * l +
                                                d.coefficients[1] * l * l +
                                                d.coefficients[2] * l + d.coefficients[3];
    EXPECT_LT(std::abs(byRoots - byCoefficients), 1e-9 * (1 + std::abs(byRoots)));
    EXPECT_EQ(d.status == OverlapStatus::separated, positive >= 2) << "pair " << i;
    (d.status == OverlapStatus::separated ? separated : overlapping)++;
  }
  EXPECT_GT(separated, 500);   // both outcomes are exercised
  EXPECT_GT(overlapping, 500);
}

TEST(JiaOverlap, TouchingBandNeverConfusesSeparatedAndOverlapping) {
  // Pairs made tangent, then moved apart/together by gap x size along the
  // common normal; any scale 1e-6..1e6. The numbers quoted in OverlapTest.hpp.
  const JiaOverlapTest jia;
  std::mt19937_64 rng(13);
  const Scalar gaps[] = {-1e-6, -1e-9, -1e-10, -1e-12, 0, 1e-12, 1e-10, 1e-9, 1e-6};
  std::map<Scalar, std::array<int, 3>> counts;
  const int n = 2000;
  for (int i = 0; i < n; ++i) {
    const Scalar scale = std::pow(10.0, std::uniform_real_distribution<Scalar>(-6, 6)(rng));
    std::uniform_real_distribution<Scalar> u(0.1, 2);
    const Ellipsoid e1(scale * Vec3(u(rng), u(rng), u(rng)), scale * Vec3(1, -2, 0.5),
                       randomRotation(rng));
    const Vec3 ax2 = scale * Vec3(u(rng), u(rng), u(rng));
    const Quat q2 = randomRotation(rng);
    const Vec3 nrm = randomUnit(rng);
    const Scalar size = std::max(e1.maxSemiAxis(), ax2.maxCoeff());
    for (Scalar gap : gaps) {
      const Ellipsoid e2 = tangentPartner(e1, ax2, q2, nrm, gap * size);
      counts[gap][static_cast<int>(jia.test(e1, e2))]++;
    }
  }
  const int sep = static_cast<int>(OverlapStatus::separated);
  const int touch = static_cast<int>(OverlapStatus::touching);
  const int over = static_cast<int>(OverlapStatus::overlapping);
  for (Scalar gap : gaps) {
    if (gap > 0) {
      EXPECT_EQ(counts[gap][over], 0) << "gap " << gap;  // never the wrong side
    } else if (gap < 0) {
      EXPECT_EQ(counts[gap][sep], 0) << "gap " << gap;
    }
  }
  EXPECT_EQ(counts[1e-9][sep], n);
  EXPECT_EQ(counts[-1e-9][over], n);
  EXPECT_EQ(counts[1e-6][sep], n);
  EXPECT_EQ(counts[-1e-6][over], n);
  EXPECT_GE(counts[1e-10][sep], n * 995 / 1000);
  EXPECT_GE(counts[-1e-10][over], n * 995 / 1000);
  EXPECT_GE(counts[0][touch], n * 98 / 100);
}

TEST(JiaOverlap, InvariantUnderScalingAndRigidMotion) {
  const JiaOverlapTest jia;
  std::mt19937_64 rng(14);
  for (int i = 0; i < 500; ++i) {
    const Ellipsoid e1 = randomEllipsoid(rng, 0.2, 2, 1);
    const Ellipsoid e2 = randomEllipsoid(rng, 0.2, 2, 2);
    const OverlapStatus reference = jia.test(e1, e2);
    const Quat R = randomRotation(rng);
    for (Scalar s : {1e-6, 1e-3, 1e3, 1e6}) {
      const Vec3 t = s * Vec3(3, -1, 2);
      EXPECT_EQ(jia.test(transformed(e1, s, R, t), transformed(e2, s, R, t)), reference);
    }
    EXPECT_EQ(jia.test(e2, e1), reference);  // symmetric
  }
}

TEST(JiaOverlap, BodiesOfDifferentSizes) {
  // a small body +-1e-3 of the larger body's size from its surface, inside its
  // bounding sphere (the polynomial decides): right up to a size ratio of 1e6
  // (measured: a quarter wrong at 1e8, OverlapTest.hpp)
  const JiaOverlapTest jia;
  std::mt19937_64 rng(15);
  for (Scalar ratio : {1e2, 1e4, 1e6}) {
    for (int i = 0; i < 200; ++i) {
      const Ellipsoid large(Vec3(1, 3, 2), Vec3::Zero(), randomRotation(rng));
      const Vec3 smallAxes = Vec3(1, 2, 3) / ratio;
      const Quat q = randomRotation(rng);
      const Vec3 n = randomUnit(rng);
      for (Scalar gap : {3e-3, -3e-3}) {
        const Ellipsoid small = tangentPartner(large, smallAxes, q, n, gap);
        const OverlapStatus expected = gap > 0 ? OverlapStatus::separated : OverlapStatus::overlapping;
        EXPECT_EQ(jia.test(large, small), expected) << "ratio " << ratio << ", " << i << ", gap " << gap;
        EXPECT_EQ(jia.test(small, large), expected) << "ratio " << ratio << ", " << i << ", gap " << gap;
      }
    }
  }
}

TEST(JiaOverlap, RejectsBadTolerance) {
  EXPECT_THROW(JiaOverlapTest(-1), std::invalid_argument);
  EXPECT_THROW(JiaOverlapTest(1), std::invalid_argument);
}
