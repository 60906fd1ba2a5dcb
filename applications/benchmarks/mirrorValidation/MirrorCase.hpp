/**
 * @file MirrorCase.hpp
 * @brief The analytic validation case of the founding paper (section 3.2).
 *
 * E1: spheroid of aspect ratio Ar = a/b, equal-volume diameter D = Lambda,
 * semi-axes a = Ar^(2/3) D/2 (body x), b = c = Ar^(-1/3) D/2, centre (xc, 0, 0),
 * rotated by pi/4 about z; E2: its mirror image in the yz plane. The exact
 * solution: x1* = s_E1(-x), x2* = s_E2(x), d* = 2 (xc - sqrt((a^2 + b^2)/2)).
 */
#ifndef MIRRORVALIDATION_MIRRORCASE_HPP
#define MIRRORVALIDATION_MIRRORCASE_HPP

#include "ellipsoids/Ellipsoid.hpp"

#include <cmath>

namespace mirror {

using ellipsoids::Ellipsoid;
using ellipsoids::Quat;
using ellipsoids::Scalar;
using ellipsoids::Vec3;

struct Case {
  Ellipsoid e1, e2;
  Scalar exactDistance;
  Vec3 exactPoint1, exactPoint2;
  Scalar xc, b;
};

/// @param distance exact distance d* (absolute), lambda = D_eq
inline Case make(Scalar ar, Scalar distance, Scalar lambda) {
  const Quat q1(Eigen::AngleAxis<Scalar>(M_PI / 4, Vec3::UnitZ()));
  const Quat q2(Eigen::AngleAxis<Scalar>(-M_PI / 4, Vec3::UnitZ()));
  const Ellipsoid shape = Ellipsoid::spheroid(ar, lambda, Vec3::Zero(), q1);
  const Scalar a = shape.semiAxes().x(), b = shape.semiAxes().y();
  const Scalar halfWidth = std::sqrt((a * a + b * b) / 2);
  const Scalar xc = distance / 2 + halfWidth;
  Case c{Ellipsoid::spheroid(ar, lambda, Vec3(xc, 0, 0), q1),
         Ellipsoid::spheroid(ar, lambda, Vec3(-xc, 0, 0), q2), 0, Vec3::Zero(), Vec3::Zero(), xc,
         b};
  c.exactPoint1 = c.e1.support(-Vec3::UnitX());
  c.exactPoint2 = c.e2.support(Vec3::UnitX());
  c.exactDistance = 2 * (xc - halfWidth);
  return c;
}

/// GJK's start of eq. 3.3, v0 = (2 xc, 2b, 2b), as a direction from body 1 to body 2 (= -v0).
inline Vec3 eq33Direction(const Case& c) { return -Vec3(2 * c.xc, 2 * c.b, 2 * c.b).normalized(); }

}  // namespace mirror

#endif
