/**
 * @file DualNewton.hpp
 * @brief Our method, beyond the founding paper: Newton's method on the dual problem.
 *
 * d* = max over unit n of L(n) = n.(r2 - r1) - sqrt(n^T P1 n) - sqrt(n^T P2 n).
 * The gradient of L is v(n) = x2(n) - x1(n), the vector between the support
 * points x1(n) = s_E1(n) and x2(n) = s_E2(-n); on the sphere the Hessian is
 * -(Q1 + Q2 + L I) on the tangent plane, with Q_m the curvature-radius tensor
 * of E_m at its support point, so a Newton step solves the 2x2 system
 * (Q1 + Q2 + L I) dn = tangential part of v, followed by n <- (n + dn)/|n + dn|
 * with a backtracking (Armijo) line search on L for global convergence.
 *
 * Stopping test (certified): |x2 - x1| - L(n) <= epsD, i.e. |v|(1 - cos angle(v, n)).
 * The answer is |x2 - x1| with the bracket [L(n), |x2 - x1|].
 *
 * Signed form: when the bodies overlap the maximum of L is negative; its
 * magnitude is the penetration depth (the shortest translation that separates
 * the bodies) and n the direction to separate them. distance is then that
 * negative maximum, status overlapping, lower = L(n) (certified) and
 * upper = 0 once a common point of the bodies is certain (x2(n) in E1, x1(n)
 * in E2 or a centre in the other body, certainlyInside). Without one (an
 * overlap below the rounding of that test) upper = |x2 - x1|, which bounds the
 * signed distance whatever the sign. If then the Jia et al. test says
 * separated, the status is failed (a spurious maximum; callers then use
 * another method, as auto does).
 *
 * Rounding: the iteration uses the stored world-frame shape matrices; the
 * bracket is widened by roundingAllowance (CertifiedBracket.hpp), which grows
 * with the elongation of the bodies for that reason. Bodies whose centres are
 * closer than eps times their size start from any direction (concentric).
 */
#ifndef ELLIPSOIDS_DUALNEWTON_HPP
#define ELLIPSOIDS_DUALNEWTON_HPP

#include "ellipsoids/DistanceMethod.hpp"

namespace ellipsoids {

/// One query of a batch: the two bodies, and optionally a warm-start direction.
struct DistancePair {
  const Ellipsoid* e1;
  const Ellipsoid* e2;
  const Vec3* initialDirection = nullptr;  ///< unit direction from body 1 to body 2, or none
};

class DualNewton : public DistanceMethod {
 public:
  static constexpr int kDefaultMaxIterations = 100;

  std::string name() const override { return "dual"; }
  bool isSigned() const override { return true; }
  DistanceResult distance(const Ellipsoid& e1, const Ellipsoid& e2,
                          const DistanceOptions& options) const override;

  /**
   * Batch API: results[i] = distance(*pairs[i].e1, *pairs[i].e2, options)
   * (with pairs[i].initialDirection as warm start when given), the same
   * answers as one at a time, computed with several queries in flight to use
   * the core's parallelism (the gain is measured in docs/benchmarks.md).
   * No allocation. results must hold count entries.
   */
  void distances(const DistancePair* pairs, std::size_t count, const DistanceOptions& options,
                 DistanceResult* results) const;
};

}  // namespace ellipsoids

#endif
