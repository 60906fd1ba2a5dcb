#include "ellipsoids/NewtonCoulomb.hpp"

#include "ellipsoids/CertifiedBracket.hpp"
#include "ellipsoids/MovingBalls.hpp"
#include "ellipsoids/OverlapTest.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace ellipsoids {

namespace {

std::string describe(const NewtonCoulomb::Parameters& p) {
  std::ostringstream os;
  os.precision(17);
  os << "cMax = " << p.cMax << ", tau = " << p.tau << ", lambda = " << p.lambda
     << ", maxBacktracking = " << p.maxBacktracking;
  return os.str();
}

/// The copy of e translated by -origin (all computations are relative to r1).
Ellipsoid relativeTo(const Ellipsoid& e, const Vec3& origin) { return e.translatedBy(-origin); }

/**
 * First-order projection onto the surface (third and fourth lines of eq. 2.41,
 * line 1 of Alg. 3): x - grad f(x) f(x) / |grad f(x)|^2.
 */
Vec3 projectFirstOrder(const Ellipsoid& e, const Vec3& x) {
  const Vec3 g = e.gradient(x);
  return x - (e.levelSet(x) / g.squaredNorm()) * g;
}

/**
 * Unit direction of the "zeroing speed" acceleration xi_m of eq. 2.37:
 * xi_1 = (x2 - x1 + ((x1 - x2).g1 / |g1|^2) g1) / |x1 - x2|^3 is the part of
 * x2 - x1 tangent to the surface at x1, divided by |x1 - x2|^3. Only its
 * direction matters: with delta_m^2 = C_curv,m R_min,m / |xi_m| (eq. 2.40),
 * delta_m^2 xi_m = C_curv,m R_min,m xi_m / |xi_m| (eq. 2.41), so the factor
 * 1/|x1 - x2|^3 cancels; it is not formed (it would overflow for tiny gaps).
 * Returns zero when the tangential part vanishes (the point is already optimal
 * for the current other point: xi_m = 0 and the charge does not move).
 */
Vec3 tangentialDirection(const Vec3& towardOther, const Vec3& g) {
  const Scalar g2 = g.squaredNorm();
  const Vec3 t = towardOther - (towardOther.dot(g) / g2) * g;
  const Scalar n = t.norm();
  return n > 0 && std::isfinite(n) ? Vec3(t / n) : Vec3::Zero();
}

}  // namespace

NewtonCoulomb::NewtonCoulomb(const Parameters& parameters) : parameters_(parameters) {
  const Parameters& p = parameters;
  if (!(p.cMax > 0) || !std::isfinite(p.cMax)) {
    throw std::invalid_argument("NewtonCoulomb: cMax must be finite and > 0 (" + describe(p) + ")");
  }
  if (!(p.tau > 0) || !std::isfinite(p.tau)) {
    throw std::invalid_argument("NewtonCoulomb: tau must be finite and > 0 (" + describe(p) + ")");
  }
  if (!(p.lambda > 0) || !(p.lambda < 1)) {
    throw std::invalid_argument("NewtonCoulomb: lambda must be in (0, 1) (" + describe(p) + ")");
  }
  if (p.maxBacktracking < 1) {
    throw std::invalid_argument("NewtonCoulomb: maxBacktracking must be >= 1 (" + describe(p) +
                                ")");
  }
}

DistanceResult NewtonCoulomb::distance(const Ellipsoid& e1, const Ellipsoid& e2,
                                       const DistanceOptions& options) const {
  options.validate();
  const int maxIterations =
      options.maxIterations > 0 ? options.maxIterations : kDefaultMaxIterations;
  const Parameters& p = parameters_;
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

  // Alg. 4 lines 2-4 (2.3.5): Jia et al.'s exact test first; touching counts as overlap.
  if (JiaOverlapTest().test(f1, f2) != OverlapStatus::separated) {
    centreSegmentPoints(f1, f2, x1, x2);
    res.status = DistanceStatus::overlapping;
    return finish(0);
  }
  // Alg. 4 line 5: the centre segment's intersections with the surfaces.
  if (!centreSegmentPoints(f1, f2, x1, x2)) {
    // Separated for the exact test but the segment shows a common point: the
    // pair is touching to rounding. No iteration is possible (|x1 - x2| ~ 0);
    // the certified bracket of the segment points still holds.
    res.status = DistanceStatus::failed;
    return finish(0);
  }

  // Alg. 3 sets delta_m <- lambda delta_m: the displacement delta_m^2 xi_m shrinks by lambda^2.
  const Scalar lambda2 = p.lambda * p.lambda;
  Scalar epsTheta = epsThetaGlobal(f1, f2, options.epsD);  // eps_theta^0, eq. 2.9 (Alg. 4 line 6)

  res.status = DistanceStatus::maxIterations;
  int k = 0;
  for (;; ++k) {
    const Vec3 d = x2 - x1;
    const Scalar dist = d.norm();
    if (!x1.allFinite() || !x2.allFinite() || !(dist > 0) || !std::isfinite(dist)) {
      // cannot happen for separated bodies in exact arithmetic
      res.status = DistanceStatus::failed;
      break;
    }
    const CurvatureRadii c1 = f1.curvatureRadii(x1);  // App. B at the (radially projected) points
    const CurvatureRadii c2 = f2.curvatureRadii(x2);
    if (!std::isfinite(c1.rMin) || !std::isfinite(c2.rMin) || !(c1.rMin > 0) || !(c2.rMin > 0)) {
      res.status = DistanceStatus::failed;
      break;
    }
    const Vec3 g1 = f1.gradient(x1);
    const Vec3 g2 = f2.gradient(x2);

    // Stopping test (Alg. 4 line 8).
    bool stop;
    if (options.stopRule == StopRule::certified) {
      // (in absolute coordinates: the reported bracket carries their rounding)
      stop = bracketWidthFromPoints(e1, e2, origin + x1, origin + x2) <= options.epsD;
    } else {
      if (k > 0) {
        // eps_theta^k from the local curvature, eq. F.6 (Alg. 4 line 11)
        epsTheta = std::sqrt(2 * options.epsD / (c1.rMax + c2.rMax));
      }
      // theta_1 = angle(x2 - x1, grad f1(x1)), theta_2 = angle(x1 - x2, grad f2(x2))
      // (eq. 2.3), tested as in App. E
      stop = angleWithin(d, g1, epsTheta) && angleWithin(-d, g2, epsTheta);
    }
    if (stop) {
      res.status = DistanceStatus::converged;
      break;
    }
    if (k >= maxIterations) {
      res.status = DistanceStatus::maxIterations;
      break;
    }

    // Adaptive C_curv,m (eq. 2.45) and the displacement amplitude
    // (delta_m)^2 |xi_m| = C_curv,m R_min,m (eq. 2.40).
    const Scalar cCurv1 = std::min(p.cMax, p.tau * std::sqrt(2 * dist / c1.rMin));
    const Scalar cCurv2 = std::min(p.cMax, p.tau * std::sqrt(2 * dist / c2.rMin));
    const Vec3 u1 = tangentialDirection(d, g1);   // xi_1 / |xi_1|, eq. 2.37
    const Vec3 u2 = tangentialDirection(-d, g2);  // xi_2 / |xi_2|
    const Scalar step1 = cCurv1 * c1.rMin;
    const Scalar step2 = cCurv2 * c2.rMin;

    // Eq. 2.41 with the backtracking loop of Alg. 3: accept the first trial
    // that decreases |x1 - x2|; each rejection sets delta_m <- lambda delta_m.
    Scalar scale = 1;
    bool accepted = false;
    Vec3 z1, z2;
    for (int j = 0; j <= p.maxBacktracking; ++j) {
      z1 = projectFirstOrder(f1, x1 + (scale * step1) * u1);
      z2 = projectFirstOrder(f2, x2 + (scale * step2) * u2);
      const Scalar trial = (z1 - z2).norm();
      if (!std::isfinite(trial)) {
        break;
      }
      if (trial < dist) {
        accepted = true;
        break;
      }
      scale *= lambda2;
    }
    if (!accepted) {
      res.status = DistanceStatus::failed;  // backtracking exhausted (or non-finite trial)
      break;
    }
    x1 = z1;
    x2 = z2;
  }
  return finish(k);
}

}  // namespace ellipsoids
