#include "ellipsoids/CertifiedBracket.hpp"

#include "ellipsoids/OverlapTest.hpp"

#include <algorithm>
#include <cmath>

namespace ellipsoids {

namespace {

struct Bracket {
  Scalar lower;
  Scalar upper;
  Vec3 direction;
};

// Radial projection that tolerates a point at the centre (then unchanged).
Vec3 ontoSurface(const Ellipsoid& e, const Vec3& x) {
  const Vec3 d = x - e.centre();
  const Scalar q = d.dot(e.quadraticMatrix() * d);
  return q > 0 && std::isfinite(q) ? Vec3(e.centre() + d / std::sqrt(q)) : x;
}

Bracket bracketFromPoints(const Ellipsoid& e1, const Ellipsoid& e2, const Vec3& x1in,
                          const Vec3& x2in) {
  const Vec3 x1 = ontoSurface(e1, x1in);
  const Vec3 x2 = ontoSurface(e2, x2in);
  const Vec3 d = x2 - x1;
  const Scalar allow = roundingAllowance(e1, e2);

  Bracket b;
  // U from absolute coordinates: their rounding is relative to |x|, not to the pair's size
  b.upper = d.norm() + allow + 4 * kEps * (x1.norm() + x2.norm());
  Scalar best = -std::numeric_limits<Scalar>::infinity();
  Vec3 bestN = e2.centre() - e1.centre();
  const Vec3 candidates[3] = {d, e1.gradient(x1), -e2.gradient(x2)};
  for (const Vec3& c : candidates) {
    const Scalar norm = c.norm();
    if (!(norm > 0) || !std::isfinite(norm)) {
      continue;
    }
    const Vec3 n = c / norm;
    const Scalar L = separatingPlaneBound(e1, e2, n);
    if (L > best) {
      best = L;
      bestN = n;
    }
  }
  if (!std::isfinite(best)) {  // all candidates degenerate: centre line
    const Scalar norm = bestN.norm();
    bestN = norm > 0 ? Vec3(bestN / norm) : Vec3::UnitX();
    best = separatingPlaneBound(e1, e2, bestN);
  }
  b.lower = std::max(best - allow, Scalar(0));  // unsigned distance is >= 0
  b.direction = bestN;
  return b;
}

}  // namespace

Scalar separatingPlaneBound(const Ellipsoid& e1, const Ellipsoid& e2, const Vec3& unitN) {
  return unitN.dot(e2.centre() - e1.centre()) - e1.supportRadius(unitN) - e2.supportRadius(unitN);
}

Scalar roundingAllowance(const Ellipsoid& e1, const Ellipsoid& e2) {
  return 32 * kEps *
         ((e2.centre() - e1.centre()).norm() + e1.maxSemiAxis() + e2.maxSemiAxis());
}

void certifyFromPoints(const Ellipsoid& e1, const Ellipsoid& e2, DistanceResult& result) {
  if (result.status == DistanceStatus::overlapping) {
    // d* = 0 is certain when a point of one body is in the other (e.g. the
    // crossed centre-segment points) or the exact Jia test says overlapping;
    // for a pair it calls touching the points bound the gap that may remain
    result.lower = 0;
    const Vec3 mid = Scalar(0.5) * (result.point1 + result.point2);
    const bool common = e1.levelSet(result.point2) <= 0 || e2.levelSet(result.point1) <= 0 ||
                        e1.levelSet(e2.centre()) <= 0 || e2.levelSet(e1.centre()) <= 0 ||
                        (e1.levelSet(mid) <= 0 && e2.levelSet(mid) <= 0);
    const bool certain = common || JiaOverlapTest().test(e1, e2) == OverlapStatus::overlapping;
    result.upper = certain ? Scalar(0)
                           : bracketFromPoints(e1, e2, result.point1, result.point2).upper;
    return;
  }
  const Bracket b = bracketFromPoints(e1, e2, result.point1, result.point2);
  result.lower = b.lower;
  result.upper = b.upper;
  result.direction = b.direction;
}

Scalar bracketWidthFromPoints(const Ellipsoid& e1, const Ellipsoid& e2, const Vec3& x1,
                              const Vec3& x2) {
  const Bracket b = bracketFromPoints(e1, e2, x1, x2);
  return b.upper - b.lower;
}

}  // namespace ellipsoids
