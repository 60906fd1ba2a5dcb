#include "ellipsoids/DualNewton.hpp"

#include "ellipsoids/CertifiedBracket.hpp"
#include "ellipsoids/OverlapTest.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace ellipsoids {

namespace {

/// Everything the iteration needs at one direction n (coordinates relative to r1).
struct DualPoint {
  Vec3 n;
  Vec3 y1, y2;      // P1 n, P2 n
  Scalar s1, s2;    // sqrt(n^T P_m n)
  Vec3 x1, x2;      // support points relative to r1
  Vec3 v;           // x2 - x1 = gradient of L
  Scalar L;         // v . n

  void evaluate(const Mat3& P1, const Mat3& P2, const Vec3& dr, const Vec3& unitN) {
    n = unitN;
    y1 = P1 * n;
    y2 = P2 * n;
    s1 = std::sqrt(n.dot(y1));
    s2 = std::sqrt(n.dot(y2));
    x1 = y1 / s1;
    x2 = dr - y2 / s2;
    v = x2 - x1;
    L = n.dot(dr) - s1 - s2;
  }

  /// Tangential part of the gradient (zero at the optimum).
  Scalar tangentialGradient() const { return (v - v.dot(n) * n).norm(); }

  /// |v| - v.n without cancellation: |v_t|^2 / (|v| + v.n), v_t tangential part of v.
  Scalar gap() const {
    const Scalar vn = v.dot(n);
    const Scalar vnorm = v.norm();
    const Scalar vt2 = std::max((v - vn * n).squaredNorm(), Scalar(0));
    const Scalar denominator = vnorm + vn;
    return denominator > 0 ? vt2 / denominator : vnorm - vn;
  }
};

/// Orthonormal basis (t1, t2) of the plane normal to the unit n.
void tangentBasis(const Vec3& n, Vec3& t1, Vec3& t2) {
  // the axis least aligned with n
  int k = 0;
  if (std::abs(n[1]) < std::abs(n[k])) k = 1;
  if (std::abs(n[2]) < std::abs(n[k])) k = 2;
  Vec3 e = Vec3::Zero();
  e[k] = 1;
  t1 = (e - n[k] * n).normalized();
  t2 = n.cross(t1);
}

/// t_i^T Q t_j with Q = (P - y y^T / s^2) / s, y = P n.
Eigen::Matrix<Scalar, 2, 2> curvatureTensor(const Mat3& P, const Vec3& y, Scalar s, const Vec3& t1,
                                            const Vec3& t2) {
  const Vec3 Pt1 = P * t1;
  const Vec3 Pt2 = P * t2;
  const Scalar yt1 = y.dot(t1), yt2 = y.dot(t2);
  const Scalar s2 = s * s;
  Eigen::Matrix<Scalar, 2, 2> q;
  q(0, 0) = (t1.dot(Pt1) - yt1 * yt1 / s2) / s;
  q(1, 1) = (t2.dot(Pt2) - yt2 * yt2 / s2) / s;
  q(0, 1) = q(1, 0) = (t1.dot(Pt2) - yt1 * yt2 / s2) / s;
  return q;
}

}  // namespace

DistanceResult DualNewton::distance(const Ellipsoid& e1, const Ellipsoid& e2,
                                    const DistanceOptions& options) const {
  options.validate();
  const int maxIterations = options.maxIterations > 0 ? options.maxIterations : kDefaultMaxIterations;
  const Mat3& P1 = e1.shapeMatrix();
  const Mat3& P2 = e2.shapeMatrix();
  const Vec3 dr = e2.centre() - e1.centre();
  const Scalar allow = roundingAllowance(e1, e2);
  const Scalar size = e1.maxSemiAxis() + e2.maxSemiAxis();
  // rounding of L = n.dr - s1 - s2
  const Scalar roundingL = 4 * kEps * (dr.norm() + e1.maxSemiAxis() + e2.maxSemiAxis());

  Vec3 n0;
  if (options.useInitialDirection) {
    n0 = options.initialDirection.normalized();
  } else if (dr.norm() > 0) {
    n0 = dr.normalized();
  } else {
    n0 = e1.rotation().col(0);  // concentric: any direction
  }

  DualPoint cur, trial;
  cur.evaluate(P1, P2, dr, n0);

  DistanceResult res;
  res.status = DistanceStatus::maxIterations;
  int it = 0;
  for (; it < maxIterations; ++it) {
    // certified stop for separated bodies
    if (cur.L > 0 && cur.gap() + 2 * allow <= options.epsD) {
      res.status = DistanceStatus::converged;
      break;
    }
    Vec3 t1, t2;
    tangentBasis(cur.n, t1, t2);
    const Eigen::Matrix<Scalar, 2, 1> G(t1.dot(cur.v), t2.dot(cur.v));
    Eigen::Matrix<Scalar, 2, 2> H =
        curvatureTensor(P1, cur.y1, cur.s1, t1, t2) + curvatureTensor(P2, cur.y2, cur.s2, t1, t2);
    H(0, 0) += cur.L;
    H(1, 1) += cur.L;
    // positive definite? otherwise shift (overlap region, or far from the optimum)
    const Scalar tr = H.trace();
    const Scalar det = H.determinant();
    const Scalar lambdaMin = Scalar(0.5) * (tr - std::sqrt(std::max(tr * tr - 4 * det, Scalar(0))));
    const Scalar scaleH = std::abs(H(0, 0)) + std::abs(H(1, 1)) + std::abs(H(0, 1)) + size * kEps;
    if (lambdaMin < 0 && G.norm() <= 64 * roundingL) {
      // a saddle of L (e.g. a symmetric start): leave along the direction of
      // negative curvature of H, where L increases
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix<Scalar, 2, 2>> es(H);
      const Vec3 escape = es.eigenvectors()(0, 0) * t1 + es.eigenvectors()(1, 0) * t2;
      bool moved = false;
      for (Scalar t = 1; t > 1e-6 && !moved; t *= Scalar(0.5)) {
        for (Scalar sign : {1.0, -1.0}) {
          trial.evaluate(P1, P2, dr, (cur.n + sign * t * escape).normalized());
          if (trial.L > cur.L + 2 * roundingL) {
            moved = true;
            break;
          }
        }
      }
      if (moved) {
        cur = trial;
        continue;
      }
    }
    if (lambdaMin <= Scalar(1e-3) * scaleH) {
      const Scalar shift = Scalar(1e-3) * scaleH - lambdaMin;
      H(0, 0) += shift;
      H(1, 1) += shift;
    }
    Eigen::Matrix<Scalar, 2, 1> step = H.llt().solve(G);
    if (!step.allFinite()) {
      res.status = DistanceStatus::failed;
      break;
    }
    // at most a quarter turn per step
    const Scalar stepNorm = step.norm();
    if (stepNorm > 1) step /= stepNorm;
    const Scalar predicted = G.dot(step);  // first-order increase of L for the full step
    if (!(predicted > 0)) {
      // stationary: the maximum of L (to rounding)
      res.status = cur.L > 0 ? (cur.gap() + 2 * allow <= options.epsD ? DistanceStatus::converged
                                                                     : DistanceStatus::failed)
                             : DistanceStatus::overlapping;
      break;
    }
    // overlap: stop when the predicted increase is below the tolerance and
    // cannot make L positive (near touching, keep iterating: the sign matters)
    if (cur.L <= 0 && predicted <= Scalar(0.1) * options.epsD && cur.L + predicted < 0) {
      res.status = DistanceStatus::overlapping;
      break;
    }
    // Backtracking line search on L along the retraction. Near the optimum L
    // is flat (second order in the angle) and its increase drops below its own
    // rounding while the bracket still needs a smaller angle (at small gaps,
    // |x2 - x1| - L ~ (R angle)^2 / gap): there the merit is the tangential
    // gradient |v_t|, which Newton's step reduces quadratically.
    const bool belowRounding = predicted <= 64 * roundingL;
    const Scalar gradNorm = cur.tangentialGradient();
    Scalar t = 1;
    bool accepted = false;
    for (int ls = 0; ls < 40; ++ls) {
      const Vec3 m = cur.n + t * (step[0] * t1 + step[1] * t2);
      trial.evaluate(P1, P2, dr, m.normalized());
      if (trial.L >= cur.L + Scalar(1e-4) * t * predicted ||
          (belowRounding && trial.L >= cur.L - 2 * roundingL &&
           trial.tangentialGradient() < gradNorm)) {
        accepted = true;
        break;
      }
      t *= Scalar(0.5);
    }
    if (!accepted) {
      // no further increase representable: at the maximum up to rounding
      res.status = cur.L > 0 ? (cur.gap() + 2 * allow <= options.epsD ? DistanceStatus::converged
                                                                     : DistanceStatus::failed)
                             : DistanceStatus::overlapping;
      break;
    }
    cur = trial;
  }
  res.iterations = it;
  res.point1 = e1.centre() + cur.x1;
  res.point2 = e1.centre() + cur.x2;
  res.direction = cur.n;

  if (res.status == DistanceStatus::overlapping ||
      (res.status != DistanceStatus::converged && cur.L <= 0)) {
    // certify the overlap with a common point, else ask the exact algebraic test
    const bool common = e1.levelSet(res.point2) <= 0 || e2.levelSet(res.point1) <= 0 ||
                        e1.levelSet(e2.centre()) <= 0 || e2.levelSet(e1.centre()) <= 0;
    res.distance = cur.L;
    res.lower = cur.L - allow;
    if (common) {
      res.upper = 0;
    } else if (JiaOverlapTest().test(e1, e2) != OverlapStatus::separated) {
      res.upper = allow;  // touching or overlapping by the exact test
    } else {
      res.status = DistanceStatus::failed;  // a spurious local maximum of L
      res.upper = (res.point2 - res.point1).norm() + allow;
    }
    if (res.status == DistanceStatus::overlapping && res.upper < res.lower) res.upper = res.lower;
    return res;
  }
  res.distance = cur.v.norm();
  res.lower = cur.L - allow;
  res.upper = res.distance + allow + 4 * kEps * (res.point1.norm() + res.point2.norm());
  return res;
}

}  // namespace ellipsoids
