#include "ellipsoids/MovingBalls.hpp"

#include "ellipsoids/CertifiedBracket.hpp"

#include <cmath>

namespace ellipsoids {

bool angleWithin(const Vec3& a, const Vec3& b, Scalar epsTheta) {
  const Scalar ab = a.dot(b);
  if (!(ab > 0)) {
    return false;
  }
  const Scalar c = 1 - epsTheta * epsTheta / 2;
  return ab * ab >= c * c * a.squaredNorm() * b.squaredNorm();
}

Scalar epsThetaGlobal(const Ellipsoid& e1, const Ellipsoid& e2, Scalar epsD) {
  return std::sqrt(2 * epsD / (e1.maxOfMaxCurvatureRadius() + e2.maxOfMaxCurvatureRadius()));
}

Scalar epsThetaAdaptive(const Ellipsoid& e1, const Ellipsoid& e2, const Vec3& x1, const Vec3& x2,
                        Scalar epsD) {
  return std::sqrt(2 * epsD / (e1.curvatureRadii(x1).rMax + e2.curvatureRadii(x2).rMax));
}

bool centreSegmentPoints(const Ellipsoid& e1, const Ellipsoid& e2, Vec3& x1, Vec3& x2) {
  const Vec3 dr = e2.centre() - e1.centre();
  if (!(dr.squaredNorm() > 0)) {
    x1 = x2 = e1.centre();
    return false;
  }
  const LineIntersection i1 = e1.intersectLine(e1.centre(), dr);  // r1 inside: tEnter < 0 < tExit
  const LineIntersection i2 = e2.intersectLine(e1.centre(), dr);  // r2 (t = 1) inside E2
  x1 = e1.centre() + i1.tExit * dr;
  x2 = e1.centre() + i2.tEnter * dr;
  return i1.count == 2 && i2.count == 2 && i1.tExit < i2.tEnter;
}

DistanceResult MovingBalls::distance(const Ellipsoid& e1, const Ellipsoid& e2,
                                     const DistanceOptions& options) const {
  options.validate();
  const int maxIterations = options.maxIterations > 0 ? options.maxIterations : kDefaultMaxIterations;
  const Scalar gamma1 = e1.minSemiAxis() * e1.minSemiAxis();
  const Scalar gamma2 = e2.minSemiAxis() * e2.minSemiAxis();
  const Scalar epsThetaFixed = epsThetaGlobal(e1, e2, options.epsD);

  DistanceResult res;
  Vec3 x1, x2;
  if (!centreSegmentPoints(e1, e2, x1, x2)) {
    res.status = DistanceStatus::overlapping;
    res.point1 = x1;
    res.point2 = x2;
    certifyFromPoints(e1, e2, res);
    return res;
  }

  auto stop = [&](const Vec3& p1, const Vec3& p2) {
    if (options.stopRule == StopRule::certified) {
      return bracketWidthFromPoints(e1, e2, p1, p2) <= options.epsD;
    }
    const Scalar epsTheta = options.adaptiveEpsTheta
                                ? epsThetaAdaptive(e1, e2, p1, p2, options.epsD)
                                : epsThetaFixed;
    return angleWithin(p2 - p1, e1.gradient(p1), epsTheta) &&
           angleWithin(p1 - p2, e2.gradient(p2), epsTheta);
  };

  res.status = DistanceStatus::maxIterations;
  int k = 0;
  for (; k < maxIterations; ++k) {
    if (stop(x1, x2)) {
      res.status = DistanceStatus::converged;
      break;
    }
    const Vec3 c1 = x1 - gamma1 * e1.gradient(x1);
    const Vec3 c2 = x2 - gamma2 * e2.gradient(x2);
    const Vec3 d = c2 - c1;
    const LineIntersection i1 = e1.intersectLine(c1, d);
    const LineIntersection i2 = e2.intersectLine(c1, d);
    if (i1.count == 0 || i2.count == 0) {
      res.status = DistanceStatus::failed;  // cannot happen in exact arithmetic: c_m is inside E_m
      break;
    }
    if (i1.tExit >= i2.tEnter) {
      res.status = DistanceStatus::overlapping;  // a common point on [c1, c2]
      x1 = c1 + i1.tExit * d;
      x2 = c1 + i2.tEnter * d;
      break;
    }
    x1 = c1 + i1.tExit * d;
    x2 = c1 + i2.tEnter * d;
  }
  res.iterations = k;
  res.point1 = x1;
  res.point2 = x2;
  res.distance = res.status == DistanceStatus::overlapping ? 0 : (x2 - x1).norm();
  certifyFromPoints(e1, e2, res);
  return res;
}

}  // namespace ellipsoids
