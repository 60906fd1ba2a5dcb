// Pairs for the tests against the long-double reference (LongDoubleReference.hpp):
// a body placed tangent to another, and the needle pairs that load the rounding
// of the world-frame shape matrices most.
#ifndef ELLIPSOIDS_TESTS_REFERENCEPAIRS_HPP
#define ELLIPSOIDS_TESTS_REFERENCEPAIRS_HPP

#include "LongDoubleReference.hpp"
#include "TestGeometry.hpp"

#include <random>

namespace testgeometry {

/// Body 2 tangent to body 1 at its support point along the unit n, then moved by gap along n.
inline BodyInput tangentInput(const BodyInput& b1, const Vec3& axes2, const Quat& q2, const Vec3& n, Scalar gap) {
  const Ellipsoid e1 = b1.body();
  const Ellipsoid atOrigin(axes2, Vec3::Zero(), q2);
  return BodyInput{axes2, e1.support(n) + atOrigin.support(n) + gap * n, q2};
}

struct InputPair {
  BodyInput b1, b2;
  Vec3 normal;  // the direction the pair was built along
};

/**
 * Two spheroids of aspect ratio ar (D_eq 1) with their symmetry axes near the
 * diagonals (1, 1, 1) and (1, -1, 1) (or both the same), tangent across that
 * axis and moved apart by gap: every entry of the world-frame matrices
 * P = U diag(a^2, b^2, b^2) U^T is of order a^2 while sqrt(n^T P n) is b, the case
 * where their rounding weighs most (eps a^2 / b = eps a kappa).
 */
inline InputPair obliqueNeedles(std::mt19937_64& rng, Scalar ar, Scalar gap, bool parallel) {
  const Vec3 axes = Ellipsoid::spheroid(ar, 1, Vec3::Zero(), Quat::Identity()).semiAxes();
  const Scalar spin = std::uniform_real_distribution<Scalar>(0, 2 * ellipsoids::kPi)(rng);
  Quat q1 = Quat::FromTwoVectors(Vec3::UnitX(), (Vec3(1, 1, 1) + 0.3 * randomUnit(rng)).normalized()) *
            Quat(Eigen::AngleAxis<Scalar>(spin, Vec3::UnitX()));
  const BodyInput b1{axes, Vec3(0.3, -0.1, 0.2), q1.normalized()};
  const Vec3 symmetryAxis = b1.body().rotation().col(0);
  Vec3 n = randomUnit(rng);
  n = (n - n.dot(symmetryAxis) * symmetryAxis).normalized();
  const Quat q2 = parallel ? b1.orientation
                           : Quat::FromTwoVectors(Vec3::UnitX(), (Vec3(1, -1, 1) + 0.3 * randomUnit(rng)).normalized());
  return InputPair{b1, tangentInput(b1, axes, q2, n, gap), n};
}

}  // namespace testgeometry

#endif
