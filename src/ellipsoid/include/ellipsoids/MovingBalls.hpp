/**
 * @file MovingBalls.hpp
 * @brief The Moving Balls algorithm of Lin & Han (2002), founding paper Alg. 1.
 *
 * Balls inside each ellipsoid, tangent at the current points x_m, with centres
 * c_m = x_m - gamma_m grad f_m(x_m), gamma_m = (smallest semi-axis)^2 (eqs. 2.1-2.2);
 * the new points are the intersections of the segment [c1, c2] with the
 * surfaces (App. D). Overlap when the segment's exit from E1 comes after its
 * entry into E2 (2.1.2). Stops when the angles between x2 - x1 and the
 * normals are below eps_theta (eq. 2.4, tested as in App. E), eps_theta from
 * eq. 2.9 (global curvature bound) or eq. F.6 (adaptive, options.adaptiveEpsTheta),
 * or, with StopRule::certified, when the certified bracket is within epsD.
 */
#ifndef ELLIPSOIDS_MOVINGBALLS_HPP
#define ELLIPSOIDS_MOVINGBALLS_HPP

#include "ellipsoids/DistanceMethod.hpp"

namespace ellipsoids {

class MovingBalls : public DistanceMethod {
 public:
  static constexpr int kDefaultMaxIterations = 100000;

  std::string name() const override { return "movingBalls"; }
  DistanceResult distance(const Ellipsoid& e1, const Ellipsoid& e2,
                          const DistanceOptions& options) const override;
};

/**
 * The angle test of Appendix E: angle(a, b) <= epsTheta, without acos:
 * a.b > 0 and (a.b)^2 >= (1 - epsTheta^2/2)^2 |a|^2 |b|^2.
 */
bool angleWithin(const Vec3& a, const Vec3& b, Scalar epsTheta);

/// eps_theta of eq. 2.9 (global) for a pair and a distance tolerance.
Scalar epsThetaGlobal(const Ellipsoid& e1, const Ellipsoid& e2, Scalar epsD);

/// eps_theta of eq. F.6 (local curvature at the current points).
Scalar epsThetaAdaptive(const Ellipsoid& e1, const Ellipsoid& e2, const Vec3& x1, const Vec3& x2,
                        Scalar epsD);

/**
 * Initial points of Moving Balls, Newton-Coulomb, exterior penalty and Jain
 * et al.: the intersections of the centre segment [r1, r2] with the surfaces.
 * @return false if the segment shows an overlap (the centre of one body is in
 *         the other, or the segment's parts inside the bodies overlap)
 */
bool centreSegmentPoints(const Ellipsoid& e1, const Ellipsoid& e2, Vec3& x1, Vec3& x2);

}  // namespace ellipsoids

#endif
