#include "ellipsoids/DualNewton.hpp"

#include "ellipsoids/CertifiedBracket.hpp"
#include "ellipsoids/OverlapTest.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <utility>

namespace ellipsoids {

namespace {

/// A 3-vector of plain doubles: the hot loop stays free of expression templates.
struct V3 {
  Scalar x, y, z;
  V3() = default;
  V3(Scalar a, Scalar b, Scalar c) : x(a), y(b), z(c) {}
  explicit V3(const Vec3& v) : x(v[0]), y(v[1]), z(v[2]) {}
  Vec3 eigen() const { return Vec3(x, y, z); }
  Scalar operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};
inline V3 operator+(const V3& a, const V3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator-(const V3& a, const V3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3 operator*(const V3& a, Scalar s) { return {a.x * s, a.y * s, a.z * s}; }
inline Scalar dot(const V3& a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/// The six entries of a symmetric 3x3 matrix.
struct Sym3 {
  Scalar xx, xy, xz, yy, yz, zz;
  explicit Sym3(const Mat3& m)
      : xx(m(0, 0)), xy(m(0, 1)), xz(m(0, 2)), yy(m(1, 1)), yz(m(1, 2)), zz(m(2, 2)) {}
  V3 operator*(const V3& n) const {
    return {xx * n.x + xy * n.y + xz * n.z, xy * n.x + yy * n.y + yz * n.z,
            xz * n.x + yz * n.y + zz * n.z};
  }
  Vec3 operator*(const Vec3& n) const { return ((*this) * V3(n)).eigen(); }
};

/// Everything the iteration needs at one direction n (coordinates relative to r1).
struct DualPoint {
  V3 n;
  V3 y1, y2;          // P1 n, P2 n
  Scalar inv1, inv2;  // 1/s_m, s_m = sqrt(n^T P_m n): support radii
  Scalar sumS;        // s1 + s2
  V3 v;               // x2 - x1 = gradient of L, x1 = y1/s1, x2 = dr - y2/s2
  Scalar L;           // n.dr - s1 - s2 = v.n

  void evaluate(const Sym3& P1, const Sym3& P2, const V3& dr, const V3& unitN) {
    n = unitN;
    y1 = P1 * n;
    y2 = P2 * n;
    const Scalar q1 = dot(n, y1), q2 = dot(n, y2);
    inv1 = 1 / std::sqrt(q1);
    inv2 = 1 / std::sqrt(q2);
    v = dr - y2 * inv2 - y1 * inv1;
    sumS = q1 * inv1 + q2 * inv2;
    L = dot(n, dr) - sumS;
  }
  void evaluate(const Sym3& P1, const Sym3& P2, const V3& dr, const Vec3& unitN) {
    evaluate(P1, P2, dr, V3(unitN));
  }

  Vec3 x1() const { return (y1 * inv1).eigen(); }
  Vec3 x2(const V3& dr) const { return (dr - y2 * inv2).eigen(); }

  /// Tangential part of the gradient (zero at the optimum).
  V3 tangential() const { return v - n * dot(v, n); }

  /// |v| - v.n without cancellation: |v_t|^2 / (|v| + v.n).
  Scalar gap() const {
    const Scalar vn = dot(v, n);
    const V3 t = tangential();
    const Scalar vnorm = std::sqrt(dot(v, v));
    const Scalar denominator = vnorm + vn;
    return denominator > 0 ? dot(t, t) / denominator : vnorm - vn;
  }
};

/// Unit vector along a + b.
inline V3 normalizedSum(const V3& a, const V3& b) {
  const V3 m = a + b;
  return m * (1 / std::sqrt(dot(m, m)));
}

/**
 * Newton step: solves (Q1 + Q2 + Lm T) dn = v_t on the tangent plane of n
 * (Lm = L: Newton's step; Lm = 0 where L < 0 makes the tangent Hessian
 * indefinite far from the maximum: still an ascent direction),
 * T = I - n n^T, with the 3x3 curvature tensors Q_m = (P_m - y_m y_m^T / s_m^2) / s_m
 * (their null direction is n). The 3x3 matrix Q1 + Q2 + L I + (c - L) n n^T
 * (c = s1 + s2 > 0) equals it on the tangent plane and c along n, so its
 * solution is tangent (n.dn = 0) and no tangent basis is needed. Solved with
 * the adjugate (one division, a short dependency chain). Returns false unless
 * the matrix is positive definite (always near the maximum of separated
 * bodies: Q_m >= 0 and L > 0); the general path then takes over.
 */
bool newtonStep(const Sym3& P1, const Sym3& P2, const DualPoint& p, const V3& vt, Scalar Lm,
                V3& dnTimesDet, Scalar& det) {
  const Scalar i1 = p.inv1, i2 = p.inv2;
  const Scalar w1 = i1 * i1 * i1, w2 = i2 * i2 * i2;  // 1/s_m^3
  const Scalar y10 = p.y1.x, y11 = p.y1.y, y12 = p.y1.z;
  const Scalar y20 = p.y2.x, y21 = p.y2.y, y22 = p.y2.z;
  const Scalar n0 = p.n.x, n1 = p.n.y, n2 = p.n.z;
  const Scalar c = p.sumS - Lm;  // the matrix is s1 + s2 along n
  const Scalar a00 = P1.xx * i1 + P2.xx * i2 - y10 * y10 * w1 - y20 * y20 * w2 + Lm + c * n0 * n0;
  const Scalar a01 = P1.xy * i1 + P2.xy * i2 - y10 * y11 * w1 - y20 * y21 * w2 + c * n0 * n1;
  const Scalar a02 = P1.xz * i1 + P2.xz * i2 - y10 * y12 * w1 - y20 * y22 * w2 + c * n0 * n2;
  const Scalar a11 = P1.yy * i1 + P2.yy * i2 - y11 * y11 * w1 - y21 * y21 * w2 + Lm + c * n1 * n1;
  const Scalar a12 = P1.yz * i1 + P2.yz * i2 - y11 * y12 * w1 - y21 * y22 * w2 + c * n1 * n2;
  const Scalar a22 = P1.zz * i1 + P2.zz * i2 - y12 * y12 * w1 - y22 * y22 * w2 + Lm + c * n2 * n2;
  const Scalar c00 = a11 * a22 - a12 * a12;
  const Scalar c01 = a02 * a12 - a01 * a22;
  const Scalar c02 = a01 * a12 - a02 * a11;
  const Scalar c11 = a00 * a22 - a02 * a02;
  const Scalar c12 = a01 * a02 - a00 * a12;
  const Scalar c22 = a00 * a11 - a01 * a01;
  det = a00 * c00 + a01 * c01 + a02 * c02;
  // Sylvester: positive definite iff the leading minors are positive
  if (!(a00 > 0) || !(c22 > 0) || !(det > 0)) return false;
  // the step times det: the division is left to the caller, who can fold it
  // into the normalisation of n + dn
  const Scalar v0 = vt.x, v1 = vt.y, v2 = vt.z;
  dnTimesDet.x = c00 * v0 + c01 * v1 + c02 * v2;
  dnTimesDet.y = c01 * v0 + c11 * v1 + c12 * v2;
  dnTimesDet.z = c02 * v0 + c12 * v1 + c22 * v2;
  return std::isfinite(dnTimesDet.x + dnTimesDet.y + dnTimesDet.z + det);
}

/// Orthonormal basis (t1, t2) of the plane normal to the unit n.
void tangentBasis(const Vec3& n, Vec3& t1, Vec3& t2) {
  int k = 0;  // the axis least aligned with n
  if (std::abs(n[1]) < std::abs(n[k])) k = 1;
  if (std::abs(n[2]) < std::abs(n[k])) k = 2;
  Vec3 e = Vec3::Zero();
  e[k] = 1;
  t1 = (e - n[k] * n).normalized();
  t2 = n.cross(t1);
}

/// t_i^T Q_m t_j of one body (general path).
Eigen::Matrix<Scalar, 2, 2> curvatureTensor(const Sym3& P, const V3& yv, Scalar inv,
                                            const Vec3& t1, const Vec3& t2) {
  const Vec3 Pt1 = P * t1;
  const Vec3 Pt2 = P * t2;
  const Vec3 y = yv.eigen();
  const Scalar yt1 = y.dot(t1), yt2 = y.dot(t2);
  const Scalar inv2 = inv * inv;
  Eigen::Matrix<Scalar, 2, 2> q;
  q(0, 0) = (t1.dot(Pt1) - yt1 * yt1 * inv2) * inv;
  q(1, 1) = (t2.dot(Pt2) - yt2 * yt2 * inv2) * inv;
  q(0, 1) = q(1, 0) = (t1.dot(Pt2) - yt1 * yt2 * inv2) * inv;
  return q;
}

}  // namespace

DistanceResult DualNewton::distance(const Ellipsoid& e1, const Ellipsoid& e2,
                                    const DistanceOptions& options) const {
  options.validate();
  const int maxIterations = options.maxIterations > 0 ? options.maxIterations : kDefaultMaxIterations;
  const Sym3 P1(e1.shapeMatrix());
  const Sym3 P2(e2.shapeMatrix());
  const Vec3 drE = e2.centre() - e1.centre();
  const V3 dr(drE);
  const Scalar drNorm = drE.norm();
  const Scalar size = e1.maxSemiAxis() + e2.maxSemiAxis();
  const Scalar allow = 32 * kEps * (drNorm + size);  // = roundingAllowance(e1, e2)
  const Scalar roundingL = 4 * kEps * (drNorm + size);  // rounding of L = n.dr - s1 - s2
  const Scalar epsStop = options.epsD - 2 * allow;

  Vec3 n0;
  if (options.useInitialDirection) {
    n0 = options.initialDirection.normalized();
  } else if (drNorm > 0) {
    n0 = drE / drNorm;
  } else {
    n0 = e1.rotation().col(0);  // concentric: any direction
  }

  DualPoint points[2];
  DualPoint* cur = &points[0];    // the iterate
  DualPoint* trial = &points[1];  // the candidate; accepted by swapping the pointers
  cur->evaluate(P1, P2, dr, n0);
  if (!options.useInitialDirection && drNorm > 0) {
    // a second candidate start: the outward normal of E1 minus that of E2 where
    // the centre segment crosses their surfaces (fewer iterations for bodies
    // that are not far from spheres; measured in docs/benchmarks.md)
    const Vec3 m = (e1.quadraticMatrix() * drE).normalized() + (e2.quadraticMatrix() * drE).normalized();
    const Scalar m2 = m.squaredNorm();
    if (m2 > 0) {
      trial->evaluate(P1, P2, dr, Vec3(m / std::sqrt(m2)));
      if (trial->L > cur->L) std::swap(cur, trial);
    }
  }

  DistanceResult res;
  res.status = DistanceStatus::maxIterations;
  int it = 0;
  for (; it < maxIterations; ++it) {
    const Scalar vn = dot(cur->v, cur->n);  // = L up to rounding
    const V3 vt = cur->v - cur->n * vn;
    const Scalar vt2 = dot(vt, vt);
    // Certified stop for separated bodies: |v| - v.n = |v_t|^2 / (|v| + v.n)
    // <= |v_t|^2 / (2 v.n), tested without a square root
    if (cur->L > 0 && vn > 0 && vt2 <= 2 * vn * epsStop) {
      res.status = DistanceStatus::converged;
      break;
    }

    // Fast path: where Q1 + Q2 + L I is positive definite (always near the
    // maximum of separated bodies), the full Newton step, accepted if L
    // increases as predicted or, below the rounding of L, if the tangential
    // gradient decreases (near the optimum L is flat, second order in the
    // angle, while the bracket still needs a smaller angle at small gaps:
    // |x2 - x1| - L ~ (R angle)^2 / gap)
    V3 raw;  // the Newton step times det
    Scalar det;
    const bool atMaximum = newtonStep(P1, P2, *cur, vt, cur->L, raw, det);  // Hessian negative definite
    // From a poor start (the first two iterations), with L < 0, the curvature
    // term max(L, 0) still gives an ascent direction: fewer iterations for
    // elongated bodies than the shifted general path (measured 5-10 %). Not
    // later: at the maximum of an overlap L < 0 is the answer, and ignoring it
    // would slow Newton down to a crawl
    if (atMaximum || (it < 2 && cur->L < 0 && newtonStep(P1, P2, *cur, vt, 0, raw, det))) {
      // n_new = (n + raw/det)/|n + raw/det| = (det n + raw)/|det n + raw|, at most
      // a quarter turn per step (|raw| <= det). The norm is computed, not taken
      // as sqrt(det^2 + |raw|^2): raw is tangent only to rounding, and |n| - 1
      // would grow from one iteration to the next
      const Scalar raw2 = dot(raw, raw), det2 = det * det;
      const Scalar scale = raw2 <= det2 ? det : std::sqrt(raw2);
      const V3 nNew = normalizedSum(cur->n * scale, raw);
      const Scalar predicted = dot(vt, raw) / scale;
      if (atMaximum && cur->L <= 0 && predicted <= Scalar(0.1) * options.epsD && cur->L + predicted < 0) {
        res.status = DistanceStatus::overlapping;  // the overlap's maximum, to the tolerance
        break;
      }
      if (predicted > 0) {
        trial->evaluate(P1, P2, dr, nNew);
        const V3 tt = trial->tangential();
        if (trial->L >= cur->L + Scalar(1e-4) * predicted ||
            (predicted <= 64 * roundingL && trial->L >= cur->L - 2 * roundingL &&
             dot(tt, tt) < vt2)) {
          std::swap(cur, trial);
          continue;
        }
      }
    }

    // General path: 2x2 system on a tangent basis, shifted to be positive
    // definite, saddle escape, backtracking line search
    if (cur->L > 0 && cur->gap() + 2 * allow <= options.epsD) {
      res.status = DistanceStatus::converged;
      break;
    }
    const Vec3 curN = cur->n.eigen(), curV = cur->v.eigen();
    Vec3 t1, t2;
    tangentBasis(curN, t1, t2);
    const Eigen::Matrix<Scalar, 2, 1> G(t1.dot(curV), t2.dot(curV));
    Eigen::Matrix<Scalar, 2, 2> H = curvatureTensor(P1, cur->y1, cur->inv1, t1, t2) +
                                    curvatureTensor(P2, cur->y2, cur->inv2, t1, t2);
    H(0, 0) += cur->L;
    H(1, 1) += cur->L;
    const Scalar tr = H.trace();
    const Scalar detH = H.determinant();
    const Scalar lambdaMin = Scalar(0.5) * (tr - std::sqrt(std::max(tr * tr - 4 * detH, Scalar(0))));
    const Scalar scaleH = std::abs(H(0, 0)) + std::abs(H(1, 1)) + std::abs(H(0, 1)) + size * kEps;
    if (lambdaMin < 0 && G.norm() <= 64 * roundingL) {
      // a saddle of L (e.g. a symmetric start): leave along the direction of
      // negative curvature of H, where L increases
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix<Scalar, 2, 2>> es(H);
      const Vec3 escape = es.eigenvectors()(0, 0) * t1 + es.eigenvectors()(1, 0) * t2;
      bool moved = false;
      for (Scalar t = 1; t > 1e-6 && !moved; t *= Scalar(0.5)) {
        for (Scalar sign : {1.0, -1.0}) {
          trial->evaluate(P1, P2, dr, Vec3((curN + sign * t * escape).normalized()));
          if (trial->L > cur->L + 2 * roundingL) {
            moved = true;
            break;
          }
        }
      }
      if (moved) {
        std::swap(cur, trial);
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
    const Scalar stepNorm = step.norm();
    if (stepNorm > 1) step /= stepNorm;
    const Scalar predicted = G.dot(step);  // first-order increase of L for the full step
    if (!(predicted > 0)) {
      // stationary: the maximum of L (to rounding)
      res.status = cur->L > 0 ? (cur->gap() + 2 * allow <= options.epsD ? DistanceStatus::converged
                                                                     : DistanceStatus::failed)
                             : DistanceStatus::overlapping;
      break;
    }
    // overlap: stop when the predicted increase is below the tolerance and
    // cannot make L positive (near touching, keep iterating: the sign matters)
    if (cur->L <= 0 && predicted <= Scalar(0.1) * options.epsD && cur->L + predicted < 0) {
      res.status = DistanceStatus::overlapping;
      break;
    }
    const bool belowRounding = predicted <= 64 * roundingL;
    const V3 ct = cur->tangential();
    const Scalar grad2 = dot(ct, ct);
    Scalar t = 1;
    bool accepted = false;
    for (int ls = 0; ls < 40; ++ls) {
      const Vec3 m = curN + t * (step[0] * t1 + step[1] * t2);
      trial->evaluate(P1, P2, dr, Vec3(m.normalized()));
      const V3 tt = trial->tangential();
      if (trial->L >= cur->L + Scalar(1e-4) * t * predicted ||
          (belowRounding && trial->L >= cur->L - 2 * roundingL && dot(tt, tt) < grad2)) {
        accepted = true;
        break;
      }
      t *= Scalar(0.5);
    }
    if (!accepted) {
      // no further increase representable: at the maximum up to rounding
      res.status = cur->L > 0 ? (cur->gap() + 2 * allow <= options.epsD ? DistanceStatus::converged
                                                                     : DistanceStatus::failed)
                             : DistanceStatus::overlapping;
      break;
    }
    std::swap(cur, trial);
  }
  res.iterations = it;
  res.point1 = e1.centre() + cur->x1();
  res.point2 = e1.centre() + cur->x2(dr);
  res.direction = cur->n.eigen();

  if (res.status == DistanceStatus::overlapping ||
      (res.status != DistanceStatus::converged && cur->L <= 0)) {
    // certify the overlap with a common point, else ask the exact algebraic test
    const bool common = e1.levelSet(res.point2) <= 0 || e2.levelSet(res.point1) <= 0 ||
                        e1.levelSet(e2.centre()) <= 0 || e2.levelSet(e1.centre()) <= 0;
    res.distance = cur->L;
    res.lower = cur->L - allow;
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
  res.distance = std::sqrt(dot(cur->v, cur->v));
  res.lower = cur->L - allow;
  // rounding of the absolute points: |p| <= |p|_1 (no square root)
  res.upper = res.distance + allow +
              4 * kEps * (res.point1.cwiseAbs().sum() + res.point2.cwiseAbs().sum());
  return res;
}

}  // namespace ellipsoids
