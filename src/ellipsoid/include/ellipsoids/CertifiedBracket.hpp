/**
 * @file CertifiedBracket.hpp
 * @brief Lower and upper bounds of the distance that hold whatever the method.
 *
 * For a unit n from body 1 to body 2, with P_m the shape matrices,
 *   L(n) = n.(r2 - r1) - sqrt(n^T P1 n) - sqrt(n^T P2 n) <= d*        (a separating-plane bound)
 * and for any x1 in E1, x2 in E2
 *   d* <= U = |x2 - x1|.
 * L(n) is also the dual function of the distance problem: d* = max_{|n|=1} L(n)
 * for separated bodies, and max_{|n|=1} L(n) = -(penetration depth) when they overlap.
 *
 * Rounding and conditioning. The true body is the one of the given semi-axes,
 * centre and (normalised) quaternion. The functions of this file evaluate it in
 * its body frame: sqrt(n^T P n) as |D U^T n| (D = diag(a, b, c)) and the
 * membership of a point from |D^-1 U^T (x - r)|; their rounding is a few eps
 * times the largest semi-axis, whatever the elongation. The methods' own loops
 * (dual, GJK, Moving Balls) use the stored world-frame matrices P = U D^2 U^T
 * and A = P^-1, whose entries are rounded at eps a_max^2 and eps / a_min^2:
 * a support radius sqrt(n^T P n) is then off by up to about 14 eps a_max^2 / a_min
 * (the rounding of P over 2 sqrt(n^T P n) >= 2 a_min, plus that of the
 * evaluation) and 12 eps a_max (the rotation matrix), and so are the support
 * points along the surface normal: the conditioning of P is the elongation
 * kappa = a_max / a_min. (Through A, as in Moving Balls' line intersections, it
 * is kappa^2: a surface point found from A is off by up to eps a_max kappa^2,
 * 2.2e-12 a_max at kappa = 100; the certificate below therefore projects
 * points with the body-frame form, never with A.) Both bounds are widened by
 *   roundingAllowance = 32 eps (|r2 - r1| + kappa1 a_max,1 + kappa2 a_max,2),
 * which bounds the above (26 kappa eps a_max per body, 3 eps |r2 - r1| for the
 * centre distance); the upper bound also by 4 eps (|x1| + |x2|), the rounding
 * of absolute coordinates. tests/geometry/ExtremeRangeTest.cpp measures the
 * largest error against a long-double reference as a fraction of the allowance.
 */
#ifndef ELLIPSOIDS_CERTIFIEDBRACKET_HPP
#define ELLIPSOIDS_CERTIFIEDBRACKET_HPP

#include "ellipsoids/DistanceResult.hpp"
#include "ellipsoids/Ellipsoid.hpp"

namespace ellipsoids {

/// sqrt(n^T P n) for a unit n, evaluated in the body frame as |D U^T n|.
Scalar bodyFrameSupportRadius(const Ellipsoid& e, const Vec3& unitN);

/// L(n) for a unit n from body 1 to body 2, support radii in the body frames (no allowance).
Scalar separatingPlaneBound(const Ellipsoid& e1, const Ellipsoid& e2, const Vec3& unitN);

/// 32 eps (|r2 - r1| + kappa1 a_max,1 + kappa2 a_max,2), kappa = elongation: see the file comment.
Scalar roundingAllowance(const Ellipsoid& e1, const Ellipsoid& e2);
/// The same with |r2 - r1| given (the callers that have it; kappa a_max = a_max^2 / a_min is
/// the largest curvature radius, precomputed per body).
inline Scalar roundingAllowance(const Ellipsoid& e1, const Ellipsoid& e2, Scalar centreDistance) {
  return 32 * kEps * (centreDistance + e1.maxOfMaxCurvatureRadius() + e2.maxOfMaxCurvatureRadius());
}

/**
 * True only if x lies in e whatever the rounding: |D^-1 U^T (x - r)|^2 at most
 * 1 minus a margin that bounds the rounding of that test (it grows with
 * |x| + |r| over the smallest semi-axis; a point near a body far from the
 * origin may be inside and still fail).
 */
bool certainlyInside(const Ellipsoid& e, const Vec3& x);

/**
 * Fills result.lower, result.upper and result.direction from result.point1
 * and result.point2.
 * - U: the distance of two points of the bodies: each given point if the
 *   body-frame test puts it inside its body, else its radial projection onto
 *   the surface (so that points a method left off the surface still give a
 *   valid bound).
 * - L: the best of the directions x2 - x1, the outward normal at x1 and minus
 *   the outward normal at x2.
 * - The method's own result.distance is kept inside the bracket: the bracket
 *   is widened to it if needed (a distance of points inside the bodies, as
 *   the exterior penalty method may return, lowers the lower bound).
 * - Status overlapping: [0, 0] only when a common point is certain
 *   (certainlyInside: a point of one body in the other, a centre in the other
 *   body, the midpoint of the points in both, or else the common point the
 *   signed dual method certifies); otherwise [0, U], since a pair said to
 *   overlap without such a point may still be apart by up to U. The Jia et al.
 *   test is not consulted: its answer is not a certificate.
 */
void certifyFromPoints(const Ellipsoid& e1, const Ellipsoid& e2, DistanceResult& result);

/// Certified bracket width of two points (as certifyFromPoints with distance |x2 - x1|): the certified stopping test.
Scalar bracketWidthFromPoints(const Ellipsoid& e1, const Ellipsoid& e2, const Vec3& x1,
                              const Vec3& x2);

}  // namespace ellipsoids

#endif
