// The reference of the extreme-range tests: a certified bracket of the exact
// distance between two ellipsoids given by their double inputs (semi-axes,
// centre, quaternion), computed in long double (64-bit significand, eps
// 1.1e-19), independently of the geometry core's code.
//
// Method: Newton's method on the dual function L(n) = n.(r2 - r1) - h1(n) - h2(n)
// over unit n, h_m(n) = |D_m R_m^T n| the support radius in the body frame
// (R_m from the quaternion normalised in long double); at the final n,
//   L(n) <= d* <= |s2(-n) - s1(n)|   (s_m the support points)
// each widened by 64 eps_ld (|r2 - r1| + a_max,1 + a_max,2 + |s1|_1 + |s2|_1),
// a bound of the long-double rounding of these body-frame evaluations. The
// bracket is "tight" when its width is below a target the caller gives
// (typically a small fraction of the double rounding allowance under test).
#ifndef ELLIPSOIDS_TESTS_LONGDOUBLEREFERENCE_HPP
#define ELLIPSOIDS_TESTS_LONGDOUBLEREFERENCE_HPP

#include "ellipsoids/Ellipsoid.hpp"

namespace testgeometry {

/// The inputs of one body, as given to the Ellipsoid constructor.
struct BodyInput {
  ellipsoids::Vec3 semiAxes;
  ellipsoids::Vec3 centre;
  ellipsoids::Quat orientation;

  ellipsoids::Ellipsoid body() const { return ellipsoids::Ellipsoid(semiAxes, centre, orientation); }
};

struct ReferenceBracket {
  long double lower = 0;
  long double upper = 0;
  bool tight = false;
  int iterations = 0;
  ellipsoids::Vec3 direction = ellipsoids::Vec3::UnitX();  ///< the final n (rounded to double)
  ellipsoids::Vec3 point1 = ellipsoids::Vec3::Zero();      ///< its support points (rounded to double)
  ellipsoids::Vec3 point2 = ellipsoids::Vec3::Zero();
};

/// A width target for the reference: eps (|r2 - r1| + a_max,1^2/a_min,1 + a_max,2^2/a_min,2 +
/// |r1|_1 + |r2|_1) / 8: at most a 32nd of the double rounding a bracket of e1 and e2 carries.
long double referenceTarget(const ellipsoids::Ellipsoid& e1, const ellipsoids::Ellipsoid& e2);

class LongDoubleReference {
 public:
  /**
   * @param start a unit direction from body 1 to body 2 near the optimum (e.g.
   *        the normal a tangent pair was built along)
   * @param targetWidth the width below which the bracket is tight
   */
  ReferenceBracket distance(const BodyInput& b1, const BodyInput& b2, const ellipsoids::Vec3& start,
                            long double targetWidth) const;
};

}  // namespace testgeometry

#endif
