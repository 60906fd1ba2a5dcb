/**
 * @file DistanceResult.hpp
 * @brief What every distance method returns, and the options every method takes.
 *
 * Frame convention: point1 is on body 1, point2 on body 2, direction is a unit
 * vector pointing from body 1 to body 2 (the n of the certified bracket).
 */
#ifndef ELLIPSOIDS_DISTANCERESULT_HPP
#define ELLIPSOIDS_DISTANCERESULT_HPP

#include "ellipsoids/Types.hpp"

#include <string>

namespace ellipsoids {

enum class DistanceStatus {
  converged,      ///< stopping test met; distance is the answer
  overlapping,    ///< the bodies overlap (distance 0, or the signed depth for the dual method)
  maxIterations,  ///< iteration limit reached before the stopping test; last iterate returned
  failed          ///< the method broke down (e.g. a step it cannot take); last iterate returned
};

/// "converged", "overlapping", "max-iterations", "failed"
const char* toString(DistanceStatus status);

/// How methods whose own stopping rule is only an estimate decide to stop.
enum class StopRule {
  paper,      ///< the method's rule from the founding paper (angles with eps_theta, eq. 2.9/F.6)
  certified   ///< the certified bracket: upper - lower <= epsD
};

struct DistanceResult {
  /// Distance |point2 - point1|; 0 when overlapping (the dual method: signed,
  /// minus the penetration depth when overlapping).
  Scalar distance = 0;
  /// Certified bracket of the true distance d* (signed d* for the dual method):
  /// lower <= d* <= upper (floating-point rounding included).
  Scalar lower = 0;
  Scalar upper = 0;
  Vec3 point1 = Vec3::Zero();
  Vec3 point2 = Vec3::Zero();
  /// Unit vector from body 1 to body 2 that gives the lower bound L(direction).
  Vec3 direction = Vec3::UnitX();
  int iterations = 0;
  DistanceStatus status = DistanceStatus::failed;

  /// upper - lower: the certified error of this answer.
  Scalar bracketWidth() const { return upper - lower; }
};

struct DistanceOptions {
  /// Requested accuracy (absolute length, > 0).
  Scalar epsD = 1e-5;
  /// Iteration limit; 0: the method's default.
  int maxIterations = 0;
  /// Stopping test of Moving Balls, Newton-Coulomb and Jain et al. (others
  /// always stop on their own certified test).
  StopRule stopRule = StopRule::paper;
  /// Moving Balls: eps_theta from the local curvature at each iteration
  /// (eq. F.6) instead of the global maximum (eq. 2.9). Newton-Coulomb always
  /// uses F.6 after its first iteration (Alg. 4); Jain et al. always eq. 2.9.
  bool adaptiveEpsTheta = false;
  /// Warm start: a unit direction from body 1 to body 2 (e.g. the previous
  /// answer's direction); used by the methods that can (dual, GJK).
  bool useInitialDirection = false;
  Vec3 initialDirection = Vec3::UnitX();

  /// @throws std::invalid_argument if epsD is not finite and > 0 or maxIterations < 0
  void validate() const;
};

}  // namespace ellipsoids

#endif
