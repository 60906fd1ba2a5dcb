#include "ellipsoids/DualNewton.hpp"

#include "ellipsoids/CertifiedBracket.hpp"
#include "ellipsoids/OverlapTest.hpp"

#include <algorithm>
#include <cmath>
#include <new>
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

  /**
   * The same at n = m/|m| for any non-zero m: the normalisation of m runs in
   * parallel with the support radii instead of before them (the square roots
   * and divisions are the critical path of an iteration). y_m and s_m are
   * homogeneous of degree 1 in m, the support points of degree 0.
   */
  void evaluateDirection(const Sym3& P1, const Sym3& P2, const V3& dr, const V3& m) {
    const V3 y1m = P1 * m, y2m = P2 * m;
    const Scalar q1 = dot(m, y1m), q2 = dot(m, y2m), mm = dot(m, m);
    const Scalar im = 1 / std::sqrt(mm);
    const Scalar i1 = 1 / std::sqrt(q1), i2 = 1 / std::sqrt(q2);
    v = dr - y2m * i2 - y1m * i1;
    n = m * im;
    y1 = y1m * im;
    y2 = y2m * im;
    const Scalar absm = mm * im;
    inv1 = i1 * absm;
    inv2 = i2 * absm;
    sumS = (q1 * i1 + q2 * i2) * im;
    L = dot(m, dr) * im - sumS;
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

/// Per-pair constants of the iteration.
struct PairSetup {
  Sym3 P1, P2;
  V3 dr;           // r2 - r1
  Scalar drNorm;
  Scalar size;     // largest semi-axes summed
  Scalar allow;    // rounding allowance of the bracket (roundingAllowance(e1, e2), with drNorm)
  Scalar roundingL;  // rounding of L = n.dr - s1 - s2
  Scalar epsD, epsStop;
  int maxIterations;
  bool spheres;    // both bodies spheres: the centre line is the answer's direction

  PairSetup(const Ellipsoid& e1, const Ellipsoid& e2, const DistanceOptions& options)
      : P1(e1.shapeMatrix()), P2(e2.shapeMatrix()), dr(Vec3(e2.centre() - e1.centre())) {
    drNorm = std::sqrt(dot(dr, dr));
    size = e1.maxSemiAxis() + e2.maxSemiAxis();
    allow = roundingAllowance(e1, e2, drNorm);
    roundingL = 4 * kEps * (drNorm + size);
    epsD = options.epsD;
    // the reported bracket is gap + 2 allow + the rounding of the absolute
    // points (finish(): 4 eps (|p1|_1 + |p2|_1), |p1|_1 + |p2|_1 <= 2 |c1|_1 +
    // |dr|_1 + sqrt(3) size) + the difference of L and v.n (roundingL): all of
    // it inside epsD, so that the bracket never exceeds epsD by a rounding
    const Scalar c1 = e1.centre().cwiseAbs().sum();
    const Scalar dr1 = std::abs(dr.x) + std::abs(dr.y) + std::abs(dr.z);
    epsStop = options.epsD - 2 * allow - 4 * kEps * (2 * c1 + dr1 + Scalar(1.7320508075688772) * size) -
              roundingL;
    maxIterations = options.maxIterations > 0 ? options.maxIterations : DualNewton::kDefaultMaxIterations;
    spheres = e1.minSemiAxis() == e1.maxSemiAxis() && e2.minSemiAxis() == e2.maxSemiAxis();
  }
};

/**
 * Cold start: the normal at the point of an ellipsoid approximating the
 * Minkowski sum K = E1 + (-E2) closest to dr. With s_m the support radii along
 * u = dr/|dr|, M = (s1 + s2)(P1/s1 + P2/s2) has support >= s1 + s2 in every
 * direction (Cauchy-Schwarz), with equality along u: the ellipsoid
 * x^T M^-1 x = 1 encloses K and touches it on the centre line. The normal of
 * its point closest to dr is (M + t I)^-1 dr, t = (distance) x (support along
 * that normal); t = 0 is the normal where the centre line crosses it, exact for
 * identical parallel bodies at touching, t -> infinity the centre line. We take
 * t = 0.75 (|dr| - s1 - s2)(s1 + s2), at least 0: (M + t I) is then, up to a
 * positive factor, P1 i1 + P2 i2 + sigma I with i_m = 1/(|dr| s_m) and sigma =
 * 0.75 (1 - (s1 + s2)/|dr|). The factor was chosen among 0.5 to 1.25 by the
 * mean Newton iterations on the packings of docs/benchmarks.md (the far pairs of
 * elongated bodies gain most; the table there has the iterations with it and
 * the run before it without the shift). Spheres keep the centre line
 * (exact), which is skipped. Costs two square roots, a division and a 3x3
 * adjugate; (M + t I)^-1 dr is used unnormalised (evaluateDirection normalises).
 */
V3 centreLineNormal(const PairSetup& p) {
  const V3 y1 = p.P1 * p.dr, y2 = p.P2 * p.dr;
  const Scalar q1 = dot(p.dr, y1), q2 = dot(p.dr, y2);  // (|dr| s_m)^2
  const Scalar i1 = 1 / std::sqrt(q1), i2 = 1 / std::sqrt(q2);
  const Scalar sigma = Scalar(0.75) * std::max(Scalar(0), 1 - (q1 * i1 + q2 * i2) / dot(p.dr, p.dr));
  // (M + t I) up to a positive factor: P1 i1 + P2 i2 + sigma I
  const Scalar a00 = p.P1.xx * i1 + p.P2.xx * i2 + sigma, a01 = p.P1.xy * i1 + p.P2.xy * i2;
  const Scalar a02 = p.P1.xz * i1 + p.P2.xz * i2, a11 = p.P1.yy * i1 + p.P2.yy * i2 + sigma;
  const Scalar a12 = p.P1.yz * i1 + p.P2.yz * i2, a22 = p.P1.zz * i1 + p.P2.zz * i2 + sigma;
  // adj(A) dr = det(A) A^-1 dr, det(A) > 0 (A is positive definite)
  const Scalar c00 = a11 * a22 - a12 * a12, c01 = a02 * a12 - a01 * a22, c02 = a01 * a12 - a02 * a11;
  const Scalar c11 = a00 * a22 - a02 * a02, c12 = a01 * a02 - a00 * a12, c22 = a00 * a11 - a01 * a01;
  const V3& d = p.dr;
  return {c00 * d.x + c01 * d.y + c02 * d.z, c01 * d.x + c11 * d.y + c12 * d.z,
          c02 * d.x + c12 * d.y + c22 * d.z};
}

/// The first iterate: the given direction, or the normal of the centre line's crossing.
void start(const PairSetup& p, const Ellipsoid& e1, const DistanceOptions& options, DualPoint& cur) {
  if (options.useInitialDirection) {
    cur.evaluate(p.P1, p.P2, p.dr, Vec3(options.initialDirection.normalized()));
  } else if (p.drNorm > kEps * p.size && p.spheres) {
    cur.evaluateDirection(p.P1, p.P2, p.dr, p.dr);  // exact: M is isotropic
  } else if (p.drNorm > kEps * p.size) {
    const V3 m = centreLineNormal(p);
    // a degenerate M (flat bodies to rounding) falls back to the centre line
    if (std::isfinite(m.x + m.y + m.z) && dot(m, p.dr) > 0) {
      cur.evaluateDirection(p.P1, p.P2, p.dr, m);
    } else {
      cur.evaluateDirection(p.P1, p.P2, p.dr, p.dr);  // normalised on the way
    }
  } else {
    // concentric to rounding (n^T P n along such a short r2 - r1 could underflow): any direction
    cur.evaluate(p.P1, p.P2, p.dr, Vec3(e1.rotation().col(0)));
  }
}

enum class Step { converged, moved, overlapping, general };

/**
 * One iteration of the fast path. Certified stop for separated bodies; else,
 * where Q1 + Q2 + L I is positive definite (always near the maximum of
 * separated bodies), the full Newton step, accepted if L increases as
 * predicted or, below the rounding of L, if the tangential gradient decreases
 * (near the optimum L is flat, second order in the angle, while the bracket
 * still needs a smaller angle at small gaps: |x2 - x1| - L ~ (R angle)^2 / gap).
 * Anything else is left to the general path.
 */
Step fastStep(const PairSetup& p, DualPoint*& cur, DualPoint*& trial, int it) {
  const Scalar vn = dot(cur->v, cur->n);  // = L up to rounding
  const V3 vt = cur->v - cur->n * vn;
  const Scalar vt2 = dot(vt, vt);
  // |v| - v.n = |v_t|^2 / (|v| + v.n) <= |v_t|^2 / (2 v.n), tested without a square root
  if (cur->L > 0 && vn > 0 && vt2 <= 2 * vn * p.epsStop) return Step::converged;

  V3 raw;  // the Newton step times det
  Scalar det;
  const bool atMaximum = newtonStep(p.P1, p.P2, *cur, vt, cur->L, raw, det);  // Hessian negative definite
  // From a poor start (the first two iterations), with L < 0, the curvature
  // term max(L, 0) still gives an ascent direction: fewer iterations for
  // elongated bodies than the shifted general path (measured 5-10 %). Not
  // later: at the maximum of an overlap L < 0 is the answer, and ignoring it
  // would slow Newton down to a crawl
  if (!atMaximum && !(it < 2 && cur->L < 0 && newtonStep(p.P1, p.P2, *cur, vt, 0, raw, det))) {
    return Step::general;
  }
  // n_new = (det n + raw)/|det n + raw|, at most a quarter turn per step
  // (|raw| <= det); the normalisation happens inside the evaluation
  const Scalar raw2 = dot(raw, raw), det2 = det * det;
  const Scalar scale = raw2 <= det2 ? det : std::sqrt(raw2);
  const Scalar predicted = dot(vt, raw) / scale;
  if (atMaximum && cur->L <= 0 && predicted <= Scalar(0.1) * p.epsD && cur->L + predicted < 0) {
    return Step::overlapping;  // the overlap's maximum, to the tolerance
  }
  if (!(predicted > 0)) return Step::general;
  trial->evaluateDirection(p.P1, p.P2, p.dr, cur->n * scale + raw);
  const V3 tt = trial->tangential();
  if (trial->L >= cur->L + Scalar(1e-4) * predicted ||
      (predicted <= 64 * p.roundingL && trial->L >= cur->L - 2 * p.roundingL && dot(tt, tt) < vt2)) {
    std::swap(cur, trial);
    return Step::moved;
  }
  return Step::general;
}

enum class GeneralStep { moved, converged, overlapping, failed };

/**
 * One iteration of the general path: the 2x2 system on a tangent basis,
 * shifted to be positive definite, an escape from saddles along the direction
 * of negative curvature, and a backtracking line search.
 */
GeneralStep generalStep(const PairSetup& p, DualPoint*& cur, DualPoint*& trial) {
  if (cur->L > 0 && cur->gap() <= p.epsStop) return GeneralStep::converged;
  const Vec3 curN = cur->n.eigen(), curV = cur->v.eigen();
  Vec3 t1, t2;
  tangentBasis(curN, t1, t2);
  const Eigen::Matrix<Scalar, 2, 1> G(t1.dot(curV), t2.dot(curV));
  Eigen::Matrix<Scalar, 2, 2> H = curvatureTensor(p.P1, cur->y1, cur->inv1, t1, t2) +
                                  curvatureTensor(p.P2, cur->y2, cur->inv2, t1, t2);
  H(0, 0) += cur->L;
  H(1, 1) += cur->L;
  const Scalar tr = H.trace();
  const Scalar detH = H.determinant();
  const Scalar lambdaMin = Scalar(0.5) * (tr - std::sqrt(std::max(tr * tr - 4 * detH, Scalar(0))));
  const Scalar scaleH = std::abs(H(0, 0)) + std::abs(H(1, 1)) + std::abs(H(0, 1)) + p.size * kEps;
  if (lambdaMin < 0 && G.norm() <= 64 * p.roundingL) {
    // a saddle of L (e.g. a symmetric start): leave along the direction of
    // negative curvature of H, where L increases
    // eigenvector of the smallest eigenvalue of the symmetric 2x2 H
    const Scalar a = H(0, 0), b = H(0, 1), c = H(1, 1);
    const Scalar lam = Scalar(0.5) * (a + c) - std::hypot(Scalar(0.5) * (a - c), b);
    const Eigen::Matrix<Scalar, 2, 1> u1(b, lam - a), u2(lam - c, b);
    const Eigen::Matrix<Scalar, 2, 1> u = u1.squaredNorm() >= u2.squaredNorm() ? u1 : u2;
    const Scalar un = u.norm();
    const Vec3 escape = un > 0 ? Vec3((u[0] * t1 + u[1] * t2) / un) : t1;
    for (Scalar t = 1; t > 1e-6; t *= Scalar(0.5)) {
      for (Scalar sign : {1.0, -1.0}) {
        trial->evaluate(p.P1, p.P2, p.dr, Vec3((curN + sign * t * escape).normalized()));
        if (trial->L > cur->L + 2 * p.roundingL) {
          std::swap(cur, trial);
          return GeneralStep::moved;
        }
      }
    }
  }
  if (lambdaMin <= Scalar(1e-3) * scaleH) {
    const Scalar shift = Scalar(1e-3) * scaleH - lambdaMin;
    H(0, 0) += shift;
    H(1, 1) += shift;
  }
  Eigen::Matrix<Scalar, 2, 1> step = H.llt().solve(G);
  if (!step.allFinite()) return GeneralStep::failed;
  const Scalar stepNorm = step.norm();
  if (stepNorm > 1) step /= stepNorm;
  const Scalar predicted = G.dot(step);  // first-order increase of L for the full step
  auto atMaximum = [&] {
    return cur->L > 0 ? (cur->gap() <= p.epsStop ? GeneralStep::converged : GeneralStep::failed)
                      : GeneralStep::overlapping;
  };
  if (!(predicted > 0)) return atMaximum();  // stationary: the maximum of L (to rounding)
  // overlap: stop when the predicted increase is below the tolerance and
  // cannot make L positive (near touching, keep iterating: the sign matters)
  if (cur->L <= 0 && predicted <= Scalar(0.1) * p.epsD && cur->L + predicted < 0) {
    return GeneralStep::overlapping;
  }
  const bool belowRounding = predicted <= 64 * p.roundingL;
  const V3 ct = cur->tangential();
  const Scalar grad2 = dot(ct, ct);
  Scalar t = 1;
  for (int ls = 0; ls < 40; ++ls) {
    const Vec3 m = curN + t * (step[0] * t1 + step[1] * t2);
    trial->evaluate(p.P1, p.P2, p.dr, Vec3(m.normalized()));
    const V3 tt = trial->tangential();
    if (trial->L >= cur->L + Scalar(1e-4) * t * predicted ||
        (belowRounding && trial->L >= cur->L - 2 * p.roundingL && dot(tt, tt) < grad2)) {
      std::swap(cur, trial);
      return GeneralStep::moved;
    }
    t *= Scalar(0.5);
  }
  return atMaximum();  // no further increase representable: at the maximum up to rounding
}

/// The result from the final iterate: points, bracket, and the overlap's certification.
DistanceResult finish(const PairSetup& p, const Ellipsoid& e1, const Ellipsoid& e2, const DualPoint& cur,
                      DistanceStatus status, int iterations) {
  DistanceResult res;
  res.status = status;
  res.iterations = iterations;
  res.point1 = e1.centre() + cur.x1();
  res.point2 = e1.centre() + cur.x2(p.dr);
  res.direction = cur.n.eigen();
  if (status == DistanceStatus::overlapping || (status != DistanceStatus::converged && cur.L <= 0)) {
    // the overlap is certified by a common point; without one, |x2 - x1| still
    // bounds the signed distance from above (>= 0 >= d* or, if apart, >= d*)
    const bool common = certainlyInside(e1, res.point2) || certainlyInside(e2, res.point1) ||
                        certainlyInside(e1, e2.centre()) || certainlyInside(e2, e1.centre());
    res.distance = cur.L;
    res.lower = cur.L - p.allow;
    res.upper = common ? Scalar(0)
                       : (res.point2 - res.point1).norm() + p.allow +
                             4 * kEps * (res.point1.cwiseAbs().sum() + res.point2.cwiseAbs().sum());
    if (!common && JiaOverlapTest().test(e1, e2) == OverlapStatus::separated) {
      res.status = DistanceStatus::failed;  // a spurious local maximum of L: not an overlap
    }
    return res;
  }
  res.distance = std::sqrt(dot(cur.v, cur.v));
  res.lower = cur.L - p.allow;
  // rounding of the absolute points: |p| <= |p|_1 (no square root)
  res.upper = res.distance + p.allow + 4 * kEps * (res.point1.cwiseAbs().sum() + res.point2.cwiseAbs().sum());
  return res;
}

}  // namespace

DistanceResult DualNewton::distance(const Ellipsoid& e1, const Ellipsoid& e2,
                                    const DistanceOptions& options) const {
  options.validate();
  const PairSetup p(e1, e2, options);
  DualPoint points[2];
  DualPoint* cur = &points[0];    // the iterate
  DualPoint* trial = &points[1];  // the candidate; accepted by swapping the pointers
  start(p, e1, options, *cur);

  DistanceStatus status = DistanceStatus::maxIterations;
  int it = 0;
  for (; it < p.maxIterations; ++it) {
    const Step s = fastStep(p, cur, trial, it);
    if (s == Step::moved) continue;
    if (s == Step::converged) {
      status = DistanceStatus::converged;
      break;
    }
    if (s == Step::overlapping) {
      status = DistanceStatus::overlapping;
      break;
    }
    const GeneralStep g = generalStep(p, cur, trial);
    if (g == GeneralStep::moved) continue;
    status = g == GeneralStep::converged     ? DistanceStatus::converged
             : g == GeneralStep::overlapping ? DistanceStatus::overlapping
                                             : DistanceStatus::failed;
    break;
  }
  return finish(p, e1, e2, *cur, status, it);
}

void DualNewton::distances(const DistancePair* pairs, std::size_t count, const DistanceOptions& options,
                           DistanceResult* results) const {
  options.validate();
  // Lanes of independent queries advanced in turn: each iteration is a chain
  // of dependent square roots and divisions, so interleaving queries keeps the
  // core busy. A lane whose query leaves the fast path is finished by the
  // one-pair method (rare); a finished lane takes the next query.
  constexpr int kLanes = 4;
  struct Lane {
    std::size_t query;
    PairSetup setup;
    DualPoint points[2];
    DualPoint* cur;
    DualPoint* trial;
    int it;
  };
  alignas(64) unsigned char storage[kLanes * sizeof(Lane)];
  Lane* lanes = reinterpret_cast<Lane*>(storage);
  int active = 0;
  std::size_t next = 0;
  auto load = [&](Lane& lane) {
    while (next < count) {
      const DistancePair& q = pairs[next];
      if (q.initialDirection) {  // warm starts go through the one-pair method's options
        DistanceOptions o = options;
        o.useInitialDirection = true;
        o.initialDirection = *q.initialDirection;
        results[next] = distance(*q.e1, *q.e2, o);
        ++next;
        continue;
      }
      new (&lane) Lane{next, PairSetup(*q.e1, *q.e2, options), {}, nullptr, nullptr, 0};
      lane.cur = &lane.points[0];
      lane.trial = &lane.points[1];
      start(lane.setup, *q.e1, options, *lane.cur);
      ++next;
      return true;
    }
    return false;
  };
  for (; active < kLanes && load(lanes[active]); ++active) {
  }
  while (active > 0) {
    for (int k = 0; k < active;) {
      Lane& lane = lanes[k];
      const DistancePair& q = pairs[lane.query];
      const Step s = lane.it < lane.setup.maxIterations ? fastStep(lane.setup, lane.cur, lane.trial, lane.it)
                                                        : Step::general;
      if (s == Step::moved) {
        ++lane.it;
        ++k;
        continue;
      }
      if (s == Step::converged) {
        results[lane.query] = finish(lane.setup, *q.e1, *q.e2, *lane.cur, DistanceStatus::converged, lane.it);
      } else {
        results[lane.query] = distance(*q.e1, *q.e2, options);  // the one-pair method from the start
      }
      if (!load(lane)) {
        lanes[k] = lanes[--active];  // compact; the moved lane's pointers must follow it
        if (k < active) {
          Lane& moved = lanes[k];
          const bool first = moved.cur == &lanes[active].points[0];
          moved.cur = &moved.points[first ? 0 : 1];
          moved.trial = &moved.points[first ? 1 : 0];
        }
      }
    }
  }
}

}  // namespace ellipsoids
