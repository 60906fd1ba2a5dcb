#include "ellipsoids/CertifiedBracket.hpp"

#include "ellipsoids/DualNewton.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ellipsoids {

namespace {

struct Bracket {
  Scalar lower;
  Scalar upper;
  Vec3 direction;
};

/// |v|_1 >= |v|: a bound of a coordinate magnitude without a square root.
Scalar norm1(const Vec3& v) { return v.cwiseAbs().sum(); }

/// |D^-1 U^T (x - r)|: 1 on the surface, < 1 inside (body frame, see the header).
Scalar scaledRadius(const Ellipsoid& e, const Vec3& x) {
  const Vec3 m = e.rotation().transpose() * (x - e.centre());
  return m.cwiseQuotient(e.semiAxes()).norm();
}

/// A point of e near x: x if the body-frame test puts it inside, else its radial projection.
Vec3 intoBody(const Ellipsoid& e, const Vec3& x) {
  const Scalar s = scaledRadius(e, x);
  return s > 1 && std::isfinite(s) ? Vec3(e.centre() + (x - e.centre()) / s) : x;
}

Bracket bracketFromPoints(const Ellipsoid& e1, const Ellipsoid& e2, const Vec3& x1in,
                          const Vec3& x2in, Scalar distance) {
  const Vec3 x1 = intoBody(e1, x1in);
  const Vec3 x2 = intoBody(e2, x2in);
  const Vec3 d = x2 - x1;
  const Scalar allow = roundingAllowance(e1, e2);

  Bracket b;
  // U from absolute coordinates: their rounding is relative to |x|, not to the pair's size
  b.upper = d.norm() + allow + 4 * kEps * (norm1(x1) + norm1(x2));
  Scalar best = -std::numeric_limits<Scalar>::infinity();
  Vec3 bestN = e2.centre() - e1.centre();
  // any unit n gives a valid L(n); these are the ones near the optimum for good points
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
  // the method's own distance inside its bracket (both bounds stay valid)
  b.lower = std::min(b.lower, distance);
  b.upper = std::max(b.upper, distance);
  return b;
}

}  // namespace

Scalar bodyFrameSupportRadius(const Ellipsoid& e, const Vec3& unitN) {
  return (e.rotation().transpose() * unitN).cwiseProduct(e.semiAxes()).norm();
}

Scalar separatingPlaneBound(const Ellipsoid& e1, const Ellipsoid& e2, const Vec3& unitN) {
  return unitN.dot(e2.centre() - e1.centre()) - bodyFrameSupportRadius(e1, unitN) -
         bodyFrameSupportRadius(e2, unitN);
}

Scalar roundingAllowance(const Ellipsoid& e1, const Ellipsoid& e2) {
  return roundingAllowance(e1, e2, (e2.centre() - e1.centre()).norm());
}


bool certainlyInside(const Ellipsoid& e, const Vec3& x) {
  // rounding of the scaled body-frame coordinates: x - r, the rotation by the
  // rounded U^T (and U's own distance from the exact rotation), over a_min
  const Scalar delta = 32 * kEps * (norm1(x) + norm1(e.centre())) / e.minSemiAxis();
  const Scalar margin = 4 * delta + 16 * kEps;
  return scaledRadius(e, x) <= 1 - margin;
}

void certifyFromPoints(const Ellipsoid& e1, const Ellipsoid& e2, DistanceResult& result) {
  if (result.status == DistanceStatus::overlapping) {
    result.lower = 0;
    const Vec3 mid = Scalar(0.5) * (result.point1 + result.point2);
    const bool common = certainlyInside(e1, result.point2) || certainlyInside(e2, result.point1) ||
                        certainlyInside(e1, e2.centre()) || certainlyInside(e2, e1.centre()) ||
                        (certainlyInside(e1, mid) && certainlyInside(e2, mid));
    if (common) {
      result.upper = 0;
      return;
    }
    // the signed dual method's points at the overlap's maximum of L are common
    // points for all but the slightest overlaps (DualNewton: upper = 0 then)
    DistanceOptions o;
    o.epsD = 1e-6 * std::min(e1.minSemiAxis(), e2.minSemiAxis());
    const DistanceResult signedResult = DualNewton().distance(e1, e2, o);
    result.upper = signedResult.status == DistanceStatus::overlapping && signedResult.upper == 0
                       ? Scalar(0)
                       : bracketFromPoints(e1, e2, result.point1, result.point2, 0).upper;
    return;
  }
  const Bracket b = bracketFromPoints(e1, e2, result.point1, result.point2, result.distance);
  result.lower = b.lower;
  result.upper = b.upper;
  result.direction = b.direction;
}

Scalar bracketWidthFromPoints(const Ellipsoid& e1, const Ellipsoid& e2, const Vec3& x1,
                              const Vec3& x2) {
  const Bracket b = bracketFromPoints(e1, e2, x1, x2, (x2 - x1).norm());
  return b.upper - b.lower;
}

}  // namespace ellipsoids
