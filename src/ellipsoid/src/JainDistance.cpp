#include "ellipsoids/JainDistance.hpp"

#include "ellipsoids/CertifiedBracket.hpp"
#include "ellipsoids/MovingBalls.hpp"
#include "ellipsoids/OverlapTest.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace ellipsoids {

namespace {

/// The copy of e translated by -origin (all computations are relative to r1).
Ellipsoid relativeTo(const Ellipsoid& e, const Vec3& origin) { return e.translatedBy(-origin); }

/// A surface point held in the ellipsoidal coordinates (nu, phi) of its body (eq. 2.68).
struct SurfacePoint {
  Scalar nu = 0;
  Scalar phi = 0;

  /// Eq. 2.69 for a point x on (or near) the surface: nu = arccos(z/c) (z/c
  /// clamped to [-1, 1] against rounding) and phi = atan2(y/b, x/a), which is the
  /// paper's case analysis of arctan(a y / (b x)) in one call (atan2(y/b, x/a) =
  /// atan2(a y, b x) as a, b > 0). The transcription of eq. 2.69 is garbled: it
  /// gives the -pi + arctan branch twice, the first time with the condition
  /// "x < 0 and y >= 0"; the derivation (phi in [-pi, pi]) requires x < 0, y < 0.
  void fromPoint(const Ellipsoid& e, const Vec3& x) {
    const Vec3 xb = e.rotation().transpose() * (x - e.centre());
    const Vec3& s = e.semiAxes();
    nu = std::acos(std::clamp(xb.z() / s.z(), Scalar(-1), Scalar(1)));
    phi = std::atan2(xb.y() / s.y(), xb.x() / s.x());
  }

  /// Body-frame position (eq. 2.68).
  Vec3 body(const Vec3& s) const {
    const Scalar sn = std::sin(nu), cn = std::cos(nu), sp = std::sin(phi), cp = std::cos(phi);
    return Vec3(s.x() * cp * sn, s.y() * sp * sn, s.z() * cn);
  }

  Vec3 position(const Ellipsoid& e) const { return e.centre() + e.rotation() * body(e.semiAxes()); }

  /**
   * One step of eq. 2.70 toward the other point: d is x_other - x_m (global frame).
   * t_nu = d x/d nu = (a cos phi cos nu, b sin phi cos nu, -c sin nu) never vanishes;
   * t_phi = d x/d phi = (-a sin phi sin nu, b cos phi sin nu, 0) vanishes at the
   * poles sin nu = 0, where the phi update is skipped (the paper is silent).
   */
  void step(const Ellipsoid& e, const Vec3& d, Scalar C) {
    const Vec3& s = e.semiAxes();
    const Vec3 db = e.rotation().transpose() * d;  // dot products are rotation invariant
    const Scalar dn = db.norm();
    const Scalar sn = std::sin(nu), cn = std::cos(nu), sp = std::sin(phi), cp = std::cos(phi);
    const Vec3 tNu(s.x() * cp * cn, s.y() * sp * cn, -s.z() * sn);
    const Vec3 tPhi(-s.x() * sp * sn, s.y() * cp * sn, 0);
    const Scalar newNu = nu + C * db.dot(tNu) / (dn * tNu.norm());
    if (std::abs(sn) > kEps) {
      phi += C * db.dot(tPhi) / (dn * tPhi.norm());
    }
    nu = newNu;
  }
};

}  // namespace

JainDistance::JainDistance(const Parameters& parameters) : parameters_(parameters) {
  if (!(parameters.cFactor > 0) || !std::isfinite(parameters.cFactor)) {
    std::ostringstream os;
    os.precision(17);
    os << "JainDistance: cFactor must be finite and > 0, got " << parameters.cFactor;
    throw std::invalid_argument(os.str());
  }
}

DistanceResult JainDistance::distance(const Ellipsoid& e1, const Ellipsoid& e2,
                                      const DistanceOptions& options) const {
  options.validate();
  const int maxIterations =
      options.maxIterations > 0 ? options.maxIterations : kDefaultMaxIterations;
  const Vec3& origin = e1.centre();
  // Translation invariance: everything below is relative to r1.
  const Ellipsoid f1 = relativeTo(e1, origin);
  const Ellipsoid f2 = relativeTo(e2, origin);

  DistanceResult res;
  Vec3 x1, x2;
  auto finish = [&](int iterations) {
    res.iterations = iterations;
    res.point1 = origin + x1;
    res.point2 = origin + x2;
    res.distance = res.status == DistanceStatus::overlapping ? 0 : (x2 - x1).norm();
    certifyFromPoints(e1, e2, res);
    return res;
  };

  // Alg. 6 lines 2-4 (2.6.3): Jia et al.'s exact test first; touching counts as overlap.
  if (JiaOverlapTest().test(f1, f2) != OverlapStatus::separated) {
    centreSegmentPoints(f1, f2, x1, x2);
    res.status = DistanceStatus::overlapping;
    return finish(0);
  }
  // Alg. 6 lines 5-6: the centre segment's points, then their coordinates (eq. 2.69).
  if (!centreSegmentPoints(f1, f2, x1, x2)) {
    res.status = DistanceStatus::failed;  // separated for the exact test, touching to rounding
    return finish(0);
  }
  SurfacePoint p1, p2;
  p1.fromPoint(f1, x1);
  p2.fromPoint(f2, x2);

  // C_m = cFactor D_eq,m / max(a_m, b_m, c_m) (eq. 2.71), D_eq,m = 2 (a b c)^(1/3).
  const Scalar C1 = parameters_.cFactor * 2 * e1.equivalentRadius() / e1.maxSemiAxis();
  const Scalar C2 = parameters_.cFactor * 2 * e2.equivalentRadius() / e2.maxSemiAxis();
  // constant eps_theta, eq. 2.9 (Alg. 6 line 7)
  const Scalar epsTheta = epsThetaGlobal(f1, f2, options.epsD);

  res.status = DistanceStatus::maxIterations;
  int k = 0;
  for (;; ++k) {
    const Vec3 y1 = p1.position(f1);  // eq. 2.68
    const Vec3 y2 = p2.position(f2);
    const Vec3 d = y2 - y1;  // d_1 = x2 - x1, d_2 = -d_1
    const Scalar dist = d.norm();
    if (!y1.allFinite() || !y2.allFinite() || !(dist > 0) || !std::isfinite(dist)) {
      res.status = DistanceStatus::failed;  // keep the last finite iterate
      break;
    }
    x1 = y1;
    x2 = y2;
    bool stop;
    if (options.stopRule == StopRule::certified) {
      // (in absolute coordinates: the reported bracket carries their rounding)
      stop = bracketWidthFromPoints(e1, e2, origin + x1, origin + x2) <= options.epsD;
    } else {
      // theta_m (eq. 2.3) against eps_theta, App. E
      stop =
          angleWithin(d, f1.gradient(x1), epsTheta) && angleWithin(-d, f2.gradient(x2), epsTheta);
    }
    if (stop) {
      res.status = DistanceStatus::converged;
      break;
    }
    if (k >= maxIterations) {
      res.status = DistanceStatus::maxIterations;
      break;
    }
    // Eq. 2.70, both points from the same (x1^k, x2^k).
    p1.step(f1, d, C1);
    p2.step(f2, -d, C2);
  }
  return finish(k);
}

}  // namespace ellipsoids
