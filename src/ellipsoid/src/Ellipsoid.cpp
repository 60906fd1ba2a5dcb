#include "ellipsoids/Ellipsoid.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace ellipsoids {

namespace {

std::string str(const Vec3& v) {
  std::ostringstream os;
  os.precision(17);
  os << "(" << v.x() << " " << v.y() << " " << v.z() << ")";
  return os.str();
}

std::string str(Scalar v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

}  // namespace

Ellipsoid::Ellipsoid(const Vec3& semiAxes, const Vec3& centre, const Quat& orientation)
    : semiAxes_(semiAxes), centre_(centre), orientation_(orientation) {
  using R = SupportedRange;
  if (!semiAxes.allFinite() || !(semiAxes.minCoeff() >= R::kMinLength) ||
      !(semiAxes.maxCoeff() <= R::kMaxLength)) {
    throw std::invalid_argument("Ellipsoid: semi-axes must be in [" + str(R::kMinLength) + ", " +
                                str(R::kMaxLength) + "], got " + str(semiAxes));
  }
  // (a relative slack of 1e-12: spheroid(100, ...) computes its semi-axes with cube roots)
  if (!(semiAxes.maxCoeff() <= R::kMaxElongation * (1 + 1e-12) * semiAxes.minCoeff())) {
    throw std::invalid_argument(
        "Ellipsoid: elongation (largest / smallest semi-axis) must be at most " +
        str(R::kMaxElongation) + " (aspect ratio 1/" + str(R::kMaxElongation) + " to " +
        str(R::kMaxElongation) + "), got semi-axes " + str(semiAxes));
  }
  if (!centre.allFinite() || !(centre.cwiseAbs().maxCoeff() <= R::kMaxLength)) {
    throw std::invalid_argument("Ellipsoid: centre coordinates must be finite and at most " +
                                str(R::kMaxLength) + " in magnitude, got " + str(centre));
  }
  const Scalar norm = orientation.norm();
  if (!std::isfinite(norm) || std::abs(norm - 1) > 1e-6) {
    std::ostringstream os;
    os.precision(17);
    os << "Ellipsoid: orientation must be a unit quaternion (|q| within 1e-6 of 1), got |q| = "
       << norm;
    throw std::invalid_argument(os.str());
  }
  orientation_.normalize();
  rotation_ = orientation_.toRotationMatrix();
  const Vec3 a2 = semiAxes_.cwiseProduct(semiAxes_);
  quadratic_ = rotation_ * a2.cwiseInverse().asDiagonal() * rotation_.transpose();
  shape_ = rotation_ * a2.asDiagonal() * rotation_.transpose();
  // exact symmetry (the products above are symmetric only up to rounding)
  quadratic_ = Scalar(0.5) * (quadratic_ + quadratic_.transpose()).eval();
  shape_ = Scalar(0.5) * (shape_ + shape_.transpose()).eval();

  minAxis_ = semiAxes_.minCoeff();
  maxAxis_ = semiAxes_.maxCoeff();
  const Scalar abc = semiAxes_.prod();
  equivalentRadius_ = std::cbrt(abc);
  minGaussianRadius_ = abc / (maxAxis_ * maxAxis_);
  maxCurvatureRadius_ = maxAxis_ * maxAxis_ / minAxis_;

  // aspect ratio: symmetry axis over the other two for a spheroid
  const Scalar a = semiAxes_.x(), b = semiAxes_.y(), c = semiAxes_.z();
  auto same = [](Scalar u, Scalar v) { return std::abs(u - v) <= 1e-12 * std::max(u, v); };
  if (same(a, b) && same(b, c)) {
    aspectRatio_ = 1;
  } else if (same(b, c)) {
    aspectRatio_ = a / b;
  } else if (same(a, c)) {
    aspectRatio_ = b / a;
  } else if (same(a, b)) {
    aspectRatio_ = c / a;
  } else {
    aspectRatio_ = maxAxis_ / minAxis_;
  }
}

Ellipsoid Ellipsoid::sphere(Scalar radius, const Vec3& centre) {
  return Ellipsoid(Vec3::Constant(radius), centre, Quat::Identity());
}

Ellipsoid Ellipsoid::spheroid(Scalar ar, Scalar dEq, const Vec3& centre, const Quat& orientation) {
  if (!(ar > 0) || !std::isfinite(ar) || !(dEq > 0) || !std::isfinite(dEq)) {
    std::ostringstream os;
    os << "Ellipsoid::spheroid: aspect ratio and diameter must be finite and > 0, got ar = " << ar
       << ", dEq = " << dEq;
    throw std::invalid_argument(os.str());
  }
  const Scalar maxAr = SupportedRange::kMaxElongation * (1 + 1e-12);
  if (!(ar <= maxAr) || !(ar * maxAr >= 1)) {
    std::ostringstream os;
    os << "Ellipsoid::spheroid: aspect ratio must be in [1/" << SupportedRange::kMaxElongation << ", "
       << SupportedRange::kMaxElongation << "], got ar = " << ar;
    throw std::invalid_argument(os.str());
  }
  const Scalar a = std::cbrt(ar * ar) * dEq / 2;
  const Scalar b = dEq / (2 * std::cbrt(ar));
  return Ellipsoid(Vec3(a, b, b), centre, orientation);
}

Mat4 Ellipsoid::homogeneousMatrix() const {
  // A_h = [A, -A r; -r^T A, r^T A r - 1] (eq. C.9 written out)
  Mat4 h;
  const Vec3 Ar = quadratic_ * centre_;
  h.topLeftCorner<3, 3>() = quadratic_;
  h.topRightCorner<3, 1>() = -Ar;
  h.bottomLeftCorner<1, 3>() = -Ar.transpose();
  h(3, 3) = centre_.dot(Ar) - 1;
  return h;
}

Scalar Ellipsoid::levelSet(const Vec3& x) const {
  const Vec3 d = x - centre_;
  return Scalar(0.5) * d.dot(quadratic_ * d) - Scalar(0.5);
}

Vec3 Ellipsoid::projectRadially(const Vec3& x) const {
  const Vec3 d = x - centre_;
  const Scalar q = d.dot(quadratic_ * d);
  if (!(q > 0) || !std::isfinite(q)) {
    throw std::invalid_argument("Ellipsoid::projectRadially: point " + str(x) +
                                " is the centre or not finite");
  }
  return centre_ + d / std::sqrt(q);
}

CurvatureRadii Ellipsoid::curvatureRadii(const Vec3& surfacePoint) const {
  // Appendix B gives K and H; R_min, R_max = (H -+ sqrt(H^2 - K))/K loses half
  // the digits near umbilic points (H^2 ~ K). The same radii are computed here
  // as the inverse eigenvalues of the shape operator on the tangent plane,
  // (t_i^T A t_j) / |A x|, a symmetric 2x2 problem without that cancellation;
  // R_G is eq. B.4 (tests check both against the closed forms of App. B).
  const Vec3 x = projectRadially(surfacePoint) - centre_;
  const Vec3 g = quadratic_ * x;
  const Scalar gnorm = g.norm();
  const Vec3 nrm = g / gnorm;
  int k = 0;
  if (std::abs(nrm[1]) < std::abs(nrm[k])) k = 1;
  if (std::abs(nrm[2]) < std::abs(nrm[k])) k = 2;
  Vec3 e = Vec3::Zero();
  e[k] = 1;
  const Vec3 t1 = (e - nrm[k] * nrm).normalized();
  const Vec3 t2 = nrm.cross(t1);
  const Scalar p = t1.dot(quadratic_ * t1) / gnorm;
  const Scalar r = t2.dot(quadratic_ * t2) / gnorm;
  const Scalar q = t1.dot(quadratic_ * t2) / gnorm;
  const Scalar mean = (p + r) / 2;
  const Scalar half = std::hypot((p - r) / 2, q);
  const Scalar kMax = mean + half;             // principal curvatures (> 0)
  const Scalar kMin = (p * r - q * q) / kMax;  // product / kMax, no cancellation

  const Vec3 xb = rotation_.transpose() * x;
  const Vec3 a2 = semiAxes_.cwiseProduct(semiAxes_);
  const Scalar s = xb.x() * xb.x() / (a2.x() * a2.x()) + xb.y() * xb.y() / (a2.y() * a2.y()) +
                   xb.z() * xb.z() / (a2.z() * a2.z());
  CurvatureRadii radii;
  radii.rMin = 1 / kMax;
  radii.rMax = 1 / kMin;
  radii.gaussian = semiAxes_.prod() * s;  // eq. B.4
  return radii;
}

Mat3 Ellipsoid::curvatureTensor(const Vec3& surfacePoint) const {
  const Vec3 g = quadratic_ * (projectRadially(surfacePoint) - centre_);
  const Scalar gnorm = g.norm();
  const Vec3 m = g / gnorm;
  const Mat3 P = Mat3::Identity() - m * m.transpose();
  const Mat3 S = P * quadratic_ * P / gnorm;
  return (S + S.transpose()) / 2;
}

Tensor3 Ellipsoid::surfaceThirdDerivative(const Vec3& surfacePoint) const {
  const Vec3 g = quadratic_ * (projectRadially(surfacePoint) - centre_);
  const Scalar gg = g.squaredNorm();
  const Vec3 m = g / std::sqrt(gg);
  const Mat3 P = Mat3::Identity() - m * m.transpose();
  Mat3 At = P * quadratic_ * P;
  At = (At + At.transpose()) / 2;
  const Vec3 b = P * quadratic_ * m;
  Tensor3 C;
  for (int k = 0; k < 3; ++k) {
    C[k] = -(At * b(k) + b * At.col(k).transpose() + At.col(k) * b.transpose()) / gg;
  }
  return C;
}

Vec3 Ellipsoid::support(const Vec3& direction) const {
  const Scalar scale = direction.cwiseAbs().maxCoeff();
  if (!(scale > 0) || !std::isfinite(scale)) {
    throw std::invalid_argument("Ellipsoid::support: direction must be non-zero and finite, got " +
                                str(direction));
  }
  const Vec3 n = direction / scale;  // scale-free: no underflow for tiny directions
  const Vec3 Pn = shape_ * n;
  return centre_ + Pn / std::sqrt(n.dot(Pn));
}

LineIntersection Ellipsoid::intersectLine(const Vec3& origin, const Vec3& direction) const {
  // f(o + t d) = 0  <=>  qa t^2 + 2 qb t + qc = 0 (eqs. D.2-D.6 with the centred
  // quadratic form). Written as t = tMid +- h with tMid = -qb/qa, the parameter of
  // the point of the line closest to the centre in the A-metric, and
  // h^2 = (1 - |oPerp|_A^2)/qa where oPerp = o + tMid d: the discriminant is
  // computed without the cancellation of qb^2 - qa qc (lines far from a small body).
  const Vec3 o = origin - centre_;
  const Vec3 Ad = quadratic_ * direction;
  const Scalar qa = direction.dot(Ad);
  LineIntersection li;
  if (!(qa > 0) || !std::isfinite(qa)) {
    return li;  // zero or non-finite direction
  }
  const Scalar tMid = -o.dot(Ad) / qa;
  const Vec3 oPerp = o + tMid * direction;
  const Scalar h2 = (1 - oPerp.dot(quadratic_ * oPerp)) / qa;
  if (!(h2 >= 0)) {
    return li;
  }
  const Scalar h = std::sqrt(h2);
  // the root farther from 0 directly, the nearer from the product of roots qc/qa
  const Scalar far = tMid + std::copysign(h, tMid);
  const Scalar qc = o.dot(quadratic_ * o) - 1;
  const Scalar near = far != 0 ? qc / (qa * far) : -far;
  li.tEnter = std::min(far, near);
  li.tExit = std::max(far, near);
  li.count = h2 > 0 ? 2 : 1;
  return li;
}

}  // namespace ellipsoids
