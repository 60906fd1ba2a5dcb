/**
 * @file DistanceMethod.hpp
 * @brief The one interface of every minimal-distance method.
 */
#ifndef ELLIPSOIDS_DISTANCEMETHOD_HPP
#define ELLIPSOIDS_DISTANCEMETHOD_HPP

#include "ellipsoids/DistanceResult.hpp"
#include "ellipsoids/Ellipsoid.hpp"

#include <memory>
#include <string>
#include <vector>

namespace ellipsoids {

class DistanceMethod {
 public:
  virtual ~DistanceMethod() = default;

  /// Name as used on the command line (movingBalls, gjk, ...).
  virtual std::string name() const = 0;

  /// True if the result's distance is signed (minus the penetration depth when overlapping).
  virtual bool isSigned() const { return false; }

  /**
   * @brief Minimal distance between e1 and e2.
   * Never throws on geometry (overlap, touching, far apart): the status says
   * what happened; the bracket is always filled and certified.
   * @throws std::invalid_argument on invalid options
   */
  virtual DistanceResult distance(const Ellipsoid& e1, const Ellipsoid& e2,
                                  const DistanceOptions& options) const = 0;
};

/// Names accepted by makeDistanceMethod, in the paper's order then ours.
const std::vector<std::string>& distanceMethodNames();

/**
 * Creates a method with its default parameters.
 * @throws std::invalid_argument for an unknown name (the message lists the valid names)
 */
std::unique_ptr<DistanceMethod> makeDistanceMethod(const std::string& name);

}  // namespace ellipsoids

#endif
