/**
 * @file Gjk.hpp
 * @brief The Gilbert-Johnson-Keerthi algorithm (founding paper Alg. 2) on the
 *        Minkowski difference C = E1 - E2, with van den Bergen's Johnson
 *        sub-algorithm: dot products and the Delta determinants of eqs. 2.25-2.26
 *        cached per subset (bit masks) and updated only for the new vertex.
 *
 * v^0 = r1 - r2 (or -options.initialDirection, e.g. eq. 3.3 in the validation
 * study); w = s_C(-v) = s_E1(-v) - s_E2(v) (eq. 2.18); lower bound
 * mu = max(mu, w.v/|v|) (eqs. 2.14-2.16), which is exactly L(-v/|v|); stop
 * when |v| - mu <= epsD (eq. 2.17): a certified stop. Points by eq. 2.30.
 * Overlap when the simplex encloses the origin (v = 0, or 4 vertices).
 */
#ifndef ELLIPSOIDS_GJK_HPP
#define ELLIPSOIDS_GJK_HPP

#include "ellipsoids/DistanceMethod.hpp"

namespace ellipsoids {

class Gjk : public DistanceMethod {
 public:
  static constexpr int kDefaultMaxIterations = 1000;

  std::string name() const override { return "gjk"; }
  DistanceResult distance(const Ellipsoid& e1, const Ellipsoid& e2,
                          const DistanceOptions& options) const override;
};

}  // namespace ellipsoids

#endif
