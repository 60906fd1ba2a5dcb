/**
 * @file Ellipsoid.hpp
 * @brief A solid ellipsoid: semi-axes, centre and orientation (unit quaternion).
 *
 * Conventions (founding paper, Appendix A):
 * - body frame: semi-axis a along e_x, b along e_y, c along e_z;
 * - x_body = U^T (x - r), with U = U(q) the rotation of eq. A.6 (Eigen's
 *   Quaterniond(w, x, y, z).toRotationMatrix() with w = q0);
 * - E = { x : f(x) <= 0 }, f(x) = 1/2 x^T A x + b^T x + alpha, with
 *   A = U Sigma U^T, Sigma = diag(1/a^2, 1/b^2, 1/c^2), b = -A r,
 *   alpha = 1/2 r^T A r - 1/2 (eqs. A.9-A.11);
 * - P = U diag(a^2, b^2, c^2) U^T = A^{-1} (the "shape matrix" used by the
 *   support mapping and the certified distance bracket).
 */
#ifndef ELLIPSOIDS_ELLIPSOID_HPP
#define ELLIPSOIDS_ELLIPSOID_HPP

#include "ellipsoids/Types.hpp"

namespace ellipsoids {

class Ellipsoid {
 public:
  /**
   * @param semiAxes (a, b, c), each finite and > 0
   * @param centre   finite centre r
   * @param orientation quaternion; normalised if its norm is within 1e-6 of 1
   * @throws std::invalid_argument on a non-positive or non-finite semi-axis, a
   *         non-finite centre, or a quaternion far from unit norm
   */
  Ellipsoid(const Vec3& semiAxes, const Vec3& centre, const Quat& orientation);

  /// Sphere of radius r at centre.
  static Ellipsoid sphere(Scalar radius, const Vec3& centre);

  const Vec3& semiAxes() const { return semiAxes_; }
  const Vec3& centre() const { return centre_; }
  const Quat& orientation() const { return orientation_; }
  /// Rotation U(q): columns are the body axes in the global frame.
  const Mat3& rotation() const { return rotation_; }
  /// A = U Sigma U^T (eq. A.9).
  const Mat3& quadraticMatrix() const { return quadratic_; }
  /// P = A^{-1} = U diag(a^2,b^2,c^2) U^T.
  const Mat3& shapeMatrix() const { return shape_; }

  /// f(x) = 1/2 (x-r)^T A (x-r) - 1/2: negative inside, zero on the surface.
  Scalar levelSet(const Vec3& x) const;

  /**
   * @brief Support mapping s(n) = argmax_{x in E} n.x = r + P n / sqrt(n^T P n).
   * @param direction any non-zero finite vector (need not be unit)
   * @throws std::invalid_argument on a zero or non-finite direction
   */
  Vec3 support(const Vec3& direction) const;

  /// Support function h(n) = max_{x in E} n.x for a unit n: n.r + sqrt(n^T P n).
  Scalar supportValue(const Vec3& unitDirection) const;

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW

 private:
  Vec3 semiAxes_;
  Vec3 centre_;
  Quat orientation_;
  Mat3 rotation_;
  Mat3 quadratic_;
  Mat3 shape_;
};

}  // namespace ellipsoids

#endif
