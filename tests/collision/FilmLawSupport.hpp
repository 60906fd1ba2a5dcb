// What the tests of the film laws (TangentialLubrication, CubicGapCoupling)
// share: spheroids touching a point with their local geometry, the 12 x 12
// load matrix of a law, and the checks every law passes (no load under a
// rigid motion of the pair, the same loads with the bodies' labels exchanged).
#ifndef COLLISION_TESTS_FILMLAWSUPPORT_HPP
#define COLLISION_TESTS_FILMLAWSUPPORT_HPP

#include "collision/FilmResistanceRate.hpp"
#include "ellipsoids/Ellipsoid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

namespace collision {

/// A spheroid touching a point with its outward normal there along m: its
/// curvature tensor and third derivatives at that point and the arm from its
/// centre to it.
struct Touching {
  Mat3 curvature;
  Tensor3 third;
  Vec3 arm;
};

/// The spheroid of semi-axes a, b, b along the axis e touching the origin.
inline Touching spheroidAt(Scalar a, Scalar b, const Vec3& e, const Vec3& m) {
  const Quat q = Quat::FromTwoVectors(Vec3::UnitX(), e.normalized());
  // the support point of the centred spheroid in the direction m
  const ellipsoids::Ellipsoid centred(Vec3(a, b, b), Vec3::Zero(), q);
  const Vec3 point = centred.support(m);
  return {centred.curvatureTensor(point), centred.surfaceThirdDerivative(point), point};
}

/// The loads (F1, T1, F2, T2) per unit (v1, Omega1, v2, Omega2) of a film law,
/// row-major: -R. Plain arrays: the product q.R q is all the tests need.
using Mat12 = std::array<std::array<Scalar, 12>, 12>;

inline Mat12 loadMatrix(const FilmLaw& law, const Vec3& arm1, const Vec3& arm2) {
  Mat12 R{};
  for (int k = 0; k < 12; ++k) {
    Vec3 motion[4] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    motion[k / 3](k % 3) = 1;
    const FilmLoads l = law({arm1, motion[0], motion[1]}, {arm2, motion[2], motion[3]});
    const Vec3 loads[4] = {l.force1, l.torque1, -l.force1, l.torque2};
    for (int row = 0; row < 12; ++row) R[row][k] = loads[row / 3](row % 3);
  }
  return R;
}

inline Scalar largestEntry(const Mat12& R) {
  Scalar m = 0;
  for (const auto& row : R)
    for (const Scalar v : row) m = std::max(m, std::abs(v));
  return m;
}

/// q.R q
inline Scalar power(const Mat12& R, const std::array<Scalar, 12>& q) {
  Scalar p = 0;
  for (int row = 0; row < 12; ++row)
    for (int col = 0; col < 12; ++col) p += q[row] * R[row][col] * q[col];
  return p;
}

/// Five random rigid motions of the pair (about any point), the bodies'
/// closest points at the origin: the law's loads below 1e-13 of scale times
/// the motion's size.
inline void expectNoLoadUnderRigidMotion(const FilmLaw& law, const Vec3& arm1, const Vec3& arm2,
                                         Scalar scale, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Scalar> u(-1, 1);
  const Vec3 c1 = -arm1, c2 = -arm2;
  for (int k = 0; k < 5; ++k) {
    const Vec3 V(u(rng), u(rng), u(rng)), W(u(rng), u(rng), u(rng)), x0(u(rng), u(rng), u(rng));
    const FilmLoads l = law({arm1, V + W.cross(c1 - x0), W}, {arm2, V + W.cross(c2 - x0), W});
    const Scalar bound = 1e-13 * scale * (V.norm() + W.norm());
    EXPECT_LT(l.force1.norm(), bound);
    EXPECT_LT(l.torque1.norm(), bound);
    EXPECT_LT(l.torque2.norm(), bound);
  }
}

/// A random motion of both bodies: the law and the law with the labels
/// exchanged (exchanged(two, one)) give the same loads on each body.
inline void expectSameLoadsExchanged(const FilmLaw& law, const FilmLaw& exchanged,
                                     const Vec3& arm1, const Vec3& arm2, Scalar length,
                                     unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<Scalar> normal;
  auto random = [&]() { return Vec3(normal(rng), normal(rng), normal(rng)); };
  const FilmSide one{arm1, random(), random()}, two{arm2, random(), random()};
  const FilmLoads a = law(one, two), b = exchanged(two, one);
  const Scalar scale = a.force1.norm() + a.torque1.norm() / length;
  ASSERT_GT(scale, 0);
  EXPECT_LT((a.force1 + b.force1).norm(), 1e-12 * scale);
  EXPECT_LT((a.torque1 - b.torque2).norm(), 1e-12 * scale * length);
  EXPECT_LT((a.torque2 - b.torque1).norm(), 1e-12 * scale * length);
}

}  // namespace collision

#endif
