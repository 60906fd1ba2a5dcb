// Shared helpers of the geometry unit tests: random bodies and pairs, the
// paper's analytic mirror case (section 3.2), tangent pairs.
#ifndef ELLIPSOIDS_TESTGEOMETRY_HPP
#define ELLIPSOIDS_TESTGEOMETRY_HPP

#include "ellipsoids/Ellipsoid.hpp"

#include <cmath>
#include <random>

namespace testgeometry {

using ellipsoids::Ellipsoid;
using ellipsoids::Quat;
using ellipsoids::Scalar;
using ellipsoids::Vec3;

inline Quat randomRotation(std::mt19937_64& rng) {
  std::normal_distribution<Scalar> g;
  Quat q(g(rng), g(rng), g(rng), g(rng));
  q.normalize();
  return q;
}

inline Vec3 randomUnit(std::mt19937_64& rng) {
  std::normal_distribution<Scalar> g;
  return Vec3(g(rng), g(rng), g(rng)).normalized();
}

/// Random tri-axial ellipsoid, semi-axes in [lo, hi], centre ~ N(0, spread).
inline Ellipsoid randomEllipsoid(std::mt19937_64& rng, Scalar lo, Scalar hi, Scalar spread) {
  std::uniform_real_distribution<Scalar> u(lo, hi);
  std::normal_distribution<Scalar> g(0, spread);
  return Ellipsoid(Vec3(u(rng), u(rng), u(rng)), Vec3(g(rng), g(rng), g(rng)), randomRotation(rng));
}

/// The same body moved: centre replaced.
inline Ellipsoid movedTo(const Ellipsoid& e, const Vec3& centre) {
  return Ellipsoid(e.semiAxes(), centre, e.orientation());
}

/// The pair transformed by x -> s R x + t (rigid motion and scaling).
inline Ellipsoid transformed(const Ellipsoid& e, Scalar s, const Quat& R, const Vec3& t) {
  return Ellipsoid(s * e.semiAxes(), s * (R * e.centre()) + t, R * e.orientation());
}

/**
 * E2 placed so that it touches e1 at e1's support point in direction n (both
 * surfaces tangent there), then moved by gap along n: the exact distance is
 * max(gap, 0) (for gap >= 0).
 */
inline Ellipsoid tangentPartner(const Ellipsoid& e1, const Vec3& semiAxes2, const Quat& q2,
                                const Vec3& unitN, Scalar gap) {
  const Ellipsoid atOrigin(semiAxes2, Vec3::Zero(), q2);
  return Ellipsoid(semiAxes2, e1.support(unitN) + atOrigin.support(unitN) + gap * unitN, q2);
}

/// The analytic validation case of the paper (section 3.2).
struct MirrorCase {
  Ellipsoid e1;       // centre (xc, 0, 0), major axis at +pi/4 about z
  Ellipsoid e2;       // its mirror image in the yz plane
  Scalar exactDistance;
  Vec3 exactPoint1;   // s_E1(-x)
  Vec3 exactPoint2;   // s_E2(+x)
  Scalar xc;
  Scalar b;           // the smaller semi-axis... (for eq. 3.3: v0 = (2 xc, 2b, 2b))
};

/**
 * @param ar aspect ratio a/b, equal-volume diameter dEq = lambda
 * @param distance exact distance d* (absolute)
 */
inline MirrorCase mirrorCase(Scalar ar, Scalar distance, Scalar lambda) {
  const Quat q1(Eigen::AngleAxis<Scalar>(M_PI / 4, Vec3::UnitZ()));
  const Quat q2(Eigen::AngleAxis<Scalar>(-M_PI / 4, Vec3::UnitZ()));
  const Ellipsoid shape = Ellipsoid::spheroid(ar, lambda, Vec3::Zero(), q1);
  const Scalar a = shape.semiAxes().x(), b = shape.semiAxes().y();
  const Scalar halfWidth = std::sqrt((a * a + b * b) / 2);  // extent along x
  const Scalar xc = distance / 2 + halfWidth;
  MirrorCase m{Ellipsoid::spheroid(ar, lambda, Vec3(xc, 0, 0), q1),
               Ellipsoid::spheroid(ar, lambda, Vec3(-xc, 0, 0), q2),
               0, Vec3::Zero(), Vec3::Zero(), xc, b};
  m.exactPoint1 = m.e1.support(-Vec3::UnitX());
  m.exactPoint2 = m.e2.support(Vec3::UnitX());
  m.exactDistance = 2 * (xc - halfWidth);
  return m;
}

}  // namespace testgeometry

#endif
