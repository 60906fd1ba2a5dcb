#include "ellipsoids/Ellipsoid.hpp"

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

}  // namespace

Ellipsoid::Ellipsoid(const Vec3& semiAxes, const Vec3& centre, const Quat& orientation)
    : semiAxes_(semiAxes), centre_(centre), orientation_(orientation) {
  if (!semiAxes.allFinite() || semiAxes.minCoeff() <= 0) {
    throw std::invalid_argument("Ellipsoid: semi-axes must be finite and > 0, got " +
                                str(semiAxes));
  }
  if (!centre.allFinite()) {
    throw std::invalid_argument("Ellipsoid: centre must be finite, got " + str(centre));
  }
  const Scalar norm = orientation.norm();
  if (!std::isfinite(norm) || std::abs(norm - 1) > 1e-6) {
    throw std::invalid_argument(
        "Ellipsoid: orientation must be a unit quaternion (|q| within 1e-6 of 1), got |q| = " +
        std::to_string(norm));
  }
  orientation_.normalize();
  rotation_ = orientation_.toRotationMatrix();
  const Vec3 a2 = semiAxes_.cwiseProduct(semiAxes_);
  quadratic_ = rotation_ * a2.cwiseInverse().asDiagonal() * rotation_.transpose();
  shape_ = rotation_ * a2.asDiagonal() * rotation_.transpose();
}

Ellipsoid Ellipsoid::sphere(Scalar radius, const Vec3& centre) {
  return Ellipsoid(Vec3::Constant(radius), centre, Quat::Identity());
}

Scalar Ellipsoid::levelSet(const Vec3& x) const {
  const Vec3 d = x - centre_;
  return Scalar(0.5) * d.dot(quadratic_ * d) - Scalar(0.5);
}

Vec3 Ellipsoid::support(const Vec3& direction) const {
  const Scalar n2 = direction.squaredNorm();
  if (!(n2 > 0) || !std::isfinite(n2)) {
    throw std::invalid_argument("Ellipsoid::support: direction must be non-zero and finite, got " +
                                str(direction));
  }
  const Vec3 Pn = shape_ * direction;
  return centre_ + Pn / std::sqrt(direction.dot(Pn));
}

Scalar Ellipsoid::supportValue(const Vec3& unitDirection) const {
  return unitDirection.dot(centre_) + std::sqrt(unitDirection.dot(shape_ * unitDirection));
}

}  // namespace ellipsoids
