#include "ellipsoids/OverlapTest.hpp"

#include "ellipsoids/CertifiedBracket.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace ellipsoids {

const char* toString(OverlapStatus status) {
  switch (status) {
    case OverlapStatus::separated:
      return "separated";
    case OverlapStatus::touching:
      return "touching";
    case OverlapStatus::overlapping:
      return "overlapping";
  }
  return "overlapping";
}

JiaOverlapTest::JiaOverlapTest(Scalar zeroTolerance) : zeroTolerance_(zeroTolerance) {
  if (!(zeroTolerance >= 0) || !(zeroTolerance < 1)) {
    std::ostringstream os;
    os << "JiaOverlapTest: zeroTolerance must be in [0, 1), got " << zeroTolerance;
    throw std::invalid_argument(os.str());
  }
}

Vec4 JiaOverlapTest::characteristicPolynomial(const Ellipsoid& e1, const Ellipsoid& e2) {
  // Frame where E1 is the unit sphere: x~ = D^{-1} U1^T (x - r1), D = diag(a1, b1, c1).
  const Vec3 invD = e1.semiAxes().cwiseInverse();
  const Mat3 R = e1.rotation().transpose() * e2.rotation();  // E2's axes in E1's body frame
  // E2's quadratic matrix in the scaled frame: Q = D R Sigma2 R^T D
  const Vec3 sigma2 = e2.semiAxes().cwiseProduct(e2.semiAxes()).cwiseInverse();
  const Mat3 DR = e1.semiAxes().asDiagonal() * R;
  Mat3 Q = DR * sigma2.asDiagonal() * DR.transpose();
  Q = Scalar(0.5) * (Q + Q.transpose()).eval();
  const Vec3 r = invD.cwiseProduct(e1.rotation().transpose() * (e2.centre() - e1.centre()));

  // M = diag(1,1,1,-1) A2~, A2~ = [Q, -Q r; -r^T Q, r^T Q r - 1]
  const Vec3 Qr = Q * r;
  Mat4 M;
  M.topLeftCorner<3, 3>() = Q;
  M.topRightCorner<3, 1>() = -Qr;
  M.bottomLeftCorner<1, 3>() = Qr.transpose();
  M(3, 3) = 1 - r.dot(Qr);

  // det(l I + M) = l^4 + e1 l^3 + e2 l^2 + e3 l + e4, e_k = sum of k x k principal minors
  Scalar s1 = M.trace();
  Scalar s2 = 0;
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) {
      s2 += M(i, i) * M(j, j) - M(i, j) * M(j, i);
    }
  }
  Scalar s3 = 0;
  for (int skip = 0; skip < 4; ++skip) {
    int idx[3], k = 0;
    for (int i = 0; i < 4; ++i) {
      if (i != skip) idx[k++] = i;
    }
    Mat3 m;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m(i, j) = M(idx[i], idx[j]);
    s3 += m.determinant();
  }
  const Scalar s4 = M.determinant();
  return Vec4(s1, s2, s3, s4);
}

bool JiaOverlapTest::provedApart(const Ellipsoid& e1, const Ellipsoid& e2) {
  // the bounding spheres apart beyond the rounding: |r2 - r1| > a_max,1 + a_max,2
  const Scalar d = (e2.centre() - e1.centre()).norm();
  return d - e1.maxSemiAxis() - e2.maxSemiAxis() > roundingAllowance(e1, e2, d);
}

OverlapStatus JiaOverlapTest::test(const Ellipsoid& e1, const Ellipsoid& e2) const {
  if (provedApart(e1, e2)) return OverlapStatus::separated;
  return decide(e1, e2).status;
}

OverlapDetails JiaOverlapTest::details(const Ellipsoid& e1, const Ellipsoid& e2) const {
  OverlapDetails out = decide(e1, e2);
  if (provedApart(e1, e2)) out.status = OverlapStatus::separated;
  return out;
}

OverlapDetails JiaOverlapTest::decide(const Ellipsoid& e1, const Ellipsoid& e2) const {
  OverlapDetails out;
  out.coefficients = characteristicPolynomial(e1, e2);
  const Scalar a = out.coefficients[0], b = out.coefficients[1], c = out.coefficients[2],
               d = out.coefficients[3];

  // Var(1, a, b, c, d): sign changes between consecutive non-zero terms
  const Scalar seq[5] = {1, a, b, c, d};
  int var = 0;
  Scalar previous = 1;
  for (int i = 1; i < 5; ++i) {
    if (seq[i] != 0) {
      if ((seq[i] > 0) != (previous > 0)) ++var;
      previous = seq[i];
    }
  }
  out.signVariations = var;

  // eq. C.4 (P written l^4 - 4 bb l^3 + 6 cc l^2 - 4 dd l + ee)
  const Scalar bb = -a / 4, cc = b / 6, dd = -c / 4, ee = d;
  const Scalar delta2 = bb * bb - cc;
  const Scalar delta3 = cc * cc - bb * dd;
  const Scalar w1 = dd - bb * cc;
  const Scalar w3 = ee - bb * dd;
  const Scalar T = -9 * w1 * w1 + 27 * delta2 * delta3 - 3 * w3 * delta2;
  const Scalar A = w3 + 3 * delta3;                       // invariant I of the quartic
  const Scalar B = -dd * w1 - ee * delta2 - cc * delta3;  // invariant J
  const Scalar T2 = A * w1 - 3 * bb * B;
  const Scalar delta1 = A * A * A - 27 * B * B;           // discriminant / 256
  out.sr22 = delta2;
  out.sr20 = -w3;
  out.sr11 = T;
  out.sr10 = T2;
  out.sr0 = delta1;

  // relative zero tests (scale invariant, see the header)
  const Scalar scale0 = std::abs(A * A * A) + 27 * B * B;
  const Scalar scale11 = 9 * w1 * w1 + 27 * std::abs(delta2 * delta3) + 3 * std::abs(w3 * delta2);
  out.sr0IsZero = std::abs(delta1) <= zeroTolerance_ * scale0;
  out.sr11IsZero = std::abs(T) <= zeroTolerance_ * scale11;
  const bool sr0Positive = !out.sr0IsZero && delta1 > 0;
  const bool sr11Positive = !out.sr11IsZero && T > 0;

  // Theorem 4 (Jia et al.)
  if (var == 2 && delta2 > 0 && sr11Positive &&
      (sr0Positive || (out.sr0IsZero && T2 > 0))) {
    out.status = OverlapStatus::separated;
  } else if (out.sr0IsZero && delta2 > 0 &&
             ((sr11Positive && T2 < 0) || (out.sr11IsZero && -w3 < 0))) {
    out.status = OverlapStatus::touching;
  } else {
    out.status = OverlapStatus::overlapping;
  }
  return out;
}

}  // namespace ellipsoids
