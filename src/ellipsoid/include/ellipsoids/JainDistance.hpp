/**
 * @file JainDistance.hpp
 * @brief The geometric iteration of Jain, Tschisgale & Froehlich (2019),
 *        founding paper Alg. 6, eqs. 2.68-2.71.
 *
 * Each surface point is held in ellipsoidal coordinates (nu, phi) of its body
 * (eq. 2.68, inverted by eq. 2.69); each iteration moves them by C_m times the
 * cosines between the direction to the other point and the tangents t_nu,
 * t_phi (eq. 2.70), with C_m = cFactor C_m^Jain, C_m^Jain = D_eq,m / max(a_m,
 * b_m, c_m) (eq. 2.71). Jia et al.'s test runs first (2.6.3). Stopping:
 * angles with the constant eps_theta of eq. 2.9 (options.adaptiveEpsTheta is
 * not consulted), or the certified bracket.
 *
 * No convergence proof exists and the paper shows failures at small
 * distances (Tables 3-5). Measured on the mirror case: the symmetric mode
 * converges in a few iterations, but when both points slide the same way by
 * delta the direction of d_m turns by ~delta / |d_m|, so that mode's gain grows
 * like C_m R / |d_m|; at small distances rounding seeds it and the iteration
 * ends in a non-converging oscillation. Bounded: the iteration limit (default
 * 1e5) ends with status maxIterations. At the poles of the parametrisation
 * (sin nu = 0, to rounding) t_phi vanishes: the phi update is skipped there
 * (the paper is silent).
 */
#ifndef ELLIPSOIDS_JAINDISTANCE_HPP
#define ELLIPSOIDS_JAINDISTANCE_HPP

#include "ellipsoids/DistanceMethod.hpp"

namespace ellipsoids {

class JainDistance : public DistanceMethod {
 public:
  struct Parameters {
    Scalar cFactor = 1;  ///< C_m / C_m^Jain
  };
  static constexpr int kDefaultMaxIterations = 100000;

  JainDistance() = default;
  /// @throws std::invalid_argument unless cFactor is finite and > 0
  explicit JainDistance(const Parameters& parameters);

  const Parameters& parameters() const { return parameters_; }
  std::string name() const override { return "jain"; }
  DistanceResult distance(const Ellipsoid& e1, const Ellipsoid& e2,
                          const DistanceOptions& options) const override;

 private:
  Parameters parameters_;
};

}  // namespace ellipsoids

#endif
