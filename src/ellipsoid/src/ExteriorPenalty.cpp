#include "ellipsoids/ExteriorPenalty.hpp"

#include "ellipsoids/CertifiedBracket.hpp"
#include "ellipsoids/MovingBalls.hpp"
#include "ellipsoids/OverlapTest.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace ellipsoids {

namespace {

std::string describe(const ExteriorPenalty::Parameters& p) {
  std::ostringstream os;
  os.precision(17);
  os << "lambdaRelative = " << p.lambdaRelative << ", epsGRelative = " << p.epsGRelative;
  return os.str();
}

/// The copy of e translated by -origin (all computations are relative to r1).
Ellipsoid relativeTo(const Ellipsoid& e, const Vec3& origin) { return e.translatedBy(-origin); }

/// s_m(beta) consistent with the sign of h: h = 0 (the kink) agrees with both signs.
bool signAgrees(Scalar h, int s) { return h == 0 || (h > 0) == (s > 0); }

/// Smallest positive root beta of h(x - beta G) = 0 (eq. 2.66, App. D), or -1 if none.
Scalar smallestPositiveRoot(const Ellipsoid& e, const Vec3& x, const Vec3& G) {
  const LineIntersection li = e.intersectLine(x, -G);
  if (li.count == 0) {
    return -1;
  }
  if (li.tEnter > 0) {
    return li.tEnter;
  }
  if (li.tExit > 0) {
    return li.tExit;
  }
  return -1;
}

}  // namespace

ExteriorPenalty::ExteriorPenalty(const Parameters& parameters) : parameters_(parameters) {
  const Parameters& p = parameters;
  if (!(p.lambdaRelative > 0) || !std::isfinite(p.lambdaRelative)) {
    throw std::invalid_argument("ExteriorPenalty: lambdaRelative must be finite and > 0 (" +
                                describe(p) + ")");
  }
  if (!(p.epsGRelative > 0) || !std::isfinite(p.epsGRelative)) {
    throw std::invalid_argument("ExteriorPenalty: epsGRelative must be finite and > 0 (" +
                                describe(p) + ")");
  }
}

DistanceResult ExteriorPenalty::distance(const Ellipsoid& e1, const Ellipsoid& e2,
                                         const DistanceOptions& options) const {
  options.validate();  // epsD is validated but not used: the accuracy is set by eps_G
  const int maxIterations =
      options.maxIterations > 0 ? options.maxIterations : kDefaultMaxIterations;
  const Vec3& origin = e1.centre();
  // Translation invariance: everything below is relative to r1, where
  // h_m(x) = 1/2 x^T A_m x + b_m^T x + alpha_m = f_m(x) (App. A) and
  // h'_m(x) = A_m x + b_m = grad f_m(x).
  const Ellipsoid f1 = relativeTo(e1, origin);
  const Ellipsoid f2 = relativeTo(e2, origin);
  const Mat3& A1 = f1.quadraticMatrix();
  const Mat3& A2 = f2.quadraticMatrix();

  // Parameters scaled with the pair (3.4.4): lambda ~ length^2, eps_G ~ length.
  const Scalar D = 2 * std::min(e1.equivalentRadius(), e2.equivalentRadius());
  const Scalar lambda = parameters_.lambdaRelative * D * D;
  const Scalar epsG = parameters_.epsGRelative * D;

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

  // Alg. 5 lines 2-4 (2.4.5): Jia et al.'s exact test first; touching counts as overlap.
  if (JiaOverlapTest().test(f1, f2) != OverlapStatus::separated) {
    centreSegmentPoints(f1, f2, x1, x2);
    res.status = DistanceStatus::overlapping;
    return finish(0);
  }
  // Alg. 5 lines 5-6: z^0 from the centre segment.
  if (!centreSegmentPoints(f1, f2, x1, x2)) {
    res.status = DistanceStatus::failed;  // separated for the exact test, touching to rounding
    return finish(0);
  }

  res.status = DistanceStatus::maxIterations;
  int k = 0;
  for (;; ++k) {
    if (!x1.allFinite() || !x2.allFinite()) {
      res.status = DistanceStatus::failed;
      break;
    }
    // Eq. 2.54 at z^k.
    const Scalar h1 = f1.levelSet(x1);
    const Scalar h2 = f2.levelSet(x2);
    const Vec3 g1 = f1.gradient(x1);                 // h'_1 (its first three components)
    const Vec3 g2 = f2.gradient(x2);                 // h'_2 (its last three components)
    const Vec3 q = x1 - x2;                          // Q = (q, -q)
    const Scalar phi = std::abs(h1) + std::abs(h2);  // eq. 2.50

    // (mu1*, mu2*) from the 2x2 system 2.58 (h'_1 . h'_2 = 0, h'_1 . Q = g1.q,
    // h'_2 . Q = -g2.q). Its determinant |g1|^2 h2^2 + h1^2 |g2|^2 + |g1|^2 |g2|^2
    // vanishes only at a centre. The box |mu_m| <= lambda of eq. 2.56 is not
    // imposed: the paper solves the unconstrained system and relies on a large lambda.
    const Scalar m11 = h1 * h1 + g1.squaredNorm();
    const Scalar m22 = h2 * h2 + g2.squaredNorm();
    const Scalar m12 = h1 * h2;
    const Scalar rhs1 = lambda * phi * h1 - g1.dot(q);
    const Scalar rhs2 = lambda * phi * h2 + g2.dot(q);
    const Scalar det = m11 * m22 - m12 * m12;
    if (!(det > 0) || !std::isfinite(det)) {
      res.status = DistanceStatus::failed;  // singular system
      break;
    }
    const Scalar mu1 = (rhs1 * m22 - m12 * rhs2) / det;
    const Scalar mu2 = (m11 * rhs2 - m12 * rhs1) / det;
    // Hypogradient G* (eq. 2.60).
    const Vec3 G1 = mu1 * g1 + q;
    const Vec3 G2 = mu2 * g2 - q;
    const Scalar normG = std::sqrt(G1.squaredNorm() + G2.squaredNorm());
    if (!std::isfinite(normG)) {
      res.status = DistanceStatus::failed;
      break;
    }
    if (normG < epsG) {  // eq. 2.67
      res.status = DistanceStatus::converged;
      break;
    }
    if (k >= maxIterations) {
      res.status = DistanceStatus::maxIterations;
      break;
    }

    // Line search (2.4.3): Gamma(beta) = Phi_lambda(z^k - beta G*) (eq. 2.62).
    const Vec3 dG = G1 - G2;
    auto gamma = [&](Scalar beta) {
      const Vec3 y1 = x1 - beta * G1;
      const Vec3 y2 = x2 - beta * G2;
      return Scalar(0.5) * (y1 - y2).squaredNorm() +
             lambda * (std::abs(f1.levelSet(y1)) + std::abs(f2.levelSet(y2)));
    };
    // Eq. 2.65 for each sign pattern (s1, s2); the terms G^T A x + G^T b of the
    // paper are G . h'(x) = G . g here.
    const Scalar p1 = G1.dot(g1), p2 = G2.dot(g2);
    const Scalar c1 = G1.dot(A1 * G1), c2 = G2.dot(A2 * G2);
    const Scalar num0 = dG.dot(q), den0 = dG.squaredNorm();
    Scalar beta = -1;
    Scalar bestGamma = std::numeric_limits<Scalar>::infinity();
    for (int s1 = -1; s1 <= 1; s1 += 2) {
      for (int s2 = -1; s2 <= 1; s2 += 2) {
        const Scalar num = num0 + lambda * (s1 * p1 + s2 * p2);
        const Scalar den = den0 + lambda * (s1 * c1 + s2 * c2);
        const Scalar b = num / den;
        if (!(b >= 0) || !std::isfinite(b)) {
          continue;
        }
        // keep beta only if s_m(beta) = sign h_m(x_m - beta G_m) (eq. 2.64)
        if (!signAgrees(f1.levelSet(x1 - b * G1), s1) ||
            !signAgrees(f2.levelSet(x2 - b * G2), s2)) {
          continue;
        }
        const Scalar gb = gamma(b);
        if (gb < bestGamma) {
          bestGamma = gb;
          beta = b;
        }
      }
    }
    if (beta < 0) {
      // No consistent root: the minimum is at a kink of Gamma, h_m(x_m - beta_m G_m) = 0
      // (eq. 2.66): the smallest positive ray parameters, keeping the one minimising Gamma.
      const Scalar candidates[2] = {smallestPositiveRoot(f1, x1, G1),
                                    smallestPositiveRoot(f2, x2, G2)};
      for (const Scalar b : candidates) {
        if (!(b > 0) || !std::isfinite(b)) {
          continue;
        }
        const Scalar gb = gamma(b);
        if (gb < bestGamma) {
          bestGamma = gb;
          beta = b;
        }
      }
    }
    const Vec3 y1 = x1 - beta * G1;
    const Vec3 y2 = x2 - beta * G2;
    if (!(beta > 0) || !std::isfinite(bestGamma) || !y1.allFinite() || !y2.allFinite() ||
        (y1 == x1 && y2 == x2)) {
      res.status = DistanceStatus::failed;  // no admissible beta, or a step that does not move
      break;
    }
    x1 = y1;  // z^{k+1} = z^k - beta^k G*(z^k) (Alg. 5 line 15)
    x2 = y2;
  }
  return finish(k);
}

}  // namespace ellipsoids
