#include "ellipsoids/Gjk.hpp"

#include "ellipsoids/CertifiedBracket.hpp"

#include <algorithm>
#include <cmath>

namespace ellipsoids {

namespace {

/**
 * Johnson's distance sub-algorithm with van den Bergen's caching. Vertices
 * y_i = p_i - q_i live in slots 0..3; a subset is a 4-bit mask. delta_[s][i]
 * is Delta_i(s) of eq. 2.26 (with l the lowest other index of s).
 */
class Simplex {
 public:
  int bits() const { return bits_; }
  int size() const { return __builtin_popcount(static_cast<unsigned>(bits_)); }

  /// True if w equals a vertex already in the simplex (no progress possible).
  bool contains(const Vec3& w) const {
    for (int i = 0, b = 1; i < 4; ++i, b <<= 1) {
      if ((bits_ & b) && y_[i] == w) return true;
    }
    return false;
  }

  /// Largest |y_i|^2 of the current vertices (scale for the zero tests).
  Scalar maxVertexNorm2() const {
    Scalar m = 0;
    for (int i = 0, b = 1; i < 4; ++i, b <<= 1) {
      if (bits_ & b) m = std::max(m, dot_[i][i]);
    }
    return m;
  }

  /// Adds y = p - q in a free slot.
  void add(const Vec3& y, const Vec3& p, const Vec3& q) {
    last_ = 0;
    lastBit_ = 1;
    while (bits_ & lastBit_) {
      ++last_;
      lastBit_ <<= 1;
    }
    y_[last_] = y;
    p_[last_] = p;
    q_[last_] = q;
    allBits_ = bits_ | lastBit_;
    updateDeterminants();
  }

  /**
   * Replaces the simplex by the smallest subset X of W + {new vertex} whose
   * affine projection of the origin lies inside conv(X) (eq. 2.28), and
   * returns that projection v. Returns false if no subset passes the test
   * (numerical breakdown); the caller then keeps its previous answer.
   */
  bool closest(Vec3& v) {
    for (int s = bits_; s; --s) {
      if ((s & bits_) == s && valid(s | lastBit_)) {
        bits_ = s | lastBit_;
        v = combination(bits_);
        return true;
      }
    }
    if (valid(lastBit_)) {
      bits_ = lastBit_;
      v = y_[last_];
      return true;
    }
    return false;
  }

  /// Eq. 2.30: x1 = sum lambda_i p_i, x2 = sum lambda_i q_i.
  void points(Vec3& x1, Vec3& x2) const {
    Scalar sum = 0;
    x1.setZero();
    x2.setZero();
    for (int i = 0, b = 1; i < 4; ++i, b <<= 1) {
      if (bits_ & b) {
        sum += delta_[bits_][i];
        x1 += delta_[bits_][i] * p_[i];
        x2 += delta_[bits_][i] * q_[i];
      }
    }
    x1 /= sum;
    x2 /= sum;
  }

 private:
  Vec3 combination(int s) const {
    Scalar sum = 0;
    Vec3 v = Vec3::Zero();
    for (int i = 0, b = 1; i < 4; ++i, b <<= 1) {
      if (s & b) {
        sum += delta_[s][i];
        v += delta_[s][i] * y_[i];
      }
    }
    return v / sum;
  }

  // Eq. 2.28: all Delta_i(X) > 0 for i in X, Delta_j(X + {y_j}) <= 0 for j not in X
  bool valid(int s) const {
    for (int i = 0, b = 1; i < 4; ++i, b <<= 1) {
      if (allBits_ & b) {
        if (s & b) {
          if (delta_[s][i] <= 0) return false;
        } else if (delta_[s | b][i] > 0) {
          return false;
        }
      }
    }
    return true;
  }

  // Cached dot products and the Delta values of every subset containing the new vertex
  void updateDeterminants() {
    for (int i = 0, b = 1; i < 4; ++i, b <<= 1) {
      if (bits_ & b) dot_[i][last_] = dot_[last_][i] = y_[i].dot(y_[last_]);
    }
    dot_[last_][last_] = y_[last_].dot(y_[last_]);
    delta_[lastBit_][last_] = 1;  // eq. 2.25
    for (int j = 0, sj = 1; j < 4; ++j, sj <<= 1) {
      if (!(bits_ & sj)) continue;
      const int s2 = sj | lastBit_;
      delta_[s2][j] = dot_[last_][last_] - dot_[last_][j];
      delta_[s2][last_] = dot_[j][j] - dot_[j][last_];
      for (int k = 0, sk = 1; k < j; ++k, sk <<= 1) {
        if (!(bits_ & sk)) continue;
        const int s3 = sk | s2;
        delta_[s3][k] = delta_[s2][j] * (dot_[j][j] - dot_[j][k]) +
                        delta_[s2][last_] * (dot_[last_][j] - dot_[last_][k]);
        delta_[s3][j] = delta_[sk | lastBit_][k] * (dot_[k][k] - dot_[k][j]) +
                        delta_[sk | lastBit_][last_] * (dot_[last_][k] - dot_[last_][j]);
        delta_[s3][last_] = delta_[sk | sj][k] * (dot_[k][k] - dot_[k][last_]) +
                            delta_[sk | sj][j] * (dot_[j][k] - dot_[j][last_]);
      }
    }
    if (allBits_ == 15) {
      delta_[15][0] = delta_[14][1] * (dot_[1][1] - dot_[1][0]) +
                      delta_[14][2] * (dot_[2][1] - dot_[2][0]) +
                      delta_[14][3] * (dot_[3][1] - dot_[3][0]);
      delta_[15][1] = delta_[13][0] * (dot_[0][0] - dot_[0][1]) +
                      delta_[13][2] * (dot_[2][0] - dot_[2][1]) +
                      delta_[13][3] * (dot_[3][0] - dot_[3][1]);
      delta_[15][2] = delta_[11][0] * (dot_[0][0] - dot_[0][2]) +
                      delta_[11][1] * (dot_[1][0] - dot_[1][2]) +
                      delta_[11][3] * (dot_[3][0] - dot_[3][2]);
      delta_[15][3] = delta_[7][0] * (dot_[0][0] - dot_[0][3]) +
                      delta_[7][1] * (dot_[1][0] - dot_[1][3]) +
                      delta_[7][2] * (dot_[2][0] - dot_[2][3]);
    }
  }

  Vec3 y_[4], p_[4], q_[4];
  Scalar dot_[4][4] = {};
  Scalar delta_[16][4] = {};
  int bits_ = 0;
  int last_ = 0;
  int lastBit_ = 0;
  int allBits_ = 0;
};

}  // namespace

DistanceResult Gjk::distance(const Ellipsoid& e1, const Ellipsoid& e2,
                             const DistanceOptions& options) const {
  options.validate();
  const int maxIterations = options.maxIterations > 0 ? options.maxIterations : kDefaultMaxIterations;
  // coordinates relative to r1: translation invariant
  const Vec3 dr = e2.centre() - e1.centre();
  const Mat3& P1 = e1.shapeMatrix();
  const Mat3& P2 = e2.shapeMatrix();
  const Scalar allow = roundingAllowance(e1, e2);
  // the stopping test leaves room for everything the reported bracket adds to
  // |v| - mu + 2 allow: the rounding of the absolute points (4 eps (|p1|_1 +
  // |p2|_1), |p_m|_1 <= |r1|_1 + |dr|_1 + sqrt(3) a_max,m) and the difference
  // between |v| and |x2 - x1| (a few eps of the simplex's size)
  const Scalar sizes = e1.maxSemiAxis() + e2.maxSemiAxis();
  const Scalar stopMargin = 2 * allow +
                            4 * kEps * (2 * e1.centre().cwiseAbs().sum() + 2 * dr.cwiseAbs().sum() +
                                        Scalar(1.7320508075688772) * sizes) +
                            8 * kEps * (dr.norm() + sizes);

  Vec3 v = options.useInitialDirection ? Vec3(-options.initialDirection) : Vec3(-dr);
  // centres closer than the rounding of the sizes (v^T P v could underflow): any direction
  if (!options.useInitialDirection && !(dr.norm() > kEps * sizes)) {
    v = Vec3::UnitX();
  }

  Simplex simplex;
  Scalar mu = 0;
  Vec3 bestN = -v.normalized();
  DistanceResult res;
  res.status = DistanceStatus::maxIterations;
  bool haveSimplex = false;
  int k = 0;
  for (; k < maxIterations; ++k) {
    // support of C in -v: p = s_E1(-v) - r1, q = s_E2(v) - r1
    const Vec3 P1v = P1 * v;
    const Vec3 P2v = P2 * v;
    const Vec3 p = -P1v / std::sqrt(v.dot(P1v));
    const Vec3 q = dr + P2v / std::sqrt(v.dot(P2v));
    const Vec3 w = p - q;
    const Scalar vnorm = v.norm();
    const Scalar delta = w.dot(v) / vnorm;  // = L(-v/|v|)
    if (delta > mu) {
      mu = delta;
      bestN = -v / vnorm;
    }
    if (haveSimplex && vnorm - mu + stopMargin <= options.epsD) {
      res.status = DistanceStatus::converged;
      break;
    }
    if (haveSimplex && simplex.contains(w)) {
      // no new vertex: at the limit of floating point
      res.status = vnorm - mu + stopMargin <= options.epsD ? DistanceStatus::converged
                                                          : DistanceStatus::failed;
      break;
    }
    Simplex previous = simplex;
    simplex.add(w, p, q);
    Vec3 vNew;
    if (!simplex.closest(vNew)) {
      simplex = previous;  // breakdown of the sub-algorithm: keep the last good simplex
      res.status = haveSimplex && vnorm - mu + stopMargin <= options.epsD ? DistanceStatus::converged
                                                                         : DistanceStatus::failed;
      break;
    }
    haveSimplex = true;
    const Scalar tiny = 64 * kEps * kEps * simplex.maxVertexNorm2();
    if (simplex.size() == 4 || vNew.squaredNorm() <= tiny) {
      res.status = DistanceStatus::overlapping;  // the simplex encloses the origin
      v = vNew;
      break;
    }
    v = vNew;
  }
  res.iterations = k;
  Vec3 x1, x2;
  simplex.points(x1, x2);
  res.point1 = e1.centre() + x1;
  res.point2 = e1.centre() + x2;
  if (res.status == DistanceStatus::overlapping) {
    // [0, 0] with a certain common point (the simplex points coincide up to
    // rounding), else [0, U] (certifyFromPoints)
    res.distance = 0;
    res.direction = bestN;
    certifyFromPoints(e1, e2, res);
    return res;
  }
  res.distance = (x2 - x1).norm();
  res.direction = bestN;
  res.lower = std::max(mu - allow, Scalar(0));
  res.upper = res.distance + allow + 4 * kEps * (res.point1.norm() + res.point2.norm());
  return res;
}

}  // namespace ellipsoids
