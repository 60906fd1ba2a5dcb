/**
 * @file OverlapTest.hpp
 * @brief Exact algebraic overlap test of Jia et al. (2011), founding paper Appendix C.
 *
 * P(lambda) = det(lambda I + A1^{-1} A2) with the homogeneous 4x4 matrices of
 * the two ellipsoids (computed in the frame where E1 is the unit sphere: the
 * matrix is similar to the paper's, so P is the same, with entries of order one).
 * Wang et al.: separated iff P has two distinct positive roots, touching iff a
 * positive double root. Jia et al. decide this from the signs of the
 * coefficients (Var(1, a, b, c, d) = 2) and of the subresultant-type quantities
 * sr22, sr20, sr11, sr10, sr0 (eq. C.4).
 *
 * The "= 0" branches in floating point. sr0 (the discriminant, up to a
 * positive factor) and sr11 are differences of products; each is compared
 * with the sum of the magnitudes of the products it is made of:
 *   |sr0|  <= zeroTolerance (|A|^3 + 27 B^2)
 *   |sr11| <= zeroTolerance (9 W1^2 + 27 |Delta2 Delta3| + 3 |W3 Delta2|)
 * counts as zero. P is invariant under a common scaling, translation or
 * rotation of the pair, and so are these relative tests: the decision is
 * scale invariant. The discriminant of a nearly tangent pair is proportional
 * to its gap with a shape-dependent factor, so "touching" is a band of gaps
 * around zero whose width depends on the shapes. With the default
 * zeroTolerance = 1e-12, measured on random tri-axial pairs (semi-axes in
 * [0.1, 2], any orientation, scales 1e-6..1e6) made tangent and then moved
 * apart or together by gap x (largest semi-axis) along the common normal
 * (tests/geometry/OverlapTestTest.cpp, JiaTouchingBand):
 *   gap 0: touching (>= 99 %; the rest is the rounding of the construction);
 *   |gap| = 1e-12: 92 % separated/overlapping, 8 % touching;
 *   |gap| = 1e-10: 99.9 % separated/overlapping;
 *   |gap| >= 1e-9: 100 % separated/overlapping;
 * a separated pair is never reported overlapping nor the reverse.
 *
 * Far-apart pairs. The coefficients of a pair far apart relative to its sizes
 * are differences of terms of order (|r2 - r1| / b1)^2 and more: with unit
 * spheres 1e8 apart every digit cancels and the decision is noise. A pair
 * whose centres are farther apart than the sum of the largest semi-axes (plus
 * the rounding allowance of CertifiedBracket.hpp) is therefore separated
 * without the polynomial; the polynomial decides only for pairs within that
 * distance, where |r| <= (a_max,1 + a_max,2) / a_min,1.
 *
 * Bodies of very different sizes. A small body near a large one's surface
 * makes one root of P smaller than the rounding of the others by the square of
 * the size ratio: measured with a body placed +-1e-3 of the larger body's size
 * from its surface (tests/geometry/OverlapTestTest.cpp, BodiesOfDifferentSizes),
 * the decision is right for size ratios up to 1e6 and wrong for a quarter of
 * the pairs at 1e8.
 *
 * The answer is an algebraic decision in floating point, not a certificate:
 * the certified brackets (CertifiedBracket.hpp) never rely on it.
 */
#ifndef ELLIPSOIDS_OVERLAPTEST_HPP
#define ELLIPSOIDS_OVERLAPTEST_HPP

#include "ellipsoids/Ellipsoid.hpp"

namespace ellipsoids {

enum class OverlapStatus { separated, touching, overlapping };

/// "separated", "touching", "overlapping"
const char* toString(OverlapStatus status);

struct OverlapDetails {
  OverlapStatus status = OverlapStatus::overlapping;
  Vec4 coefficients = Vec4::Zero();  ///< (a, b, c, d) of P(l) = l^4 + a l^3 + b l^2 + c l + d
  int signVariations = 0;            ///< Var(1, a, b, c, d)
  Scalar sr22 = 0, sr20 = 0, sr11 = 0, sr10 = 0, sr0 = 0;
  bool sr11IsZero = false, sr0IsZero = false;
};

class JiaOverlapTest {
 public:
  static constexpr Scalar kDefaultZeroTolerance = 1e-12;

  explicit JiaOverlapTest(Scalar zeroTolerance = kDefaultZeroTolerance);

  /// separated when the bounding spheres are apart (provedApart), else Jia et al.'s decision
  OverlapStatus test(const Ellipsoid& e1, const Ellipsoid& e2) const;

  /// The test with every intermediate quantity (for diagnostics and tests).
  OverlapDetails details(const Ellipsoid& e1, const Ellipsoid& e2) const;

  /// Coefficients (a, b, c, d) of the monic characteristic polynomial P.
  static Vec4 characteristicPolynomial(const Ellipsoid& e1, const Ellipsoid& e2);

  /// |r2 - r1| - a_max,1 - a_max,2 exceeds roundingAllowance(e1, e2): apart for certain.
  static bool provedApart(const Ellipsoid& e1, const Ellipsoid& e2);

 private:
  /// Jia et al.'s decision from the polynomial alone.
  OverlapDetails decide(const Ellipsoid& e1, const Ellipsoid& e2) const;

  Scalar zeroTolerance_;
};

}  // namespace ellipsoids

#endif
