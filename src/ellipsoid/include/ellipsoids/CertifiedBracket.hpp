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
 * Rounding: both bounds are widened by roundingAllowance(), a few ulps of the
 * pair's size, so that the bracket also holds in floating point.
 */
#ifndef ELLIPSOIDS_CERTIFIEDBRACKET_HPP
#define ELLIPSOIDS_CERTIFIEDBRACKET_HPP

#include "ellipsoids/DistanceResult.hpp"
#include "ellipsoids/Ellipsoid.hpp"

namespace ellipsoids {

/// L(n) for a unit n from body 1 to body 2 (no rounding allowance).
Scalar separatingPlaneBound(const Ellipsoid& e1, const Ellipsoid& e2, const Vec3& unitN);

/// 32 eps (|r2 - r1| + largest semi-axes): bound on the rounding of L and U.
Scalar roundingAllowance(const Ellipsoid& e1, const Ellipsoid& e2);

/**
 * Fills result.lower, result.upper and result.direction from result.point1
 * and result.point2: U from the points projected radially onto their surfaces
 * (so that points a method left slightly off the surface still give a valid
 * bound), L as the best of the directions x2 - x1, the outward normal at x1
 * and minus the outward normal at x2. For status overlapping the bracket is
 * [0, 0] when one point lies in the other body (a common point) or the Jia
 * test says overlapping, else [0, U] (a pair the Jia test calls touching).
 */
void certifyFromPoints(const Ellipsoid& e1, const Ellipsoid& e2, DistanceResult& result);

/// Certified bracket width of two surface points (as certifyFromPoints): used as stopping test.
Scalar bracketWidthFromPoints(const Ellipsoid& e1, const Ellipsoid& e2, const Vec3& x1,
                              const Vec3& x2);

}  // namespace ellipsoids

#endif
