/**
 * @file NewtonCoulomb.hpp
 * @brief The modified Newton-Coulomb ("charged balls") method of the founding
 *        paper: Alg. 4 with the backtracking loop of Alg. 3, eqs. 2.37-2.45.
 *
 * Two charges on the surfaces attract each other; with the "zeroing speed"
 * scheme each iteration moves x_m by (delta_m)^2 xi_m (eq. 2.37, 2.41) and
 * projects back to the surface to first order; the step is limited by the
 * local minimum curvature radius (eq. 2.40) with C_curv,m = min(C_max,
 * tau sqrt(2 |x1 - x2| / R_min,m)) (eq. 2.45); a backtracking loop (Alg. 3)
 * multiplies the steps by lambda until the distance decreases.
 * Jia et al.'s test runs first (2.3.5): overlap returns distance 0.
 * Stopping: angles with eps_theta^0 from eq. 2.9, then eq. F.6 at each
 * iteration (2.3.4), or the certified bracket (StopRule::certified).
 * options.adaptiveEpsTheta is not consulted: Alg. 4 always switches to F.6
 * after the first test (the curvature is computed anyway for eq. 2.40).
 *
 * Implementation notes: delta_m^2 xi_m = C_curv,m R_min,m xi_m / |xi_m| (eq. 2.40
 * in 2.41), so each trial moves x_m by C_curv,m R_min,m along the part of
 * x_other - x_m tangent at x_m; the 1/|x1 - x2|^3 of xi_m cancels and is not
 * formed. Alg. 3 sets delta_m <- lambda delta_m, i.e. the displacement shrinks
 * by lambda^2 per rejection. Computed relative to r1 (translation invariant);
 * the displacement scales with R_min, so the method is scale invariant.
 *
 * The paper found this method slow and fragile (Table 1: 216x GJK's time and
 * 3 failures in 606 queries with C_max = 0.01, tau = 0.01, lambda = 0.5); it is
 * here to measure and show that, faithfully. Every loop is bounded: the
 * iteration limit (default 1e5, as the paper) ends with status maxIterations,
 * a backtracking loop that cannot decrease the distance in maxBacktracking
 * halvings ends with status failed.
 */
#ifndef ELLIPSOIDS_NEWTONCOULOMB_HPP
#define ELLIPSOIDS_NEWTONCOULOMB_HPP

#include "ellipsoids/DistanceMethod.hpp"

namespace ellipsoids {

class NewtonCoulomb : public DistanceMethod {
 public:
  struct Parameters {
    Scalar cMax = 0.01;        ///< C_max of eq. 2.45
    Scalar tau = 1;            ///< tau of eq. 2.45 (< 1 in the paper's Table 1: 0.01)
    Scalar lambda = 0.5;       ///< shrinking factor of the backtracking loop (Alg. 3)
    int maxBacktracking = 60;  ///< bound on the backtracking loop per iteration
  };
  static constexpr int kDefaultMaxIterations = 100000;

  NewtonCoulomb() = default;
  /// @throws std::invalid_argument unless cMax > 0, tau > 0, 0 < lambda < 1, maxBacktracking >= 1
  explicit NewtonCoulomb(const Parameters& parameters);

  const Parameters& parameters() const { return parameters_; }
  std::string name() const override { return "newtonCoulomb"; }
  DistanceResult distance(const Ellipsoid& e1, const Ellipsoid& e2,
                          const DistanceOptions& options) const override;

 private:
  Parameters parameters_;
};

}  // namespace ellipsoids

#endif
