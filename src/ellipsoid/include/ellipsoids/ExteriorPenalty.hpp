/**
 * @file ExteriorPenalty.hpp
 * @brief The exterior penalty function method of Tamasyan & Chumakov, founding
 *        paper Alg. 5, eqs. 2.46-2.67.
 *
 * Minimises Phi_lambda(z) = |x1 - x2|^2/2 + lambda (|h1(x1)| + |h2(x2)|) over
 * z = (x1, x2) in R^6 (h_m = f_m of App. A). Descent direction: the
 * hypogradient G* (eq. 2.60) with (mu1*, mu2*) from the 2x2 system 2.58;
 * step beta from Gamma'(beta) = 0 (eq. 2.65, trying the four sign patterns
 * s_m(beta) and keeping the consistent ones) or, when no consistent root
 * exists, from the ray-surface intersections of eq. 2.66 (App. D), keeping
 * the beta that minimises Gamma. Stops when |G*| < eps_G (eq. 2.67).
 * Jia et al.'s test runs first (2.4.5): overlap returns distance 0.
 *
 * The penalty and tolerance scale with the pair: lambda = lambdaRelative D^2,
 * eps_G = epsGRelative D, with D the smaller equal-volume diameter (the paper
 * uses lambda = 1e3 D_eq^2, eps_G = 1e-4 D_eq and found no scaling that makes
 * the method scale invariant; Figs. 15-18). The method ignores epsD and
 * stopRule: its accuracy is set by eps_G. Bounded: iteration limit (default
 * 1e5) ends with status maxIterations; a step that cannot be found (singular
 * 2x2 system, no admissible beta, a step that does not move) ends with status failed.
 *
 * Measured behaviour: G* at surface points is the tangential part of x1 - x2,
 * so the absolute test |G*| < eps_G leaves an angle ~ eps_G / d: the error
 * grows as d -> 0 (|d - d*| ~ 1e-3 D at d* <= 1e-4 D on the mirror case, as
 * the paper's Fig. 16). The returned points may lie slightly off the surfaces
 * (the penalty is exact only in the limit); the certified bracket projects them.
 * The unconstrained solution of eq. 2.58 is used (the box |mu_m| <= lambda of
 * eq. 2.56 is not imposed, as in the paper). With lambda ~ D^2 and eps_G ~ D the
 * method is scale invariant in exact arithmetic, but its thousands of steps
 * amplify rounding: a dilation changes the iteration count and the
 * result within eps_G (tests/geometry/ExteriorPenaltyTest.cpp).
 */
#ifndef ELLIPSOIDS_EXTERIORPENALTY_HPP
#define ELLIPSOIDS_EXTERIORPENALTY_HPP

#include "ellipsoids/DistanceMethod.hpp"

namespace ellipsoids {

class ExteriorPenalty : public DistanceMethod {
 public:
  struct Parameters {
    Scalar lambdaRelative = 1e3;  ///< penalty lambda / D^2
    Scalar epsGRelative = 1e-4;   ///< stopping tolerance eps_G / D
  };
  static constexpr int kDefaultMaxIterations = 100000;

  ExteriorPenalty() = default;
  /// @throws std::invalid_argument unless both parameters are finite and > 0
  explicit ExteriorPenalty(const Parameters& parameters);

  const Parameters& parameters() const { return parameters_; }
  std::string name() const override { return "exteriorPenalty"; }
  DistanceResult distance(const Ellipsoid& e1, const Ellipsoid& e2,
                          const DistanceOptions& options) const override;

 private:
  Parameters parameters_;
};

}  // namespace ellipsoids

#endif
