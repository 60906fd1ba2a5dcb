/**
 * @file Ellipsoid.hpp
 * @brief A solid ellipsoid: semi-axes, centre and orientation (unit quaternion), with
 *        everything the distance methods need precomputed once per body.
 *
 * Conventions (founding paper, Appendix A):
 * - body frame: semi-axis a along e_x, b along e_y, c along e_z (any order of sizes);
 * - x_body = U^T (x - r), with U = U(q) the rotation of eq. A.6 (Eigen's
 *   Quaterniond(w, x, y, z).toRotationMatrix() with w = q0);
 * - E = { x : f(x) <= 0 }, f(x) = 1/2 x^T A x + b^T x + alpha, with
 *   A = U Sigma U^T, Sigma = diag(1/a^2, 1/b^2, 1/c^2), b = -A r,
 *   alpha = 1/2 r^T A r - 1/2 (eqs. A.9-A.11); here f(x) = 1/2 ((x-r)^T A (x-r) - 1);
 * - P = U diag(a^2, b^2, c^2) U^T = A^{-1} (the "shape matrix" of the support
 *   mapping and of the certified distance bracket);
 * - homogeneous form (App. C.2): X^T A_h X <= 0 with X = (x, 1),
 *   A_h = M^{-T} diag(1/a^2, 1/b^2, 1/c^2, -1) M^{-1}, M = [U r; 0 1].
 */
#ifndef ELLIPSOIDS_ELLIPSOID_HPP
#define ELLIPSOIDS_ELLIPSOID_HPP

#include "ellipsoids/Types.hpp"

#include <array>

namespace ellipsoids {

/// Principal curvature radii at a surface point (Appendix B).
struct CurvatureRadii {
  Scalar rMin;      ///< smallest principal radius of curvature
  Scalar rMax;      ///< largest principal radius of curvature
  Scalar gaussian;  ///< R_G = 1/sqrt(K) = sqrt(rMin rMax)
};

/// Intersections of a line x(t) = origin + t direction with the surface (Appendix D).
struct LineIntersection {
  int count = 0;             ///< 0 (misses), 1 (tangent) or 2
  Scalar tEnter = 0;         ///< smaller root
  Scalar tExit = 0;          ///< larger root
};

/**
 * The bodies the geometry core supports, checked by the Ellipsoid constructor:
 * - every semi-axis in [kMinLength, kMaxLength];
 * - elongation (largest / smallest semi-axis) at most kMaxElongation, i.e.
 *   spheroids of aspect ratio 1/100 to 100;
 * - every centre coordinate at most kMaxLength in magnitude.
 * Why these bounds: the methods form products of up to six lengths (GJK's
 * sub-determinants) and ratios of up to four (Jia's polynomial, the shape
 * matrices times squared centre distances); within these bounds none leaves
 * the normal range of double (1e-307 .. 1e308), whatever the two bodies of a
 * pair. The rounding allowance of the certified bracket grows with the
 * elongation (CertifiedBracket.hpp); tests/geometry/ExtremeRangeTest.cpp checks
 * the bracket against a long-double reference over this whole range.
 */
struct SupportedRange {
  static constexpr Scalar kMinLength = 1e-35;
  static constexpr Scalar kMaxLength = 1e35;
  static constexpr Scalar kMaxElongation = 100;
};

class Ellipsoid {
 public:
  /**
   * @param semiAxes (a, b, c), each in [kMinLength, kMaxLength] with
   *        max/min <= kMaxElongation (SupportedRange)
   * @param centre   coordinates of magnitude <= kMaxLength
   * @param orientation quaternion; normalised if its norm is within 1e-6 of 1
   * @throws std::invalid_argument naming the parameter and its allowed values
   *         on a semi-axis, elongation or centre outside SupportedRange (or not
   *         finite), or a quaternion farther than 1e-6 from unit norm
   */
  Ellipsoid(const Vec3& semiAxes, const Vec3& centre, const Quat& orientation);

  /// Sphere of radius r at centre.
  static Ellipsoid sphere(Scalar radius, const Vec3& centre);

  /// The same body moved by shift, its precomputed matrices reused. The new
  /// centre is not checked: the methods use it for coordinates relative to the
  /// other body's centre, up to twice kMaxLength.
  Ellipsoid translatedBy(const Vec3& shift) const {
    Ellipsoid moved(*this);
    moved.centre_ += shift;
    return moved;
  }

  /**
   * Spheroid of aspect ratio ar = (symmetry semi-axis)/(other semi-axes) and
   * equal-volume diameter dEq (paper eq. 3.1): a = ar^(2/3) dEq/2 along the
   * body x axis, b = c = ar^(-1/3) dEq/2.
   */
  static Ellipsoid spheroid(Scalar ar, Scalar dEq, const Vec3& centre, const Quat& orientation);

  const Vec3& semiAxes() const { return semiAxes_; }
  const Vec3& centre() const { return centre_; }
  const Quat& orientation() const { return orientation_; }
  /// Rotation U(q): columns are the body axes in the global frame.
  const Mat3& rotation() const { return rotation_; }
  /// A = U Sigma U^T (eq. A.9).
  const Mat3& quadraticMatrix() const { return quadratic_; }
  /// P = A^{-1} = U diag(a^2,b^2,c^2) U^T.
  const Mat3& shapeMatrix() const { return shape_; }
  /// b = -A r (eq. A.10).
  Vec3 linearTerm() const { return -(quadratic_ * centre_); }
  /// alpha = 1/2 r^T A r - 1/2 (eq. A.11).
  Scalar constantTerm() const { return Scalar(0.5) * centre_.dot(quadratic_ * centre_) - Scalar(0.5); }
  /// The 4x4 homogeneous matrix of Appendix C.2 (eq. C.9).
  Mat4 homogeneousMatrix() const;

  Scalar minSemiAxis() const { return minAxis_; }
  Scalar maxSemiAxis() const { return maxAxis_; }
  /// Equal-volume radius (abc)^(1/3).
  Scalar equivalentRadius() const { return equivalentRadius_; }
  /**
   * Aspect ratio: for a spheroid (two semi-axes equal to 1e-12 relative),
   * the symmetry semi-axis over the other (< 1 oblate, > 1 prolate); for a
   * sphere 1; for a tri-axial ellipsoid max/min semi-axis.
   */
  Scalar aspectRatio() const { return aspectRatio_; }
  /// max/min semi-axis (>= 1): how far from a sphere, whatever the kind.
  Scalar elongation() const { return maxAxis_ / minAxis_; }

  /// max over the surface of R_max: (largest semi-axis)^2 / (smallest) = elongation x largest
  /// semi-axis (also the scale of the rounding of the world-frame shape matrix, CertifiedBracket.hpp).
  Scalar maxOfMaxCurvatureRadius() const { return maxCurvatureRadius_; }
  /// min over the surface of R_min: (smallest semi-axis)^2 / (largest).
  Scalar minOfMinCurvatureRadius() const { return minAxis_ * minAxis_ / maxAxis_; }
  /// min over the surface of the Gaussian radius R_G: min_i (abc / a_i^2), reached at a vertex.
  Scalar minGaussianRadius() const { return minGaussianRadius_; }

  /// f(x) = 1/2 (x-r)^T A (x-r) - 1/2: negative inside, zero on the surface.
  Scalar levelSet(const Vec3& x) const;
  /// grad f = A (x - r): outward normal direction (not unit).
  Vec3 gradient(const Vec3& x) const { return quadratic_ * (x - centre_); }
  /// Radial projection r + (x - r)/sqrt((x-r)^T A (x-r)) onto the surface.
  /// @throws std::invalid_argument if x is the centre
  Vec3 projectRadially(const Vec3& x) const;

  /**
   * @brief Principal curvature radii at a surface point (Appendix B, eqs. B.1-B.4).
   * The point is first projected radially onto the surface.
   */
  CurvatureRadii curvatureRadii(const Vec3& surfacePoint) const;

  /**
   * @brief The curvature tensor (shape operator) at a surface point, in the
   *        world frame: S = P A P / |A x|, x the point relative to the centre,
   *        P = I - m m^T the projector on the tangent plane, m the outward unit
   *        normal. S m = 0; on the tangent plane its eigenvalues are the
   *        principal curvatures and its eigenvectors their directions; the
   *        surface near the point is y = -t^T S t / 2 along -m for a tangent
   *        offset t (to second order). The point is first projected radially.
   */
  Mat3 curvatureTensor(const Vec3& surfacePoint) const;

  /**
   * @brief The third derivatives of the surface at a surface point, the term
   *        after the curvature tensor: near the point the surface is
   *        y = -(t^T S t/2 + C(t, t, t)/6) along -m for a tangent offset t,
   *        with C_ijk = -(A'_ij b_k + A'_jk b_i + A'_ik b_j)/|g|^2, g = A x
   *        (x the point relative to the centre), A' = P A P, b = P A m
   *        (from f(x + t - y m) = 0 to third order in t). C vanishes where
   *        A m is along m: at the vertices and everywhere on a sphere.
   *        Returned as C[k](i, j) = C_ijk (world frame). The point is first
   *        projected radially.
   */
  Tensor3 surfaceThirdDerivative(const Vec3& surfacePoint) const;

  /**
   * @brief Support mapping s(n) = argmax_{x in E} n.x = r + P n / sqrt(n^T P n)
   *        (eqs. 2.19-2.20).
   * @param direction any non-zero finite vector (need not be unit)
   * @throws std::invalid_argument on a zero or non-finite direction
   */
  Vec3 support(const Vec3& direction) const;

  /// Support function about the centre, sqrt(n^T P n), for a unit n.
  Scalar supportRadius(const Vec3& unitDirection) const {
    return std::sqrt(unitDirection.dot(shape_ * unitDirection));
  }
  /// Support function h(n) = max_{x in E} n.x for a unit n: n.r + sqrt(n^T P n).
  Scalar supportValue(const Vec3& unitDirection) const {
    return unitDirection.dot(centre_) + supportRadius(unitDirection);
  }

  /**
   * @brief Intersections of the line origin + t direction with the surface
   *        (Appendix D: the quadratic A t^2 + B t + C = 0 of eqs. D.2-D.6,
   *        solved without cancellation).
   */
  LineIntersection intersectLine(const Vec3& origin, const Vec3& direction) const;

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW

 private:
  Vec3 semiAxes_;
  Vec3 centre_;
  Quat orientation_;
  Mat3 rotation_;
  Mat3 quadratic_;
  Mat3 shape_;
  Scalar minAxis_;
  Scalar maxAxis_;
  Scalar equivalentRadius_;
  Scalar aspectRatio_;
  Scalar minGaussianRadius_;
  Scalar maxCurvatureRadius_;
};

}  // namespace ellipsoids

#endif
